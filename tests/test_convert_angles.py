"""Words a code makes angles, directions, factors or selectors: kept by a units conversion, and
never taken for a position, a radius or a word read in increments by the checker.

One table in the core (``crates/core/src/meaning.rs``) says what each such word is, from each
control's documentation (docs/convert.md, "Words a code gives another meaning"); these tests
hold the converter, ``--verify`` and the checker to it on the built-in profiles, with round
trips metric -> inch -> metric where the numbers allow one.
"""

from __future__ import annotations

import re
from decimal import Decimal
from pathlib import Path

import pytest

from formats.convert import ConvertOptions, convert_file
from formats.errors import ConversionError
from formats.parser import parse_text
from formats.profile import load_profile
from postproc.check import check_text
from postproc.state import state_at


def convert(tmp_path: Path, text: str, profile: str, units: str, name: str = "p.nc") -> str:
    """The program converted to ``units`` on its own profile, verified."""
    source = tmp_path / name
    source.write_text(text)
    out = tmp_path / f"{units}-{name}"
    prof = load_profile(profile)
    convert_file(str(source), str(out), ConvertOptions(prof, prof, units=units), verify=True,
                 overwrite=True)
    return out.read_text()


# One program per row of the task's table and per class: (profile, metric source, inch output).
CASES = {
    "fanuc rotation": ("fanuc-mill", "G21\nG68 X25.4 Y0 R45.\nG69\nM30\n",
                       "G20\nG68 X1. Y0 R45.\nG69\nM30\n"),
    "fanuc 3D rotation": ("fanuc-mill", "G21\nG68 X0 Y0 Z25.4 I0 J1. K0 R30.\nG69\nM30\n",
                          "G20\nG68 X0 Y0 Z1. I0 J1. K0 R30.\nG69\nM30\n"),
    "fanuc tilted plane": ("fanuc-mill", "G21\nG68.2 X25.4 Y0 Z0 I0. J45. K0.\nG53.1\nG69\nM30\n",
                           "G20\nG68.2 X1. Y0 Z0 I0. J45. K0.\nG53.1\nG69\nM30\n"),
    "fanuc polar G17": ("fanuc-mill", "G21 G17\nG16\nG00 X25.4 Y30.\nG01 X50.8 Y-60. F254.\n"
                                      "G15\nG00 X25.4 Y25.4\nM30\n",
                        "G20 G17\nG16\nG00 X1. Y30.\nG01 X2. Y-60. F10.\nG15\nG00 X1. Y1.\nM30\n"),
    "fanuc polar G18": ("fanuc-mill", "G21 G18\nG16\nG00 Z25.4 X45.\nG15\nM30\n",
                        "G20 G18\nG16\nG00 Z1. X45.\nG15\nM30\n"),
    "fanuc polar G19": ("fanuc-mill", "G21 G19\nG16\nG00 Y25.4 Z90.\nG15\nM30\n",
                        "G20 G19\nG16\nG00 Y1. Z90.\nG15\nM30\n"),
    "fanuc selectors": ("fanuc-mill", "G21\nG05.1 Q1\nG05 P10000\nG08 P1\nG01 X25.4 F254.\n"
                                      "G08 P0\nG05.1 Q0\nM30\n",
                        "G20\nG05.1 Q1\nG05 P10000\nG08 P1\nG01 X1. F10.\nG08 P0\nG05.1 Q0\nM30\n"),
    "fanuc scaling per axis": ("fanuc-mill", "G21\nG51 X25.4 Y0 I2. J2.\nG50\nM30\n",
                               "G20\nG51 X1. Y0 I2. J2.\nG50\nM30\n"),
    "haas accuracy control": ("haas-mill", "G21\nG187 P2 E0.254\nM30\n",
                              "G20\nG187 P2 E0.01\nM30\n"),
    "haas bolt hole arc": ("haas-mill", "G21\nG81 Z-2.54 R2.54 F254. L0\nG71 I50.8 J45. K30. L4\n"
                                        "G80\nM30\n",
                           "G20\nG81 Z-0.1 R0.1 F10. L0\nG71 I2. J45. K30. L4\nG80\nM30\n"),
    "linuxcnc rotation": ("linuxcnc", "G21\nG10 L2 P1 X25.4 R45\nG10 L20 P2 Y0 R30\nM2\n",
                          "G20\nG10 L2 P1 X1. R45\nG10 L20 P2 Y0 R30\nM2\n"),
    "linuxcnc polar words": ("linuxcnc", "G21\nG1 @25.4 ^30 F254\nM2\n",
                             "G20\nG1 @1. ^30 F10.\nM2\n"),
    "linuxcnc io numbers": ("linuxcnc", "G21\nM66 P0 L3 Q5\nM19 R90 Q2\nM2\n",
                            "G20\nM66 P0 L3 Q5\nM19 R90 Q2\nM2\n"),
    # M66-M68 E: an analog input or output number; G76 E: the thread's taper, a length
    "linuxcnc analog numbers and thread taper": (
        "linuxcnc", "G21\nM67 E1 Q2\nM68 E2 Q3\nM66 E0 L0\nG18\n"
                    "G76 P2.54 Z-25.4 I-0.254 J0.254 K2.54 E2.54\nM2\n",
        "G20\nM67 E1 Q2\nM68 E2 Q3\nM66 E0 L0\nG18\nG76 P0.1 Z-1. I-0.01 J0.01 K0.1 E0.1\nM2\n"),
    # M61 Q: the tool number taken as loaded (rs274 would take a scaled Q0.11811 as tool 0)
    "linuxcnc tool number": ("linuxcnc", "G21\nM61 Q3\nG0 X25.4\nM2\n",
                             "G20\nM61 Q3\nG0 X1.\nM2\n"),
    # G10 L1 I J: a lathe tool's front and back angles; M100-M199 P Q: a user program's numbers
    "linuxcnc tool angles and user codes": (
        "linuxcnc", "G21\nG10 L1 P1 Z25.4 I80 J30 Q2\nM100 P1.5 Q2\nM2\n",
        "G20\nG10 L1 P1 Z1. I80 J30 Q2\nM100 P1.5 Q2\nM2\n"),
    "sinumerik frames": ("sinumerik-840d", "G71\nTRANS X25.4 Y-12.7\nATRANS Z=2.54\nROT Z45\n"
                                           "AROT RPL=30\nSCALE X2 Y2\nMIRROR X0\nTRANS\nM30\n",
                         "G70\nTRANS X1. Y-0.5\nATRANS Z=0.1\nROT Z45\nAROT RPL=30\n"
                         "SCALE X2 Y2\nMIRROR X0\nTRANS\nM30\n"),
    "sinumerik named lengths and angles": (
        "sinumerik-840d", "G71\nG2 X25.4 Y0 CR=12.7\nG1 X50.8 RND=2.54\nG1 X76.2 CHF=1.27\n"
                          "G111 X0 Y0\nG1 RP=25.4 AP=45\nG3 X0 Y25.4 AR=90\nM30\n",
        "G70\nG2 X1. Y0 CR=0.5\nG1 X2. RND=0.1\nG1 X3. CHF=0.05\n"
        "G111 X0 Y0\nG1 RP=1. AP=45\nG3 X0 Y1. AR=90\nM30\n"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_each_word_is_converted_by_what_it_means_and_back(tmp_path, case):
    profile, metric, inch = CASES[case]
    out = convert(tmp_path, metric, profile, "inch")
    assert out == inch
    # the round trip: every length here is a whole number of 0.0001 in, so the metric
    # program comes back with the same values (a whole number gains its point)
    back = convert(tmp_path, out, profile, "metric", name="back.nc")
    assert numbers(back) == numbers(metric)


def numbers(text: str) -> list[tuple[str, Decimal]]:
    """The words of a program as (address, value): 25.4 and 25.40, X10 and X10. alike."""
    return [(m.group(1), Decimal(m.group(2))) for m in
            re.finditer(r"([A-Z@^]+ *=? *)(-?[0-9]*\.?[0-9]+\.?)", text.upper())]


def test_the_task_s_table_from_the_reproduction(tmp_path):
    """The six rows as reported, each on the built-in profile named."""
    assert convert(tmp_path, "G21\nG68 X0 Y0 R45.\nM30\n", "fanuc-mill", "inch") \
        == "G20\nG68 X0 Y0 R45.\nM30\n"
    assert convert(tmp_path, "G21\nG68.2 X10. Y0 Z0 I0. J45. K0.\nM30\n", "fanuc-mill",
                   "inch") == "G20\nG68.2 X0.3937 Y0 Z0 I0. J45. K0.\nM30\n"
    assert convert(tmp_path, "G21 G17\nG16\nG0 X10. Y30.\nG15\nM30\n", "fanuc-mill",
                   "inch") == "G20 G17\nG16\nG0 X0.3937 Y30.\nG15\nM30\n"
    assert convert(tmp_path, "G21\nG05.1 Q1\nM30\n", "fanuc-mill", "inch") \
        == "G20\nG05.1 Q1\nM30\n"
    assert convert(tmp_path, "G21\nG10 L2 P1 X10 R45\nM2\n", "linuxcnc", "inch") \
        == "G20\nG10 L2 P1 X0.393701 R45\nM2\n"
    assert convert(tmp_path, "G71\nTRANS X10\nM30\n", "sinumerik-840d", "inch") \
        == "G70\nTRANS X0.3937\nM30\n"


def test_a_lathe_s_g68_is_no_rotation(tmp_path):
    """FANUC lathe G68: mirror image for double turrets, no angle; Haas lathe G15/G16: the
    secondary spindle, no polar coordinates."""
    out = convert(tmp_path, "G21\nG68\nG00 X25.4 Z0\nG69\nM30\n", "fanuc-lathe", "inch")
    assert out == "G20\nG68\nG00 X1. Z0\nG69\nM30\n"
    out = convert(tmp_path, "G21\nG15\nG00 X25.4 Z25.4\nM30\n", "haas-lathe", "inch")
    assert out == "G20\nG15\nG00 X1. Z1.\nM30\n"


def test_statements_that_cannot_be_shown_lengths_are_still_refused(tmp_path):
    for text, column in (("G71\nG2 X1 Y0 CR=5+R2\nM30\n", 10),
                         ("G71\nTRANS X=R1\nM30\n", 1),
                         ("G71\nG1 X1 SPOS=45\nM30\n", 7)):
        with pytest.raises(ConversionError) as info:
            convert(tmp_path, text, "sinumerik-840d", "inch")
        assert info.value.line == 2 and info.value.column == column, str(info.value)
    # a frame before the program's units code would be read in the other units
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, "TRANS X10\nG71 G1 X1\nM30\n", "sinumerik-840d", "inch")
    assert (info.value.line, info.value.column) == (1, 8)
    assert "before the program selects its units" in str(info.value)


# -- the checker --------------------------------------------------------------------------------


def test_a_selector_has_no_decimal_point_to_miss():
    fanuc = load_profile("fanuc-mill")
    quiet = "%\nO1000\nG21 G90\nG01 X1. F100.\nG05.1 Q1\nG05 P10000\nG08 P1\nM30\n%\n"
    assert not [f for f in check_text(quiet, fanuc) if f.rule == "TG201"]
    # a peck Q without its point is still read in increments
    peck = "%\nO1000\nG21 G90\nG01 X1. F100.\nG83 Z-10. R1. Q5\nG80\nM30\n%\n"
    found = [f for f in check_text(peck, fanuc) if f.rule == "TG201"]
    assert [(f.line, f.column) for f in found] == [(5, 15)]


def test_a_polar_move_leaves_the_position_unknown():
    fanuc = load_profile("fanuc-mill")
    text = "G21 G17 G90\nG00 X10. Y10.\nG16\nG00 X100. Y30.\nG15\nG00 X5.\n"
    state = state_at(parse_text(text, fanuc.dialect), fanuc, 5)
    assert state.position.get("Y") is None and state.position.get("X") is None
    state = state_at(parse_text(text, fanuc.dialect), fanuc, 3)
    assert (state.position["X"], state.position["Y"]) == (10, 10)


def test_a_selector_and_an_angle_without_their_point(tmp_path):
    """A selector is the whole number written, whatever the formats; an angle without its
    point counts 0.001 degree (the A format) in inch as in metric, on a FANUC."""
    fanuc = load_profile("fanuc-mill")
    source = tmp_path / "s.nc"
    source.write_text("G21\nG05.1 Q1\nG68 X0 Y0 R45.\nM30\n")
    out = tmp_path / "implicit.nc"
    convert_file(str(source), str(out), ConvertOptions(fanuc, fanuc, units="inch",
                                                       decimal="implicit"), verify=True)
    assert out.read_text() == "G20\nG05.1 Q1\nG68 X0 Y0 R45000\nM30\n"
    # the same angle in increments, written in inch, is 45 degrees
    assert convert(tmp_path, "G20\nG68 X0 Y0 R45000\nG16\nG00 X1. Y30000\nG15\nM30\n",
                   "fanuc-mill", "metric") \
        == "G21\nG68 X0 Y0 R45.\nG16\nG00 X25.4 Y30.\nG15\nM30\n"
    # a lathe's G73 R is the number of divisions
    assert convert(tmp_path, "G21\nG73 U2. W0 R3\nM30\n", "fanuc-lathe", "inch") \
        == "G20\nG73 U0.0787 W0 R3\nM30\n"


def test_an_okuma_thread_cycle_counts_its_threads(tmp_path):
    """OSP-P200L (5238-E), fixed thread cutting cycle G31/G33: the lead is F/J, J the number of
    threads within F: J stays the count written, F E L are lengths (L the chamfer's)."""
    text = "$T1.MIN%\nG21\nG0 X30. Z5.\nG33 X25.4 Z-25.4 F2.54 J2 E2.54 L1.27\nM2\n"
    out = convert(tmp_path, text, "okuma-lathe", "inch", name="t.min")
    assert "G33 X1. Z-1. F0.1 J2 E0.1 L0.05" in out


def test_a_corner_chamfer_or_rounding_is_converted_as_a_length(tmp_path):
    """`,C` and `,R` are lengths (FANUC, "Chamfering and corner R"; Haas, "Corner rounding and
    chamfering"): converted with the axis words beside them, verified; `,A` (the angle of
    direct drawing dimensions) stays as written. A value given by a parameter or an expression
    is refused at the corner word with the true reason, never left in the old units."""
    text = "%\nO1000\nG21\nG0 X0 Y0\nG1 X10. ,C1. F100.\nY10. ,R2.\nX20. Y20. ,A45.\nM30\n%\n"
    out = convert(tmp_path, text, "fanuc-mill", "inch")
    assert out.splitlines()[4:7] == ["G1 X0.3937 ,C0.0394 F3.937", "Y0.3937 ,R0.0787",
                                     "X0.7874 Y0.7874 ,A45."]
    assert convert(tmp_path, text, "fanuc-mill", "metric") == text
    # the same on a lathe (issue 32's fl1.nc), and on a Haas
    lathe = "%\nO2000\nG20 G99\nG0 X2. Z0.1\nG1 Z0 F0.01\nX2.5 ,C0.05\nZ-1. ,R0.1\nM30\n%\n"
    assert convert(tmp_path, lathe, "fanuc-lathe", "metric").splitlines()[5:7] == [
        "X63.5 ,C1.27", "Z-25.4 ,R2.54"]
    assert convert(tmp_path, text, "haas-mill", "inch").splitlines()[5] == "Y0.3937 ,R0.0787"
    computed = text.replace(",R2.", ",R#1")
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, computed, "fanuc-mill", "inch")
    assert (info.value.line, info.value.column) == (6, 6)
    assert "a chamfer's or corner rounding's length given by a parameter or an expression" \
        in info.value.message
    assert "cannot show to be a length" not in info.value.message


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("from_decimal, chamfer, rounding", [
    # the profile's own reading and --from-decimal increments: ,C5 counts least input
    # increments as X40000 beside it does (0.0005 in = 0.0127 mm, to the 0.001 mm format)
    (None, ",C0.013", ",R0.013"),
    ("increments", ",C0.013", ",R0.013"),
    # --from-decimal explicit: X4 and ,C5 are whole inches
    ("explicit", ",C127.", ",R127."),
])
def test_a_corner_without_its_point_is_read_as_an_axis_word(tmp_path, profile, from_decimal,
                                                           chamfer, rounding):
    """FANUC "Decimal point programming": a distance written without a point counts least
    input increments where the source does; a corner's `,C`/`,R` is such a distance and is
    read by the same rule as the axis words of its block, never as whole units (review 8,
    finding 1: `,C5` became `,C127.` beside `X40000` read as 4 in, and was verified). A corner
    written with its point is read as written whatever the reading of the others."""
    axes = "X4." if from_decimal == "explicit" else "X40000"
    text = (f"%\nO0013\nG20 G90 G94\nG0 X0 Y0\nG1 {axes} ,C5 F10.\nY4. ,R5\n"
            "X0 ,C.1\nM30\n%\n")
    source = tmp_path / "c.nc"
    source.write_text(text)
    out = tmp_path / "c-mm.nc"
    prof = load_profile(profile)
    convert_file(str(source), str(out),
                 ConvertOptions(prof, prof, units="metric", from_decimal=from_decimal),
                 verify=True, overwrite=True)
    assert out.read_text().splitlines()[4:7] == [f"G1 X101.6 {chamfer} F254.",
                                                 f"Y101.6 {rounding}", "X0 ,C2.54"]
    # in its own units the corner is written with its point as X is: ,C5 read as 0.0005 in
    # is ,C0.0005, not a ,C5 a target reading whole numbers takes for 5 in
    convert_file(str(source), str(out), ConvertOptions(prof, prof, from_decimal=from_decimal),
                 verify=True, overwrite=True)
    # and a `,C5` read as 5 in (--from-decimal explicit) is written `,C5.`: the target reads a
    # corner without its point in increments, as 0.0005 in (the proof reads it so and caught it)
    kept = (",C5.", ",R5.") if from_decimal == "explicit" else (",C0.0005", ",R0.0005")
    assert out.read_text().splitlines()[4:7] == [f"G1 X4. {kept[0]} F10.", f"Y4. {kept[1]}",
                                                 "X0 ,C.1"]


