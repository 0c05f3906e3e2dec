"""Does every reader read what ``check`` reads? Convert, verify, diff and restart on every program.

    .venv/bin/python benchmarks/convert_sweep.py [--json] [--only NAME-PART] [--jobs N]
        [--corpus DIR]

Every program of ``shared/corpus`` (the ones of a family here, as tests/test_dialects.py's
MATCHING gives them) and of ``shared/corpus/shops`` (on its family's built-in profile, as
benchmarks/shops.py reads it: FAMILY_PROFILES, RELABELLED) is run through each reader beside the
checker, every conversion with ``--verify``:

- ``units``     the same profile, ``--units`` the other units (inch when the program selects no
                inch, metric otherwise); ``units-allow`` the same with ``--allow-unconverted``
                (what cannot be shown a length left as written: the rest of the program is
                converted and verified);
- ``implicit``  the same profile, ``--decimal implicit``;
- ``explicit``  the same profile, ``--decimal explicit``;
- ``to-PROFILE`` another family's profile where one reads the same programs: fanuc <-> haas (mill
                and lathe), a fanuc mill to linuxcnc;
- ``diff``      ``tapegate diff`` of the file against itself (``--motion``): the same program;
- ``restart``   ``send --restart-at`` planning at the middle block that moves an axis.

A run is ``ok``, or ``refused`` with the located message and its stable code (a refusal may be
right: the program is wrong there, or converting would change what the machine does), or
``crashed`` (an exception that is not a tapegate error: always a bug). A refusal because a
block of the source cannot be read (a ``ParseError``, its code a reading rule) is held to the
checker: ``check reads it too`` where ``tapegate check`` reports a reading error on that line,
``ONLY THIS READER`` where the checker reads the line and this reader does not -- the
disagreement issue 32 removes. The totals per job are the measure of the readers' agreement;
docs/benchmarks.md keeps the figures.

Exit code 0 always (a measurement).
"""

from __future__ import annotations

import argparse
import json
import os
import re
import sys
import tempfile
from collections import Counter
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import TypeVar

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))

from benchmarks.rs274_compare import matching  # noqa: E402
from benchmarks.shops import READING, SHOPS, entries, profile_for  # noqa: E402
from formats.conversion import ConvertOptions  # noqa: E402
from formats.convert import convert_file  # noqa: E402
from formats.diff import DiffOptions, diff_files  # noqa: E402
from formats.errors import ParseError, TapegateError  # noqa: E402
from formats.parser import parse_stream  # noqa: E402
from formats.profile import load_profile  # noqa: E402
from formats.source import Source  # noqa: E402
from postproc.check import Checker  # noqa: E402
from postproc.restart import plan_restart_text  # noqa: E402

CORPUS = SHOPS.parent

# The corpus programs of a family with a built-in profile: tests/test_dialects.py's MATCHING,
# read as benchmarks/rs274_compare.py reads it (one list, kept with the tests)
CORPUS_PROFILES = matching()

# Another family's profile that reads the same programs (a word-for-word conversion).
CROSS = {
    "fanuc-mill": ("haas-mill", "linuxcnc"),
    "haas-mill": ("fanuc-mill",),
    "fanuc-lathe": ("haas-lathe",),
    "haas-lathe": ("fanuc-lathe",),
}



@dataclass
class Run:
    program: str
    profile: str
    job: str
    result: str  # ok | refused | crashed
    code: str = ""
    message: str = ""
    # for a source block that cannot be read: whether the checker reports a reading error there
    checker_agrees: bool | None = None


def other_units(path: Path, profile_name: str) -> str:
    """Inch, unless the program selects inch somewhere (then metric)."""
    profile = load_profile(profile_name)
    if not profile.units_by_code:  # the machine's parameter: the other of the profile's units
        return "metric" if profile.default_units == "inch" else "inch"
    code = profile.inch_code
    text = re.sub(r"\([^)\n]*\)|;[^\n]*", "", path.read_text(encoding="latin-1"))
    inch = re.search(rf"(?<![0-9.A-Z]){code[0]}0*{code[1:]}(?![0-9.])", text)
    return "metric" if inch else "inch"


