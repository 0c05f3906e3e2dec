"""Lathe, Haas and Okuma cycles whose words a units conversion once moved elsewhere.

Each program is small and of its control's documented form (docs/convert.md, "Words a code
gives another meaning" and "Word roles by cycle", with the sources): the converter scales the
depths, heights and pecks, keeps counts, angles and dwells, and refuses, at the word, what no
page at hand explains; ``--verify`` reads each word the same way.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from formats.convert import ConvertOptions, convert_file, convert_text
from formats.errors import ConversionError
from formats.profile import Profile, load_profile, profile_from_text
from postproc.check import check_text
from tapegate.cli import main


def convert(tmp_path: Path, text: str, source: str, units: str | None,
            name: str = "p.nc", target: str | None = None) -> str:
    """The program converted (verified) for ``target`` (its own profile by default)."""
    path = tmp_path / name
    path.write_text(text)
    out = tmp_path / f"out-{name}"
    options = ConvertOptions(load_profile(target or source), load_profile(source), units=units)
    convert_file(str(path), str(out), options, verify=True, overwrite=True)
    return out.read_text()


OKUMA = ("$L1.MIN%\nG21\nG00 X50. Z2.\nG85 NLAP1 D4. F0.3 U0.4 W0.1\nG87 NLAP1\n"
         "G88 NTHR1 H1.083 B60 D0.4 U0.05 F1.5\n"
         "G71 X27.835 Z-25. B60 D0.4 U0.05 H1.083 F1.5 J1 M32\n"
         "G183 X0 Z-30. D5. E0.5 F100.\n"
         "NLAP1 G81\nG00 X20. Z2.\nG01 Z-20. F0.2\nX40.\nG80\n"
         "NTHR1 G81\nG00 X28. Z2.\nG01 Z-20.\nG80\nM02\n")


def test_okuma_lap_thread_and_drilling_depths_convert_counts_and_dwells_stay(tmp_path):
    """5238-E: the LAP depth of cut D and thread height H are lengths (D4. stayed 4 in, a
    102 mm cut); the compound thread cycle's J counts threads (J1 became J0.0394, lead x25);
    the M-tool cycle's D is the peck, E the dwell in seconds (E0.5 became E0.02)."""
    out = convert(tmp_path, OKUMA, "okuma-lathe", "inch", name="l.min").splitlines()
    assert out[3] == "G85 NLAP1 D0.1575 F0.012 U0.0157 W0.0039"
    assert out[5] == "G88 NTHR1 H0.0426 B60 D0.0157 U0.002 F0.059"
    assert out[6] == "G71 X1.0959 Z-0.9843 B60 D0.0157 U0.002 H0.0426 F0.059 J1 M32"
    assert out[7] == "G183 X0 Z-1.1811 D0.1969 E0.5 F3.937"


def test_okuma_u_w_steps_add_up_to_the_converted_position(tmp_path):
    """An OSP lathe's U W are increments of X Z, tracked as Fanuc's and Haas's are: 20 steps
    of W-1. come to -0.7874 in (they were each W-0.0394 rounded: short or long by the rounding
    times 20). (No G21: on an OSP lathe it is a home position return; lengths in 0.0001 in,
    4203-E.)"""
    text = "$A.MIN%\nG00 X10. Z0\n" + "G01 W-1. F0.1\n" * 20 + "M02\n"
    out = convert(tmp_path, text, "okuma-lathe", "inch", name="a.min").splitlines()
    steps = [line.split()[1] for line in out if line.startswith("G01 W")]
    assert len(steps) == 20
    assert sum(round(float(s[1:]) * 10000) for s in steps) == -7874


def test_a_fanuc_lathe_s_drilling_cycles_peck_in_increments_and_count_repeats(tmp_path):
    """FANUC 0i-TF, "Canned cycle for drilling": Q the peck in least input increments (5 mm
    is Q1969 in 0.0001 in; it was Q197), K the number of repeats (it was K0, no hole)."""
    text = ("%\nO1\nG21 G98\nG0 X50. Z5. C0\nG83 X0 C0 Z-20. R-3. Q5000 P500 F100. K1\n"
            "G87 Z-10. C0 X20. R-5. Q3000 P300 F80.\nG80\nM30\n%\n")
    inch = convert(tmp_path, text, "fanuc-lathe", "inch")
    assert "G83 X0 C0 Z-0.7874 R-0.1181 Q1969 P500 F3.937 K1\n" in inch
    assert "G87 Z-0.3937 C0 X0.7874 R-0.1969 Q1181 P300 F3.1496\n" in inch
    # and back: 0.1969 in is 5.001 mm, a count of 0.001 mm (it was Q50013, 50 mm)
    back = convert(tmp_path, inch, "fanuc-lathe", "metric", name="back.nc")
    assert " Q5001 " in back and back.count(" K1") == 1
    # no change of units: every word as written (K1 was written K0.001)
    assert convert(tmp_path, text, "fanuc-lathe", None, name="same.nc") == text


