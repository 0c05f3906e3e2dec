import pytest
from click.testing import CliRunner
from hypothesis import given
from hypothesis import strategies as st

from formats.errors import TapeError
from formats.tape import (
    EIA_TABLE,
    decode,
    detect,
    encode,
    encode_stream,
    identify,
    iso_byte,
    parity_bits,
)
from tapegate.cli import main


def test_iso_parity_examples_of_annex_a():
    assert [iso_byte(c) for c in "%\n\r01X\x13"] == [0xA5, 0x0A, 0x8D, 0x30, 0xB1, 0xD8, 0x93]


def test_eia_table_has_odd_parity_and_distinct_codes():
    assert all(parity_bits(b) % 2 == 1 for b in EIA_TABLE.values())
    assert len(set(EIA_TABLE.values())) == len(EIA_TABLE)
    assert EIA_TABLE["\n"] == 0x80 and EIA_TABLE["%"] == 0x0B


def test_detect_from_the_first_end_of_block():
    assert detect(encode("%\nN1 X1\n", "iso")) == "iso"
    assert detect(encode("%\nN1 X1\n", "eia")) == "eia"
    assert detect(b"%\nN1 X1\n") == "text"
    assert detect("%\n(Flaschenöffner)\nN1 X1\n".encode()) == "text"


def test_utf8_text_is_text_though_its_em_dash_holds_eias_end_of_block():
    assert detect("(PART 7 \u2014 OP 20)\nN1 X1\n".encode()) == "text"  # e2 80 94
    assert detect("(\u2014)".encode()[:-1]) == "text"  # cut inside its character at 64 KiB
    assert detect(encode("%\nC1\n", "iso")) == "iso"


def test_identify_says_binary_for_what_is_no_program_in_any_code():
    program = "%\nN1 G1 X1. Y2. F100\nN2 M30\n%\n" * 20
    tape = encode(program, "iso")
    assert identify(program.encode()) == ("text", 0)
    assert identify(tape) == ("iso", 0)
    assert identify(encode(program, "eia", leader=30)) == ("eia", 0)
    # a tape with a few parity errors is still a tape: decoding reports them
    damaged = bytearray(tape)
    for i in range(0, len(damaged), 100):
        damaged[i] ^= 0x80
    assert identify(bytes(damaged)) == ("iso", len(range(0, len(damaged), 100)))
    png = bytes.fromhex("89504e470d0a1a0a0000000d4948445200000010") + bytes(range(256))
    assert identify(png)[0] == "binary"
    assert identify(b"\x00\x01\x02\xff\xfe") == ("binary", 2)  # two controls in four bytes
    # Latin-1 comments are text, however short; UTF-16 (a NUL in every other byte) and a blank
    # tape (nothing but fill) are no program
    assert identify("(T1 Ø6 FRÄSER)\nN1 X1\n".encode("latin-1")) == ("text", 0)
    assert identify("%\nN1 G1 X1.\n".encode("utf-16-le"))[0] == "binary"
    assert identify(bytes(20000)) == ("binary", 20000)
    assert identify(bytes(100) + program.encode() + bytes(100)) == ("text", 0)  # leader
    # DOS's Ctrl-Z, DC2/DC4 of a punch dump, form feeds: text still
    assert identify(program.encode() + b"\x12\x14\x0c\x1a")[0] == "text"
    assert identify(b"") == ("text", 0)


def test_leader_trailer_and_erase_are_removed_and_counted():
    data = bytes(10) + encode("%\nN1 X1\n%\n", "iso") + b"\x7f\xff" + bytes(5)
    result = decode(data)
    assert result.text == "%\nN1 X1\n%\n" and result.fill == 17 and not result.issues


def test_every_parity_error_is_located_and_the_data_kept():
    data = bytearray(encode("%\nN10 X1\nN20 Y2\n", "iso"))
    data[3] ^= 0x80  # "1" of N10 loses its parity bit
    data[10] ^= 0x80  # "2" of N20
    result = decode(bytes(data))
    assert result.text == "%\nN10 X1\nN20 Y2\n"
    assert [(i.kind, i.offset, i.line, i.column) for i in result.issues] == [
        ("parity", 3, 2, 2), ("parity", 10, 3, 2)]


def test_eia_parity_error_and_illegal_code():
    data = bytearray(encode("N10 X1\n", "eia"))
    data[1] ^= 0x10  # track 5 lost on "1"
    data.insert(3, 0x0E)  # odd parity, but not an EIA code
    result = decode(bytes(data), "eia")
    assert [(i.kind, i.column) for i in result.issues] == [("parity", 2), ("illegal", 4)]
    assert result.text == "N10\ufffd X1\n"


