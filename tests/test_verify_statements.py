"""`convert --verify` compares what statements and corner words carry, or says it does not.

The proof's reader read no statement: a `BHC X100` converted `BHC X3.937` and one left
`BHC X100` (25.4 times too far) both "verified". Now a statement's lengths are read by the
converter's own roles (`crates/core/src/meaning.rs`, read by `ncread::Reader::statement_words`)
and compared at the tolerance of a word; the rest of the statement as written; a statement
holding a number of no known role, read in other units in the output (left as written under
`--allow-unconverted`), is not compared, and the file is "partly verified" with its line.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from formats.conversion import ConvertOptions, ConvertStats
from formats.convert import convert_file
from formats.diff import BlockDiff, Differ, DiffOptions, diff_files
from formats.errors import ConversionError
from formats.profile import load_profile
from formats.verify import verify_conversion
from tapegate.cli import main

CORNERS = "O1000\nG21 G90 G17\nG01 X10. Y10. F100.\nX50. ,R5.\nY50. ,C2.5\nM30\n"
FRAMES = "G71 G90\nTRANS X10 Y20.5\nG0 X0 Y0\nG2 X20 Y0 CR=5\nROT Z45\nM30\n"
PATTERN = "G21 G90\nG0 X0 Y0 Z50\nG81 Z-5. R2. F100\nBHC X100 Y50 I50 J0 K6\nG80\nM02\n"


def converted(tmp_path: Path, text: str, profile: str, units: str, name: str,
              allow: bool = False) -> tuple[Path, Path, ConvertOptions, ConvertStats]:
    """The program converted to ``units`` on its own profile, verified."""
    source = tmp_path / name
    source.write_text(text)
    out = tmp_path / f"{units}-{name}"
    prof = load_profile(profile)
    options = ConvertOptions(prof, prof, units=units, allow_unconverted=allow)
    stats = convert_file(str(source), str(out), options, verify=True, overwrite=True)
    return source, out, options, stats


def proof(source: Path, output: Path, options: ConvertOptions, stats: ConvertStats
          ) -> ConvertStats:
    """The proof of ``output`` against ``source``, with the conversion's roundings."""
    fresh = ConvertStats(file=str(source), rounding=dict(stats.rounding))
    assert options.source is not None
    verify_conversion(str(source), str(output), options.source, options, fresh,
                      file=str(source))
    return fresh


@pytest.mark.parametrize("text, profile, name, right, wrong, line, message", [
    (CORNERS, "fanuc-mill", "c.nc", ",R0.1969", ",R0.1979", 4,
     ",R5. converts to 0.19685 but the output ,R0.1979 reads 0.1979"),
    (CORNERS, "fanuc-mill", "c.nc", ",C0.0984", ",C2.5", 5,
     ",C2.5 converts to 0.0984252 but the output ,C2.5 reads 2.5"),
    (FRAMES, "sinumerik-840d", "f.mpf", "TRANS X0.3937", "TRANS X0.3947", 2,
     "TRANS X10 converts to 0.393701 but the output TRANS X0.3947 reads 0.3947"),
    (FRAMES, "sinumerik-840d", "f.mpf", "CR=0.1969", "CR=5", 4,
     "CR=5 converts to 0.19685 but the output CR=5 reads 5"),
    (PATTERN, "okuma-mill", "p.min", "I1.9685", "I1.9695", 4,
     "BHC I50 converts to 1.9685 but the output BHC I1.9695 reads 1.9695"),
    (PATTERN, "okuma-mill", "p.min", "BHC X3.937", "BHC X100", 4,
     "BHC X100 converts to 3.93701 but the output BHC X100 reads 100"),
])
def test_a_statement_s_length_corrupted_fails_the_proof_at_its_line(
        tmp_path, text, profile, name, right, wrong, line, message):
    source, out, options, stats = converted(tmp_path, text, profile, "inch", name)
    assert stats.verified and not stats.not_compared
    written = out.read_text()
    assert right in written
    out.write_text(written.replace(right, wrong, 1))
    with pytest.raises(ConversionError) as caught:
        proof(source, out, options, stats)
    assert caught.value.line == line and message in str(caught.value)


@pytest.mark.parametrize("right, wrong", [
    ("J0 K6", "J0 K7"),  # a count kept as written
    ("J0 K6", "J1 K6"),  # an angle kept as written
    ("BHC X3.937", "BHC  X3.937"),  # the statement's text around its numbers
])
def test_a_pattern_s_count_or_angle_is_held_as_written(tmp_path, right, wrong):
    source, out, options, stats = converted(tmp_path, PATTERN, "okuma-mill", "inch", "p.min")
    out.write_text(out.read_text().replace(right, wrong, 1))
    with pytest.raises(ConversionError) as caught:
        proof(source, out, options, stats)
    assert caught.value.line == 4