def test_polar_interpolation_c_and_the_cylinder_s_h_are_lengths(tmp_path):
    """FANUC lathe G12.1 ... G13.1: C is the hypothetical axis, a length; G07.1 H is the
    cylinder's radius by C's incremental address; C after G13.1 is degrees again."""
    text = ("%\nO1\nG21 G98\nG0 X60. Z5. C0\nG12.1\nG42 G1 X40. F200.\nC10.\n"
            "G3 X20. C20. R10.\nG40 X60. C0\nG13.1\nG07.1 H57299\nG1 Z-10. C90. F100.\n"
            "G07.1 H0\nM30\n%\n")
    out = convert(tmp_path, text, "fanuc-lathe", "inch").splitlines()
    assert out[6:8] == ["C0.3937", "G3 X0.7874 C0.7874 R0.3937"]
    assert out[10:12] == ["G07.1 H2.2559", "G1 Z-0.3937 C90. F3.937"]


def test_a_haas_lathe_peck_keeps_its_decimals(tmp_path):
    """Haas lathe G83 Q: the peck with its point (Q2.5 mm was written Q0)."""
    text = "%\nO1\nG21 G98\nG00 X0 Z5.\nG83 Z-25. R2. Q2.5 F100.\nG80\nM30\n%\n"
    assert "G83 Z-0.9843 R0.0787 Q0.0984 F3.937\n" in convert(tmp_path, text, "haas-lathe",
                                                               "inch")


def test_a_haas_lathe_peck_s_least_depth_converts_as_a_length(tmp_path):
    """Haas lathe G83's K is the optional minimum depth of cut, a length, with or without I
    and J (Haas lathe operator's manual, G83 "End face peck drilling"): K0.05 inch is 1.27 mm
    in both blocks, not a FANUC repeat count kept as written (review 55a, F8); a FANUC lathe's
    G83 K is its number of repeats and stays as written, beside I and J too, which its G83 has
    not (0i-TF; review 56a, F3)."""
    text = ("%\nO1\nG20 G99\nG00 X0 Z0.2\nG83 Z-1. R0.1 Q0.1 K0.05 F0.005\nG80\n"
            "G83 Z-1. R0.1 I0.1 J0.02 K0.05 F0.005\nG80\nM30\n%\n")
    out = convert(tmp_path, text, "haas-lathe", "metric")
    assert "G83 Z-25.4 R2.54 Q2.54 K1.27 F0.127\n" in out
    assert "G83 Z-25.4 R2.54 I2.54 J0.508 K1.27 F0.127\n" in out
    fanuc = "%\nO1\nG20 G99\nG00 X0 Z0.2\nG83 Z-1. R0.1 Q1000 K3 F0.005\nG80\nM30\n%\n"
    assert " K3 " in convert(tmp_path, fanuc, "fanuc-lathe", "metric")
    beside = fanuc.replace("Q1000 K3", "I0.1 J0.02 K3")
    assert " J0.508 K3 " in convert(tmp_path, beside, "fanuc-lathe", "metric")
    # a count that is no whole number is refused, as on a FANUC mill (review 56d F10: K2.5 and
    # a Haas-style K1.27 beside I and J were carried and "verified"), in every drilling cycle
    for cycle in ("G83 Z-1. R0.1 Q1000 K2.5", "G85 Z-1. R0.1 K2.5",
                  "G83 Z-1. R0.1 I0.1 J0.02 K0.05"):
        text = fanuc.replace("G83 Z-1. R0.1 Q1000 K3", cycle)
        for profile in ("fanuc-lathe", "fanuc-lathe-b"):
            with pytest.raises(ConversionError) as info:
                convert(tmp_path, text, profile, "metric")
            word = cycle.split()[-1]
            assert (info.value.line, info.value.column) == (5, len(cycle) - len(word) + 1)
            assert str(info.value).split(": ", 1)[1].startswith(
                f"{word}: a canned cycle's repeat count that is not a whole number"), info.value


HAAS_ROUGHING = ("%\nO1\nG20 G99\nG00 X2.1 Z0.1\nG71 P10 Q20 U0.02 W0.005 D0.1 F0.012\n"
                 "N10 G00 X1.\nG01 Z-1.5 F0.005\nN20 X2.1\nG70 P10 Q20\nM30\n%\n")


def test_a_haas_one_block_cycle_s_depth_is_not_rounded_away(tmp_path):
    """G71 D0.1 (the Haas's depth of cut) was written D0 for a FANUC lathe; the cycle is now
    refused there (test_a_lathe_cycle_written_in_another_form_is_refused), and on a Haas its
    depth converts as a length."""
    out = convert(tmp_path, HAAS_ROUGHING, "haas-lathe", "metric")
    assert "G71 P10 Q20 U0.508 W0.127 D2.54 F0.305\n" in out


