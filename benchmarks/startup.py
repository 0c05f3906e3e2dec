"""Start-up of a one-file command: ``tapegate check FILE -p fanuc-mill`` of a 2,000-block program
(or, with ``--command convert``, ``tapegate convert FILE -o OUT --force --from fanuc-mill --to
fanuc-mill --units inch``).

    .venv/bin/python benchmarks/startup.py [--build LABEL=CHECKOUT ...] [--runs 21]
                                           [--importtime 7] [--no-callgrind] [--blocks 2000]
                                           [--profile fanuc-mill] [--top 12]
                                           [--command check|convert]

The program is ``real_program.py --blocks 2000`` (the corpus's Praktikum program's first 2,000
blocks), written to a scratch folder. Each build is a checkout with its built extension
(``formats/_core*.so``), put first on ``PYTHONPATH`` for its own ``tapegate`` script: the one
pip writes for the entry point its ``pyproject.toml`` names (``[project.scripts]``), written to
the scratch folder for the virtual environment's Python (default: this checkout, as ``now``).
Several builds are measured in the same run, their runs interleaved, so the machine's load
falls on each alike. For each build:

- ``wall``: the whole command (``tapegate check FILE -p P``, its output captured), the median
  and minimum of ``--runs`` runs, ``.pyc`` files written (``PYTHONDONTWRITEBYTECODE`` unset) and
  one run first to write them;
- ``instructions``: the whole process under ``valgrind --tool=callgrind`` (no toggle: start-up
  included), which the load does not change;
- ``-X importtime``: the modules imported, and the sum of their self times, each module's the
  least of ``--importtime`` runs, with the part of tapegate's own packages; then the ``--top``
  largest self times.

Beside them, in the same run: ``python -c pass``, ``python -c "import click"`` and LinuxCNC's
``rs274 -g -t TOOLS FILE /dev/null`` on the same file (its tool table as ``rs274_compare.py``
writes it; for ``check``), and the load average (``os.getloadavg``) at the start and end. The
outputs of the builds are compared (stdout, stderr, exit code): a build that answers
differently is reported. Exit 0, or 2 when the corpus (or valgrind, unless
``--no-callgrind``) is missing.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

from real_program import CorpusMissing, build  # noqa: E402
from rs274_compare import tool_table  # noqa: E402

PYTHON = Path(sys.executable)
OWN = {"formats", "postproc", "dnc", "tapegate"}  # tapegate's packages, in -X importtime


def env_for(checkout: Path | None) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}
    if checkout is None:
        env.pop("PYTHONPATH", None)
    else:
        env["PYTHONPATH"] = str(checkout)
    return env


def console_script(checkout: Path, folder: Path) -> Path:
    """``folder/tapegate``: the script pip installs for ``checkout``'s entry point."""
    import tomllib

    project = tomllib.loads((checkout / "pyproject.toml").read_text())["project"]
    module, func = project["scripts"]["tapegate"].split(":")
    folder.mkdir(parents=True, exist_ok=True)
    script = folder / "tapegate"
    script.write_text(f"#!{PYTHON}\nimport sys\nfrom {module} import {func}\n"
                      f"if __name__ == '__main__':\n"
                      f"    sys.argv[0] = sys.argv[0].removesuffix('.exe')\n"
                      f"    sys.exit({func}())\n")
    script.chmod(0o755)
    return script


def wall(argv: list[str], env: dict[str, str], cwd: Path) -> tuple[float, bytes, bytes, int]:
    start = time.perf_counter()
    p = subprocess.run(argv, env=env, cwd=cwd, capture_output=True, stdin=subprocess.DEVNULL,
                       check=False)
    return time.perf_counter() - start, p.stdout, p.stderr, p.returncode


def instructions(argv: list[str], env: dict[str, str], cwd: Path) -> int:
    p = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", *argv],
                       env=env, cwd=cwd, capture_output=True, text=True,
                       stdin=subprocess.DEVNULL, check=False)
    found = re.search(r"Collected : (\d+)", p.stderr)
    if not found:
        raise SystemExit(f"startup: callgrind gave no count for {' '.join(argv)}:\n{p.stderr}")
    return int(found.group(1))


def importtimes(argv: list[str], env: dict[str, str], cwd: Path, runs: int) -> dict[str, int]:
    """Each module's least self time (microseconds) over ``runs`` runs under -X importtime."""
    least: dict[str, int] = {}
    for _ in range(runs):
        p = subprocess.run([str(PYTHON), "-X", "importtime", *argv], env=env, cwd=cwd,
                           capture_output=True, text=True, stdin=subprocess.DEVNULL, check=False)
        for line in p.stderr.splitlines():
            m = re.match(r"import time:\s+(\d+) \|\s+\d+ \|\s*(\S+)", line)
            if m:
                name, us = m.group(2), int(m.group(1))
                least[name] = min(us, least.get(name, us))
    return least


