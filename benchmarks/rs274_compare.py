"""tapegate's errors against LinuxCNC's interpreter ``rs274`` on the programs it runs.

    .venv/bin/python benchmarks/rs274_compare.py [--json] [--only samples|corpus|seeded|arcs]
                                                 [--samples DIR] [--corpus DIR]

For every program, ``rs274 -g -t TOOLS.tbl PROGRAM /dev/null`` (LinuxCNC's standalone
interpreter, Debian package linuxcnc-uspace, batch mode, in a temporary directory) and
``tapegate check PROGRAMS... -p PROFILE --format json``; per file, rs274's verdict (ok, or its
message and the line it stopped at) and tapegate's error findings (rule, line, message).

- **samples**: the ``.ngc`` programs LinuxCNC ships (``/usr/share/linuxcnc/ncfiles``, recursive),
  on the ``linuxcnc`` profile.
- **corpus**: the real CAM programs of the corpus (``TAPEGATE_CORPUS``, default
  ``shared/corpus`` beside the project, as for the tests) on their matching profile (``MATCHING``
  in tests/test_dialects.py). Only those rs274 runs are compared; the others are listed as
  another dialect.
- **seeded**: small programs written here with one fault each, on ``linuxcnc``: does each side
  report it, and on the line of the fault? A fault of the block delete switch ("switch": a
  setting after ``/``) is one rs274 reports on its line with the switch off (``-g``) or on
  (``-b -g``) but not both; tapegate, which knows no machine's switch, reports no error.
- **arcs**: the arc radius tolerance of rs274, measured by bisection in mm and inch at small,
  medium and large radii, and tapegate's answer just inside and just outside it.

rs274 needs a tool table: it stops with "Requested tool N not found" otherwise. The table written
here holds tools 1-99 and every T number of the program, diameter 0 and length 0 (a loaded
machine, no tool geometry). rs274 prints the text of the block it stopped at, not its line
number; the line is the program line with that text, and where several lines have it, the first
whose prefix of the program (the lines up to it) stops rs274 with the same message.

rs274 stops at its first error, so a file is compared up to that line:

- ``agree``: rs274 runs it and tapegate reports no error; or rs274 stops at line L with a program
  fault and tapegate's first error is on line L.
- ``disagree``: anything else (tapegate errors before L, or none at L).
- Some rs274 stops are not faults of the program. They are classified and compared only on the
  lines before the stop: ``library`` (a file of ``o<name> sub`` definitions only: rs274 reads the
  definitions without running their bodies and then stops at the end of the file, which has no
  M2; nothing is compared), ``configuration`` (the program needs a configured machine: HAL pins
  of ``#<_hal[...]>``, user M codes M100-M199, M200-M999 (a REMAP's), subroutines from the
  configuration's path, a probe input, an axis the standalone interpreter does not have).
- A file without M2/M30 that is not a library (a fragment) is a program fault: rs274 refuses it
  at the end of the file, and tapegate agrees when it reports TG114 anywhere.

Exit code 0 always (a measurement, not a test); tests/test_oracle_rs274.py asserts.
"""

from __future__ import annotations

import argparse
import ast
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from collections import Counter
from dataclasses import asdict, dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))

from postproc.rules import rule_id  # noqa: E402  (the registry's IDs, never written here)

NO_PROGRAM_END = rule_id("NoProgramEnd")
ARC_RADIUS_MISMATCH = rule_id("ArcRadiusMismatch")
ARC_RADIUS_TOO_SHORT = rule_id("ArcRadiusTooShort")
NCFILES = Path("/usr/share/linuxcnc/ncfiles")
CORPUS = Path(os.environ.get("TAPEGATE_CORPUS", ROOT.parent / "shared" / "corpus"))
TIMEOUT = 120.0


def rs274_exe() -> str | None:
    return shutil.which("rs274")


def tapegate_exe() -> str | None:
    exe = ROOT / ".venv" / "bin" / "tapegate"
    return str(exe) if exe.exists() else shutil.which("tapegate")


def matching() -> dict[str, str]:
    """``MATCHING`` of tests/test_dialects.py, read without importing the test module."""
    tree = ast.parse((ROOT / "tests" / "test_dialects.py").read_text())
    for node in tree.body:
        if (isinstance(node, ast.Assign) and len(node.targets) == 1
                and isinstance(node.targets[0], ast.Name) and node.targets[0].id == "MATCHING"):
            value = ast.literal_eval(node.value)
            assert isinstance(value, dict)
            return {str(k): str(v) for k, v in value.items()}
    raise LookupError("MATCHING not found in tests/test_dialects.py")


# --- rs274 -------------------------------------------------------------------------------------

@dataclass
class Rs274:
    ok: bool
    message: str = ""  # the error, empty when ok
    text: str = ""  # the block rs274 stopped at, as it printed it
    line: int | None = None  # 1-based line of that block in the program
    note: str = ""


def tool_table(text: str) -> str:
    code = re.sub(r"\([^)]*\)|;.*", "", text)
    tools = set(range(1, 100)) | {int(t) for t in re.findall(r"(?<![A-Za-z_<])[Tt]\s*(\d+)", code)}
    return "".join(f"T{t} P{t} D0 Z0 ;\n" for t in sorted(tools - {0}))


def _rs274_raw(program: Path, table: str, workdir: Path,
               flags: tuple[str, ...] = ()) -> tuple[int | None, str]:
    (workdir / "tools.tbl").write_text(table)
    try:
        # rs274 maps its tool table to $HOME/.tool.mmap: two runs at once with one HOME share
        # it (a tool "not found", a bus error), so each runs with the work folder as its HOME
        p = subprocess.run([rs274_exe() or "rs274", *flags, "-g", "-t", "tools.tbl",
                            str(program), "/dev/null"], stdin=subprocess.DEVNULL,
                           capture_output=True,
                           cwd=workdir, timeout=TIMEOUT,
                           env={**os.environ, "HOME": str(workdir)})
    except subprocess.TimeoutExpired:
        return None, ""
    return p.returncode, (p.stdout + p.stderr).decode("utf-8", "replace")


def _parse_error(out: str) -> tuple[str, str]:
    """(message, block text) from rs274's output: after ``executing``, the message, then the
    block. Status lines of the interpreter (``executing``) are skipped."""
    lines = [ln for ln in out.splitlines() if ln.strip() and ln.strip() != "executing"]
    if not lines:
        return "", ""
    if len(lines) == 1:
        return lines[0].strip(), ""
    return lines[-2].strip(), lines[-1]


def run_rs274(program: Path, workdir: Path, table: str | None = None,
              flags: tuple[str, ...] = ()) -> Rs274:
    """rs274's verdict; ``flags`` before ``-g`` (``-b``: the block delete switch on)."""
    raw = program.read_bytes().decode("utf-8", "replace")
    table = tool_table(raw) if table is None else table
    rc, out = _rs274_raw(program, table, workdir, flags)
    if rc is None:
        return Rs274(ok=False, message=f"timed out after {TIMEOUT:.0f} s", note="timeout")
    if rc == 0:
        return Rs274(ok=True)
    message, text = _parse_error(out)
    result = Rs274(ok=False, message=message, text=text)
    result.line = locate(program, raw, text, message, table, workdir, flags)
    return result


def locate(program: Path, raw: str, text: str, message: str, table: str,
           workdir: Path, flags: tuple[str, ...] = ()) -> int | None:
    lines = raw.splitlines()
    want = text.rstrip()
    if not want:  # rs274 printed no block (the end of the file): the last line
        return len(lines) if message.startswith(LIBRARY_END) else None
    candidates = [i + 1 for i, ln in enumerate(lines) if ln.rstrip() == want]
    if not candidates:
        return None
    if len(candidates) == 1:
        return candidates[0]
    prefix = workdir / ("prefix" + program.suffix)
    for n in candidates[:25]:
        prefix.write_text("\n".join(lines[:n]) + "\n")
        _, out = _rs274_raw(prefix, table, workdir, flags)
        # (a message naming the file, "File:... redefining sub", names the prefix's)
        if _parse_error(out.replace(str(prefix), str(program))) == (message, text):
            return n
    return candidates[0]


LIBRARY_END = "File ended with no percent sign or program end"
SUB = re.compile(r"^\s*o\s*(<[^>]*>|\d+)\s*sub\b", re.I | re.M)
CONFIGURATION = [
    (re.compile(r"Named parameter #<_hal\["), "HAL pins of a configured machine (#<_hal[...]>)"),
    (re.compile(r"Unknown m code used: M1\d\d"), "user M code M100-M199 of the configuration"),
    (re.compile(r"M-code greater than 199: M[2-9]\d\d\b"),
     "M200-M999, open to a REMAP of the configuration"),
    (re.compile(r"EOF in file.*seeking o-word|Unable to open file|not found in"),
     "subroutine from the configuration's subroutine path"),
    (re.compile(r"probe", re.I), "needs a probe input"),
    (re.compile(r"remap", re.I), "remapped code of the configuration"),
    (re.compile(r"Bad character '[uvwUVW]' used"), "axis the standalone interpreter lacks"),
    (re.compile(r"Requested tool \d+ not found"), "tool table"),
]


def classify(rs: Rs274, raw: str) -> tuple[str, str]:
    """(class, why): ``program`` (a verdict on the program), ``library``, ``configuration``."""
    if rs.ok:
        return "program", ""
    if rs.message.startswith(LIBRARY_END):
        if SUB.search(raw):
            return "library", "subroutine definitions only, no M2 (o<name> call from elsewhere)"
        return "program", "no program end (a fragment)"
    for pattern, why in CONFIGURATION:
        if pattern.search(rs.message):
            return "configuration", why
    if rs.note == "timeout":
        return "configuration", "rs274 timed out"
    return "program", ""


# --- tapegate ----------------------------------------------------------------------------------

@dataclass
class Err:
    rule: str
    line: int
    message: str
    severity: str = "error"


