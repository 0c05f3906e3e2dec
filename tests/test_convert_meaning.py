"""Conversions that must not move the machine elsewhere: what the control reads is kept, or the
conversion is refused with a located reason (docs/convert.md, "What a word means").

Each program here is the smallest one that showed a wrong conversion: a G91 path across a
units code, counts and selectors of cycles written without a point, values with a point that
the conversion does not scale.
"""

from __future__ import annotations

import pytest

from formats.convert import ConvertOptions, convert_file, convert_text
from formats.errors import ConversionError
from formats.profile import load_profile

from .conftest import CORPUS, ISO_MACROS, profile


def convert(text: str, source: str, target: str | None = None, **kw) -> str:
    src = profile(source)
    dst = profile(target or source)
    out, _ = convert_text(text, ConvertOptions(target=dst, source=src, **kw))
    return out


def test_an_increment_after_a_units_code_moves_from_the_place_reached():
    """The machine keeps its place through G20/G21; the increment after it is in the new
    units: 10 mm, +1 in (35.4 mm), +1 mm (36.4 mm = 1.43307 in, written from 1.3937 in as
    +0.0394)."""
    src = "O1\nG21 G91\nG0 X10.\nG20\nX1.\nG21\nX1.\nM30\n"
    assert convert(src, "fanuc-mill", units="inch").splitlines()[2:] == [
        "G0 X0.3937", "G20", "X1.", "G20", "X0.0394", "M30"]
    back = "O1\nG20 G91\nG0 X1.\nG21\nX10.\nG20\nX1.\nM30\n"
    assert convert(back, "fanuc-mill", units="metric").splitlines()[2:] == [
        "G0 X25.4", "G21", "X10.", "G21", "X25.4", "M30"]
    # LinuxCNC reads G91 across G20/G21 the same way (rs274 -g: X 10 mm, 1.3937 in, 36.4 mm)
    ngc = "G21 G91\nG0 X10\nG20\nX1\nG21\nX1\nM2\n"
    assert convert(ngc, "linuxcnc", units="inch").splitlines()[-2] == "X0.03937"
    # without a change of units the program is kept as written
    assert convert(src, "fanuc-mill") == src


@pytest.mark.parametrize("profile, line, word", [
    # FANUC 0i-MF canned cycles: K the number of repeats
    ("fanuc-mill", "G81 X20. Y20. Z-5. R2. K2 F100.", "K2"),
    ("fanuc-mill", "G98 G83 X10. Y10. Z-20. R2. Q5. F100. K3", "K3"),
    # FANUC 0i-TF G73 first block: R the number of divisions
    ("fanuc-lathe", "G73 U5. W2. R3", "R3"),
    # Haas lathe G76 A the tool nose angle, "do not use a decimal point"; G71 R1 the type II
    # roughing selector
    ("haas-lathe", "G76 X0.9 Z-1. K0.06 D0.01 F0.0625 A60", "A60"),
    ("haas-lathe", "G71 P10 Q20 U0.02 W0.005 D0.1 F0.01 R1", "R1"),
    # Haas G84 J the retract multiple
    ("haas-mill", "G84 Z-0.5 R0.1 J2 F25.", "J2"),
])
def test_a_count_or_selector_of_a_cycle_is_kept_whole(profile, line, word):
    inch = profile.startswith("haas")
    text = f"O1\n{'G20' if inch else 'G21'}\n{line}\nM30\n"
    assert convert(text, profile) == text
    out = convert(text, profile, units="metric" if inch else "inch").splitlines()[2]
    assert word in out.split(), out


def test_the_repeat_count_stays_a_count_and_the_lengths_convert():
    out = convert("O1\nG21\nG81 X20. Y20. Z-5. R2. K2 F100.\nM30\n", "fanuc-mill", units="inch")
    assert out.splitlines()[2] == "G81 X0.7874 Y0.7874 Z-0.1969 R0.0787 K2 F3.937"
    # a Haas G83's I J K are peck depths, lengths
    out = convert("O1\nG20\nG83 Z-1. I0.2 J0.05 K0.1 R0.1 F10.\nM30\n", "haas-mill",
                  units="metric")
    assert out.splitlines()[2] == "G83 Z-25.4 I5.08 J1.27 K2.54 R2.54 F254."


@pytest.mark.parametrize("profile, line", [
    ("haas-mill", "G51 X0 Y0 P1.5"),     # Haas G51 P: the scale factor, 0.001 to 999.999
    # (a dwell's P with a point, seconds, is written in milliseconds: test_convert_review9)
])
def test_a_value_with_a_point_the_conversion_does_not_scale_is_kept(profile, line):
    inch = profile.startswith("haas")
    text = f"O1\n{'G20' if inch else 'G21'}\n{line}\nM30\n"
    assert convert(text, profile).splitlines()[2] == line
    p = line.split()[-1]
    out = convert(text, profile, units="metric" if inch else "inch").splitlines()[2]
    assert p in out.split(), out


def test_a_lathe_s_increments_are_written_from_rounded_positions():
    """A Fanuc lathe's U W are increments of X Z by their letter: 20 x W-1. is -20 mm =
    -0.7874 in exactly, not 20 x -0.0394 = -0.788 (each step rounded on its own)."""
    text = "O1\nG21\nG0 X10. Z0\n" + "G1 W-1. F0.1\n" * 20 + "M30\n"
    out = convert(text, "fanuc-lathe", units="inch")
    steps = [line.split()[1] for line in out.splitlines() if line.startswith("G1 W")]
    assert len(steps) == 20 and set(steps) == {"W-0.0394", "W-0.0393"}
    assert sum(float(s[1:]) for s in steps) == pytest.approx(-0.7874, abs=1e-9)
    # in a turning cycle the U W are the cycle's (the tool returns): each converted alone
    cycle = "O1\nG21\nG0 X50. Z2.\nG90 U-2. W-20. F0.2\nU-4.\nU-6.\nG0 X60.\nM30\n"
    assert convert(cycle, "fanuc-lathe", units="inch").splitlines()[3:6] == [
        "G90 U-0.0787 W-0.7874 F0.0079", "U-0.1575", "U-0.2362"]


def test_a_lathe_conversion_with_increments_verifies(tmp_path):
    from click.testing import CliRunner

    from tapegate.cli import main
    src, out = tmp_path / "p.nc", tmp_path / "o.nc"
    src.write_text("O1\nG21\nG0 X10. Z0\n" + "G1 W-1. F0.1\n" * 20 + "G1 U1.\nM30\n")
    result = CliRunner().invoke(main, ["convert", str(src), "-o", str(out), "--from",
                                       "fanuc-lathe", "--to", "fanuc-lathe", "--units", "inch",
                                       "--verify"])
    assert result.exit_code == 0, result.output
    assert "verified" in result.output


@pytest.mark.parametrize("source, system", [
    ("fanuc-lathe", "A"), ("haas-lathe", "A"), ("fanuc-lathe-b", "B"), ("fanuc-lathe-c", "C")])
def test_a_thread_written_with_increments_carries_its_rounding_and_verifies(tmp_path, source,
                                                                           system):
    """Review 59c F7: a G32's U W are the end point's increments, as a G01's (FANUC 0i-TF,
    "Thread cutting G32"): their rounding is carried on X Z (`W-0.7875` from Z0.1969 ends at
    -15 mm within half a step, as G01's), and --verify reads them as moves; a thread
    written with W failed it ("then position Z -15 mm -> -14.9987 mm") under any change of
    units.

    Review 60, F2: in G code system B and C (threading G33, mm G21 and G71), where no manual
    at hand says U and W are increments of X and Z (docs/dialects.md), the converter carried
    them as system A's and --verify read them each on its own: `G33 W-20.` to inch (since
    lathe59b) and `G01 W-20.` (before it) FAILED ("W-20. converts to -0.787402 but the output
    W-0.7875 reads -0.7875"). Both read them by one rule now (`convert::UwMoves`): in B and C
    each converted on its own (`W-0.7874`), noted once, and verified."""
    from click.testing import CliRunner

    from tapegate.cli import main
    thread, mm, per_rev = {"A": ("G32", "G21", "G99"), "B": ("G33", "G21", "G95"),
                           "C": ("G33", "G71", "G95")}[system]
    text = (f"%\nO1\n{mm} {per_rev}\nG00 X30. Z5.\n{thread} W-20. F1.5\nG00 X30. Z5.\n"
            f"{thread} U-1. W-20.\nW-5.\nG00 X30. Z5.\nG01 W-20. F0.2\nM30\n%\n")
    out = convert(text, source, units="inch").splitlines()
    # system A: carried on Z (from Z0.1969, the end -15 mm within half a step, and W-5.
    # from there); B and C: each on its own
    w, w5 = ("W-0.7875", "W-0.1968") if system == "A" else ("W-0.7874", "W-0.1969")
    assert [line.split(" F")[0] for line in out[4:10]] == [
        f"{thread} {w}", "G00 X1.1811 Z0.1969", f"{thread} U-0.0394 {w}", w5,
        "G00 X1.1811 Z0.1969", f"G01 {w}"]
    for units, program in (("inch", text), ("metric", "\n".join(out) + "\n")):
        src, dst = tmp_path / f"{units}.nc", tmp_path / f"{units}.out.nc"
        src.write_text(program)
        result = CliRunner().invoke(main, ["convert", str(src), "-o", str(dst), "--from",
                                           source, "--to", source, "--units", units,
                                           "--verify"])
        assert result.exit_code == 0, result.output
        assert "verified" in result.output and "FAILED" not in result.output
        noted = "converted on its own, not carried on Z's position" in result.output
        assert noted == (system != "A"), result.output
    if system != "A":
        # the output carried as system A's (W-0.7875 for W-20.) is no conversion of the B/C
        # program by the proof's reading, the one the converter keeps: refused at its word
        from formats.verify import verify_conversion
        options = ConvertOptions(target=profile(source), source=profile(source), units="inch")
        written, stats = convert_text(text, options)
        src, bad = tmp_path / "b.nc", tmp_path / "b.out.nc"
        src.write_text(text)
        bad.write_text(written.replace(w, "W-0.7875", 1))
        with pytest.raises(ConversionError) as err:
            verify_conversion(str(src), str(bad), profile(source), options, stats,
                              file="b.nc")
        assert err.value.line == 5
        assert "W-20. converts to -0.787402 but the output W-0.7875 reads -0.7875" in str(
            err.value)


