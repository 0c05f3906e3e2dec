"""Seeded faults against LinuxCNC's interpreter: where rs274 (linuxcnc-uspace) stops, tapegate
reports an error on the same line, on the ``linuxcnc`` profile; a clean program is clean for both.

The programs and the comparison are benchmarks/rs274_compare.py's (run it for the whole
measure: LinuxCNC's samples, the corpus and the arc tolerance). Skipped without rs274.
"""

from __future__ import annotations

import importlib.util
import re
import shutil
import sys
from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[1] / "benchmarks" / "rs274_compare.py"


def _load():
    spec = importlib.util.spec_from_file_location("rs274_compare", SCRIPT)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["rs274_compare"] = module  # dataclasses look their module up
    spec.loader.exec_module(module)
    return module


compare = _load()

pytestmark = pytest.mark.skipif(
    shutil.which("rs274") is None or compare.tapegate_exe() is None,
    reason="LinuxCNC's rs274 (Debian linuxcnc-uspace) or the tapegate command is absent")

# Faults both report on the line of the fault (docs/check.md, "Compared with LinuxCNC's
# interpreter").
BOTH = [
    "arc radius mismatch",
    "arc centre missing",
    # review 55c, F2: whatever the plane, one the checker does not know too
    "arc centre missing after an if of an unknown condition setting G18",
    # review 55c, F5: after a call of a body that writes only the caller's plane (TG404)
    "J centre after a call whose body sets the caller's G18",
    "two G codes of the motion group",
    "two G codes of the distance group",
    "feed motion without feed",
    # F0 is no feed either (TG401): "Cannot do g1 / make arc with zero feed rate"
    "feed motion at F0",
    # review 55c, F7: a loop's next turn takes the else after a branch with a call
    "J centre in the else of an if with a call, on a while's second turn",
    "arc at F0",
    "G81 without Z",
    "G81 without R",
    "M00 and M30 in one block",
    "two M codes of the coolant group",
    "arc centre outside the plane (K in G17)",
    "unknown G code G130",
    "axis words before any motion code",
    "axis words after G80",
    # the move just after G40 must be straight (TG501 on the linuxcnc profile)
    "cutter compensation ended on an arc",
    "arc as the first move after G40",
    # every G93/G94/G95 zeroes rs274's feed rate (TG401)
    "G1 after a G94 restated, without F",
    # TG412 too, but rs274's message names its file and line first (test below)
    "sub defined after its call",
    # review 48 (lcnc49), TG412 with rs274's message after its file and line, or its line
    # number (test below): a label kept for the whole program used again (F19), a closing
    # label read with the values its block set (F10), G91 restored by M73 at a return (F16)
    "sub defined twice", "sub defined twice by a computed label", "if label used twice",
    "if label used twice, the first a parameter's value", "while label of an if before",
    "repeat label of a do before", "endif label changed inside its block",
    "endif label of a parameter kept",
    # review 49a, F2 and F8: a condition of comparisons runs its block, a repeat of 1.5 runs;
    # a closing word of a label no line named (rs274 names the line number first)
    "endif label changed in an if of a comparison",
    "endwhile label changed in a loop of a comparison",
    "endrepeat label changed in a repeat of 1.5",
    "endif with no if", "endif of another label in an if that runs",
    # review 49a, F3: the file ends in the skip of a block not run (TG114)
    "endif of another label in an if not run", "endrepeat of another label in a repeat of 0",
    # a cycle drills along the plane's axis (TG541, every family's rule)
    "G18 cycle without Y",
    # review 56c (lcnc57): the rate M72 restores zero (TG401)
    "G1 after M72 restores G94 from G93 at the same rate",
    "G1 beside an M72 with nothing to restore",
    "G1 after M72 restores G94 from a G93 move at the same rate",
    # review 57d, F6 (lcnc57b): ` F%.1f` writes the saved F0.04 as F0.0
    "G1 after M72 restores F0.04 written F0.0",
    # review 57d, F1 (lcnc57b): the dropped M72 G1 leaves the tool where it was
    "arc from where a dropped M72 G1 found the tool, radius differs",
    # review 57d, F2, F4 (lcnc58): what every save agrees on after an M72 not followed; an
    # M5 after the M72 stops the spindle it restored
    "G1 in G95 after M72 restores the S0 of an M70 in an if",
    "G1 after an M72 in an if, G93 whether it runs or not", "G33 after M72 and M5",
    # review 58c, F3, F5 (lcnc58b): the M72 block's late codes, a followed M72
    "G1 beside an M72 whose block's G18 runs after it",
    "G1 beside a second M72 after a followed one",
    # TG412: rs274's own refusals
    # review 58c, F1 (lcnc58b): a followed save gives back the spindle and compensation
    "G33 after M70 and M72, the spindle never on", "cycle after M72 restores G41.1",
    # review 53, F13 (lcnc57b): the move after G18.1 under compensation
    "G1 in G18.1 under compensation with no move before",
    # review 55c, F9 (lcnc57b): a branch left by break is no way to its endif
    "R arc after an if whose branch breaks in G19, in G18",
    # lcnc51: a definition read again on a loop's second turn
    "a definition in a repeat [2]", "a definition in a repeat [2], called",
    "a definition in a do with a true while",
    "G53 under G2",
    # review 49a, F8: an o-word only at the start of its line
    "o-word after a comment", "o-word after a word", "words after an o-word",
    "G53 after a sub whose M73 restores G91",
    "G53 after a sub whose G90 follows its return",
    "G83 without Q",
    "G73 without Q",
    "G83 with Q0",
    "G83 repeated with Q0",
    "G82 without P",
    "G82 with P-1",
    "cycle repeated with Z above R",
    "T not whole",
    "H not whole",
    "G41 D not whole",
    "G87 without I",
    "cycle with L0",
    "cycle with R below Z",
    "cycle without feed",
    "cycle under cutter compensation",
    "G74 with M3",
    "G84 with M4",
    "G84 with the spindle stopped",
    "G86 with the spindle stopped",
    "G76 without I J K (a Fanuc boring block)",
    "G76 without P",
    "G70 without Q",
    "G71.1 without Q",
    "G42.1 with L in G17",
    "G41.1 without D",
    "a % line in a file not begun with %",
    "% and a comment as the first line",
    "a closing % with a comment",
    "T 0.00011 from a whole number",
    "cycle after a G95, without F",
    "G76 with J0",
    "G76 with K not beyond J",
    "cycle in G18 repeated with R below Y",
    "E word with no code to use it",
    "H word with no G43 or G76",
    "P word with no code to use it",
    "arc with P0",
    "G4 P-1 (rs274's no P)",
    "G10 L2 P10",
    "G33 with the spindle stopped",
    "G33 after a tool change",
    "UTF-8 byte order mark",
    # review 15, findings 5 and 8
    "probe after G94 without F",
    "cycle under G93",
    "probe ending where it starts",
    "M code from an expression",
    "division by zero",
    "M66 with P and E",
    "M3 beside M70",
    "NURBS point without its weight",
    "named parameter read before it is set",
    "R arc after G43 H1 ending where it starts",
    "R arc after G92 ending where it starts",
    # o-word labels read_o reads (lcnc48): a fraction, and an endif closed by its value
    "o-word label with a fraction",
    "endif label of a parameter's value",
    # review 48 (fixl48): a fraction on any o-word; an M word reads the value before its line
    "if label with a fraction", "sub label with a fraction",
    "M of a parameter set on its line (old 5)",
    # review 50: G53 in G91 and M72 with nothing saved, wherever the line runs
    "G53 after a sub whose nested call leaves G91 before its return",
    "G53 after a G91 in its own branch", "G53 after a G91 in a condition equal to the mode",
    "G53 after a G91 in a do body", "G53 in a body after its own G91",
    "G53 in a body defined in G90 called in G91", "M72 with nothing saved",
    "M72 in a body with nothing saved there", "G53 after a sub with a dead G91 after its return",
    "G53 after a call written in a definition", "G53 and M72 in one block",
    # lcnc51: the lines of a block known to run, judged in the state the program left; X
    # alone unsettled by G7; codes run under cutter radius compensation
    "a P word in a known-true if", "M[3.5] after an unclosed known-true if",
    "a probe in place in a repeat", "a probe in place in a while's first turn",
    "a Z probe in place after G7", "G43 under compensation", "G55 under compensation",
    "G10 L2 P0 under compensation", "G40 M66 under compensation", "M6 under compensation",
    "G41.1 in G19", "G92 under compensation",
    # comp52 (review 52, F3): a change of plane, the splines, G28.1/G30.1
    "G18 under compensation begun in G17", "G18 G40 under compensation",
    "G17 under compensation begun in G18", "G5 under compensation", "G5.1 under compensation",
    "G28.1 under compensation", "G30.1 under compensation",
    # lspl53 (review 53, F12): splines outside G17, arcs in G17.1-G19.1
    "G5 in G18", "G5.1 in G17.1", "G2 in G18.1", "G2 in force run in G19.1",
    # review 54, F4: a spline's feed, before its plane
    "G5 without a feed rate", "G5.1 at F0", "G5.1 in G93 without F",
    "G5 in G93 and G18 without F",
    # plane55 (review 54, F2): a plane known where every way through an if leaves it
    "arc after an if and else both setting G18.1", "spline after an if that sets no plane, in G18",
    "spline after a known-false if setting G17, in G18",
    "arc in the else of an if setting G17, begun in G18.1",
    "arc in G18.1 after a definition setting G17", "G41.1 in G19 after an if that sets no plane",
    "spline in G18 after a call whose body sets no plane",
    # review 53, F7: compensation turned on in a plane of U V W
    "G41.1 in G17.1", "G42.1 in G18.1", "G41.1 beside G17.1",
    # review 55c, F8: a known branch before an elseif; F2: the plane-free arc checks where
    # the plane is not known
    "R arc after a known if before an elseif, setting G18",
    "R arc after a plane chooser of a known parameter, G18",
    "mixed R and I after a call whose body sets G18", "mixed R and I in a definition's body",
    # review 55c, F6: M72 restores the plane M70 saved
    "R arc after M72 restores G18",
    # review 56c (lcnc57): M72 restores the feed mode, rate and speed M70 saved
    "spline after M72 restores G94 from G95 at the same rate",
    "spline without F after M72 restores G93", "G1 in G95 after M72 restores S0",
]
# programs rs274 runs that tapegate once refused: within its integer tolerance, after a call
# whose body (not followed) sets the spindle or the compensation, and E words the block uses
RUN = ["T, H and D within 0.0001 of a whole number",
       "G84 after a call that starts the spindle clockwise",
       "cycle after a call that cancels the compensation",
       "E words with G33, G76 and M66-M68",
       # P and H words with the codes that use them; a definition after M2 is never reached
       "P and H words their codes use", "sub defined after its call and M2",
       # G93 keeps rs274's feed rate, which a probe reads (review 15, finding 5)
       "probe after G93 keeps the feed rate",
       # o-word labels read_o reads through read_integer_value, and an endsub closed by its
       # label's value (lcnc48)
       "o-word label with a sign", "o-word label with a point",
       "o-word label a parameter's parameter", "o-word label a function",
       "endsub label of a parameter's value",
       # review 48 (fixl48): a function's label on a definition; an end by the value before
       "sub label a function", "M of a parameter set on its line (old 2)",
       # review 48 (lcnc49): labels rs274 does not count as duplicates, a closing label whose
       # block never ran, a subroutine's G90 in force after its return
       "do label of a do before", "if label in a body and the main program",
       "endwhile label changed in a loop not run", "G53 after a sub that leaves G90",
       # review 49a, F1 and F6: the distance mode not known, or G90 again
       "G53 after a sub whose G91 is in a condition", "G53 after a call in a condition not run",
       "G53 after a sub whose G91 follows a return in a condition",
       "G53 after a sub whose G91 follows its return", "G53 after a G91 in a condition not run",
       "G53 after M72 restores G90",
       # review 49a, F2: a condition known false, a repeat of 0.5 (half to even) skip their
       # block; F8: an o-word after a line number, one rs274 passes over in a condition not
       # run, a closing word of a label recorded before; review 48, c19: a body's M2 ends
       # the program at the call
       "endif label changed in an if of a comparison false",
       "endrepeat label changed in a repeat of 0.5", "o-word after a line number",
       "o-word after a comment in a condition not run", "endif of a label closed before",
       "sub whose body ends with M2", "sub whose body ends with M30, no M2 after its call",
       # review 50: the distance mode followed through nested calls, M73, a body's own mode
       # and its calls, M72 with a G53
       "G53 after a sub whose nested call leaves G90 before its return",
       "G53 after M72 restores what M73 saved", "G53 in a body defined in G91 called in G90",
       "G53 and M72 restoring G91 in one block",
       # lcnc51: an else of a known-true if does not run; a loop of one turn reads its
       # definition once; codes rs274 runs beside G40 or with the compensation off
       "a probe in place in the else of a known-true if", "a definition in a while of one turn",
       "a definition in a repeat [1]", "a definition in a repeat whose call ends the program",
       "G40 G43 under compensation", "G10 L2 P2 under compensation in G54",
       # comp52: G18 in G18 changes no plane; G40 beside a spline runs it uncompensated
       "G18 under compensation begun in G18", "G5 beside G40",
       # lspl53: a NURBS outside G17, an arc after the plane is set again
       "G5.2 in G18 and G2 after G17.1 G17",
       # review 54, F4: G95 checks a spline's feed not; G93 with the block's F
       "G5 in G95 at S0 and G5 in G93 with F",
       # plane55 (review 54, F2): a definition's plane stays in it; a call or an if of an
       # unknown condition leaves the plane unknown
       "uncalled definition's G18.1 before an arc", "uncalled definition's G18 before a spline",
       "uncalled definition's G18 before an R arc of X Y", "arc after a call whose body sets G17",
       "spline after a call whose body sets G17",
       "arc after an if of an unknown condition setting G18.1",
       "spline after an if of an unknown condition setting G18",
       "spline after an if and else setting G17 and G18",
       "spline after a while that sets G17, begun in G18",
       "spline after a while left by a break in G17",
       # review 55c, F6: M72 restores the plane M70 saved
       "spline after M72 restores G17",
       # review 56c, F2, F9: the feed mode an M72 restores is not followed
       "spline under G93 after M72 restores G95",
       "spline under G93 after M72 restores the G95 of a known-true if",
       # review 56c, F3, F5, F7 (lcnc57): the rate M72 restores, its block's motion not run
       # where the restore runs a block, a spline's feed not the G1's in force
       "G1 after M72 restores G94 F100 from G93", "G1 after M72 beside G93 restores G94 F100",
       "G5.1 in G95 after a G1", "G1 beside an M72 that restores G94",
       "spline beside an M72 that restores G94 F100",
       # review 57d, F1; review 53, F13 (lcnc57b)
       "arc from where a dropped M72 G1 found the tool",
       # review 57d, F2-F4 (lcnc58): an M72 not followed, its block's motion, its spindle
       # and compensation
       "G1 in G95 after M72 whose save an if between unfollows",
       "cycle after M72 G95 whose M70 stands in an if", "G1 beside an M72 restoring G17",
       "G1 after M72 of a save in a loop whose later turn runs under G94",
       "G33 after M72 restores M3", "cycle after M72 restores G40",
       # review 58c, F4 (lcnc58b): no zero kept through G20/G21
       "probe after G20 from a cycle's retract level",
       "G18.1 under compensation with no move before its G40",
       "R arc of X after a while left by a break in G19",
       # review 55c, F7: the elseif after a known-true branch with a call never runs
       "J centre in an elseif after a known-true if with a call",
       # review 55c, F3, F4: a G code by an expression, or a parameter not known
       "spline after G[17], in G18", "R arc after G#<p> of #5220+16, in G18"]