@pytest.mark.parametrize("body, line", [
    ("G1 X1 E1 F100\n", 3),
    ("G0 X1e3\n", 3),  # an exponent: X1 and E3, as rs274 reads it
    ("E1\n", 3),
    ("S100 M3\nG33 Z-1 K1\nG1 X1\nZ-2 E1\n", 6),  # G1 in force, not G33
    ("o100 call\nE1\n", 4),  # no axis word: no motion mode runs it, whatever the call set
])
def test_a_linuxcnc_e_word_no_code_uses_is_refused(tmp_path, body, line):
    """rs274 refuses a block whose E no G33, G33.1, G70, G76 or M66-M68 uses ("E word with no
    G70, G76, M66, M67 or M68 to use it"): the check says so (TG412, at the E), and a change of
    units refuses it rather than scale a word with no meaning."""
    text = "G21 G90 G18\nG0 X0 Z5\n" + body + "M2\n"
    if "o100" in body:
        text += "o100 sub\nG90 G0 X2\no100 endsub\n"
    refusals = [f for f in check_text(text, load_profile("linuxcnc")) if f.rule == "TG412"]
    assert [(f.line, f.severity) for f in refusals] == [(line, "error")]
    assert refusals[0].message.startswith(
        "E word with no G70, G76, M66, M67 or M68 to use it (rs274ngc)")
    with pytest.raises(ConversionError) as info:
        convert(tmp_path, text, "linuxcnc", "inch")
    assert "E word with no G70, G76, M66, M67 or M68 to use it" in str(info.value)
    # in its own units nothing is converted: the program is written as it was
    assert convert(tmp_path, text, "linuxcnc", "metric") == text


@pytest.mark.parametrize("body, converted", [
    # G33 in force runs the block, and rs274 accepts its E (which G33 does not use)
    ("G33 Z-2.54 K2.54\nZ-5.08 K2.54 E2.54\n", "G33 Z-0.1 K0.1\nZ-0.2 K0.1 E0.1\n"),
    ("G33.1 Z-2.54 K2.54 E2.54\n", "G33.1 Z-0.1 K0.1 E0.1\n"),
    # after a call the motion in force is not known: a moving block may be a G76's
    ("o100 call\nZ-5.08 E2.54\n", "o100 call\nZ-0.2 E0.1\n"),
])
def test_a_linuxcnc_e_word_a_code_may_use_is_converted(tmp_path, body, converted):
    text = "G21 G90 G18\nG0 X0 Z5\nS100 M3\n" + body + "M2\n"
    if "o100" in body:
        text += "o100 sub\nG90 G0 X2\no100 endsub\n"
    assert [f for f in check_text(text, load_profile("linuxcnc")) if f.rule == "TG412"] == []
    out = convert(tmp_path, text, "linuxcnc", "inch")
    assert out.splitlines()[3:3 + converted.count("\n")] == converted.splitlines()
