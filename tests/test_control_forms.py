"""Forms of the controls' programs read as each control's documentation and interpreter read them
(issue 32's last review): one small program per rule, error paths with their code, line and
column. Where LinuxCNC's ``rs274`` is installed, the LinuxCNC cases are run through it too."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from formats.parser import BadBlock, parse_text
from formats.profile import load_profile
from postproc.check import Checker


def bad_blocks(text: str, profile: str) -> list[tuple[str, int, int, str]]:
    """The reading errors of ``text``: code, line, column, message."""
    read = parse_text(text, load_profile(profile).dialect, errors="collect")
    return [(b.error.code, b.error.line, b.error.column, b.error.message)
            for b in read if isinstance(b, BadBlock)]


def findings(text: str, profile: str, file: str = "<input>") -> list:
    prof = load_profile(profile)
    return list(Checker(prof, file).run(parse_text(text, prof.dialect, errors="collect")))


def rs274(tmp_path: Path, text: str) -> tuple[bool, str]:
    """Whether rs274 runs ``text`` through, and its output; skipped where it is absent."""
    if shutil.which("rs274") is None:
        pytest.skip("LinuxCNC's rs274 is not installed")
    path = tmp_path / "program.ngc"
    path.write_text(text)
    run = subprocess.run(["rs274", "-g", str(path)], capture_output=True, text=True,
                         timeout=30, input="")
    out = run.stdout + run.stderr
    return "PROGRAM_END" in out, out


# -- 1. LinuxCNC: blanks inside a parameter reference ------------------------------------------

@pytest.mark.parametrize("body", [
    "# <x> = 1\nG0 X# < x >\nM2\n",
    "# < x y > = 2\nG0 X#<xy>\nM2\n",
    "#1 = 2\n# #1 = 7\nG0 X#2\nM2\n",
    "# [1 + 1] = 5\nG0 X#2\nM2\n",
    "#<x> = 1\no100 if [# <x> GT 0]\nG0 X1\no100 endif\nM2\n",
])
def test_linuxcnc_reads_blanks_inside_a_parameter_reference(tmp_path, body):
    """rs274ngc drops every blank outside comments before it reads a line (close_and_downcase),
    so ``# <x> = 1`` is ``#<x>=1`` and ``##1 = 7`` sets the parameter #1 names."""
    ran, out = rs274(tmp_path, body)
    assert ran, out
    assert bad_blocks(body, "linuxcnc") == []
    assert not [f for f in findings(body, "linuxcnc") if f.severity == "error"]


@pytest.mark.parametrize("body, column, message", [
    ("# <x = 1\nM2\n", 1, "named parameter '#<' without its closing '>'"),
    ("# <x> 1\nM2\n", 7, "a parameter must be set as #n = value"),
])
def test_linuxcnc_a_broken_parameter_reference_is_located(tmp_path, body, column, message):
    ran, _ = rs274(tmp_path, body)
    assert not ran
    assert bad_blocks(body, "linuxcnc") == [("TG100", 1, column, message)]


def test_linuxcnc_a_read_only_parameter_written_with_blanks_is_still_read_only(tmp_path):
    body = "# <_x> = 1\n# 5420 = 2\nM2\n"
    ran, _ = rs274(tmp_path, body)
    assert not ran
    found = [(f.rule, f.line, f.column) for f in findings(body, "linuxcnc") if f.rule == "TG209"]
    assert found == [("TG209", 1, 1), ("TG209", 2, 1)]