def run_tapegate(paths: list[Path], profile: str, *,
                 everything: bool = False) -> dict[str, list[Err]]:
    """Error findings (``everything``: all findings) per file, by the path as given; one
    process for all the paths."""
    found: dict[str, list[Err]] = {str(p): [] for p in paths}
    if not paths:
        return found
    exe = tapegate_exe()
    if exe is None:
        raise SystemExit("tapegate is not installed (make the .venv first)")
    p = subprocess.run([exe, "check", *map(str, paths), "-p", profile, "--format", "json"],
                       capture_output=True, text=True, timeout=600, cwd=ROOT)
    if p.returncode not in (0, 1):
        raise SystemExit(f"tapegate check failed ({p.returncode}): {p.stderr.strip()}")
    for f in json.loads(p.stdout)["findings"]:
        if everything or f["severity"] == "error":
            found.setdefault(f["file"], []).append(
                Err(f["rule"], f["line"], f["message"], f["severity"]))
    return found


# --- comparison --------------------------------------------------------------------------------

@dataclass
class Row:
    name: str
    source: str  # sample, corpus, seeded
    profile: str
    rs274: Rs274
    errors: list[Err]
    kind: str = "program"  # program, library, configuration, dialect
    why: str = ""
    verdict: str = ""  # agree, disagree, excluded
    compared: list[Err] = field(default_factory=list)  # errors on the lines rs274 judged
    unverified: list[Err] = field(default_factory=list)  # errors past rs274's stop


def judge(row: Row) -> None:
    rs, errors = row.rs274, sorted(row.errors, key=lambda e: e.line)
    if row.kind == "dialect":
        row.verdict = "excluded"
        row.unverified = errors
        return
    if row.kind == "library":
        # rs274 read the definitions without running them: nothing to compare but the end.
        row.verdict = "excluded"
        row.unverified = errors
        return
    if rs.ok:
        row.compared = errors
        row.verdict = "agree" if not errors else "disagree"
        return
    stop = rs.line if rs.line is not None else 10**9
    if row.kind == "configuration":
        row.compared = [e for e in errors if e.line < stop]
        row.unverified = [e for e in errors if e.line >= stop]
        row.verdict = "agree" if not row.compared else "disagree"
        return
    if rs.message.startswith(LIBRARY_END):  # a fragment: the fault is the missing end
        row.compared = [e for e in errors if e.rule != NO_PROGRAM_END]
        row.verdict = ("agree" if any(e.rule == NO_PROGRAM_END for e in errors)
                       and not row.compared
                       else "disagree")
        return
    row.compared = [e for e in errors if e.line <= stop]
    row.unverified = [e for e in errors if e.line > stop]
    row.verdict = ("agree" if row.compared and all(e.line == stop for e in row.compared)
                   else "disagree")


def compare_files(paths: list[tuple[Path, str, str]], workdir: Path) -> list[Row]:
    """(path, source, profile) -> rows; rs274 on each, tapegate once per profile."""
    by_profile: dict[str, list[Path]] = {}
    for path, _, profile in paths:
        by_profile.setdefault(profile, []).append(path)
    found: dict[str, list[Err]] = {}
    for profile, group in by_profile.items():
        found.update(run_tapegate(group, profile))
    rows = []
    for path, source, profile in paths:
        raw = path.read_bytes().decode("utf-8", "replace")
        rs = run_rs274(path, workdir)
        kind, why = classify(rs, raw)
        if source == "corpus" and not rs.ok:
            kind, why = "dialect", "rs274 refuses it: not LinuxCNC's dialect"
        row = Row(name=str(path), source=source, profile=profile, rs274=rs,
                  errors=found.get(str(path), []), kind=kind, why=why)
        judge(row)
        rows.append(row)
    return rows


def samples(root: Path) -> list[tuple[Path, str, str]]:
    return [(p, "sample", "linuxcnc") for p in sorted(root.rglob("*.ngc"))] if root.is_dir() else []


def corpus(root: Path) -> list[tuple[Path, str, str]]:
    if not root.is_dir():
        return []
    return [(root / name, "corpus", profile) for name, profile in sorted(matching().items())
            if (root / name).is_file()]


# --- seeded faults -----------------------------------------------------------------------------

HEAD = "G21 G17 G90 G94\nG0 X0 Y0 Z5\n"  # lines 1-2; the fault is on line 3 unless said

