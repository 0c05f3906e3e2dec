"""The code tables, variables and block forms of each family, from the makers' references
(issue 32, docs/dialects.md): small programs written from the manuals' examples, each firing
and quiet.

- TG304 between a decimal code and the other codes of its group (``G54.1 P1 G55``);
  on LinuxCNC each pair against rs274 where it is installed.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from formats.profile import load_profile
from postproc.check import check_text

RS274 = shutil.which("rs274")


def found(text: str, profile: str) -> list[tuple[str, str, int, str]]:
    """(rule, severity, line, message) of every finding but the notes about style."""
    return [(f.rule, f.severity, f.line, f.message) for f in check_text(text, load_profile(profile))
            if f.rule not in ("TG130", "TG133", "TG703")]


def fired(text: str, profile: str, rule: str) -> list[tuple[str, int, str]]:
    """(severity, line, message) of each finding of ``rule``."""
    return [(severity, line, message) for r, severity, line, message in found(text, profile)
            if r == rule]


def fanuc(body: str) -> str:
    return f"%\nO1000\nG21 G90 G17 G00 X0 Y0 Z10.\n{body}\nM30\n%\n"


def linuxcnc(body: str) -> str:
    return f"G21 G90 G17 G40 G49 G80 G94 G97\n{body}\nM2\n"


# -- TG304 between decimal codes -----------------------------------------------------------------


@pytest.mark.parametrize(("block", "pair"), [
    ("G54.1 P1 G55", "G55 and G54.1"),  # work offset (Fanuc group 14)
    ("G55 G54.1 P1", "G54.1 and G55"),
    ("G43.4 H1 G49", "G49 and G43.4"),  # length (group 08)
    ("G43.4 H1 G43.5", "G43.5 and G43.4"),
    ("G68.2 X0 Y0 Z0 I0 J45. K0 G69", "G69 and G68.2"),  # rotation (group 16)
    ("G12.1 G13.1", "G13.1 and G12.1"),  # polar interpolation (group 21)
    ("G41.2 D1 G40", "G40 and G41.2"),  # cutter (group 07)
    ("G50.1 X0 G51.1 X0", "G51.1 and G50.1"),  # mirror (group 22)
])
def test_a_decimal_fanuc_code_and_another_of_its_group_are_tg304(block, pair):
    hits = fired(fanuc(block), "fanuc-mill", "TG304")
    assert [(severity, line) for severity, line, _ in hits] == [("error", 4)]
    assert pair in hits[0][2]


@pytest.mark.parametrize("block", [
    "G54.1 P1 G43.4 H1",  # two groups
    "G54.1 P1 G54.1 P1",  # one code twice
    "G05.1 Q1 G04 P100",  # G05.1 is group 00: no modal group to share
    "G12.1 G40",
])
def test_decimal_fanuc_codes_of_two_groups_are_no_tg304(block):
    assert fired(fanuc(block), "fanuc-mill", "TG304") == []


def test_a_decimal_fanuc_lathe_code_and_another_of_its_group_are_tg304():
    program = "%\nO1000\nG21 G18 G00 X50. Z10.\nG12.1 G13.1\nM30\n%\n"
    assert [line for _, line, _ in fired(program, "fanuc-lathe", "TG304")] == [4]


# LinuxCNC: each pair against rs274 2.9 ("Two g codes used from same modal group")
LINUXCNC_PAIRS = [
    ("G90.1 G91.1", True),
    ("G59.1 G54", True),
    ("G61.1 G64", True),
    ("G43.1 Z1 G49", True),
    ("G38.2 Z-1 F10 G1", True),
    ("G17.1 G18", True),
    ("G41.1 D1 G40", True),
    ("G28.1 G4 P1", True),
    ("G92.1 G92.3", True),
    # rs274 runs G92.1-G92.3 beside the other codes of the Overview's group 0
    ("G4 P1 G92.1", False),
    ("G92 X0 G92.2", False),
    ("G28.1 G92.1", False),
    ("G90.1 G90", False),
]


@pytest.mark.parametrize(("block", "refused"), LINUXCNC_PAIRS)
def test_decimal_linuxcnc_codes_in_one_group_as_rs274_has_them(block, refused):
    assert bool(fired(linuxcnc(block), "linuxcnc", "TG304")) is refused


@pytest.mark.skipif(RS274 is None, reason="LinuxCNC's rs274 is absent")
def test_the_linuxcnc_pairs_are_what_rs274_says(tmp_path: Path):
    (tmp_path / "tools.tbl").write_text("T1 P1 D1 Z0 ;\n")
    for block, refused in LINUXCNC_PAIRS:
        (tmp_path / "t.ngc").write_text(linuxcnc(block))
        assert RS274 is not None
        result = subprocess.run([RS274, "-g", "-t", "tools.tbl", "t.ngc", "/dev/null"],
                                capture_output=True, text=True, timeout=30, cwd=tmp_path,
                                stdin=subprocess.DEVNULL)
        said = "Two g codes used from same modal group" in result.stdout + result.stderr
        assert said is refused, block
