"""The dialects of real controls (docs/dialects.md): each family's statements are read into the
program model, printed back byte for byte, and followed by the checker as far as it can.

The measure is real programs: every file of the corpus reprints byte-identically on its matching
built-in profile and parses completely (no error that comes only from reading), and so do the
sample programs LinuxCNC ships, wherever LinuxCNC's interpreter rs274 accepts them too.
"""

from __future__ import annotations

import dataclasses
import re
import shutil
import subprocess
from decimal import Decimal
from fractions import Fraction
from pathlib import Path

import pytest
from click.testing import CliRunner

from formats.convert import ConvertOptions, convert_file
from formats.diff import DiffOptions, diff_files
from formats.errors import ConversionError, ParseError
from formats.parser import BadBlock, count_blocks, parse_stream, parse_text
from formats.printer import program_text
from formats.profile import NEUTRAL, builtin_text, load_profile, profile_from_text
from formats.source import Source
from formats.verify import verify_conversion
from formats.wordformat import Rounding
from postproc.check import Checker
from tapegate.cli import main

from .conftest import CORPUS, corpus_files, needs_corpus, rs274_env, rs274_output

# The rules a finding of which means the program could not be read: characters, statements,
# number format. The measure: none of them with error severity on the matching profile.
READING = {"TG100", "TG101", "TG120", "TG121", "TG125", "TG201", "TG202", "TG203", "TG204",
           "TG205", "TG206"}

# Each corpus program of a family with a built-in profile, and that profile (SOURCES.md says
# what each program is). The others have no family here: the H&K and foam-cutter controls and a
# Fagor-style post (`: G90` blocks); the corpus test reads them with the permissive dialect.
MATCHING = {
    "cnc-sprayer__7997A.NC": "fanuc-mill",
    "GCodeWorkShop__FANUC0M.nc": "fanuc-mill",
    "Post-Processing__1401.nc": "fanuc-mill",
    "vip74120.github.io__T.NC": "fanuc-mill",
    "vip74120.github.io__1223.NC": "fanuc-mill",
    "GCodeWorkShop__FANUC0T.nc": "fanuc-lathe",
    "GCodeWorkShop__TOKARKA.NC": "fanuc-lathe",
    "CNC-GCode-Milling-and-Lathe__2001.nc": "fanuc-lathe",
    "GCodeWorkShop__HAAS.nc": "haas-mill",
    "enier-cnc__1006.nc": "haas-mill",
    "Praktikum-CAD-CAM-Modul-12__1001.nc": "haas-mill",
    "AplicacionWebDePrueba__1010.nc": "haas-mill",
    "enier-cnc__round_head_plug.nc": "haas-lathe",
    "Hass-CNC-Programs__CaliperDepthAttachmentThumbscrew.nc": "haas-lathe",
    "Five-Axis-Milling-Dataset__Bottle_opener_Flaschenoeffner.txt": "sinumerik-840d",
    "GCodeWorkShop__SINUMERIK850.nc": "sinumerik-840d",
    # Fusion 360's Mach3 post: G91.1, the LinuxCNC-style dialect
    "cnc-sprayer__fusion-inch.nc": "linuxcnc",
}

# Real format errors in the program itself, not reading. (The hand-written Haas lathe program's
# thread height K0.07065 and first cut D0.0176625 in inches, finer than the control's 0.0001 in,
# are TG208 warnings: no Haas source says the control alarms on them.)
KNOWN_FORMAT_ERRORS: dict[str, int] = {}


def blocks(text: str, profile: str):
    return parse_text(text, load_profile(profile).dialect, errors="collect")


def findings(text: str, profile: str) -> list:
    prof = load_profile(profile)
    return list(Checker(prof).run(parse_text(text, prof.dialect, errors="collect")))


def rules(text: str, profile: str) -> list[str]:
    return [f.rule for f in findings(text, profile)]


# -- Fanuc and Haas: Custom Macro B -------------------------------------------------------------

MACRO = """%
O7997A (NESTED CUTOFF)
#136=.375 (DISTANCE)
#114=#5021#115=#5022
N10 IF [#118 EQ #116] AND [#119 EQ #117] GOTO 40
WHILE [#1 LT 10] DO1
#1 = #1 + 1
END1
G90 G00 X#114-#136 Y#115
#101 = 250.
G01 X[#114 + 2] F#101
N40 IF [ #5405 GE 6000 ] THEN #3000= 15 ( TOOL LIFE )
GOTO 50
N50 M30
%
"""


def test_macro_b_statements_are_read_kept_and_reprinted():
    read = blocks(MACRO, "fanuc-mill")
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert program_text(read) == MACRO
    statements = [s for b in read for s in b.statements]
    assert [(text, kind) for _, text, kind in statements] == [
        ("O7997A", "name"),
        ("IF [#118 EQ #116] AND [#119 EQ #117] GOTO 40", "flow"),
        ("WHILE [#1 LT 10] DO1", "flow"),
        ("END1", "flow"),
        ("IF [ #5405 GE 6000 ] THEN #3000= 15", "flow"),
        ("GOTO 50", "flow"),
    ]
    assert read[8].words == ["G90", "G00", "X#114-#136", "Y#115"]
    assert read[4].statements[0][0] == 5  # the column of IF after N10


def test_what_the_checker_cannot_know_is_unknown_not_missing():
    found = findings(MACRO, "fanuc-mill")
    codes = [f.rule for f in found]
    # F#101 is a feed in force: no "no feed" error; X#114-#136 no arc check from it
    assert "TG401" not in codes and "TG403" not in codes
    # each said once, as a note, where it first happens
    assert codes.count("TG140") == 1 and codes.count("TG141") == 1
    jump = next(f for f in found if f.rule == "TG140")
    assert (jump.line, jump.severity) == (5, "info")
    assert "IF [#118 EQ #116]" in jump.message
    unknown = next(f for f in found if f.rule == "TG141")
    assert unknown.line == 9 and "X#114-#136" in unknown.message
    assert not [f for f in found if f.rule in READING and f.severity == "error"]


def test_a_constant_assignment_is_known_until_a_jump():
    """What the checker can know statically it uses: #101 = 20000. makes F#101 a feed of 20000,
    above fanuc-mill's 10000 (TG605: a FANUC clamps it); after a jump the variable may hold
    anything."""
    known = "%\nO1\n#101 = 20000.\nG21 G90 G01 X1. F#101\nM30\n%\n"
    found = findings(known, "fanuc-mill")
    assert [(f.rule, f.line) for f in found if f.rule in ("TG605", "TG141")] == [("TG605", 4)]
    after_jump = "%\nO1\n#101 = 20000.\nGOTO 5\nN5 G21 G90 G01 X1. F#101\nM30\n%\n"
    rules_after = [f.rule for f in findings(after_jump, "fanuc-mill")]
    assert "TG605" not in rules_after and "TG141" in rules_after
    reassigned = known.replace("G21", "#101 = #101 + 1\nG21")
    assert "TG605" not in [f.rule for f in findings(reassigned, "fanuc-mill")]


def test_a_spindle_speed_clamp_is_no_speed_and_a_speed_above_the_maximum_is_a_warning():
    """Audit 37 of the held-out programs: `G50 S8000` (a lathe's spindle speed clamp, Haas and
    FANUC lathe manuals; G92 S on a mill) was TG603 against the profile's maximum, though it
    turns nothing. And no source says a FANUC, Haas or Okuma alarms on an S above the
    machine's maximum rather than limiting it (a SINUMERIK limits it, MD35100): on a family
    profile TG606, a warning naming the profile's machine; the strict ISO profiles keep
    TG603."""
    lathe = ("%\nO0001\nG21 G99 G18\nG50 S8000\nG96 S200 M03\nG00 X50. Z2.\n"
             "G01 Z-10. F0.2\nG97 S{s} M03\nG00 X60.\nM30\n%\n")
    for profile in ("haas-lathe", "fanuc-lathe"):
        assert not [f for f in findings(lathe.format(s=1000), profile)
                    if f.rule in ("TG603", "TG606")], profile
        over = [f for f in findings(lathe.format(s=9000), profile)
                if f.rule in ("TG603", "TG606")]
        assert [(f.rule, f.line, f.severity) for f in over] == [("TG606", 8, "warning")]
        assert "set the profile's spindle_max" in over[0].message
    mill = "%\nO1\nG21 G90\nG92 S15000\nG97 S{s} M03\nM30\n%\n"
    assert not [f for f in findings(mill.format(s=8000), "fanuc-mill")
                if f.rule in ("TG603", "TG606")]
    assert [f.rule for f in findings(mill.format(s=16000), "fanuc-mill")
            if f.rule in ("TG603", "TG606")] == ["TG606"]
    # (review 37, finding 4) a Haas or Okuma mill's G92 sets coordinates only: its S is a speed
    for profile in ("haas-mill", "okuma-mill"):
        if load_profile(profile).limits.spindle_max is None:
            continue
        speed = "%\nO1\nG21 G90\nG92 X0 Y0 Z0 S15000 M03\nM30\n%\n"
        assert [f.rule for f in findings(speed, profile)
                if f.rule in ("TG603", "TG606")] == ["TG606"], profile
    sinumerik = findings("N10 G0 X0 Y0\nN20 S30000 M3\nN30 M30\n", "sinumerik-840d")
    limited = [f for f in sinumerik if f.rule == "TG606"]
    assert len(limited) == 1 and "MD35100" in limited[0].message
    # (review 37, finding 5) a SINUMERIK's G26 S is its upper spindle speed limit: no speed
    g26 = findings("N10 G0 X0 Y0\nN20 G26 S30000\nN30 S1000 M3\nN40 M30\n", "sinumerik-840d")
    assert not [f for f in g26 if f.rule in ("TG603", "TG606")]
    iso = findings("%\nN1 G71\nN2 S7000 M03\nN99 M30\n%\n", "iso-mill")
    assert [(f.rule, f.severity) for f in iso if f.rule in ("TG603", "TG606")] == [
        ("TG603", "error")]
    # (review 37, finding 6) a user's profile's maximum is the user's machine (a chuck's
    # rating): TG603, the error, stays
    own = profile_from_text('base = "haas-lathe"\n[limits]\nspindle_max = 2500\n',
                            source="my-lathe.toml")
    text = lathe.format(s=3500)
    mine = [(f.rule, f.severity) for f in Checker(own).run(iter(parse_text(text, own.dialect)))
            if f.rule in ("TG603", "TG606")]
    assert mine == [("TG603", "error")]


def test_a_users_profile_counts_as_the_users_machine_only_for_the_limits_it_sets(tmp_path):
    """Review 38, finding 4: a user's file on a base that sets no spindle_max of its own (its
    [serial] alone) has the built-in's sample maximum, so an S above it stays TG606, the
    warning, with the sample machine's wording; one that sets spindle_max gets TG603. The same
    for the other limits: the first finding against a limit the file leaves to its base says
    it is the base's sample, not one against a limit the file sets."""
    @dataclasses.dataclass
    class Said:
        rule: str
        severity: str
        message: str

    def found(toml: str, text: str) -> list[Said]:
        """`tapegate check` of `text` with the profile file `toml`: its findings."""
        (tmp_path / "my-mill.toml").write_text(toml)
        (tmp_path / "p.nc").write_text(text)
        result = CliRunner().invoke(main, ["check", str(tmp_path / "p.nc"), "-p",
                                           str(tmp_path / "my-mill.toml")])
        lines = re.findall(r"p\.nc:\d+:\d+: (\w+) (TG\d+) (.*)", result.output)
        return [Said(rule, severity, message) for severity, rule, message in lines]

    speed = "%\nO1\nG20 G90 G54 G0 X0 Y0\nS15000 M03\nG1 X1. F10.\nM30\n%\n"
    serial_only = 'name = "mymill"\nbase = "haas-mill"\n[serial]\nbaud = 9600\n'
    sample = [f for f in found(serial_only, speed) if f.rule in ("TG603", "TG606")]
    assert [(f.rule, f.severity) for f in sample] == [("TG606", "warning")]
    assert "set the profile's spindle_max to your machine's" in sample[0].message
    # (a [limits] table of other keys leaves the spindle's to the base too)
    feed_only = 'base = "haas-mill"\n[limits]\nfeed_max = 500\n'
    assert [f.rule for f in found(feed_only, speed) if f.rule in ("TG603", "TG606")] == [
        "TG606"]
    own = 'base = "haas-mill"\n[limits]\nspindle_max = 12000\n'
    assert [(f.rule, f.severity) for f in found(own, speed)
            if f.rule in ("TG603", "TG606")] == [("TG603", "error")]
    # no base: every limit is the file's own
    whole = builtin_text("haas-mill").replace('name = "haas-mill"', 'name = "mine"', 1)
    assert [f.rule for f in found(whole, speed) if f.rule in ("TG603", "TG606")] == ["TG603"]
    # the travel and the feed: the hint names the base's sample only where the file leaves
    # the limit to it
    far = "%\nO1\nG20 G90 G54 G0 X0 Y0\nG1 X100. F1000.\nM30\n%\n"
    hint = "a typical machine of the family"
    base_only = {f.rule: f.message for f in found(serial_only, far)}
    assert hint in base_only["TG601"] and "built-in profile's limits" in base_only["TG601"]
    travel = found(feed_only, far)
    assert [f.rule for f in travel if f.rule in ("TG601", "TG602")] == ["TG601", "TG602"]
    said = {f.rule: f.message for f in travel}
    assert "this limit is the base profile's" in said["TG601"]
    assert hint not in said["TG602"]
    axes = 'base = "haas-mill"\n[limits]\nX = [-30, 30]\nY = [-16, 16]\nZ = [-20, 0]\n'
    assert not [f for f in found(axes, far) if hint in f.message]
    # (an axis left to the base keeps the travel the sample's)
    assert [f for f in found(axes.replace("Z = [-20, 0]\n", ""), far) if hint in f.message]
    assert load_profile("haas-mill").sample_limits == {"travel", "feed_max", "spindle_max",
                                                       "tool_max"}
    assert profile_from_text(whole, source="mine.toml").sample_limits == frozenset()