# name, program, the line of the fault, what a correct checker says
SEEDED: list[tuple[str, str, int, str]] = [
    ("arc radius mismatch", HEAD + "G2 X10 Y0 I5.5 J0 F100\nM2\n", 3, "error"),
    ("arc centre missing", HEAD + "G2 X10 Y0 F100\nM2\n", 3, "error"),
    # review 55c, F2: no centre and no R is refused whatever the plane, one not known too
    ("arc centre missing after an if of an unknown condition setting G18",
     HEAD + "o1 if [#5220 GT 1]\nG18\no1 endif\nG2 X10 Y0 F100\nM2\n", 6, "error"),
    ("two G codes of the motion group", HEAD + "G0 G1 X10 F100\nM2\n", 3, "error"),
    ("two G codes of the distance group", HEAD + "G90 G91 X10\nM2\n", 3, "error"),
    ("feed motion without feed", HEAD + "G1 X10\nM2\n", 3, "error"),
    # F0 is no feed either: "Cannot do g1 with zero feed rate", "Cannot make arc with zero ..."
    ("feed motion at F0", HEAD + "G1 X10 F0\nM2\n", 3, "error"),
    ("arc at F0", HEAD + "G2 X10 Y0 I5 J0 F0\nM2\n", 3, "error"),
    ("G81 without Z", HEAD + "G81 X10 Y0 R1 F100\nG80\nM2\n", 3, "error"),
    ("G81 without R", HEAD + "G81 X10 Y0 Z-1 F100\nG80\nM2\n", 3, "error"),
    ("M00 and M30 in one block", HEAD + "G1 X10 F100\nM0 M30\n", 4, "error"),
    ("unknown G code G130", HEAD + "G130 X1\nM2\n", 3, "error"),
    ("two M codes of the coolant group", HEAD + "M7 M8\nM2\n", 3, "error"),
    ("arc centre outside the plane (K in G17)", HEAD + "G2 X10 Y0 I5 K0 F100\nM2\n", 3, "error"),
    # LinuxCNC has no motion mode at the start and after G80
    ("axis words before any motion code", "G21 G17 G90 G94\nX10\nM2\n", 2, "error"),
    ("axis words after G80", HEAD + "G81 X10 Y0 Z-1 R1 F100\nG80\nX20\nM2\n", 5, "error"),
    # LinuxCNC accepts an arc as the entry move of cutter compensation (tool radius 1 here).
    ("cutter compensation started on an arc",
     HEAD + "T1 M6\nG41 D1 G2 X40 Y0 I20 J0 F100\nG1 Y-20\nG40 G1 X20 Y-40\nM2\n", 4, "accepted"),
    # ... but not end it on one: the move just after G40 must be straight
    ("cutter compensation ended on an arc",
     HEAD + "T1 M6\nG41 D1 G1 X40 Y0 F100\nG1 Y-20\nG40 G2 X20 Y-40 I-20 J0\nM2\n", 6,
     "error"),
    ("arc as the first move after G40",
     HEAD + "T1 M6\nG41 D1 G1 X40 Y0 F100\nG1 Y-20\nG40\nG2 X20 Y-40 I-20 J0\nM2\n", 7,
     "error"),
    ("clean program", HEAD + "G1 X10 F100\nG2 X20 Y0 I5 J0\nG3 X10 Y0 R5\nG0 Z5\nM2\n", 0, "none"),
    # G53 moves by the G0 or G1 in force; G28, G30, G92 take their block's axis words
    ("G53 under G2", HEAD + "G1 X10 F100\nG2 X20 Y0 R5\nG53 Z0\nM2\n", 5, "error"),
    ("G28, G30 and G92 after an arc",
     HEAD + "G1 X10 F100\nG2 X20 Y0 R5\nG91 G28 Z0\nG90 G2 X30 Y0 R5\nG30 Z5\n"
     "G2 X40 Y0 R5\nG92 X0 Y0\nG92.1\nM2\n", 0, "accepted"),
    ("G83 without Q", HEAD + "G83 X10 Y0 Z-1 R1 F100\nG80\nM2\n", 3, "error"),
    # rs274's other canned-cycle refusals (interp_cycles.cc), TG412 with its message
    ("G73 without Q", HEAD + "G73 X10 Y0 Z-1 R1 F100\nG80\nM2\n", 3, "error"),
    ("G83 with Q0", HEAD + "G83 X10 Y0 Z-1 R1 Q0 F100\nG80\nM2\n", 3, "error"),
    ("G83 repeated with Q0", HEAD + "G83 X10 Y0 Z-1 R1 Q1 F100\nX20 Q0\nG80\nM2\n", 4,
     "error"),
    ("G82 without P", HEAD + "G82 X10 Y0 Z-1 R1 F100\nG80\nM2\n", 3, "error"),
    ("G82 with P-1", HEAD + "G82 X10 Y0 Z-1 R1 P-1 F100\nG80\nM2\n", 3, "error"),
    ("cycle repeated with Z above R", HEAD + "G81 X10 Y0 Z-1 R1 F100\nZ2\nG80\nM2\n", 4,
     "error"),
    # rs274 reads T and H as integers, and G41/G42's D as a tool number
    ("T not whole", HEAD + "T1.5 M6\nM2\n", 3, "error"),
    ("H not whole", HEAD + "G43 H1.5\nM2\n", 3, "error"),
    ("G41 D not whole", HEAD + "G41 D0.1 G1 X10 F100\nG40 G1 X20\nM2\n", 3, "error"),
    ("G87 without I", HEAD + "M3 S500\nG87 X10 Y0 Z-1 R1 J1 K-2 F100\nG80\nM2\n", 4,
     "error"),
    ("cycle with L0", HEAD + "G81 X10 Y0 Z-1 R1 L0 F100\nG80\nM2\n", 3, "error"),
    ("cycle with R below Z", HEAD + "G81 X10 Y0 Z-1 R-2 F100\nG80\nM2\n", 3, "error"),
    ("cycle without feed", HEAD + "G81 X10 Y0 Z-1 R1\nG80\nM2\n", 3, "error"),
    ("cycle under cutter compensation",
     HEAD + "G41.1 D2 G1 X10 F100\nG81 X20 Y0 Z-1 R1\nG80\nG40 G0 X0\nM2\n", 4, "error"),
    ("G74 with M3", HEAD + "M3 S100\nG74 X10 Y0 Z-1 R1 F100\nG80\nM2\n", 4, "error"),
    ("G84 with M4", HEAD + "M4 S100\nG84 X10 Y0 Z-1 R1 F100\nG80\nM2\n", 4, "error"),
    ("G84 with the spindle stopped", HEAD + "G84 X10 Y0 Z-1 R1 F100\nG80\nM2\n", 3, "error"),
    ("G86 with the spindle stopped", HEAD + "M3 S100\nM5\nG86 X10 Y0 Z-1 R1 P1 F100\nG80\nM2\n",
     5, "error"),
    ("a repeated cycle keeps its Z, R and Q",
     HEAD + "M3 S100\nG83 X10 Y0 Z-1 R1 Q0.5 F100\nX20\nG83 X30 Z-2\nG81 X10 Z-1 R1\n"
     "G81 X20\nG80\nM4\nG74 X10 Y0 Z-1 R1\nX20\nG80\nM2\n", 0, "accepted"),
    # G76 is LinuxCNC's threading cycle, G70-G72 its lathe cycles (LinuxCNC 2.9)
    ("G76 without I J K (a Fanuc boring block)",
     HEAD + "M3 S100\nG76 X30. Y30. Z-10. R2. Q0.5 P500 F50.\nM2\n", 4, "error"),
    ("G76 without P", "G21 G18 G90\nG0 X1 Z5\nM3 S100\nG76 I-1 J0.1 K1 Z-10\nM2\n", 4,
     "error"),
    ("G76 threading", "G21 G18 G90\nG0 X1 Z5\nM3 S100\nG76 P1.5 Z-10 I-0.1 J0.1 K1\nM2\n", 0,
     "accepted"),
    ("G70 without Q", "G21 G18 G90\nG0 X10 Z5\nG70 X10\nM2\n", 3, "error"),
    ("G71.1 without Q", "G21 G18 G90\nG0 X10 Z5\nG71.1 X10 D1\nM2\n", 3, "error"),
    ("G42.1 with L in G17", HEAD + "G42.1 D5 L1 G1 X10 F100\nG40 G1 X0\nM2\n", 3, "error"),
    # rs274 reads a % line as a program boundary only as the file's first line and, after
    # it, as the closing line, % alone (rs274ngc_pre.cc open, interp_read.cc read_text)
    ("a % line in a file not begun with %", "(header)\n%\nG21 G90\nG0 X1\nM2\n", 2,
     "error"),
    ("% and a comment as the first line", "% (header)\nG21 G90\nG0 X1\nM2\n", 1, "error"),
    ("a closing % with a comment", "%\nG21 G90\nG0 X1\n% (end)\nG0 X5\nM2\n", 4, "error"),
    ("G41.1 without D", "G21 G18 G90\nG0 X0 Z0\nG41.1 L1 G1 X5 F100\nG40 G1 X6\nM2\n", 3,
     "error"),
    # rs274 reads T, H and D within 0.0001 of a whole number as that number
    ("T, H and D within 0.0001 of a whole number",
     HEAD + "T1.00005 M6\nG43 H0.99995\nG41 D1.0001 G1 X40 Y0 F100\nG1 Y-20\n"
     "G40 G1 X20 Y-40\nM2\n", 0,
     "accepted"),
    ("T 0.00011 from a whole number", HEAD + "T1.00011 M6\nM2\n", 3, "error"),
    # every G93, G94, G95 sets the feed rate to zero, even one restating the mode
    ("G1 after a G94 restated, without F", HEAD + "G1 X10 F100\nG94\nG1 X20\nM2\n", 5,
     "error"),
    ("cycle after a G95, without F",
     HEAD + "M3 S500\nF100\nG95\nG81 X10 Y0 Z-1 R1\nG80\nM2\n", 6, "error"),
    # G76's other refusals (interp_convert.cc convert_threading_cycle)
    ("G76 with J0", "G21 G18 G90\nG0 X1 Z5\nM3 S100\nG76 P1.5 Z-10 I-0.1 J0 K1\nM2\n", 4,
     "error"),
    ("G76 with K not beyond J",
     "G21 G18 G90\nG0 X1 Z5\nM3 S100\nG76 P1.5 Z-10 I-0.1 J0.2 K0.2\nM2\n", 4, "error"),
    # rs274 keeps a repeated cycle's bottom along the plane's cycle axis (Y in G18)
    ("cycle in G18 repeated with R below Y",
     "G21 G18 G90 G94\nG0 X0 Y10 Z10\nF100\nM3 S500\nG81 X1 Z1 Y-1 R1\nX2 R-3\nG80\nM2\n",
     6, "error"),
    # an E word needs G33, G33.1, G70 or G76 (the block's motion) or M66-M68 in its block
    # (interp_check.cc check_other_codes); X1e3 is X1 and E3
    ("E word with no code to use it", HEAD + "G1 X10 E1 F100\nM2\n", 3, "error"),
    ("E words with G33, G76 and M66-M68",
     "G21 G18 G90\nG0 X1 Z5\nM3 S100\nG76 P1.5 Z-10 I-0.1 J0.1 K1 E0.5\nG33 Z-1 K1 E0.5\n"
     "Z-2 K1 E0.5\nM66 E0 L0\nM67 E0 Q1\nM68 E1 Q2\nM2\n", 0,
     "accepted"),
    # a call the checker does not follow may set the spindle and the compensation
    ("G84 after a call that starts the spindle clockwise",
     "o100 sub\nM3 S500\no100 endsub\nG21 G17 G90 G94\nG0 X0 Y0 Z5\nM4 S500\nF100\n"
     "o100 call\nG84 X1 Y1 Z-1 R1\nG80\nM2\n", 0, "accepted"),
    ("cycle after a call that cancels the compensation",
     "o100 sub\nG40\no100 endsub\nG21 G17 G90 G94\nG0 X0 Y0 Z5\nT1 M6\n"
     "G41 D1 G1 X40 Y0 F100\nG1 Y-20\no100 call\nG81 X1 Y1 Z-1 R1\nG80\nM2\n", 0,
     "accepted"),
    # a word no code of its block uses, and G4/G10's P (interp_check.cc check_g_codes,
    # check_other_codes)
    ("H word with no G43 or G76", HEAD + "G1 X10 F100 H1\nM2\n", 3, "error"),
    ("P word with no code to use it", HEAD + "G1 X10 F100 P1\nM2\n", 3, "error"),
    ("arc with P0", HEAD + "G3 X0 Y0 I1 J0 P0 F100\nM2\n", 3, "error"),
    ("G4 P-1 (rs274's no P)", HEAD + "G4 P-1\nM2\n", 3, "error"),
    ("G10 L2 P10", HEAD + "G10 L2 P10 X0\nM2\n", 3, "error"),
    ("P and H words their codes use",
     HEAD + "G43 H1\nG64 P0.01\nG10 L2 P1 X0\nG10 L1 P1 Z0\nG4 P0.5\n"
     "G3 X0 Y0 I1 J0 P2 F100\nM62 P1\nM2\n", 0, "accepted"),
    # a threading move needs the spindle turning (interp_convert.cc); M6 stops it
    ("G33 with the spindle stopped", HEAD + "G33 Z-1 K1\nM2\n", 3, "error"),
    ("G33 after a tool change", HEAD + "M3 S100\nT1 M6\nG33 Z-1 K1\nM2\n", 5, "error"),
    # a definition the program reaches after a call found it ahead (interp_o_word.cc)
    ("sub defined after its call", HEAD + "o100 call\no100 sub\nG0 X1\no100 endsub\nM2\n", 4,
     "error"),
    ("sub defined after its call and M2",
     HEAD + "o100 call\nM2\no100 sub\nG0 X1\no100 endsub\n", 0, "accepted"),
    # rs274 reads no byte outside its language (interp_read.cc read_text)
    ("UTF-8 byte order mark", "\ufeff" + HEAD + "G1 X10 F100\nM2\n", 1, "error"),
    # review 15, findings 5 and 8: rs274's feed rate, which G93 keeps (interp_convert.cc)
    ("probe after G93 keeps the feed rate", HEAD + "F100\nG93\nG38.2 X5\nM2\n", 0, "accepted"),
    ("probe after G94 without F", HEAD + "F100\nG93\nG94\nG38.2 X5\nM2\n", 6, "error"),
    ("cycle under G93", HEAD + "F100\nG93\nG81 X1 Y1 Z-1 R1\nG80\nM2\n", 5, "error"),
    ("probe ending where it starts", HEAD + "G38.2 Z5 F10\nM2\n", 3, "error"),
    ("G18 cycle without Y", "G21 G18 G90 G94\nG0 X0 Z5\nG81 X1 Z-1 R2 F100\nG80\nM2\n", 3,
     "error"),
    ("M code from an expression", HEAD + "M[3.5]\nM2\n", 3, "error"),
    ("division by zero", HEAD + "G0 X[1/0]\nM2\n", 3, "error"),
    ("M66 with P and E", HEAD + "M66 P0 E0 L0\nM2\n", 3, "error"),
    ("M3 beside M70", HEAD + "M3 M70 S100\nM2\n", 3, "error"),
    ("NURBS point without its weight", HEAD + "F100\nG5.2 X1 Y1 L3\nX2 Y2\nG5.3\nM2\n", 5,
     "error"),
    ("named parameter read before it is set", HEAD + "G0 X#<nope>\nM2\n", 3, "error"),
    ("R arc after G43 H1 ending where it starts", HEAD + "G43 H1\nG2 X0 Y0 R5 F100\nM2\n", 4,
     "error"),
    ("R arc after G92 ending where it starts",
     HEAD + "G0 X1 Y0\nG92 X0\nG2 X0 Y0 R5 F100\nM2\n", 5, "error"),
    # the o-word labels read_o reads through read_integer_value (interp_read.cc; lcnc48)
    ("o-word label with a sign", "o+100 sub\nG0 X1\no+100 endsub\n" + HEAD + "o100 call\nM2\n",
     0, "accepted"),
    ("o-word label with a point", "o100.0 sub\nG0 X1\no100 endsub\n" + HEAD
     + "o100.00 call\nM2\n", 0, "accepted"),
    ("o-word label a parameter's parameter", "o100 sub\nG0 X1\no100 endsub\n" + HEAD
     + "#2=3\n#3=100\no##2 call\nM2\n", 0, "accepted"),
    ("o-word label a function", "o100 sub\nG0 X1\no100 endsub\n" + HEAD
     + "oabs[-100] call\nM2\n", 0, "accepted"),
    ("o-word label with a fraction", "o100 sub\nG0 X1\no100 endsub\n" + HEAD
     + "o100.5 call\nM2\n", 6, "error"),
    ("endsub label of a parameter's value", "#1=100\no100 sub\nG0 X1\no#1 endsub\n" + HEAD
     + "o100 call\nM2\n", 0, "accepted"),
    ("endif label of a parameter's value", HEAD + "o5 if [1]\n#1=5\no#1 endif\n"
     "G0 X#<nope>\nM2\n", 6, "error"),
    # review 48 (fixl48): a function's label on a definition, a fraction on any o-word, an M
    # word's parameter set on its own line
    ("sub label a function", "oabs[-100] sub\nG0 X1\no100 endsub\n" + HEAD
     + "o100 call\nM2\n", 0, "accepted"),
    ("if label with a fraction", HEAD + "o100.5 if [1]\nG0 X1\no100.5 endif\nM2\n", 3,
     "error"),
    ("sub label with a fraction", "o100.5 sub\nG0 X1\no100.5 endsub\n" + HEAD
     + "o100.5 call\nM2\n", 1, "error"),
    ("M of a parameter set on its line (old 5)", HEAD + "#1=5\n#1=2 M#1\nG0 X#<nope>\nM2\n",
     5, "error"),
    ("M of a parameter set on its line (old 2)", HEAD + "#1=2\n#1=5 M#1\nG0 X1\nM2\n", 0,
     "accepted"),
    # review 48 (lcnc49): a label rs274 keeps for the whole program used again (F19), a
    # closing label read with the values its block set (F10), a subroutine's G90/G91 after
    # its return (F16)
    ("sub defined twice", "o100 sub\nG0 X1\no100 endsub\no100 sub\nG0 X2\no100 endsub\n"
     + HEAD + "o100 call\nM2\n", 4, "error"),
    ("sub defined twice by a computed label", "o100 sub\nG0 X1\no100 endsub\no[100] sub\n"
     "G0 X2\no100 endsub\n" + HEAD + "o100 call\nM2\n", 4, "error"),
    ("if label used twice", HEAD + "o1 if [1]\nG0 X1\no1 endif\no1 if [1]\nG0 X2\n"
     "o1 endif\nM2\n", 6, "error"),
    ("if label used twice, the first a parameter's value", HEAD + "#1=1\no#1 if [1]\n"
     "G0 X1\no#1 endif\no1 if [1]\nG0 X2\no1 endif\nM2\n", 7, "error"),
    ("while label of an if before", HEAD + "o1 if [1]\no1 endif\no1 while [0]\n"
     "o1 endwhile\nM2\n", 5, "error"),
    ("repeat label of a do before", HEAD + "o1 do\nG0 X1\no1 while [0]\no1 repeat [1]\n"
     "o1 endrepeat\nM2\n", 6, "error"),
    ("do label of a do before", HEAD + "o1 do\nG0 X1\no1 while [0]\no1 do\nG0 X2\n"
     "o1 while [0]\nM2\n", 0, "accepted"),
    ("if label in a body and the main program", "o<s> sub\no1 if [1]\nG0 X1\no1 endif\n"
     "o<s> endsub\n" + HEAD + "o1 if [1]\no1 endif\no<s> call\no<s> call\nM2\n", 0,
     "accepted"),
    ("endif label changed inside its block", HEAD + "#1=3\no#1 if [1]\n#1=4\no#1 endif\n"
     "M2\n", 6, "error"),
    ("endwhile label changed in a loop not run", HEAD + "#1=3\no#1 while [0]\n#1=4\n"
     "o#1 endwhile\nM2\n", 0, "accepted"),
    ("endif label of a parameter kept", HEAD + "#1=5\no#1 if [1]\nG0 X1\no#1 endif\n"
     "G0 X#<nope>\nM2\n", 7, "error"),
    ("G53 after a sub that leaves G90", "o<s> sub\nG90 G0 X1\no<s> endsub\nG21 G17 G90 G94\n"
     "G91\no<s> call\nG53 G0 X0\nM2\n", 0, "accepted"),
    ("G53 after a sub whose M73 restores G91", "o<s> sub\nM73\nG90 G0 X1\no<s> endsub\n"
     "G21 G17 G90 G94\nG91\no<s> call\nG53 G0 X0\nM2\n", 8, "error"),
    # review 49a, F1 and F6: G53 where the distance mode is not known is not refused
    ("G53 after a sub whose G91 is in a condition", "G21 G90\no<s> sub\no1 if [0]\nG91\n"
     "o1 endif\no<s> endsub\no<s> call\nG53 G0 Z0\nM2\n", 0, "accepted"),
    ("G53 after a call in a condition not run", "G21 G90\no<s> sub\nG91\no<s> endsub\n#5=0\n"
     "o1 if [#5 eq 1]\no<s> call\no1 endif\nG53 G0 Z0\nM2\n", 0, "accepted"),
    ("G53 after a sub whose G91 follows a return in a condition", "G21 G90\no<s> sub\n"
     "o1 if [#1 gt 0]\no<s> return\no1 endif\nG91\no<s> endsub\no<s> call [1]\n"
     "G53 G0 Z0\nM2\n", 0, "accepted"),
    ("G53 after a sub whose G91 follows its return", "G21 G90\no<s> sub\nG90\no<s> return\n"
     "G91\no<s> endsub\nG91\no<s> call\nG53 G0 Z0\nM2\n", 0, "accepted"),
    ("G53 after a sub whose G90 follows its return", "G21 G90\no<s> sub\nG91\no<s> return\n"
     "G90\no<s> endsub\no<s> call\nG53 G0 Z0\nM2\n", 8, "error"),
    ("G53 after a G91 in a condition not run", "G21 G90\no1 if [0]\nG91\no1 endif\n"
     "G53 G0 Z0\nM2\n", 0, "accepted"),
    ("G53 after M72 restores G90", "G21 G90\nM70\nG91\nM72\nG53 G0 Z0\nM2\n", 0, "accepted"),
    # review 49a, F2: a condition of comparisons and logical operators decides whether the
    # block's lines run (interp_execute.cc execute_binary2), a repeat's count is rounded half
    # to even (nearbyint: [0.5] runs no time, [1.5] twice)
    ("endif label changed in an if of a comparison", HEAD + "#1=0\n#2=3\n"
     "o#2 if [#1 LT 3]\n#2=4\no#2 endif\nM2\n", 7, "error"),
    ("endwhile label changed in a loop of a comparison", HEAD + "#1=0\n#2=3\n"
     "o#2 while [[#1 LT 3] AND [#1 GE 0]]\n#2=4\n#1=[#1+1]\no#2 endwhile\nM2\n", 8, "error"),
    ("endif label changed in an if of a comparison false", HEAD + "#1=5\n#2=3\n"
     "o#2 if [#1 LT 3 OR #1 EQ 4]\n#2=4\no#2 endif\nM2\n", 0, "accepted"),
    ("endrepeat label changed in a repeat of 0.5", HEAD + "#2=3\no#2 repeat [0.5]\n#2=4\n"
     "o#2 endrepeat\nM2\n", 0, "accepted"),
    ("endrepeat label changed in a repeat of 1.5", HEAD + "#2=3\no#2 repeat [1.5]\n#2=4\n"
     "o#2 endrepeat\nM2\n", 6, "error"),
    # review 49a, F8: an o-word only at the start of its line, a closing word of a label no
    # line named (interp_read.cc read_items, interp_o_word.cc control_find_oword)
    ("o-word after a comment", HEAD + "(c) o5 if [1]\nG0 X1\no5 endif\nM2\n", 3, "error"),
    ("o-word after a word", HEAD + "G0 X1 o5 if [1]\nG0 X1\no5 endif\nM2\n", 3, "error"),
    ("words after an o-word", HEAD + "o5 if [1] G0 X1\no5 endif\nM2\n", 3, "error"),
    ("o-word after a comment in a condition not run", HEAD + "o1 if [0]\n(c) o5 if [1]\n"
     "o1 endif\nM2\n", 0, "accepted"),
    ("o-word after a line number", HEAD + "N10 o5 if [1]\nG0 X1\no5 endif\nM2\n", 0,
     "accepted"),
    ("endif with no if", HEAD + "o2 endif\nM2\n", 3, "error"),
    ("endif of another label in an if that runs", HEAD + "#1=5\no#1 if [1]\nG0 X1\n"
     "o6 endif\nM2\n", 6, "error"),
    ("endif of a label closed before", HEAD + "o2 if [1]\no2 endif\no2 endif\nM2\n", 0,
     "accepted"),
    # review 49a, F3: a block known not to run skips to an o-word line of its label, which
    # the file does not have: the file ends in the skip (interp_read.cc read_items)
    ("endif of another label in an if not run", HEAD + "#1=5\no#1 if [0]\nG0 X1\n"
     "o6 endif\nM2\n", 7, "error"),
    ("endrepeat of another label in a repeat of 0", HEAD + "o5 repeat [0]\nG0 X1\n"
     "o6 endrepeat\nM2\n", 6, "error"),
    # review 48, c19: a subroutine whose body ends the program ends it at the call
    ("sub whose body ends with M2", "G21\no<s> sub\nG0 X1\nM2\no<s> endsub\no<s> call\n"
     "G0 X#<nope>\nM2\n", 0, "accepted"),
    ("sub whose body ends with M30, no M2 after its call", "G21\no<s> sub\nG0 X1\nM30\n"
     "o<s> endsub\no<s> call\nG0 X#<nope>\n", 0, "accepted"),
    # review 49a, F4: a setting the block skip deletes may run or not, as the machine's
    # switch is (rs274 -g runs it, rs274 -b -g deletes it): tapegate says neither
    ("endif label changed by a deleted setting", HEAD + "#1=3\no#1 if [1]\n/#1=4\n"
     "o#1 endif\nM2\n", 6, "switch"),
    ("division by a value a deleted setting gives", HEAD + "#1=1\n/#1=0\nG0 X[1/#1]\nM2\n",
     5, "switch"),
    ("division by a value a deleted setting changes", HEAD + "#1=0\n/#1=1\nG0 X[1/#1]\nM2\n",
     5, "switch"),

    # review 50: G53 and M72 where rs274 refuses them wherever the line runs, not elsewhere
    ("G53 after a sub whose nested call leaves G90 before its return", "G21 G90\no<t> sub\n"
     "G90\no<t> endsub\no<s> sub\nG91\no<t> call\no<s> return\no<s> endsub\no<s> call\n"
     "G53 G0 Z0\nM2\n", 0, "accepted"),
    ("G53 after a sub whose nested call leaves G91 before its return", "G21 G91\no<t> sub\n"
     "G91\no<t> endsub\no<s> sub\nG90\no<t> call\no<s> return\no<s> endsub\no<s> call\n"
     "G53 G0 Z0\nM2\n", 11, "error"),
    ("G53 after M72 restores what M73 saved", "G21 G91\nM70\nG90\nM73\nG91\nM72\n"
     "G53 G0 Z0\nM2\n", 0, "accepted"),
    ("G53 after a G91 in its own branch", "G21 G90\n#1=1\no1 if [#1 gt 0]\nG91\nG53 G0 Z0\n"
     "o1 endif\nM2\n", 5, "error"),
    ("G53 after a G91 in a condition equal to the mode", "G21 G91\n#1=1\no1 if [#1 gt 0]\n"
     "G91\no1 endif\nG53 G0 Z0\nM2\n", 6, "error"),
    ("G53 after a G91 in a do body", "G21 G90\no1 do\nG91\no1 while [0]\nG53 G0 Z0\nM2\n",
     5, "error"),
    ("G53 in a body after its own G91", "G21 G90\n#1=0\no1 if [#1 gt 0]\nG91\no1 endif\n"
     "o<s> sub\nG91\nG53 G0 Z0\no<s> endsub\no<s> call\nM2\n", 8, "error"),
    ("G53 in a body defined in G91 called in G90", "G21 G91\no<s> sub\nG53 G0 Z0\n"
     "o<s> endsub\nG90\no<s> call\nM2\n", 0, "accepted"),
    ("G53 in a body defined in G90 called in G91", "G21 G90\no<s> sub\nG53 G0 Z0\n"
     "o<s> endsub\nG91\no<s> call\nM2\n", 3, "error"),
    ("M72 with nothing saved", "G21 G90\nM72\nG53 G0 Z0\nM2\n", 2, "error"),
    ("M72 in a body with nothing saved there", "G21 G90\no<s> sub\nM72\no<s> endsub\nM70\n"
     "o<s> call\nM2\n", 3, "error"),
    ("G53 after a sub with a dead G91 after its return", "G21 G91\no<s> sub\nM70\n"
     "o<s> return\nG91\no<s> endsub\no<s> call\nG53 G0 Z0\nM2\n", 8, "error"),
    ("G53 after a call written in a definition", "G21 G91\no<s0> sub\nM70\nG91\n"
     "o<s0> endsub\no<s1> sub\no<s0> call\no<s1> endsub\nG53 G0 Z0\nM2\n", 9, "error"),
    ("G53 and M72 in one block", "G21 G90\nM70\nG91\nM72 G53 G0 Z0\nM2\n", 4, "error"),
    ("G53 and M72 restoring G91 in one block", "G21 G91\nM70\nG90\nM72 G53 G0 Z0\nM2\n", 0,
     "accepted"),
    # lcnc51: the lines of a condition known true or a loop known to run, up to the block's
    # next o-word line, run in the state the program left; G7/G8 unsettle X alone
    ("a P word in a known-true if", HEAD + "o1 if [1]\nX2 Y2 P1\no1 endif\nM2\n", 4, "error"),
    ("M[3.5] after an unclosed known-true if", HEAD + "o1 if [1]\nM[3.5]\nM2\n", 4, "error"),
    ("a probe in place in a repeat", HEAD + "F10\no1 repeat [2]\nG38.2 Z5\no1 endrepeat\nM2\n",
     5, "error"),
    ("a probe in place in a while's first turn", HEAD + "F10\n#1=0\no1 while [#1 lt 2]\n"
     "G91 G0 Z1\nG90\nG38.2 Z6\n#1=[#1+1]\no1 endwhile\nM2\n", 8, "error"),
    ("a probe in place in the else of a known-true if", HEAD + "F10\no1 if [1]\nG0 Z1\n"
     "o1 else\nG38.2 Z5\no1 endif\nM2\n", 0, "accepted"),
    ("a Z probe in place after G7", HEAD + "F10\nG7\nG0 X1\nG38.2 Z5\nM2\n", 6, "error"),
    # lcnc51: a definition in a loop's body read again on the loop's second turn
    ("a definition in a repeat [2]", HEAD + "o1 repeat [2]\no<s> sub\nG0 X1\no<s> endsub\n"
     "o1 endrepeat\nM2\n", 4, "error"),
    ("a definition in a repeat [2], called", HEAD + "o1 repeat [2]\no<s> sub\nG0 X1\n"
     "o<s> endsub\no<s> call\no1 endrepeat\nM2\n", 4, "error"),
    ("a definition in a do with a true while", HEAD + "o1 do\no<s> sub\nG0 X1\no<s> endsub\n"
     "o1 while [1]\nM2\n", 4, "error"),
    ("a definition in a while of one turn", HEAD + "#1=0\no1 while [#1 lt 1]\no<s> sub\n"
     "G0 X1\no<s> endsub\n#1=1\no1 endwhile\nM2\n", 0, "accepted"),
    ("a definition in a repeat [1]", HEAD + "o1 repeat [1]\no<s> sub\nG0 X1\no<s> endsub\n"
     "o1 endrepeat\nM2\n", 0, "accepted"),
    ("a definition in a repeat whose call ends the program", HEAD + "o1 repeat [2]\no<s> sub\n"
     "M2\no<s> endsub\no<s> call\no1 endrepeat\nM2\n", 0, "accepted"),
    # lcnc51: codes run under cutter radius compensation (interp_convert.cc)
    ("G43 under compensation", HEAD + "G41.1 D1\nG43 H1\nM2\n", 4, "error"),
    ("G40 G43 under compensation", HEAD + "G41.1 D1\nG40 G43 H1\nM2\n", 0, "accepted"),
    ("G55 under compensation", HEAD + "G41.1 D1\nG55\nM2\n", 4, "error"),
    ("G10 L2 P0 under compensation", HEAD + "G41.1 D1\nG10 L2 P0 X1\nM2\n", 4, "error"),
    ("G10 L2 P2 under compensation in G54", HEAD + "G54\nG41.1 D1\nG10 L2 P2 X1\nM2\n", 0,
     "accepted"),
    ("G40 M66 under compensation", HEAD + "G41.1 D1\nG40 M66 P0 L3 Q1\nM2\n", 4, "error"),
    ("M6 under compensation", HEAD + "T1 M6\nG41.1 D1\nT1 M6\nM2\n", 5, "error"),
    ("G41.1 in G19", HEAD + "G19\nG41.1 D1\nM2\n", 4, "error"),
    ("G92 under compensation", HEAD + "G41.1 D1\nG92 X0\nM2\n", 4, "error"),
    # comp52 (review 52, F3): any change of plane under compensation (convert_set_plane), the
    # splines (convert_spline) and G28.1/G30.1 (convert_savehome)
    ("G18 under compensation begun in G17", HEAD + "G41.1 D1\nG18\nM2\n", 4, "error"),
    ("G18 G40 under compensation", HEAD + "G41.1 D1\nG18 G40\nM2\n", 4, "error"),
    ("G17 under compensation begun in G18", HEAD + "G18\nG41.1 D1\nG17\nM2\n", 5, "error"),
    ("G18 under compensation begun in G18", HEAD + "G18\nG41.1 D1\nG18\nG40\nM2\n", 0,
     "accepted"),
    ("G5 under compensation", HEAD + "G41.1 D1\nG1 X5 F100\nG5 X2 Y2 I1 J0 P1 Q1\nM2\n", 5,
     "error"),
    ("G5.1 under compensation", HEAD + "G41.1 D1\nG1 X5 F100\nG5.1 X1 I1 J1\nM2\n", 5,
     "error"),
    ("G5 beside G40", HEAD + "G41.1 D1\nG1 X5 F100\nG5 X2 Y2 I1 J0 P1 Q1 G40\nM2\n", 0,
     "accepted"),
    ("G28.1 under compensation", HEAD + "G41.1 D1\nG28.1\nM2\n", 4, "error"),
    ("G30.1 under compensation", HEAD + "G41.1 D1\nG30.1\nM2\n", 4, "error"),
    # lspl53 (review 53, F12): splines in G17 only, no arc in G17.1-G19.1
    ("G5 in G18", HEAD + "G18 F100\nG5 X3 Y2 I1 J0 P1 Q1\nM2\n", 4, "error"),
    ("G5.1 in G17.1", HEAD + "G17.1 F100\nG5.1 X3 I1 J1\nM2\n", 4, "error"),
    ("G2 in G18.1", HEAD + "G18.1 F100\nG2 X10 Y0 R5\nM2\n", 4, "error"),
    ("G2 in force run in G19.1", HEAD + "G2 X10 Y0 R5 F100\nG19.1\nY1 Z1\nM2\n", 5,
     "error"),
    # review 54, F4 (lcnc56): a spline's feed, checked before its plane (convert_spline)
    ("G5 without a feed rate", HEAD + "G5 X3 Y2 I1 J0 P1 Q1\nM2\n", 3, "error"),
    ("G5.1 at F0", HEAD + "F100\nF0\nG5.1 X3 Y2 I1 J1\nM2\n", 5, "error"),
    ("G5.1 in G93 without F", HEAD + "G93\nG5.1 X3 Y2 I1 J1\nM2\n", 4, "error"),
    ("G5 in G93 and G18 without F", HEAD + "G93 G18\nG5 X3 Y2 I1 J0 P1 Q1\nM2\n", 4,
     "error"),
    ("G5 in G95 at S0 and G5 in G93 with F",
     HEAD + "G95\nG5 X3 Y2 I1 J0 P1 Q1\nG93\nG5 X4 Y2 I1 J0 P1 Q1 F2\nM2\n", 0, "accepted"),
    ("G5.2 in G18 and G2 after G17.1 G17",
     HEAD + "G18 F100\nG5.2 X1 Y1 P1\nX2 Y0 P1\nX3 Y1 P1\nG5.3\nG17.1\nG17\n"
     "G2 X5 Y1 R2\nM2\n", 0, "accepted"),
    # plane55 (review 54, F2): the plane the checker cannot know. A definition does not run
    # where it stands (the main program below it keeps the plane from before its sub); a
    # call and an `if` whose condition is not known leave a plane that may differ unknown
    ("uncalled definition's G18.1 before an arc",
     "o100 sub\nG18.1\nG1 X1 Z1 F100\no100 endsub\nG21 G90 G94\nG0 X0 Y0 Z5\n"
     "G2 X10 Y0 R10 F100\nM2\n", 0, "accepted"),
    ("uncalled definition's G18 before a spline",
     "o100 sub\nG18\nG1 X1 Z1 F100\no100 endsub\nG21 G90 G94\nG0 X0 Y0 Z5\n"
     "G5 X3 Y2 I1 J0 P1 Q1 F100\nM2\n", 0, "accepted"),
    ("uncalled definition's G18 before an R arc of X Y",
     "o100 sub\nG18\nG1 X1 Z1 F100\no100 endsub\nG21 G90 G94\nG0 X0 Y0 Z5\n"
     "G2 Y10 R10 F100\nM2\n", 0, "accepted"),
    ("arc after a call whose body sets G17",
     "o100 sub\nG17\no100 endsub\n" + HEAD + "G18.1\nG1 X1 F100\no100 call\n"
     "G2 X10 Y0 R10\nM2\n", 0, "accepted"),
    ("spline after a call whose body sets G17",
     "o100 sub\nG17\no100 endsub\n" + HEAD + "G18\nG1 X1 F100\no100 call\n"
     "G5 X3 Y2 I1 J0 P1 Q1\nM2\n", 0, "accepted"),
    ("arc after an if of an unknown condition setting G18.1",
     HEAD + "o1 if [#5220 GT 1]\nG18.1\no1 endif\nG2 X10 Y0 R10 F100\nM2\n", 0, "accepted"),
    ("spline after an if of an unknown condition setting G18",
     HEAD + "o1 if [#5220 GT 1]\nG18\no1 endif\nG5 X3 Y2 I1 J0 P1 Q1 F100\nM2\n", 0,
     "accepted"),
    ("spline after an if and else setting G17 and G18",
     "G21 G90 G94\nG0 X0 Y0 Z5\no1 if [#5220 EQ 1]\nG17\no1 else\nG18\no1 endif\n"
     "G5 X3 Y2 I1 J0 P1 Q1 F100\nM2\n", 0, "accepted"),
    ("spline after a while that sets G17, begun in G18",
     HEAD + "G18\no1 while [#5220 LT 2]\nG17\n#5220=2\no1 endwhile\n"
     "G5 X3 Y2 I1 J0 P1 Q1 F100\nM2\n", 0, "accepted"),
    ("spline after a while left by a break in G17",
     HEAD + "G18\no1 while [#5220 LT 3]\nG17\no2 if [#5220 GT 0]\no1 break\no2 endif\nG18\n"
     "o1 endwhile\nG5 X3 Y2 I1 J0 P1 Q1 F100\nM2\n", 0, "accepted"),
    ("arc after an if and else both setting G18.1",
     HEAD + "o1 if [#5220 GT 1]\nG18.1\no1 else\nG18.1\no1 endif\nG2 X10 Y0 R10 F100\nM2\n",
     8, "error"),
    ("spline after an if that sets no plane, in G18",
     HEAD + "G18\no1 if [#5220 GT 1]\nG0 X1\no1 endif\nG5 X3 Y2 I1 J0 P1 Q1 F100\nM2\n",
     7, "error"),
    ("spline after a known-false if setting G17, in G18",
     HEAD + "G18\no1 if [0]\nG17\no1 endif\nG5 X3 Y2 I1 J0 P1 Q1 F100\nM2\n", 7, "error"),
    ("arc in the else of an if setting G17, begun in G18.1",
     HEAD + "G18.1\no1 if [#5220 GT 1]\nG17\no1 else\nG2 X10 Y0 R10 F100\no1 endif\nM2\n",
     7, "error"),
    ("arc in G18.1 after a definition setting G17",
     "o100 sub\nG17\no100 endsub\n" + HEAD + "G18.1\nG2 X10 Y0 R10 F100\nM2\n", 7, "error"),
    ("spline in G18 after a call whose body sets no plane",
     "o100 sub\nG0 X1\no100 endsub\n" + HEAD + "G18\no100 call\nG5 X3 Y2 I1 J0 P1 Q1 F100\nM2\n",
     8, "error"),
    # review 53, F7: compensation turned on in G17.1-G19.1 (the block's own plane first)
    ("G41.1 in G17.1", HEAD + "G17.1\nG41.1 D2\nG1 X5 F100\nG40\nM2\n", 4, "error"),
    ("G42.1 in G18.1", HEAD + "G18.1\nG42.1 D2\nG1 X5 F100\nG40\nM2\n", 4, "error"),
    ("G41.1 beside G17.1", HEAD + "G41.1 D2 G17.1\nG1 X5 F100\nG40\nM2\n", 3, "error"),
    ("G41.1 in G19 after an if that sets no plane",
     HEAD + "G19\no1 if [#5220 GT 1]\nG0 X1\no1 endif\nG41.1 D1\nG1 X1 F100\nG40\nM2\n",
     7, "error"),
    # review 55c, F8: an if/elseif whose taken branch is known leaves that branch's plane
    ("R arc after a known if before an elseif, setting G18",
     HEAD + "o1 if [1]\nG18\no1 elseif [0]\nG19\no1 endif\nG2 Y10 R10 F100\nM2\n", 8,
     "error"),
    ("R arc after a plane chooser of a known parameter, G18",
     HEAD + "#<plane>=2\no1 if [#<plane> EQ 1]\nG17\no1 elseif [#<plane> EQ 2]\nG18\n"
     "o1 elseif [#<plane> EQ 3]\nG19\no1 endif\nG2 Y10 R10 F100\nM2\n", 11, "error"),
    # review 55c, F2: where the plane is not known, the arc checks that need none
    ("mixed R and I after a call whose body sets G18",
     "o100 sub\nG18\no100 endsub\n" + HEAD + "o100 call\nG2 X10 Y0 R10 I5 F100\nM2\n", 7,
     "error"),
    ("mixed R and I in a definition's body",
     "o<arc> sub\nG2 X10 Y0 R10 I5 F100\no<arc> endsub\n" + HEAD + "o<arc> call\nM2\n", 2,
     "error"),
    # review 55c, F5: a body whose every plane code writes the caller's plane leaves it
    ("J centre after a call whose body sets the caller's G18",
     "o100 sub\nG18\nG0 X1\no100 endsub\n" + HEAD
     + "G18\no100 call\nG2 X10 Z0 I5 J0 F100\nM2\n", 9, "error"),
    # review 55c, F6: M72 restores the plane M70 saved
    ("R arc after M72 restores G18",
     HEAD + "G18\nM70\nG17\nM72\nG2 Y10 R10 F100\nM2\n", 7, "error"),
    # review 55c, F3, F4: a G code by an expression, or a parameter not known, may set G17
    ("spline after G[17], in G18",
     HEAD + "G18\nG[17]\nG5 X3 Y2 I1 J0 P1 Q1 F100\nM2\n", 0, "accepted"),
    ("R arc after G#<p> of #5220+16, in G18",
     HEAD + "G18\n#<p>=[#5220+16]\nG#<p>\nG2 Y10 R10 F100\nM2\n", 0, "accepted"),
    ("spline after M72 restores G17",
     HEAD + "F100\nM70\nG18\nG1 X1 Z1\nM72\nG5 X3 Y2 I1 J0 P1 Q1\nM2\n", 0, "accepted"),
    # review 56c, F2, F9: a spline after an M72, whose restored feed mode is not followed
    ("spline under G93 after M72 restores G95",
     HEAD + "F100\nM70\nG95 F0.1\nG93\nM72\nG5 X3 Y2 I1 J0 P1 Q1\nM2\n", 0, "accepted"),
    ("spline under G93 after M72 restores the G95 of a known-true if",
     HEAD + "o1 if [1]\nG95\no1 endif\nM70\nG93\nM72\nG5.1 X1 Y1 I1 J1\nM2\n", 0,
     "accepted"),
    # review 56c (lcnc57): M72 restores the feed mode, the feed rate and the speed M70 saved,
    # with the F only where it differs from rs274's rate (2.9.0's gen_settings); where the
    # restore runs a block of its own, the M72 block's motion does not run
    ("G1 after M72 restores G94 from G93 at the same rate",
     HEAD + "F100\nM70\nG93\nF100\nM72\nG1 X2\nM2\n", 8, "error"),
    ("G1 after M72 restores G94 from a G93 move at the same rate",
     HEAD + "F100\nM70\nG93\nG1 X1 F100\nM72\nG1 X2\nM2\n", 8, "error"),
    ("spline after M72 restores G94 from G95 at the same rate",
     HEAD + "F100\nM70\nG95 F100\nM72\nG5 X3 Y2 I1 J0 P1 Q1\nM2\n", 7, "error"),
    ("spline without F after M72 restores G93",
     HEAD + "G93\nM70\nG94 F100\nM72\nG5.1 X1 Y1 I1 J1\nM2\n", 7, "error"),
    ("G1 in G95 after M72 restores S0",
     HEAD + "G95 F0.1\nM70\nS1000 M3\nM72\nG1 X1\nM2\n", 7, "error"),
    ("G1 beside an M72 with nothing to restore",
     HEAD + "M70\nM72 G1 X1\nM2\n", 4, "error"),
    ("G1 after M72 restores G94 F100 from G93",
     HEAD + "F100\nM70\nG95 F0.1\nG93\nM72\nG1 X3\nM2\n", 0, "accepted"),
    ("G1 after M72 beside G93 restores G94 F100",
     HEAD + "F100\nM70\nG95 F0.1\nM72 G93\nG1 X1\nM2\n", 0, "accepted"),
    ("G5.1 in G95 after a G1",
     HEAD + "S100 M3\nG1 X2 F10\nG95\nG5.1 X1 Y1 I1 J1\nM2\n", 0, "accepted"),
    ("G1 beside an M72 that restores G94",
     HEAD + "F100\nM70\nG93\nM72 G1 X1\nM2\n", 0, "accepted"),
    ("spline beside an M72 that restores G94 F100",
     HEAD + "F100\nM70\nG95 F100\nM72 G5 X3 Y2 I1 J0 P1 Q1\nM2\n", 0, "accepted"),
    # review 57d, F1, F6 (lcnc57b): the motion of a dropped M72 block does not move the
    # tool; a saved rate the restore writes is rounded as ` F%.1f` writes it
    ("arc from where a dropped M72 G1 found the tool, radius differs",
     HEAD + "F100\nM70\nG93\nM72 G1 X1\nG94 G2 X2 Y0 I0.5 J0 F100\nM2\n", 7, "error"),
    ("arc from where a dropped M72 G1 found the tool",
     HEAD + "F100\nM70\nG93\nM72 G1 X1\nG94 G2 X2 Y0 I1 J0 F100\nM2\n", 0, "accepted"),
    ("G1 after M72 restores F0.04 written F0.0",
     HEAD + "F0.04\nM70\nG95 F1\nM72\nG1 X1\nM2\n", 7, "error"),
    # review 57d, F2-F4 (lcnc58): an M72 whose save is not followed leaves what it restores
    # unknown, save where every save that may be in force agrees; the restore may take the
    # place of its block's motion; it restores the spindle and the compensation too
    ("G1 in G95 after M72 whose save an if between unfollows",
     HEAD + "F100\nM70\no1 if [1]\nF200\no1 endif\nG95 F200\nM72\nG1 X1\nM2\n", 0,
     "accepted"),
    ("cycle after M72 G95 whose M70 stands in an if",
     HEAD + "F100\no1 if [1]\nM70\no1 endif\nM72 G95\nG81 X1 Z-1 R1\nM2\n", 0, "accepted"),
    ("G1 in G95 after M72 restores the S0 of an M70 in an if",
     HEAD + "o1 if [1]\nM70\no1 endif\nM72\nG95 F0.1\nG1 X1\nM2\n", 8, "error"),
    ("G1 after an M72 in an if, G93 whether it runs or not",
     HEAD + "G93\nM70\no1 if [1]\nM72\no1 endif\nG1 X1\nM2\n", 8, "error"),
    ("G1 beside an M72 restoring G17", HEAD + "M70\nG18\nM72 G1 X1\nM2\n", 0, "accepted"),
    ("G1 after M72 of a save in a loop whose later turn runs under G94",
     HEAD + "G95\no1 repeat [2]\nM70\nG94\no1 endrepeat\nM72\nG1 X1 F100\nM2\n", 0,
     "accepted"),
    ("G33 after M72 restores M3",
     HEAD + "S1000 M3\nM70\nM5\nM72\nG33 Z-1 K0.1\nM2\n", 0, "accepted"),
    ("cycle after M72 restores G40",
     HEAD + "F100\nM70\nG41.1 D0.1\nG1 X1\nM72\nG81 X1 Z-1 R1\nM2\n", 0, "accepted"),
    ("G33 after M72 and M5", HEAD + "S1000 M3\nM70\nM72\nM5\nG33 Z-1 K0.1\nM2\n", 7,
     "error"),
    # review 58c (lcnc58b): F1, a followed save gives back the direction and compensation it
    # took; F4, no zero kept through G20/G21 (the Z after a cycle is its Z word here)
    ("G33 after M70 and M72, the spindle never on", HEAD + "M70\nM72\nG33 Z-1 K0.1\nM2\n", 5,
     "error"),
    ("cycle after M72 restores G41.1",
     HEAD + "F10\nG41.1 D0.1\nG1 X1\nM70\nM72\nG81 X1 Z-1 R1\nM2\n", 8, "error"),
    # F3, F5: the M72 block's plane runs after the restore, a followed M72 left nothing changed
    ("G1 beside an M72 whose block's G18 runs after it", HEAD + "M70\nM72 G18 G1 X1\nM2\n", 4,
     "error"),
    ("G1 beside a second M72 after a followed one", HEAD + "M70\nM8\nM72\nM72 G1 X1\nM2\n",
     6, "error"),
    ("probe after G20 from a cycle's retract level",
     HEAD + "G0 Z0\nG20 F4\nG81 X1 Z-1 R1\nG38.2 Z-1\nM2\n", 0, "accepted"),
    # review 53, F13 (lcnc57b): G17.1-G19.1 under compensation with no compensated move held
    # stops rs274 at the next move only
    ("G1 in G18.1 under compensation with no move before",
     HEAD + "F100\nG41.1 D2\nG18.1\nG1 X5\nM2\n", 6, "error"),
    ("G18.1 under compensation with no move before its G40",
     HEAD + "F100\nG41.1 D2\nG18.1\nG40\nG1 X5\nM2\n", 0, "accepted"),
    # review 55c, F9 (lcnc57b): a branch that ends in `break` is no way to its `endif`
    ("R arc after an if whose branch breaks in G19, in G18",
     HEAD + "F100\n#<n>=0\no1 while [#<n> LT 1]\n#<n>=[#<n>+1]\nG18\no2 if [#5220 GT 5]\nG19\n"
     "o1 break\no2 endif\nG0 X0 Y0 Z0\nG2 Y10 R10\no1 endwhile\nM2\n", 13, "error"),
    ("R arc of X after a while left by a break in G19",
     HEAD + "F100\n#<n>=0\no1 while [#<n> LT 1]\n#<n>=[#<n>+1]\nG18\no2 if [#5220 GT 5]\nG19\n"
     "o1 break\no2 endif\no1 endwhile\nG0 X0 Y0 Z0\nG2 X10 R10\nM2\n", 0, "accepted"),
    # review 55c, F7 (lcnc56): a call in a branch that ran leaves the elseif after it dead,
    # but not in a loop, whose next turn takes the else
    ("J centre in an elseif after a known-true if with a call",
     "o<sb> sub\nG0 X1\no<sb> endsub\nG21 G18 G90 G40 G94 F100\nG0 X0 Y0 Z5\n"
     "o150 if [1]\no<sb> call\no150 elseif [1]\nG2 X1 Y0 I0.5 J0\no150 endif\nM2\n", 0,
     "accepted"),
    ("J centre in the else of an if with a call, on a while's second turn",
     "o<sb> sub\nG0 X1\no<sb> endsub\nG21 G18 G90 G40 G94 F100\nG0 X0 Y0 Z5\n"
     "#<k>=0\no2 while [#<k> LT 2]\no1 if [#<k> EQ 0]\no<sb> call\no1 else\n"
     "G2 X1 Y0 I0.5 J0\no1 endif\n#<k>=[#<k>+1]\no2 endwhile\nM2\n", 11, "error"),
]
SEED_TOOLS = "T1 P1 D2 Z0 ;\n"


