"""One character table: the checker reads a program by it and the emulated control's TH check
rejects by it, so `check` and `emulate` never disagree about the same bytes."""

from __future__ import annotations

import pytest

from dnc.control import Control
from formats import _core
from formats.profile import load_profile
from formats.source import Source
from postproc.check import check_text

from .conftest import CORPUS, needs_corpus

FANUC = load_profile("fanuc-mill")


def th_errors(text: str, profile=FANUC) -> list[tuple[int, int, str]]:
    """The TH errors of an emulated control of the profile reading ``text`` (line, column)."""
    control = Control(cps=1e6, buffer=1 << 20, rate=None, allowance=10, programs=None,
                      dialect=profile.dialect, keep_text=False)
    control.time_passed(0.0)
    control.data_received(text.encode("latin-1"), 0.0)
    return [(e.line, e.column, e.detail) for e in control.stats.errors if e.kind == "TH illegal"]


def character_errors(text: str, profile=FANUC) -> list[int]:
    return [f.line for f in check_text(text, profile) if f.rule == "TG101"]


def test_lower_case_in_a_comment_is_text_for_both():
    text = ("%\nO1001\n(Using high feed G1 F5000. instead of G0.)\nG21 G90 G00 X0 (t1: face)\n"
            "M30\n%\n")
    assert th_errors(text) == []
    assert character_errors(text) == []


def test_lower_case_outside_a_comment_is_refused_by_both():
    text = "%\nO1001\nG21 G90 G00 x10.\nM30\n%\n"
    assert [line for line, _, _ in th_errors(text)] == [3]
    assert character_errors(text) == [3]


def test_the_table_follows_the_dialect():
    fanuc, linuxcnc = FANUC.dialect.flags, load_profile("linuxcnc").dialect.flags
    assert not _core.character_allowed("x", False, fanuc)
    assert _core.character_allowed("x", False, linuxcnc)
    assert _core.character_allowed("#", False, fanuc)  # macro variables
    assert not _core.character_allowed("$", False, fanuc)
    assert _core.character_allowed("$", False, linuxcnc)  # the spindle word
    assert all(_core.character_allowed(c, True, fanuc) for c in "abc;$@!\"")
    assert not _core.character_allowed("\x01", True, fanuc)


@pytest.mark.parametrize("char", [chr(c) for c in range(0x21, 0x7F)])
def test_every_printable_character_in_a_comment_is_accepted_by_both(char):
    if char in "()":
        return
    text = f"%\nO1\n(A{char}B)\nM30\n%\n"
    assert th_errors(text) == [] and character_errors(text) == []


@needs_corpus
def test_a_fusion_360_program_passes_the_emulated_th_check():
    """The emulator raised 87-174 TH errors for the lower case in the comments of Fusion 360
    programs that check passes."""
    path = CORPUS / "Praktikum-CAD-CAM-Modul-12__1001.nc"
    text = "".join(Source(str(path)).chunks())
    profile = load_profile("haas-mill")
    assert th_errors(text.replace("\r", ""), profile) == []
    assert character_errors(text, profile) == []


def test_a_fanuc_program_named_in_angle_brackets_passes_both():
    """A 30i names a program `<NAME>` (B-64014EN/03, 2.5): read by check, taken by the
    emulated FANUC's TH check, the name's '_' included; a Haas refuses the '<' in both."""
    text = "%\n<PART_A>\nG21 G90 G00 X0 Y0\nM30\n%\n"
    assert th_errors(text) == [] and character_errors(text) == []
    haas = load_profile("haas-mill")
    assert [e[:2] for e in th_errors(text, haas)] == [(2, 1), (2, 6), (2, 8)]  # < _ >
    assert character_errors(text, haas) == [2]


def test_a_sinumerik_comparison_is_no_program_name():
    """Only a FANUC reads `<NAME>`: a SINUMERIK's `IF R1<5 GOTOF` keeps its blanks."""
    assert th_errors("%\nIF R1<5 GOTOF END1\nM30\n%\n", load_profile("sinumerik-840d")) == []
