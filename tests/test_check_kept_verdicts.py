"""The check keeps verdicts by key to save work: a word's format verdict by the word's shape
(rules TG201-TG205, TG208), a block's address rules by its sequence of addresses, a block's
codes' meanings by its shape (docs/architecture.md, "Verdicts kept by key"). A key that misses
an input hides a finding in a release build, whose assertions do not ask the rules of a kept
word again. These tests hold the findings of a run that keeps verdicts to those of a run that
keeps none (``_core.Checker.keep_verdicts(False)``: every rule asked of every word and block),
on random small programs of each family whose blocks come back to the same words in another
modal state: units, feed mode, a macro call, a canned cycle, a data-setting block, a lathe's
diameter mode, a skipped block, a statement, a subprogram's end."""

from __future__ import annotations

import functools

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from formats.profile import Profile, load_profile
from postproc.check import Checker
from tests.conftest import timeout_for_work

# per profile: groups of blocks that change what a word means or how it is read (each group
# the alternatives of one mode, a program toggling between them), and its language's
# statements and calls
MODES: dict[str, list[list[str]]] = {
    "fanuc-mill": [["G20", "G21"], ["G93", "G94", "G95"], ["G17", "G18", "G19"],
                   ["G65 P9001", "G66 P9001", "G67"], ["G10 L2 P1", "G10 L11 P1", "G11"],
                   ["G68 X0 Y0", "G69"], ["G51 X0 Y0", "G50"],
                   # G51.1/G50.1 X: the mirror's axis, no move, where G51 X is a centre
                   ["G51.1 X0", "G50.1 X0", "G51 X0 Y0 P2."],
                   ["G81 Z-1. R1.", "G83 Z-1. R1.", "G80"], ["G05.1", "G04", "G43 H1", "G28"],
                   ["M98 P100", "M99", "M3", "M6", "N10"],
                   ["#1 = 1.5", "IF [#1 GT 0] GOTO 10", "WHILE [#1 LT 3] DO1", "END1"]],
    "haas-mill": [["G20", "G21"], ["G93", "G94"], ["G187 P1", "G103 P1", "G04"],
                  ["G65 P9001", "M97 P100", "M99", "N100"], ["G81 Z-1. R1.", "G80"],
                  ["G17", "G18"], ["#1 = 1.5"]],
    "fanuc-lathe": [["G20", "G21"], ["G98", "G99"], ["G50 S2000", "G04"],
                    ["G71 U2. R0.5", "G71 P100 Q200", "G70 P100 Q200", "N100", "N200"],
                    ["G32 Z-1. F1.5", "G92 X19. Z-1. F1.5", "G76 P010060", "G80"],
                    ["G83 Z-1. R1.", "G80"], ["G65 P9001", "M98 P100", "M99", "#1 = 1.5"]],
    "haas-lathe": [["G20", "G21"], ["G98", "G99"], ["G71 P100 Q200", "N100", "N200"],
                   ["G76 K1.", "G32 Z-1. F1.5", "G04", "G80"], ["M97 P100", "M99"]],
    "linuxcnc": [["G20", "G21", "g20", "g21"], ["G93", "G94", "G95"], ["G7", "G8"],
                 ["G17", "G18"], ["G10 L2 P1", "G10 L20 P1", "G10 L1 P1", "G4"],
                 ["G81 Z-1. R1.", "G76 Z-1.", "G80"], ["G64", "M100"],
                 ["o100 sub", "o100 endsub", "o100 call [1.5]", "#1 = 1.5"]],
    "sinumerik-840d": [["G70", "G71", "G700", "G710"], ["G94", "G95"], ["DIAMON", "DIAMOF"],
                       ["G17", "G18"], ["L100", "M17", "TRANS X1"],
                       ["R1=5", "G1 X=R1+5", "G2 X1. Y1."]],
    "heidenhain-iso": [["G70", "G71"], ["G17", "G18", "G94"], ["%SUB"]],
    "okuma-mill": [["G20", "G21"], ["G94", "G95"], ["G17", "G18"], ["G81 Z-1. R1.", "G80"],
                   ["G11 X0 Y0 R90.", "G10", "G62 X0", "G69", "G68"],
                   ["VC1 = 1.5", "CALL O100"]],
    "iso-mill": [["G70", "G71"], ["G93", "G94", "G95"], ["G17", "G18"],
                 ["G81 Z-1. R1.", "G80"]],
    "pm322-eia": [["G70", "G71"], ["G81 Z-1. R1.", "G80"]],
    "cm332-quadrant": [["G70", "G71"], ["G93", "G94"], ["G17", "G18"]],
}
PROFILES = sorted(MODES)

# the words' addresses and signs; their numbers are drawn digit by digit (number())
LETTERS = "XYZIJKUWRQPFSTHDABCELN"
SIGNS = ["", "-", "+"]
MOTIONS = ["G0", "G1", "G2", "G3", "G4", "G32", "M3", "M98", "T1"]


