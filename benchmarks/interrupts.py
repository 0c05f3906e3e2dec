"""^C in the middle of `tapegate convert DIR --out-dir OUT -j 2`, many times: what it leaves.

    .venv/bin/python benchmarks/interrupts.py [--runs 60] [--files 1500] [--tapegate PATH]
                                              [--build CHECKOUT] [--signal INT|TERM|HUP]

A folder of ``--files`` short programs (four that differ, 300 blocks each) is converted
(``--from fanuc-mill --to fanuc-mill --units inch -j 2``) ``--runs`` times, each run sent
SIGINT (its default handler: Python's ``KeyboardInterrupt``) after a random 0.15-0.8 s.
Counted: the runs that exit 1 ("Aborted!"), those that leave a hidden file (a temporary
``.NAME.XXXXXXXX.part``) in the output folder, with its size, those that do not end within 60 s
(then ended by SIGKILL), and the outputs that differ from a single conversion of their input
(review 39, finding 7). ``--build`` puts a checkout first on ``PYTHONPATH`` (its extension
built). The moments are drawn from a fixed seed, so two builds meet the same ones.
``--signal TERM`` or ``HUP`` sends that signal instead (a CI job's timeout, a terminal closed):
the exit expected is then 128 + its number (review 44, finding 8: SIGHUP hung 2 of 140 runs
before the batch's threads held it to a safe point).
"""

from __future__ import annotations

import argparse
import os
import random
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tests.test_convert_interrupt import ARGS, VARIANTS, _program  # noqa: E402


def _default_sigint() -> None:
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--runs", type=int, default=60)
    parser.add_argument("--files", type=int, default=1500)
    parser.add_argument("--tapegate", default=str(Path(sys.executable).with_name("tapegate")))
    parser.add_argument("--build", default=None)
    parser.add_argument("--signal", choices=("INT", "TERM", "HUP"), default="INT")
    args = parser.parse_args()
    signum = getattr(signal, f"SIG{args.signal}")
    expected_exit = 1 if signum == signal.SIGINT else 128 + signum
    command = shlex.split(args.tapegate)
    env = dict(os.environ)
    if args.build:
        env["PYTHONPATH"] = os.pathsep.join(
            p for p in (os.path.abspath(args.build), env.get("PYTHONPATH")) if p)
    with tempfile.TemporaryDirectory() as scratch:
        place = Path(scratch)
        cam = place / "cam"
        cam.mkdir()
        expected = {}
        for variant in range(VARIANTS):
            (place / f"v{variant}.nc").write_text(_program(variant, 300))
            subprocess.run([*command, "convert", str(place / f"v{variant}.nc"), "-o",
                            str(place / f"r{variant}.nc"), *ARGS], env=env, check=True,
                           capture_output=True)
            expected[variant] = (place / f"r{variant}.nc").read_bytes()
        for n in range(args.files):
            (cam / f"p{n:04d}.nc").write_text(_program(n % VARIANTS, 300))
        draw = random.Random(1)
        aborted = left = hung = differing = 0
        out = place / "out"
        for _ in range(args.runs):
            shutil.rmtree(out, ignore_errors=True)
            out.mkdir()
            proc = subprocess.Popen([*command, "convert", str(cam), "--out-dir", str(out),
                                     *ARGS, "-j", "2"], env=env, stdout=subprocess.DEVNULL,
                                    stderr=subprocess.PIPE, preexec_fn=_default_sigint)
            time.sleep(draw.uniform(0.15, 0.8))
            proc.send_signal(signum)
            try:
                proc.communicate(timeout=60)
            except subprocess.TimeoutExpired:
                hung += 1
                proc.kill()
                proc.communicate()
            aborted += proc.returncode == expected_exit
            names = os.listdir(out)
            hidden = [(n, (out / n).stat().st_size) for n in names if n.startswith(".")]
            if hidden:
                left += 1
                print("left:", hidden, flush=True)
            differing += sum(1 for n in names if not n.startswith(".")
                             and (out / n).read_bytes() != expected[int(n[1:5]) % VARIANTS])
        print(f"runs {args.runs}, SIG{args.signal}: exit {expected_exit} {aborted}, "
              f"a temporary file left {left}, "
              f"hung {hung}, outputs differing {differing}")


if __name__ == "__main__":
    main()
