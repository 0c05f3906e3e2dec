"""Random short LinuxCNC programs, read by ``rs274 -g`` and ``tapegate check -p linuxcnc``.

    .venv/bin/python benchmarks/rs274_random.py [--seed N] [--programs N] [--show] [--flow]

Each program is the comparison's head (G21 G17 G90 F100, G0 X0 Y0 Z0), two to six blocks drawn
at random from ``SNIPPETS`` (the forms of the LinuxCNC refusals that follow rs274's own state:
its feed rate, probes, NURBS points, offsets, M66, named parameters, expressions of numbers),
then M2. A **false refusal** is a program rs274 runs to its end where tapegate says an error;
a **miss** one rs274 stops on where tapegate says none (rules not modelled, or a start the
checker does not know exactly: these are safe). Printed: the counts, and with ``--show`` each
false refusal and miss. Review 15 found four false refusals so (docs/dialects.md, LinuxCNC),
and after their fixes none in seeds 1-5 of 300 programs each (docs/benchmarks.md). Exit code 0
always: a measurement. Needs ``rs274`` (linuxcnc-uspace) on the path.
"""

from __future__ import annotations

import argparse
import os
import random
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from formats.profile import load_profile  # noqa: E402
from postproc.check import check_text  # noqa: E402

HEAD = "G21 G17 G90 F100\nG0 X0 Y0 Z0\n"
SNIPPETS = [
    "G93", "G94", "G95", "F100", "F0", "G38.2 X5", "G38.2 Z0", "G38.3 Z0", "G38.4 X0", "G91",
    "G90", "G0 X1 Y0", "G0 X0 Y0 Z0", "G1 X2 F50", "G93 G1 X1 F2", "G5.2 X1 Y1 P1",
    "X2 Y2 P1", "X3 Y0", "G5.3", "G5.2 X1 Y1 L4", "G43 H1", "G49", "G92 X0", "G92.1", "G28",
    "G2 X0 Y0 R5", "G2 X1 Y0 R5", "G18", "G17", "G19", "G81 X1 Z-1 R2", "G81 X1 Y-1 R2", "G80",
    "M66 P0 L0", "M66 E0 L1 Q1", "M3 S100", "M70", "M72", "#<a> = 1", "G0 X#<a>", "G0 X#<b>",
    "M[3.5]", "M[1+2]", "G0 X[1/2]", "G43.1 Z1", "G38.2 X1 Y0", "G55", "G0 X1",
    "S100 M3 G95 F0.1", "G33 Z-1 K1", "G5.1 X1 Y1 I1 J1", "o<s> call", "G1 X0 Y0 Z0 F10",
    "G41.1 D1", "G40", "G64 P0.01", "G20", "G21", "G7", "G8", "G91 G38.2 X0", "G91 G0 X0",
    "G38.5 X0", "T1 M6", "M5", "M4 S200", "#<c> = [#<a> + 1]", "o1 if [1]", "o1 endif",
    "G0 X[2*3]", "M66 P0 L3 Q1", "G5.2 P2", "X1 Y1 P1", "G2 X0 Y0 I1 J0", "G52 X1",
    "G92 Y0 Z0", "G43.2 H1", "G10 L2 P1 X1", "G54", "G59.3", "G30", "G53 G0 X0",
]


# With ``--flow``, also these, each whole (a block, a definition or a sum of increments): the
# lines that run only when called or when a condition holds, the feed mode set there, and the
# doubles rs274 adds under G91 (review 16c, findings 1-4; review 17). The default draws are
# unchanged, so that the counts of a seed stay comparable across stops.
FLOW_SNIPPETS = [
    "o2 if [0]\nG95\no2 endif", "o3 if [1]\nG93\no3 endif", "o4 if [0]\nM[3.5]\no4 endif",
    "o5 repeat [2]\nG1 X1\no5 endrepeat", "o6 do\nG0 Z1\no6 while [0]",
    "o<t> sub\nG95\no<t> endsub", "o<u> sub\nM73\nG93\no<u> endsub\no<u> call",
    "o<v> sub\n#<d> = 1\no<v> endsub", "G0 X#<d>", "M73",
    "G91 G0 Z0.1\nG0 Z0.2\nG90", "G91 G0 Z0.5\nG0 Z0.25\nG90", "G38.2 Z0.3", "G38.2 Z0.75",
    "G91 G0 X0.1\nG0 X0.2\nG90", "G2 X0.3 Y0 R5", "G81 X1 Y1 Z-1 R2\nG80",
]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--programs", type=int, default=300)
    parser.add_argument("--show", action="store_true", help="list each disagreement")
    parser.add_argument("--flow", action="store_true",
                        help="draw from FLOW_SNIPPETS too (conditions, definitions, G91 sums)")
    args = parser.parse_args()
    if shutil.which("rs274") is None:
        print("rs274 is not installed")
        return
    profile = load_profile("linuxcnc")
    rng = random.Random(args.seed)
    counts = {"agree": 0, "false refusal": 0, "miss": 0}
    with tempfile.TemporaryDirectory() as home:
        path = Path(home) / "program.ngc"
        for _ in range(args.programs):
            pool = SNIPPETS + FLOW_SNIPPETS if args.flow else SNIPPETS
            body = [rng.choice(pool) for _ in range(rng.randint(2, 6))]
            text = HEAD + "\n".join(body) + "\nM2\n"
            if "o<s> call" in text:
                text += "o<s> sub\no<s> endsub\n"
            found = [f for f in check_text(text, profile) if f.severity == "error"]
            path.write_text(text)
            run = subprocess.run(["rs274", "-g", str(path)], capture_output=True, text=True,
                                 input="", timeout=30, env={**os.environ, "HOME": home})
            ran = "PROGRAM_END" in run.stdout + run.stderr
            kind = ("false refusal" if found and ran else
                    "miss" if not found and not ran else "agree")
            counts[kind] += 1
            if args.show and kind != "agree":
                said = [(f.rule, f.line, f.message[:80]) for f in found] if found else \
                    (run.stdout + run.stderr).strip().splitlines()[-2:]
                print(f"{kind}: {body!r} {said}")
    print(", ".join(f"{k} {v}" for k, v in counts.items()), f"(seed {args.seed})")


if __name__ == "__main__":
    main()