# faults of the block delete switch (review 49a, F4): rs274 refuses the line with the switch
# off (-g) or on (-b -g), not both; tapegate reports no error
SWITCH = ["endif label changed by a deleted setting",
          "division by a value a deleted setting gives",
          "division by a value a deleted setting changes"]
# TG412's seeds: tapegate's message begins with rs274's own
REFUSALS = BOTH[BOTH.index("G53 under G2"):]


@pytest.fixture(scope="module")
def seeds(tmp_path_factory):
    return {s.name: s for s in compare.seeded(tmp_path_factory.mktemp("rs274"))}


@pytest.mark.parametrize("name", BOTH)
def test_both_report_the_seeded_fault_on_its_line(seeds, name):
    s = seeds[name]
    assert not s.rs274.ok, "rs274 ran the faulty program"
    assert s.rs274.line == s.line, (s.rs274.message, s.rs274.line)
    assert s.errors, "tapegate reports no error"
    assert s.errors[0].line == s.line, s.errors
    assert s.same


def test_non_modal_codes_after_an_arc_run_for_both(seeds):
    """G28, G30 and G92 take their block's axis words: no arc runs there (no TG404)."""
    s = seeds["G28, G30 and G92 after an arc"]
    assert s.rs274.ok, s.rs274.message
    assert s.errors == []


