"""Restarts planned at ~25 points of every FANUC and Haas program of the corpus.

Usage: python benchmarks/restart_sweep.py [--corpus DIR] [--points N] [--lines N] > OUT.tsv

The programs: ``shared/corpus`` (tests/test_dialects.py's MATCHING, the FANUC and Haas ones) and
``shared/corpus/shops`` (families.tsv's fanuc and haas programs, on the lathe profile where the
description says lathe or turn: benchmarks/shops.py's ``profile_for``), each up to its first
``--lines`` lines (3000). In each, ``--points`` lines spread evenly over its lines, and at each
:func:`postproc.restart.plan_restart` (as tests/test_restart.py calls it). One line a restart:
file, profile, line, outcome (``planned`` at the first block from that line, ``refused``,
``unread``: no block from there, or one the control never reads) and the refusal's reason. The
totals go to stderr. Compare two runs with ``diff``. Exit code 0 always (a measurement).
"""

from __future__ import annotations

import argparse
import sys
from collections import Counter
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))

from benchmarks.rs274_compare import matching  # noqa: E402
from benchmarks.shops import SHOPS, entries, profile_for  # noqa: E402
from formats.parser import parse_text  # noqa: E402
from formats.profile import load_profile  # noqa: E402
from postproc.restart import RestartRefused, plan_restart  # noqa: E402


def programs(corpus: Path) -> list[tuple[Path, str]]:
    out = [(corpus / name, profile) for name, profile in sorted(matching().items())
           if profile.split("-")[0] in ("fanuc", "haas")]
    for name, family, description in entries(corpus / "shops"):
        if family in ("fanuc", "haas"):
            profile = profile_for(family, description)
            if profile is not None:
                out.append((corpus / "shops" / name, profile))
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", type=Path, default=SHOPS.parent)
    parser.add_argument("--points", type=int, default=25)
    parser.add_argument("--lines", type=int, default=3000)
    args = parser.parse_args()
    totals: Counter[str] = Counter()
    for path, name in programs(args.corpus):
        profile = load_profile(name)
        lines = path.read_text(encoding="latin-1").splitlines(keepends=True)[:args.lines]
        text = "".join(lines)
        at = sorted({1 + i * len(lines) // args.points for i in range(args.points)})
        for line in at:
            totals["plans"] += 1
            try:
                plan_restart(parse_text(text, profile.dialect, errors="collect"), profile, line,
                             path.name)
                outcome, reason = "planned", ""
            except RestartRefused as exc:
                unread = exc.code in ("restart-not-read", "restart-no-block")
                outcome = "unread" if unread else "refused"
                reason = " ".join(exc.message.split())
            except Exception as exc:  # noqa: BLE001 -- a crash is an outcome to count
                outcome, reason = "crashed", f"{type(exc).__name__}: {exc}"
            totals[outcome] += 1
            print(f"{path.name}\t{name}\t{line}\t{outcome}\t{reason}")
    print(", ".join(f"{k} {v}" for k, v in sorted(totals.items())), file=sys.stderr)


if __name__ == "__main__":
    main()
