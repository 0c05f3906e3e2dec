"""Speed and memory benchmarks (outside the test suite). Results go to docs/benchmarks.md by hand.

    .venv/bin/python benchmarks/run.py [--blocks 1000000] [--only parse,convert,check,check:clean]

Each measurement runs in a fresh subprocess so that peak RSS (ru_maxrss) belongs to that job
alone; memory independence of size is shown by running the same job on 10x fewer blocks.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

JOBS = {
    "parse": """
from formats.parser import parse_stream, read_chunks, decode_chunks
from formats.profile import load_profile
p = load_profile("fanuc-mill")
n = words = 0
for b in parse_stream(decode_chunks(read_chunks(PATH)), p.dialect):
    n += 1
    words += len(b.words)
""",
    "parse+values": """
from formats.parser import parse_stream, read_chunks, decode_chunks
from formats.profile import load_profile
p = load_profile("fanuc-mill")
value = p.value
n = 0
for b in parse_stream(decode_chunks(read_chunks(PATH)), p.dialect):
    n += 1
    for t in b.words:
        if t[0] in "XYZ":
            value(t)
""",
    "convert": """
# explicit metric -> implicit inch, leading zeros omitted (the issue's case), written to a file
import os, tempfile
from formats.convert import ConvertOptions, convert_file
from formats.profile import profile_from_text
target = profile_from_text(
    'name = "implicit-inch"\\n'
    'detailed = "%:/ N07 G02 X+044 Y+044 Z+044 I+044 J+044 F042 S05 T02 M02*"\\n'
    'units_codes = "G20/G21"\\nunits = "inch"\\n')
out = os.path.join(tempfile.mkdtemp(), "out.nc")
stats = convert_file(PATH, out, ConvertOptions(target=target, units="inch"))
n = stats.blocks
os.unlink(out)
""",
    "check": """
# every rule, the fanuc-mill profile (explicit metric), findings counted
from formats.profile import load_profile
from postproc.check import iter_check_file
checker, findings = iter_check_file(PATH, load_profile("fanuc-mill"))
found = sum(1 for _ in findings)  # streamed and counted, not kept
n = checker.stats.blocks
""",
    "peer:gcodeparser": """
import re
from gcodeparser import parse_gcode_lines
# gcodeparser cannot read a trailing decimal point (X0.): give it X0.0, outside the timing.
with open(PATH) as f:
    text = re.sub(r"\\.(?![0-9])", ".0", f.read())
t0 = time.perf_counter(); c0 = time.process_time()
for line in parse_gcode_lines(text):
    pass
n = text.count("\\n")  # it yields only lines with a command: rate per block of the program
""",
}

# the same checks on the program a CAM post would write (program.py --clean)
JOBS["check:clean"] = JOBS["check"]

RUNNER = """
import resource, sys, time, json
PATH = sys.argv[1]
t0 = time.perf_counter(); c0 = time.process_time()
{job}
elapsed = time.perf_counter() - t0
cpu = time.process_time() - c0
rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
print(json.dumps({{"blocks": n, "seconds": elapsed, "cpu": cpu, "rss_mb": rss}}))
"""


def measure(job: str, path: str) -> dict[str, float]:
    code = RUNNER.format(job=JOBS[job])
    out = subprocess.run([sys.executable, "-c", code, path], capture_output=True, text=True,
                         cwd=ROOT, check=False)
    if out.returncode != 0:
        return {"error": out.stderr.strip().splitlines()[-1] if out.stderr else "failed"}
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--blocks", type=int, default=1_000_000)
    parser.add_argument("--only", default=",".join(JOBS))
    args = parser.parse_args()
    sys.path.insert(0, HERE)
    from program import write

    with tempfile.TemporaryDirectory() as tmp:
        big = os.path.join(tmp, "big.nc")
        small = os.path.join(tmp, "small.nc")
        t = time.perf_counter()
        write(big, args.blocks)
        write(small, args.blocks // 10)
        clean = {"big": os.path.join(tmp, "clean.nc"), "small": os.path.join(tmp, "clean10.nc")}
        if any(job.endswith(":clean") for job in args.only.split(",")):
            write(clean["big"], args.blocks, clean=True)
            write(clean["small"], args.blocks // 10, clean=True)
        size = os.path.getsize(big) / 1e6
        print(f"program: {args.blocks} blocks, {size:.1f} MB (written in "
              f"{time.perf_counter() - t:.1f} s); python {sys.version.split()[0]}, "
              f"{os.cpu_count()} cores")
        print(f"{'job':18} {'blocks/s':>12} {'s':>8} {'cpu s':>8} {'peak MB':>8} "
              f"{'peak MB at 1/10':>16}")
        for job in args.only.split(","):
            cleaned = job.endswith(":clean")
            r = measure(job, clean["big"] if cleaned else big)
            if "error" in r:
                print(f"{job:18} not measured: {r['error']}")
                continue
            r_small = measure(job, clean["small"] if cleaned else small)
            print(f"{job:18} {r['blocks'] / r['seconds']:12,.0f} {r['seconds']:8.2f} "
                  f"{r['cpu']:8.2f} {r['rss_mb']:8.1f} {r_small.get('rss_mb', 0):16.1f}")


if __name__ == "__main__":
    main()