def test_a_limit_passed_by_a_program_that_writes_no_units_code_says_so():
    """Audit 37: 28 held-out Haas programs of metric shops write no G21; a Haas reads them in
    the units of its Setting 9, which haas-mill takes as inches, so `Z150.` spans 140 in and
    F1500. is 1500 in/min. Still errors (on a machine set to inches the program does go
    there), but the message says the numbers were read in the assumed units, that in mm they
    fit, and how to check it for a machine set to mm; with G21 written, or where mm would not
    fit either, it does not."""
    text = ("%\nO00001\nG00 G17 G90 G54\nT1 M06\nG43 H1 Z150.\nS1000 M03\n"
            "G01 Z10. F1500.\nG00 Z150.\nM30\n%\n")
    found = [f for f in findings(text, "haas-mill") if f.rule in ("TG601", "TG602")]
    assert [f.rule for f in found] == ["TG601", "TG602"]
    for f in found:
        assert f.severity == "error"
        assert "no units code by here" in f.message and "Setting 9" in f.message, f.message
        assert "--units metric" in f.message
    assert not [f for f in findings(text.replace("G17 G90", "G17 G21 G90"), "haas-mill")
                if f.rule in ("TG601", "TG602")]
    # beyond the travel in mm too: no hint
    far = text.replace("Z150.", "Z1500.")
    spans = [f for f in findings(far, "haas-mill") if f.rule == "TG601"]
    assert spans and "units code" not in spans[0].message
    # (review 37, finding 2) a subprogram after M30 runs under its caller's G21: the file has
    # written a units code, so no hint
    sub = ("%\nO00001\nG21 G00 G17 G90 G54\nM98 P1000\nM30\nO1000\nG43 H1 Z150.\n"
           "G01 Z10. F1500.\nG00 Z150.\nM99\n%\n")
    assert not [f for f in findings(sub, "haas-mill")
                if f.rule in ("TG601", "TG602") and "units code" in f.message]
    # with G20 written the inches are the program's own: no hint
    inch = [f for f in findings(text.replace("G17 G90", "G17 G20 G90"), "haas-mill")
            if f.rule == "TG601"]
    assert inch and "units code" not in inch[0].message


def test_the_first_arc_error_after_mixed_decimal_styles_names_the_likely_cause():
    """Audit 37: ten Grbl-style programs in the FANUC family write `Y10` beside `X10.`; a
    FANUC reads Y10 as 0.010 mm (TG201 says so once), and the arcs after it gave 530 TG403
    errors that did not say why. The file's first arc error names TG201's word as the likely
    cause; the later ones do not repeat it, and an arc error in a program of decimal points
    alone does not say it."""
    text = ("%\nO1\nG21 G90 G17\nG00 X10. Y0.\nG01 Z-1. F100.\nG03 X0 Y10 I-10. J0.\n"
            "G01 X10. Y0.\nG03 X0 Y10 I-10. J0.\nM30\n%\n")
    arcs = [f for f in findings(text, "fanuc-mill") if f.rule == "TG403"]
    assert [f.line for f in arcs] == [6, 8]
    assert "TG201: Y10 on line 6, read as 0.01" in arcs[0].message, arcs[0].message
    assert "TG201" not in arcs[1].message
    decimal = text.replace("Y10 ", "Y1. ")
    arcs = [f for f in findings(decimal, "fanuc-mill") if f.rule == "TG403"]
    assert arcs and not any("TG201" in f.message for f in arcs)


def test_a_sinumerik_changes_d_under_cutter_compensation():
    """Audit 37: `D1 X=XD+unut` under G42 in three held-out SINUMERIK programs was TG502. The
    840Di sl Programming Manual Fundamentals (8.8, "Changing the offset number D") says the
    offset number can be changed in compensation mode, the new radius in effect from its
    block. A T under compensation is still said; elsewhere a D is too."""
    text = ("N10 T1 D1\nN20 G17 G90 G0 X0 Y0 Z5 S1000 M3\nN30 G1 Z-1 F200\n"
            "N40 G1 G41 X10 Y0\nN50 G1 X20\nN60 {word} X30\nN70 G1 G40 X40\nN80 M30\n")
    assert "TG502" not in [f.rule for f in findings(text.format(word="D2"), "sinumerik-840d")]
    assert [(f.rule, f.line) for f in findings(text.format(word="T2"), "sinumerik-840d")
            if f.rule == "TG502"] == [("TG502", 6)]
    fanuc = "%\nO1\n" + text.format(word="D2").replace("N80 M30\n", "N80 M30\n%\n")
    assert "TG502" in [f.rule for f in findings(fanuc, "fanuc-mill")]


def test_a_sinumerik_d_of_an_r_parameter_under_compensation_is_judged_by_its_value(tmp_path):
    """Review 38, finding 7: `D=R1` under G41 was TG502, the error, whatever R1 held. The
    checker evaluates R parameters set before (`R1=2`): a D of 2 is a D change (840Di sl
    Fundamentals 8.8), quiet; one of 0 is D0, the offset off (TG502); one it cannot know
    (`R1=$P_TOOLNO`, the control's own) is TG503, a warning naming D0. Through the CLI."""
    text = ("N10 G71 G90 G17 G0 X0 Y0 T1 D1\nN20 M6\nN30 R1={value}\nN40 G41 G1 X10 Y0 F100\n"
            "N50 D=R1 X20\nN60 G40 X60\nN70 M30\n")
    path = tmp_path / "d.mpf"
    said = {}
    for value in ("2", "0", "$P_TOOLNO"):
        path.write_text(text.format(value=value))
        result = CliRunner().invoke(main, ["check", str(path), "-p", "sinumerik-840d",
                                           "--select", "TG502,TG503"])
        said[value] = re.findall(r"d\.mpf:(\d+):\d+: (\w+) (TG\d+) (.*)", result.output)
    assert said["2"] == []
    assert [(line, rule) for line, _, rule, _ in said["0"]] == [("5", "TG502")]
    [(line, severity, rule, message)] = said["$P_TOOLNO"]
    assert (line, severity, rule) == ("5", "warning", "TG503")
    assert "not known" in message and "D0 switches the offset off under G41" in message


def test_a_feed_above_the_maximum_is_clamped_on_a_fanuc_and_alarms_on_a_haas():
    """Issue 32's severity by evidence: a FANUC clamps a cutting feed above its maximum
    (B-63172EN 4.2.2), a warning; a Haas alarms ("max feedrate exceeded", NGC manual, G01)."""
    fanuc = findings("%\nO1\nG21 G90 G01 X1. F20000.\nM30\n%\n", "fanuc-mill")
    clamped = [f for f in fanuc if f.rule in ("TG602", "TG605")]
    assert [(f.rule, f.severity) for f in clamped] == [("TG605", "warning")]
    assert "clamps" in clamped[0].message
    haas = findings("%\nO1\nG20 G90 G01 X1. F2000.\nM30\n%\n", "haas-mill")
    assert [(f.rule, f.severity) for f in haas if f.rule in ("TG602", "TG605")] == [
        ("TG602", "error")]


def test_a_feed_still_missing_is_still_found():
    assert "TG401" in rules("%\nO1\nG21 G90 G01 X10\nM30\n%\n", "fanuc-mill")


def test_a_statement_the_dialect_does_not_allow_is_located_and_the_rest_is_read():
    text = "%\nO1000\nG21 G90\no100 sub\nG01 X1 F100.\nM30\n%\n"
    read = blocks(text, "fanuc-mill")
    bad = [b for b in read if isinstance(b, BadBlock)]
    assert [(b.line, b.error.code) for b in bad] == [(4, "TG101")]  # lower case: not Fanuc
    assert program_text(read) == text
    assert read[4].words == ["G01", "X1", "F100."]
    found = findings(text, "fanuc-mill")
    assert [(f.rule, f.line, f.column) for f in found if f.severity == "error"] == [
        ("TG101", 4, 1)]


def test_a_fanuc_lathe_dwell_may_give_its_seconds_with_u():
    """Fanuc's lathe dwell takes its time as X, U (seconds) or P (ms): "G04 X_ ; or G04 U_ ;
    or G04 P_ ;". The reader takes U as that time, so the checker does too: `G4 U0.1` (a
    Fusion 360 Doosan PUMA post) is neither a dwell without a duration (TG532) nor a word
    too many (TG531) on the lathe, while a G04 with no time word still is, located at the
    G04, and F, which the lathe's dwell does not name, is a word too many; the mill's dwell
    is X or P only."""
    quiet = "%\nO0001\nG50 S2000\nG04 U0.1\nG04 X0.5\nG04 P500\nM30\n%\n"
    assert not {"TG531", "TG532"} & set(rules(quiet, "fanuc-lathe"))
    without = "%\nO0001\nG04 W0.1\nG97 G04 W1.\nG04 F1.\nM30\n%\n"
    found = [(f.rule, f.line, f.column) for f in findings(without, "fanuc-lathe")
             if f.rule in ("TG531", "TG532")]
    assert found == [("TG532", 3, 1), ("TG531", 3, 5), ("TG532", 4, 5), ("TG531", 4, 9),
                     ("TG532", 5, 1), ("TG531", 5, 5)]
    mill = "%\nO0001\nG04 U0.1\nM30\n%\n"
    assert ("TG532", 3, 1) in [(f.rule, f.line, f.column) for f in findings(mill, "fanuc-mill")]


def linuxcnc_found(text: str, wanted: tuple[str, ...]) -> list[tuple[str, int, int]]:
    return [(f.rule, f.line, f.column) for f in findings(text, "linuxcnc") if f.rule in wanted]


def test_a_linuxcnc_dwell_is_g4_p_only(tmp_path):
    """rs274 takes a dwell's time from P alone: `G4 X1` in a motion mode is "Dwell time
    missing with g4" (TG532, at the G4, the X a word too many, TG531); with no motion mode in
    force rs274 refuses the X first ("Cannot use axis values without a g code that uses
    them", TG411 at the X), with P or without."""
    body = "G21\nG0 X0\nG4 X1\nM2\n"
    assert "Dwell time missing with g4" in rs274_output(tmp_path, body)
    wanted = ("TG411", "TG531", "TG532")
    assert linuxcnc_found(body, wanted) == [("TG532", 3, 1), ("TG531", 3, 4)]
    for body, x in [("G21\nG4 X1\nM2\n", 4), ("G21\nG4 P1 X1\nM2\n", 7)]:
        assert "Cannot use axis values without a g code that uses them" in rs274_output(
            tmp_path, body)
        assert ("TG411", 2, x) in linuxcnc_found(body, wanted)
    assert not linuxcnc_found("G21\nG4 P1\nM2\n", wanted)


def test_a_linuxcnc_dwell_moves_and_feeds_by_its_other_words(tmp_path):
    """rs274 reads `G4 P1 X10` as DWELL(1) then a move to X10 in the motion mode in force, and
    `G4 P1 F100` sets the feed: the arc after the first starts at X10 (no TG403), the feed
    move after the second has its feed (no TG401). Each is still a dwell not alone (TG531)."""
    moved = "G21\nG0 X0 Y0\nG4 P1 X10\nG2 X20 Y0 I5 J0 F100\nM2\n"
    canon = rs274_output(tmp_path, moved)
    assert canon.index("DWELL(1.0000)") < canon.index("STRAIGHT_TRAVERSE(10.0000")
    assert "ARC_FEED(20.0000" in canon
    wanted = ("TG401", "TG403", "TG411", "TG531", "TG532")
    assert linuxcnc_found(moved, wanted) == [("TG531", 3, 7)]
    fed = "G21\nG0 X0 Y0\nG4 P1 F100\nG1 X10\nM2\n"
    canon = rs274_output(tmp_path, fed)
    assert "SET_FEED_RATE(100.0000)" in canon and "STRAIGHT_FEED(10.0000" in canon
    assert linuxcnc_found(fed, wanted) == [("TG531", 3, 7)]


def test_a_sinumerik_dwell_is_f_seconds_or_s_revolutions():
    """Fundamentals, "Dwell time (G4)": `G4 F..` seconds, `G4 S..` revolutions of the master
    spindle; the F and S programmed before stay valid. `G4 S2` is no dwell without its time
    (TG532) and leaves the speed at 1000; X and P are not its dwell words (TG532)."""
    text = "N10 G0 X0 Y0\nN20 S1000 M3\nN30 G4 S2\nN40 G4 F1.5\nN50 G4 P1\nM30\n"
    found = [(f.rule, f.line, f.column) for f in findings(text, "sinumerik-840d")
             if f.rule in ("TG531", "TG532")]
    assert found == [("TG532", 5, 5), ("TG531", 5, 8)]
    from postproc.state import state_at

    profile = load_profile("sinumerik-840d")
    state = state_at(parse_text(text, profile.dialect), profile, 6)
    assert (state.speed, state.feed) == (1000, None)


def test_macro_b_errors_name_what_is_wrong():
    bad = [b for b in blocks("IF #1 GT 2 GOTO 5\nWHILE [#1 LT 2] X1\n", "fanuc-mill")
           if isinstance(b, BadBlock)]
    assert [(b.error.line, b.error.column) for b in bad] == [(1, 4), (2, 17)]
    assert "condition in brackets" in str(bad[0].error)
    assert "DOm" in str(bad[1].error)


# -- LinuxCNC -----------------------------------------------------------------------------------

# #<_rate>, a global of the program's own (#<_feed> is LinuxCNC's feed, read only: TG209)
LINUXCNC = """; a LinuxCNC program: o-words, named parameters, lower case
#<depth> = -1.5
#<_rate> = 300
o100 sub
  g1 z#1 f#<_rate>
o100 endsub
g21 g90 g17 g64 p0.01
g0 x0 y0 z5
o<loop> while [#<depth> lt 0]
  o100 call [#<depth>]
  #<depth> = [#<depth> + 0.5]
o<loop> endwhile
o200 if [#<_rate> GT 100]
  g1 @10 ^45 f100
o200 else if [#<_rate> EQ 0]
  m3 $0 s1000
o200 endif
g91.1 g2 x10 y0 i5 j0 f100
m2
"""


def test_linuxcnc_programs_are_read_and_checked():
    read = blocks(LINUXCNC, "linuxcnc")
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert program_text(read) == LINUXCNC
    kinds = [kind for b in read for _, _, kind in b.statements]
    assert kinds == ["definition", "definition", "flow", "call", "flow", "flow", "flow", "flow"]
    assert read[1].words == ["#<depth>=-1.5"]
    assert read[13].words == ["g1", "@10", "^45", "f100"]
    found = findings(LINUXCNC, "linuxcnc")
    assert not [f for f in found if f.severity == "error"], found


def test_linuxcnc_numbers_words_of_any_size_as_its_interpreter_does(tmp_path):
    """rs274 reads a line number past 99999 (its "greater than 99999" test is commented out:
    "many CAM systems will exceed this") and any non-negative spindle speed; T and H are whole
    numbers of any size to it (a tool number is an index of the tool table, which may hold
    T30601). None of these is a digit overflow (TG205) on the linuxcnc profile; a negative T is
    still refused by the word's sign, and nine digits remain the format's most."""
    body = "G21 G90\nN123456 G0 X1\nS12345678 M3\nG0 X2\nM2\n"
    canon = rs274_output(tmp_path, body)
    assert "SET_SPINDLE_SPEED(0, 12345678.0000)" in canon and "PROGRAM_END" in canon
    assert not [f for f in findings(body, "linuxcnc") if f.severity == "error"]
    tools = "G21 G90\nT30601 M6\nG43 H30601 Z5\nG1 X1 F100 D1234567\nM2\n"
    assert not [f for f in findings(tools, "linuxcnc") if f.rule == "TG205"]
    too_long = [(f.rule, f.line) for f in findings("G21\nT1234567890 M6\nM2\n", "linuxcnc")
                if f.rule == "TG205"]
    assert too_long == [("TG205", 2)]


def test_linuxcnc_refuses_what_its_interpreter_refuses():
    bad = [b for b in blocks("O<g20sub> callsub\n", "linuxcnc") if isinstance(b, BadBlock)]
    assert len(bad) == 1 and "unknown o-word keyword 'callsub'" in str(bad[0].error)


