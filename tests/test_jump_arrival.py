"""A parameter's value where a jump may arrive (issue 32, review 39 finding 3).

The checker reads a program in file order and forgets every parameter at a jump it reads
(TG140). A block a jump may reach -- a Custom Macro B sequence number a GOTO read before it
names, a SINUMERIK label (any: a GOTOB below may come back to it) or a block number a jump
read before names, an Okuma label -- forgets the parameters assigned since, which the jump
passes over: the control may arrive there with the values from before the jump.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner

from formats.parser import parse_text
from formats.profile import load_profile
from postproc.check import Checker
from tapegate.cli import main


def findings(text: str, profile: str) -> list[tuple[str, int]]:
    prof = load_profile(profile)
    found = Checker(prof, "<input>").run(parse_text(text, prof.dialect, errors="collect"))
    return [(f.rule, f.line) for f in found]


SINUMERIK_HEAD = "G71 G90 G17\nT1 D1\nM6\nS1000 M3\n"
# lines 5-: a cut under G41 whose D is R1's value; {} is the flow before it
SINUMERIK_CUT = "G0 X0 Y0 Z5\nG1 G41 X10 Y0 F100\nD=R1 X20\nG1 X50\nG40 G0 X60\n"


def d_findings(flow: str, tail: str = "M30\n") -> list[tuple[str, int]]:
    text = SINUMERIK_HEAD + flow + SINUMERIK_CUT + tail
    d_line = text.splitlines().index("D=R1 X20") + 1
    return [r for r, line in findings(text, "sinumerik-840d")
            if r in ("TG502", "TG503") and line == d_line]


def test_sinumerik_a_forward_jump_over_an_assignment():
    """Review 39's repro: with R2 = 1 the control reaches the label with R1 = 0 (D0 under
    G41). R1=5 between the jump and the label is not R1's value there: TG503, not quiet."""
    assert d_findings("R1=0\nIF R2==1 GOTOF LBL\nR1=5\nLBL:\n") == ["TG503"]


def test_sinumerik_a_jump_that_skips_nothing():
    """Nothing assigned between the jump and its label: the value before the jump is the
    value on both paths, but the checker forgets every parameter at the jump it reads
    (TG140's 'from here on ... unknown'), so R1 is unknown at the D: TG503 as before."""
    assert d_findings("R1=5\nIF R2==1 GOTOF LBL\nLBL:\n") == ["TG503"]
    # and with no jump at all the value is known (5: quiet; 0: TG502)
    assert d_findings("R1=5\n") == []
    assert d_findings("R1=0\n") == ["TG502"]


def test_sinumerik_a_backward_jump_to_a_label():
    """A loop: the second pass reaches BACK with R1 = 0, set below it. The label forgets R1
    though no jump to it was read yet: TG503 (R1=5 alone, before it, was quiet)."""
    flow = "R1=5\nBACK:\n"
    assert d_findings(flow, "R1=0\nIF R2==1 GOTOB BACK\nM30\n") == ["TG503"]
    assert d_findings("R1=5\n", "R1=0\nM30\n") == []


def test_sinumerik_a_jump_to_a_block_number():
    """GOTOF N100: the block numbered N100 forgets R1=5 set between the jump and it."""
    flow = "R1=0\nIF R2==1 GOTOF N100\nR1=5\nN100 G0 Z10\n"
    assert d_findings(flow) == ["TG503"]
    # a block number no jump names keeps the values: the jump passes over the cut to N100
    # below it, and the cut runs only with R1=5 (quiet)
    flow = "R1=0\nIF R2==1 GOTOF N100\nN90 G0 Z10\nR1=5\n"
    assert d_findings(flow, "N100 G0 Z10\nM30\n") == []


FANUC = "%\nO1000\nG21 G90 G54\nG0 X700. Y0\n#1=-900.\nIF[#2EQ1]GOTO10\n{}N10 G0 X#1\nM30\n%\n"