@pytest.mark.parametrize("profile, text, where, start", [
    # the turning tool's drilling cycle: D and E not explained by the pages at hand
    ("okuma-lathe", "$A.MIN%\nG21\nG00 X60. Z5.\nG73 X47. Z53. K2.79 D4 F0.1 E0.14\nM02\n",
     (4, 21), "D4: the source control's manual, as tapegate has it, does not say what D is"),
    # an OSP mill's cycle E: no mill manual at hand
    ("okuma-mill", "$A.MIN%\nG21\nG00 X0 Y0\nG82 X30. Y10. Z-10. R3. E0.5 F100.\nM02\n",
     (4, 25), "E0.5: the source control's manual"),
    # (a FANUC mill's G73 `K0.5` is its repeat count, no whole number: refused as such,
    # tests/test_check.py, review 56a F3; on a Haas the least peck depth, converted)
    # Haas M19 R: the orientation angle by what is known of the manual, no page at hand
    ("haas-mill", "%\nO1\nG20\nM19 R90.\nM30\n%\n", (4, 5), "R90.: the source control's"),
    # a lathe's C beside X in G01, no C axis shown: a chamfer or a move of C
    ("fanuc-lathe", "%\nO1\nG21 G99\nG0 X20. Z2.\nG1 Z0 F0.2\nX30. C1.\nM30\n%\n", (6, 6),
     "C1.: beside one of X or Z in a linear move, a lathe's C is the chamfer"),
    # a subprogram's S before its own G96/G97: surface speed or rpm by the caller
    ("haas-lathe", "%\nO1\nG20 G99\nG50 S3000\nG96 S500 M03\nM97 P100\nM30\nN100 G20\n"
                   "G01 X1.5 Z-1. S600 F0.01\nM99\n%\n", (9, 15),
     "S600: a spindle speed of a subprogram (it ends with M99 at line 10)"),
])
def test_what_no_page_explains_is_refused_at_its_word(tmp_path, profile, text, where, start):
    units = "metric" if "G20" in text else "inch"
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, text, profile, units, name="p.min" if "okuma" in profile else "p.nc")
    assert (info.value.line, info.value.column) == where
    assert str(info.value).split(": ", 1)[1].startswith(start), str(info.value)
    # --allow-unconverted leaves the unexplained word as written, but not the speed
    if "S600" not in start:
        path = tmp_path / "allow.nc"
        path.write_text(text)
        prof = load_profile(profile)
        out = tmp_path / "allow-out.nc"
        convert_file(str(path), str(out), ConvertOptions(prof, prof, units=units,
                                                         allow_unconverted=True),
                     verify=True, overwrite=True)
        assert start.split(":")[0] in out.read_text()


def test_haas_m97_is_refused_for_a_fanuc(tmp_path):
    """Haas M97 (local subprogram call) is FANUC's interrupt type custom macro off: the sub
    would be skipped; refused at the code, exit 1."""
    path = tmp_path / "h.nc"
    path.write_text("%\nO1\nG20 G90\nG00 X0 Y0\nM97 P1000 L2\nM30\nN1000 G91 G00 X1.\nG90\n"
                    "M99\n%\n")
    result = CliRunner().invoke(main, ["convert", str(path), "--from", "haas-mill", "--to",
                                       "fanuc-mill", "-o", str(tmp_path / "f.nc")],
                                catch_exceptions=False)
    assert result.exit_code == 1
    assert ("h.nc:5:1: M97: the source and target controls give this code different meanings "
            "(no modal group on the source, group \"interrupt macro\" on the target, by their "
            "profiles)") in result.output
    assert not (tmp_path / "f.nc").exists()


FANUC_THREAD_PASS = "%\nO1\nG00 X82. Z5.\nG97 S500 M03\nG32 Z-20. F2.\nG00 X90.\nM30\n%\n"
FANUC_ROUGHING = ("%\nO1\nG00 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.3\nN10 G00 X20.\n"
                  "G01 Z-10.\nN20 X50.\nG70 P10 Q20\nM30\n%\n")
OSP_COMPOUND = "O1\nG00 X30. Z5.\nG71 X27.4 Z-20. B60 D0.3 H1.3 L1. F2. J1 Q2\nM02\n"
OSP_THREAD = "O1\nG00 X30. Z5.\nG33 X27.4 Z-20. F2.\nG00 X50.\nM02\n"
FANUC_SUBPROGRAM = "%\nO1\nG21 G90\nG00 X0 Y0\nM98 P1000\nM30\n%\n"