@dataclass
class Seed:
    name: str
    line: int
    expected: str
    rs274: Rs274
    errors: list[Err]
    others: list[Err] = field(default_factory=list)  # warnings and notes on the fault's line
    # rs274 with the block delete switch on (``-b``), for an ``expected`` of "switch"
    rs274_deleting: Rs274 | None = None
    rs274_line: bool = False  # rs274 reports it on the fault's line
    tapegate_line: bool = False  # tapegate's first error is on the fault's line
    same: bool = False  # both report it on the fault's line (or both accept the program)


def seeded(workdir: Path) -> list[Seed]:
    paths = []
    for i, (_, text, _, _) in enumerate(SEEDED):
        path = workdir / f"seed{i:02d}.ngc"
        path.write_text(text)
        paths.append(path)
    found = run_tapegate(paths, "linuxcnc", everything=True)
    seeds = []
    for path, (name, _, line, expected) in zip(paths, SEEDED, strict=True):
        rs = run_rs274(path, workdir, SEED_TOOLS)
        every = sorted(found.get(str(path), []), key=lambda e: e.line)
        errors = [e for e in every if e.severity == "error"]
        others = [e for e in every if e.severity != "error" and e.line == line]
        s = Seed(name, line, expected, rs, errors, others)
        if expected == "error":
            s.rs274_line = not rs.ok and rs.line == line
            s.tapegate_line = bool(errors) and errors[0].line == line
            s.same = s.rs274_line and s.tapegate_line
        elif expected == "switch":
            # (rs274 refuses the line with the switch in one place and runs on in the other:
            # the program's fault is the machine's switch, and tapegate reports no error)
            s.rs274_deleting = run_rs274(path, workdir, SEED_TOOLS, ("-b",))
            one_way = [r for r in (rs, s.rs274_deleting) if not r.ok]
            s.rs274_line = len(one_way) == 1 and one_way[0].line == line
            s.same = s.rs274_line and not errors
        else:
            s.same = rs.ok and not errors
        seeds.append(s)
    return seeds