def test_a_sinumerik_angle_statement_is_held_as_written(tmp_path):
    source, out, options, stats = converted(tmp_path, FRAMES, "sinumerik-840d", "inch", "f.mpf")
    assert "ROT Z45\n" in out.read_text()
    out.write_text(out.read_text().replace("ROT Z45", "ROT Z1.7717"))
    with pytest.raises(ConversionError) as caught:
        proof(source, out, options, stats)
    assert caught.value.line == 5


def test_in_the_same_units_a_statement_is_kept_byte_for_byte(tmp_path):
    """No change of units: the converter leaves statements alone, so `,R5.0` for `,R5.`
    (the same value) is a difference, as `G1` for `G01` is."""
    source, out, options, stats = converted(tmp_path, CORNERS, "fanuc-mill", "metric", "c.nc")
    assert out.read_text() == CORNERS and stats.verified
    out.write_text(CORNERS.replace(",R5.", ",R5.0"))
    with pytest.raises(ConversionError, match=r",R5\. is written ,R5\.0 in the output"):
        proof(source, out, options, stats)


def test_there_and_back_verifies(tmp_path):
    for text, profile, name in [(CORNERS, "fanuc-mill", "c.nc"),
                                (FRAMES, "sinumerik-840d", "f.mpf"),
                                (PATTERN, "okuma-mill", "p.min")]:
        _, out, _, stats = converted(tmp_path, text, profile, "inch", name)
        assert stats.verified
        _, _, _, back = converted(tmp_path, out.read_text(), profile, "metric", "b" + name)
        assert back.verified and not back.not_compared


def test_a_statement_the_proof_cannot_read_is_reported_not_verified(tmp_path):
    """CYCLE81's numbers have no role in the table: --allow-unconverted leaves them as
    written, and the proof says it did not compare them, with the line."""
    text = FRAMES.replace("ROT Z45\n", "ROT Z45\nCYCLE81(10,0,2,-5)\n")
    source, out, options, stats = converted(tmp_path, text, "sinumerik-840d", "inch", "f.mpf",
                                            allow=True)
    assert not stats.verified
    assert stats.not_compared == [(6, "CYCLE81(10,0,2,-5)")]
    assert any(n.startswith("line 6: statement 'CYCLE81(10,0,2,-5)' not compared")
               for n in stats.notes)
    # changed, it is a difference all the same
    out.write_text(out.read_text().replace("CYCLE81(10,0,2,-5)", "CYCLE81(10,0,2,-6)"))
    with pytest.raises(ConversionError) as caught:
        proof(source, out, options, stats)
    assert caught.value.line == 6


def test_the_summary_says_partly_verified_and_exits_0(tmp_path):
    source = tmp_path / "f.mpf"
    source.write_text(FRAMES.replace("ROT Z45\n", "CYCLE81(10,0,2,-5)\n"))
    result = CliRunner().invoke(main, [
        "convert", str(source), "-o", str(tmp_path / "o.mpf"), "--from", "sinumerik-840d",
        "--to", "sinumerik-840d", "--units", "inch", "--allow-unconverted", "--verify"])
    assert result.exit_code == 0, result.output
    assert "partly verified: 1 statement not compared" in result.output
    assert "line 5: statement 'CYCLE81(10,0,2,-5)' not compared" in result.output


def test_a_statement_without_numbers_or_in_the_same_units_verifies(tmp_path):
    """A statement holding no number (a label, a jump on parameters) or read in the same
    units on both sides is compared as written: verified."""
    text = "G71\nR1=5\nLAB1:\nG0 X=R1\nCYCLE81(10,0,2,-5)\nIF R1==R2 GOTOB LAB1\nM30\n"
    _, out, _, stats = converted(tmp_path, text, "sinumerik-840d", "metric", "n.mpf")
    assert out.read_text() == text and stats.verified and not stats.not_compared


def test_diff_compares_statements_whatever_the_spacing(tmp_path):
    """`tapegate diff` reads statements the same way: a BHC that differs is a difference (it
    took them for the same), blanks inside a statement are not."""
    okuma = load_profile("okuma-mill")
    a = tmp_path / "a.min"
    a.write_text(PATTERN)

    def found(text: str) -> list[BlockDiff]:
        b = tmp_path / "b.min"
        b.write_text(text)
        differ = Differ(DiffOptions(), okuma)
        return list(diff_files(str(a), str(b), okuma, okuma, differ.options, differ=differ))

    assert found(PATTERN.replace("BHC X100 Y50", "BHC  X100  Y50")) == []
    changed = found(PATTERN.replace("I50", "I3.937"))
    assert [d.a.line for d in changed if d.a is not None] == [4]
    assert found(PATTERN.replace("K6", "K7")) != []
