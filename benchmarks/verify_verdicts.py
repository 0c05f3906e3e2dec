"""What ``convert --verify`` says of every program: its summary and its verdict, to compare.

    .venv/bin/python benchmarks/verify_verdicts.py [--only NAME-PART] > runs.jsonl

Every program of ``shared/corpus`` and ``shared/corpus/shops`` on its family's profile (the
programs of benchmarks/convert_sweep.py) is converted to that profile with ``--verify`` and
``--dry-run``, once per way of units and decimal style (``--units metric``, ``--units inch``,
``--decimal implicit``, ``--decimal explicit``), with and without ``--allow-unconverted``. One
JSON object per run: the command line's exit code and its whole output (the table, the notes,
the error; the corpus folder written ``DIR``), and from the Python API the verdict and the
counts it is decided from (``verified``, ``left_as_written``, ``not_compared``,
``verified_assuming``) or the error's class and text.

Run it on two builds and compare the files line by line: a change to how the verdict is
decided must leave every line the same, or name the case it fixes (docs/benchmarks.md).
Only what both builds have is read (no option newer than ``--verify``), so a build from before
a change can be measured with the same script. Exit code 0 always (a measurement).
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))

from click.testing import CliRunner  # noqa: E402

from benchmarks.convert_sweep import CORPUS, programs  # noqa: E402
from formats.conversion import ConvertOptions  # noqa: E402
from formats.convert import convert_file  # noqa: E402
from formats.profile import load_profile  # noqa: E402
from tapegate.cli import main as cli  # noqa: E402

JOBS = (("units", "metric"), ("units", "inch"), ("decimal", "implicit"), ("decimal", "explicit"))


def runs(path: Path, profile_name: str) -> list[dict[str, object]]:
    out: list[dict[str, object]] = []
    runner = CliRunner()
    profile = load_profile(profile_name)
    for option, value in JOBS:
        for allow in (False, True):
            args = ["convert", str(path), "--to", profile_name, "--from", profile_name,
                    "--verify", "--dry-run", "-j", "1", f"--{option}", value]
            run = runner.invoke(cli, args + (["--allow-unconverted"] if allow else []))
            record: dict[str, object] = {
                "file": path.name, "profile": profile_name, "job": [option, value],
                "allow": allow, "exit": run.exit_code,
                "text": run.output.replace(str(path.parent), "DIR")}
            try:
                options = ConvertOptions(profile, profile, allow_unconverted=allow,
                                         **{option: value})  # type: ignore[arg-type]
                stats = convert_file(str(path), None, options, verify=True, display=path.name)
            except Exception as exc:  # noqa: BLE001 - a refusal is a result to compare
                record["stats"] = {"error": type(exc).__name__, "message": str(exc)[:300]}
            else:
                record["stats"] = {"verified": stats.verified, "left": stats.left_as_written,
                                   "not_compared": stats.not_compared,
                                   "assuming": stats.verified_assuming}
            out.append(record)
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--corpus", type=Path, default=CORPUS)
    parser.add_argument("--only", help="only files whose name holds this")
    args = parser.parse_args(argv)
    for path, profile_name in programs(args.corpus, args.only):
        for record in runs(path, profile_name):
            print(json.dumps(record), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