def test_a_lathe_s_peck_rigid_tapping_q_converts_as_g83_s():
    """Review 59c F3: a FANUC lathe's G84/G88 Q (peck rigid tapping, 0i-TF: the depth of
    each peck, in least input increments without a point) was kept as written under a change
    of units, and --verify said "verified"; converted as G83's Q now, in the repeat too. A
    Haas lathe's G84 reads no Q: refused under a change of units, not guessed."""
    text = ("%\nO1\nG21 G99\nG00 X0 Z5.\nM29 S500\nG84 X0 Z-10. R1. Q3000 F1.\n"
            "Z-12. Q2000\nG80\nM29 S500\nG88 X20. C0 Z-10. R22. Q3. F1.\nG80\nM30\n%\n")
    out = convert(text, "fanuc-lathe", units="inch").splitlines()
    assert [out[5], out[6], out[9]] == [
        "G84 X0 Z-0.3937 R0.0394 Q1181 F0.0394", "Z-0.4724 Q787",
        "G88 X0.7874 C0 Z-0.3937 R0.8661 Q0.1181 F0.0394"]
    # no change of units: as written
    assert convert(text, "fanuc-lathe").splitlines()[5] == "G84 X0 Z-10. R1. Q3000 F1."
    with pytest.raises(ConversionError) as err:
        convert(text, "haas-lathe", units="inch")
    assert (err.value.line, err.value.column) == (6, 18)
    assert "does not say what Q is in this block" in str(err.value)


@pytest.mark.parametrize("text, why", [
    ("O1\nG21 G90\nG0 X0 Y0 Z0\nM98 P2 L20\nM30\nO2\nG91 G1 Z-1. F100.\nM99\n",
     "line 7: the incremental move Z-1. is rounded to the target's format, and the subprogram "
     "(it returns at line 8) runs it again at each call and each repeat of M98 L"),
    ("O1\nG21\n#1=0\n#2=20\nG91\nN10 G1 Z-1. F100.\n#1=#1+1\nIF [#1 LT #2] GOTO10\nM30\n",
     "line 6: the incremental move Z-1. is rounded to the target's format, and the program's "
     "jumps or loops may run it again"),
])
def test_a_rounded_increment_of_a_repeated_body_is_noted(text, why):
    out, stats = convert_text(text, ConvertOptions(target=load_profile("fanuc-mill"),
                                                   source=load_profile("fanuc-mill"),
                                                   units="inch"))
    assert any(why in note for note in stats.notes), stats.notes
    # an exact step repeats exactly: no note
    exact = text.replace("Z-1.", "Z-2.54")
    _, stats = convert_text(exact, ConvertOptions(target=load_profile("fanuc-mill"),
                                                  source=load_profile("fanuc-mill"),
                                                  units="inch"))
    assert not any("incremental move" in note for note in stats.notes), stats.notes


def test_a_dwell_converts_to_the_target_s_time_word():
    """A FANUC mill's G04 P is milliseconds, its G04 X seconds; LinuxCNC's G4 P is seconds
    (rs274 -g on the output: DWELL(1.0000), DWELL(1.5000), DWELL(0.5000))."""
    src = ("O1\nG21 G90 G17\nG0 X0 Y0 Z5.\nG04 P1000\nG04 X1.5\n"
           "G82 X1. Y1. Z-3. R1. P500 F50.\nG80\nM30\n")
    out = convert(src, "fanuc-mill", "linuxcnc").splitlines()
    assert out[3:6] == ["G04 P1.", "G04 P1.5", "G82 X1. Y1. Z-3. R1. P0.5 F50."]
    back = "G21 G90\nG4 P1.5\nG82 X1 Y1 Z-3 R1 P0.5 F50\nG80\nM2\n"
    out = convert(back, "linuxcnc", "fanuc-mill").splitlines()
    assert out[1] == "G4 P1500" and "P500" in out[2].split()


@pytest.mark.parametrize("source, target, text, message", [
    ("linuxcnc", "fanuc-mill", "G21\nG4 P0.0005\nM2\n",
     "<input>:2:4: P0.0005: the dwell's time is written differently on the target control "
     "(LinuxCNC to Custom Macro B (Fanuc, Haas)): a FANUC or Haas control reads G04 P in "
     "whole milliseconds, which this time is not"),
    ("fanuc-mill", "sinumerik-840d", "O1\nG21\nG04 P1000\nM30\n",
     "<input>:3:5: P1000: the dwell's time is written differently on the target control "
     "(Custom Macro B (Fanuc, Haas) to SINUMERIK): tapegate does not translate it"),
])
def test_a_dwell_the_target_cannot_read_alike_is_refused(source, target, text, message):
    from formats.errors import ConversionError
    with pytest.raises(ConversionError) as e:
        convert(text, source, target)
    assert message in str(e.value)


@pytest.mark.parametrize("source, target, text, message", [
    # Okuma OSP: G15 H1 selects work coordinate system 1, G56 H3 a tool length offset; on a
    # FANUC G15 cancels polar coordinates and G56 is work offset 3
    ("okuma-mill", "fanuc-mill", "O1\nG21 G90\nG15 H1\nG0 X0 Y0\nM30\n",
     '<input>:3:1: G15: the source and target controls give this code different meanings '
     '(group "work offset" on the source, group "polar" on the target, by their profiles)'),
    ("fanuc-mill", "okuma-mill", "O1\nG21 G90\nG54 G0 X0 Y0\nM30\n",
     '<input>:3:1: G54: the source and target controls give this code different meanings '
     '(group "work offset" on the source, group "length" on the target'),
    # HEIDENHAIN ISO I J: the centre's coordinates; FANUC I J: incremental from the start (a
    # FANUC program is not converted for a HEIDENHAIN at all: test_between_families.py)
    ("heidenhain-iso", "fanuc-mill",
     "%P G71 *\nN10 G00 G90 X+10 Y+0 Z+5 *\nN20 G01 Z-1 F100 *\nN30 G02 X+30 Y+0 I+20 J+0 *\n"
     "N99999 %P G71 *\n",
     "<input>:4:18: I+20: the source control reads an arc centre's I J K as absolute "
     "coordinates, the target as incremental from the start point"),
    # a CM 332's sign-less quadrant I J, a signed ISO control's
    ("cm332-quadrant", "iso-mill", "%\nN001 G90\nN002 G00 X1000 Y0\nN004 G02 X0 Y-1000 I1000 "
     "J0\nN005 M30\n",
     "<input>:4:20: I1000: the source control reads an arc centre's I J K as sign-less"),
])
def test_a_code_or_word_the_target_reads_otherwise_is_refused(source, target, text, message):
    from formats.errors import ConversionError
    with pytest.raises(ConversionError) as e:
        convert(text, source, target)
    assert message in str(e.value)


def test_codes_of_the_same_meaning_still_convert_across_controls():
    # FANUC -> Haas and -> LinuxCNC read G54 G17 G90 G81 G02 I J alike
    text = ("O1\nG21 G90 G17 G54\nG0 X10. Y0 Z5.\nG1 Z-1. F100.\nG2 X30. Y0 I10. J0\n"
            "G81 X5. Y5. Z-2. R1. F50.\nG80\nM30\n")
    assert convert(text, "fanuc-mill", "haas-mill") == text
    assert convert(text, "fanuc-mill", "linuxcnc").splitlines()[1:] == text.splitlines()[1:]


def test_a_word_the_implicit_source_has_no_format_for_is_refused():
    """A PM 322 writes X and Y without a point by its format (X+430); it has no Z or R, so
    where the decimal sign of `Z1` falls is not known: it was read as 0.0001 and written Z0."""
    from formats.errors import ConversionError
    text = "%\nN001 G90\nN002 G00 X0125 Y-05 Z1\nN003 M30\n"
    with pytest.raises(ConversionError) as e:
        convert(text, "pm322-eia", "iso-mill")
    assert "<input>:3:21: Z1: the source writes numbers without a decimal point and its " \
        "profile gives no format for address Z" in str(e.value)
    # its own words convert by its format: X0125 is 125 mm
    out = convert("%\nN001 G90\nN002 G00 X0125 Y-05\nN003 M30\n", "pm322-eia", "iso-mill")
    assert "X125. Y-500." in out