def test_illegal_iso_control_code():
    result = decode(bytes([0xA5, 0x0A, 0x4E, 0x81, 0x0A]), "iso")
    assert result.issues[0].kind == "illegal" and result.issues[0].column == 2


def test_a_dos_end_of_file_mark_survives_the_round_trip(tmp_path):
    """A program ending with 0x1A after its last line: ISO carries SUB and decodes it as itself,
    so tape encode then decode gives back every byte (no U+FFFD, EF BF BD, in its place); EIA
    has no code for it and leaves it off, saying so; with text after it, refused, located."""
    program = "%\nO1\nG0 X1\nM30\n%\n\x1a"
    back = decode(encode(program, "iso"), "iso")
    assert back.text == program and not back.issues
    path = tmp_path / "eof.nc"
    path.write_bytes(program.encode("ascii"))
    runner = CliRunner()
    assert runner.invoke(main, ["tape", "encode", str(path), "-o", str(tmp_path / "t.iso")]
                         ).exit_code == 0
    assert runner.invoke(main, ["tape", "decode", str(tmp_path / "t.iso"), "-o",
                                str(tmp_path / "back.nc")]).exit_code == 0
    assert (tmp_path / "back.nc").read_bytes() == path.read_bytes()
    result = runner.invoke(main, ["tape", "encode", "--code", "eia", str(path), "-o",
                                  str(tmp_path / "t.eia")])
    assert result.exit_code == 0, result.output
    assert "1 characters from the DOS end of file (Ctrl-Z) on not carried" in result.output
    assert decode((tmp_path / "t.eia").read_bytes()).text == program[:-1]
    with pytest.raises(TapeError) as info:
        encode(program + "N9\n", "eia")
    assert (info.value.code, info.value.line, info.value.column) == ("tape-character", 6, 1)


@pytest.mark.parametrize("text, column", [("N1 X1=2\n", 6), ("N1\n:10 X1\n", 1),
                                          ("n1\n", 1)])
def test_characters_eia_cannot_carry(text, column):
    with pytest.raises(TapeError) as info:
        encode(text, "eia", file="p.nc")
    assert info.value.column == column and info.value.file == "p.nc"
    assert (info.value.code, info.value.clause) == ("tape-character", "Annex A")


def test_iso_refuses_non_ascii():
    with pytest.raises(TapeError) as info:
        encode("(ÖL)\n", "iso")
    assert (info.value.code, info.value.line, info.value.column) == ("tape-character", 1, 2)
    assert info.value.clause == "Annex A"


iso_text = st.text(alphabet=st.characters(min_codepoint=32, max_codepoint=126) | st.sampled_from(
    "\t\n\r"), max_size=200)
# EIA text: its '%' (ER, the rewind stop) only where a line starts
eia_text = st.lists(st.tuples(st.booleans(), st.text(
    alphabet=[c for c in EIA_TABLE if c not in "%\n"], max_size=40)), max_size=6).map(
    lambda lines: "".join(("%" if er else "") + line + "\n" for er, line in lines))


@given(iso_text)
def test_iso_round_trip(text):
    data = encode(text, "iso")
    assert all(parity_bits(b) % 2 == 0 for b in data)
    result = decode(data, "iso")
    assert result.text == text and not result.issues


@given(eia_text, st.integers(0, 20))
def test_eia_round_trip(text, leader):
    data = encode(text, "eia", leader=leader, trailer=leader)
    assert all(parity_bits(b) % 2 == 1 for b in data if b)
    assert decode(data, "eia").text == text


@given(st.binary(max_size=300), st.sampled_from(["iso", "eia", None]))
def test_decode_never_fails_on_random_bytes(data, code):
    result = decode(data, code)
    assert len(result.text) + result.fill == len(data)