# rs274 stops at an M2/M30 it runs: the line after is never read (a call still finds the
# subroutine defined after the end, reading its O-word lines)
AFTER_END = 'G21 G0 X1\no<s> call\nM30\nprint["Hello World!"]\no<s> sub\nG90 G0 X2\no<s> endsub\n'


def test_linuxcnc_never_reads_the_lines_after_its_end(tmp_path):
    canon = rs274_output(tmp_path, AFTER_END)
    assert "STRAIGHT_TRAVERSE(2.0000" in canon  # the subroutine after M30 ran
    assert "Bad character" not in canon and "PROGRAM_END" in canon
    found = [(f.rule, f.severity, f.line) for f in findings(AFTER_END, "linuxcnc")
             if f.rule not in ("TG133", "TG140")]
    assert found == [("TG117", "warning", 4)]
    # the reprint is the file, and the line is a block of its text alone
    read = blocks(AFTER_END, "linuxcnc")
    assert program_text(read) == AFTER_END
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert read[3].words == [] and read[3].text == 'print["Hello World!"]'
    # parse's counts read it so too (one block, no word), the last line without its LF too
    assert count_blocks([AFTER_END], load_profile("linuxcnc").dialect) == (7, 7, 0)
    assert count_blocks([AFTER_END + "bad"], load_profile("linuxcnc").dialect) == (8, 7, 0)
    # a Fanuc reads on: the words after its M30 are read (and said, TG106: never run, a
    # warning; TG116, the error, on the strict ISO profiles)
    after = rules("%\nO1\nG0 X1\nM30\nG0 X2\n%\n", "fanuc-mill")
    assert "TG106" in after and "TG116" not in after
    assert "TG116" in rules("%\nN1 G71\nN2 G0 X1\nN3 M30\nN4 G0 X2\n%\n", "iso-mill")


def test_a_conversion_keeps_the_lines_after_a_linuxcnc_end(tmp_path):
    """The converter passes over the line rs274 never reads and writes it as it was; the
    converted program verifies against the source (the diff reader passes over it too)."""
    source = tmp_path / "end.ngc"
    source.write_text(AFTER_END)
    out = tmp_path / "end.inch.ngc"
    linuxcnc = load_profile("linuxcnc")
    stats = convert_file(str(source), str(out), ConvertOptions(linuxcnc, linuxcnc, units="inch"),
                         verify=True)
    assert stats.verified
    text = out.read_text()
    assert 'M30\nprint["Hello World!"]\no<s> sub\n' in text
    assert "X0.03937" in text
    # said once: such a line is left in the source's units
    unread = [n for n in stats.notes if "never reads" in n]
    assert len(unread) == 1 and unread[0].startswith("line 4:"), stats.notes


def test_linuxcnc_reads_the_blanks_out_of_a_parameter_number(tmp_path):
    """rs274 drops blanks before it reads a line: `#1 2 = 3` sets #12, as `G0 X#1 2` reads it."""
    text = "G21\n#1 2 = 3\nG0 X#12\nG0 X#1 2\nM2\n"
    assert "STRAIGHT_TRAVERSE(3.0000" in rs274_output(tmp_path, text)
    read = blocks(text, "linuxcnc")
    assert read[1].words == ["#12=3"] and read[3].words == ["G0", "X#12"]
    assert program_text(read) == text
    assert not [f for f in findings(text, "linuxcnc") if f.rule in ("TG100", "TG141")]


def rs274_refuses(tmp_path: Path, text: str) -> str | None:
    """rs274's message on ``text`` (its last line but one when it stops), None where it runs
    the program through, or the test is skipped where LinuxCNC's rs274 is not installed."""
    lines = rs274_output(tmp_path, text).splitlines()
    return next((m for m in ("Parameter is readonly",
                             "File ended with no percent sign or program end")
                 if any(m in line for line in lines)), None)


def test_a_variable_chosen_by_a_negative_expression_is_out_of_range():
    found = [(f.rule, f.line) for f in findings("%\nO1\n#1=-3\n#[#1+1]=1\n#[0]=1\nM30\n%\n",
                                                "fanuc-mill") if f.rule == "TG206"]
    assert found == [("TG206", 4), ("TG206", 5)]


@pytest.mark.parametrize("body, line, column", [
    ("#[5420] = 1\nM2\n", 1, 1),
    ("#<i> = 20\n#[5400 + #<i>] = 1\nM2\n", 2, 1),
])
def test_linuxcnc_a_read_only_parameter_chosen_by_an_expression(tmp_path, body, line, column):
    """``#[5420] = 1`` sets #5420, which rs274 refuses as it refuses ``#5420 = 1``."""
    assert rs274_refuses(tmp_path, body) == "Parameter is readonly"
    found = [f for f in findings(body, "linuxcnc") if f.rule == "TG209"]
    assert [(f.line, f.column, f.severity) for f in found] == [(line, column, "error")]
    assert "#5420" in found[0].message


@pytest.mark.parametrize("body, line, column", [
    ("o<a> sub\nG0 X1\nM2\n", 1, 1),
    ("G0 X0\n  o<a> sub\nG1 X1 F100\nM2\n", 2, 3),
    ("o<a> sub\nG0 X1\no<b> endsub\no<a> call\nM2\n", 1, 1),
])
def test_linuxcnc_a_definition_never_closed_swallows_the_end(tmp_path, body, line, column):
    """rs274 reads everything after an ``o<a> sub`` without its ``o<a> endsub`` as the
    definition, the M2 too: the program never ends, said at the sub (TG114). (A file of only
    ``o<a> sub`` ... ``o<b> endsub`` and M2 is a subroutine file, which a call runs and leaves
    at that endsub: TG138, tests/test_dialect_classes.py.)"""
    assert rs274_refuses(tmp_path, body) == "File ended with no percent sign or program end"
    found = [f for f in findings(body, "linuxcnc") if f.rule == "TG114"]
    assert [(f.line, f.column, f.severity) for f in found] == [(line, column, "error")]
    assert "not closed by o<a> endsub" in found[0].message
    closed = "o<a> sub\nG0 X1\no<a> endsub\no<a> call\nM2\n"
    assert rs274_refuses(tmp_path, closed) is None
    assert "TG114" not in rules(closed, "linuxcnc")


# -- Siemens Sinumerik 840D ---------------------------------------------------------------------

SINUMERIK = """; Sinumerik 840D
N10 DEF REAL _X_HOME, _Z_HOME
N20 _X_HOME=-365. _Z_HOME=610.
N30 G40 G17 G710 G94 G90 G60 G601 FNORM
N40 T="SCHAFT_D8" M6
N50 MSG("MILL (FINISH)")
N60 CYCLE832(0.02,1,1)
N70 G0 SUPA Z=_Z_HOME D0
N80 G0 X=_X_HOME Y0 S5000 M3
N90 R1=12.5 R2=R1*2
N100 G1 X=R1+5 Y=R2 F=R2*100
N110 G2 X20 Y10 CR=5
N120 M30
"""


def test_sinumerik_programs_are_read_and_checked():
    read = blocks(SINUMERIK, "sinumerik-840d")
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert program_text(read) == SINUMERIK
    assert read[10].words == ["N100", "G1", "X=R1+5", "Y=R2", "F=R2*100"]
    assert [(t, k) for b in read for _, t, k in b.statements] == [
        ("DEF REAL _X_HOME, _Z_HOME", "declaration"),
        ("_X_HOME=-365.", "assignment"), ("_Z_HOME=610.", "assignment"),
        ("FNORM", "command"), ('MSG("MILL (FINISH)")', "message"),
        ("CYCLE832(0.02,1,1)", "call"), ("SUPA", "command"), ("CR=5", "assignment"),
    ]
    found = findings(SINUMERIK, "sinumerik-840d")
    codes = [f.rule for f in found]
    assert "TG401" not in codes  # F=R2*100 is a feed in force
    assert not [f for f in found if f.rule in READING and f.severity == "error"], found


def test_sinumerik_words_written_without_blanks_are_words_not_a_name():
    # a name begins with two letters or underscores (Programming Manual Fundamentals): G0X170Z5
    # is three words, and the feed motion G1X10Y-5 without F is found, not taken for a call
    text = "G71 G90 G17\nG0X170Z5\ng1X10Y-5\nM30\n"
    read = blocks(text, "sinumerik-840d")
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert program_text(read) == text
    assert read[1].words == ["G0", "X170", "Z5"] and read[2].words == ["g1", "X10", "Y-5"]
    assert not [s for b in read for s in b.statements]
    missing = [f for f in findings(text, "sinumerik-840d") if f.rule == "TG401"]
    assert [(f.line, f.column) for f in missing] == [(3, 3)]  # at X10


SINUMERIK_ARCHIVE = """%_N_MAIN_MPF
;$PATH=/_N_MPF_DIR
G71 G90 G0 X10 Y10
R1=5
G1 X=R1 F100
M30
%_N_SUB1_SPF
;$PATH=/_N_SPF_DIR
G90 G1 X5 Y5
RET
%_N_MAIN2_MPF
;$PATH=/_N_MPF_DIR
G90 G1 X20
M30
"""


def test_a_sinumerik_archive_is_read_file_by_file(tmp_path):
    """An archive in punched tape format (SINUMERIK Operator's Guide HMI Advanced, "Formats
    for saving and importing data") holds one file after another, each after the `%` line
    naming it: after the M30 or RET of one, the next is a program of its own (no TG116), from
    the reset state (the second main program's feed move without F, TG401), a subprogram by
    its `_SPF` name (its feed its caller's); convert gives each its own start units."""
    found = findings(SINUMERIK_ARCHIVE, "sinumerik-840d")
    assert not {"TG106", "TG116"} & {f.rule for f in found}, found
    assert [(f.line, f.column) for f in found if f.rule == "TG401"] == [(13, 8)]
    path = tmp_path / "ARCHIVE.ARC"
    path.write_text(SINUMERIK_ARCHIVE)
    siemens = load_profile("sinumerik-840d")
    stats = convert_file(str(path), str(tmp_path / "inch.arc"),
                         ConvertOptions(siemens, siemens, units="inch"), verify=True)
    assert stats.verified
    out = (tmp_path / "inch.arc").read_text().splitlines()
    assert out[10:13] == ["%_N_MAIN2_MPF", ";$PATH=/_N_MPF_DIR", "G70 G90 G1 X0.7874"]
    assert any("program beginning on line 11" in n for n in stats.notes), stats.notes
    result = CliRunner().invoke(main, ["diff", str(path), str(path), "-p", "sinumerik-840d"])
    assert result.exit_code == 0, result.output


def test_sinumerik_g70_keeps_the_feed_in_the_basic_system_and_g700_sets_it():
    """feed_max is 30000 mm/min: under G70 (lengths in inch) F20000 is 20000 mm/min, within it;
    under G700 F2000 is 2000 in/min (50800 mm/min), above it. The word formats follow: X with
    four decimals under G70, F with three (the metric format) until G700."""
    g70 = findings("G70 G90\nG1 X1.2345 F20000.123\nG1 X2 F200.1234\nG700\nG1 X1 F20.1234\n"
                   "M30\n", "sinumerik-840d")
    assert [(f.rule, f.line) for f in g70 if f.rule.startswith(("TG2", "TG6"))] == [
        ("TG208", 3)], g70  # F200.1234 under G70: mm/min, F083 (the control rounds it)
    g700 = findings("G700 G90\nG1 X1 F2000\nM30\n", "sinumerik-840d")
    assert [(f.rule, f.line, f.message.split(" (the built-in")[0]) for f in g700
            if f.rule == "TG602"] == [
        ("TG602", 2, "feed 2000 in/min (50800 mm/min) above the maximum 30000 mm/min")]
    # G71 after G700: the feed is back in the basic system
    g71 = findings("G700 G90\nG1 X1 F200\nG71\nG1 X30 F20000\nM30\n", "sinumerik-840d")
    assert [f for f in g71 if f.rule == "TG602"] == []


SINUMERIK_EXPRESSIONS = """; R parameters computed from constants
N10 G71 G90 G17 G94
N20 R1=10000*2 R2=R1*2 ; 40000
N30 R3 = (R2 - R1) / 4 + POT(3) * SIN(30)
N40 G1 X=R3/100 Y=-R1/1000 F=R2
N50 G1 X=R3*0 F=R3 ; 5004.5
N60 R4=R9*2 R5=R3+$AA_IM[X]
N70 G1 X10 F=R4
N80 IF (R1==20000) AND (R2<>3) GOTOF ENDE ; condition
N90 ENDE:
N100 M30
"""


def test_sinumerik_expressions_of_constants_are_known():
    """R1=10000*2 is 20000, R2=R1*2 is 40000: F=R2 is above the feed maximum 30000 of
    sinumerik-840d (TG602, not TG141); R3 = (40000 - 20000) / 4 + POT(3) * SIN(30) is 5004.5, so
    X=R3/100 is 50.045 and F=R3 a feed within the maximum. R4 reads R9, which no block set, and
    R5 a system variable: F=R4 is unknown (TG141)."""
    read = blocks(SINUMERIK_EXPRESSIONS, "sinumerik-840d")
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert program_text(read) == SINUMERIK_EXPRESSIONS
    assert read[3].words == ["N30", "R3=(R2-R1)/4+POT(3)*SIN(30)"]
    assert read[8].statements[0][1:] == (
        "IF (R1==20000) AND (R2<>3) GOTOF ENDE", "flow")
    found = findings(SINUMERIK_EXPRESSIONS, "sinumerik-840d")
    assert [(f.rule, f.line) for f in found if f.rule in ("TG602", "TG141")] == [
        ("TG602", 5), ("TG141", 8)], found
    feed = next(f for f in found if f.rule == "TG602")
    assert "40000" in feed.message, feed.message
    assert not [f for f in found if f.severity == "error" and f.rule != "TG602"], found


SINUMERIK_JUMPS_IN_ONE_BLOCK = """PROC DRILL(REAL DP, REAL DPR)
DEF REAL HH2
HH2=DP-DPR
IF DP==0 GOTOF _MM0 IF DP==HH2 GOTOF _MM1
G0 X1
_MM0: G0 X2
_MM1: G0 X3
if dpr>=1 gotof _MM2 IF DPR<0 GOTOF _MM9 ; two
_MM2: G0 X4
RET
"""