# FANUC's data input modes (FANUC 0i-MF/0i-TF operator's manual, "Programmable parameter input
# (G10)", "Tool life management"): G10 L50 ... G11 writes parameters (N the parameter's number,
# P an axis, R its value in the parameter's own unit), G10 L3 ... G11 registers tool life data
PARAMETERS = ("O1\nG21 G90 G17\nG10 L50\nN1420 R15000\nN1422 P1 R20000\nN6711 R500.\nG11\n"
              "G0 X10. Y10.\nM30\n")
TOOL_LIFE = "O1\nG21\nG10 L3\nP1 L500 Q1\nT10\nT11\nP2 L300 Q1\nT20\nG11\nG0 X10.\nM30\n"


@pytest.mark.parametrize("text, first, last, what", [
    (PARAMETERS, 3, 7, "G10 L50 programmable parameter input"),
    (TOOL_LIFE, 3, 9, "G10 L3 tool life data"),
])
def test_fanuc_data_input_is_kept_as_written_under_a_change_of_units(text, first, last, what):
    """Before: R15000 -> R0.5906 (a rapid traverse rate of 15000 mm/min made 0.59), Q1 -> Q0
    (a tool life counted by uses made by time). The data blocks are kept byte for byte, the
    program's own words convert, and a note names the lines."""
    out, stats = convert_text(text, ConvertOptions(target=load_profile("fanuc-mill"),
                                                   source=load_profile("fanuc-mill"),
                                                   units="inch"))
    lines, source = out.splitlines(), text.splitlines()
    assert lines[first - 1:last] == source[first - 1:last]
    assert lines[1].startswith("G20") and lines[-2] in ("G0 X0.3937 Y0.3937", "G0 X0.3937")
    assert stats.notes == [
        f"lines {first}-{last}: {what} ("
        + ("N a parameter number, P an axis, R the parameter's value in its own unit)"
           if "L50" in what else
           "P a tool group, L a life, Q how it is counted, T H D a tool's numbers)")
        + " kept as written: no unit of the program applies to them"]


def test_fanuc_data_input_verifies_and_a_changed_value_is_a_difference(tmp_path):
    from click.testing import CliRunner

    from tapegate.cli import main
    src, out = tmp_path / "p.nc", tmp_path / "o.nc"
    src.write_text(PARAMETERS)
    args = ["convert", str(src), "-o", str(out), "--from", "fanuc-mill", "--to", "fanuc-mill",
            "--units", "inch", "--verify"]
    result = CliRunner().invoke(main, args)
    assert result.exit_code == 0, result.output
    assert "verified" in result.output
    # the data compared as written: a parameter value changed is found
    changed = tmp_path / "c.nc"
    changed.write_text(out.read_text().replace("R15000", "R1500"))
    result = CliRunner().invoke(main, ["diff", str(out), str(changed), "-p", "fanuc-mill"])
    assert result.exit_code == 1, result.output
    assert "R15000" in result.output and "R1500" in result.output


def test_the_g10_l50_blocks_own_data_is_kept_as_written():
    """`G10 L50 N1420 R15000`: the words of the block that opens the mode are data as the
    mode's other blocks are (R15000 the parameter's value in its own unit): kept byte for byte,
    on the same profile and under a change of units."""
    text = PARAMETERS.replace("G10 L50\nN1420 R15000", "G10 L50 N1420 R15000")
    assert convert(text, "fanuc-mill", "fanuc-mill") == text
    inch = convert(text, "fanuc-mill", "fanuc-mill", units="inch").splitlines()
    assert inch[2:6] == ["G10 L50 N1420 R15000", "N1422 P1 R20000", "N6711 R500.", "G11"]


@pytest.mark.parametrize("target, text, message", [
    # the mode carried to another family's control, which reads N1420 R15000 as a block
    # (refused at the G10 block that opens it)
    ("linuxcnc", PARAMETERS,
     "<input>:3:1: G10 L50 programmable parameter input (N a parameter number, P an axis, R the "
     "parameter's value in its own unit) opened on line 3: the target control (LinuxCnc) has "
     "no such mode"),
    # a Haas reads Custom Macro B but its G10 has no L50 (nor L3): FANUC parameter numbers
    ("haas-mill", PARAMETERS,
     "<input>:3:1: G10 L50 programmable parameter input (N a parameter number, P an axis, R the "
     "parameter's value in its own unit) opened on line 3: the target control (MacroB, not a "
     "FANUC: a Haas's G10 takes L2, L10-L13 and L20) has no such mode"),
    # an axis word in the G10 L50 block: no data the mode takes (the control alarms)
    ("fanuc-mill", PARAMETERS.replace("G10 L50\n", "G10 L50 X5.\n"),
     "<input>:3:9: X5.: a word the G10 L50 programmable parameter input (N a parameter number, "
     "P an axis, R the parameter's value in its own unit) does not take in its G10 block, which "
     "holds only N P R data words: the control alarms here"),
    # data that reads a parameter the program also uses as a length (X#1): under a change of
    # units it would get the converted value
    ("fanuc-mill", PARAMETERS.replace("G10 L50\nN1420 R15000", "#1=10.\nG10 L50\nN1420 R#1"),
     "<input>:5:7: R#1: the data of the G10 L50 programmable parameter input (N a parameter "
     "number, P an axis, R the parameter's value in its own unit) opened on line 4 reads a "
     "parameter, which the change of units may have converted as a length, while the data is "
     "written in the parameter's own unit; write the value"),
    # a program word inside the mode: the G11 is missing (the control alarms there)
    ("fanuc-mill", PARAMETERS.replace("G11\n", ""),
     "<input>:7:1: G word inside the G10 L50 programmable parameter input (N a parameter "
     "number, P an axis, R the parameter's value in its own unit) opened on line 3, which holds "
     "only N P R words until its G11"),
])
def test_fanuc_data_input_is_refused_where_it_cannot_be_kept(target, text, message):
    from formats.errors import ConversionError
    with pytest.raises(ConversionError) as e:
        convert(text, "fanuc-mill", target, units="inch")
    assert message in str(e.value)


@pytest.mark.parametrize("source, text, units, notes", [
    # FANUC 0i-TF G92 threading cycle: 1.5 mm/rev from Z2. to Z-10., 8 revolutions
    ("fanuc-lathe", "O1\nG21 G99\nG0 X22. Z2.\nG92 X20. Z-10. F1.5\nX19.5\nG0 X30.\nM30\n",
     "inch",
     ["line 4: the thread lead F1.5 converts to 0.0590551 in per revolution and is written "
      "0.0591: 0.0000449 in long per revolution, 0.000359 in over the thread's 12 mm (8.0 "
      "revolutions), an error that builds up at every turn of the thread"]),
    # Haas lathe G76 (16 TPI) from Z0.1 to Z-1.
    ("haas-lathe", "O1\nG20\nG0 X1.1 Z0.1\nG76 X0.95 Z-1. K0.06 D0.01 F0.0625 A60\nM30\n",
     "metric",
     ["line 4: the thread lead F0.0625 converts to 1.5875 mm per revolution and is written "
      "1.588: 0.0005 mm long per revolution, 0.0088 mm over the thread's 1.1 in (17.6 "
      "revolutions), an error that builds up at every turn of the thread"]),
    # LinuxCNC G33 K (the distance per revolution)
    ("linuxcnc", "G21 G18\nG0 X10 Z2\nM3 S500\nG33 Z-20 K1.5\nG0 X12\nM2\n", "inch",
     ["line 4: the thread lead K1.5 converts to 0.0590551 in per revolution and is written "
      "0.059055: 0.000000118 in short per revolution, 0.00000173 in over the thread's 22 mm "
      "(14.7 revolutions), an error that builds up at every turn of the thread"]),
    # Okuma OSP lathe G33 (16 TPI, 1.5875 mm: 0.0625 in, written to the F format's 3
    # decimals) and its compound thread cycle G71: F the lead (5238-E)
    ("okuma-lathe", "O1\nG00 X30. Z5.\nG97 S500 M03\nG33 X24.6 Z-25. F1.5875\nM02\n", "inch",
     ["line 4: the thread lead F1.5875 converts to 0.0625 in per revolution and is written "
      "0.062: 0.0005 in short per revolution, 0.00945 in over the thread's 30 mm (18.9 "
      "revolutions), an error that builds up at every turn of the thread"]),
    ("okuma-lathe",
     "O1\nG00 X30. Z5.\nG97 S500 M03\nG71 X24.6 Z-25. B60 D0.3 H0.9 F1.5875\nM02\n", "inch",
     ["line 4: the thread lead F1.5875 converts to 0.0625 in per revolution and is written "
      "0.062: 0.0005 in short per revolution, 0.00945 in over the thread's 30 mm (18.9 "
      "revolutions), an error that builds up at every turn of the thread"]),
])
def test_a_rounded_thread_lead_is_noted_with_its_error_over_the_thread(source, text, units,
                                                                        notes):
    """A lead is no position: its rounding is off at every revolution (probe F17). The
    conversion writes it at the target's feed format and says what that costs over the
    thread's Z travel; a lead that converts exactly (F2.54 -> F0.1) has no note."""
    profile = load_profile(source)
    _, stats = convert_text(text, ConvertOptions(target=profile, source=profile, units=units))
    assert [n for n in stats.notes if "thread lead" in n] == notes
    exact = text.replace("F1.5875", "F2.54").replace("F1.5", "F2.54").replace(
        "F0.0625", "F0.1").replace("K1.5", "K2.54")
    _, stats = convert_text(exact, ConvertOptions(target=profile, source=profile, units=units))
    assert not [n for n in stats.notes if "thread lead" in n], stats.notes