def test_fanuc_a_goto_over_an_assignment():
    """Review 39's repro: with #2 = 1 the machine goes X700 -> X-900 (1600 mm, more than
    fanuc-mill's 1524). #1=0 between the GOTO and N10 is not #1's value at N10: X#1 is
    unknown there (TG141), not the X0 that spans 700."""
    found = findings(FANUC.format("#1=0\n"), "fanuc-mill")
    assert ("TG141", 8) in found, found
    # the jump itself forgets #1 (TG141 as well); a sequence number no GOTO names keeps a
    # value set after the jump
    text = "%\nO1000\nG21 G90 G54\nIF[#2EQ1]GOTO20\n#1=-900.\nN10 G0 X#1\nG0 X700.\nN20 M30\n%\n"
    found = findings(text, "fanuc-mill")
    assert ("TG141", 6) not in found, found
    assert ("TG601", 7) in found, found


def test_fanuc_a_backward_goto_target_is_read_before_the_goto():
    """A GOTO back to a sequence number read before it: the block was read with the values
    above it (the checker reads in file order and cannot know then that a jump comes back);
    after the GOTO every value is unknown. Recorded as the checker's limit: #1=0 set in the
    loop's body is not #1's value on the first pass, and the loop's first pass is what is
    read."""
    text = "%\nO1000\nG21 G90 G54\n#1=700.\nN10 G0 X#1\n#1=-900.\nIF[#2EQ1]GOTO10\nG0 X#1\nM30\n%\n"
    found = findings(text, "fanuc-mill")
    assert ("TG141", 8) in found, found


def test_okuma_a_jump_to_a_label():
    """An Okuma's variables (VC1) are not evaluated at all: X=VC1 is unknown wherever it is
    read, so a jump over VC1=0 to NLB1 leaves nothing known to forget (TG141)."""
    for jump in ("GOTO NLB1", "IF[VC2 EQ 1] NLB1"):
        text = f"G90\nVC1=-900.\n{jump}\nVC1=0\nNLB1 G0 X=VC1\nM02\n"
        assert ("TG141", 5) in findings(text, "okuma-mill")


# -- review 41: the value where the jump is not taken (through the CLI) -----------------------

def cli_findings(tmp_path: Path, name: str, text: str, profile: str,
                 select: str) -> list[dict[str, object]]:
    """`tapegate check FILE --profile PROFILE --select SELECT --format json`'s findings."""
    path = tmp_path / name
    path.write_text(text)
    result = CliRunner().invoke(
        main, ["check", str(path), "--profile", profile, "--select", select, "--all",
               "--format", "json"], catch_exceptions=False)
    found: list[dict[str, object]] = json.loads(result.output)["findings"]
    return found


def rules_at(found: list[dict[str, object]]) -> list[tuple[object, object]]:
    return [(f["rule"], f["line"]) for f in found]


# review 41's programs r1, r3, r4 (fanuc-mill: X travel 1524, S 10000, F 10000)
R1 = "%\nO1000\nG21 G90 G54\nG0 X700. Y0\n#1=0\nIF[#2EQ1]GOTO10\n#1=-900.\nN10 G0 X#1\nM30\n%\n"
R3 = ("%\nO1000\nG21 G90 G54\nT1 M6\n#1=1000\nIF[#2EQ1]GOTO10\n#1=20000\nN10 S#1 M3\n"
      "G0 X0 Y0\nM30\n%\n")
R4 = ("%\nO1000\nG21 G90 G54\nT1 M6\nS1000 M3\n#1=100.\nIF[#2EQ1]GOTO10\n#1=20000.\n"
      "N10 G1 X10. Y0 F#1\nM30\n%\n")
R5 = "%\nO1000\nG21 G90 G54\nG0 X700. Y0\n#1=-900.\nIF[#2EQ1]GOTO10\nG0 X#1\nN10 G0 X#1\nM30\n%\n"
R7 = ("%\nO1000\nN1 G21 G90 G54\nN2 G0 X700. Y0\nN3 IF[#3EQ1]GOTO#5\nN4 #1=-900.\n"
      "N5 G0 X#1\nN6 M30\n%\n")