def test_sinumerik_reads_several_conditional_jumps_in_one_block():
    """Siemens' own cycles (CYCLE81, CYCLE82, CYCLE84, HOLES1, HOLES2) write two or three
    conditional jumps in one block, `IF DP==0 GOTOF _MM0 IF DP==HH2 GOTOF _MM1`: each IF is a
    statement of its own, reprinted as written, and each destination is checked (TG118 where a
    GOTOF finds none after it). Any other word after a jump's destination is still refused."""
    read = blocks(SINUMERIK_JUMPS_IN_ONE_BLOCK, "sinumerik-840d")
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert program_text(read) == SINUMERIK_JUMPS_IN_ONE_BLOCK
    assert [s[1:] for s in read[3].statements] == [
        ("IF DP==0 GOTOF _MM0", "flow"), ("IF DP==HH2 GOTOF _MM1", "flow")]
    found = findings(SINUMERIK_JUMPS_IN_ONE_BLOCK, "sinumerik-840d")
    errors = [(f.rule, f.line, f.column) for f in found if f.severity == "error"]
    assert errors == [("TG118", 8, 31)], found  # the GOTOF to _MM9, nowhere after line 8
    for bad, column in [("IF DP==0 GOTOF _MM0 G0 X5", 21), ("IF DP==0 GOTOF _MM0 IF DP==1", 21)]:
        text = SINUMERIK_JUMPS_IN_ONE_BLOCK.replace(
            "IF DP==0 GOTOF _MM0 IF DP==HH2 GOTOF _MM1", bad)
        assert ("TG100", 4, column) in [(f.rule, f.line, f.column) for f in findings(
            text, "sinumerik-840d")], bad


def test_sinumerik_variables_set_to_constants_are_known():
    """_FEED=R1*2 (a user variable, any case) is 40000 where F=_feed reads it: TG602; after a
    call (CYCLE832) it is unknown again, and an element or system variable is never known."""
    program = ("N10 G71 G90 G17 G94\nN20 DEF REAL _FEED, _A[2]\nN30 R1=20000\n"
               "N40 _FEED = R1 * 2 _A[1]=5\nN50 G1 X10 F=_feed\nN60 CYCLE832(0.02,1,1)\n"
               "N70 G1 X20 F=_FEED\nN80 G1 X30 F=_A[1]\nN90 M30\n")
    read = blocks(program, "sinumerik-840d")
    assert program_text(read) == program
    assert [(t, k) for _, t, k in read[3].statements] == [
        ("_FEED = R1 * 2", "assignment"), ("_A[1]=5", "assignment")]
    found = findings(program, "sinumerik-840d")
    assert [(f.rule, f.line) for f in found if f.rule in ("TG602", "TG141")] == [
        ("TG602", 5), ("TG141", 7)], found
    # a declaration's initial value: DEF REAL _FEED=45000, _A[2] (the name after the type)
    declared = program.replace("DEF REAL _FEED, _A[2]", "DEF REAL _FEED=45000, _A[2]").replace(
        "N40 _FEED = R1 * 2 _A[1]=5\n", "")
    found = findings(declared, "sinumerik-840d")
    feed = [f for f in found if f.rule == "TG602"]
    assert [(f.line, "45000" in f.message) for f in feed] == [(4, True)], found


def test_sinumerik_known_positions_are_measured(tmp_path):
    """--stats measures the path from the known values: X=R3/100 is X50.045, Y=-R1/1000 is
    Y-20, then X=R3*0 back to X0."""
    program = SINUMERIK_EXPRESSIONS.replace("F=R2", "F=R2/100").replace("F=R4", "F1000")
    path = tmp_path / "EXPR.MPF"
    path.write_text(program)
    result = CliRunner().invoke(main, ["check", str(path), "--profile", "sinumerik-840d",
                                       "--stats"])
    assert "50.045" in result.output and "-20" in result.output, result.output
    assert "TG141" not in result.output and "TG602" not in result.output, result.output


def test_a_malformed_sinumerik_expression_is_located_and_the_rest_is_read(tmp_path):
    text = SINUMERIK_EXPRESSIONS.replace("N30 R3 = (R2 - R1) / 4", "N30 R3 = (R2 - R1 / 4")
    read = blocks(text, "sinumerik-840d")
    bad = [b for b in read if isinstance(b, BadBlock)]
    assert [(b.error.line, b.error.column, b.error.code) for b in bad] == [(4, 41, "TG100")]
    assert "'(' without a closing ')' in the expression" in str(bad[0].error)
    assert program_text(read) == text
    assert read[4].words == ["N40", "G1", "X=R3/100", "Y=-R1/1000", "F=R2"]
    condition = SINUMERIK_EXPRESSIONS.replace("(R2<>3)", "(R2<>3")
    bad = [b for b in blocks(condition, "sinumerik-840d") if isinstance(b, BadBlock)]
    assert [(b.error.line, b.error.column) for b in bad] == [(9, 31)]
    path = tmp_path / "EXPR.MPF"
    path.write_text(text)
    result = CliRunner().invoke(main, ["check", str(path), "--profile", "sinumerik-840d"])
    assert result.exit_code == 1
    assert f"{path}:4:41: error TG100 '(' without a closing ')'" in result.output


SINUMERIK_EXTENDED = """N10 DEF INT SPINU=2
N20 G0 X0 Y0 Z5
N30 M1=3 S1=INI[53]
N40 S2 = $AA_IM[X] * 2 ; a system variable
N50 s3=(R1+20)*2 m3=4
N60 S[SPINU]=470 M[SPINU]=3 T[SPINU]=7
N70 X4=20 Y=10 H1=2
N80 M30
"""


def test_sinumerik_extended_addresses_read_their_expressions_as_an_address_does(tmp_path):
    """An extended address, `S1=INI[53]` (Programming Manual Fundamentals, "Extended
    addresses"), takes the expression `S=` takes: a GUD array, a system variable, round
    brackets. The value the checker cannot know is a note, never a format error; the converter
    reprints the words byte for byte."""
    read = blocks(SINUMERIK_EXTENDED, "sinumerik-840d")
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert program_text(read) == SINUMERIK_EXTENDED
    assert read[2].words == ["N30", "M1=3", "S1=INI[53]"]
    assert read[3].words == ["N40", "S2=$AA_IM[X]*2"]
    assert read[4].words == ["N50", "s3=(R1+20)*2", "m3=4"]
    assert [(t, k) for _, t, k in read[5].statements] == [
        ("S[SPINU]=470", "assignment"), ("M[SPINU]=3", "assignment"),
        ("T[SPINU]=7", "assignment")]
    found = findings(SINUMERIK_EXTENDED, "sinumerik-840d")
    assert [(f.rule, f.line, f.column) for f in found if f.severity != "info"] == []
    assert [(f.rule, f.line, f.column) for f in found if f.rule == "TG141"] == [("TG141", 3, 10)]
    out = convert_text(tmp_path, SINUMERIK_EXTENDED, source="sinumerik-840d",
                       target="sinumerik-840d")
    assert out == SINUMERIK_EXTENDED


@pytest.mark.parametrize("body, line, column, message", [
    ("N30 M3 S1=", 2, 11, "expression ends without an operand"),
    ("N30 S1=INI[53 M1=3", 2, 15, "'[' without a closing ']' in the expression"),
    ("N30 S1=(100+20*2", 2, 17, "'(' without a closing ')' in the expression"),
    ("N30 M[SPINU=3", 2, 6, "'[' without its closing bracket"),
])
def test_a_malformed_extended_address_is_located_and_the_rest_is_read(body, line, column,
                                                                      message):
    text = f"N20 G0 X0 Y0\n{body}\nN40 S1=470 M1=3\nN50 M30\n"
    read = blocks(text, "sinumerik-840d")
    bad = [b for b in read if isinstance(b, BadBlock)]
    assert [(b.error.line, b.error.column, b.error.code) for b in bad] == [(line, column, "TG100")]
    assert message in str(bad[0].error)
    assert program_text(read) == text
    assert read[2].words == ["N40", "S1=470", "M1=3"]


def test_a_plain_number_after_an_extension_is_another_spindle_s_or_axis_s():
    """S2=30000 is spindle 2's speed, X4=100 axis X4's position, M1=3 M2=4 two spindles' codes:
    none is the profile's one spindle or X ("Extended addresses"). Taken as set but unknown
    (TG141, said once), where they were TG603 above its 24000, a TG403 arc from X=100 and
    TG304 for one modal group. The profile's own S30000 is still judged: TG606, a warning (a
    SINUMERIK limits the speed to its maximum, MD35100)."""
    text = ("N10 G0 X0 Y0 F100\nN20 S2=30000 M3\nN30 X4=100\nN40 G2 X10 Y0 I5 J0\n"
            "N50 M1=3 M2=4\nN60 S30000\nN70 M30\n")
    found = [(f.rule, f.line, f.column) for f in findings(text, "sinumerik-840d")
             if f.rule in ("TG141", "TG304", "TG403", "TG603", "TG606")]
    assert found == [("TG141", 2, 5), ("TG606", 6, 5)]
    note = [f for f in findings(text, "sinumerik-840d") if f.rule == "TG141"][0]
    assert "another axis or spindle (an extended address)" in note.message


def test_only_the_manual_s_letters_take_an_extension():
    """The manual extends the axes, I J K, S, M, H, T and F: D1=R1 L1=R2 P1=R3 are read as
    ISO indexed words as they were before extended addresses were read, with no TG141 (their
    letters are not set unknown) and no TG140 (L1=R2 calls nothing, as L100 does)."""
    text = "N10 G0 X0 Y0\nN20 D1=R1 L1=R2 P1=R3\nN30 L100\nN40 M30\n"
    read = blocks(text, "sinumerik-840d")
    assert read[1].words == ["N20", "D1=R1", "L1=R2", "P1=R3"]
    found = [(f.rule, f.line, f.column) for f in findings(text, "sinumerik-840d")
             if f.rule in ("TG140", "TG141")]
    assert found == [("TG140", 3, 5)]  # said at the L word that calls
    # the ISO reader's expression has no round brackets: refused where the extended address
    # reading took them
    bad = [b for b in blocks("N10 D1=(R1+2)\nN20 M30\n", "sinumerik-840d")
           if isinstance(b, BadBlock)]
    assert [(b.error.line, b.error.column, b.error.code) for b in bad] == [(1, 8, "TG100")]


def test_an_extended_address_extension_has_one_or_two_digits_and_is_positive():
    text = "N20 G0 X0 Y0\nN30 X0=5\nN40 S100=1000\nN50 S99=1000 M99=3\nN60 M30\n"
    found = [(f.rule, f.line, f.column) for f in findings(text, "sinumerik-840d")
             if f.severity == "error"]
    assert found == [("TG206", 2, 6), ("TG206", 3, 6)]


def test_constant_parameters_are_known_values_in_every_family():
    """A parameter set to a constant is that value until a jump or call: Macro B #101, the R
    parameters of Sinumerik (and ISO 6.4.7's R11 = 22.2), LinuxCNC's #<name> (blanks and case
    ignored, as rs274 reads names; a bracketed expression of values known too)."""
    siemens = findings("G71 G90 G17\nR1=50000 R2=5.\nG1 X=R2 F=R1\nM30\n", "sinumerik-840d")
    assert [(f.rule, f.line) for f in siemens if f.rule in ("TG602", "TG141")] == [
        ("TG602", 3)]  # F=R1 is 50000, above feed_max 30000
    jumped = findings("G71 G90\nR1=200\nGOTOF NEXT\nNEXT:\nG1 X1 F=R1\nM30\n",
                      "sinumerik-840d")
    assert [(f.rule, f.line) for f in jumped if f.rule == "TG141"] == [("TG141", 5)]
    # rs274: "Arc radius too small to reach end point" on line 4
    arc = findings("g21 g90 g17\ng0 x0 y0\n#<Rad> = 1\ng2 x10 y0 r#<rad> f100\nm2\n",
                   "linuxcnc")
    assert [(f.rule, f.line) for f in arc if f.severity == "error"] == [("TG410", 4)]
    # a bracketed expression of values known is worked out as rs274 does (review 52, F7);
    # one reading a value not known is not
    computed = findings("#<feed> = [1+2]\ng1 x1 f#<feed>\nm2\n", "linuxcnc")
    assert [(f.rule, f.line) for f in computed if f.rule == "TG141"] == []
    unknown = findings("#<feed> = [1+#5220]\ng1 x1 f#<feed>\nm2\n", "linuxcnc")
    assert [(f.rule, f.line) for f in unknown if f.rule == "TG141"] == [("TG141", 2)]


@pytest.mark.parametrize("units, radius, error", [
    ("g21", "4.9988", False), ("g21", "4.9987", True),  # half the chord 5: 0.0012 / 0.0013 short
    ("g20", "4.99996", False), ("g20", "4.99994", True),  # 0.00004 / 0.00006 in short
])
def test_an_r_arc_on_linuxcnc_may_fall_short_of_half_its_chord_as_rs274_allows(units, radius,
                                                                                error):
    """rs274's arc_data_r refuses an R arc whose half chord passes the radius by more than
    0.00005 in (0.00127 mm): the figures benchmarks/rs274_compare.py measures. R4.99 on a chord
    of 10 mm passed tapegate's wider I J tolerance."""
    text = f"{units} g90 g17\ng0 x0 y0\ng2 x10 y0 r{radius} f100\nm2\n"
    assert ("TG410" in rules(text, "linuxcnc")) == error


# -- Heidenhain TNC, ISO mode -------------------------------------------------------------------

HEIDENHAIN = """%PART1 G71 *
N10 G30 G17 X+0 Y+0 Z-40 *
N20 G31 G90 X+100 Y+100 Z+0 *
N30 T1 G17 S4000 *
N40 G00 G40 G90 Z+250 *
N50 D00 Q1 P01 +5 *
N60 G01 X+10 Y+10 F200 ; approach *
N70 G98 L1 *
N80 L1,0 *
N85 G200 BOHREN
  Q200=2 ;SICHERHEITS-ABST.
  Q201=-20 ;TIEFE *
N86 Q3 = ( Q1 + 2 ) * SIN ( 30 ) *
N87 G01 X+Q3 Y-Q1 *
N90 M30 *
N99999999 %PART1 G71 *
"""


def test_heidenhain_iso_programs_are_read():
    read = blocks(HEIDENHAIN, "heidenhain-iso")
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert program_text(read) == HEIDENHAIN
    assert read[4].words == ["N40", "G00", "G40", "G90", "Z+250"]
    assert [(t, k) for b in read for _, t, k in b.statements] == [
        ("D00 Q1 P01 +5", "assignment"), ("L1,0", "call"), ("BOHREN", "command"),
        ("Q200=2", "assignment"), ("Q201=-20", "assignment"),
        ("Q3 = ( Q1 + 2 ) * SIN ( 30 )", "assignment"), ("%PART1 G71", "name")]
    assert read[13].words == ["N87", "G01", "X+Q3", "Y-Q1"]
    found = findings(HEIDENHAIN, "heidenhain-iso")
    # X+Q3: set by a parameter, so unknown, not missing (TG141 once, no TG4xx)
    assert [(f.rule, f.line) for f in found if f.rule in ("TG141", "TG401")] == [("TG141", 14)]
    # the %NAME lines open and close the program: no TG111/TG112, no TG115/TG116
    assert not [f for f in found if f.rule in READING | {"TG111", "TG112", "TG115", "TG116"}]


