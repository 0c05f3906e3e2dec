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


@pytest.mark.parametrize("call", ["PCALL SUBA", "PCALL /_N_WKS_DIR/_N_SHAFT_WPD/SUBA",
                                  "MCALL SUBA"])
def test_every_sinumerik_call_form_that_names_the_subprogram_is_followed(tmp_path, call):
    """PCALL calls the named program, with or without its path (Programming Manual Job
    Planning, "Subprogram call with path specification"): SUBA runs in the caller's G70, so
    its X2.5 is 63.5 mm (review 8, finding 2: left as X2.5 mm and verified)."""
    out = convert(tmp_path, ARCHIVE.format(call=call, name="SUBA"), "sinumerik-840d", "metric",
                  "p.arc").splitlines()
    assert out[4] == f"N25 {call}" and out[8] == "N10 G90 G0 X63.5"


@pytest.mark.parametrize("call, column", [("CALL PNAME", 5), ('EXTCALL "SUBA"', 5),
                                          ('CALL "SU" << "BA"', 5)])
@pytest.mark.parametrize("spf_first", [False, True])
def test_a_sinumerik_call_the_converter_cannot_name_is_refused_at_the_call(tmp_path, call,
                                                                           column, spf_first):
    """A string variable (`CALL PNAME`, Job Planning "Indirect subprogram call"), a string
    expression or an EXTCALL (a program of external memory, maybe of a name of the file) may
    run the file's SUBA in the caller's units: refused at the call, whether the SPF comes
    after it or before; without a subprogram in the file the call is no concern."""
    main = f"%_N_MAIN_MPF\nN10 G70 G90\nN20 G0 X1 Y1\nN25 {call}\nN30 M30\n"
    sub = "%_N_SUBA_SPF\nN10 G90 G0 X2.5\nN20 M17\n"
    text = sub + main if spf_first else main + sub
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, text, "sinumerik-840d", "metric", "v.arc")
    assert (info.value.line, info.value.column) == (4 + 3 * spf_first, column)
    assert info.value.message.startswith(
        f"{call}: a call of a program the converter cannot name")
    assert "runs in the units of its call" in info.value.message
    alone = convert(tmp_path, main, "sinumerik-840d", "metric", "w.arc").splitlines()
    assert alone[1:4] == ["N10 G71 G90", "N20 G0 X25.4 Y25.4", f"N25 {call}"]


def test_a_sinumerik_subprogram_with_no_call_in_a_file_of_other_units_is_noted(tmp_path):
    """An SPF no recognised call reaches is read in the reset units; where the file's MPF
    selects others, the conversion says so at the SPF (it may be called from outside)."""
    text = ("%_N_MAIN_MPF\nN10 G70 G90\nN20 G0 X1 Y1\nN30 M30\n"
            "%_N_SUBA_SPF\nN10 G90 G0 X2.5\nN20 M17\n")
    source = tmp_path / "n.arc"
    source.write_text(text)
    prof = load_profile("sinumerik-840d")
    stats = convert_file(str(source), str(tmp_path / "n-mm.arc"),
                         ConvertOptions(prof, prof, units="metric"), verify=True)
    assert [n for n in stats.notes if "no call" in n] == [
        "line 5: the subprogram SUBA has no call in the file the converter recognises; it is "
        "read in metric, the units at its start, while a program of the file selects inch: "
        "called from there it would run in those"]
    # an MPF in the SPF's units: nothing to say
    source.write_text(text.replace("N10 G70 G90\nN20 G0 X1 Y1", "N10 G71 G90\nN20 G0 X25.4"))
    stats = convert_file(str(source), str(tmp_path / "n-in.arc"),
                         ConvertOptions(prof, prof, units="inch"), verify=True)
    assert [n for n in stats.notes if "no call" in n] == []


@pytest.mark.parametrize("proc", ["PROC SUBA SAVE", "PROC SUBA(REAL X1) SAVE DISPLOF"])
def test_a_save_subprogram_returns_its_caller_to_the_callers_units(tmp_path, proc):
    """Fundamentals, "Subprograms with SAVE mechanism": at the return the control restores the
    caller's modal G functions, G70/G71 among them, so N26 runs in inch again (review 8,
    finding 6: refused); without SAVE the G71 stays in force and the program is refused."""
    text = ("%_N_MAIN_MPF\nN10 G70 G90\nN20 G0 X1 Y1\nN25 SUBA\nN26 G0 X2\nN30 M30\n"
            f"%_N_SUBA_SPF\n{proc}\nN5 G71\nN10 G90 G0 X25.4\nN20 M17\n")
    out = convert(tmp_path, text, "sinumerik-840d", "metric", "s.arc").splitlines()
    assert out[1:5] == ["N10 G71 G90", "N20 G0 X25.4 Y25.4", "N25 SUBA", "N26 G0 X50.8"]
    assert out[7:10] == [proc, "N5 G71", "N10 G90 G0 X25.4"]
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, text.replace(proc, "PROC SUBA"), "sinumerik-840d", "metric", "t.arc")
    assert info.value.line == 11
    assert "the subprogram SUBA ends in metric" in info.value.message


def test_an_okuma_modal_call_runs_the_subprogram_in_its_callers_units(tmp_path):
    """MODIN OSUBA calls OSUBA after each move until MODOUT (OSP programming manual, "Modal
    call"): its peck of 0.5 in is 12.7 mm (review 8, finding 2: left as 0.5 mm, verified)."""
    text = ("$MAIN.MIN%\nG20\nG0 X1 Y1\nMODIN OSUBA\nG0 X2 Y2\nMODOUT\nM2\n"
            "OSUBA\nG91 G1 Z-0.5 F10\nG0 Z0.5\nG90\nRTS\n")
    out = convert(tmp_path, text, "okuma-mill", "metric", "m.min").splitlines()
    assert out[3:6] == ["MODIN OSUBA", "G0 X50.8 Y50.8", "MODOUT"]
    assert out[8:10] == ["G91 G1 Z-12.7 F254.", "G0 Z12.7"]