@pytest.mark.parametrize("text, source, target, where, source_means, target_means", [
    (FANUC_THREAD_PASS, "fanuc-lathe", "okuma-lathe", "5:1: G32",
     "a single thread cutting move", "a face thread cutting cycle"),
    (FANUC_ROUGHING, "fanuc-lathe", "okuma-lathe", "4:1: G71",
     "a stock removal (roughing) cycle in turning",
     "a longitudinal multi-pass thread cutting cycle"),
    (OSP_COMPOUND, "okuma-lathe", "fanuc-lathe", "3:1: G71",
     "a longitudinal multi-pass thread cutting cycle",
     "a stock removal (roughing) cycle in turning"),
    (OSP_COMPOUND, "okuma-lathe", "haas-lathe", "3:1: G71",
     "a longitudinal multi-pass thread cutting cycle",
     "a stock removal (roughing) cycle in turning"),
    (OSP_COMPOUND.replace("G71", "G72").replace(" J1 Q2", ""), "okuma-lathe", "fanuc-lathe",
     "3:1: G72", "a face multi-pass thread cutting cycle",
     "a stock removal (roughing) cycle in facing"),
    # ISO 6983-1's G71 is no FANUC cycle: said as the table's code
    (OSP_COMPOUND, "okuma-lathe", "iso-lathe", "3:1: G71",
     "a longitudinal multi-pass thread cutting cycle",
     "the ISO 6983-1 table's code of that number"),
    (OSP_THREAD, "okuma-lathe", "iso-lathe", "3:1: G33",
     "a longitudinal thread cutting cycle", "a single thread cutting move"),
    # (Z alone before: a lathe's X, a diameter, is refused for a target that reads X as a
    # length, at the first X word)
    (OSP_THREAD.replace("G00 X30. Z5.", "G00 Z5."), "okuma-lathe", "linuxcnc", "3:1: G33",
     "a longitudinal thread cutting cycle", "a single thread cutting move"),
    (OSP_THREAD.replace("G00 X30. Z5.", "G00 Z5."), "okuma-lathe", "sinumerik-840d",
     "3:1: G33",
     "a longitudinal thread cutting cycle", "a single thread cutting move"),
])
def test_a_code_of_another_function_in_the_same_group_is_refused(
        tmp_path, text, source, target, where, source_means, target_means):
    """A code the OSP numbers as the FANUC and ISO tables do but gives a function of its own
    (a thread cycle for G32/G33/G71/G72, oil mist for M98) is refused at the code, naming both
    meanings, though both profiles put it in the same modal group."""
    path = tmp_path / "p.nc"
    path.write_text(text)
    out = tmp_path / "out.nc"
    result = CliRunner().invoke(main, ["convert", str(path), "--from", source, "--to", target,
                                       "-o", str(out)], catch_exceptions=False)
    assert result.exit_code == 1
    assert (f"p.nc:{where}: the source and target controls give this code different meanings "
            f"(\"{source_means}\" on the source, \"{target_means}\" on the target") \
        in result.output
    assert not out.exists()


@pytest.mark.parametrize("text, source, target, where, source_form, target_form", [
    # FANUC's first block: U the depth of cut, R the retract; a Haas reads U as the X
    # finishing allowance and takes its depth from D
    (FANUC_ROUGHING, "fanuc-lathe", "haas-lathe", "4:1",
     "stock removal in turning (U R / P Q U W F)\" with its words in FANUC's form",
     "O.D./I.D. stock removal cycle (P Q U W D F)\" with its words in Haas's form"),
    # Haas's one block: a FANUC's standard form has no D (its depth comes from parameter 5132)
    (HAAS_ROUGHING, "haas-lathe", "fanuc-lathe", "5:1",
     "O.D./I.D. stock removal cycle (P Q U W D F)\" with its words in Haas's form",
     "stock removal in turning (U R / P Q U W F)\" with its words in FANUC's form"),
    (FANUC_ROUGHING.replace("G71 U2. R0.5", "G72 W2. R0.5").replace("G71 P", "G72 P"),
     "fanuc-lathe", "haas-lathe", "4:1", "stock removal in facing\" with its words in FANUC's",
     "end face stock removal cycle\" with its words in Haas's form"),
    ("%\nO1\nG00 X32. Z5.\nG76 P021060 Q100 R0.05\nG76 X27.6 Z-30. P1200 Q300 F2.\nM30\n%\n",
     "fanuc-lathe", "haas-lathe", "4:1", "multiple threading cycle (P Q R / X Z R P Q F)\" with",
     "threading cycle, multiple pass (X Z K D F)\" with its words in Haas's form"),
    ("%\nO1\nG00 X0 Z2.\nG74 R0.5\nG74 Z-20. Q5000 F0.1\nM30\n%\n", "fanuc-lathe",
     "haas-lathe", "4:1", "end face peck drilling\" with its words in FANUC's form",
     "end face grooving cycle\" with its words in Haas's form"),
])
def test_a_lathe_cycle_written_in_another_form_is_refused(
        tmp_path, text, source, target, where, source_form, target_form):
    """A multiple repetitive cycle has one function on a FANUC and a Haas lathe, but FANUC
    0i-TF writes G71-G76 in two blocks and a Haas in one, with the same letters for other data
    (FANUC's first `G71 U2.` a 2 mm depth of cut, a Haas's U the finishing allowance): refused
    at the code both ways, naming both forms (docs/convert.md)."""
    path = tmp_path / "p.nc"
    path.write_text(text)
    out = tmp_path / "out.nc"
    result = CliRunner().invoke(main, ["convert", str(path), "--from", source, "--to", target,
                                       "-o", str(out)], catch_exceptions=False)
    assert result.exit_code == 1, result.output
    assert f"p.nc:{where}: G7" in result.output, result.output
    assert "the source and target controls give this code different meanings" in result.output
    assert source_form in result.output and target_form in result.output, result.output
    assert not out.exists()


def test_the_finishing_cycle_is_one_form_on_a_fanuc_and_a_haas():
    """G70 P Q (finish the contour of blocks P to Q) is one form on both (FANUC 0i-TF, Haas
    lathe manual G70): carried; LinuxCNC's G70 names its contour by an o-word (Q), refused."""
    text = "G18 G99\nG00 X50. Z2.\nG70 P10 Q20\nN10 G01 X20. F0.2\nN20 Z-10.\nM30\n"
    for source, target in (("fanuc-lathe", "haas-lathe"), ("haas-lathe", "fanuc-lathe")):
        out, _ = convert_text(text, ConvertOptions(load_profile(target), load_profile(source)))
        assert "G70 P10 Q20\n" in out
    with pytest.raises(ConversionError) as refused:
        # (Z alone before the cycle: a lathe's X is refused for LinuxCNC at the first X word)
        convert_text(text.replace("G18 G99", "G18").replace("G00 X50. Z2.", "G00 Z2."),
                     ConvertOptions(load_profile("linuxcnc"), load_profile("haas-lathe")))
    assert (refused.value.line, refused.value.column) == (3, 1), refused.value.message
    assert "with its words in LinuxCNC's form" in refused.value.message


