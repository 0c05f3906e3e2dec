"""Does every conversion that says "ok" write what the target's own check reads?

    .venv/bin/python benchmarks/convert_targets.py [--json] [--only NAME-PART] [--jobs N]
        [--corpus DIR] [--to PROFILE ...] [--all] [--keep DIR]

Every program of ``shared/corpus`` (the ones of a family here, as tests/test_dialects.py's
MATCHING gives them) and of ``shared/corpus/shops`` (on its family's built-in profile, as
benchmarks/shops.py reads it) -- the programs benchmarks/convert_sweep.py takes -- is converted
from that profile to every built-in profile (``tapegate profiles``; ``--to`` names some). A
conversion that is refused is a refusal (counted by its code); one that says "ok" has its output
checked on the target profile as ``tapegate check`` does, and is

- ``ok``       where that check reports no error the source's own check (on its profile) does not
               report too (by rule: an axis beyond the target's limits that the source already
               went beyond is the program's, not the conversion's);
- ``REFUSED``  where it reports an error of a rule the source's check does not: the output the
               conversion called "ok" is one the target (or tapegate's check of it) refuses.
               Each is listed with its first such error; ``reading`` marks a reading rule
               (benchmarks/shops.py's READING: a block the reader cannot read, a character
               outside the set, a digit overflow ...), ``rs274`` LinuxCNC's interpreter's
               refusals (rule LinuxCncRefuses).

The principle (docs/convert.md): a conversion never reports success for output the target control
refuses; it refuses at the source word, or carries the meaning exactly. The count of REFUSED is
the measure; docs/benchmarks.md keeps the figures and the classes of those that remain.
tests/test_convert_targets.py runs a fixed few. ``--keep DIR`` keeps each output that said "ok"
as ``DIR/TARGET/PROGRAM`` (two builds' outputs compared byte for byte: ``diff -r``).

Exit code 0 always (a measurement).
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from collections import Counter
from dataclasses import asdict, dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))

from benchmarks.convert_sweep import CORPUS, programs, run_all  # noqa: E402
from benchmarks.shops import READING  # noqa: E402
from formats.conversion import ConvertOptions  # noqa: E402
from formats.convert import convert_file  # noqa: E402
from formats.errors import TapegateError  # noqa: E402
from formats.parser import parse_stream  # noqa: E402
from formats.profile import builtin_names, load_profile  # noqa: E402
from formats.source import Source  # noqa: E402
from postproc.check import Checker  # noqa: E402
from postproc.rules import rule_id  # noqa: E402

# LinuxCNC's interpreter's refusals (rs274 as the checker reads it)
RS274 = rule_id("LinuxCncRefuses")


@dataclass
class Run:
    program: str
    source: str
    target: str
    result: str  # ok | refused (by the conversion) | REFUSED (ok, but the target's check errs)
    code: str = ""
    message: str = ""
    kind: str = ""  # of a REFUSED output's first new error: reading | rs274 | other


# A machine's limit that a control family's profile says as a warning (the control clamps or
# limits it, or no source says it alarms) and a strict profile as an error: the same limit, so
# a source that passed it already passes it on any target (docs/rules.md, TG605, TG606).
SAME_LIMIT = {rule_id("FeedClamped"): rule_id("FeedTooHigh"),
              rule_id("SpeedLimited"): rule_id("SpeedTooHigh")}


def errors(path: Path, profile_name: str, name: str, source: bool = False
           ) -> list[tuple[str, int, str]]:
    """The check's errors of ``path`` on ``profile_name``: (rule, line, message); of the
    ``source`` program, a limit said as a warning (SAME_LIMIT) counts as the error of the same
    limit too (the program's, not the conversion's); of a target, only errors count."""
    profile = load_profile(profile_name)
    read = parse_stream(Source(str(path)).chunks(), profile.dialect, file=name, errors="collect")
    return [(SAME_LIMIT.get(f.rule, f.rule), f.line or 0, f.message)
            for f in Checker(profile, file=name).run(read)
            if f.severity == "error" or source and f.rule in SAME_LIMIT]


def kind(rule: str) -> str:
    if rule in READING:
        return "reading"
    return "rs274" if rule == RS274 else "other"


def sweep(path: Path, source: str, targets: list[str], keep: Path | None = None) -> list[Run]:
    name = path.name
    own = {rule for rule, _, _ in errors(path, source, name, source=True)}
    runs = []
    with tempfile.TemporaryDirectory(prefix="tapegate-targets-") as tmp:
        for target in targets:
            out = Path(tmp) / f"{target}.nc"
            try:
                convert_file(str(path), str(out), ConvertOptions(load_profile(target),
                                                                 load_profile(source)),
                             overwrite=True, display=name)
            except TapegateError as exc:
                runs.append(Run(name, source, target, "refused", exc.code, str(exc)[:300]))
                continue
            except Exception as exc:  # noqa: BLE001 - a crash is a finding too
                runs.append(Run(name, source, target, "crashed", type(exc).__name__,
                                str(exc)[:300]))
                continue
            if keep is not None:
                (keep / target).mkdir(parents=True, exist_ok=True)
                (keep / target / name).write_bytes(out.read_bytes())
            new = [e for e in errors(out, target, name) if e[0] not in own]
            if new:
                rule, line, message = new[0]
                runs.append(Run(name, source, target, "REFUSED", rule,
                                f"{line}: {message}"[:300], kind(rule)))
            else:
                runs.append(Run(name, source, target, "ok"))
    return runs


def _sweep(args: tuple[Path, str, list[str], Path | None]) -> list[Run]:
    return sweep(*args)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--json", action="store_true", help="one JSON object per run")
    parser.add_argument("--corpus", type=Path, default=CORPUS)
    parser.add_argument("--only", help="only files whose name holds this")
    parser.add_argument("--to", action="append", help="only these target profiles")
    parser.add_argument("--jobs", "-j", type=int, default=1)
    parser.add_argument("--all", action="store_true", help="list the refusals too")
    parser.add_argument("--keep", type=Path, help="keep the outputs that said ok here")
    args = parser.parse_args(argv)
    targets = args.to or builtin_names()
    todo = [(path, source, targets, args.keep)
            for path, source in programs(args.corpus, args.only)]
    if not todo:
        print(f"no programs in {args.corpus}", file=sys.stderr)
        return 0
    results = run_all(_sweep, todo, args.jobs)
    by_target: dict[str, Counter[str]] = {}
    kinds: Counter[str] = Counter()
    for run in results:
        by_target.setdefault(run.target, Counter())[run.result] += 1
        if run.result == "REFUSED":
            kinds[f"{run.kind} {run.code}"] += 1
        if args.json:
            print(json.dumps(asdict(run)))
        elif run.result in ("REFUSED", "crashed") or (args.all and run.result == "refused"):
            print(f"{run.result:8} {run.source:15} -> {run.target:15} {run.program}")
            print(f"         [{run.code}{' ' + run.kind if run.kind else ''}] {run.message}")
    totals = Counter(run.result for run in results)
    if args.json:
        print(json.dumps({"programs": len(todo), "runs": len(results), "totals": dict(totals),
                          "targets": {t: dict(c) for t, c in by_target.items()},
                          "refused_by_rule": dict(kinds)}))
    else:
        print(f"\n{len(todo)} programs, {len(results)} conversions: "
              + ", ".join(f"{k} {v}" for k, v in sorted(totals.items())))
        for target, counts in sorted(by_target.items()):
            print(f"  {target:15} " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
        if kinds:
            print("  ok but refused, by the first new error's rule: "
                  + ", ".join(f"{k} {v}" for k, v in kinds.most_common()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
