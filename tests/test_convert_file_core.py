"""A file converted by the core with the GIL released (``Converter.convert_file``): the same
bytes, notes, statistics and refusals as the conversion of the same program held in memory,
which reads it through Python (``convert_text``); what the core leaves to Python (a tape image,
a head that is not UTF-8, a last line without its LF, a line past ``MAX_BLOCK``) read there."""

from __future__ import annotations

import pytest

from formats import _core
from formats.convert import (
    ConvertOptions,
    analyse_file_parameters,
    analyse_parameters,
    convert_file,
    convert_text,
)
from formats.errors import ConversionError, ParseError
from formats.parser import CHUNK, MAX_BLOCK
from formats.profile import load_profile
from formats.tape import encode

FANUC = load_profile("fanuc-mill")
LINUXCNC = load_profile("linuxcnc")
TO_INCH = ConvertOptions(FANUC, FANUC, units="inch")
# a body past one chunk, so the core reads, converts and writes it in several
LONG = "%\nO1000\nG21 G90\n" + "".join(f"G1 X{i % 997}.25 Y-{i % 89}.5 F300.\n"
                                     for i in range(CHUNK // 20)) + "M30\n%\n"


def _both(tmp_path, data: bytes, options: ConvertOptions):
    """(the file's conversion: its output's bytes and stats; the text's, encoded back)."""
    source = tmp_path / "in.nc"
    source.write_bytes(data)
    out = tmp_path / "out.nc"
    stats = convert_file(str(source), str(out), options, overwrite=True)
    text, text_stats = convert_text(data.decode("utf-8", "surrogateescape"), options,
                                    file=str(source))
    return (out.read_bytes(), stats), (text.encode("utf-8", "surrogateescape"), text_stats)


@pytest.mark.parametrize("data", [
    LONG.encode(),
    b"%\nO1000\nG21 G90\nG1 X1.5 Y2 F100.\nG1 X2.25",  # a last line without its LF
    b"%\r\nO1000\r\nG21\r\nG1 X1.5 F100.\r\nM30\r\n%\r\n",  # CRLF, kept
    b"",  # an empty file
    LONG.encode() + b"(caf\xe9 \xff)\nG1 X3.5\n",  # bytes that are not UTF-8 past the head
    b"%\n(Fr\xe4sen)\nG21\nG1 X1.5\nM30\n%\n",  # a head that is not UTF-8: Python reads it
    # a character cut at the first chunk's end
    b"G21\n" + b"G1 X1.5 Y2.5\n" * ((CHUNK - 5) // 13) + "(\u00e4\u00e4)\nG1 X1.\n".encode(),
], ids=["long", "no-last-lf", "crlf", "empty", "bad-bytes-late", "latin1-head", "cut-char"])
def test_a_file_converts_to_the_bytes_and_stats_of_its_text(tmp_path, data):
    (out, stats), (text, text_stats) = _both(tmp_path, data, TO_INCH)
    assert out == text
    assert (stats.blocks, stats.words, stats.changed, stats.notes, stats.rounding) == (
        text_stats.blocks, text_stats.words, text_stats.changed, text_stats.notes,
        text_stats.rounding)


def test_notes_of_every_chunk_are_said_in_order(tmp_path):
    """Notes made in the second chunk come after those of the first, as they are said."""
    data = ("G21\nG1 X[#<a>*1.]\n" + "G1 X1.5 Y2.5\n" * (CHUNK // 13)
            + "G1 Q[#<b>*2.]\n").encode()
    (out, stats), (text, text_stats) = _both(tmp_path, data, ConvertOptions(
        LINUXCNC, LINUXCNC, units="inch", allow_unconverted=True))
    assert out == text
    assert len(stats.notes) >= 2 and stats.notes == text_stats.notes
    assert "#<a>" in stats.notes[0] and any("#<b>" in note for note in stats.notes[1:])


def test_a_line_past_max_block_is_refused_where_the_text_refuses_it(tmp_path):
    for data in (b"G21\nG1 X1.\n(" + b"a" * (MAX_BLOCK + 10),  # no LF after it
                 b"G21\nG1 X1.\n(" + b"a" * (3 * CHUNK)):      # past a chunk, read by Python
        source = tmp_path / "in.nc"
        source.write_bytes(data)
        out = tmp_path / "out.nc"
        with pytest.raises(ParseError) as info:
            convert_file(str(source), str(out), TO_INCH)
        with pytest.raises(ParseError) as text_info:
            convert_text(data.decode(), TO_INCH, file=str(source))
        assert (info.value.line, str(info.value)) == (3, str(text_info.value))
        assert "longer than" in str(info.value)
        assert not out.exists() and [p.name for p in tmp_path.iterdir()] == ["in.nc"]


def test_a_refusal_in_a_later_chunk_leaves_no_output(tmp_path):
    """The first chunk was written to the temporary file before the second refused: nothing is
    left behind, and the refusal names its line as the text's does."""
    data = (LONG[:-len("M30\n%\n")] + "G1 X[#1+2.] F100.\nM30\n%\n").encode()
    source = tmp_path / "in.nc"
    source.write_bytes(data)
    out = tmp_path / "out.nc"
    with pytest.raises(ConversionError) as info:
        convert_file(str(source), str(out), TO_INCH)
    with pytest.raises(ConversionError) as text_info:
        convert_text(data.decode(), TO_INCH, file=str(source))
    assert info.value.line == text_info.value.line == data.count(b"\n") - 2
    assert str(info.value) == str(text_info.value)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.nc"]


def test_a_tape_image_is_read_by_python(tmp_path):
    program = "%\nO1000\nG21 G90\nG1 X1.5 Y2. F100.\nM30\n%\n"
    tape = tmp_path / "in.tap"
    tape.write_bytes(encode(program, "iso"))
    out = tmp_path / "out.nc"
    convert_file(str(tape), str(out), TO_INCH)
    assert out.read_text() == convert_text(program, TO_INCH)[0]


def test_has_parameters_reads_the_whole_file_and_fails_as_open_does(tmp_path):
    source = tmp_path / "in.nc"
    source.write_bytes(b"G1 X1.\n" * (CHUNK // 7) + b"#1=2.\n")  # in the second chunk
    assert _core.has_parameters(str(source))
    source.write_bytes(b"G1 X1.\n" * (CHUNK // 7))
    assert not _core.has_parameters(str(source))
    with pytest.raises(FileNotFoundError) as info:
        _core.has_parameters(str(tmp_path / "missing.nc"))
    assert info.value.strerror == "No such file or directory"
    with pytest.raises(IsADirectoryError):
        _core.has_parameters(str(tmp_path))


@pytest.mark.parametrize(("data", "lengths"), [
    # #101 set and read in the second chunk
    (b"%\nO1000\nG21\n#100=5.\n" + b"G1 X#100 Y2.5\n" * (CHUNK // 14)
     + b"#101=[#100*2]\nG1 Z#101\n", ["#100", "#101"]),
    (b"%\nO1000\nG21\n#100=5.\nG1 X#100", ["#100"]),  # a last line without its LF
    (b"%\n(Fr\xe4sen)\nG21\n#1=2.\nG1 X#1\n", ["#1"]),  # a head that is not UTF-8
], ids=["long", "no-last-lf", "latin1-head"])
def test_a_files_parameters_are_those_of_its_chunks(tmp_path, data, lengths):
    source = tmp_path / "in.nc"
    source.write_bytes(data)
    text = data.decode("utf-8", "surrogateescape")
    programs = analyse_file_parameters(str(source), FANUC).programs()
    assert programs == analyse_parameters([text[:CHUNK], text[CHUNK:]], FANUC).programs()
    assert programs[0][1] == lengths


def test_a_files_parameter_analysis_refuses_as_the_text_does(tmp_path):
    source = tmp_path / "in.nc"
    for data, line in ((b"G21\n#1=2.\nG1 X[#1+\n", 3),  # an expression that cannot be read
                       (b"G21\n#1=2.\n(" + b"a" * (3 * CHUNK), 3)):  # past MAX_BLOCK
        source.write_bytes(data)
        with pytest.raises(ParseError) as info:
            analyse_file_parameters(str(source), FANUC, file="in.nc")
        with pytest.raises(ParseError) as text_info:
            analyse_parameters([data.decode()], FANUC, file="in.nc")
        assert info.value.line == text_info.value.line == line
        assert str(info.value) == str(text_info.value)


def test_the_pending_file_counts_what_the_core_wrote(tmp_path):
    from formats.convert import Converter
    from formats.files import PendingFile

    data = LONG.encode() + b"G1 X2.25"  # the last line, without its LF, written by Python
    source = tmp_path / "in.nc"
    source.write_bytes(data)
    converter = Converter(TO_INCH, FANUC, file="in.nc")
    with PendingFile(tmp_path, "out.nc") as pending:
        converter.convert_file(str(source), FANUC.dialect, pending)
        path = pending.commit(tmp_path / "out.nc")
    expected = convert_text(data.decode(), TO_INCH)[0].encode()
    assert path.read_bytes() == expected and pending.size == len(expected)
