"""Tape codes: speed and peak memory of ``tapegate tape encode`` and ``decode`` (outside the test
suite; results go to docs/benchmarks.md by hand).

    .venv/bin/python benchmarks/tape.py [--mb 10]

Three programs of ``--mb`` megabytes are made in a temporary folder: one of CR characters only
(no end of block at all: one line), and two from the real programs of ``../shared/corpus``
(``TAPEGATE_CORPUS`` overrides; read at run time, never copied into the repository) repeated to
the size -- one with the characters ISO's 7-bit code carries (non-ASCII characters and control
codes other than TAB, LF and CR dropped: a real program holds a DOS end-of-file), one with
those EIA RS-244 carries (upper-cased, the others dropped). Each is encoded (ISO, and EIA where
the code carries it) and the tape image decoded again, each command in its own process (an
EIA tape of CRs holds an EOB for each: a CR with no LF next to it ends a block).

"peak MB" is the process's maximum resident set, measured by GNU time (``/usr/bin/time``); the
last column is the same command on a program ten times smaller -- equal figures mean memory
does not grow with the program. "CPU s" is the command's user and system time, start-up
included (the start-up alone is printed first; CPU time, not wall-clock time, so that other work
on the machine counts less); "MB/s" is the program's size over that time less the start-up.
"""

from __future__ import annotations

import argparse
import glob
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
TAPEGATE = [sys.executable, "-m", "tapegate"]
TIME = "/usr/bin/time"  # GNU time


def corpus_text() -> str:
    folder = os.environ.get("TAPEGATE_CORPUS", os.path.join(ROOT, "..", "shared", "corpus"))
    texts = []
    for path in sorted(glob.glob(os.path.join(folder, "*"))):
        if os.path.isfile(path) and not path.endswith(".md"):
            with open(path, "rb") as f:
                texts.append(f.read().decode("utf-8", "replace"))
    if not texts:
        sys.exit(f"benchmarks/tape.py: no programs in {folder} (set TAPEGATE_CORPUS)")
    return "".join(t if t.endswith("\n") else t + "\n" for t in texts)


def grown(text: str, size: int) -> str:
    """``text`` repeated to ``size`` characters, cut after an end of block."""
    whole = text * (size // len(text) + 1)
    return whole[:size].rsplit("\n", 1)[0] + "\n"


def programs(folder: str, size: int) -> dict[str, str]:
    from formats.tape import EIA_TABLE

    text = corpus_text()
    made = {
        "cr": "\r" * size,
        "real-iso": grown("".join(ch for ch in text
                               if ch.isascii() and (ch >= " " or ch in "\t\n\r")), size),
        # (a '%' inside a block is refused by EIA encode: its ER would stop the reader)
        "real-eia": grown(re.sub(r"(?<=[^\n])%", "", "".join(
            ch for ch in text.upper() if ch in EIA_TABLE)), size),
    }
    paths = {}
    for name, body in made.items():
        paths[name] = os.path.join(folder, f"{name}-{size}.nc")
        with open(paths[name], "w", encoding="ascii", newline="") as f:
            f.write(body)
    return paths


def run(args: list[str]) -> tuple[float, float, float]:
    """Wall-clock seconds, CPU seconds and peak resident MB of one command in its own process,
    measured by GNU time: a child's ru_maxrss counts the memory of the process that forked it
    (Linux keeps the high water mark across exec), so it is taken from a small parent, not from
    this one."""
    with tempfile.NamedTemporaryFile("r") as report:
        proc = subprocess.run([TIME, "-f", "%e %U %S %M", "-o", report.name, *TAPEGATE, *args],
                              cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                              check=False)
        # decode exits 1 when the tape has errors; none of these tapes has any
        if proc.returncode != 0:
            sys.exit(f"tapegate {' '.join(args)} failed: {proc.stderr.decode().strip()}")
        wall, user, system, rss = report.read().split()[-4:]
        return float(wall), float(user) + float(system), int(rss) / 1024


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--mb", type=float, default=10)
    size = int(parser.parse_args().mb * 1_000_000)
    with tempfile.TemporaryDirectory() as tmp:
        big, small = programs(tmp, size), programs(tmp, size // 10)
        print(f"programs of {size / 1e6:g} MB; python {sys.version.split()[0]}, "
              f"{os.cpu_count()} cores")
        tiny = os.path.join(tmp, "tiny.nc")
        with open(tiny, "w") as f:
            f.write("%\n")
        _, start, start_rss = run(["tape", "detect", tiny])
        print(f"start-up (tapegate tape detect of a 2-byte file): {start:.2f} CPU s, "
              f"{start_rss:.1f} MB")
        print(f"{'program':10} {'code':5} {'command':7} {'MB/s':>8} {'CPU s':>7} {'wall s':>7} "
              f"{'peak MB':>8} {'peak MB at 1/10':>16}")
        for name in ("cr", "real-iso", "real-eia"):
            for code in ("iso", "eia"):
                if name == "real-iso" and code == "eia" or name == "real-eia" and code == "iso":
                    continue
                results = []
                for paths in (big, small):
                    text, tape = paths[name], paths[name] + f".{code}"
                    results.append((run(["tape", "encode", text, "--code", code, "-o", tape]),
                                    run(["tape", "decode", tape, "-o", tape + ".nc"])))
                    with open(text, "rb") as a, open(tape + ".nc", "rb") as b:
                        if code == "iso" and a.read() != b.read():
                            sys.exit(f"{name}: the decoded ISO tape differs from the program")
                for i, command in enumerate(("encode", "decode")):
                    (wall, cpu, rss), (_, _, rss_small) = results[0][i], results[1][i]
                    work = cpu - start  # "-": too little to measure
                    rate = f"{size / 1e6 / work:8.1f}" if work > 0.05 else f"{'-':>8}"
                    print(f"{name:10} {code:5} {command:7} {rate} {cpu:7.2f} {wall:7.2f} "
                          f"{rss:8.1f} {rss_small:16.1f}")

if __name__ == "__main__":
    main()
