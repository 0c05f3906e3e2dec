"""The checker fed text (the core reads whole lines a chunk at a time) against the checker fed
Block objects (as the Python API hands them over).

The rules exist once, in the core; these tests hold the two ways into it to each other. Random
programs mix runs of plain blocks with blocks that change the modal state, comments, bad words,
repeated words, signs and implicit-looking numbers; both must give the same findings in the same
order and the same statistics, whatever the chunk size.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from formats.parser import parse_stream
from formats.profile import load_profile, profile_from_text
from postproc.check import Checker
from tests import words as shared
from tests.conftest import timeout_for_work

ABSOLUTE = profile_from_text(
    'name = "absolute-ijk"\n'
    'detailed = "%:/DS O04 N04 G02 X+043 Y+043 Z+043 I+043 J+043 K+043 F041 S04 T02 M02*"\n'
    'units_codes = "G70/G71"\n'
    '[limits]\nX = [-50, 50]\nY = [0, 120.5]\nfeed_max = 500\n'
    '[checks]\nijk = "absolute"\narc_tolerance = 0.01\narc_tolerance_relative = 0\n'
    '[serial]\ntv_check = true\n')
PROFILES = [load_profile("fanuc-mill"), load_profile("iso-mill"), load_profile("sinumerik-7e2"),
            load_profile("cm332-quadrant"), ABSOLUTE]


def plain_word() -> st.SearchStrategy[str]:
    wholes = ["", "0", "1", "12", "45", "123", "761", "763", "0012", "99999", "100000"]
    return shared.plain_word("XYZIJKFXYXY", wholes, ["", "", "", "-", "+"])


@st.composite
def arc(draw: st.DrawFn) -> str:
    """A G02/G03 block whose end point is on the circle (from X0 Y0 when nothing else is
    known), or nearly so: radii equal within rounding, or off by about the tolerance."""
    r = draw(st.floats(0.5, 80))
    a0, a1 = draw(st.floats(0, 6.28)), draw(st.floats(0, 6.28))
    miss = draw(st.sampled_from([0.0, 0.0, 0.027, 0.0285, 0.5]))
    cx, cy = -r * math.cos(a0), -r * math.sin(a0)
    ex, ey = cx + (r + miss) * math.cos(a1), cy + (r + miss) * math.sin(a1)
    g = draw(st.sampled_from(["G02 ", "G03 ", "G2 ", ""]))
    return f"N1 G90 X0 Y0\n{g}X{ex:.3f} Y{ey:.3f} I{cx:.3f} J{cy:.3f}"


@st.composite
def line(draw: st.DrawFn) -> str:
    kind = draw(st.integers(0, 12))
    if kind == 2 and draw(st.booleans()):  # comments: the arrays blank the plain ones
        comment = draw(st.sampled_from([
            "(TOOL 1)", "(A (B) C)", "(50% FEED)", "(SET: UP)", "(\u00d8 12)", "(\x01)",
            "(OPEN", "CLOSE)", "()", "(a;b)", "(X1.5)"]))
        where = draw(st.sampled_from(["alone", "alone", "after", "between", "glued"]))
        sep = draw(st.sampled_from(["", " ", "  ", "\t"]))
        if where == "alone":
            return sep + comment + draw(st.sampled_from(["", " ", "\r"]))
        if where == "after":
            return "N3 G01 X1.5 Y2" + sep + comment
        if where == "between":
            return "N3 G01 X1.5" + sep + comment + sep + "Y2"
        return draw(st.sampled_from(["X", "X1", "X1.", "G0", "N4 Y"])) + comment + "5"
    if kind == 0:
        return draw(st.sampled_from([
            "G91", "G90", "G93 G01 X1 F2", "G94", "G95 F.2", "G20", "G21", "G70", "G71", "G17",
            "G18", "G19", "G04 X1.5", "(NOTE)", "", "N7 G92 X0 Y0", "G96 S200", "G97 S1000",
            "%", "M30", "M02", "X1.2.3", "G28 X0", "G81 Z-5. R1.", "G80", "T3 M06", "G41 D1",
            "G40", "x12.5", "/N5 X1", "N5 G06 X1", "G01 R5. X3", "G33 Z-10. K1.5",
            "N1 G01 X2 (C) Y3", "O1234", "N8 X1 Y2 ; semi", "X#1", "G05 X1"]))
    if kind == 1:
        return draw(arc())
    words = draw(st.lists(plain_word(), min_size=0, max_size=5))
    if draw(st.booleans()):
        words.insert(0, draw(st.sampled_from(["G00", "G01", "G02", "G03", "G1", "G0", "G2"])))
    if draw(st.booleans()):
        words.insert(0, f"N{draw(st.sampled_from(['1', '05', '9999', '99999', '123456']))}")
    if draw(st.integers(0, 9)) == 0:
        words.reverse()
    sep = draw(st.sampled_from([" ", " ", " ", "", "\t", "  "]))
    end = draw(st.sampled_from(["", "", "", "\r", " "]))
    return sep.join(words) + end


@st.composite
def program(draw: st.DrawFn) -> str:
    head = draw(st.sampled_from(["%\n", "%\nO1000\n", "%\nN1 G21 G17 G90 G94 G01 F100\n", "",
                                 "%\nG90 G00 X0 Y0 Z0\n"]))
    body = "\n".join(draw(st.lists(line(), min_size=0, max_size=40)))
    tail = draw(st.sampled_from(["\nM30\n%\n", "\n", "", "\nM30\n"]))
    return head + body + tail


def both(text: str, profile_index: int, chunk: int) -> tuple[Checker, list, Checker, list]:
    profile = PROFILES[profile_index]
    reference = Checker(profile, "p.nc")
    expected = list(reference.run(parse_stream([text], profile.dialect, file="p.nc",
                                               errors="collect")))
    fast = Checker(profile, "p.nc")
    chunks = [text[i:i + chunk] for i in range(0, len(text), chunk)] or [""]
    found = list(fast.run_stream(chunks, profile.dialect))
    return reference, expected, fast, found


@timeout_for_work(3.6)  # measured: the 400 examples take 3.6 s of CPU alone
@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(program(), st.integers(0, len(PROFILES) - 1), st.sampled_from([5, 64, 1 << 20]))
def test_text_and_blocks_give_the_same_findings(text: str, which: int, chunk: int) -> None:
    reference, expected, fast, found = both(text, which, chunk)
    assert found == expected
    a, b = reference.stats, fast.stats
    assert (b.blocks, b.low, b.high, b.tools) == (a.blocks, a.low, a.high, a.tools)
    for name in ("rapid_length", "feed_length", "seconds"):
        assert math.isclose(getattr(b, name), getattr(a, name), rel_tol=1e-9, abs_tol=1e-9)


def test_a_long_run_of_plain_blocks() -> None:
    """A long run of plain blocks: the same findings from text as from blocks."""
    lines = ["%", "N1 G71", "N2 G01 X-520 F100"]
    lines += [f"N{i} X{i}.5 Y-{i}.25" for i in range(3, 503)]
    lines += ["M30", "%"]
    _, expected, _, found = both("\n".join(lines) + "\n", 1, 1 << 20)  # iso-mill
    assert found == expected
    # X spans -520 to 502.5, wider than iso-mill's travel of 1000: said once, where it happens
    assert [(f.rule, f.line) for f in found] == [("TG601", 481)]


def test_comments_count_for_the_tv_check() -> None:
    """Comments, on a line of their own or after the words: their characters count for the TV
    check."""
    lines = ["%", "N1 G21", "N2 G01 F100"]
    for i in range(3, 203):
        lines.append(f"N{i} X{i}.5 Y-1.25 (PASS {i})" if i % 10 else "(ROUGH)")
    lines += ["M30", "%"]
    _, expected, _, found = both("\n".join(lines) + "\n", 0, 1 << 20)  # fanuc-mill: TV
    assert found == expected
    odd = [n + 1 for n, t in enumerate(lines) if len(t) % 2 and t != "%"]
    assert 10 in odd  # "N9 X9.5 Y-1.25 (PASS 9)": 23 characters, the comment's included
    assert 11 in odd  # "(ROUGH)": 7
    assert 12 not in odd  # "N11 X11.5 Y-1.25 (PASS 11)": 26
    # said once per file, with the count and the first odd block
    tv = [f for f in found if f.rule == "TG703"]
    assert [(f.line, f.severity) for f in tv] == [(odd[0], "info")]
    assert tv[0].message.startswith(f"{len(odd)} blocks have an odd number of characters")


def test_repeated_words_signs_and_implicit_numbers_in_a_run() -> None:
    """A repeated word, an unsigned F with a sign, and an implicit-looking number in the middle
    of a run: the same findings as block by block, at the same places."""
    lines = ["%", "O1", "N1 G21 G17 G90 G94 G01 F100"]
    lines += [f"N{i} X{i}.5 Y1." for i in range(2, 40)]
    lines[10] = "N10 X1. X2."
    lines[20] = "N20 X1. F-5."
    lines[30] = "N30 X12500 Y1."
    lines += ["M30", "%"]
    text = "\n".join(lines) + "\n"
    _, expected, _, found = both(text, 0, 1 << 20)
    assert found == expected
    assert {f.rule for f in found} >= {"TG131", "TG204", "TG201"}
    assert [f.line for f in found if f.rule == "TG131"] == [11]


def test_arc_decisions_near_the_tolerance_agree() -> None:
    """Arcs whose radii differ by almost exactly the tolerance."""
    lines = ["%", "N1 G71 G17 G90 G94 G01 F100 X0 Y0"]
    for end in ("10.009", "10.010", "10.011", "10.0100001"):  # the radius is 10
        lines += ["G01 X0 Y10.", f"G02 X{end} Y0 I0 J0"]
    lines += ["M30", "%"]
    text = "\n".join(lines) + "\n"
    _, expected, _, found = both(text, len(PROFILES) - 1, 1 << 20)
    assert found == expected
    # X10.0100001 is past the format X+043 (TG203, the control alarms): its X is not known,
    # and the arc is measured to no end point guessed from the start
    assert [f.line for f in found if f.rule == "TG403"] == [8]
    assert [(f.rule, f.line) for f in found if f.line == 10] == [("TG203", 10)]


@pytest.mark.parametrize("plane", ["G17", "G18", "G19"])
def test_centre_word_order_in_every_plane(plane: str) -> None:
    """I J K rank by letter after their axes, in every plane (a real program found that an
    earlier fast path ranked them by their place in the plane)."""
    lines = ["%", f"N1 G21 {plane} G90 G94 G01 F100 X0 Y0 Z0"]
    lines += ["G03 X1. Z-1. I-1. K0.", "G03 X2. Z-2. K0. I-1.", "G02 Y1. Z1. J1. K0.",
              "G02 Y2. Z2. K1. J0.", "G02 X1. Y1. I1. J0.", "G02 X2. Y2. J1. I0.", "M30", "%"]
    _, expected, _, found = both("\n".join(lines) + "\n", 1, 1 << 20)
    assert found == expected
    assert any(f.rule == "TG130" for f in found)