@st.composite
def number(draw: st.DrawFn) -> str:
    """A number of up to six whole digits and five decimals, leading and trailing zeros,
    with or without a point: the shapes the digit rules compare, within and past formats."""
    whole = draw(st.text("0123456789", max_size=6))
    if not draw(st.booleans()):
        return whole or "0"
    return whole + "." + draw(st.text("0123456789", max_size=5))


def block(letters: list[str], numbers: list[str]) -> st.SearchStrategy[str]:
    """A block of words of a few letters and numbers (the program's pools: a few dozen
    shapes come back as in a CAM program), perhaps a code before them and a '/' before all."""
    word = st.tuples(st.sampled_from(letters), st.sampled_from(SIGNS), st.sampled_from(numbers),
                     st.integers(0, 9)).map(
        lambda w: ("," if w[0] in "CR" and w[3] == 0 else "")
        + (w[0].lower() if w[3] == 1 else w[0]) + w[1] + w[2])
    return st.tuples(st.integers(0, 7), st.none() | st.sampled_from(MOTIONS),
                     st.lists(word, min_size=1, max_size=4,
                              unique_by=lambda w: w.lstrip(",")[0].upper())).map(
        lambda b: ("/" if b[0] == 0 else "") + " ".join(([b[1]] if b[1] else []) + b[2]))


@st.composite
def program(draw: st.DrawFn) -> tuple[str, str]:
    """A profile and a program of a few blocks met again and again, between them blocks that
    set a mode or a statement of the profile's language."""
    profile = draw(st.sampled_from(PROFILES))
    # one or two of the profile's modes, toggled again and again: a key that misses one
    # meets a word kept in the other soon
    groups = draw(st.lists(st.sampled_from(MODES[profile]), min_size=1, max_size=2))
    modes = [mode for group in groups for mode in group]
    # mostly axes and the feed, whose formats change with the units and the feed mode
    letters = draw(st.lists(st.sampled_from("XYZF") | st.sampled_from(LETTERS), min_size=1,
                            max_size=4, unique=True))
    numbers = draw(st.lists(number(), min_size=1, max_size=3, unique=True))
    shapes = draw(st.lists(block(letters, numbers), min_size=1, max_size=3))
    lines = []
    for _ in range(draw(st.integers(4, 16))):
        choice = draw(st.integers(0, 2))
        if choice == 0:
            lines.append(draw(st.sampled_from(modes)))
        elif choice == 1:
            # a mode and a shape met before in one block: the block's own code reads its words
            lines.append(draw(st.sampled_from(modes)) + " " + draw(st.sampled_from(shapes)))
        else:
            lines.append(draw(st.sampled_from(shapes)))
    head = {"heidenhain-iso": "%TEST G71 *", "okuma-mill": "$TEST.MIN%",
            "linuxcnc": "", "sinumerik-840d": ""}.get(profile, "%\nO1000")
    end = {"heidenhain-iso": "%TEST G71 *", "okuma-mill": "M2\n%",
           "linuxcnc": "M2", "sinumerik-840d": "M30"}.get(profile, "M30\n%")
    body = "\n".join(lines)
    if profile == "heidenhain-iso":
        body = "\n".join(line + " *" for line in lines)
    return profile, "\n".join(x for x in (head, body, end) if x) + "\n"


@functools.cache
def built_in(name: str) -> Profile:
    """A built-in profile, loaded once (each run has a fresh checker of its own)."""
    return load_profile(name)


def findings(text: str, profile_name: str, keep: bool) -> list[tuple[str, int, int, str]]:
    profile = built_in(profile_name)
    checker = Checker(profile, "<generated>")
    checker._core.keep_verdicts(keep)
    return [(f.rule, f.line, f.column, f.message)
            for f in checker.run_stream([text], profile.dialect)]


@timeout_for_work(17)  # measured: the 1,500 examples take 17 s of CPU alone
@settings(max_examples=1500, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program())
def test_kept_verdicts_find_what_the_rules_asked_afresh_find(case: tuple[str, str]) -> None:
    profile, text = case
    assert findings(text, profile, True) == findings(text, profile, False)


def test_a_word_met_again_in_other_units_has_its_own_verdict() -> None:
    """X1.2345 holds one decimal too many for a FANUC mill's metric format and none for its
    inch format: its verdict in G21, then G20, then G21 again is a finding, none, a finding,
    with verdicts kept or not (a key without the block's units would keep the inch verdict)."""
    text = "%\nO1000\nG21\nG1 X1.2345 F100.\nG20\nG1 X1.2345 F10.\nG21\nG1 X1.2345 F100.\nM30\n%\n"
    for keep in (True, False):
        past = [f for f in findings(text, "fanuc-mill", keep) if f[0] == "TG208"]
        assert [f[1] for f in past] == [4, 8], keep