def restart_line(path: Path) -> int | None:
    """The middle block that moves an axis (a line with X, Y or Z and a number, no comment)."""
    lines = [i for i, text in enumerate(path.read_text(encoding="latin-1").split("\n"), 1)
             if re.match(r"^[^(;]*[XYZ][+-]?[0-9.]", text)]
    return lines[len(lines) // 2] if lines else None


def reading_error_lines(path: Path, profile_name: str) -> set[int]:
    """The lines where ``tapegate check`` reports a reading error (benchmarks/shops.py's
    READING rules, error severity), as shops.measure reads the program."""
    profile = load_profile(profile_name)
    read = list(parse_stream(Source(str(path)).chunks(), profile.dialect, file=path.name,
                             errors="collect"))
    return {f.line for f in Checker(profile, file=path.name).run(iter(read))
            if f.rule in READING and f.severity == "error" and f.line is not None}


def outcome(program: str, profile: str, job: str, run,  # type: ignore[no-untyped-def]
            reading: Callable[[], set[int]]) -> Run:
    try:
        run()
    except ParseError as exc:
        agrees = None
        if exc.file == program and exc.line is not None:  # a line of the source
            agrees = exc.line in reading()
        return Run(program, profile, job, "refused", exc.code, str(exc), agrees)
    except TapegateError as exc:
        return Run(program, profile, job, "refused", exc.code, str(exc))
    except Exception as exc:  # noqa: BLE001 - a crash is what the sweep is looking for
        return Run(program, profile, job, "crashed", type(exc).__name__, str(exc)[:300])
    return Run(program, profile, job, "ok")


def sweep(path: Path, profile_name: str) -> list[Run]:
    name = path.name
    profile = load_profile(profile_name)
    runs = []

    def convert(target: str, **options: object):  # type: ignore[no-untyped-def]
        def run() -> None:
            convert_file(str(path), None, ConvertOptions(load_profile(target), profile,
                                                         **options),  # type: ignore[arg-type]
                         verify=True, display=name)
        return run

    lines: list[set[int]] = []

    def reading() -> set[int]:
        if not lines:
            lines.append(reading_error_lines(path, profile_name))
        return lines[0]

    units = other_units(path, profile_name)
    runs.append(outcome(name, profile_name, f"units {units}", convert(profile_name, units=units),
                        reading))
    runs.append(outcome(name, profile_name, f"units-allow {units}",
                        convert(profile_name, units=units, allow_unconverted=True), reading))
    for decimal in ("implicit", "explicit"):
        runs.append(outcome(name, profile_name, decimal,
                            convert(profile_name, decimal=decimal), reading))
    for target in CROSS.get(profile_name, ()):
        runs.append(outcome(name, profile_name, f"to {target}", convert(target), reading))

    def diff() -> None:
        found = list(diff_files(str(path), str(path), profile, profile,
                                DiffOptions(motion=True), name_a=name, name_b=name))
        if found:
            raise TapegateError(f"{name} differs from itself: "
                                f"{found[0].describe(name, name).splitlines()[0]}",
                                code="diff-self")

    runs.append(outcome(name, profile_name, "diff", diff, reading))
    line = restart_line(path)
    if line is not None:
        def restart() -> None:
            plan_restart_text(Source(str(path)).chunks(), profile, line, name)

        runs.append(outcome(name, profile_name, f"restart {line}", restart, reading))
    return runs


def programs(corpus: Path, only: str | None) -> list[tuple[Path, str]]:
    out = []
    for name, profile in sorted(CORPUS_PROFILES.items()):
        out.append((corpus / name, profile))
    shops = corpus / "shops"
    if (shops / "families.tsv").is_file():
        for name, family, description in entries(shops):
            profile = profile_for(family, description)
            if profile is not None:
                out.append((shops / name, profile))
    return [(p, prof) for p, prof in out if p.is_file() and (not only or only in p.name)]


T = TypeVar("T")
R = TypeVar("R")


def run_all(sweep_one: Callable[[T], list[R]], todo: list[T], jobs: int) -> list[R]:
    """Every item's runs, in the items' order: in ``jobs`` processes (each its own core
    module) where ``jobs`` > 1. The temporary folder is fixed first, so that the processes
    write their outputs where the parent does."""
    os.environ.setdefault("TMPDIR", tempfile.gettempdir())
    if jobs > 1:
        with ProcessPoolExecutor(jobs) as pool:
            return [run for runs in pool.map(sweep_one, todo) for run in runs]
    return [run for item in todo for run in sweep_one(item)]


def _sweep(args: tuple[Path, str]) -> list[Run]:
    return sweep(*args)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--json", action="store_true", help="one JSON object per run")
    parser.add_argument("--corpus", type=Path, default=CORPUS)
    parser.add_argument("--only", help="only files whose name holds this")
    parser.add_argument("--jobs", "-j", type=int, default=1)
    parser.add_argument("--all", action="store_true", help="list the runs that pass too")
    args = parser.parse_args(argv)
    todo = programs(args.corpus, args.only)
    if not todo:
        print(f"no programs in {args.corpus}", file=sys.stderr)
        return 0
    results = run_all(_sweep, todo, args.jobs)
    totals: dict[str, Counter[str]] = {}
    for run in results:
        job = run.job.split()[0] if not run.job.startswith("to ") else run.job
        totals.setdefault(job, Counter())[run.result] += 1
        if args.json:
            print(json.dumps(asdict(run)))
        elif run.result != "ok" or args.all:
            print(f"{run.result:8} {run.job:18} {run.profile:15} {run.program}")
            if run.message:
                print(f"         [{run.code}] {run.message}")
            if run.checker_agrees is not None:
                print("         check reads it too: a reading error on that line"
                      if run.checker_agrees else
                      "         ONLY THIS READER: check reads that line")
    summary = {job: dict(counts) for job, counts in totals.items()}
    unread = [r for r in results if r.checker_agrees is not None]
    only = sum(1 for r in unread if not r.checker_agrees)
    if args.json:
        print(json.dumps({"programs": len(todo), "runs": len(results), "jobs": summary,
                          "unreadable": len(unread), "only_this_reader": only}))
    else:
        print(f"\n{len(todo)} programs, {len(results)} runs; {len(unread)} refused at a "
              f"source line they cannot read, {only} of them a line check reads")
        for job, counts in summary.items():
            print(f"  {job:18} " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    return 0


if __name__ == "__main__":
    sys.exit(main())