@pytest.mark.parametrize(("name", "text", "rule", "line", "said"), [
    ("r1.nc", R1, "TG601", 8, "X#1 is -900 where the jump of line 6 is not taken"),
    ("r3.nc", R3, "TG606", 8, "S#1 is 20000 where the jump of line 6 is not taken"),
    ("r4.nc", R4, "TG605", 9, "F#1 is 20000 where the jump of line 7 is not taken"),
    ("r7.nc", R7, "TG601", 7, "X#1 is -900 where the jump of line 5 is not taken"),
])
def test_a_jump_target_keeps_the_value_where_the_jump_is_not_taken(
        tmp_path: Path, name: str, text: str, rule: str, line: int, said: str) -> None:
    """Review 41, finding 0: with the jump not taken the machine runs the block with the
    value set just above it (r1: X700 -> X-900, 1600 mm); the finding says so, and the value
    stays unknown after the block (TG141), as where the jump arrives."""
    found = cli_findings(tmp_path, name, text, "fanuc-mill", "TG6,TG141")
    assert rules_at(found) == [("TG141", line), (rule, line)], found
    assert said in str(found[1]["message"]), found[1]


def test_a_conditional_jump_forward_keeps_the_values_where_it_falls_through(
        tmp_path: Path) -> None:
    """Review 41, finding 0's older half (r5.nc): `IF[#2EQ1]GOTO10` not taken changes no
    parameter, so `G0 X#1` after it goes to X-900; N10 reads it where the jump is not taken
    (the span already said)."""
    found = cli_findings(tmp_path, "r5.nc", R5, "fanuc-mill", "TG6,TG141")
    assert rules_at(found) == [("TG601", 7), ("TG141", 8)], found
    assert "not taken" not in str(found[0]["message"])


def test_sinumerik_a_jump_back_to_a_block_number(tmp_path: Path) -> None:
    """Review 41, finding 3 (s5.mpf): the second pass of `GOTOB N10` reads `D=R1` with R1 =
    0, set after it: TG503 at the D, said at the jump. Without the R1=0 in the loop, and with
    numbered blocks and no jump back, the D stays quiet (fix (a): an N-numbered program
    without loops keeps its D=R1 quiet)."""
    body = ("G71 G90 G17\nT1 D1\nM6\nS1000 M3\nR1=5\nR2=0\nG0 X0 Y0 Z5\nG1 G41 X10 Y0 F100\n"
            "N10 D=R1 X20\nR1=0\nR2=R2+1\nIF R2<2 GOTOB N10\nG40 G0 X60\nM30\n")
    found = cli_findings(tmp_path, "s5.mpf", body, "sinumerik-840d", "TG502,TG503")
    assert rules_at(found) == [("TG503", 9)], found
    assert "the jump of line 12 back to N10" in str(found[0]["message"])
    quiet = body.replace("R1=0\n", "R2=R2\n")
    assert cli_findings(tmp_path, "s5q.mpf", quiet, "sinumerik-840d", "TG502,TG503") == []
    numbered = body.replace("IF R2<2 GOTOB N10\n", "N40 R3=1\n")
    assert cli_findings(tmp_path, "s5n.mpf", numbered, "sinumerik-840d", "TG502,TG503") == []


# -- review 44 F3: the value a forward jump carries (through the CLI) --------------------------

# the review's programs: #1 is -900 where the jump of line 6 is taken (X700 -> X-900, 1600 mm,
# more than fanuc-mill's 1524), 0 where it is not; and the value reaching the word through an
# assignment at the target, either way
F3 = "%\nO1000\nG21 G90 G54\nG0 X700. Y0\n#1=-900.\nIF[#2EQ1]GOTO10\n#1=0\nN10 G0 X#1\nM30\n%\n"
F3_FALLS = ("%\nO1000\nG21 G90 G54\nG0 X700. Y0\n#1=0\nIF[#2EQ1]GOTO10\n#1=-900.\nN10 #3=#1\n"
            "G0 X#3\nM30\n%\n")
F3_TAKEN = ("%\nO1000\nG21 G90 G54\nG0 X700. Y0\n#1=-900.\nIF[#2EQ1]GOTO10\n#1=0\nN10 #3=#1\n"
            "G0 X#3\nM30\n%\n")