def test_tape_codes_stream_and_still_locate_errors():
    """tape encode and decode work chunk by chunk (a 10 MB file of CRs peaked at 2.2 GB); an
    error in a later chunk, even in the middle of a line cut by a chunk, keeps its place."""
    import tracemalloc

    from formats.errors import TapeError
    from formats.tape import decode_stream, encode_stream

    text = "N1 X1.\nN2 Y2.\nN3 Z3 x\n"
    chunks = [text[i:i + 4] for i in range(0, len(text), 4)]  # "N3 Z" | "3 x\n"
    with pytest.raises(TapeError) as info:
        b"".join(encode_stream(chunks, "eia"))
    assert (info.value.code, info.value.line, info.value.column) == ("tape-character", 3, 7)
    tape = b"".join(encode_stream(iter(["N1 X1.\n"] * 3), "iso", leader=5))
    decoder, texts = decode_stream(iter([tape[:9], tape[9:]]))
    assert "".join(texts) == "N1 X1.\n" * 3 and decoder.fill == 5
    tracemalloc.start()
    for _ in encode_stream(("\r" * 100_000 for _ in range(20)), "eia"):
        pass
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert peak < 5_000_000  # 2 MB of input, encoded 100 kB at a time


def _reference_decode(data: bytes, code: str) -> tuple[str, list[tuple[str, int, int, int]], int]:
    """Byte by byte, as the spec reads: the text, the issues (kind, offset, line, column) and the
    fill count -- what the table-driven decoder must give exactly."""
    out, issues, fill, line, column = [], [], 0, 1, 1
    for offset, byte in enumerate(data):
        seven = byte & 0x7F if code == "iso" else byte
        if seven in (0x00, 0x7F):
            fill += 1
            continue
        if code == "iso":
            char = chr(seven)
            if parity_bits(byte) & 1:
                issues.append(("parity", offset, line, column))
            if seven < 0x20 and char not in "\t\n\r\x1a":
                issues.append(("illegal", offset, line, column))
                char = "\ufffd"
        else:
            decoded = {b: c for c, b in EIA_TABLE.items()}.get(byte)
            flipped = {b: c for c, b in EIA_TABLE.items()}.get(byte ^ 0x10)
            if decoded is None and flipped is not None and parity_bits(byte) % 2 == 0:
                issues.append(("parity", offset, line, column))
                decoded = flipped
            elif decoded is None:
                issues.append(("illegal", offset, line, column))
                decoded = "\ufffd"
            char = decoded
        out.append(char)
        line, column = (line + 1, 1) if char == "\n" else (line, column + 1)
    return "".join(out), issues, fill


@given(st.binary(max_size=400) | eia_text.map(lambda t: encode(t, "eia"))
       | iso_text.map(lambda t: encode(t, "iso")),
       st.sampled_from(["iso", "eia"]), st.lists(st.integers(0, 400), max_size=4))
def test_decoding_in_c_keeps_every_issue_at_its_byte_line_and_column(data, code, cuts):
    """The decoder translates runs of good bytes in C (it looped in Python over every byte:
    1.7 MB/s); the bytes that raise an issue are still taken one by one, so every position
    is the one the byte-by-byte reading gives, however the tape arrives in chunks."""
    from formats.tape import TapeDecoder

    points = sorted({min(c, len(data)) for c in cuts})
    chunks = [data[i:j] for i, j in zip([0, *points], [*points, len(data)], strict=True)]
    decoder = TapeDecoder(code)  # type: ignore[arg-type]
    text = "".join(decoder.feed(chunk) for chunk in chunks)
    assert (text, [(i.kind, i.offset, i.line, i.column) for i in decoder.issues],
            decoder.fill) == _reference_decode(data, code)


def test_decoding_streams_in_flat_memory():
    import tracemalloc

    from formats.tape import decode_stream

    tape = encode("N1 X1.\r\n" * 12_500, "iso")  # 100 kB
    tracemalloc.start()
    decoder, texts = decode_stream(tape for _ in range(20))
    size = sum(len(t) for t in texts)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert size == 2_000_000 and decoder.line == 250_001 and not decoder.issues
    assert peak < 2_000_000  # 2 MB of tape decoded 100 kB at a time


def _reference_detect(sample: bytes) -> str:
    """detect() as it was written byte by byte, before it counted in C."""
    try:
        sample.decode("utf-8")
        if any(b & 0x80 for b in sample):
            return "text"
    except UnicodeDecodeError as exc:
        if exc.reason == "unexpected end of data" and exc.end == len(sample):
            return "text"
    lf, eob = sample.find(b"\n"), sample.find(b"\x80")
    if eob >= 0 and (lf < 0 or eob < lf):
        return "eia"
    eia = {b for b in EIA_TABLE.values()}
    if (lf < 0 and all(b in eia or b in (0x00, 0x7F) for b in sample)
            and any(b in eia and b < 0x20 for b in sample)):
        return "eia"  # an EIA tape without an end of block
    if not any(b & 0x80 for b in sample):
        return "text"
    if all(parity_bits(b) % 2 == 0 for b in sample if b not in (0x00, 0x7F, 0xFF)):
        return "iso"
    even = sum(1 for b in sample if parity_bits(b) % 2 == 0)
    high = sum(1 for b in sample if b & 0x80)
    return "iso" if even > 0.9 * len(sample) and high > 0.1 * len(sample) else "text"


