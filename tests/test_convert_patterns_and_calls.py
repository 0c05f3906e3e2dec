"""Issue 32's audit, findings 1 and 2: conversions that were 25.4 times off and said "verified".

- An Okuma OSP hole pattern (`BHC`, `LAA`, `GRDX`/`GRDY`) has its words converted by their
  roles (the centre or reference point, the radius and pitches are lengths; the angle and the
  counts stay as written); a pattern whose words' roles the sources do not give (`ARC`,
  `SQRX`/`SQRY`) or a word given by a variable is refused at the word.
- A subprogram of the same file called by name (a SINUMERIK archive's SPF, an OSP subprogram
  after the main program) runs in its caller's units: read in them where its calls agree,
  refused where they differ or where the subprogram changes the units it returns in.

Each converted program is verified (`convert --verify`'s proof), and each refusal is located.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from formats.convert import ConvertOptions, convert_file
from formats.errors import ConversionError
from formats.profile import load_profile


def convert(tmp_path: Path, text: str, profile: str, units: str, name: str) -> str:
    """The program converted to ``units`` on its own profile, verified."""
    source = tmp_path / name
    source.write_text(text)
    out = tmp_path / f"{units}-{name}"
    prof = load_profile(profile)
    convert_file(str(source), str(out), ConvertOptions(prof, prof, units=units), verify=True,
                 overwrite=True)
    return out.read_text()


PATTERNS = ("$PAT.MIN%\nG21\nG15 H1\nG0 X0 Y0 Z50\nG81 R3 Z-10 F100\n{}\nG80\nM2\n")


@pytest.mark.parametrize("pattern, converted", [
    # centre X Y, radius I: lengths; J the first hole's angle, K the number of holes
    ("BHC X100 Y50 I50 J0 K6", "BHC X3.937 Y1.9685 I1.9685 J0 K6"),
    # reference point, pitch I (repeated with its count K), angle J
    ("LAA X10 Y10 I10 K2 I25.4 K3 J30", "LAA X0.3937 Y0.3937 I0.3937 K2 I1. K3 J30"),
    # reference point, pitches I J (negative: the other way), counts K P
    ("GRDX X10 Y10 I25.4 J-15 K4 P3", "GRDX X0.3937 Y0.3937 I1. J-0.5906 K4 P3"),
    ("GRDY X0 Y0 I50.8 J25.4 K2 P2", "GRDY X0 Y0 I2. J1. K2 P2"),
])
def test_an_okuma_hole_pattern_converts_its_lengths_by_role(tmp_path, pattern, converted):
    out = convert(tmp_path, PATTERNS.format(pattern), "okuma-mill", "inch", "pat.min")
    assert out.splitlines()[5] == converted
    assert out.splitlines()[4] == "G81 R0.1181 Z-0.3937 F3.937"
    # and back: the same numbers in millimetres (to the target's 1 µm)
    back = convert(tmp_path, out, "okuma-mill", "metric", "back.min")
    assert back.splitlines()[1] == "G21"


@pytest.mark.parametrize("pattern, column, word", [
    ("ARC X100 Y50 I50 J0 P30 K4", 14, "ARC's word I"),
    ("SQRX X10 Y10 I20 J20 P3 K2", 14, "SQRX's word I"),
    ("SQRY X10 Y10 I20 J20 P3 K2", 14, "SQRY's word I"),
    ("BHC X100 Y50 I50 J0 K6 Q1", 24, "BHC's word Q"),
])
def test_an_okuma_pattern_of_undocumented_words_is_refused_at_the_word(
        tmp_path, pattern, column, word):
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, PATTERNS.format(pattern), "okuma-mill", "inch", "pat.min")
    assert (info.value.line, info.value.column) == (6, column)
    assert f"the sources at hand do not give the role of {word}" in info.value.message
    # without a change of units the pattern is carried as written
    prof = load_profile("okuma-mill")
    source = tmp_path / "same.min"
    source.write_text(PATTERNS.format(pattern))
    convert_file(str(source), str(tmp_path / "out.min"), ConvertOptions(prof, prof),
                 verify=True, overwrite=True)
    assert (tmp_path / "out.min").read_text() == PATTERNS.format(pattern)


def test_an_okuma_pattern_word_given_by_a_variable_is_refused(tmp_path):
    text = PATTERNS.format("BHC X=XPOS Y50 I50 J0 K6")
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, text, "okuma-mill", "inch", "pat.min")
    assert (info.value.line, info.value.column) == (6, 5)
    assert "BHC's word X is no plain number" in info.value.message


ARCHIVE = ("%_N_MAIN_MPF\n;$PATH=/_N_MPF_DIR\nN10 G70 G90\nN20 G0 X1 Y1\nN25 {call}\nN30 M30\n"
           "%_N_{name}_SPF\n;$PATH=/_N_SPF_DIR\nN10 G90 G0 X2.5\nN30 M17\n")


@pytest.mark.parametrize("call, name", [("SUBA", "SUBA"), ('CALL "SUBA"', "SUBA"),
                                        ("L100", "L100")])
def test_a_sinumerik_subprogram_runs_in_its_callers_units(tmp_path, call, name):
    """SUBA runs in the G70 of its caller: its X2.5 is 2.5 in = 63.5 mm (it was left as
    X2.5, read as mm, and verified)."""
    text = ARCHIVE.format(call=call, name=name)
    out = convert(tmp_path, text, "sinumerik-840d", "metric", "a.arc").splitlines()
    assert out[2:4] == ["N10 G71 G90", "N20 G0 X25.4 Y25.4"]
    assert out[8] == "N10 G90 G0 X63.5"
    # a subprogram that selects its own units is read in them
    own = text.replace("N10 G90 G0 X2.5", "N5 G70\nN10 G90 G0 X2.5")
    out = convert(tmp_path, own, "sinumerik-840d", "metric", "b.arc").splitlines()
    assert out[8:10] == ["N5 G71", "N10 G90 G0 X63.5"]


def test_a_sinumerik_subprogram_called_in_two_units_is_refused(tmp_path):
    text = ("%_N_MAIN_MPF\nN10 G70 G90\nN20 SUBA\nN30 G71\nN40 SUBA\nN50 M30\n"
            "%_N_SUBA_SPF\nN10 G90 G0 X2.5\nN20 M17\n")
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, text, "sinumerik-840d", "metric", "c.arc")
    assert (info.value.line, info.value.column) == (8, 12)
    assert "called on line 3 in inch and on line 5 in metric" in info.value.message


def test_a_sinumerik_subprogram_before_its_call_in_other_units_is_refused_at_the_call(tmp_path):
    text = ("%_N_SUBA_SPF\nN10 G90 G0 X25.4\nN20 M17\n"
            "%_N_MAIN_MPF\nN10 G70 G90\nN20 G0 X1 Y1\nN30 SUBA\nN40 M30\n")
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, text, "sinumerik-840d", "metric", "d.arc")
    assert (info.value.line, info.value.column) == (7, 5)
    assert "reads its first values in metric" in info.value.message
    assert "here inch" in info.value.message
    # an SPF that selects its units first reads its values in them; it returns in them too,
    # so a call in those units converts and a call in other units is refused (its caller
    # would go on in the SPF's units)
    fixed = text.replace("N10 G90 G0 X25.4", "N5 G70\nN10 G90 G0 X1.")
    out = convert(tmp_path, fixed, "sinumerik-840d", "metric", "e.arc").splitlines()
    assert out[1:3] == ["N5 G71", "N10 G90 G0 X25.4"] and out[5] == "N10 G71 G90"
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, fixed.replace("N10 G70 G90", "N10 G71 G90"), "sinumerik-840d",
                "inch", "e2.arc")
    assert (info.value.line, info.value.column) == (8, 5)
    assert "ends in inch, its own units code's" in info.value.message


def test_a_subprogram_that_returns_in_other_units_is_refused(tmp_path):
    text = ("%_N_MAIN_MPF\nN10 G70 G90\nN20 SUBA\nN25 G0 X1\nN30 M30\n"
            "%_N_SUBA_SPF\nN5 G71\nN10 G90 G0 X25.4\nN20 M17\n")
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, text, "sinumerik-840d", "metric", "f.arc")
    assert info.value.line == 9
    assert "the subprogram SUBA ends in metric" in info.value.message


def test_an_archive_part_program_still_starts_from_the_reset_state(tmp_path):
    """An MPF is a program of its own: no call makes it a subprogram here."""
    text = ("%_N_A_MPF\nN10 G70 G90\nN20 G0 X1\nN30 M30\n"
            "%_N_B_MPF\nN10 G71 G90\nN20 G0 X25.4\nN30 M30\n")
    out = convert(tmp_path, text, "sinumerik-840d", "metric", "g.arc").splitlines()
    assert out[1:3] == ["N10 G71 G90", "N20 G0 X25.4"] and out[5:7] == ["N10 G71 G90",
                                                                        "N20 G0 X25.4"]


def test_an_okuma_subprogram_after_the_main_program_runs_in_its_units(tmp_path):
    """On an OSP the unit system is the machine's, which the main program's G20 confirms: the
    subprogram after M2 is in inch too (its X25.4 was left as written and verified)."""
    text = "$MAIN.MIN%\nG20\nG0 X1 Y1\nCALL OSUBA\nM2\nOSUBA\nG90 G0 X2.5\nRTS\n"
    out = convert(tmp_path, text, "okuma-mill", "metric", "m.min").splitlines()
    assert out[1:3] == ["G21", "G0 X25.4 Y25.4"]
    assert out[5:8] == ["OSUBA", "G90 G0 X63.5", "RTS"]
    # called in two units: refused at the subprogram's first value
    two = text.replace("CALL OSUBA\n", "CALL OSUBA\nG21\nCALL OSUBA\n")
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, two, "okuma-mill", "metric", "n.min")
    assert (info.value.line, info.value.column) == (9, 8)
    assert "called on line 4 in inch and on line 6 in metric" in info.value.message


def test_an_okuma_pattern_where_the_units_are_not_known_is_refused(tmp_path):
    """A jump brings inch to the label, the straight path metric: the pattern's lengths are
    read in one or the other, so it is refused at the statement, as a length word is."""
    text = ("$F.MIN%\nG20\nG0 X0 Y0 Z2.\nIF [VC1 EQ VC2] NLBL\nG21\nNLBL\n"
            "BHC X100 Y50 I50 J0 K6\nM2\n")
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, text, "okuma-mill", "metric", "f.min")
    assert (info.value.line, info.value.column) == (7, 1)
    assert "the jump on line 4 to NLBL comes here in inch" in info.value.message
