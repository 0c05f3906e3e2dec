"""A value the checker cannot work out is taken as given and unknown, never as absent, and a
parameter's number is worked out as the control works it out (review 54, F6 and F3)."""

from __future__ import annotations

import pytest

from formats.profile import load_profile
from postproc.check import check_text

from .conftest import rs274_output


def _found(text: str, profile: str) -> list[tuple[str, int, int]]:
    return [(f.rule, f.line, f.column) for f in check_text(text, load_profile(profile))
            if f.severity in ("error", "warning")]


@pytest.mark.parametrize(("profile", "setting"), [
    ("fanuc-mill", ""), ("fanuc-mill", "#[#9]=1.\n"), ("haas-mill", ""),
])
def test_an_arc_whose_radius_is_a_value_not_known_is_no_arc_without_a_radius(profile, setting):
    """Review 54, F6: `G02 X10. Y0 R#500` with #500 not known was TG404 "arc without I J (or
    R)"; an assignment to #[k] with k not known forgets every value, and made it common."""
    text = ("%\nO1000\nG21 G17 G90 G54\nG0 X0 Y0 Z1.\n" + setting
            + "G02 X10. Y0 R#500 F100.\nG0 Z10.\nM30\n%\n")
    assert _found(text, profile) == []


def test_an_arc_without_a_radius_is_still_refused():
    text = "%\nO1000\nG21 G17 G90 G54\nG0 X0 Y0 Z1.\nG02 X10. Y0 F100.\nM30\n%\n"
    assert ("TG404", 5, 1) in _found(text, "fanuc-mill")


def test_linuxcnc_reads_an_indirect_number_with_the_values_from_before_the_line(tmp_path):
    """Review 54, F3: `#1=2 ##1=900` sets #3 where #1 was 3 before the line (rs274ngc reads
    a line's values before it sets any); the checker set #2. It now takes the number as not
    known there and forgets every value, so none it holds is wrong (R#3 and X#2 not known)."""
    text = ("G21 G90 G17\nG0 X0 Y0 Z0\n#1=3\n#2=5\n#3=1\n#1=2 ##1=900\n"
            "G2 X10 Y0 R#3 F100\nG0 X#2\nM2\n")
    found = check_text(text, load_profile("linuxcnc"))
    assert [f for f in found if f.severity == "error"] == []
    assert any(f.rule == "TG141" and f.line == 7 for f in found)  # R#3: not known
    out = rs274_output(tmp_path, text)
    if out:
        assert "ARC_FEED" in out and "PROGRAM_END" in out  # R900: the arc runs
