"""Fuzz the public Python API for a bounded time: ``python fuzz/run.py [SECONDS_PER_TARGET]``
(default 60; ``make fuzz`` runs it after the core's cargo-fuzz targets).

Each target (``fuzz/<target>.py``) runs in its own process under atheris (libFuzzer) with
``-max_total_time=SECONDS -timeout=5 -rss_limit_mb=256 -max_len=2048``: an exception that is
not a documented, located error, an input that takes over 5 s, or a process over 256 MB
resident is a crash. The seeds are written to a temporary folder at run time (``--write-seeds``:
pieces of ``../shared/corpus`` and the project's own profiles and docs) and removed after;
what libFuzzer adds is kept in ``fuzz/corpus/<target>/`` for the next run, a crashing input in
``fuzz/artifacts/<target>/``, the log of each run in ``fuzz/logs/<target>.log`` (all three
git-ignored).

Prints the executions per target (libFuzzer's ``stat::number_of_executed_units``) and whether
it crashed; exits 1 if a target crashed, 2 if one could not run. Environment:
``FUZZ_PY_TARGETS`` (default: every target), ``FUZZ_JOBS`` (targets run at once, default 1),
``FUZZ_ARGS`` (extra libFuzzer flags).
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
TARGETS = ["parse", "check", "convert", "convert_verify", "diff", "tape", "classification",
           "expr", "profile", "gateway_config", "requests"]


def run(target: str, seconds: int) -> tuple[str, int | None, str]:
    """(target, executions, state) of one run."""
    log = HERE / "logs" / f"{target}.log"
    corpus = HERE / "corpus" / target
    artifacts = HERE / "artifacts" / target
    for folder in (log.parent, corpus, artifacts):
        folder.mkdir(parents=True, exist_ok=True)
    # the seeds, and a TMPDIR for the folders the targets make (removed with it: libFuzzer
    # ends the process without running Python's clean-up)
    with tempfile.TemporaryDirectory(prefix=f"tapegate-seeds-{target}-") as seeds, \
            tempfile.TemporaryDirectory(prefix=f"tapegate-fuzz-{target}-") as tmp:
        env = {**os.environ, "TMPDIR": tmp}
        made = subprocess.run([sys.executable, "-m", f"fuzz.{target}", "--write-seeds", seeds],
                              cwd=ROOT, capture_output=True, text=True, check=False, env=env)
        if made.returncode != 0:
            return target, None, f"FAILED to write seeds: {made.stderr.strip()[-300:]}"
        command = [sys.executable, "-m", f"fuzz.{target}", f"-max_total_time={seconds}",
                   "-timeout=5", "-rss_limit_mb=256", "-max_len=2048", "-print_final_stats=1",
                   f"-artifact_prefix={artifacts}/", *shlex.split(os.environ.get("FUZZ_ARGS", "")),
                   str(corpus), seeds]
        with open(log, "w") as out:
            out.write(" ".join(command) + "\n")
            out.flush()
            rc = subprocess.run(command, cwd=ROOT, stdout=out, stderr=subprocess.STDOUT,
                                check=False, env=env).returncode
    text = log.read_text(errors="replace")
    execs = re.findall(r"stat::number_of_executed_units: *(\d+)", text)
    artifact = re.findall(r"(?:Test unit|artifact) written to (\S+)", text)
    if rc == 0:
        state = "no crash"
    elif artifact or "Uncaught Python exception" in text:
        lines = [line for line in text.splitlines()
                 if re.match(r"(=== Uncaught Python exception|\w*(Error|Find)\b|==\d+== ERROR)",
                             line)]
        where = artifact[-1] if artifact else f"(no input written, see {log})"
        state = f"CRASHED: {where}\n    " + "\n    ".join(lines[:4])
    else:
        state = f"FAILED (exit {rc}, see {log})"
    return target, int(execs[-1]) if execs else None, state


def main() -> int:
    seconds = int(sys.argv[1]) if len(sys.argv) > 1 else 60
    targets = os.environ.get("FUZZ_PY_TARGETS", " ".join(TARGETS)).split()
    missing = [t for t in targets if not (HERE / f"{t}.py").exists()]
    for t in missing:
        print(f"fuzz/run.py: no target {t} (fuzz/{t}.py)", file=sys.stderr)
    targets = [t for t in targets if t not in missing]
    jobs = int(os.environ.get("FUZZ_JOBS", "1"))
    print(f"fuzz/run.py: {len(targets)} targets, {seconds}s each, {jobs} at a time "
          f"(logs in {HERE / 'logs'})", flush=True)
    with ThreadPoolExecutor(jobs) as pool:
        results = list(pool.map(lambda t: run(t, seconds), targets))
    total = 0
    print()
    for target, execs, state in results:
        total += execs or 0
        print(f"{target:15} {execs if execs is not None else '?':>10} executions  {state}")
    print(f"{'total':15} {total:>10} executions")
    if any(state.startswith("CRASHED") for _, _, state in results):
        return 1
    return 2 if missing or any(state.startswith("FAILED") for _, _, state in results) else 0


if __name__ == "__main__":
    sys.exit(main())