# SINUMERIK (X travel 1600): GOTOF to a block number, an R parameter copied there
F3_SINUMERIK = "G0 X700 Y0\nR1=-1000\nIF R2==1 GOTOF N100\nR1=0\nN100 R3=R1\nG0 X=R3\nM30\n"


@pytest.mark.parametrize(("name", "text", "profile", "line", "said"), [
    ("f3.nc", F3, "fanuc-mill", 8, "X#1 is -900 where the jump of line 6 is taken"),
    ("f3h.nc", F3, "haas-mill", 8, "X#1 is -900 where the jump of line 6 is taken"),
    ("f3f.nc", F3_FALLS, "fanuc-mill", 9, "X#3 is -900 where the jump of line 6 is not taken"),
    ("f3t.nc", F3_TAKEN, "fanuc-mill", 9, "X#3 is -900 where the jump of line 6 is taken"),
    ("f3s.mpf", F3_SINUMERIK, "sinumerik-840d", 6,
     "X=R3 is -1000 where the jump of line 3 is taken"),
])
def test_a_jump_target_judges_the_value_the_jump_carries(
        tmp_path: Path, name: str, text: str, profile: str, line: int, said: str) -> None:
    """Review 44 F3: at a jump target each run that arrives -- the fall-through and each
    forward jump taken, with the values at its line -- is judged by the limits; the finding
    names the jump. The word stays unknown after its block (TG141)."""
    found = cli_findings(tmp_path, name, text, profile, "TG601,TG141")
    assert rules_at(found) == [("TG141", line), ("TG601", line)], found
    assert said in str(found[1]["message"]), found[1]


def test_where_the_jump_brings_the_fall_through_s_value_nothing_changes(
        tmp_path: Path) -> None:
    """No assignment between the jump and N10: both runs read #1 = -900, and the finding is
    the fall-through's alone, as before."""
    same = F3.replace("#1=0\n", "")
    found = cli_findings(tmp_path, "same.nc", same, "fanuc-mill", "TG601,TG141")
    assert rules_at(found) == [("TG141", 7), ("TG601", 7)], found
    assert "X#1 is -900 where the jump of line 6 is not taken" in str(found[1]["message"])


# review 48 F2: a forward jump met inside a jump's run (f4.nc, j9.nc)
F2_IF = ("%\nO1000\nG20 G90 G54 G17\nG0 X1. Y0\n#9=9999.\nIF[#2EQ1]GOTO10\n#9=500.\n"
         "N10 G0 Y0\nIF[#3EQ1]GOTO20\n#9=400.\nN20 G1 X3. F#9\nM30\n%\n")
F2_GOTO = ("%\nO1000\nG21 G90 G54 G17\nG0 X700. Y0\n#1=-900.\nIF[#2EQ1]GOTO10\n#1=0\n"
           "N10 G0 Y0\nGOTO20\nN15 G0 X0\nN20 G0 X#1\nM30\n%\n")


@pytest.mark.parametrize(("name", "text", "profile", "rule", "said"), [
    ("f4.nc", F2_IF, "haas-mill", "TG602", "F#9 is 9999 where the jumps of lines 6 and 9 are "
     "taken"),
    ("j9.nc", F2_GOTO, "fanuc-mill", "TG601", "X#1 is -900 where the jumps of lines 6 and 9 "
     "are taken"),
])
def test_a_jump_met_in_a_jump_s_run_is_followed(
        tmp_path: Path, name: str, text: str, profile: str, rule: str, said: str) -> None:
    """Review 48 F2: the run where line 6's jump is taken meets line 9's jump (an IF or a
    GOTO with no condition): that run's values arrive at line 9's target too, and are
    judged there (before: TG141 alone)."""
    found = cli_findings(tmp_path, name, text, profile, f"{rule},TG141")
    assert rules_at(found) == [("TG141", 11), (rule, 11)], found
    assert said in str(found[1]["message"]), found[1]


# -- review 48's t1.nc and review 49b's R6 (jump50) --------------------------------------------