def ms(seconds: float) -> str:
    return f"{seconds * 1000:.1f}"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", action="append", default=[], metavar="LABEL=CHECKOUT")
    parser.add_argument("--runs", type=int, default=21)
    parser.add_argument("--importtime", type=int, default=7)
    parser.add_argument("--no-callgrind", dest="callgrind", action="store_false")
    parser.add_argument("--blocks", type=int, default=2000)
    parser.add_argument("--profile", default="fanuc-mill")
    parser.add_argument("--top", type=int, default=12)
    parser.add_argument("--command", choices=["check", "convert"], default="check")
    args = parser.parse_args()
    builds = [(b.split("=", 1)[0], Path(b.split("=", 1)[1]).resolve()) for b in args.build
              ] or [("now", ROOT)]
    if args.callgrind and not shutil.which("valgrind"):
        print("startup: valgrind is not installed (or give --no-callgrind)", file=sys.stderr)
        return 2
    rs274 = shutil.which("rs274")
    with tempfile.TemporaryDirectory(prefix="tapegate-startup-") as tmp:
        work = Path(tmp)
        program = work / "program.nc"
        try:
            built = build(program, args.blocks)
        except CorpusMissing as exc:
            print(f"startup: {exc}", file=sys.stderr)
            return 2
        (work / "tools.tbl").write_text(tool_table(program.read_text("latin-1")))
        check = (["check", program.name, "-p", args.profile] if args.command == "check" else
                 ["convert", program.name, "-o", "converted.nc", "--force", "--from",
                  args.profile, "--to", args.profile, "--units", "inch"])
        scripts = {label: console_script(path, work / f"script-{n}")
                   for n, (label, path) in enumerate(builds)}
        jobs: list[tuple[str, list[str], dict[str, str]]] = [
            (label, [str(scripts[label]), *check], env_for(path)) for label, path in builds]
        jobs.append(("python -c pass", [str(PYTHON), "-c", "pass"], env_for(None)))
        jobs.append(("python -c 'import click'", [str(PYTHON), "-c", "import click"],
                     env_for(None)))
        if rs274 and args.command == "check":
            jobs.append(("rs274 -g", [rs274, "-g", "-t", "tools.tbl", program.name, "/dev/null"],
                         env_for(None)))
        load_before = os.getloadavg()
        answers = {}
        for label, argv, env in jobs:  # the .pyc files, and each build's answer
            _, out, err, rc = wall(argv, env, work)
            answers[label] = (out, err, rc)
        times: dict[str, list[float]] = {label: [] for label, _, _ in jobs}
        for _ in range(args.runs):
            for label, argv, env in jobs:
                times[label].append(wall(argv, env, work)[0])
        load_after = os.getloadavg()
        print(f"program: {built.blocks:,} blocks ({built.bytes:,} bytes), "
              f"tapegate {' '.join(check).replace(program.name, 'FILE')}; load average "
              f"{load_before[0]:.2f} -> {load_after[0]:.2f}; {args.runs} runs, interleaved")
        print(f"{'':28} {'median ms':>9} {'min ms':>7} {'instructions':>14}")
        counts = {}
        for label, argv, env in jobs:
            n = instructions(argv, env, work) if args.callgrind else 0
            counts[label] = n
            print(f"{label:28} {ms(statistics.median(times[label])):>9} "
                  f"{ms(min(times[label])):>7} {n:>14,}")
        first = builds[0][0]
        for label, _ in builds[1:]:
            if answers[label] != answers[first]:
                print(f"DIFFERS: {label} answers otherwise than {first} "
                      f"(exit {answers[first][2]} -> {answers[label][2]})")
        for label, path in builds:
            least = importtimes([str(scripts[label]), *check], env_for(path), work,
                                args.importtime)
            own = sum(us for name, us in least.items() if name.split(".")[0] in OWN)
            print(f"\n{label}: {len(least)} modules imported, their self times "
                  f"{sum(least.values()) / 1000:.1f} ms (each the least of {args.importtime} runs)"
                  f", tapegate's own packages {own / 1000:.1f} ms"
                  f" ({sum(name.split('.')[0] in OWN for name in least)} modules)"
                  "; the largest, self ms:")
            for name, us in sorted(least.items(), key=lambda kv: -kv[1])[:args.top]:
                print(f"  {us / 1000:6.2f}  {name}")
        print(f"\nexit code {answers[first][2]}; {len(answers[first][0]):,} bytes out")
    return 0


if __name__ == "__main__":
    sys.exit(main())