def test_a_fanuc_subprogram_call_is_refused_for_an_osp(tmp_path):
    """An OSP calls by CALL O and reads M98 as oil mist on: the subprogram call is refused at
    the M98, by the rule for calls between families (which an M code's table comparison
    follows)."""
    path = tmp_path / "p.nc"
    path.write_text(FANUC_SUBPROGRAM)
    result = CliRunner().invoke(main, ["convert", str(path), "--from", "fanuc-mill", "--to",
                                       "okuma-mill", "-o", str(tmp_path / "out.nc")])
    assert result.exit_code == 1
    assert "p.nc:5:1: M98: a subprogram call or return on a Custom Macro B" in result.output
    assert "an Okuma by CALL" in result.output


@pytest.mark.parametrize("profile, units, peck", [
    ("fanuc-lathe", "G21", "Q2.5"), ("haas-lathe", "G20", "Q0.25")])
def test_a_pointed_g74_peck_is_a_length(tmp_path, profile, units, peck):
    """G74's Q counts least input increments without a point; written with one it is the length
    it writes: a conversion to the same profile leaves it byte for byte, a change of units
    scales it."""
    text = (f"%\nO1\n{units}\nG00 X0 Z2.\nG74 R1.\nG74 Z-10. {peck} F0.1\nG80\nM30\n%\n")
    path = tmp_path / "p.nc"
    path.write_text(text)
    same = tmp_path / "same.nc"
    result = CliRunner().invoke(main, ["convert", str(path), "--from", profile, "--to", profile,
                                       "-o", str(same), "--verify"], catch_exceptions=False)
    assert result.exit_code == 0, result.output
    assert same.read_text() == text
    if profile == "fanuc-lathe":
        inch = tmp_path / "inch.nc"
        result = CliRunner().invoke(main, ["convert", str(path), "--from", profile, "--to",
                                           profile, "--units", "inch", "-o", str(inch)],
                                    catch_exceptions=False)
        assert result.exit_code == 0, result.output
        assert "G74 Z-0.3937 Q0.0984 F0.0039\n" in inch.read_text()


def test_an_okuma_subprogram_speed_before_its_own_spindle_mode_is_refused(tmp_path):
    """An OSP subprogram (it ends with RTS) whose S comes before its own G96/G97 runs in its
    caller's spindle mode: under the main program's G96 its S150 is 150 m/min (492 ft/min),
    under G97 150 rpm; the text does not show which, so a change of units refuses it, as a
    Fanuc's or Haas's subprogram ending with M99; with its own G96 it converts."""
    text = ("O1\nG50 S2000\nG96 S200 M03\nCALL O2\nM02\nO2\nS150\nG01 X20. F0.1\nRTS\n")
    with pytest.raises(ConversionError) as refused:
        convert(tmp_path, text, "okuma-lathe", "inch", name="s.min")
    error = refused.value
    assert (error.line, error.column) == (7, 1)
    assert error.message == (
        "S150: a spindle speed of a subprogram (it ends with RTS at line 9) before the "
        "subprogram selects G96 or G97: it is a surface speed under the caller's G96, converted "
        "with the units, and revolutions per minute under G97, which the text does not show; "
        "write G96 or G97 in the subprogram before its first S")
    own = text.replace("O2\nS150", "O2\nG96 S150")
    out = convert(tmp_path, own, "okuma-lathe", "inch", name="own.min").splitlines()
    assert out[6] == "G96 S492"
    # without a change of units the speed is the same number either way
    assert convert(tmp_path, text, "okuma-lathe", None, name="keep.min") == text


HAAS_INCH = ("%\nO1\nG00 X1. Z0.1\nG97 S1000 M03\nG01 Z-1. F0.01\nG02 X1.5 Z-1.25 I0.25 K0.\n"
             "M30\n%\n")
OSP_METRIC = "O1000\nG50 S2000\nG00 X100. Z50.\nG96 S200 M03\nG01 X50. Z-20. F0.2\nM30\n"


def test_an_inch_program_to_a_units_parameter_control_verifies_in_inch(tmp_path):
    """A Haas lathe program (inch, its reset state) to an OSP lathe without --units: its
    lengths stay inch and the note says to set the machine to inch; --verify reads the output
    so, and verifies (it failed, reading X1. as 1 mm)."""
    path = tmp_path / "h.nc"
    path.write_text(HAAS_INCH)
    out = tmp_path / "h.min"
    result = CliRunner().invoke(main, ["convert", str(path), "--from", "haas-lathe", "--to",
                                       "okuma-lathe", "-o", str(out), "--verify"],
                                catch_exceptions=False)
    assert result.exit_code == 0, result.output
    assert "set the machine to inch before running it" in result.output
    assert "verified" in result.output
    assert "G00 X1. Z0.1\n" in out.read_text()