def test_a_clean_program_is_clean_for_both(seeds):
    s = seeds["clean program"]
    assert s.rs274.ok, s.rs274.message
    assert s.errors == []


def test_both_run_cutter_compensation_started_on_an_arc(seeds):
    """LinuxCNC takes an arc as the entry move; the linuxcnc profile does too (no TG501)."""
    s = seeds["cutter compensation started on an arc"]
    assert s.rs274.ok, s.rs274.message
    assert s.errors == []


@pytest.mark.parametrize("name", REFUSALS)
def test_tg412_says_rs274s_message(seeds, name):
    s = seeds[name]
    first = [e for e in s.errors if e.line == s.line and e.rule == "TG412"]
    assert first, s.errors
    assert first[0].message.startswith(s.rs274.message.strip() + " (rs274ngc)"), (
        first[0].message, s.rs274.message)


def test_tg412_says_rs274s_message_after_its_file_and_line(seeds):
    """rs274 names the file and line of a definition it finds in an illegal location."""
    s = seeds["sub defined after its call"]
    message = re.sub(r"^File:\S+ line:\d+ ", "", s.rs274.message.strip())
    assert message == "sub: o|100| found in illegal location", s.rs274.message
    first = [e for e in s.errors if e.line == s.line and e.rule == "TG412"]
    assert first and first[0].message.startswith(message + " (rs274ngc)"), s.errors