def test_a_thread_lead_note_reads_the_end_z_as_the_source_does():
    """Review 58b F5: under --from-decimal increments the G92's `Z-20000` is -20 mm, as the
    start `Z5000` is 5 mm: the thread is 25 mm (the note said "the thread's 20005 mm")."""
    profile = load_profile("fanuc-lathe")
    text = ("O1017\nG21 G18 G99\nG97 S500 M03\nG00 X30000 Z5000\nG92 X24000 Z-20000 F1.5 Q0\n"
            "X23500 Q18000\nG00 X30000\nM30\n")
    out, stats = convert_text(text, ConvertOptions(target=profile, source=profile, units="inch",
                                                   decimal="explicit",
                                                   from_decimal="increments"))
    assert out.splitlines()[4] == "G92 X0.9449 Z-0.7874 F0.0591 Q0", out
    assert [n for n in stats.notes if "thread lead" in n] == [
        "line 5: the thread lead F1.5 converts to 0.0590551 in per revolution and is written "
        "0.0591: 0.0000449 in long per revolution, 0.000748 in over the thread's 25 mm (16.7 "
        "revolutions), an error that builds up at every turn of the thread"]


LOOP = ("%\nO1\nG21 G90 G17\n#1=0\n#2=50.\n#3=5.\nG0 Z5.\nWHILE [#1 LE #2] DO1\n"
        "G81 X#1 Y0 Z-5. R2. F100.\n#1=#1+#3\nEND1\nG80\nM30\n%\n")


def test_a_rounded_loop_bound_is_refused_and_noted_where_it_is_rounded():
    """Probe F12: #2=50. and #3=5. become #2=1.9685 and #3=0.1969, and the loop that drilled
    11 holes (X0 to X50 mm) drills 10 (ten steps of 0.1969 pass 1.9685); `#2=0.25 #3=1.`
    from 0 are 4 passes, `#2=0.0098 #3=0.0394` 5. The converter does not count the passes, and
    --verify compares the text, which sees none of it: a rounded value compared in a condition
    is refused at its rounding. With --allow-unconverted the values stay the converted ones and
    a note says at each rounding what reads it."""
    with pytest.raises(ConversionError) as refused:
        convert(LOOP, "fanuc-mill", units="inch")
    assert (refused.value.line, refused.value.column) == (5, 1)
    assert refused.value.message == (
        "#2=50. is written #2=1.9685, rounded, and #2 is compared in the condition on line 8: a "
        "loop's bound or step rounded apart from the value it is compared with may change how "
        "many times the loop runs, which tapegate does not count; write the bound and the step "
        "in values the target's format holds exactly, or a count of passes, or give "
        "--allow-unconverted to convert it with a note")
    out, stats = convert_text(LOOP, ConvertOptions(target=load_profile("fanuc-mill"),
                                                   source=load_profile("fanuc-mill"),
                                                   units="inch", allow_unconverted=True))
    assert out.splitlines()[4:6] == ["#2=1.9685", "#3=0.1969"]
    assert stats.notes == [
        "line 5: #2=50. is written #2=1.9685, rounded, and #2 is compared in the condition on "
        "line 8: a loop's bound or step rounded apart from the value it is compared with may "
        "change how many times the loop runs",
        "line 6: #3=5. is written #3=0.1969, rounded, and #3 is added to #1 on line 10, which "
        "adds itself: a loop's step rounded builds up its rounding at every pass and may "
        "change how many times the loop runs"]
    # values that convert exactly (50.8 mm, 2.54 mm) are no rounding: no note
    exact = LOOP.replace("#2=50.", "#2=50.8").replace("#3=5.", "#3=2.54")
    _, stats = convert_text(exact, ConvertOptions(target=load_profile("fanuc-mill"),
                                                  source=load_profile("fanuc-mill"),
                                                  units="inch"))
    assert stats.notes == []
    # LinuxCNC's o-word loop and named parameters alike
    ngc = ("G21\n#<n>=0\n#<end>=50.\n#<step>=5.\no1 while [#<n> LE #<end>]\nG0 X#<n>\n"
           "#<n>=[#<n>+#<step>]\no1 endwhile\nM2\n")
    _, stats = convert_text(ngc, ConvertOptions(target=load_profile("linuxcnc"),
                                                source=load_profile("linuxcnc"),
                                                units="inch", allow_unconverted=True))
    assert [n.split(",")[0] for n in stats.notes] == [
        "line 3: #<end>=50. is written #<end>=1.968504", "line 4: #<step>=5. is written "
        "#<step>=0.19685"]


def test_a_rounded_loop_step_is_refused_as_a_rounded_bound_is():
    """A bound that converts exactly (50.8 mm, 2 in) and a step that does not (5 mm, 0.19685
    in written 0.1969): ten steps of 0.1969 pass 1.969 where ten of 5 mm reach 50 < 50.8, so
    the count can change as with a rounded bound (eleven holes either way here, but the last
    at X1.969, 0.0005 in past the source's X50 mm, and a step's rounding builds up at every
    pass). Refused at the step's rounding; with --allow-unconverted a note there."""
    text = LOOP.replace("#2=50.", "#2=50.8")
    with pytest.raises(ConversionError) as refused:
        convert(text, "fanuc-mill", units="inch")
    assert (refused.value.line, refused.value.column) == (6, 1)
    assert refused.value.code == "conversion-unprovable"
    assert refused.value.message == (
        "#3=5. is written #3=0.1969, rounded, and #3 is added to #1 on line 10, which adds "
        "itself: a loop's step rounded builds up its rounding at every pass and may change how "
        "many times the loop runs, which tapegate does not count; write the bound and the step "
        "in values the target's format holds exactly, or a count of passes, or give "
        "--allow-unconverted to convert it with a note")
    fanuc = load_profile("fanuc-mill")
    out, stats = convert_text(text, ConvertOptions(target=fanuc, source=fanuc, units="inch",
                                                   allow_unconverted=True))
    assert out.splitlines()[4:6] == ["#2=2.", "#3=0.1969"]
    assert stats.notes == [
        "line 6: #3=5. is written #3=0.1969, rounded, and #3 is added to #1 on line 10, which "
        "adds itself: a loop's step rounded builds up its rounding at every pass and may "
        "change how many times the loop runs"]
    # a step that converts exactly (2.54 mm) is no rounding: converted, nothing said
    out, stats = convert_text(text.replace("#3=5.", "#3=2.54"), ConvertOptions(
        target=fanuc, source=fanuc, units="inch"))
    assert out.splitlines()[4:6] == ["#2=2.", "#3=0.1"] and stats.notes == []


def test_linuxcnc_g76_pitch_and_rigid_tapping_pitch_are_leads_too():
    """LinuxCNC's G76 P (the pitch) and G33.1 K: noted like G33 K. After the G76, which ends
    where it began, the Z reached is not the cycle's Z: no length is named for the G33.1."""
    text = "G21 G18\nG0 X10 Z2\nM3 S500\nG76 P1.5 Z-20 I-0.5 J0.2 K1\nG33.1 Z-10 K1.5\nM2\n"
    profile = load_profile("linuxcnc")
    _, stats = convert_text(text, ConvertOptions(target=profile, source=profile, units="inch"))
    assert stats.notes == [
        "line 4: the thread lead P1.5 converts to 0.0590551 in per revolution and is written "
        "0.059055: 0.000000118 in short per revolution, 0.00000173 in over the thread's 22 mm "
        "(14.7 revolutions), an error that builds up at every turn of the thread",
        "line 5: the thread lead K1.5 converts to 0.0590551 in per revolution and is written "
        "0.059055: 0.000000118 in short per revolution, an error that builds up at every turn "
        "of the thread"]


@pytest.mark.parametrize("loop", [
    "WHILE R3<=R1\nG0 X=R3\nR3=R3+R2\nENDWHILE\n",
    "MARKE:\nG0 X=R3\nR3=R3+R2\nIF R3<=R1 GOTOB MARKE\n",
    "REPEAT\nG0 X=R3\nR3=R3+R2\nUNTIL R3>R1\n",
])
def test_a_sinumerik_loop_bound_rounded_apart_is_refused_as_a_macro_b_one(loop):
    """Probe P3-1: the SINUMERIK form of the F12 loop (11 holes from X0 to X50 mm by 5 mm;
    in inches R1=1.9685 and R2=0.1969 drill 10). Its condition (WHILE, IF..GOTOB, UNTIL)
    compares R parameters, which the parameter analysis ties as it ties a Macro B condition's
    (the bound is proved a length by the counter it is compared with, even where it is read
    nowhere else) and the converter's loop guard reads: refused at the rounding, or noted with
    --allow-unconverted; a bound and step the target holds exactly (50.8 mm, 2.54 mm) pass."""
    src = "G17 G71 G90\nR1=50 R2=5 R3=0\n" + loop + "M30\n"
    with pytest.raises(ConversionError) as refused:
        convert(src, "sinumerik-840d", units="inch")
    condition = 3 + loop.splitlines().index(next(
        line for line in loop.splitlines() if "R1" in line))
    assert (refused.value.line, refused.value.column) == (2, 1)
    step = loop.splitlines().index("R3=R3+R2") + 3
    # the first of the two the converter meets: the condition comparing the rounded bound, or
    # the rounded step added to the counter (a step is refused as a bound is)
    assert refused.value.message.startswith((
        "R1=50 is written R1=1.9685, rounded, and R1 is compared in the condition on line "
        f"{condition}: a loop's bound or step rounded apart",
        f"R2=5 is written R2=0.1969, rounded, and R2 is added to R3 on line {step}, which adds "
        "itself: a loop's step rounded")), refused.value.message
    assert ("compared in the condition" in refused.value.message) == (condition < step)
    profile = load_profile("sinumerik-840d")
    _, stats = convert_text(src, ConvertOptions(target=profile, source=profile, units="inch",
                                                allow_unconverted=True))
    assert sorted(n.split(",")[0] for n in stats.notes) == [
        "line 2: R1=50 is written R1=1.9685", "line 2: R2=5 is written R2=0.1969"]
    exact = src.replace("R1=50 R2=5", "R1=50.8 R2=2.54")
    assert convert(exact, "sinumerik-840d", units="inch").splitlines()[1] == "R1=2. R2=0.1 R3=0"


