"""The measure of the "one fast core" issue: whole commands, on a synthetic and a real program,
beside LinuxCNC's interpreter, in one run.

    .venv/bin/python benchmarks/core.py [--blocks 1000000] [--sizes 100000,1000000]
                                        [--only check,convert,parse,api,rs274,peer] [--keep DIR]
    .venv/bin/python benchmarks/core.py --every [--match TEXT] [--sizes 1000000] [--tsv FILE]
                                        [--format F] [--repeat N] [--before TAPEGATE]

``--only`` also takes ``check-text``, ``check-jsonl`` and ``check-sarif`` (the check's other
output formats) and ``restart``.

Programs (built here, in a temporary folder, deleted afterwards unless ``--keep``):

- synthetic: ``benchmarks/program.py`` with ``--clean`` (what a CAM post writes);
- real: ``benchmarks/real_program.py``, the corpus's Fusion 360 Fanuc-post program repeated (needs
  ``../shared/corpus``; skipped with a message without it).

Each command runs in its own process under ``/usr/bin/time -v``: seconds are wall time of the
whole process (start-up included), peak MB its maximum resident set. The commands:

- ``tapegate check FILE -p fanuc-mill --format json > /dev/null`` (all rules);
- ``tapegate convert FILE -o OUT --from fanuc-mill --to implicit-inch.toml --units inch``
  (explicit metric to implicit inch, leading zeros omitted);
- ``tapegate parse FILE --profile fanuc-mill --summary``;
- the Python API: iterating ``parse_stream`` over Block objects;
- ``restart`` (only with ``--only restart``): the walk of ``send --restart-at`` to a block 100
  lines before the program's end, planned in the API (``postproc.restart.plan_restart_text``);
- ``rs274 -g -t TOOLS FILE /dev/null`` on the real program (Debian package linuxcnc-uspace);
- peer ``gcodeparser`` (``pip install gcodeparser``) reading the same programs, where installed.

``--every``: every CAM program of ``../shared/corpus`` and ``../shared/corpus/shops`` longer than
1,000 blocks whose family has a profile (``EVERY_TOP`` below, as tests/test_dialects.py matches
them; ``shops/families.tsv``: fanuc, haas, linuxcnc, sinumerik, a lathe program on the family's
lathe profile), each repeated to the size as ``real_program.py`` repeats its source, then:
``check --format json`` on the family's profile; ``convert`` to the other units and implicit
decimal on the same profile (``--from P --to P --units inch|metric --decimal implicit
--allow-unconverted``: a lathe's T0101 or a Sinumerik's G601 fits no generic target; explicit
decimals for a control that reads no implicit ones, LinuxCNC and SINUMERIK, which refuse
``--decimal implicit``: :func:`decimal_style`); and
LinuxCNC's ``rs274`` on the same program (``real_program.linuxcnc_line`` applied; its tool
table as ``rs274_compare.py`` writes it). Each is shown with its wall and CPU (user + system)
seconds; the rates and the ratio to rs274 are of CPU time, which a shared machine's load does not
stretch. ``--match``
keeps the programs whose name contains TEXT, ``--part K/N`` every N-th from the K-th (to split
a run). ``--format F`` checks with that report format; ``--repeat N`` runs each check N times
and keeps the run of least CPU; ``--before TAPEGATE`` times another build's check of the same
program in turn with this one's (before, after, before, after...), its figures in the last
columns: a before-and-after on a loaded machine, where the load changes between two runs.
rs274 stops at the first block it cannot read: its exit code and message are shown, and such
a time is no comparison.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

import program  # noqa: E402
from real_program import CorpusMissing, build, corpus_dir  # noqa: E402
from rs274_compare import tool_table as rs274_tools  # noqa: E402

IMPLICIT_INCH = ('name = "implicit-inch"\n'
                 'detailed = "%:/ N07 G02 X+044 Y+044 Z+044 I+044 J+044 K+044 F042 S05 T02 M02*"\n'
                 'units_codes = "G20/G21"\nunits = "inch"\n')
# The corpus's own programs longer than 1,000 blocks, with their family's profile (as
# tests/test_dialects.py MATCHING has them; TopFridge, a foam cutter's, has no family here)
EVERY_TOP = {
    "AplicacionWebDePrueba__1010.nc": "haas-mill",
    "CNC-GCode-Milling-and-Lathe__2001.nc": "fanuc-lathe",
    "Praktikum-CAD-CAM-Modul-12__1001.nc": "haas-mill",
    "enier-cnc__1006.nc": "haas-mill",
    "GCodeWorkShop__TOKARKA.NC": "fanuc-lathe",
    "vip74120.github.io__1223.NC": "fanuc-mill",
    "Five-Axis-Milling-Dataset__Bottle_opener_Flaschenoeffner.txt": "sinumerik-840d",
}
FAMILY = {"fanuc": "fanuc-mill", "haas": "haas-mill", "linuxcnc": "linuxcnc",
          "sinumerik": "sinumerik-840d"}
LATHE = {"fanuc": "fanuc-lathe", "haas": "haas-lathe"}
API = ("import sys\nfrom formats.parser import parse_stream, read_chunks, decode_chunks\n"
       "from formats.profile import load_profile\n"
       "n = sum(1 for b in parse_stream(decode_chunks(read_chunks(sys.argv[1])),"
       " load_profile('fanuc-mill').dialect))\n")
# send --restart-at's walk to the block: a restart planned 100 lines before the program's end
RESTART = ("import sys\nfrom formats.profile import load_profile\n"
           "from formats.source import Source\n"
           "from postproc.restart import RestartRefused, plan_restart_text\n"
           "lines = sum(1 for _ in open(sys.argv[1], 'rb'))\n"
           "try:\n    plan = plan_restart_text(Source(sys.argv[1]).chunks(),"
           " load_profile('fanuc-mill'), lines - 100)\n    print(plan.preamble)\n"
           "except RestartRefused as exc:\n    print(exc)\n")
PEER = ("import re, sys\nfrom gcodeparser import parse_gcode_lines\n"
        "text = re.sub(r'\\.(?![0-9])', '.0', open(sys.argv[1]).read())\n"
        "for _ in parse_gcode_lines(text):\n    pass\n")


def timed(argv: list[str], stdout: str | None = None) -> tuple[float, float, int]:
    """(seconds, peak MB, exit code) of a command under /usr/bin/time -v."""
    seconds, rss, rc, _ = timed_cpu(argv, stdout)
    return seconds, rss, rc


def timed_cpu(argv: list[str], stdout: str | None = None,
              said: list[str] | None = None,
              env: dict[str, str] | None = None) -> tuple[float, float, int, float]:
    """(seconds, peak MB, exit code, CPU seconds: user + system) of a command under
    /usr/bin/time -v. On a machine shared with other work the wall time grows with the others'
    load; the CPU time of a one-thread command is what it would take alone."""
    out = open(stdout, "w") if stdout else subprocess.DEVNULL  # noqa: SIM115
    try:
        proc = subprocess.run(["/usr/bin/time", "-v", *argv], stdout=out,
                              stderr=subprocess.PIPE, text=True, stdin=subprocess.DEVNULL,
                              check=False, cwd=ROOT, env=env)
    finally:
        if stdout:
            out.close()  # type: ignore[union-attr]
    err = proc.stderr
    if said is not None:  # what the command itself wrote on stderr, before time's report
        said.extend(err.split("\tCommand being timed:")[0].strip().splitlines())
    wall = re.search(r"Elapsed \(wall clock\) time.*: (?:(\d+):)?(\d+):(\d+(?:\.\d+)?)", err)
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)", err)
    cpu = sum(float(m) for m in re.findall(r"(?:User|System) time \(seconds\): ([\d.]+)", err))
    seconds = 0.0
    if wall:
        hours = float(wall.group(1) or 0)
        seconds = hours * 3600 + float(wall.group(2)) * 60 + float(wall.group(3))
    return seconds, (int(rss.group(1)) / 1024 if rss else 0.0), proc.returncode, cpu


def every_program(min_blocks: int = 1000) -> list[tuple[Path, str]]:
    """(program, profile) for every corpus CAM program longer than ``min_blocks`` lines whose
    family has a profile, shortest first."""
    corpus = corpus_dir()
    found = [(corpus / name, prof) for name, prof in EVERY_TOP.items()]
    families = corpus / "shops" / "families.tsv"
    for row in families.read_text("utf-8").splitlines():
        family, name, note = (row.split("\t") + ["", ""])[:3]
        if family in FAMILY:
            lathe = "lathe" in note.lower() and family in LATHE
            found.append((corpus / "shops" / name, LATHE[family] if lathe else FAMILY[family]))
    sized = [(sum(1 for _ in p.open("rb")), p, prof) for p, prof in found if p.is_file()]
    return [(p, prof) for n, p, prof in sorted(sized) if n > min_blocks]


def is_inch(path: Path) -> bool:
    """Whether the program selects inch (G20/G70) before metric (G21/G71)."""
    head = re.search(rb"(?<![A-Z0-9.])G(20|21|70|71)(?![0-9])", path.read_bytes())
    return bool(head) and head.group(1) in (b"20", b"70")


def decimal_style(profile: str) -> str:
    """``implicit``, or ``explicit`` for a control that reads a number without a point as a
    whole number (``formats.conversion.WHOLE_WITHOUT_POINT``: convert refuses implicit there)."""
    from formats.conversion import WHOLE_WITHOUT_POINT
    from formats.profile import load_profile

    family = load_profile(profile).dialect.family
    return "explicit" if family in WHOLE_WITHOUT_POINT else "implicit"


def run_every(args: argparse.Namespace, work: Path, tapegate: str) -> None:
    """The ``--every`` run: see the module's docstring."""
    rs274 = shutil.which("rs274")
    out = open(args.tsv, "a") if args.tsv else None  # noqa: SIM115
    print(f"{'program':<40} {'profile':<14} {'lines':>6} | {'check s':>7} {'cpu':>5} "
          f"{'/s (cpu)':>10} {'MB':>5} {'rc':>2} | {'conv s':>6} {'cpu':>5} {'/s (cpu)':>10} "
          f"{'MB':>5} {'rc':>2} | {'rs274':>6} {'cpu':>5} {'rc':>2} {'x':>5}"
          + (f" | {'before':>5} {'/s (cpu)':>10} {'MB':>5} rc" if args.before else ""),
          flush=True)
    try:
        part, parts = (int(n) for n in args.part.split("/"))
        for index, (source, prof) in enumerate(every_program()):
            if args.match and args.match not in source.name or index % parts != part - 1:
                continue
            lines = sum(1 for _ in source.open("rb"))
            for size in (int(s) for s in args.sizes.split(",")):
                path, ref = work / "every.nc", work / "every-linuxcnc.nc"
                try:
                    build(path, size, source=source)
                    if "rs274" in args.only:
                        build(ref, size, source=source, linuxcnc=True)
                except ValueError as exc:
                    print(f"{source.name[:40]:<40} skipped: {exc}", flush=True)
                    break
                inch = is_inch(source)
                none: tuple[float, float, int, float] = (0.0, 0.0, -1, 0.0)
                check = conv = before = none
                if "check" in args.only:
                    # --repeat: the run of least CPU of each; --before: its check in turn
                    for _ in range(args.repeat):
                        for which in ([args.before] if args.before else []) + [tapegate]:
                            t = timed_cpu([which, "check", str(path), "-p", prof, "--format",
                                           args.format])
                            if which == tapegate and (check is none or t[3] < check[3]):
                                check = t
                            elif which != tapegate and (before is none or t[3] < before[3]):
                                before = t
                conv_said: list[str] = []
                if "convert" in args.only:
                    conv = timed_cpu([tapegate, "convert", str(path), "-o", str(work / "out.nc"),
                                      "--force", "--from", prof, "--to", prof, "--units",
                                      "metric" if inch else "inch", "--decimal",
                                      decimal_style(prof), "--allow-unconverted"],
                                     said=conv_said)
                lcnc: tuple[float, float, int, float] = (0.0, 0.0, -1, 0.0)
                lcnc_said: list[str] = []
                if rs274 and "rs274" in args.only:
                    # rs274_compare's table: T1-T99 and every T of the program, diameter 0
                    # (a cutter compensation entry move is never "not greater than the radius")
                    table = work / "tools.tbl"
                    table.write_text(rs274_tools(source.read_text("latin-1")))
                    lcnc = timed_cpu([rs274, "-g", "-t", str(table), str(ref), "/dev/null"],
                                     said=lcnc_said)
                ratio = lcnc[3] / check[3] if check[3] and lcnc[2] == 0 else 0.0
                row = (f"{source.name[:40]:<40} {prof:<14} {lines:>6} | {check[0]:>7.2f} "
                       f"{check[3]:>5.2f} {size / max(check[3], 1e-3):>10,.0f} {check[1]:>5.1f} "
                       f"{check[2]:>2} | {conv[0]:>6.2f} {conv[3]:>5.2f} "
                       f"{size / max(conv[3], 1e-3):>10,.0f} {conv[1]:>5.1f} {conv[2]:>2} | "
                       f"{lcnc[0]:>6.2f} {lcnc[3]:>5.2f} {lcnc[2]:>2} {ratio:>5.2f}")
                if args.before:  # the other build's check: CPU, rate, peak MB, exit code
                    row += (f" | {before[3]:>5.2f} {size / max(before[3], 1e-3):>10,.0f} "
                            f"{before[1]:>5.1f} {before[2]:>2}")
                print(row, flush=True)
                why = []
                if conv[2] > 0:  # the conversion refused: why (its first message)
                    why.append("convert: " + next((ln for ln in conv_said if ":" in ln), "?"))
                if lcnc[2] > 0:  # rs274 stopped: the block and its message
                    why.append("rs274: " + " / ".join(lcnc_said[-2:]))
                for line in why:
                    print(f"    {line[:150]}", flush=True)
                if out:
                    out.write("\t".join(str(v) for v in (
                        source.name, prof, lines, size, f"{check[0]:.2f}", f"{check[3]:.2f}",
                        f"{check[1]:.1f}", check[2], f"{conv[0]:.2f}", f"{conv[3]:.2f}",
                        f"{conv[1]:.1f}", conv[2], f"{lcnc[0]:.2f}", f"{lcnc[3]:.2f}",
                        f"{lcnc[1]:.1f}", lcnc[2], " | ".join(why),
                        *((f"{before[3]:.2f}", f"{before[1]:.1f}", before[2])
                          if args.before else ()))) + "\n")
                    out.flush()
                for done in (path, ref, work / "out.nc"):
                    done.unlink(missing_ok=True)
    finally:
        if out:
            out.close()