@pytest.mark.parametrize("name", [
    "sub defined twice", "sub defined twice by a computed label", "if label used twice",
    "if label used twice, the first a parameter's value", "while label of an if before",
    "repeat label of a do before", "endif label changed inside its block",
    "endif label changed in an if of a comparison",
    "endwhile label changed in a loop of a comparison",
    "endrepeat label changed in a repeat of 1.5", "endif with no if",
    "endif of another label in an if that runs", "a definition in a repeat [2]",
    "a definition in a repeat [2], called", "a definition in a do with a true while"])
def test_tg412_says_rs274s_o_word_message(seeds, name):
    """rs274 names the file and line of a definition (and the file it is in), or the line
    number, before its o-word refusals: tapegate's message begins with the rest."""
    s = seeds[name]
    message = re.sub(r"^File:\S+ line:\d+ |^\d+: | in file:\S+$", "", s.rs274.message.strip())
    message = re.sub(r" in file:\S+$", "", message)
    first = [e for e in s.errors if e.line == s.line and e.rule == "TG412"]
    assert first, s.errors
    if message.startswith("undefined O-word label"):
        # (rs274 quotes the line after its message; tapegate says why the label is another)
        assert first[0].message.startswith("undefined O-word label (rs274ngc)"), first[0]
    else:
        assert first[0].message.startswith(message + " (rs274ngc)"), (first[0].message, message)