@pytest.mark.parametrize(("loop", "condition"), [
    ("WHILE R1<10\nG1 X=R1 F100\nR1=R1+1\nENDWHILE\n", "WHILE R1<10"),
    ("LAB: G1 X=R1 F100\nR1=R1+0.1\nIF R1<10 GOTOB LAB\n", "IF R1<10 GOTOB LAB"),
    ("WHILE R1 > -2.5\nG1 X=R1 F100\nR1=R1-0.5\nENDWHILE\n", "WHILE R1 > -2.5"),
])
def test_a_sinumerik_condition_holding_a_number_is_refused_under_a_change_of_units(
        loop, condition):
    """Review 4, section 9: `WHILE R1<10` (or `IF R1<10 GOTOB`) compares the counter with a
    number and no `=`: kept as written while the step is converted, the loop ran 25.4 times as
    far in inches and said ok. Refused at the statement, as `UNTIL R1>=10` and the Macro B
    `WHILE [#1 LT 10.]` are; --allow-unconverted leaves it as written with a note; a condition
    that compares two parameters is the loop guard's (the test above)."""
    src = "G71 G90\nR1=0\n" + loop + "M30\n"
    line = 3 + loop.splitlines().index(condition)
    with pytest.raises(ConversionError) as refused:
        convert(src, "sinumerik-840d", units="inch")
    assert (refused.value.line, refused.value.column) == (line, 1)
    assert refused.value.message == (
        f"cannot convert the units of the statement {condition!r}: it holds a number the "
        "converter cannot show to be a length or not (--allow-unconverted leaves it as written)"
    ).replace("'", '"')
    profile = load_profile("sinumerik-840d")
    out, stats = convert_text(src, ConvertOptions(target=profile, source=profile, units="inch",
                                                  allow_unconverted=True))
    assert condition in out.splitlines()
    assert f"line {line}: statement {condition!r} left unconverted".replace("'", '"') in stats.notes
    # no change of units: nothing to refuse
    assert convert(src, "sinumerik-840d") == src


@pytest.mark.parametrize(("src", "source", "name", "lines"), [
    ("G21 G90 G17\n#1 = 10\nG0 X#1 Y0 Z5\nG20\nG0 X#1\nG21\nM2\n", "linuxcnc", "#1", (5, 3)),
    ("%\nO1\nG21 G90 G17\n#1=10.\nG0 X#1 Y0 Z5.\nG20\nG0 X#1\nG21\nM30\n%\n", "fanuc-mill", "#1",
     (7, 5)),
    ("G17 G71 G90\nR1=10\nG0 X=R1 Y0 Z5\nG70\nG0 X=R1\nG71\nM30\n", "sinumerik-840d", "R1",
     (5, 3)),
    # set in inches, read in millimetres and then in inches
    ("G20 G90\n#1 = 1\nG21\nG0 X#1\nG20\nG0 X#1\nM2\n", "linuxcnc", "#1", (6, 4)),
    # a named parameter read again in the same units first (looked up by its text), the
    # first read the one named
    ("G21 G90\n#<a> = 10\nG0 X#<a> Y0\nG0 X[#<a>*2]\nG20\nG0 X#<a>\nG21\nM2\n", "linuxcnc",
     "#<a>", (6, 3)),
])
def test_a_parameter_read_as_a_length_in_two_unit_systems_is_refused(src, source, name, lines):
    """Probe P3-17: `#1 = 10` read by `G0 X#1` in G21 and again after G20 moves to X10 mm, then
    X10 in (rs274 -g: 254 mm); its one assignment is converted once (0.393701 in), so the
    second move went to 10 mm. The converter names the parameter and both reads, in either
    direction of conversion; a program that reads it in one units system converts as before."""
    for units in ("inch", "metric"):
        with pytest.raises(ConversionError) as refused:
            convert(src, source, units=units)
        error = refused.value
        assert (error.code, error.line) == ("conversion-units", lines[0])
        assert error.message.startswith(f"{name} is read as a length on line {lines[0]} in ")
        assert f"and on line {lines[1]} in " in error.message
    one = "G21 G90 G17\n#1 = 10\nG0 X#1 Y0 Z5\nG0 X[#1*2]\nG20\nG0 X1\nM2\n"
    assert convert(one, "linuxcnc", units="inch").splitlines()[1] == "#1 = 0.393701"
    # without a change of units nothing is converted, nothing refused
    assert convert(src, source) == src


@pytest.mark.parametrize(("src", "source", "inch", "metric"), [
    # review 4, section 3 (LinuxCNC's mmount.ngc: `#102=3.0` before its G20, read after)
    ("#1=3.0\nG20 G90\nG1 X1 F#1\nM2\n", "linuxcnc", "G20 #1=3.0", "#1=76.2"),
    ("%\nO1000\n#1=3.\nG20 G90\nG0 X#1\nM30\n%\n", "fanuc-mill", "G20 #1=3.", "#1=76.2"),
    # set in inches, read in millimetres only: millimetres
    ("G20 G90\n#1 = 1\nG21\nG0 X#1\nM2\n", "linuxcnc", "#1 = 0.03937", "#1 = 1"),
    # set twice before its read, under two units: both in the read's
    ("G21 G90\n#1 = 2\nG20\n#1 = 1\nG0 X#1\nM2\n", "linuxcnc", "#1 = 2", "#1 = 50.8"),
])
def test_a_parameter_set_before_its_read_is_converted_in_the_read_s_units(
        src, source, inch, metric):
    """A parameter has no units: `#1=3.0` means 3 of whatever units the block that reads it is
    in (LinuxCNC, rs274ngc: a parameter holds a number; FANUC Custom Macro B alike). Set before
    the program's G20 and read after it, it is 3 inches: kept in inches, 76.2 in millimetres
    (was refused as "used in metric"; before that written 3.0 under G21). The first read
    fixes the factor of every assignment before it."""
    def first_set(text: str) -> str:
        return next(line for line in text.splitlines() if "#1" in line and "=" in line)
    inch_out = convert(src, source, units="inch")
    metric_out = convert(src, source, units="metric")
    assert first_set(inch_out) == inch
    assert first_set(metric_out) == metric
    if "#1 = 2" in src:
        assert inch_out.splitlines()[3] == "#1 = 1"
        assert metric_out.splitlines()[3] == "#1 = 25.4"
    # the reads themselves are kept: the value moved with its assignments
    for out in (inch_out, metric_out):
        assert [w for w in out.split() if w.endswith("#1")] == [
            w for w in src.split() if w.endswith("#1")]


@pytest.mark.parametrize(("src", "line", "how"), [
    ("G17 G71 G90\nR1=2 R2=0 R3=10\nG0 X=R1 Y0 Z5\nR[R1]=R3\nG1 X=R2 F100\nG1 X=R3\nM30\n", 4,
     "sets"),
    ("G17 G71 G90\nR1=2\nR[R1]=10\nG0 X=R2 Y10 Z5\nM30\n", 3, "sets"),
    ("G17 G71 G90\nR1=2 R2=0 R3=10\nG0 X=R[R1] Y0 Z5\nG1 X=R3\nM30\n", 3, "reads"),
])
def test_a_sinumerik_r_parameter_chosen_by_a_value_proves_no_class(src, line, how):
    """Probe P3-15: `R[R1]=R3` writes the R parameter whose number R1 holds (Job Planning,
    "R parameters"); R1 read as a length elsewhere became R1=0.0787 and the write went to
    another parameter, "ok". As a Macro B `#[#1]=#3`, a parameter chosen by a value may be
    any, so none is proved: refused, naming the line that chooses it."""
    with pytest.raises(ConversionError) as refused:
        convert(src, "sinumerik-840d", units="inch")
    assert refused.value.line == 2
    assert (f"line {line} {how} a parameter chosen by a value (#[..], ##, R[..])"
            in refused.value.message)
    assert convert(src, "sinumerik-840d") == src


@pytest.mark.skipif(not (CORPUS / "shops" / "LinuxCNC__linuxcnc__mmount.ngc").is_file(),
                    reason="the shops corpus (../shared/corpus/shops) is not here")