@pytest.mark.parametrize("target, units, note", [
    # converted: the note for the target's parameter says what the source was read in
    ("okuma-lathe", "inch",
     "no units code written: the target control selects its units by a machine parameter, not "
     "by a G code; every length from line 2 on is converted to inch: set the machine to inch "
     "before running it; the source was read in metric, the source profile's units: its "
     "control selects them by a machine parameter the program does not show"),
    # nothing converted (the units asked for are the profile's, or another family's control
    # in the same units): said too, an inch OSP program is not made metric by this
    ("okuma-lathe", "metric",
     "no length converted: the source was read in metric, the source profile's units: its "
     "control selects them by a machine parameter the program does not show; a program "
     "written for the machine set to the other units is not converted by this"),
    ("fanuc-lathe", None,
     "no length converted: the source was read in metric, the source profile's units: its "
     "control selects them by a machine parameter the program does not show; a program "
     "written for the machine set to the other units is not converted by this"),
])
def test_a_units_parameter_source_says_what_it_was_read_in(tmp_path, target, units, note):
    """An OSP lathe selects its units by a machine parameter: its program is read in the
    profile's (metric), which the text does not confirm, and every conversion where the units
    matter says so (an inch OSP program converted "back" to metric was a silent no-op)."""
    path = tmp_path / "o.min"
    path.write_text(OSP_METRIC)
    args = ["convert", str(path), "--from", "okuma-lathe", "--to", target, "-o",
            str(tmp_path / "out.nc")] + (["--units", units] if units else [])
    result = CliRunner().invoke(main, args, catch_exceptions=False)
    assert result.exit_code == 0, result.output
    assert f"o.min: {note}\n" in result.output


OSP_INCH = "O1000\nG50 S2000\nG00 X4. Z0.1\nG96 S600 M03\nG01 X3.5 Z-1. F0.01\nM30\n"


def test_the_units_an_osp_lathe_is_set_to_are_given_by_from_units(tmp_path):
    """An inch OSP lathe program (its machine's UNIT parameter set to inch, which nothing in
    the program shows) converted to a metric Fanuc lathe: with --from-units inch every length,
    the feed per revolution and the surface speed are scaled and G21 is written; without it the
    program is read in the profile's metric, nothing is converted, and the note says so;
    --verify says what it assumed."""
    path = tmp_path / "i.min"
    path.write_text(OSP_INCH)
    out = tmp_path / "i.nc"
    base = ["convert", str(path), "--from", "okuma-lathe", "--to", "fanuc-lathe", "--units",
            "metric", "-o", str(out), "--verify", "--force"]
    result = CliRunner().invoke(main, [*base, "--from-units", "inch"], catch_exceptions=False)
    assert result.exit_code == 0, result.output
    assert out.read_text().splitlines() == [
        "O1000", "G21 G50 S2000", "G00 X101.6 Z2.54", "G96 S183 M03",
        "G01 X88.9 Z-25.4 F0.254", "M30"]
    assert ("i.min: source: read in inch from the program's start, the units its machine "
            "parameter is set to (--from-units inch)\n") in result.output
    assert ("i.min: inserted G21: the source control selects its units by a machine parameter, "
            "not by a G code; the program was read in inch, the units given for its machine "
            "(--from-units)\n") in result.output
    assert "machine parameter the program does not show" not in result.output
    assert "assumed" not in result.output
    # without it: read as metric, written as it was, and said; the proof says what it assumed
    result = CliRunner().invoke(main, base, catch_exceptions=False)
    assert result.exit_code == 0, result.output
    assert out.read_text() == OSP_INCH
    assert ("i.min: no length converted: the source was read in metric, the source profile's "
            "units: its control selects them by a machine parameter the program does not show; "
            "a program written for the machine set to the other units is not converted by "
            "this\n") in result.output
    assert ("i.min: verified with the source read in metric, the source profile's units: its "
            "control selects them by a machine parameter the program does not show, so a "
            "program written for a machine set to the other units is not proved; give "
            "--from-units to say what the machine is set to\n") in result.output
    assert "verified (metric assumed)" in result.output


def test_from_units_is_the_start_units_where_the_profile_has_units_codes():
    """On a control with units codes --from-units gives the units before the program's first
    units code (the machine's setting at power-on); a units code in the program wins."""
    fanuc = load_profile("fanuc-mill")
    text = "%\nO1\nG00 X1. Y2.\nG21\nG00 X25.4\nM30\n%\n"
    options = ConvertOptions(fanuc, fanuc, units="metric", from_units="inch")
    out, stats = convert_text(text, options)
    assert out.splitlines()[2:5] == ["G21 G00 X25.4 Y50.8", "G21", "G00 X25.4"]
    assert stats.notes[0] == ("source: read in inch from the program's start, until a units "
                              "code of the program (--from-units inch)")
    # without it the profile's metric: nothing to convert
    out, _ = convert_text(text, ConvertOptions(fanuc, fanuc, units="metric"))
    assert out == text
    with pytest.raises(ConversionError) as refused:
        ConvertOptions(fanuc, fanuc, from_units="feet")
    assert refused.value.code == "conversion-option"