HINT = "the built-in profile's limits are a typical machine of the family"


def test_the_blocks_a_jump_surely_taken_passes_over_are_not_run(tmp_path: Path) -> None:
    """Review 48's t1.nc: `#1=1` / `IF [#1 EQ 1] GOTO 10` skips the `G1 X9999.` and the `G91`
    before N10, so neither is judged nor in force there; N10's `X#2` reads #2 as it was at
    the jump (-900: a 1600 span from X700, at its word). A line the checker cannot read
    between stays an error at its line and column."""
    t1 = ("%\nO1000\nG21 G90 G54\nG0 X700. Y0\n#2=-900.\n#1=1\nIF [#1 EQ 1] GOTO 10\n"
          "G1 X9999. F100.\nG91\n#2=0\n-------\nN10 G0 X#2\nX100.\nM30\n%\n")
    found = cli_findings(tmp_path, "t1.nc", t1, "fanuc-mill", "TG601,TG100,TG141")
    assert [(f["rule"], f["line"], f["column"]) for f in found] == [
        ("TG100", 11, 1), ("TG601", 12, 8)]
    assert "X spans 1600 (from -900 to 700)" in str(found[1]["message"])
    # the condition not known: the blocks are judged as before (the X9999. at its line)
    unknown = t1.replace("#1=1\n", "#1=#5\n")
    assert ("TG601", 8) in rules_at(cli_findings(tmp_path, "t2.nc", unknown, "fanuc-mill",
                                                 "TG601"))
    # the target not in the program: as before (TG118 at the jump, the X9999. judged)
    lost = t1.replace("N10 G0", "N20 G0")
    assert rules_at(cli_findings(tmp_path, "t3.nc", lost, "fanuc-mill", "TG601,TG118")) == [
        ("TG601", 8), ("TG118", 7)]


def test_the_sample_machine_hint_goes_on_the_first_finding_shown(tmp_path: Path) -> None:
    """Review 49b, R6: the sample machine's hint is said once, on the first limit finding
    shown; with the span's TG601 left out by --select or --ignore, the feed's TG605 after it
    carries it."""
    path = tmp_path / "r6.nc"
    path.write_text("%\nO1000\nG21 G90 G54\nG0 X700. Y0\nG0 X-900.\nG1 X0 F20000.\nM30\n%\n")
    for option in (["--select", "TG605"], ["--ignore", "TG601"], []):
        result = CliRunner().invoke(
            main, ["check", str(path), "--profile", "fanuc-mill", *option, "--format", "json"],
            catch_exceptions=False)
        found = [f for f in json.loads(result.output)["findings"]
                 if str(f["rule"]).startswith("TG60")]
        assert [HINT in str(f["message"]) for f in found] == (
            [True, False] if not option else [True]), option
        assert (found[-1]["rule"], found[-1]["line"], found[-1]["column"]) == ("TG605", 6, 7)


# review 51, F14: the file's program; line 9 is `N10 G91 G0 X850.`
F14 = ("%\nO1000\nG21 G17 G90 G54\nG0 X-700. Y0 Z10.\nG0 X700.\nG0 X0\n{jump}\nG0 X10.\n"
       "N10 G91 G0 X850.\nG90\nM30\n%\n")


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("jump", ["GOTO10", "#1=1\nIF[#1EQ1]GOTO10"])
def test_an_increment_at_a_jump_target_starts_where_the_jump_left(profile, jump):
    """A jump surely taken leaves the machine where its block did (X0): the target's G91 X850.
    goes to X850, a 1550 span from X-700 past the fanuc-mill's 1524 (X -762..762) and the
    haas-mill's travel, at the target's line -- not a move whose start is not known."""
    text = F14.format(jump=jump)
    line = 9 + jump.count("\n")
    prof = load_profile(profile)
    found = Checker(prof, "<input>").run(parse_text(text, prof.dialect, errors="collect"))
    travel = [f for f in found if f.rule == "TG601"]
    assert [(f.line, f.column) for f in travel] == [(line, 12)], travel
    assert "start not known" not in travel[0].message
    if profile == "fanuc-mill":
        assert travel[0].message.startswith("X spans 1550 (from -700 to 850)"), travel[0].message