def test_the_shops_mmount_program_converts_to_its_own_units_and_verifies(tmp_path):
    """Review 4, section 3: LinuxCNC's mmount.ngc sets `#102=3.0 (drill feed)` on line 26,
    before its `G17 G20 G40 G90`, and reads it after: converted to inch (its own units) it is
    kept and the conversion verifies; it was refused as "used as one on line 26 in metric"."""
    path = CORPUS / "shops" / "LinuxCNC__linuxcnc__mmount.ngc"
    profile = load_profile("linuxcnc")
    out = tmp_path / "mmount.ngc"
    stats = convert_file(str(path), str(out), ConvertOptions(profile, profile, units="inch"),
                         verify=True)
    assert stats.verified
    source = path.read_text(encoding="utf-8", errors="surrogateescape").splitlines()
    converted = out.read_text(encoding="utf-8", errors="surrogateescape").splitlines()
    line = next(i for i, text in enumerate(source) if text.startswith("#102"))
    assert converted[line] == source[line]


# -- a G code the source family's list lacks (review 8, finding 4) -----------------------------

FANUC_MILL_G71_7 = ("%\nO0020\nG20 G90 G94 G17\nG0 X2. Y0 Z0.1\nG71.7 P100 Q200 U0.01 F10.\n"
                    "N100 G1 X1.\nG1 Z-1.\nN200 X2.\nG0 Z1.\nM30\n%\n")


@pytest.mark.parametrize("source, text, message", [
    # the 0i-MF turning cycle on a mill whose list has no G71.7: Q200 is a block number to a
    # control that has it, no length to convert
    ("fanuc-mill", FANUC_MILL_G71_7,
     "<input>:5:7: P100 Q200: G71.7 is not in the source control's G code list (the control "
     "alarms on it, or runs the macro its parameters name), so what these words are to it"),
    # a Haas lathe's list has no G244 (it runs G241-G243, G245, G246 and G249): its R and Q
    # are refused, not one converted, one kept
    ("haas-lathe", "%\nO1\nG20 G18 G99\nG0 X1. Z1.\nG98 G244 X1.0 Z-0.5 R0.1 Q0.1 F5.\nG80\n"
     "M30\n%\n",
     "<input>:5:21: R0.1 Q0.1: G244 is not in the source control's G code list"),
    # system B/C threading on a system A lathe: the lead word E (a length to G32) is refused
    ("fanuc-lathe", "%\nO1\nG20 G99\nG0 X1. Z0.1\nG33 Z-1. E0.0625\nM30\n%\n",
     "<input>:5:10: E0.0625: G33 is not in the source control's G code list"),
])
def test_words_of_a_code_the_source_list_lacks_are_refused_under_a_change_of_units(
        source, text, message):
    with pytest.raises(ConversionError) as e:
        convert(text, source, units="metric")
    assert message in str(e.value)


def test_a_code_the_source_list_lacks_is_carried_and_its_axis_words_converted() -> None:
    """The refusal is of the words a code gives a role; a block whose other words are the
    axes and the feed converts (the code carried, as the control will meet it), and without a
    change of units only a word a role would rewrite is refused: a FANUC reads Q200 in
    least increments as a length (Q0.02), but G71.7's Q names block N200."""
    text = "%\nO1\nG20 G99\nG0 X1. Z0.1\nG33 Z-1. F0.0625\nM30\n%\n"
    out = convert(text, "fanuc-lathe", units="metric")
    assert "G33 Z-25.4 F1.5875" in out
    assert convert(text, "fanuc-lathe") == text
    with pytest.raises(ConversionError) as e:
        convert(FANUC_MILL_G71_7, "fanuc-mill")
    assert ("<input>:5:12: Q200: G71.7 is not in the source control's G code list" in str(e.value)
            and "writing it with a decimal point cannot convert it" in str(e.value))
    pointed = FANUC_MILL_G71_7.replace("P100 Q200", "U0.02")
    assert convert(pointed, "fanuc-mill") == pointed


def test_a_later_block_under_the_lacked_code_has_its_role_words_refused() -> None:
    """The lacked code's motion stays in force until a motion code the list holds (as the check
    takes it): a later block's Q of `G244 X1. Z-.5` then `X.8 Z-.6 Q.2` is no more known than
    the first block's would be, and is refused under a change of units; after a listed motion
    code (G0, G2 with its R) the words are read by its roles again, and without a change of
    units nothing of it is refused."""
    later = "%\nO1\nG20 G18 G99\nG0 X2. Z0.1\nG98 G244 X1.0 Z-0.5\nX0.8 Z-0.6 Q0.2\nG80\nM30\n%\n"
    with pytest.raises(ConversionError) as e:
        convert(later, "haas-lathe", units="metric")
    assert ("<input>:6:12: Q0.2: the motion in force is that of G244 (line 5), which is not in "
            "the source control's G code list") in str(e.value)
    assert convert(later, "haas-lathe") == later
    after = ("%\nO1\nG20 G18 G99\nG0 X2. Z0.1\nG98 G244 X1.0 Z-0.5\nG0 X0.8\nG2 X1. Z-1. R0.2\n"
             "M30\n%\n")
    out = convert(after, "haas-lathe", units="metric")
    assert "G2 X25.4 Z-25.4 R5.08" in out


def test_a_lower_case_word_is_upper_cased_with_its_blanks_kept():
    """Review 19, 5: a lower-case word converted for a target that reads only upper case was
    written from its token, its blanks dropped (`x [1 + 2]` became `X[1+2]`). Spacing "keep"
    keeps them: only the letters outside comments are upper-cased; a word written anew (a
    value converted) is written as before."""
    text = "g21 g90\ng0 x [1 + 2] y 1.5 (keep me)\n#1 = [sin[30] * 2]\nm2\n"
    assert convert(text, "linuxcnc", "fanuc-mill") == (
        "G21 G90\nG0 X [1 + 2] Y 1.5 (keep me)\n#1 = [SIN[30] * 2]\nM2\n")
    # the same program written in upper case converts to the same text
    upper = "G21 G90\nG0 X [1 + 2] Y 1.5 (keep me)\n#1 = [SIN[30] * 2]\nM2\n"
    assert convert(upper, "linuxcnc", "fanuc-mill") == upper
    # a value the conversion rewrites (mm to inch) is written anew, in upper case
    out = convert("g21 g90\ng0 x 25.4 y 2 (a note)\nm2\n", "linuxcnc", "fanuc-mill",
                  units="inch")
    assert out.splitlines()[1] == "G0 X1. Y0.0787 (a note)"


@pytest.mark.parametrize("source, target, text, column, name, meanings", [
    # rs274 2.9: [2 OR 4] is 1, ATAN[-1]/[1] -45, ASIN[-0.5] -30, ROUND[1.4] 1, FIX[-1.2] -2
    ("linuxcnc", "fanuc-mill", "G21 G90\nG0 X[2 OR 4]\nM2\n", 4, "OR",
     ("a logical OR, 1 or 0", "a bitwise OR of the integer parts")),
    ("linuxcnc", "haas-mill", "g21 g90\n#1 = [2 and 1]\ng0 x#1\nm2\n", 1, "AND",
     ("a logical AND, 1 or 0", "a bitwise AND of the integer parts")),
    ("linuxcnc", "fanuc-mill", "G21 G90\nG0 X1. Y[ATAN[-1]/[1]]\nM2\n", 8, "ATAN",
     ("in degrees, -180 to 180", "in degrees, 0 to 360")),
    ("linuxcnc", "fanuc-mill", "G21 G90\nG0 Z[ASIN[-0.5]]\nM2\n", 4, "ASIN",
     ("-90 to 90", "270 to 90")),
    ("linuxcnc", "fanuc-mill", "G21 G90\nG0 X[ROUND[1.4]]\nM2\n", 4, "ROUND",
     ("a half away from zero (ROUND[-2.5] is -3)", "to the address's least input increment")),
    # in a plain assignment too: rs274 rounds a negative half away from zero, which no FANUC
    # or Haas page at hand settles (issue 32, item 3)
    ("linuxcnc", "fanuc-mill", "G21 G90\n#1 = [ROUND[#2]]\nG0 X#1\nM2\n", 1, "ROUND",
     ("a half away from zero", "a negative half, ROUND[-2.5], in no page at hand")),
    ("haas-mill", "linuxcnc", "O1\nG21 G90\n#1=ROUND[#2]\nM30\n", 1, "ROUND",
     ("a negative half, ROUND[-2.5], in no page at hand", "a half away from zero")),
    # the other way: a FANUC's or Haas's bitwise XOR and truncating FIX are not LinuxCNC's
    ("fanuc-mill", "linuxcnc", "O1\nG21 G90\n#1=[2 XOR 3]\nG0 X[FIX[#1]]\nM30\n", 1, "XOR",
     ("a bitwise exclusive OR", "a logical exclusive OR")),
    ("haas-mill", "linuxcnc", "O1\nG21 G90\nG0 X[FIX[-1.2]]\nM30\n", 4, "FIX",
     ("discarding the fraction (FIX[-1.2] is -1)", "rounding down (FIX[-1.2] is -2)")),
    # a name one family has and the other does not
    ("fanuc-mill", "linuxcnc", "O1\nG21 G90\n#1=BCD[12]\nM30\n", 1, "BCD",
     ("a conversion between BCD and binary", "no operator or function of that name")),
    ("linuxcnc", "fanuc-mill", "G21 G90\nG0 X[2**3]\nM2\n", 4, "**",
     ("a power", "no operator or function of that name")),
    # a name run on into the next is split as the controls read it (MOD, then FIX)
    ("linuxcnc", "fanuc-mill", "G21 G90\nG0 X[2 MODFIX[3]]\nM2\n", 4, "MOD",
     ("the remainder made positive", "the remainder (of a negative operand")),
    # ISO 6983-1 leaves every operation to the control's manual
    # (to an ISO 6983-1 profile that reads `[ ]`: the built-in ones do not)
    ("linuxcnc", ISO_MACROS, "G21 G90\nG0 X[SIN[30]]\nM2\n", 4, "SIN",
     ("the sine of an angle in degrees", "leaves to the control's manual")),
])
def test_an_expression_whose_operation_differs_between_families_is_refused(
        source, target, text, column, name, meanings):
    """Review 19, 2: between families an expression was carried as written, and `[2 OR 4]`,
    `ATAN[-1]/[1]`, `ASIN[-0.5]`, `ROUND[1.4]` compute otherwise on a FANUC or Haas (Custom
    Macro B: bitwise AND OR XOR, ATAN 0-360, ASIN 270-90, ROUND in an address to its
    increment) than on LinuxCNC (rs274). Refused at the word, naming the operation and both
    meanings."""
    with pytest.raises(ConversionError) as e:
        convert(text, source, target)
    message = str(e.value)
    assert e.value.code == "conversion-meaning"
    line = next(i for i, t in enumerate(text.splitlines(), 1) if name.lower() in t.lower()
                or (name == "**" and "**" in t))
    assert message.startswith(f"<input>:{line}:{column}: ")
    source_says, target_says = message.split(f": {name} is ", 1)[1].split(" control and ", 1)
    assert meanings[0] in source_says and meanings[1] in target_says
    assert "computes the same on both" in message