def test_no_verify_assumption_where_the_units_do_not_matter(tmp_path):
    """The same OSP lathe profile without a change of units reads the output as the source:
    nothing to assume, plain "verified"."""
    path = tmp_path / "m.min"
    path.write_text(OSP_METRIC)
    result = CliRunner().invoke(main, ["convert", str(path), "--from", "okuma-lathe", "--to",
                                       "okuma-lathe", "--dry-run", "--verify"],
                                catch_exceptions=False)
    assert result.exit_code == 0, result.output
    assert "assumed" not in result.output and "verified" in result.output


def test_a_sinumerik_cutting_rate_stays_in_the_basic_system_under_g70(tmp_path):
    """Probe P3-13: a SINUMERIK's G70/G71 set "all geometric parameters that directly refer to
    the workpiece" and leave the other values, the feed among them, in the basic system
    (802D sl Programming 8.2.3; 840D Fundamentals, "Inch or metric dimensions"): `G96 S200`
    (200 m/min on a metric machine) was written S656 under G70, 3.3 times the speed. It is
    kept, as F is, and --verify reads it so. Under G700/G710, which set the feed too, no source
    says whether the cutting rate follows: a surface speed converted there is refused."""
    src = "G18 G71 G90 G95\nG96 S200 M3\nG0 X50 Z2\nG1 Z-20 F0.2\nG97 S1000\nM30\n"
    profile = load_profile("sinumerik-840d")
    options = ConvertOptions(target=profile, source=profile, units="inch")
    out, _ = convert_text(src, options)
    assert out.splitlines()[:4] == ["G18 G70 G90 G95", "G96 S200 M3", "G0 X1.9685 Z0.0787",
                                    "G1 Z-0.7874 F0.2"]
    path = tmp_path / "sv.mpf"
    path.write_text(src)
    assert convert_file(str(path), str(tmp_path / "out.mpf"), options, verify=True).verified
    with pytest.raises(ConversionError) as refused:
        convert_text(src.replace("G71", "G710"), options)
    assert (refused.value.line, refused.value.column) == (2, 5)
    assert refused.value.message.startswith(
        "a surface speed (S under G96) where a SINUMERIK's G700/G710 set the feed's units")
    # a G96 S of another family converts with the units of lengths, as before
    fanuc = load_profile("fanuc-lathe")
    out, _ = convert_text("O1\nG21 G18\nG96 S200 M3\nG0 X50. Z2.\nM30\n",
                          ConvertOptions(target=fanuc, source=fanuc, units="inch"))
    assert out.splitlines()[2] == "G96 S656 M3"


PROFILES = Path(__file__).resolve().parents[1] / "formats" / "profiles"


def without_feed_per_revolution(name: str) -> Profile:
    """A built-in profile without its feed per revolution facility notes: its F format (per
    minute) then holds a feed per revolution too, as every profile's did before them."""
    text = (PROFILES / f"{name}.toml").read_text()
    text = re.sub(r" \(with feed per revolution facility, the F word becomes F0\d\d\)", "", text)
    return profile_from_text(text.replace(f'name = "{name}"', f'name = "{name}-per-minute"'))


@pytest.mark.parametrize(("src", "source", "target", "units", "at", "why"), [
    ("%\nO1\nG20 G90 G17 G95\nS8000 M3\nG0 X0 Y0 Z0.1\nG1 Z-0.1 F0.0002\nM30\n%\n", "fanuc-mill",
     "fanuc-mill-per-minute", "metric", (6, 10), "of 0.00508 mm/rev is written 0.01 by the "
     "target's F format (2 decimals) and changes by 0.00492 mm/rev, more than half of the "
     "0.001 mm"),
    ("%\nO1\nG20 G90 G17 G95\nS8000 M3\nG0 X0 Y0 Z0.1\nG1 Z-0.1 F0.000001\nM30\n%\n",
     "fanuc-mill", "fanuc-mill", "metric", (6, 10), "of 0.0000254 mm/rev is written 0 by the "
     "target's F format (4 decimals) and rounds to zero"),
    ("G18 G90 G95\nG71\nG0 X50 Z2\nG70\nG1 Z-1 F0.01\nG71\nG0 X60 Z5\nM30\n", "sinumerik-840d",
     "iso-lathe", None, (5, 8), "of 0.0003937 in/rev is written 0 by the target's F format "
     "(3 decimals) and rounds to zero"),
])
def test_a_feed_per_revolution_rounded_past_the_controls_increment_is_refused(
        src, source, target, units, at, why):
    """Probe P3-18: a G95 feed written at the per-minute feed format (FANUC F052, 0.01 mm):
    `F0.0002` in/rev (0.00508 mm/rev) became `F0.01`, twice the feed, and a smaller one `F0`,
    "ok". The control reads a feed per revolution to its least input increment (0.001 mm/rev
    at IS-B); a feed rounded to zero or by more than half of that is refused at its column. One
    the format holds within half an increment converts (0.2 mm/rev is 0.007874 in/rev, written
    0.0079 by the lathe's F044, 0.000026 off), and a feed per minute is not held to it."""
    to = (without_feed_per_revolution("fanuc-mill") if target.endswith("-per-minute")
          else load_profile(target))
    options = ConvertOptions(target=to, source=load_profile(source), units=units)
    with pytest.raises(ConversionError) as refused:
        convert_text(src, options)
    assert (refused.value.line, refused.value.column) == at
    assert refused.value.message.startswith("F: a feed per revolution (G95) " + why)
    fanuc = load_profile("fanuc-lathe")
    out, _ = convert_text("O1\nG21 G18 G95\nG0 X50. Z2.\nG1 Z-20. F0.2\nM30\n",
                          ConvertOptions(target=fanuc, source=fanuc, units="inch"))
    assert out.splitlines()[3] == "G1 Z-0.7874 F0.0079"
    # a feed per minute is not held to the increment: F10. in/min is 254 mm/min
    mill = load_profile("fanuc-mill")
    out, _ = convert_text("O1\nG20 G94\nG1 X1. F10.\nG1 X2. F0.0002\nM30\n",
                          ConvertOptions(target=mill, source=mill, units="metric"))
    assert out.splitlines()[2:4] == ["G1 X25.4 F254.", "G1 X50.8 F0.01"]


