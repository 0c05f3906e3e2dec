"""`check -j` and `convert -j`: a batch of real files with 1 and 2 (or more) workers.

    .venv/bin/python benchmarks/workers.py [--jobs 1,2] [--copies 200] [--repeat 3]
                                           [--tapegate PATH]

Two batches, each command in its own process under ``/usr/bin/time -v`` (wall seconds of the
whole command, and the peak resident set of the largest process: the main one or a worker):

- **shops**: every file of ``../shared/corpus/shops`` (``check -p fanuc-mill --format json``;
  the programs of other families give reading findings, which are work too);
- **copies**: 200 copies of ``Praktikum-CAD-CAM-Modul-12__1001.nc`` (3,157 blocks) in a
  temporary folder: ``check -p haas-mill --format json`` and ``convert --from haas-mill`` to
  implicit inch (``benchmarks/core.py``'s target) into another folder.

Each measure is repeated (``--repeat``) and the fastest kept; the speed-up is 1 worker's time
over N workers'. CPU s is the CPU time of the command and its workers (user + system): equal
figures for 1 and N workers mean the workers cost no more work than one process. Needs
``../shared/corpus`` (or ``$TAPEGATE_CORPUS``).
"""

from __future__ import annotations

import argparse
import shutil
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from core import IMPLICIT_INCH, ROOT, timed_cpu  # noqa: E402
from real_program import SOURCE, corpus_dir  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--jobs", default="1,2", help="comma-separated worker counts")
    parser.add_argument("--copies", type=int, default=200)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--tapegate", default=str(ROOT / ".venv" / "bin" / "tapegate"))
    args = parser.parse_args()
    corpus = corpus_dir()
    if not (corpus / "shops").is_dir():
        print(f"corpus not found: {corpus} (set TAPEGATE_CORPUS)", file=sys.stderr)
        return 2
    work = Path(tempfile.mkdtemp(prefix="tapegate-workers-"))
    try:
        copies = work / "copies"
        copies.mkdir()
        for n in range(args.copies):
            shutil.copy(corpus / SOURCE, copies / f"p{n:03d}.nc")
        target = work / "implicit-inch.toml"
        target.write_text(IMPLICIT_INCH)
        shops = [p for p in (corpus / "shops").iterdir() if p.is_file()]
        tg = args.tapegate
        batches = {
            f"check shops ({len(shops)} files)":
                [tg, "check", str(corpus / "shops"), "-p", "fanuc-mill", "--format", "json"],
            f"check {args.copies} copies": [tg, "check", str(copies), "-p", "haas-mill",
                                            "--format", "json"],
            f"convert {args.copies} copies": [tg, "convert", str(copies), "--out-dir",
                                              str(work / "out"), "--force", "--from",
                                              "haas-mill", "--to", str(target), "--units",
                                              "inch"],
        }
        jobs = [int(j) for j in args.jobs.split(",")]
        print(f"{'batch':<34} {'-j':>3} {'seconds':>8} {'CPU s':>6} {'peak MB':>8} "
              f"{'speed-up':>8} rc")
        for name, argv in batches.items():
            first = 0.0
            for j in jobs:
                runs = [timed_cpu([*argv, "-j", str(j)]) for _ in range(args.repeat)]
                seconds, rss, rc, cpu = min(runs)
                first = first or seconds
                print(f"{name:<34} {j:>3} {seconds:>8.2f} {cpu:>6.2f} "
                      f"{max(r[1] for r in runs):>8.1f} {first / seconds:>8.2f} {rc}", flush=True)
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