HEIDENHAIN_PATHS = """%PATHS G71 *
N10 G30 G17 X+0 Y+0 Z-40 *
N20 G31 G90 X+100 Y+100 Z+0 *
N30 T1 G17 S4000 *
N40 G00 G40 G90 X+0 Y+0 Z+2 *
N50 G83 P01 +2 P02 -20 P03 -5 P04 0 P05 150 *
N60 G01 X+10 Y+0 F100 *
N70 I+10 J+10 *
N80 G02 X+20 Y+10 *
N90 G03 X+10 Y+20 *
N100 G11 G40 R+20 H+30 F200 *
N110 G12 H+90 *
N120 G80 A+10 *
N130 G01 X+5 F100 *
N140 M30 *
N99999999 %PATHS G71 *
"""


def test_heidenhain_paths_as_the_tnc_runs_them():
    """The circle centre CC (I J) stays in force for the arcs after it (TG404 'arc without I J'
    on N80 and N90 was false); G83 P01 +2 ... defines a cycle by its parameters (TG100 was
    false); G30/G31 give the blank form, G11/G12 move by radius and angle about the pole, G80
    tilts the plane: none of them is a move to their X Y Z, and after the polar moves the
    position is not followed (no TG404 on the G80 A+10 block after G02)."""
    read = blocks(HEIDENHAIN_PATHS, "heidenhain-iso")
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert read[5].statements[0][1:] == ("P01 +2 P02 -20 P03 -5 P04 0 P05 150", "assignment")
    found = findings(HEIDENHAIN_PATHS, "heidenhain-iso")
    assert [f for f in found if f.severity != "info"] == [], found
    wrong = HEIDENHAIN_PATHS.replace("G03 X+10 Y+20", "G03 X+10 Y+25")  # 15 from CC, not 10
    assert [(f.rule, f.line) for f in findings(wrong, "heidenhain-iso")
            if f.severity == "error"] == [("TG403", 10)]


HEIDENHAIN_FORMULAS = """%FORM G71 *
N10 G30 G17 X+0 Y+0 Z-40 *
N20 G31 G90 X+100 Y+100 Z+0 *
N30 T1 G17 S4000 *
N40 Q1 = 5 * 3 + 2 * 10 *
N50 QL2 = ( Q1 + 5 ) * 1000 + SQ 10 - 3^3 + 400 % 360 *
N60 G01 X+Q1 Y+0 FQL2 *
N70 Q3 = Q1 + Q99 *
N80 G01 X+Q3 F200 *
N110 M30 *
N99999999 %FORM G71 *
"""


def test_heidenhain_formulas_with_constant_values_are_known():
    """A formula of numbers, PI, functions of them and parameters already known gives its Q
    parameter a value, as #101 = 250. does: the manuals' Q1 = 5 * 3 + 2 * 10 is 35 and
    QL2 = (35 + 5) * 1000 + SQ 10 - 3^3 + 400 % 360 is 40113, above heidenhain-iso's feed of
    40000 (TG602, not TG141); Q3 reads Q99, which no block set, so X+Q3 is unknown (TG141)."""
    read = blocks(HEIDENHAIN_FORMULAS, "heidenhain-iso")
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert program_text(read) == HEIDENHAIN_FORMULAS
    assert read[5].statements[0][1:] == (
        "QL2 = ( Q1 + 5 ) * 1000 + SQ 10 - 3^3 + 400 % 360", "assignment")
    assert read[6].words == ["N60", "G01", "X+Q1", "Y+0", "FQL2"]
    # a cycle's parameters on one line are a formula each (iTNC 530: N54 G221 Q225=+15 ...)
    pattern = blocks("N54 G221 Q225=+15 Q226=+15 Q237=+10 *\n", "heidenhain-iso")[0]
    assert [(t, k) for _, t, k in pattern.statements] == [
        ("Q225=+15", "assignment"), ("Q226=+15", "assignment"), ("Q237=+10", "assignment")]
    found = findings(HEIDENHAIN_FORMULAS, "heidenhain-iso")
    feed = next(f for f in found if f.rule == "TG602")
    assert (feed.line, "40113" in feed.message) == (7, True), feed.message
    assert [(f.rule, f.line) for f in found if f.rule in ("TG141", "TG401")] == [("TG141", 9)]
    assert not [f for f in found if f.severity == "error" and f.rule != "TG602"], found


def test_a_formula_whose_order_the_manuals_do_not_settle_has_no_value():
    """SIN 30 * 2: whether SIN takes 30 or 30 * 2 the manuals' examples do not show, so QR4
    is unknown (TG141); SIN (30) * 2 is 1, and 1 * 1000000 is far outside the travel."""
    program = HEIDENHAIN_FORMULAS.replace("N70 Q3 = Q1 + Q99 *", "N70 Q3 = {} *")
    unsettled = findings(program.format("SIN 30 * 2 * 1000000"), "heidenhain-iso")
    assert ("TG141", 9) in [(f.rule, f.line) for f in unsettled]
    assert "TG601" not in [f.rule for f in unsettled]
    settled = findings(program.format("SIN (30) * 2 * 1000000 + PI - PI"), "heidenhain-iso")
    assert "TG141" not in [f.rule for f in settled]
    assert [f.line for f in settled if f.rule == "TG601"][:1] == [9]


def test_a_known_formula_value_is_checked_and_lost_after_a_jump():
    known = HEIDENHAIN_FORMULAS.replace("N70 Q3 = Q1 + Q99 *", "N70 Q3 = Q1 * 1000 *")
    found = findings(known, "heidenhain-iso")
    # X+Q3 = 35000 mm is a position the travel does not reach
    assert [f.line for f in found if f.rule == "TG601"][:1] == [9]
    jumped = known.replace("N70 Q3", "N65 L1,0 *\nN70 Q3")
    found = findings(jumped, "heidenhain-iso")
    # after the call Q1 may hold anything: Q3 = Q1 * 1000 is unknown, and so is X+Q3
    assert not [f for f in found if f.rule == "TG601"]
    assert "TG141" in [f.rule for f in found]


def test_a_label_forgets_the_known_formula_values():
    """A jump back to a label (D12: if Q1 < 10 go to L1) brings other values: after G98 L1 the
    loop's Q1 = Q1 + 1 is not 1 but unknown, and X+Q1 with it (TG141)."""
    loop = """%LOOP G71 *
N10 G30 G17 X+0 Y+0 Z-40 *
N20 G31 G90 X+100 Y+100 Z+0 *
N30 T1 G17 S4000 *
N40 Q1 = 0 *
N50 G98 L1 *
N60 Q1 = Q1 + 1 *
N70 G01 X+Q1 Y+0 F200 *
N80 D12 P01 +Q1 P02 +10 P03 1 *
N90 M30 *
N99999999 %LOOP G71 *
"""
    found = findings(loop, "heidenhain-iso")
    assert ("TG141", 8) in [(f.rule, f.line) for f in found]
    straight = findings(loop.replace("N50 G98 L1 *\n", ""), "heidenhain-iso")
    assert "TG141" not in [f.rule for f in straight]


HEIDENHAIN_SET_THEN_USED = """%T G71 *
N10 G30 G17 X+0 Y+0 Z-40 *
N20 G31 G90 X+100 Y+100 Z+0 *
N30 T1 G17 S4000 *
N40 Q2 = 50000 *
{}
N60 G01 X+0 Y+0 FQ2 *
N900 M30 *
N99999999 %T G71 *
"""


@pytest.mark.parametrize("between", [
    "N50 QS1 = \"A\" Q2 = 3 *",  # a string, then another assignment on its line
    "N50 QL1 = STRLEN ( SRC_QS10 ) Q2 = 3 *",  # a string function read as text, then one
    "N50 D01Q2 P01 +Q2 P02 +1 *",  # a D function whose target follows its number unspaced
    "N50 D01 Q2 P01 +Q2 P02 +1 *",
    "N50 %OTHER *",  # a call of another program, which shares the Q parameters
    "%OTHER *",
    # the control computes in binary: INT (0.3 / 0.1) is 2 there, 3 in decimals
    "N50 Q2 = INT ( 0.3 / 0.1 ) * 20000 *",
    "N50 Q2 = ( SGN -1 + 1 ) * 50000 *",  # SGN below 0: the manuals give 0 or -1
    "N50 Q2 = 2 * 3^2 * 5000 *",  # a power beside a product: an order the manuals do not give
])
def test_what_may_change_a_known_heidenhain_parameter_makes_it_unknown(between):
    """Q2 is known as 50000, above the feed maximum, until a statement that sets it or may:
    then FQ2 is a feed set but unknown (TG141), never the old 50000 (TG602)."""
    known = findings(HEIDENHAIN_SET_THEN_USED.format("N50 G01 X+0 *"), "heidenhain-iso")
    assert "TG602" in [f.rule for f in known]
    found = findings(HEIDENHAIN_SET_THEN_USED.format(between), "heidenhain-iso")
    assert "TG602" not in [f.rule for f in found], found
    assert "TG141" in [f.rule for f in found] or "TG140" in [f.rule for f in found]
    assert not [f for f in found if f.severity == "error"], found


def test_a_heidenhain_program_call_is_not_its_end():
    """%OTHER * calls a program (TG140, what follows is still this program's); the closing
    line is the one with the units, N99999999 %T G71 *."""
    found = findings(HEIDENHAIN_SET_THEN_USED.format("N50 %OTHER *"), "heidenhain-iso")
    assert [(f.rule, f.line) for f in found if f.rule in ("TG140", "TG114", "TG115")] == [
        ("TG140", 6)]


def test_a_malformed_heidenhain_formula_is_located_and_the_rest_is_read(tmp_path):
    text = HEIDENHAIN_FORMULAS.replace("N70 Q3 = Q1 + Q99 *", "N70 Q3 = ( Q1 + 2 * FOO 3 *")
    read = blocks(text, "heidenhain-iso")
    bad = [b for b in read if isinstance(b, BadBlock)]
    assert [(b.error.line, b.error.column, b.error.code) for b in bad] == [(8, 21, "TG100")]
    assert "unknown function FOO in a formula" in str(bad[0].error)
    assert program_text(read) == text
    assert read[8].words == ["N80", "G01", "X+Q3", "F200"]
    found = findings(text, "heidenhain-iso")
    assert [(f.rule, f.line, f.column) for f in found if f.severity == "error"] == [
        ("TG602", 7, 18), ("TG100", 8, 21)]
    path = tmp_path / "FORM.I"
    path.write_text(text)
    result = CliRunner().invoke(main, ["check", str(path), "--profile", "heidenhain-iso"])
    assert result.exit_code == 1
    assert f"{path}:8:21: error TG100 unknown function FOO" in result.output


# -- conversion -------------------------------------------------------------------------------


def convert_text(tmp_path: Path, text: str, *, source: str, target: str, from_profile=None,
                 **options) -> str:
    path = tmp_path / "in.nc"
    path.write_text(text)
    out = tmp_path / "out.nc"
    convert_file(str(path), str(out), ConvertOptions(
        target=load_profile(target), source=from_profile or load_profile(source), **options),
        overwrite=True)
    return out.read_text()


def test_macro_variables_that_are_lengths_are_converted(tmp_path):
    text = "%\nO1000\nG21\n#136=.375\nG0 X#136 Y10.\nM30\n%\n"
    out = convert_text(tmp_path, text, source="fanuc-mill", target="fanuc-mill", units="inch")
    assert "#136=0.0148" in out and "Y0.3937" in out


def test_a_statement_holding_a_number_is_not_converted_silently(tmp_path):
    text = "%\nO1000\nG21\nIF [#5021 GT 10.] GOTO 5\nG0 X1.\nN5 M30\n%\n"
    with pytest.raises(ConversionError) as info:
        convert_text(tmp_path, text, source="fanuc-mill", target="fanuc-mill", units="inch")
    assert info.value.code == "conversion-unprovable"
    assert (info.value.line, info.value.column) == (4, 1)
    assert "statement" in info.value.message  # the why, within the one code
    out = convert_text(tmp_path, text, source="fanuc-mill", target="fanuc-mill", units="inch",
                       allow_unconverted=True)
    assert "IF [#5021 GT 10.] GOTO 5" in out and "X0.0394" in out


def test_respacing_keeps_statements_whole(tmp_path):
    text = "%\nO1000\nN10 IF [#1 GT 2] GOTO 20\nN20 G0 X1. Y2.\nM30\n%\n"
    out = convert_text(tmp_path, text, source="fanuc-mill", target="fanuc-mill", spacing="remove")
    assert "N10 IF [#1 GT 2] GOTO 20\n" in out and "N20G0X1.Y2.\n" in out


def test_a_word_whose_token_dropped_a_blank_is_still_placed(tmp_path):
    """A NUL inside a word on a last line without an end of block: the converter re-finds the
    word in the text; where it cannot place it, it writes the block anew instead of panicking
    (a fuzzing find)."""
    out = convert_text(tmp_path, "Y#1-#2\x00*#1Y#1-#2*#1Y5", source="fanuc-mill",
                       target="fanuc-mill", units="inch", allow_unconverted=True)
    assert "Y0.0002" in out  # Y5 is 5 increments, 0.005 mm


def test_what_the_scanner_reads_the_expression_tree_reads(tmp_path):
    """Fuzzing finds: Macro B has no ##n (LinuxCNC does), and a lower-case function is a call,
    not a crash of the parameter analysis: both are located errors."""
    with pytest.raises(ParseError) as info:
        convert_text(tmp_path, "G21\nY##136\nM30\n", source="fanuc-mill", target="fanuc-mill",
                     units="inch")
    assert (info.value.line, info.value.column) == (2, 2)
    with pytest.raises(ConversionError) as info:
        # (to the neutral profile, which reads `[ ]` as the source does: iso-mill does not)
        convert_text(tmp_path, "G71\nX1=AtAN[1]\nM30\n", source="neutral", target="neutral",
                     units="inch", from_profile=NEUTRAL)
    assert (info.value.code, info.value.line, info.value.column) == \
        ("conversion-unprovable", 2, 1)
    assert "non-linear" in info.value.message  # the why, within the one code


def test_a_cycles_words_convert_by_their_role_in_the_cycle(tmp_path):
    """Issue 23: G71 P Q are block numbers, U R D lengths (Haas D the depth of cut); M98 P is a
    program number."""
    fanuc = ("%\nO1\nG21 G99\nG71 U2. R0.5\nG71 P100 Q200 U0.4 W0.1 F0.25\n"
             "M98 P1234 L2\nM30\n%\n")
    out = convert_text(tmp_path, fanuc, source="fanuc-lathe", target="fanuc-lathe",
                       units="inch").splitlines()
    assert out[3] == "G71 U0.0787 R0.0197"
    assert out[4] == "G71 P100 Q200 U0.0157 W0.0039 F0.0098"
    assert out[5] == "M98 P1234 L2"
    haas = "%\nO1\nG20\nG71 P10 Q20 U0.02 W0.01 D0.05 F0.008\nG70 P10 Q20\nM30\n%\n"
    out = convert_text(tmp_path, haas, source="haas-lathe", target="haas-lathe",
                       units="metric").splitlines()
    assert out[3] == "G71 P10 Q20 U0.508 W0.254 D1.27 F0.203"
    assert out[4] == "G70 P10 Q20"