@given(st.binary(max_size=300) | iso_text.map(lambda t: encode(t, "iso"))
       | eia_text.map(lambda t: encode(t, "eia").replace(b"\x80", b""))
       | st.tuples(iso_text, st.binary(max_size=3)).map(lambda p: p[0].encode() + p[1]))
def test_detect_counts_in_c_as_it_counted_byte_by_byte(data):
    assert detect(data) == _reference_detect(data)
    assert detect(b"\t\n\nG\n\t\nG.\x80N") == "text"  # one odd high byte in 11: not a tape


def test_a_byte_that_is_no_utf8_is_named_as_it_is_in_the_file(tmp_path):
    """A Latin-1 degree sign in a comment was named '\\udcb0' (Python's surrogate escape) by
    tape encode; parse names it 0xB0, and so does the encoder now."""
    from formats.parser import decode_chunks

    text = "".join(decode_chunks([b"%\nN1 G1 X1. (\xb0C)\nM30\n%\n"]))
    with pytest.raises(TapeError) as info:
        b"".join(encode_stream([text], "iso", file="p.nc"))
    assert (info.value.code, info.value.file) == ("tape-character", "p.nc")
    assert (info.value.line, info.value.column) == (2, 12)
    assert info.value.message.startswith("byte 0xB0 (not ASCII or UTF-8 text")
    assert "udcb0" not in str(info.value)


def test_eia_refuses_a_percent_inside_a_block_where_its_er_would_stop_the_reader():
    """EIA has no '%': its ER, the rewind stop, is written for it; inside a comment it would
    stop the reader part-way through the program. A '%' that starts a line is the stop."""
    text = "%\nO1000 (FEED 50%)\nG00 X10.\nM30\n%\n"
    with pytest.raises(TapeError) as info:
        encode(text, "eia", file="t.nc")
    assert (info.value.line, info.value.column, info.value.file) == (2, 15, "t.nc")
    assert "rewind stop" in info.value.message
    for size in (1, 3, 7):  # the same place when the text arrives in chunks
        with pytest.raises(TapeError) as info:
            b"".join(encode_stream([text[i:i + size] for i in range(0, len(text), size)],
                                   "eia"))
        assert (info.value.line, info.value.column) == (2, 15), size
    tape = encode("%\nO1000 (FEED 50)\n%\n", "eia")
    assert tape.count(0x0B) == 2 and tape[0] == 0x0B and tape[-2] == 0x0B
    assert encode("N1 (50%)\n", "iso")  # ISO carries '%' as it is


def test_eia_writes_cr_line_ends_as_eob_and_counts_every_byte_it_does_not_carry():
    """EIA has no CR: CR next to LF is dropped (with the blanks between it and the LF, no
    text, as the sender leaves them), the CRs ending the text's last line become EOB; NUL and
    DEL go on the tape as fill. Each kind is counted, and the same whatever the chunks."""
    from formats.tape import EncodeNotes

    cases = {
        "%\nO1\nG0 X1.\r \t\nM30\n%\r\r": ("%\nO1\nG0 X1.\nM30\n%\n\n", EncodeNotes(3, 2, 0)),
        "%\nO1\nM30\n%\r \r": ("%\nO1\nM30\n%\n\n", EncodeNotes(1, 2, 0)),
        "%\r\nO1\r\nG0\r\n%\r\n": ("%\nO1\nG0\n%\n", EncodeNotes(4, 0, 0)),
        "X1\n\r\rY2\n": ("X1\nY2\n", EncodeNotes(2, 0, 0)),  # FANUC's LF CR CR
        "G0 X1.\x00\x7f\nM30\r": ("G0 X1.\nM30\n", EncodeNotes(0, 1, 2)),
    }
    for text, (back, counts) in cases.items():
        notes = EncodeNotes()
        tape = encode(text, "eia", notes=notes)
        assert notes == counts, text
        decoded = decode(tape)
        assert (decoded.code, decoded.text, decoded.fill) == ("eia", back, counts.fill)
        assert len(back) + counts.fill + counts.cr_by_lf == len(text)  # every byte is counted
        for size in (1, 2, 5):
            streamed = EncodeNotes()
            pieces = [text[i:i + size] for i in range(0, len(text), size)]
            assert b"".join(encode_stream(pieces, "eia", notes=streamed)) == tape
            assert streamed == counts, (text, size)
    notes = EncodeNotes()
    encode("G0\x00\r\n", "iso", notes=notes)  # ISO carries CR; NUL is fill all the same
    assert notes == EncodeNotes(0, 0, 1)