@pytest.mark.parametrize(("src", "units", "feed"), [
    # review 4, 11: no change of units, the feed as written (it was refused: F052's 2 decimals)
    ("%\nO1000\nG21 G90 G95\nS1000 M3\nG0 X0 Y0 Z5.\nG1 Z-5. F0.202\nM30\n%\n", "metric",
     "F0.202"),
    # 0.202 mm/rev is 0.0079528 in/rev: F024, 0.0000472 off, under half of 0.0001 in
    ("%\nO1000\nG21 G90 G95\nS1000 M3\nG0 X0 Y0 Z5.\nG1 Z-5. F0.202\nM30\n%\n", "inch",
     "F0.008"),
    # 0.0002 in/rev is 0.00508 mm/rev: F034 writes 0.0051 (it was 0.01, twice the feed, refused)
    ("%\nO1\nG20 G90 G17 G95\nS8000 M3\nG0 X0 Y0 Z0.1\nG1 Z-0.1 F0.0002\nM30\n%\n", "metric",
     "F0.0051"),
])
def test_a_fanuc_mill_feed_per_revolution_has_its_own_format(tmp_path, src, units, feed):
    """The FANUC 0i-F reads F per revolution to 0.0001 mm/rev (0.0001-500.0000 mm/rev), not
    to the 0.01 mm of a feed per minute: fanuc-mill's classification gives G95's F its own
    format by a facility note, F034 (F024 in inch), and the converter and the checker read a
    feed per revolution by it (docs/dialects.md)."""
    mill = load_profile("fanuc-mill")
    path = tmp_path / "feed.nc"
    path.write_text(src)
    out = tmp_path / "out.nc"
    stats = convert_file(str(path), str(out), ConvertOptions(target=mill, source=mill,
                                                             units=units), verify=True)
    assert stats.verified
    assert out.read_text().splitlines()[5].endswith(feed)
    assert not [f for f in check_text(src, mill) if f.rule == "TG208"]
    # past the per-revolution format's 4 decimals, and a feed per minute past its 2
    many = src.replace("F0.202", "F0.20256").replace("M30", "G94 F100.123\nM30")
    found = [(f.line, f.message) for f in check_text(many, mill) if f.rule == "TG208"]
    if "F0.20256" in many:
        assert [line for line, _ in found] == [6, 7]
        assert "the format F034 holds 4" in found[0][1]
        assert "the format F052 holds 2" in found[1][1]


@pytest.mark.parametrize("profile, name, text, limit, speed", [
    # OSP-P200L 5238-E: G50 S is the maximum spindle speed (it was converted as a surface
    # speed: G50 S2500 became S8202 rpm)
    ("okuma-lathe", "o.min", "$O1.MIN%\nG50 S2000\nG96 S150 M03\nG50 S2500\nG00 X50. Z2.\nM02\n",
     "G50 S2500", "G96 S492 M03"),
    # FANUC lathe: G50 S is the clamp
    ("fanuc-lathe", "f.nc", "%\nO1\nG21 G99\nG50 S2000\nG96 S150 M03\nG50 S2500\nM30\n%\n",
     "G50 S2500", "G96 S492 M03"),
    # LinuxCNC: G92 only offsets the coordinates; an S beside it is the speed in force, here
    # a surface speed (rs274ngc: S under G96 is feet or metres a minute)
    ("linuxcnc", "l.ngc", "G21 G90\nG96 D2000 S150 M03\nG92 X0 S200\nG0 X25.\nM2\n",
     "G92 X0 S656.167979", "G96 D2000 S492.125984 M03"),
])
def test_a_spindle_speed_limit_stays_in_rpm_and_a_speed_beside_a_g92_converts(
        tmp_path, profile, name, text, limit, speed):
    """An S that limits the spindle's speed is revolutions a minute in either units; the
    converter takes it by the check's and the restart's rule (``ModalSettings::s_limit``),
    where it once had its own: every G92 S was a clamp and an Okuma lathe's G50 S none."""
    out = convert(tmp_path, text, profile, "inch", name=name).splitlines()
    assert limit in out and speed in out