THREADING = ("%\nO1\nG21 G99\nG0 X22. Z5.\nG76 P021060 Q100 R0.02\n"
             "G76 X20.3 Z-30. R0 P1200 Q350 F2.\nG74 R1.\nG74 X0 Z-50. P0 Q5000 F0.1\n"
             "G75 R0.5\nG75 X10. Z-20. P3000 Q2000 F0.1\nM30\n%\n")


def test_a_cycle_length_in_least_input_increments_is_converted(tmp_path):
    """The 0i's G76 P1200 Q350 (thread height, first cut) and G76 Q100 (least cut depth), and
    G74/G75 P Q (travel, peck), are lengths written as counts of least input increments
    (0.001 mm, 0.0001 in on fanuc-lathe): converted exactly, rounded to the target's increment
    and written back as counts, with no decimal point; the packed P021060 is a number."""
    path, out = tmp_path / "in.nc", tmp_path / "out.nc"
    path.write_text(THREADING)
    lathe = load_profile("fanuc-lathe")
    stats = convert_file(str(path), str(out), ConvertOptions(lathe, lathe, units="inch"),
                         verify=True)
    lines = out.read_text().splitlines()
    assert lines[4] == "G76 P021060 Q39 R0.0008"  # 0.1 mm = 0.003937 in: 39 x 0.0001 in
    assert lines[5] == "G76 X0.7992 Z-1.1811 R0 P472 Q138 F0.0787"  # 1.2 mm, 0.35 mm
    assert lines[7] == "G74 X0 Z-1.9685 P0 Q1969 F0.0039"
    assert lines[9] == "G75 X0.3937 Z-0.7874 P1181 Q787 F0.0039"
    # the rounding is reported as any word's: Q5000 is 1968.504 increments, written 1969
    assert Fraction(*stats.rounding["Q"]) == Fraction(63, 1270000) and stats.verified
    # tapegate diff reads them so too: the metric and the inch program are the same program
    assert list(diff_files(str(path), str(out), lathe, lathe,
                           DiffOptions(tolerance=Decimal("0.5")))) == []
    # and back: the counts of 0.0001 in become counts of 0.001 mm
    back = tmp_path / "back.nc"
    convert_file(str(out), str(back), ConvertOptions(lathe, lathe, units="metric"),
                 verify=True)
    assert back.read_text().splitlines()[5] == "G76 X20.3 Z-30. R0 P1199 Q351 F1.999"
    # without a change of units nothing is rewritten: Q0044 keeps its zeros
    same = tmp_path / "same.nc"
    path.write_text(THREADING.replace("Q100", "Q0044"))
    convert_file(str(path), str(same), ConvertOptions(lathe, lathe), verify=True)
    assert "G76 P021060 Q0044 R0.02" in same.read_text()


def test_a_length_in_increments_is_refused_for_a_control_of_another_family(tmp_path):
    """P1200 is 1.2 mm only for a control whose cycle table reads it so: for an ISO lathe (or a
    mill) it is another number, so the conversion stops at the word, with or without a change of
    units. The program's own family converts it."""
    # (without the G99: ISO 6983-1's table leaves G99 unassigned, so the FANUC lathe's feed per
    # revolution code is refused for iso-lathe at the code, before the cycle)
    with pytest.raises(ConversionError) as info:
        convert_text(tmp_path, THREADING, source="fanuc-lathe", target="iso-lathe", units=None)
    assert (info.value.clause, info.value.line, info.value.column) == ("profile", 3, 5)
    reset_feed = THREADING.replace("G21 G99", "G21")
    for target, units in (("iso-lathe", "inch"), ("iso-lathe", None)):
        with pytest.raises(ConversionError) as info:
            convert_text(tmp_path, reset_feed, source="fanuc-lathe", target=target, units=units)
        assert (info.value.code, info.value.clause) == ("conversion-cycle", "cycle")
        assert (info.value.line, info.value.column) == (5, 13), target  # Q100, the first
    # Haas writes G76 in one block with K D, its P Q differ: the cycle itself is refused, at
    # its code (docs/convert.md, "Codes and words the two controls read differently")
    with pytest.raises(ConversionError) as info:
        convert_text(tmp_path, THREADING, source="fanuc-lathe", target="haas-lathe", units="inch")
    assert (info.value.clause, info.value.line, info.value.column) == ("codes", 5, 1)
    assert "with its words in Haas's form" in str(info.value)
    # a mill stops earlier: the FANUC lathe's G99 is feed per revolution, the mill's the
    # cycle's return to the R point (the two profiles' code tables)
    with pytest.raises(ConversionError) as info:
        convert_text(tmp_path, THREADING, source="fanuc-lathe", target="fanuc-mill", units="inch")
    assert (info.value.clause, info.value.line, info.value.column) == ("codes", 3, 5)
    assert "G99: the source and target controls give this code different meanings" \
        in str(info.value)
    assert "P472" in convert_text(tmp_path, THREADING, source="fanuc-lathe",
                                  target="fanuc-lathe", units="inch")


def test_a_length_read_from_a_parameter_set_nowhere_in_the_program_is_refused(tmp_path):
    """X#1 in a macro whose #1 a caller gives (G65 ... A) holds a length in units this
    conversion does not change: it went through as written. Sinumerik's X=R1 said 'non-linear'
    for it; a parameter the program sets converts (R1=10 then X=R1+5)."""
    with pytest.raises(ConversionError) as info:
        convert_text(tmp_path, "%\nO1\nG21 G90\nG0 X#1 Z50.\nM30\n%\n", source="fanuc-mill",
                     target="fanuc-mill", units="inch")
    assert (info.value.code, info.value.line, info.value.column) == \
        ("conversion-unprovable", 4, 4)
    # one code for every unprovable value: the wording tells "not set" from "non-linear"
    assert "#1 is read as a length (line 4) but not set" in info.value.message
    left = convert_text(tmp_path, "%\nO1\nG21 G90\nG0 X#1 Z50.\nM30\n%\n",
                        source="fanuc-mill", target="fanuc-mill", units="inch",
                        allow_unconverted=True)
    assert "G0 X#1 Z1.9685" in left
    with pytest.raises(ConversionError) as info:
        convert_text(tmp_path, "G71 G90\nG0 X=R1 Z50\nM30\n", source="sinumerik-840d",
                     target="sinumerik-840d", units="inch")
    assert (info.value.code, info.value.line, info.value.column) == \
        ("conversion-unprovable", 2, 4)
    assert "value: R1" in info.value.message  # not "non-linear" (the old reading): as above
    out = convert_text(tmp_path, "G71 G90\nR1=10\nG0 X=R1+5 Z50\nM30\n",
                       source="sinumerik-840d", target="sinumerik-840d", units="inch")
    assert out.splitlines()[1:3] == ["R1=0.3937", "G0 X=R1+0.1969 Z1.9685"]


def test_a_heidenhain_program_refuses_a_change_of_units(tmp_path):
    """Its units are in its %NAME G71 * lines, which the converter does not rewrite (it put a
    G70 into N10), and X+Q1 reads a Q parameter nothing analyses."""
    text = "%H4 G71 *\nN10 G00 G90 X+Q1 Z+50 *\nN20 G01 X+10 F200 *\nN30 M30 *\n" \
           "N99999999 %H4 G71 *\n"
    with pytest.raises(ConversionError) as info:
        convert_text(tmp_path, text, source="heidenhain-iso", target="heidenhain-iso",
                     units="inch")
    assert (info.value.code, info.value.clause) == ("conversion-units", "units")
    assert (info.value.line, info.value.column) == (2, 1)
    # conversion-units has several causes: the wording tells the HEIDENHAIN one apart
    assert "HEIDENHAIN program gives its units" in info.value.message
    assert convert_text(tmp_path, text, source="heidenhain-iso", target="heidenhain-iso",
                        units="metric") == text


def test_a_length_in_increments_refuses_inexact_rounding_and_overflow(tmp_path):
    with pytest.raises(ConversionError) as info:
        convert_text(tmp_path, "%\nO1\nG21\nG76 P021060 Q100 R0.0254\nM30\n%\n",
                     source="fanuc-lathe", target="fanuc-lathe", units="inch",
                     rounding=Rounding.ERROR)
    assert info.value.code == "conversion-format"
    assert (info.value.line, info.value.column) == (4, 13)  # Q100: 39.37 increments
    # conversion-format is also digit overflow (below): the wording tells the two apart
    assert "rounding is not allowed" in info.value.message
    out = convert_text(tmp_path, "%\nO1\nG21\nG76 P021060 Q127 R0.0254\nM30\n%\n",
                       source="fanuc-lathe", target="fanuc-lathe", units="inch",
                       rounding=Rounding.ERROR)
    assert "G76 P021060 Q50 R0.001" in out  # 0.127 mm is 0.005 in exactly
    # a peck of 9.9999 in is 253997 increments of 0.001 mm: six digits, where Q05 holds five
    with pytest.raises(ConversionError) as info:
        convert_text(tmp_path, "%\nO1\nG20\nG74 X0 Z-5. P0 Q99999 F0.01\nM30\n%\n",
                     source="fanuc-lathe", target="fanuc-lathe", units="metric")
    assert (info.value.code, info.value.line, info.value.column) == ("conversion-format", 4, 16)
    assert "digit overflow" in info.value.message  # not rounding (above): one code for both


@pytest.mark.parametrize(("wrong", "message"), [
    # the count left in 0.001 mm under G20: 350 x 0.0001 in, not 0.35 mm
    (lambda t: t.replace("Q138", "Q350"), "Q350 converts to 0.0137795 but the output Q350"),
    # a count one increment off
    (lambda t: t.replace("P472", "P473"), "P1200 converts to 0.0472441 but the output P473"),
])
def test_verify_reads_a_length_in_increments_as_the_control_does(tmp_path, wrong, message):
    path, out = tmp_path / "in.nc", tmp_path / "out.nc"
    path.write_text(THREADING)
    lathe = load_profile("fanuc-lathe")
    options = ConvertOptions(lathe, lathe, units="inch")
    stats = convert_file(str(path), str(out), options)
    verify_conversion(str(path), str(out), lathe, options, stats, file="in.nc")
    out.write_text(wrong(out.read_text()))
    with pytest.raises(ConversionError) as info:
        verify_conversion(str(path), str(out), lathe, options, stats, file="in.nc")
    assert (info.value.code, info.value.file, info.value.line) == ("conversion-verify", "in.nc", 6)
    assert message in info.value.message  # the word and the values compared: no field has them
    assert info.value.code == "conversion-verify"


def test_a_named_variable_as_a_value_is_refused_at_its_column_or_left_partly_verified(tmp_path):
    """Sinumerik Z=_Z_HOME: the parameter analysis cannot read the named variable, and passes
    it over; the converter refuses the word at its column (the analysis stopped the file with
    no column before), and --allow-unconverted leaves it as written, which --verify compares as
    written: the file is only partly verified."""
    text = "N10 DEF REAL _Z_HOME\nN20 G0 Z5.\nN30 SUPA G0 Z=_Z_HOME D0\nN40 M30\n"
    with pytest.raises(ConversionError) as info:
        convert_text(tmp_path, text, source="sinumerik-840d", target="sinumerik-840d",
                     units="inch")
    assert info.value.code == "conversion-unprovable"
    assert (info.value.line, info.value.column) == (3, 13)
    assert "non-linear expression" in info.value.message  # the why, within the one code
    path, out = tmp_path / "z.nc", tmp_path / "z-inch.nc"
    path.write_text(text)
    siemens = load_profile("sinumerik-840d")
    stats = convert_file(str(path), str(out), ConvertOptions(
        siemens, siemens, units="inch", allow_unconverted=True), verify=True)
    assert "N30 SUPA G0 Z=_Z_HOME D0\n" in out.read_text()
    # the word is left as written under a change of units: compared as written, so not
    # "verified" but "partly verified" (review 12, 4)
    assert not stats.verified and stats.left_as_written == 1
    assert "N20 G70 G0 Z0.1969\n" in out.read_text()  # the units the program never selected


def test_macro_call_arguments_are_not_converted_silently(tmp_path):
    text = "%\nO1\nG21\nG65 P9010 A10. B2.5\nM30\n%\n"
    with pytest.raises(ConversionError) as info:
        convert_text(tmp_path, text, source="fanuc-mill", target="fanuc-mill", units="inch")
    assert info.value.code == "conversion-unprovable"
    assert (info.value.line, info.value.column) == (4, 1)
    assert "arguments of a macro call" in info.value.message  # the why, within the one code


def test_macro_call_arguments_are_left_as_written_when_allowed(tmp_path):
    """The refusal says --allow-unconverted leaves them as written; they were converted as
    lengths (X10. -> X0.3937, the macro reading #24 in inch what was meant in mm, or the other
    way). Now kept and noted; the proof reads a macro call's arguments as the numbers its macro
    reads, the same on both sides, but a macro that moves by #24 moves 10 in where it moved
    10 mm: words left as written where the units change, so "partly verified", each counted
    by the core (the note names no line, and a count read from the notes' wording missed it)."""
    path = tmp_path / "p.nc"
    path.write_text("%\nO1\nG21\nG65 P9810 X10. W2. F500.\nG0 X25.4\nM30\n%\n")
    fanuc = load_profile("fanuc-mill")
    out = tmp_path / "o.nc"
    stats = convert_file(str(path), str(out), ConvertOptions(
        fanuc, fanuc, units="inch", allow_unconverted=True), verify=True)
    assert not stats.verified and (stats.left_as_written, stats.left_at) == (3, (4, 11))
    assert out.read_text().splitlines()[3:5] == ["G65 P9810 X10. W2. F500.", "G0 X1."]
    assert "the arguments of macro calls (G65) left as written (--allow-unconverted)" in (
        stats.notes)
    # I1 without its point counts the increment (0.001 mm, 0.0001 in): another number in inch
    with pytest.raises(ConversionError) as info:
        convert_text(tmp_path, "O1\nG21\nG65 P9810 I1.0 J1\nM30\n", source="fanuc-mill",
                     target="fanuc-mill", units="inch", allow_unconverted=True)
    assert (info.value.code, info.value.line, info.value.column) == (
        "conversion-unprovable", 3, 16)
    assert "without its decimal point" in info.value.message


# -- the measure: real programs -------------------------------------------------------------------


@needs_corpus
@pytest.mark.parametrize("name", sorted(MATCHING))
def test_real_programs_parse_completely_on_their_profile(name):
    path = CORPUS / name
    profile = load_profile(MATCHING[name])
    read = list(parse_stream(Source(str(path)).chunks(), profile.dialect, file=name,
                             errors="collect"))
    assert program_text(read).encode("utf-8", "surrogateescape") == path.read_bytes()
    assert not [b for b in read if isinstance(b, BadBlock)]
    reading = [f for f in Checker(profile).run(iter(read))
               if f.rule in READING and f.severity == "error"]
    assert len(reading) == KNOWN_FORMAT_ERRORS.get(name, 0), reading[:5]


