"""A FANUC program named by a file name in ``< >`` in place of its O number, and the leader a
FANUC skips after the first ``%`` (issue 32, held9; docs/dialects.md, "Program names and the
leader"): small programs of our own from the manuals' forms.

- B-64014EN/03 (FANUC Fast Ethernet / Fast Data Server for 30i/31i/32i-A), 2.5 "NC program
  format": at the beginning of the program section an O number or a file name of up to 32
  characters enclosed by ``<`` and ``>``; before it, from the ``%`` to the first end of block,
  the leader section where a title may stand; an end of block is LF, CR-LF or LF-CR-CR.
- B-63524EN/01 (FANUC Series 16i/18i-TB), 8, memory card file format: "data between the first
  % and the next LF is skipped".
"""

from __future__ import annotations

import json
import re

import pytest
from click.testing import CliRunner

from formats import _core
from formats.convert import ConvertOptions, convert_file, convert_text
from formats.diff import DiffOptions, diff_files
from formats.parser import parse_text
from formats.printer import program_text
from formats.profile import load_profile
from postproc.check import check_text
from postproc.restart import plan_restart_text
from tapegate.cli import main

FANUC = load_profile("fanuc-mill")

# A 30i memory backup of our own: a main program by number, a named program in another folder
# (metric, incremental), and a named program whose name shares its block with M60 and which
# selects no units; #1 is a length in the first and a count in the third (a file of main
# programs: each program's locals its own).
NAMED = (
    "%\n"
    "&F=/USER/PATH1/\n"
    "O0001(MAIN)\n"
    "G20 G90 G54 G17\n"
    "#1 = 1.\n"
    "G0 X#1 Y2.\n"
    "M30\n"
    "&F=/USER/LIBRARY/\n"
    "<SUB_A.1>\n"
    "G21 G91\n"
    "G1 X25.4 F100.\n"
    "M30\n"
    "<101>M60\n"
    "#1 = 3\n"
    "M98 P1000 L#1\n"
    "G90 G0 X10. Y10.\n"
    "M30\n"
    "%\n"
)


def found(text: str, profile: str = "fanuc-mill") -> list[tuple[str, str, int, int]]:
    """(rule, severity, line, column) of every finding but the notes about style."""
    return [(f.rule, f.severity, f.line, f.column)
            for f in check_text(text, load_profile(profile))
            if f.rule not in ("TG130", "TG133", "TG703")]


def programs(text: str) -> list[str]:
    """The text cut before each O number, ``<NAME>`` or folder marker that follows an M30 or
    M99: the programs of the file, each with what surrounds it."""
    pieces, start, ended, at = [], 0, False, 0
    for line in text.splitlines(keepends=True):
        if ended and re.match(r"(O\d|&F=|<)", line):
            pieces.append(text[start:at])
            start, ended = at, False
        if re.search(r"M(30|99)\b", line):
            ended = True
        at += len(line)
    pieces.append(text[start:])
    return pieces


def jsonl(*args: str) -> tuple[int, list[dict]]:
    result = CliRunner().invoke(main, ["check", "--format", "jsonl", "-j", "1", *args])
    return result.exit_code, [json.loads(line) for line in result.output.splitlines()
                              if line.startswith("{")]


# -- program names ---------------------------------------------------------------------------


@pytest.mark.parametrize("profile", ["fanuc-mill", "fanuc-lathe"])
def test_a_named_program_is_read_as_a_numbered_one(profile):
    lathe = profile == "fanuc-lathe"
    text = "%\n<PART_A>\nG21 G00 X0 Z0\nM30\n%\n" if lathe else \
        "%\n<PART_A>\nG21 G90 G00 X0 Y0\nM30\n%\n"
    assert found(text, profile) == []
    assert found(text.replace("<PART_A>", "O1234"), profile) == []