def test_eia_leaves_crs_after_a_dos_end_of_file_off_and_holds_long_runs_in_flat_memory():
    """CRs after the Ctrl-Z that ends the text are no part of the program (review 16a: one had
    become an EOB after the ER); a CR run of any length, blanks between, is held as counts."""
    from formats.tape import EncodeNotes

    text = "%\nO1\nM30\n%\x1a\r\n"
    for size in (1, 2, 100):
        notes = EncodeNotes()
        tape = b"".join(encode_stream([text[i:i + size] for i in range(0, len(text), size)],
                                      "eia", notes=notes))
        assert tape == encode("%\nO1\nM30\n%\n", "eia")[:-1], size  # the ER ends it
        assert notes == EncodeNotes(0, 0, 0, 3), size
    import tracemalloc

    def chunks():  # 4 MB of CR blank CR blank ... inside one line, 2 kB at a time
        yield "X1."
        for _ in range(2_000):
            yield "\r " * 1_000
        yield "\n"

    tracemalloc.start()
    notes = EncodeNotes()
    tape = b"".join(encode_stream(chunks(), "eia", notes=notes))
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert peak < 1_000_000 and notes.cr_by_lf == 4_000_000 and decode(tape).text == "X1.\n"


def test_eia_refuses_a_cr_with_text_after_it_in_its_line():
    """The check splits blocks at LF alone, as a FANUC does, and reads a line across a CR as one
    block; EIA's end of block, its only way to write a CR, would split that block (a comment
    left open, then ``) F50.``): refused at the CR, whatever the chunks, as the sender refuses
    it. A file whose lines end in CR alone is one block to the check, refused the same way."""
    cases = {
        "%\nO1\nG1 Z-5. (A B \r) F50.\nM30\n%\n": (3, 14),
        "%\rO1\rG0 X1.\rM30\r%\r": (1, 2),  # CR-only line ends
        "%\nG0 X1.\r \rY2.\n": (2, 7),  # blanks between CRs are no line end
        "%\nM30\r%": (2, 4),  # the last line too: the check reads 'M30 CR %' as one line
        "%\n\r\rG0 (A\r) F50.\n": (2, 8),  # the columns count LF CR CR's CRs, as send's do
        "%\nM30\r\x1aX": (2, 4),  # text after the Ctrl-Z: no end of file, the CR inside
    }
    for text, place in cases.items():
        with pytest.raises(TapeError) as info:
            encode(text, "eia")
        assert (info.value.line, info.value.column) == place, text
        assert "CR with text after it in its line" in info.value.message
        for size in (1, 2, 5):
            with pytest.raises(TapeError) as info:
                b"".join(encode_stream([text[i:i + size] for i in range(0, len(text), size)],
                                       "eia"))
            assert (info.value.line, info.value.column) == place, (text, size)
    assert decode(encode(next(iter(cases)), "iso"), "iso").text == next(iter(cases))  # ISO: kept


def test_tape_commands_say_what_the_tape_does_not_carry(tmp_path):
    runner = CliRunner()
    source = tmp_path / "t.nc"
    source.write_bytes(b"%\r\nO1000\r\nG00 X10. Y20.\r\nM30\r\n%\r")
    result = runner.invoke(main, ["tape", "encode", "--code", "eia", str(source), "-o",
                                  str(tmp_path / "t.tap")])
    assert result.exit_code == 0
    assert "4 CR next to LF (or blank after a line end's CR) not carried" in result.stderr
    assert "1 CR line ends written as EOB" in result.stderr
    result = runner.invoke(main, ["tape", "decode", str(tmp_path / "t.tap"), "-o",
                                  str(tmp_path / "back.nc")])
    assert result.exit_code == 0 and "EIA code" in result.output
    assert "every EOB decoded as LF" in result.stderr
    assert (tmp_path / "back.nc").read_bytes() == b"%\nO1000\nG00 X10. Y20.\nM30\n%\n"
    source.write_text("%\nO1000 (FEED 50%)\nM30\n%\n")
    result = runner.invoke(main, ["tape", "encode", "--code", "eia", str(source), "-o",
                                  str(tmp_path / "t.tap")])
    assert result.exit_code != 0 and "t.nc:2:15:" in result.stderr
    source.write_bytes(b"%\nO1000\nG1 Z-5. (A B \r) F50.\nM30\n%\n")
    result = runner.invoke(main, ["tape", "encode", "--code", "eia", str(source), "-o",
                                  str(tmp_path / "cr.tap")])
    assert result.exit_code != 0 and "t.nc:3:14: a CR with text after it" in result.stderr
    assert "Traceback" not in result.stderr and not (tmp_path / "cr.tap").exists()