# The corpus programs a change of units refuses, each at its line, and why: the Haas program's
# IF [#5405 GE 6000] (a number of no shown role), parameters assigned and never read (#130 of the
# Fanuc macro, R11 of the Sinumerik 850 program), and the 840D program's _camtolerance=.02, a
# named variable set to a number (docs/convert.md). The others convert there and back, each way
# verified.
UNITS_REFUSED = {
    "GCodeWorkShop__HAAS.nc": (7, 'the statement "IF [ #5405 GE 6000 ] THEN #3000= 15"'),
    # #130 is compared in an IF (line 43), so it is read; #132 is set and never read
    "cnc-sprayer__7997A.NC": (17, "parameter #132: #132 is assigned on line 17 but never read"),
    "GCodeWorkShop__SINUMERIK850.nc": (4, "parameter R11: R11 is assigned on line 4 but never"),
    "Five-Axis-Milling-Dataset__Bottle_opener_Flaschenoeffner.txt": (
        11, 'the statement "_camtolerance=.02"'),
}


@needs_corpus
@pytest.mark.parametrize("name", sorted(MATCHING))
def test_real_programs_convert_their_units_there_and_back_verified(tmp_path, name):
    path = CORPUS / name
    profile = load_profile(MATCHING[name])
    code = profile.inch_code
    inch = re.search(rf"(?<![0-9.A-Z]){code[0]}0*{code[1:]}(?![0-9.])",
                     re.sub(r"\([^)\n]*\)|;[^\n]*", "", path.read_text(errors="replace")))
    there, back = ("metric", "inch") if inch else ("inch", "metric")
    converted, returned = tmp_path / "there.nc", tmp_path / "back.nc"
    options = ConvertOptions(profile, profile, units=there)
    if name in UNITS_REFUSED:
        line, message = UNITS_REFUSED[name]
        with pytest.raises(ConversionError) as info:
            convert_file(str(path), str(converted), options, verify=True)
        assert (info.value.code, info.value.line) == ("conversion-unprovable", line)
        assert message in info.value.message  # what is unprovable: a statement, a parameter
        assert not converted.exists()
        return
    assert convert_file(str(path), str(converted), options, verify=True).verified
    assert convert_file(str(converted), str(returned), ConvertOptions(profile, profile,
                        units=back), verify=True).verified


@needs_corpus
def test_every_corpus_program_of_a_family_has_its_profile():
    names = {p.name for p in corpus_files()}
    assert set(MATCHING) <= names
    assert len(names - set(MATCHING)) == 3  # H&K, the foam cutter, the Fagor-style post


NCFILES = Path("/usr/share/linuxcnc/ncfiles")
RS274 = shutil.which("rs274")


def linuxcnc_samples() -> list[Path]:
    if not NCFILES.is_dir():
        return []
    return sorted(NCFILES.rglob("*.ngc"))


@pytest.mark.skipif(not linuxcnc_samples(), reason="LinuxCNC's sample programs are not installed")
def test_linuxcnc_samples_parse_completely():
    profile = load_profile("linuxcnc")
    unread = {}
    for path in linuxcnc_samples():
        read = parse_stream(Source(str(path)).chunks(), profile.dialect, file=path.name,
                            errors="collect")
        bad = [b for b in read if isinstance(b, BadBlock)]
        if bad:
            unread[path.name] = bad
    # nestedcall.ngc calls "O<g20sub> callsub", which rs274 refuses as well
    assert set(unread) <= {"nestedcall.ngc"}, {k: str(v[0].error) for k, v in unread.items()}
    assert len(linuxcnc_samples()) - len(unread) >= 150


@pytest.mark.skipif(RS274 is None or not linuxcnc_samples(), reason="LinuxCNC's rs274 is absent")
def test_what_rs274_refuses_at_reading_tapegate_refuses_too(tmp_path):
    (tmp_path / "tools.tbl").write_text("")
    path = NCFILES / "nestedcall.ngc"
    result = subprocess.run(env=rs274_env(),
                            args=[RS274, "-g", "-t", str(tmp_path / "tools.tbl"), str(path),
                             "/dev/null"], capture_output=True, text=True, timeout=30,
                            cwd=tmp_path)
    assert "Unexpected character after O-word" in result.stdout + result.stderr
    bad = [b for b in parse_stream(Source(str(path)).chunks(), load_profile("linuxcnc").dialect,
                                   errors="collect") if isinstance(b, BadBlock)]
    assert [b.line for b in bad] == [11]


def test_g80_cancels_the_motion_mode_on_linuxcnc_only():
    """LinuxCNC: G80 cancels the motion mode too; a Fanuc, a Haas or an ISO control keeps G01
    after G80."""
    from postproc.state import state_at

    program = "G21 G90 G17\nG01 X0 Y0 Z5 F100\nG81 X1 Y1 Z-1 R1\nG80\nX2\n"
    for profile, motion in (("linuxcnc", None), ("fanuc-mill", 1), ("haas-mill", 1),
                            ("iso-mill", 1)):
        prof = load_profile(profile)
        state = state_at(parse_text(program, prof.dialect), prof, 5)
        assert state.motion == motion, profile


def _rules(program: str, profile: str) -> list[tuple[str, int]]:
    prof = load_profile(profile)
    checker = Checker(prof)
    return [(f.rule, f.line) for f in checker.run_stream([program], prof.dialect)
            if f.severity != "info"]


CYCLE = "G21 G90 G17 G94\nG00 X0 Y0 Z5\nG81 X1 Y1 Z-1 R1 F100\nX2\n{}\nM30\n"


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill", "linuxcnc"])
def test_a_motion_code_ends_a_cycle_on_the_dialects_and_iso_asks_for_g80(profile):
    """Fanuc, Haas and LinuxCNC end a fixed cycle with any code of the motion group: the move
    after it is a plain move, no G80 needed; only ISO 6983-1 wants G80 first (TG542)."""
    program = CYCLE.format("G00 X5 Z10")
    if profile != "linuxcnc":
        program = "%\nO1\n" + program + "%\n"
    assert [r for r in _rules(program, profile) if r[0].startswith("TG54")] == []
    iso = "%\n" + CYCLE.format("G00 X5 Z10").replace("G21", "G71") + "%\n"
    assert ("TG542", 6) in _rules(iso, "iso-mill")


def test_a_cycle_goes_on_until_it_is_ended():
    """X2 after G81 drills again at X2 (a cycle block, not a feed move without its feed)."""
    from postproc.state import state_at

    prof = load_profile("fanuc-mill")
    program = "%\nO1\n" + CYCLE.format("G80\nZ20") + "%\n"
    state = state_at(parse_text(program, prof.dialect), prof, 6)
    assert state.cycle == 81  # line 6 is X2: the cycle is still in force before it
    assert state_at(parse_text(program, prof.dialect), prof, 8).cycle is None


@pytest.mark.parametrize(("body", "line"), [
    ("G21 G90\nX1\nM2\n", 2),  # no motion mode at the start
    ("G21 G90\nG01 X0 F100\nG81 X1 Z-1 R1\nG80\nX2\nM2\n", 5),  # none after G80
    ("G21 G90\nG01 X0 F100\nG81 X1 Z-1 R1\nG80 X2\nM2\n", 4),  # G80 with axis words
    ("G21 G90\nG53 X0\nM2\n", 2),  # G53 needs G0 or G1 too (rs274 says so)
])
def test_axis_words_without_a_motion_mode_on_linuxcnc(body, line):
    """rs274: "Cannot use axis values without a g code that uses them"."""
    assert ("TG411", line) in _rules(body, "linuxcnc")
    fanuc = "%\nO1\n" + body.replace("M2", "M30") + "%\n"  # G00/G01 from reset, kept by G80
    assert "TG411" not in {r for r, _ in _rules(fanuc, "fanuc-mill")}


@pytest.mark.parametrize("body", [
    "G21 G90\nG92 X0\nG10 L2 P1 X0\nG28 X0\nM2\n",  # codes that take axis words
    "G21 G90\nG81 X1 Z-1 R1 F100\nX2\nG80\nG0 X0\nM2\n",  # the cycle's own blocks
    "G21 G90\nG38.2 Z-10 F100\nZ-12\nG73 X1 Z-1 R1 Q0.5\nX2\nM2\n",  # modes not modelled
])
def test_no_tg411_where_a_code_takes_the_axis_words(body):
    assert "TG411" not in {r for r, _ in _rules(body, "linuxcnc")}


# -- block skip in the middle of a block (Fanuc, Haas) -------------------------------------------

MID_SKIP = """%
O1234
G21 G90 G17 G94
N10 G00 X10. Y5. /M08
N20 G01 Z-1.0/Y20. F100.
N30 G00 Z5.
M30
%
"""


@pytest.mark.parametrize("profile", ["fanuc-mill", "fanuc-lathe", "haas-mill", "haas-lathe"])
def test_a_skip_in_the_middle_of_a_block_is_read_and_warned_about(profile):
    """A Fanuc skips from a slash in the middle of a block to its end when the block-skip
    switch is on: the block is read whole, reprinted byte for byte, checked as written (the
    switch off), and TG128 names what the switch would skip, at the slash."""
    text = MID_SKIP if "mill" in profile else MID_SKIP.replace("G17 G94", "G18 G98")
    read = blocks(text, profile)
    assert not [b for b in read if isinstance(b, BadBlock)]
    assert program_text(read) == text
    assert (read[3].words, read[3].skip, read[3].skip_within) == (
        ["N10", "G00", "X10.", "Y5.", "M08"], "", (18, "/"))
    assert read[4].skip_within == (14, "/")
    prof = load_profile(profile)
    # the blocks made in Python and the chunks of text read by the core say the same
    for found in (findings(text, profile), list(Checker(prof).run_stream([text], prof.dialect))):
        skips = [(f.severity, f.line, f.column, f.message) for f in found if f.rule == "TG128"]
        assert [s[:3] for s in skips] == [("warning", 4, 18), ("warning", 5, 14)]
        assert "(M08)" in skips[0][3] and "(Y20. F100.)" in skips[1][3]
        assert not [f for f in found if f.severity == "error"], found


def test_a_skip_in_the_middle_of_a_block_keeps_its_place_through_convert(tmp_path):
    same = convert_text(tmp_path, MID_SKIP, source="fanuc-mill", target="fanuc-mill")
    assert same == MID_SKIP
    inch = convert_text(tmp_path, MID_SKIP, source="fanuc-mill", target="fanuc-mill",
                        units="inch")
    assert "N10 G00 X0.3937 Y0.1969 /M08\n" in inch
    assert "N20 G01 Z-0.0394/Y0.7874 F3.937\n" in inch
    glued = convert_text(tmp_path, MID_SKIP, source="fanuc-mill", target="fanuc-mill",
                         spacing="remove")
    assert "N10G00X10.Y5./M08\n" in glued and "N20G01Z-1.0/Y20.F100.\n" in glued
    # and verified: the converted program read back has the slash before the same words
    source, there, back = tmp_path / "a.nc", tmp_path / "there.nc", tmp_path / "back.nc"
    source.write_text(MID_SKIP)
    prof = load_profile("fanuc-mill")
    assert convert_file(str(source), str(there), ConvertOptions(prof, prof, units="inch"),
                        verify=True).verified
    assert convert_file(str(there), str(back), ConvertOptions(prof, prof, units="metric"),
                        verify=True).verified
    assert "N20 G01 Z-1.001/Y20. F100.\n" in back.read_text()  # 0.0394 in, rounded


@pytest.mark.parametrize("target", ["sinumerik-840d", "linuxcnc", "iso-mill"])
def test_a_skip_in_the_middle_of_a_block_is_not_carried_to_a_control_that_refuses_it(tmp_path,
                                                                                  target):
    source = tmp_path / "a.nc"
    source.write_text(MID_SKIP)
    with pytest.raises(ConversionError) as refused:
        convert_file(str(source), str(tmp_path / "o.nc"),
                     ConvertOptions(load_profile(target), load_profile("fanuc-mill")))
    line = MID_SKIP.splitlines().index(next(x for x in MID_SKIP.splitlines() if "/" in x)) + 1
    text = MID_SKIP.splitlines()[line - 1]
    assert (refused.value.line, refused.value.column) == (line, text.index("/") + 1)
    assert "'/' in the middle of the block" in str(refused.value)
    assert not (tmp_path / "o.nc").exists()


def test_a_skipped_tool_change_or_spindle_start_is_named_as_changing_what_follows():
    found = {f.line: f.message for f in findings(
        "%\nO1\nG21 G90\nT2 /M06\nS100 /S2000 M03\nM30\n%\n", "fanuc-mill")
        if f.rule == "TG128"}
    assert "(M06)" in found[4] and "another machine state (M code)" in found[4]
    assert "another speed and machine state (M code)" in found[5]


def test_an_okuma_m98_is_the_machine_s_code_not_a_call():
    # OSP's M98 is a coolant code (the OSP M code list); its call is CALL: the position stays
    # known, so the travel the move leaves is found
    program = "$O1%\nG15 H1\nG90 G00 X0 Y0 Z5.\nM98\nG91 G00 X5000.\nM02\n"
    assert "TG601" in rules(program, "okuma-mill")
    assert "TG140" not in rules(program, "okuma-mill")
    # a FANUC's M98 P100 calls a program not in the file: the position after it is not known
    # (TG140), and X5000. is judged as an increment from a start not known, longer than X's
    # whole travel (incr48), not as a position from X0
    fanuc = "%\nO1\nG90 G00 X0 Y0 Z5.\nM98 P100\nG91 G00 X5000.\nM30\n%\n"
    assert "TG140" in rules(fanuc, "fanuc-mill")
    travel = [f.message for f in findings(fanuc, "fanuc-mill") if f.rule == "TG601"]
    assert len(travel) == 1
    assert travel[0].startswith("X moves 5000 (X5000.) with its start not known")
    fits = fanuc.replace("X5000.", "X500.")
    assert "TG601" not in rules(fits, "fanuc-mill")


# An Okuma OSP lathe's arcs give their radius by L (OSP-P200L Programming Manual 5238-E, section
# 3 "Circular Interpolation (G02, G03)", P-26: "L: Sets the radius of the arc"), in the blocks
# of a modal G02 too; G33's L is the thread's chamfering distance (P-97).
OKUMA_ARCS = ("$ARC.MIN%\nG0 X20. Z5.\nG1 Z0 F.2\nG3 X26. Z-3. L3.\nG1 Z-10.\n"
              "G2 X30. Z-12. L2.\nX34. Z-14. L2.\nG33 X18. Z-20. F1.5 L1.5\nG0 X50. Z50.\nM02\n")


def arc_findings(text: str, profile: str) -> list[tuple[str, int, str]]:
    return [(f.rule, f.line, f.message) for f in findings(text, profile)
            if f.rule in ("TG134", "TG403", "TG404", "TG405", "TG410")]