# --- the arc tolerance -------------------------------------------------------------------------

ARC_POINTS = [("mm", 1.0), ("mm", 100.0), ("mm", 5000.0), ("inch", 0.1), ("inch", 10.0),
              ("inch", 500.0)]
# R arcs: half the chord, the radius short of it by the excess measured
R_POINTS = [("mm", 5.0), ("mm", 500.0), ("inch", 5.0), ("inch", 50.0)]


def arc_program(units: str, radius: float, d: float) -> str:
    """An arc from (0,0) about (r,0) to (2r+d,0): start radius r, end radius r+d."""
    code = "G21" if units == "mm" else "G20"
    return (f"{code} G17 G90 G94\nG0 X0 Y0 Z1\nG2 X{2 * radius + d:.9f} Y0 I{radius:.9f} J0 F10\n"
            "M2\n")


def r_arc_program(units: str, half: float, d: float) -> str:
    """An arc by R from (0,0) to (2 half, 0) whose radius is d short of half the chord."""
    code = "G21" if units == "mm" else "G20"
    return (f"{code} G17 G90 G94\nG0 X0 Y0 Z1\nG2 X{2 * half:.9f} Y0 R{half - d:.9f} F10\n"
            "M2\n")


def _rs_accepts(units: str, radius: float, d: float, workdir: Path, form: str) -> bool:
    path = workdir / "arc.ngc"
    path.write_text((arc_program if form == "I J" else r_arc_program)(units, radius, d))
    rc, _ = _rs274_raw(path, "", workdir)
    return rc == 0