def test_a_short_eia_tape_with_one_damaged_character_is_still_a_tape():
    tape = bytearray(encode("%\nO1000\nG00 X10. Y20.\nM30\n%\n", "eia"))
    tape[tape.index(EIA_TABLE["G"])] ^= 0x10  # one parity error in 28 bytes: 3.6 %
    assert identify(bytes(tape)) == ("eia", 1)
    assert decode(bytes(tape)).issues[0].kind == "parity"
    # an EIA tape with no end of block at all (written by a converter that dropped them) is
    # read as EIA, not as ISO text with a parity error in every other byte
    lost = encode("%\nO1000\nG00 X10.\n%\n", "eia").replace(b"\x80", b"")
    assert detect(lost) == "eia" and decode(lost).text == "%O1000G00 X10.%"
    assert detect(b"G00 X10.") == "text"


def test_the_message_names_the_reason_a_character_cannot_be_carried():
    with pytest.raises(TapeError) as info:
        encode("(Gew\u0161)\n", "iso")
    assert "no ASCII character" in info.value.message and "upper case" not in info.value.message
    with pytest.raises(TapeError) as info:
        encode("(gew)\n", "eia")
    assert "EIA carries upper case only" in info.value.message


@given(st.text(alphabet="%\r\n\x00\x7fG1 X.(:", max_size=60),
       st.lists(st.integers(0, 60), max_size=5))
def test_eia_in_chunks_encodes_and_refuses_as_the_whole_text(text, cuts):
    """CR runs cut between chunks, a '%' at a chunk's start inside a line: the tape, the
    counts and the error's place are those of the whole text."""
    from formats.tape import EncodeNotes

    points = sorted({min(c, len(text)) for c in cuts})
    chunks = [text[i:j] for i, j in zip([0, *points], [*points, len(text)], strict=True)]
    whole_notes, streamed_notes = EncodeNotes(), EncodeNotes()
    try:
        whole = encode(text, "eia", notes=whole_notes)
    except TapeError as exc:
        with pytest.raises(TapeError) as info:
            b"".join(encode_stream(chunks, "eia"))
        assert (info.value.line, info.value.column) == (exc.line, exc.column)
        return
    assert b"".join(encode_stream(chunks, "eia", notes=streamed_notes)) == whole
    assert streamed_notes == whole_notes
    back = decode(whole, "eia")
    assert len(back.text) + back.fill + whole_notes.cr_by_lf == len(text)


def test_eia_leaves_a_dos_end_of_file_off_and_refuses_text_after_it():
    """A DOS editor's Ctrl-Z after the closing % is no part of the program and EIA has no
    character for it: left off with what blanks follow it, and counted, whatever the chunks
    (ISO carries it as it is). Text after it is refused at the Ctrl-Z."""
    from formats.tape import EncodeNotes

    text = "%\nO1\nG0 X1.\nM30\n%\n\x1a"
    plain = encode("%\nO1\nG0 X1.\nM30\n%\n", "eia")
    for tail, dropped in [("", 1), ("\r\n", 3), ("\x1a\n", 3)]:
        for size in (1, 2, 5, 100):
            notes = EncodeNotes()
            pieces = [(text + tail)[i:i + size] for i in range(0, len(text + tail), size)]
            assert b"".join(encode_stream(pieces, "eia", notes=notes)) == plain, (tail, size)
            assert notes == EncodeNotes(0, 0, 0, dropped), (tail, size)
            assert "DOS end of file" in notes.lines()[0]
    assert decode(encode(text, "iso"), "iso").text == text  # ISO carries the byte
    for size in (1, 3, 100):
        with pytest.raises(TapeError) as info:
            b"".join(encode_stream([(text + "\nN9")[i:i + size]
                                    for i in range(0, len(text) + 3, size)], "eia"))
        assert (info.value.line, info.value.column) == (6, 1), size
        assert "'\\x1a' cannot be carried" in info.value.message