def test_rs274_rounds_a_half_away_from_zero(tmp_path):
    """The meaning the refusal gives LinuxCNC's ROUND, asked of rs274 -g (issue 32, item 3):
    -1.5 is -2, -2.5 is -3, 2.5 is 3, -1.4 is -1."""
    from .conftest import rs274_output
    cases = {"-1.5": "-2", "-2.5": "-3", "2.5": "3", "1.5": "2", "-1.4": "-1", "-0.5": "-1"}
    text = "G21\n" + "".join(f"#1=[ROUND[{v}]]\n(debug,r{i}=#1)\n"
                               for i, v in enumerate(cases)) + "M2\n"
    out = rs274_output(tmp_path, text)
    for i, want in enumerate(cases.values()):
        assert f'MESSAGE("r{i}={want}.000000")' in out, out


def test_an_expression_of_operations_read_alike_is_carried_between_families():
    """+ - * / and SIN COS TAN ACOS SQRT ABS LN EXP compute the same on a LinuxCNC and on a
    FANUC or Haas (rs274; 0i-MF, 96-8000): such an expression is carried, both ways."""
    text = ("G21 G90\n#1 = [SQRT[16] + ABS[-2] * COS[60]]\nG0 X[#1 / 2] Y[SIN[30] - TAN[45]]\n"
            "G0 Z[ACOS[0.5] + LN[EXP[1]]]\nM2\n")
    assert convert(text, "linuxcnc", "fanuc-mill").splitlines()[1:] == text.splitlines()[1:]
    assert convert(text, "linuxcnc", "haas-mill").splitlines()[1:] == text.splitlines()[1:]
    fanuc = "O1\n" + text.replace("M2", "M30")
    assert convert(fanuc, "fanuc-mill", "linuxcnc").splitlines()[2:] == \
        fanuc.splitlines()[2:]


def test_a_bracketed_expression_is_refused_for_a_sinumerik():
    """A SINUMERIK reads [ ] as an array's index and writes an expression X=(..): a
    bracketed expression carried to it was written as it stood (review 19, 2)."""
    with pytest.raises(ConversionError) as e:
        convert("G21 G90\nG0 X[1+2] Y1.\nM2\n", "linuxcnc", "sinumerik-840d")
    assert str(e.value).startswith("<input>:2:4: X[1+2]: an expression in [ ], which a "
                                   "SINUMERIK reads as an array's index")


def test_an_okuma_expression_is_refused_between_families_both_ways():
    """An Okuma OSP sets an address by an expression written `X=..`; another family reads no
    `=` in an address, and no page at hand compares the OSP's functions with theirs: `X=SIN[30]`
    for a FANUC and `X[ATAN[1]/[1]]` for an OSP were carried as written (review 19, 2)."""
    with pytest.raises(ConversionError) as e:
        convert("G21 G90\nG0 X=SIN[30]*2\nM30\n", "okuma-mill", "fanuc-mill")
    assert str(e.value).startswith("<input>:2:4: X=SIN[30]*2: an Okuma OSP's expression")
    with pytest.raises(ConversionError) as e:
        convert("O1\nG21 G90\nG0 X[ATAN[1]/[1]]\nM30\n", "fanuc-mill", "okuma-mill")
    assert str(e.value).startswith("<input>:3:4: X[ATAN[1]/[1]]: an expression in [ ] after "
                                   "an address, which an Okuma OSP writes X=..")
    # a program without expressions converts as before
    assert convert("O1\nG21 G90\nG0 X1. Y2.\nM30\n", "fanuc-mill", "okuma-mill").splitlines()[
        -2] == "G0 X1. Y2."


PROFILES = ["cm332-quadrant", "fanuc-lathe", "fanuc-lathe-b", "fanuc-lathe-c", "fanuc-mill",
            "haas-lathe", "haas-mill", "heidenhain-iso", "iso-lathe", "iso-mill", "linuxcnc",
            "okuma-lathe", "okuma-mill", "pm322-eia", "sinumerik-7e2", "sinumerik-840d"]


@pytest.mark.parametrize("target", PROFILES)
@pytest.mark.parametrize("text", [
    "g0 x 1.5 y2\nm2\n", "G0 X 1.5 Y2\nM2\n", "G0 X- 1.5\nM2\n",
    # LinuxCNC reads a number through blanks: X1 2.5 is X12.5, G1 8 is G18
    "G0 X1 2.5\nM2\n", "g1 8\ng0 x 1 2\nm2\n",
])
def test_a_word_written_with_blanks_converts_to_what_the_target_reads(text, target):
    """Review 20, 2: a word's blanks carried to a target that reads them otherwise (`X 1.5`
    for a Haas, which alarms: TG100; `X1 2.5`, LinuxCNC's X12.5, for any other control). The
    output of each conversion that succeeds has no TG100 on its target's own check, and reads
    the LinuxCNC source's values."""
    from postproc.check import check_text

    try:
        out = convert(text, "linuxcnc", target)
    except ConversionError:
        return  # (refused with a reason: nothing written)
    found = [f for f in check_text(out, load_profile(target)) if f.rule == "TG100"]
    assert found == [], (out, found)
    if target != "linuxcnc":
        # (a target with an implicit decimal writes X12.5 as X00125)
        assert "G1 8" not in out and "X1 2" not in out.upper(), out
        assert not any(s in out for s in ("#1 0", "[1 0]", "#2 0", "# 3", "1 . 5")), out
    if "2.5" in text and target in ("fanuc-mill", "haas-mill", "sinumerik-840d"):
        assert "X12.5" in out, out


@pytest.mark.parametrize("target", PROFILES)
@pytest.mark.parametrize("text, joined", [
    # review 21, 2: through a parameter's or an expression's number, X#1 0 is X#10, X[1 0] is
    # X[10], #2 0=3 is #20=3 (rs274 drops every blank outside comments)
    ("G21 G90\n#10=5\n#1=1\nG0 X#1 0\nM2\n", "G21 G90\n#10=5\n#1=1\nG0 X#10\nM2\n"),
    ("G21 G90\nG0 X[1 0]\nM2\n", "G21 G90\nG0 X[10]\nM2\n"),
    ("G21 G90\n#2 0=3\nG0 Z#20\nM2\n", "G21 G90\n#20=3\nG0 Z#20\nM2\n"),
    ("G21 G90\n# 3=1\nG0 X[#3 + 1 . 5]\nM2\n", "G21 G90\n#3=1\nG0 X[#3+1.5]\nM2\n"),
])
def test_blanks_inside_a_number_convert_as_the_number_written_whole(text, joined, target):
    """Review 21, 2: the conversion of a word with blanks inside its numbers is the conversion
    of the word written without them, which the target reads as LinuxCNC does, on each of the
    16 profiles; so its output has no TG100 the blank-free program's output has not (a
    target with no parameters refuses `#` either way)."""
    from postproc.check import check_text

    def outcome(program: str) -> tuple[str, list[tuple[str, int, str]]]:
        try:
            out = convert(program, "linuxcnc", target)
        except ConversionError as e:
            return f"refused: {str(e).split(': ', 2)[-1]}", []
        return out, [(f.rule, f.line, f.message)
                     for f in check_text(out, load_profile(target)) if f.rule == "TG100"]

    if target == "linuxcnc":
        assert convert(text, "linuxcnc", target) == text  # as written
        return
    assert outcome(text) == outcome(joined)