def _tg_accepts(units: str, radius: float, d: float, workdir: Path, form: str) -> bool:
    path = workdir / "arc_tg.ngc"
    path.write_text((arc_program if form == "I J" else r_arc_program)(units, radius, d))
    errors = run_tapegate([path], "linuxcnc").get(str(path), [])
    rule = ARC_RADIUS_MISMATCH if form == "I J" else ARC_RADIUS_TOO_SHORT
    return not any(e.rule == rule for e in errors)


@dataclass
class ArcPoint:
    units: str
    radius: float  # I J: the start radius; R: half the chord
    rs274_limit: float  # the largest excess rs274 accepts (to 1e-7 of the unit): of the end
    # radius over the start radius (I J), of half the chord over the radius (R)
    tapegate_inside: bool  # tapegate accepts the arc 0.5 % inside rs274's limit
    tapegate_outside: bool  # tapegate refuses it 0.5 % outside
    form: str = "I J"


def arcs(workdir: Path) -> list[ArcPoint]:
    points = []
    for form, table in (("I J", ARC_POINTS), ("R", R_POINTS)):
        for units, radius in table:
            lo, hi = 0.0, radius  # rs274 accepts lo, refuses hi
            while hi - lo > 1e-7:
                mid = (lo + hi) / 2
                ok = _rs_accepts(units, radius, mid, workdir, form)
                lo, hi = (mid, hi) if ok else (lo, mid)
            points.append(ArcPoint(units, radius, round(lo, 7),
                                   _tg_accepts(units, radius, lo * 0.995, workdir, form),
                                   not _tg_accepts(units, radius, lo * 1.005, workdir, form),
                                   form))
    return points