def test_each_named_program_of_a_backup_is_checked_from_its_reset_state():
    """No TG106/TG116 (words after the end) at the named programs, no '<' refused; the third
    program's G90 X10. measured from no position (the second ended incremental)."""
    assert [f for f in found(NAMED) if f[1] == "error"] == []
    # a name after no end begins no program: as an O number there, TG113, a warning
    glued = NAMED.replace("M30\n<101>", "<101>")
    assert [f for f in found(glued) if f[0] in ("TG101", "TG113", "TG106", "TG116")] == [
        ("TG113", "warning", 12, 1)]
    assert [f for f in found(glued.replace("<101>", "O0101 ")) if f[0] == "TG113"] == [
        ("TG113", "warning", 12, 1)]


def test_the_reprint_keeps_every_byte():
    blocks = list(parse_text(NAMED, FANUC.dialect))
    assert program_text(blocks) == NAMED
    name = [b for b in blocks if b.line == 13][0]
    assert (name.words, name.statements) == (["M60"], [(1, "<101>", "name")])


def test_each_named_program_converts_as_a_file_of_its_own(tmp_path):
    """Converted to inch: the whole file is its programs converted one by one (its locals
    each program's own, the third program in its own start units), and it verifies."""
    opts = ConvertOptions(FANUC, FANUC, units="inch")
    whole, stats = convert_text(NAMED, opts)
    assert whole == "".join(convert_text(p, opts)[0] for p in programs(NAMED))
    lines = whole.splitlines()
    assert lines[8:11] == ["<SUB_A.1>", "G20 G91", "G1 X1. F3.937"]
    assert lines[4] == "#1 = 1." and lines[14] == "M98 P1000 L#1"  # O0001 is inch already
    # as the same file numbered O0002 and O0101 converts
    numbered = NAMED.replace("<SUB_A.1>", "O0002").replace("<101>", "O0101")
    assert whole == convert_text(numbered, opts)[0].replace("O0002", "<SUB_A.1>").replace(
        "O0101", "<101>")
    assert any("the program beginning on line 13 did not select its units" in n
               for n in stats.notes)
    path, out = tmp_path / "named.nc", tmp_path / "out.nc"
    path.write_text(NAMED)
    assert convert_file(str(path), str(out), opts, verify=True).verified
    # no change of units: byte for byte
    assert convert_text(NAMED, ConvertOptions(FANUC, FANUC))[0] == NAMED


def test_diff_and_restart_read_each_named_program_apart(tmp_path):
    path = tmp_path / "named.nc"
    path.write_text(NAMED)
    assert list(diff_files(str(path), str(path), FANUC, FANUC, DiffOptions(motion=True))) == []
    # a restart in a named program is walked from its own start, not refused for the G68
    # (a rotation no preamble restores) the program before it left in force
    src = ("%\nO1\nG21 G90 G54\nG0 X0 Y0\nG68 X0 Y0 R45.\nG1 X10. F100.\nM99\n"
           "<PART_B>\nG21 G90 G54 G17\nT1 M6\nG43 H1 Z50.\nS1000 M3\nG0 X5. Y5.\n"
           "G1 Z-1. F100.\nX20.\nM30\n%\n")
    plan = plan_restart_text([src], FANUC, 15, "named.nc")
    assert plan.preamble[0].startswith("G21 G17 G90")
    assert "G01 Z-1. F100." in plan.preamble


@pytest.mark.parametrize(("line", "column", "rule", "says"), [
    ("<ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456>", 34, "TG100", "33 characters"),
    ("<PART A>", 6, "TG101", "a blank in a program name"),
    ("<A%B>", 3, "TG101", "ends the record"),
    ("<A(B)>", 3, "TG101", "'(' in a program name"),
    ("<OPEN", 1, "TG100", "not closed by '>'"),
    ("<>", 1, "TG100", "empty program name"),
    ("M98 <SUB_A>", 5, "TG101", "a call by name"),
    ("G65 <SUB_A> A1.", 5, "TG101", "a call by name"),
    ("X1. >", 5, "TG101", "'>' without its '<'"),
])
def test_a_name_the_sources_exclude_is_refused_where_it_stands(tmp_path, line, column, rule,
                                                               says):
    path = tmp_path / "bad.nc"
    path.write_text(f"%\nO0001\nG21 G90 G00 X0\n{line}\nM30\n%\n")
    code, findings = jsonl(str(path), "-p", "fanuc-mill")
    assert code != 0
    hits = [f for f in findings if f["severity"] == "error"]
    assert [(f["file"], f["line"], f["column"], f["rule"]) for f in hits] == [
        (str(path), 4, column, rule)], hits
    assert says in hits[0]["message"]