def tool_table(path: Path, table: Path) -> None:
    tools = sorted({int(t) for t in re.findall(r"\bT(\d+)", path.read_text(errors="replace"))})
    table.write_text("".join(f"T{t} P{t} D6.0 Z0 ;\n" for t in tools or [1]))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--sizes", default="1000000", help="comma-separated block counts")
    parser.add_argument("--only", default="check,convert,parse,api,rs274,peer")
    parser.add_argument("--keep", help="keep the programs in this folder")
    parser.add_argument("--every", action="store_true",
                        help="every corpus CAM program over 1,000 blocks (see above)")
    parser.add_argument("--match", default="", help="with --every: names containing this")
    parser.add_argument("--tsv", help="with --every: append the figures to this file")
    parser.add_argument("--part", default="1/1", metavar="K/N",
                        help="with --every: the K-th of N parts of the programs (every N-th)")
    parser.add_argument("--tapegate", default=str(ROOT / ".venv" / "bin" / "tapegate"),
                        help="the tapegate command measured (default: .venv's)")
    parser.add_argument("--before", metavar="TAPEGATE",
                        help="with --every: another build's tapegate command, its check timed "
                             "in turn with this one's (its CPU, rate, MB, rc: the last columns)")
    parser.add_argument("--repeat", type=int, default=1, metavar="N",
                        help="with --every: each check N times, the run of least CPU shown")
    parser.add_argument("--format", default="json", choices=["text", "json", "jsonl", "sarif"],
                        help="with --every: the check's --format (default json)")
    args = parser.parse_args()
    only = set(args.only.split(","))
    tapegate = args.tapegate
    python = str(ROOT / ".venv" / "bin" / "python")
    work = Path(args.keep or tempfile.mkdtemp(prefix="tapegate-bench-"))
    work.mkdir(parents=True, exist_ok=True)
    if args.every:
        try:
            run_every(args, work, tapegate)
        finally:
            if not args.keep:
                shutil.rmtree(work, ignore_errors=True)
        return 0
    target = work / "implicit-inch.toml"
    target.write_text(IMPLICIT_INCH)
    rs274 = shutil.which("rs274")
    peer = subprocess.run([python, "-c", "import gcodeparser"], capture_output=True,
                          check=False).returncode == 0
    print(f"{'program':<22} {'command':<34} {'seconds':>8} {'blocks/s':>11} {'peak MB':>8} rc")
    for size in (int(s) for s in args.sizes.split(",")):
        programs: list[tuple[str, Path]] = []
        synthetic = work / f"synthetic-{size}.nc"
        if not synthetic.exists():
            program.write(str(synthetic), size, clean=True)
        programs.append(("synthetic", synthetic))
        real = work / f"real-{size}.nc"
        try:
            if not real.exists():
                build(real, size)
            programs.append(("real", real))
        except CorpusMissing as exc:
            print(f"(real program skipped: {exc})")
        for name, path in programs:
            label = f"{name} {size:,}"
            jobs: list[tuple[str, list[str], str | None]] = []
            if "check" in only:
                jobs.append(("check --format json", [tapegate, "check", str(path), "-p",
                                                     "fanuc-mill", "--format", "json"], None))
            for fmt in ("text", "jsonl", "sarif"):
                if f"check-{fmt}" in only:
                    jobs.append((f"check --format {fmt}",
                                 [tapegate, "check", str(path), "-p", "fanuc-mill", "--format",
                                  fmt], None))
            if "convert" in only:
                jobs.append(("convert metric->implicit inch",
                             [tapegate, "convert", str(path), "-o", str(work / "out.nc"),
                              "--force", "--from", "fanuc-mill", "--to", str(target), "--units",
                              "inch"], None))
            if "parse" in only:
                jobs.append(("parse --summary", [tapegate, "parse", str(path), "--profile",
                                                 "fanuc-mill", "--summary"], None))
            if "api" in only:
                jobs.append(("API: parse_stream Blocks", [python, "-c", API, str(path)], None))
            if "restart" in only:
                jobs.append(("restart near the end", [python, "-c", RESTART, str(path)], None))
            if "peer" in only and peer:
                jobs.append(("peer gcodeparser", [python, "-c", PEER, str(path)], None))
            if "rs274" in only and rs274 and name == "real":
                table = work / "tools.tbl"
                tool_table(path, table)
                jobs.append(("LinuxCNC rs274", [rs274, "-g", "-t", str(table), str(path),
                                                "/dev/null"], None))
            for command, argv, stdout in jobs:
                seconds, rss, rc = timed(argv, stdout)
                rate = size / seconds if seconds else 0
                print(f"{label:<22} {command:<34} {seconds:>8.2f} {rate:>11,.0f} {rss:>8.1f} {rc}",
                      flush=True)
            if (work / "out.nc").exists():
                os.unlink(work / "out.nc")
    if not args.keep:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