@pytest.mark.parametrize("name", ["a repeated cycle keeps its Z, R and Q", "G76 threading"])
def test_cycles_rs274_runs_are_clean(seeds, name):
    """A cycle repeated keeps the Z, R, Q of its first block; G74 under M4 taps; a G76 thread
    with P I J K runs."""
    s = seeds[name]
    assert s.rs274.ok, s.rs274.message
    assert s.errors == []


def test_every_seed_is_named_here(seeds):
    named = {"cutter compensation started on an arc", "clean program",
             "G28, G30 and G92 after an arc", "a repeated cycle keeps its Z, R and Q",
             "G76 threading"}
    assert set(seeds) == set(BOTH) | named | set(RUN) | set(SWITCH)


@pytest.mark.parametrize("name", SWITCH)
def test_a_fault_of_the_block_delete_switch_is_no_error(seeds, name):
    s = seeds[name]
    assert s.rs274_deleting is not None
    refused = [r for r in (s.rs274, s.rs274_deleting) if not r.ok]
    assert [r.line for r in refused] == [s.line], (s.rs274, s.rs274_deleting)
    assert s.errors == []
    assert s.same


@pytest.mark.parametrize("name", RUN)
def test_programs_rs274_runs_have_no_error(seeds, name):
    s = seeds[name]
    assert s.rs274.ok, s.rs274.message
    assert s.errors == []