def test_a_haas_and_the_strict_iso_profiles_refuse_the_angle_brackets():
    """A Haas names its programs O and five digits (Mill Operator's Manual, NGC, 2017, 5.3.1);
    ISO 6983-1 has no '<' in Annex A. The emulator's TH check reads the same table."""
    text = "%\n<PART_A>\nG21 G90 G00 X0 Y0\nM30\n%\n"
    for profile in ("haas-mill", "iso-mill"):
        assert ("TG101", "error", 2, 1) in found(text, profile)
    for profile, takes in (("fanuc-mill", True), ("fanuc-lathe", True), ("haas-mill", False),
                           ("iso-mill", False)):
        flags = load_profile(profile).dialect.flags
        assert [_core.character_allowed(c, False, flags) for c in "<>"] == [takes, takes]


# -- the leader after the first % -------------------------------------------------------------


@pytest.mark.parametrize(("leader", "lost"), [
    ("% PART A REV 2", None), ("% O0001", "O0001"), ("%O0003(FIXTURE)", "O0003"),
    ("% <PART_A> REV 2", "<PART_A>"), ("% 00214", None)])
@pytest.mark.parametrize("profile", ["fanuc-mill", "fanuc-lathe"])
def test_a_fanuc_skips_the_leader_and_says_so(profile, leader, lost):
    text = f"{leader}\nO0001\nG21 G00 X0\nM30\n%\n"
    hits = [f for f in check_text(text, load_profile(profile)) if f.rule == "TG129"]
    assert [(f.severity, f.line, f.column) for f in hits] == [("warning", 1, 2)]
    assert not [f for f in found(text, profile) if f[0] in ("TG111", "TG112")]
    if lost:
        assert f"the program number '{lost}' there is lost" in hits[0].message
    else:
        assert "program number" not in hits[0].message


@pytest.mark.parametrize(("profile", "leader", "rule", "severity"), [
    ("haas-mill", "% PART A REV 2", "TG137", "warning"),
    ("haas-lathe", "% O0001", "TG137", "warning"),
    ("okuma-mill", "% PART A REV 2", "TG137", "warning"),
    ("iso-mill", "% PART A REV 2", "TG112", "error"), ("iso-mill", "%N1 G71", "TG111", "error")])
def test_elsewhere_the_leader_keeps_its_errors(profile, leader, rule, severity):
    """No Haas source says what the control does with text after the first % (its manual:
    '%' begins and ends a program written in a text editor), nor an Okuma source: a warning
    there (issue 32, severity by evidence); ISO 6983-1 refuses it: its errors on the strict
    profiles."""
    text = f"{leader}\nO0001\nG21 G00 X0\nM30\n%\n"
    assert (rule, severity, 1, 2) in found(text, profile)
    assert not {"TG111", "TG112"} & {f[0] for f in found(text, profile)} or severity == "error"
    assert "TG129" not in [f[0] for f in found(text, profile)]


def test_a_bare_cr_is_no_end_of_block_on_a_fanuc():
    """An end of block is LF, CR-LF or LF-CR-CR (B-64014EN/03, 2.5): a bare CR (an old Mac's
    line end) joins the lines into one block, and tapegate reads them so, as the control
    does: two G codes of one group and a repeated X in the one block."""
    text = "%\nO0001\nG21 G90 G00 X0\rG91 G01 X5. F100.\rM30\n%\n"
    errors = [f[:3] for f in found(text) if f[1] == "error"]
    assert ("TG304", "error", 3) in errors and ("TG131", "error", 3) in errors
    assert "TG114" not in [f[0] for f in found(text)]  # the M30 is in that block
    assert program_text(list(parse_text(text, FANUC.dialect))) == text