def test_a_numbered_block_before_the_target_gives_the_passage_up():
    """`N5 G0 X10.` between may be named by another jump: the blocks are judged as before,
    the X10. run (from -700 to 860)."""
    text = F14.format(jump="GOTO10").replace("\nG0 X10.\n", "\nN5 G0 X10.\n")
    prof = load_profile("fanuc-mill")
    found = Checker(prof, "<input>").run(parse_text(text, prof.dialect, errors="collect"))
    travel = [f for f in found if f.rule == "TG601"]
    assert [f.line for f in travel] == [9]
    assert travel[0].message.startswith("X spans 1560 (from -700 to 860)"), travel[0].message


def _found(text: str, profile: str) -> list:
    prof = load_profile(profile)
    return Checker(prof, "<input>").run(parse_text(text, prof.dialect, errors="collect"))


# review 53, F17 (w7.nc): line 8 is the target `N26 IF [#1 EQ 0] GOTO 39`
W7 = ("%\nO1000\nG21 G17 G90 G54\n#1=0\nG0 X0 Y0 Z10.\nGOTO 26\n{between}\n"
      "N26 IF [#1 EQ 0] GOTO 39\nG91\nN39 G0 X900.\nN48 G0 X900.\nM30\n%\n")


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
def test_a_goto_keeps_the_parameters_for_its_target(profile):
    """A `GOTO 26` with no condition reaches N26 with #1 = 0, as a known-true IF would: the
    IF there is surely taken, the G91 passed over, and X900. twice is absolute (no TG601);
    a word `X#1` at the target is evaluated (no TG141)."""
    found = _found(W7.format(between="G0 X5."), profile)
    assert [f for f in found if f.rule in ("TG601", "TG141")] == []
    text = W7.format(between="G0 X5.").replace("N26 IF [#1 EQ 0] GOTO 39", "N26 G0 X#1")
    assert [f for f in _found(text, profile) if f.rule == "TG141"] == []


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
def test_a_parameter_changed_on_another_way_in_is_not_known(profile):
    """`N20 #1=5` between may be another way into N26 (a jump may name N20): #1 is not
    known at the target, X#1 is TG141 there (line 8, column 8), as before."""
    text = W7.format(between="N20 #1=5").replace("N26 IF [#1 EQ 0] GOTO 39", "N26 G0 X#1")
    found = _found(text, profile)
    assert [(f.line, f.column) for f in found if f.rule == "TG141"] == [(8, 8)]
    assert [f for f in found if f.severity == "error"] == []


# review 53, F2 (g2g.nc): line 7 is the target `N10 G1 Z-1.`
G2G = ("%\nO1000\nG21 G17 G90 G54\nM3 S1000\nG0 X0 Y0 Z10.\nGOTO 10\n{between}\n"
       "N10 G1 Z-1.{target}\nX50.\nM30\n%\n")


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("between", ["G0 X5.", "N5 F100.", "N5 G1 X1. F100.", "G1 X1. F100."])
def test_a_sure_goto_from_no_feed_arrives_with_none(profile, between):
    """No F was ever given before the sure `GOTO 10`: its target runs first with none, so
    the feed moves there are TG401, as without the jump -- an F in a block between, passed
    over or not run before the target's first run, does not count."""
    found = _found(G2G.format(between=between, target=""), profile)
    assert [(f.line, f.column) for f in found if f.rule == "TG401"] == [(8, 8), (9, 1)]


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
def test_a_feed_at_the_target_or_before_the_jump_is_in_force(profile):
    """Quiet: the target gives its F, or an F came before the jump."""
    found = _found(G2G.format(between="N5 F100.", target=" F50."), profile)
    assert [f for f in found if f.rule == "TG401"] == []
    text = G2G.format(between="N5 G0 X5.", target="").replace("Z10.\nGOTO", "Z10. F50.\nGOTO")
    assert [f for f in _found(text, profile) if f.rule == "TG401"] == []