def test_a_word_s_blank_is_dropped_only_for_a_target_that_reads_it_otherwise():
    # a Haas alarms on the blank after the address: dropped, upper and lower case alike
    assert convert("g0 x 1.5 y2\nm2\n", "linuxcnc", "haas-mill") == "G21 G0 X1.5 Y2.\nM2\n"
    assert convert("G0 X 1.5 Y2\nM2\n", "linuxcnc", "haas-mill") == "G21 G0 X1.5 Y2.\nM2\n"
    assert convert("O1\nG0 X 1.5 Y2.\nM30\n", "fanuc-mill", "haas-mill") == (
        "O1\nG21 G0 X1.5 Y2.\nM30\n")
    # a FANUC skips it (ISO 6983-1 4-08): kept, as an expression's blanks are on a Haas
    assert convert("G0 X 1.5 Y2\nM2\n", "linuxcnc", "fanuc-mill") == "G0 X 1.5 Y2.\nM2\n"
    assert convert("g0 x [1 + 2]\nm2\n", "linuxcnc", "haas-mill") == "G21 G0 X [1 + 2]\nM2\n"
    # LinuxCNC to LinuxCNC: as written
    assert convert("G0 X1 2.5\nM2\n", "linuxcnc") == "G0 X1 2.5\nM2\n"


@pytest.mark.parametrize("text, column, message", [
    # a FANUC reads #1=#2*#3 as an expression; rs274 stops at the '*' ("Bad character")
    ("O1\n#2=2\n#3=4\n#1=#2*#3\nG0 X#1\nM30\n", 1, "'*' after a value outside [ ]"),
    ("O1\n#4=SIN[30]*2\nG0 X#4\nM30\n", 1, "'*' after a value outside [ ]"),
    ("O1\n#2=2\n#1=[#2+2]*3\nG0 X#1\nM30\n", 1, "'*' after a value outside [ ]"),
    # an operator of another meaning is refused for that first (bitwise OR on a FANUC)
    ("O1\n#2=2\n#3=4\n#1=#2OR#3\nG0 X#1\nM30\n", 1, "OR is a bitwise OR"),
    ("O1\n#2=2\n#3=4\n#4=#2 AND #3\nG0 Y#4\nM30\n", 1, "AND is a bitwise AND"),
])
def test_an_expression_outside_brackets_is_refused_for_linuxcnc(text, column, message):
    """Review 20, 1: a Custom Macro B expression written without [ ] (`#1=#2*#3`) was carried
    to LinuxCNC as written, where rs274 refuses it; the bracketed test alone looked at it."""
    with pytest.raises(ConversionError) as e:
        convert(text, "fanuc-mill", "linuxcnc")
    assert e.value.code == "conversion-meaning"
    line = next(i for i, t in enumerate(text.splitlines(), 1)
                if t.startswith("#") and not t[3:].lstrip("=").replace(".", "").isdigit())
    assert str(e.value).startswith(f"<input>:{line}:{column}: "), str(e.value)
    assert message in str(e.value)
    # the same value in [ ] is carried
    if "OR" not in text and "AND" not in text:
        lines = text.splitlines()
        name, value = lines[line - 1].split("=", 1)
        lines[line - 1] = f"{name}=[{value}]"
        bracketed = "\n".join(lines) + "\n"
        assert convert(bracketed, "fanuc-mill", "linuxcnc") == bracketed


@pytest.mark.parametrize("target", ["fanuc-mill", "haas-mill"])
def test_blanks_inside_a_parameter_or_expression_number_are_dropped(target, tmp_path):
    """Review 21, 2: rs274 drops every blank outside comments, so `X#1 0` is X#10 (compared
    with rs274 -g where installed); a FANUC or Haas reads `X#1` and a number without an
    address. A word with a blank inside a number is written whole, its blanks dropped."""
    from postproc.check import check_text

    from .conftest import rs274_output

    cases = [("G0 X#1 0", "G0 X#10"), ("G0 X[1 0]", "G0 X[10]"), ("#2 0=3", "#20=3"),
             ("G0 X[#10 + 1 0]", "G0 X[#10+10]"), ("G0 X- [1 0 + 2]", "G0 X-[10+2]"),
             ("G0 X[#10 + 1]", "G0 X[#10 + 1]")]
    for written, read in cases:
        text = f"G21 G90\n#10=5\n#1=1\n{written}\nM2\n"
        out = convert(text, "linuxcnc", target)
        assert out.splitlines()[-2] == read, out
        assert [f for f in check_text(out, load_profile(target)) if f.severity == "error"] == []
    # the source's own reading: rs274 reads X#1 0 as X#10 (5), X[1 0] as X10
    out = rs274_output(tmp_path, "G21 G90\n#10=5\n#1=1\nG0 X#1 0\nG0 X[1 0]\nM2\n")
    assert "STRAIGHT_TRAVERSE(5.0000," in out and "STRAIGHT_TRAVERSE(10.0000," in out, out
    # LinuxCNC to LinuxCNC: as written
    assert convert("G21\nG0 X[1 0]\nM2\n", "linuxcnc") == "G21\nG0 X[1 0]\nM2\n"


def test_a_value_after_a_value_in_brackets_is_named_so():
    # review 21, 2: the `]` is there; the reading stops at the second value
    from postproc.check import check_text

    found = [f for f in check_text("O1\nG21 G90\nG0 X[1 0]\nM30\n", load_profile("fanuc-mill"))
             if f.rule == "TG100"]
    assert [(f.line, f.column) for f in found] == [(3, 8)], found
    assert found[0].message.startswith("'0' after a value inside [ ], where an operation or the "
                                       "closing ']' must follow it"), found
    unclosed = [f for f in check_text("O1\nG21 G90\nG0 X[1\nM30\n", load_profile("fanuc-mill"))
                if f.rule == "TG100"]
    assert [f.message for f in unclosed] == ["'[' without a closing ']' in the expression"]


@pytest.mark.parametrize("block, word", [
    ("G1 X10. F100. M98 P100", "<input>:4:15: M98 after other words or a comment of its block"),
    ("G2 X10. Y0 R5. F100. M98 P100", "<input>:4:22: M98 after other words"),
    ("M98 P100 M08", "<input>:4:10: M08 after M98"),
    ("(CALL) M98 P100", "<input>:4:8: M98 after other words or a comment"),
])
@pytest.mark.parametrize("source", ["fanuc-mill", "haas-mill"])
def test_m98_beside_other_words_is_refused_for_linuxcnc(source, block, word):
    """Review 28, finding 3: a FANUC/Haas block that moves and then calls (`G1 X10. F100.
    M98 P100`) was converted "ok" to LinuxCNC, which refuses M98 after other words ("Unknown
    m code used: M98", rs274ngc interp_read.cc read_o) and runs none of the words after its
    P and L. Refused, naming the word; the block as LinuxCNC reads it converts."""
    text = f"O1000\nG21 G17 G90\nG0 X0 Y0 Z5.\n{block}\nM30\n"
    with pytest.raises(ConversionError) as e:
        convert(text, source, "linuxcnc")
    assert word in str(e.value)
    assert "tapegate does not split the block" in str(e.value)
    split = text.replace(block, "G1 X10. F100.\nM98 P100 L2")
    assert convert(split, source, "linuxcnc").splitlines()[3:5] == ["G1 X10. F100.",
                                                                    "M98 P100 L2"]


@pytest.mark.parametrize("source", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("line", [
    "#3000=1(TOOL BROKEN)", "#3006=1(CHECK PART)", "#3901=#3901+1",
    "IF[#4003 EQ 91]THEN #3000=2(NO TOOL)", "IF[#4003 EQ 91]GOTO10",
])
def test_a_system_variable_that_holds_no_length_converts(source, line):
    """Audit 50, B6: the alarm #3000, the message stop #3006, the parts count #3901 and the
    modal G code #4003 are no lengths (FANUC 0i-MF "System variables", Haas NGC Macro
    Variables Table): set or compared, they are kept as written and the program converts."""
    src = f"%\nO1001\nG21 G90\n{line}\nG0 X10.\nN10 M30\n%\n"
    out = convert(src, source, units="inch").splitlines()
    assert out[2:5] == ["G20 G90", line, "G0 X0.3937"]


@pytest.mark.parametrize(("line", "at", "why"), [
    # a position, a work offset: lengths, refused as before
    ("#100=#5021", (4, 1), "#100 is assigned on line 4 but never read"),
    ("#5221=10.", (4, 1), "#5221 is assigned on line 4 but never read"),
    # a parts count read as a length
    ("G0 X#3901", (4, 4), "#3901 is read as a length (line 4), but on this control it is a "
                          "parts count, not a length"),
    # a local in the condition may be a caller's length; a THEN target that is a length
    ("IF[#1 EQ 91]THEN #3000=2", (4, 1), "it holds a number the converter cannot show"),
    ("IF[#4003 EQ 91]THEN #1=2\nG0 X#1", (4, 1), "it holds a number the converter cannot show"),
])
def test_a_system_variable_that_holds_a_length_is_still_refused(line, at, why):
    src = f"%\nO1001\nG21 G90\n{line}\nG0 X10.\nM30\n%\n"
    with pytest.raises(ConversionError) as refused:
        convert(src, "fanuc-mill", units="inch")
    assert (refused.value.line, refused.value.column) == at
    assert why in refused.value.message