def test_the_arc_tolerances_are_rs274s_at_every_point(tmp_path):
    """Bisected against rs274: the I J radius difference (0.0282843 mm, 0.1 % of the radius,
    capped) and how far half the chord of an R arc may pass its radius (0.00127 mm, 0.00005
    in). tapegate accepts 0.5 % inside each limit and refuses 0.5 % outside."""
    for point in compare.arcs(tmp_path):
        assert point.tapegate_inside and point.tapegate_outside, point


# -- the sweep's one-form variants (benchmarks/rs274_sweep.py) ---------------------------------

def _load_sweep():
    spec = importlib.util.spec_from_file_location(
        "rs274_sweep", SCRIPT.parent / "rs274_sweep.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["rs274_sweep"] = module
    spec.loader.exec_module(module)
    return module


# Where the linuxcnc profile and rs274 still differ on a variant, and why (docs/dialects.md,
# LinuxCNC, "Not read" and the sweep's list in docs/benchmarks.md):
DIFFERENT = {
    # blanks inside a function's or an operator's name (`S IN[30]`): rs274 drops them, the
    # expression reader of the profile does not read them so
    "blank inside a function name": "tapegate refuses",
    # a call of a subroutine the file does not define is taken for one of the configuration's
    # subroutine path; rs274 alone has none
    "subroutine after the closing %": "rs274 refuses",
    # an M2 in a branch, or after a block skip `/`, may not run: the profile reads on (and
    # finds the bad line after it); rs274 ran the branch and the switch was off
    "M2 inside an if": "tapegate refuses",
    "M2 after block delete": "tapegate refuses",
}


def test_the_variants_read_as_rs274_reads_them(tmp_path):
    sweep = _load_sweep()
    rows = sweep.sweep(sweep.variant_files(tmp_path), tmp_path)
    assert len(rows) == len(sweep.VARIANTS)
    verdicts = {r.name: r.verdict for r in rows}
    differ = {n: v for n, v in verdicts.items() if v not in ("both read", "both refuse")}
    assert differ == DIFFERENT
    # the forms this work made the profile read as rs274 does
    for name in ("blank inside a parameter number", "text after M30", "subroutine after M2",
                 "text after the closing %", "two signs", "a function as a word's value"):
        assert verdicts[name] == "both read", name
    # `X1e3` is X1 and E3, an E word without G70, G76, M66-M68: TG412 on both sides
    for name in ("a line number after a word", "a Fanuc function", "exponent"):
        assert verdicts[name] == "both refuse", name