def test_an_okuma_lathe_arc_takes_its_radius_from_l():
    assert arc_findings(OKUMA_ARCS, "okuma-lathe") == []
    # half the chord from X20. Z0 to X26. Z-3. (X a diameter) is 2.121: no arc of radius 2
    short = arc_findings(OKUMA_ARCS.replace("L3.", "L2."), "okuma-lathe")
    assert [(rule, line) for rule, line, _ in short] == [("TG410", 4)]
    assert "radius 2 is shorter than half the chord 2.12132" in short[0][2]
    # neither I K nor L; R is no arc radius on this control
    for arc in ("G3 X26. Z-3.", "G3 X26. Z-3. R3."):
        found = arc_findings(OKUMA_ARCS.replace("G3 X26. Z-3. L3.", arc), "okuma-lathe")
        assert found == [("TG404", 4, "arc without I K (or L)")], arc
    assert arc_findings(OKUMA_ARCS.replace("L3.", "L0"), "okuma-lathe") == [
        ("TG405", 4, "arc of zero radius (L0)")]
    # on a Fanuc lathe L is no radius: the arc has none (and its R is one)
    fanuc = "%\nO1\nG0 X20. Z5.\nG1 Z0 F.2\nG3 X26. Z-3. L3.\nG3 X32. Z-6. R3.\nM30\n%\n"
    assert [(r, line) for r, line, _ in arc_findings(fanuc, "fanuc-lathe")] == [("TG404", 5)]


def test_an_okuma_lathe_arc_radius_is_converted_as_a_length(tmp_path):
    lathe = load_profile("okuma-lathe")
    path, inch, back = tmp_path / "arc.min", tmp_path / "inch.min", tmp_path / "back.min"
    path.write_text(OKUMA_ARCS)
    stats = convert_file(str(path), str(inch), ConvertOptions(lathe, lathe, units="inch"),
                         verify=True)
    assert stats.verified
    lines = inch.read_text().splitlines()
    # an OSP's lengths in inch to 0.0001 in (4203-E, section 1); F keeps its format
    assert lines[3] == "G3 X1.0236 Z-0.1181 L0.1181"
    assert lines[5:8] == ["G2 X1.1811 Z-0.4724 L0.0787", "X1.3386 Z-0.5512 L0.0787",
                          "G33 X0.7087 Z-0.7874 F0.059 L0.0591"]
    # the inch program checks as the metric one, and tapegate diff reads it as the same program
    # on the lathe set to inch (its unit system is a parameter: no code in the program says it)
    inch_lathe = dataclasses.replace(lathe, default_units="inch")
    assert arc_findings(inch.read_text(), "okuma-lathe") == []
    assert list(diff_files(str(path), str(inch), lathe, inch_lathe,
                           DiffOptions(tolerance=Decimal("0.5")))) == []
    # and back to millimetres, within the inch program's 0.0001 in
    convert_file(str(inch), str(back), ConvertOptions(lathe, inch_lathe, units="metric"),
                 verify=True)
    assert back.read_text().splitlines()[3] == "G3 X25.999 Z-3. L3."
    # an L the manual does not explain is refused under a change of units, at its column (and
    # the cycle's D, a word of the same kind: tests/test_convert_lathes.py)
    cycle = OKUMA_ARCS.replace("G0 X50. Z50.", "G73 X47. Z53. K2.79 L12.4 D4")
    with pytest.raises(ConversionError) as refused:
        convert_text(tmp_path, cycle, source="okuma-lathe", target="okuma-lathe", units="inch")
    assert (refused.value.line, refused.value.column) == (9, cycle.splitlines()[8].index("L") + 1)
    assert "outside an arc and a thread cutting cycle" in str(refused.value)
    kept = convert_text(tmp_path, cycle, source="okuma-lathe", target="okuma-lathe",
                        units="inch", allow_unconverted=True)
    assert "L12.4 D4" in kept


# An Okuma OSP lathe's G20 is its home position return (G20 HP=n), G21 the tool change home
# position return, and its unit system a machine parameter: no G code selects inch or metric
# (the OSP-P200L/P20L programming manual's code table and section 2-3, as NC-PB/gEdit's OSP
# syntax notes transcribe them; an Okuma Multus user task writes G20 HP=4 (HOME POSITION RETURN
# 4), Autodesk's OSP-300 Multus post G20 HP=1 as its retract, its LB3000 lathe post no units
# code). Read as inch, the blocks after it were 25.4 times too long.
OKUMA_HOME = ("$HOME.MIN%\nG50 S2000\nG00 X100 Z100\nG20 HP=4 (HOME POSITION RETURN 4)\n"
              "G00 X50. Z2.\nG01 Z-20. F0.2\nG20 HP=1\nM02\n")


def test_an_okuma_lathe_g20_is_a_home_position_return_not_inch():
    lathe = load_profile("okuma-lathe")
    assert lathe.units_codes == ("", "") and not lathe.units_by_code
    assert lathe.code("G", 20).function == "home position return (HP=n)"
    assert lathe.code("G", 21).function == "tool change (ATC) home position return"
    assert "G21" not in lathe.reset_state()
    # it was TG601: X50. read as 50 inches, 1270 mm, past the travel
    assert findings(OKUMA_HOME, "okuma-lathe") == []
    # the machining centre's G20 stays inch (4203-E, List of G Codes)
    assert load_profile("okuma-mill").units_codes == ("G20", "G21")
    # after the return no position is known: an incremental move from it gives no position
    # (from X100 it does: 100 + 5000 is past the travel)
    far = "$FAR.MIN%\nG00 X100 Z100\nG91 G00 X5000\nM02\n"
    assert "TG601" in rules(far, "okuma-lathe")
    # after the home position return X is not known: X5000 is judged as an increment from a
    # start not known, longer than X's whole travel (incr48), not as a position from X100
    home = [f.message for f in findings(far.replace("G91", "G20 HP=1\nG91"), "okuma-lathe")
            if f.rule == "TG601"]
    assert len(home) == 1 and "with its start not known" in home[0]


def test_an_okuma_lathe_program_converts_its_units_by_the_machine_parameter(tmp_path):
    lathe = load_profile("okuma-lathe")
    path, inch = tmp_path / "home.min", tmp_path / "inch.min"
    path.write_text(OKUMA_HOME)
    stats = convert_file(str(path), str(inch), ConvertOptions(lathe, lathe, units="inch"),
                         verify=True)
    assert stats.verified
    # every length converted, from the first; G20 HP=4 as written (HP a count); no G20 added
    assert inch.read_text() == ("$HOME.MIN%\nG50 S2000\nG00 X3.937 Z3.937\n"
                                "G20 HP=4 (HOME POSITION RETURN 4)\nG00 X1.9685 Z0.0787\n"
                                "G01 Z-0.7874 F0.008\nG20 HP=1\nM02\n")
    assert ("no units code written: the target control selects its units by a machine "
            "parameter, not by a G code; every length from line 2 on is converted to inch: "
            "set the machine to inch before running it; the source was read in metric, the "
            "source profile's units: its control selects them by a machine parameter the "
            "program does not show") in stats.notes
    # a Fanuc lathe's G21 has nothing to become on it (left, it would be a home return)
    fanuc = "%\nO1\nG21 G40 G97\nG00 X100. Z100.\nM30\n%\n"
    with pytest.raises(ConversionError) as refused:
        convert_text(tmp_path, fanuc, source="fanuc-lathe", target="okuma-lathe")
    assert (refused.value.line, refused.value.column) == (3, 1)
    assert "selects its units by a machine parameter, not by a G code" in str(refused.value)
    # without it, the units are converted and the note says where the machine's are set
    out = convert_text(tmp_path, fanuc.replace("G21 ", ""), source="fanuc-lathe",
                       target="okuma-lathe", units="inch")
    assert "G00 X3.937 Z3.937" in out and "G20" not in out and "G21" not in out
    # an Okuma lathe's G20 is not an Okuma machining centre's inch code
    with pytest.raises(ConversionError) as other:
        # (Z alone on line 2: a lathe's X, a diameter, is refused for a mill at the first X)
        convert_text(tmp_path, OKUMA_HOME.replace("G50 S2000\n", "").replace(
            "G00 X100 Z100\n", "G00 Z100\n"), source="okuma-lathe", target="okuma-mill")
    assert other.value.line == 3 and other.value.message.startswith(
        'G20: the source and target controls give this code different meanings (no modal group '
        'on the source, group "units" on the target')


def test_a_program_of_a_machine_without_units_codes_gets_the_target_s_code(tmp_path):
    """From the OSP lathe (units by parameter) to a control that selects them by G20/G21 (an
    OSP-family lathe profile that has them, as a user might write one): the code is inserted
    and the note says the source's units were its profile's, the parameter's."""
    from importlib import resources

    text = (resources.files("formats") / "profiles" / "okuma-lathe.toml").read_text()
    text = re.sub(r"\nG2[01] = [^\n]*", "", text.replace('units_codes = "none"',
                                                        'units_codes = "G20/G21"'))
    coded = profile_from_text(text)
    assert coded.units_codes == ("G20", "G21")
    path, out = tmp_path / "a.min", tmp_path / "out.min"
    path.write_text("$A.MIN%\nG00 X100. Z100.\nM02\n")
    stats = convert_file(str(path), str(out), ConvertOptions(
        coded, load_profile("okuma-lathe"), units="inch"), verify=True)
    assert out.read_text() == "$A.MIN%\nG20 G00 X3.937 Z3.937\nM02\n" and stats.verified
    assert stats.notes == ["inserted G20: the source control selects its units by a machine "
                           "parameter, not by a G code; the program was read in metric, the "
                           "source profile's units",
                           "verified with the source read in metric, the source profile's "
                           "units: its control selects them by a machine parameter the program "
                           "does not show, so a program written for a machine set to the other "
                           "units is not proved; give --from-units to say what the machine is "
                           "set to"]
    assert stats.verified_assuming == "metric"


def test_g20_hp_is_no_units_code_when_the_source_is_detected():
    from formats.convert import detect_source

    _, notes = detect_source(OKUMA_HOME)
    assert notes[0] == "source: no units code (G70/G71, G20/G21) found, read as metric"
    _, notes = detect_source("%\nO1\nG20 G90\nM30\n")
    assert notes[0] == "source: units codes G20/G21 (G20 found)"


@pytest.mark.parametrize("source, target, text, word", [
    # (no X: a lathe's X, a diameter, is refused for a mill at the first X word)
    ("okuma-lathe", "okuma-mill", "$ARC.MIN%\nG0 Z5.\nG3 Z-3. L3.\nM02\n", "L3."),
    ("okuma-lathe", "fanuc-lathe", OKUMA_ARCS.replace("$ARC.MIN%\n", ""), "L3."),
    ("fanuc-lathe", "okuma-lathe", "%\nO1\nG0 X20. Z5.\nG1 Z0 F.2\nG3 X26. Z-3. R3.\nM30\n%\n",
     "R3."),
])
def test_an_arc_by_its_radius_is_refused_for_a_control_that_reads_another_letter(
        tmp_path, source, target, text, word):
    """An Okuma lathe reads the radius from L, an Okuma machining centre and a Fanuc lathe from R:
    the other control would read the arc without its radius, so the conversion stops at the
    word, in any units."""
    with pytest.raises(ConversionError) as refused:
        convert_text(tmp_path, text, source=source, target=target)
    line = next(i for i, x in enumerate(text.splitlines(), 1) if word in x)
    column = text.splitlines()[line - 1].index(word) + 1
    assert (refused.value.line, refused.value.column, refused.value.clause) == (line, column, "7.3")
    assert "reads an arc's radius from" in str(refused.value)


@pytest.mark.parametrize("change, line, details", [
    # the slash lost, moved to another word, given a level: each a difference at its block
    ((" /M08", " M08"), 4, ["/ removed"]),
    (("Z-1.0/Y20. F100.", "Z-1.0 Y20. /F100."), 5, ["/ removed", "/ added"]),
    ((" /M08", " /2M08"), 4, ["/ -> /2"]),
])
def test_diff_sees_the_skip_in_the_middle_of_a_block(tmp_path, change, line, details):
    prof = load_profile("fanuc-mill")
    (tmp_path / "a.nc").write_text(MID_SKIP)
    (tmp_path / "b.nc").write_text(MID_SKIP.replace(*change))
    (tmp_path / "c.nc").write_text(MID_SKIP)
    assert not list(diff_files(str(tmp_path / "a.nc"), str(tmp_path / "c.nc"), prof, prof))
    found = list(diff_files(str(tmp_path / "a.nc"), str(tmp_path / "b.nc"), prof, prof))
    assert [(d.kind, d.a.line if d.a else None) for d in found] == [("changed", line)]
    assert found[0].details() == details


def test_the_restart_walk_reads_the_words_after_a_skip_in_the_middle_of_a_block():
    from postproc.restart import plan_restart_text

    # (the program never raises Z above its cut before N30: the profile gives the safe Z,
    # without which the restart is refused, docs/dnc.md)
    fanuc = load_profile("fanuc-mill")
    safe = dataclasses.replace(fanuc, restart=dataclasses.replace(fanuc.restart,
                                                                  clearance=Decimal("50")))
    plan = plan_restart_text([MID_SKIP], safe, 6)
    assert plan.preamble[1:] == ["M08", "G00 Z50.", "G00 X10. Y20.", "G01 Z-1. F100."]


@pytest.mark.parametrize("profile", ["iso-mill", "linuxcnc", "sinumerik-840d"])
def test_a_skip_in_the_middle_of_a_block_is_refused_elsewhere_located(profile):
    """ISO 6983-1, LinuxCNC (rs274: "Bad character '/' used") and SINUMERIK (skip levels only in
    front of the block) read a block skip at the head of the block alone."""
    text = "%\nN10 G00 X10. Y5. /M08\nN20 M30\n%\n"
    bad = [b for b in blocks(text, profile) if isinstance(b, BadBlock)]
    assert len(bad) == 1
    error = bad[0].error
    assert (error.code, error.line, error.column) == ("TG123", 2, 18)
    assert "must stand at the start of the block" in error.message


def test_the_block_objects_and_the_text_read_the_skip_in_the_middle_of_a_block_alike():
    """The Python API's Block objects (BlockInfo.skip_within) and the core's reading of whole
    chunks of text: the same diff words, the same conversion, and `parse --json` shows it."""
    from formats.convert import Converter
    from formats.diff import ProgramReader

    prof = load_profile("fanuc-mill")
    read = blocks(MID_SKIP, "fanuc-mill")

    def words(reader_blocks) -> list[list[tuple[str, str]]]:
        return [[(w[0], w[1]) for w in b.words()] for b in reader_blocks]

    by_blocks = words(ProgramReader(prof, file="a", options=DiffOptions()).read(read))
    by_text = words(ProgramReader(prof, file="a", options=DiffOptions()).read_text([MID_SKIP]))
    assert by_blocks == by_text
    assert ("/M", "/") in by_text[3] and ("/Y", "/") in by_text[4]
    options = ConvertOptions(prof, prof, units="inch", spacing="remove")
    assert "".join(Converter(options, prof).convert(read)) == "".join(
        Converter(options, prof).convert_stream([MID_SKIP], prof.dialect))
    assert "N20G01Z-0.0394/Y0.7874F3.937\n" in "".join(Converter(options, prof).convert(read))
    result = CliRunner().invoke(main, ["parse", "-", "--json", "-p", "fanuc-mill"],
                                input=MID_SKIP)
    assert '"skip_within": {"column": 14, "text": "/"}' in result.output.splitlines()[4]