def cycles_twice(first: str, second: str, *, lathe: bool = False) -> str:
    """A program that drills with `first`, then with `second`: two canned cycle blocks whose
    words have the same shapes, so the second's are read from the first's kept verdicts."""
    if lathe:
        head = "G21 G18 G40 G80 G97\nG54 G00 X0 Z5. S500 M03"
        return f"%\nO2014\n{head}\n{first}\nG80\nG00 X0 Z5.\n{second}\nG80\nM30\n%\n"
    head = "G21 G17 G40 G80 G90\nG54 G00 X0 Y0 S2000 M03\nG43 H01 Z5."
    return f"%\nO2014\n{head}\n{first}\nG90 G80\n{second}\nG90 G80\nM30\n%\n"


def by_rule(found: list[tuple[str, int, int, str]], rule: str) -> list[tuple[int, int]]:
    return [(f[1], f[2]) for f in found if f[0] == rule]


@pytest.mark.parametrize("k", ["K3", "K03", "K3."])
@pytest.mark.parametrize("cycle", ["G81", "G73 Q1.", "G83 Q1."])
def test_a_fanuc_cycle_s_repeat_count_met_again_is_a_count(cycle: str, k: str) -> None:
    """Review 54, F1: a FANUC mill's K is the cycle's number of repeats (0i-MF, "Canned
    cycle"), written without a point as a count. The second of two cycle blocks whose K has
    the first's shape read it from the kept verdict in the letter's least increments
    (K3 as 0.003): a false TG544, and the holes after it not followed, so a real TG601 was
    lost. Three holes 10 apart, then three 500 apart: X ends at 1530, past the 1524 travel."""
    first = f"G91 G99 {cycle} X10. Z-5. R-3. {k} F100."
    text = cycles_twice(first, first.replace("X10.", "X500."))
    for keep in (True, False):
        found = findings(text, "fanuc-mill", keep)
        assert by_rule(found, "TG544") == [], keep
        travel = [f for f in found if f[0] == "TG601"]
        assert [(f[1], f[2]) for f in travel] == [(8, 10 + len(cycle))], keep
        assert "X spans 1530 (from 0 to 1530)" in travel[0][3]


def test_identical_cycle_blocks_read_alike() -> None:
    """The reproducer of review 54 F1 (the same row of holes drilled twice: the same block
    twice) and a count that is none (K2 then K2.5): clean, then TG544 at the second only."""
    block = "G91 G99 G81 X10. Z-5. R-3. K3 F100."
    text = cycles_twice(block, "G00 X0 Y20.\n" + block)
    assert by_rule(findings(text, "fanuc-mill", True), "TG544") == []
    text = cycles_twice("G91 G73 X100. Z-25. R-8. Q1. K2 F120.",
                        "G91 G73 X50. Z-20. R-5. Q1. K2.5 F60.")
    assert by_rule(findings(text, "fanuc-mill", True), "TG544") == [(8, 29)]


def test_a_haas_count_is_l_and_its_peck_k_a_length() -> None:
    """A Haas mill counts holes with L (mill operator's manual, G81-G89: "L number of holes"),
    which is met again as a count; its K under G83 is the least peck depth, a length (review
    51 F15): K3 without a point is 0.003 in both blocks, with no TG544."""
    first = "G91 G99 G81 X10. Z-5. R-3. L3 F100."
    text = cycles_twice(first, first.replace("X10.", "X500."))
    found = findings(text, "haas-mill", True)
    assert by_rule(found, "TG544") == []
    assert by_rule(found, "TG601") == [(8, 13)]
    first = "G91 G99 G83 X10. Z-5. R-3. Q1. K3 F100."
    text = cycles_twice(first, first)
    for keep in (True, False):
        found = findings(text, "haas-mill", keep)
        assert by_rule(found, "TG544") == [], keep
        mixed = [f for f in found if f[0] == "TG201"]
        assert [(f[1], f[2]) for f in mixed] == [(6, 32)], keep
        assert "as 0.003" in mixed[0][3]


@pytest.mark.parametrize("profile", ["fanuc-lathe", "fanuc-lathe-c"])
def test_a_fanuc_lathe_s_drilling_count_met_again_is_a_count(profile: str) -> None:
    """A FANUC lathe's G83 takes K as its repeats too: met again, K3 and K03 are counts (no
    TG544); K0 is none, in both blocks, kept or not."""
    for k, expected in (("K3", []), ("K03", []), ("K0", [(5, 22), (8, 22)])):
        block = f"G83 Z-10. R-3. Q2000 {k} F0.1"
        text = cycles_twice(block, block, lathe=True)
        for keep in (True, False):
            assert by_rule(findings(text, profile, keep), "TG544") == expected, (k, keep)