# --- report ------------------------------------------------------------------------------------

def short(name: str) -> str:
    for root in (NCFILES, CORPUS):
        if name.startswith(str(root) + os.sep):
            return os.path.relpath(name, root)
    return name


def errs(errors: list[Err], limit: int = 4) -> str:
    if not errors:
        return "-"
    counted = Counter(f"{e.rule}:{e.line}" for e in errors)
    text = " ".join(list(counted)[:limit])
    return text + (f" (+{len(counted) - limit})" if len(counted) > limit else "")


def print_table(rows: list[Row], seeds: list[Seed], points: list[ArcPoint]) -> None:
    if rows:
        print(f"{'file':44} {'kind':13} {'profile':12} {'rs274':34} {'tapegate errors':32} verdict")
        for r in rows:
            rs = ("ok" if r.rs274.ok else
                  f"L{r.rs274.line if r.rs274.line is not None else '?'} {r.rs274.message}")
            print(f"{short(r.name)[:44]:44} {r.kind:13} {r.profile:12} {rs[:34]:34} "
                  f"{errs(r.errors)[:32]:32} {r.verdict}")
        print()
        for r in rows:
            if r.verdict != "disagree":
                continue
            rules: dict[str, list[Err]] = {}
            for e in r.compared:
                rules.setdefault(e.rule, []).append(e)
            if not r.rs274.ok and not r.compared:
                print(f"  {short(r.name)}:{r.rs274.line}: rs274 {r.rs274.message}; "
                      "tapegate: no error there")
            for rule, found in rules.items():
                lines = ",".join(str(e.line) for e in found[:6]) + (",..." if len(found) > 6
                                                                    else "")
                print(f"  {short(r.name)}:{lines}: {rule} x{len(found)} {found[0].message}")
        print()
        judged = [r for r in rows if r.verdict != "excluded"]
        kinds = Counter(r.kind for r in rows)
        print(f"files {len(rows)}: compared {len(judged)}, "
              f"agree {sum(r.verdict == 'agree' for r in judged)}, "
              f"disagree {sum(r.verdict == 'disagree' for r in judged)}; "
              + ", ".join(f"{k} {n}" for k, n in sorted(kinds.items())))
        by_rule = Counter(e.rule for r in judged if r.verdict == "disagree" for e in r.compared)
        if by_rule:
            print("tapegate errors where rs274 disagrees, by rule: "
                  + ", ".join(f"{k} {n}" for k, n in by_rule.most_common()))
        print()
    if seeds:
        print(f"{'seeded fault':42} {'fault':5} {'rs274':44} {'tapegate':22} same line")
        for s in seeds:
            rs = "ok" if s.rs274.ok else f"L{s.rs274.line} {s.rs274.message}"
            tg = errs(s.errors) if s.errors else "-" + "".join(
                f" ({e.severity} {e.rule})" for e in s.others)
            print(f"{s.name:42} {('L' + str(s.line)) if s.line else '-':5} {rs[:44]:44} "
                  f"{tg[:22]:22} {'yes' if s.same else 'NO'}")
        print(f"seeded: {len(seeds)}, both report the same line (or both accept): "
              f"{sum(s.same for s in seeds)}")
        print()
    if points:
        print(f"{'form':4} {'units':6} {'radius':>8} {'rs274 accepts up to':>20} "
              f"{'tapegate inside ok':>19} {'outside refused':>16}")
        for p in points:
            print(f"{p.form:4} {p.units:6} {p.radius:8g} {p.rs274_limit:20.7f} "
                  f"{str(p.tapegate_inside):>19} {str(p.tapegate_outside):>16}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", action="store_true", help="machine-readable output")
    ap.add_argument("--only", choices=["samples", "corpus", "seeded", "arcs"], action="append")
    ap.add_argument("--samples", type=Path, default=NCFILES)
    ap.add_argument("--corpus", type=Path, default=CORPUS)
    args = ap.parse_args(argv)
    if rs274_exe() is None:
        print("rs274 is not installed (Debian package linuxcnc-uspace): nothing to compare",
              file=sys.stderr)
        return 0
    only = set(args.only or ["samples", "corpus", "seeded", "arcs"])
    with tempfile.TemporaryDirectory(prefix="rs274_compare.") as tmp:
        work = Path(tmp)
        files = (samples(args.samples) if "samples" in only else []) + \
                (corpus(args.corpus) if "corpus" in only else [])
        rows = compare_files(files, work) if files else []
        seeds = seeded(work) if "seeded" in only else []
        points = arcs(work) if "arcs" in only else []
    if args.json:
        out = {"files": [asdict(r) | {"name": short(r.name)} for r in rows],
               "seeded": [asdict(s) for s in seeds], "arcs": [asdict(p) for p in points],
               "summary": {"files": len(rows),
                           "agree": sum(r.verdict == "agree" for r in rows),
                           "disagree": sum(r.verdict == "disagree" for r in rows),
                           "excluded": sum(r.verdict == "excluded" for r in rows)}}
        json.dump(out, sys.stdout, indent=1)
        print()
    else:
        print_table(rows, seeds, points)
    return 0


if __name__ == "__main__":
    sys.exit(main())
