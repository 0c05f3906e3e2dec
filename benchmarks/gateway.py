"""Gateway benchmark: many machines asking for a program at the same moment.

    .venv/bin/python benchmarks/gateway.py [--ports 32] [--blocks 2000] [--baud 115200]
                                           [--machining 0.5] [--dc3-reaction S]

``tapegate serve`` runs as its own process with one port per emulated control. The controls
(one process each, on its own pty behind a symbolic link, so that no control waits for another's
turn to answer) punch a remote request ``(PRG=n)`` at the same moment and then read the program
at ``--baud``, machining at ``--machining`` times the line speed (half by default) with a
128-character buffer, so every port is throttled by DC3/DC1 all the way -- as long as the service
feeds it faster than it machines; with many ports at a high baud rate, a slower control keeps
the throttling going.

Reported: programs byte-exact, the most characters any control received after a DC3 (Fanuc
allowance: 10) and how many DC3s had 0, 1, 2... characters after them, alarms and the program
lines they came at (the controls read the same program in step, so one line is one moment on
every port), wall time, per-port line utilisation while sending, and the service's CPU time
and peak resident memory (from /proc).
"""

from __future__ import annotations

import argparse
import io
import multiprocessing
import os
import signal
import subprocess
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, ROOT)

from dnc.control import Control  # noqa: E402
from dnc.emulator import Emulator  # noqa: E402
from dnc.framing import Framer, split_lines  # noqa: E402
from dnc.journal import read_journal  # noqa: E402
from dnc.link import chars_per_second  # noqa: E402
from formats.profile import load_profile  # noqa: E402


def program(blocks: int, number: int) -> str:
    lines = ["%", f"O{number}", "N1 G21 G17 G90 G94", "N2 T1 M06", "N3 S3000 M03"]
    lines += [f"N{i + 4} G01 X{i % 97}.125 Y{i % 61}.5 F300." for i in range(blocks)]
    return "\n".join(lines + ["M30", "%"]) + "\n"


def machine(cps: float, share: float, number: int, link: str,
            expected: bytes) -> dict[str, float]:
    """One emulated control in its own process: ask for program ``number``, read it."""
    control = Control(cps=cps, buffer=128, rate=cps * share, allowance=10, tv_check=True,
                      dc1_every=0.05, keep_text=False, sink=io.BytesIO(), now=time.monotonic())
    emu = Emulator(control, punch=f"%\n(PRG={number})\n%\n".encode(), link=Path(link))
    emu.wait(600)
    emu.stop()
    s = control.stats
    return {"exact": control.sink.getvalue() == expected,  # type: ignore[union-attr]
            "most_after_dc3": s.most_after_dc3, "alarms": s.alarms_087, "dc3": s.dc3,
            "chars": s.chars, "utilisation": s.utilisation(cps), "tail": s.after_dc3,
            "alarm_lines": [e.line for e in s.errors if e.kind == "087"]}


def proc_stats(pid: int) -> tuple[float, float]:
    """CPU seconds (user + system) and peak resident MB of a running process."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    ticks = os.sysconf("SC_CLK_TCK")
    cpu = (int(fields[11]) + int(fields[12])) / ticks
    peak = 0.0
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmHWM:"):
            peak = int(line.split()[1]) / 1024
    return cpu, peak


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ports", type=int, default=32)
    ap.add_argument("--blocks", type=int, default=2000)
    ap.add_argument("--baud", type=int, default=115200)
    ap.add_argument("--machining", type=float, default=0.5,
                    help="the controls' reading speed as a share of the line (default 0.5)")
    ap.add_argument("--dc3-reaction", type=float, default=None,
                    help="the gateway's dc3_reaction in seconds (default: the gateway's own)")
    args = ap.parse_args()
    settings = replace(load_profile("fanuc-mill").serial, baud=args.baud)
    cps = chars_per_second(settings)
    with tempfile.TemporaryDirectory() as tmp_name:
        tmp = Path(tmp_name)
        (tmp / "programs").mkdir()
        expected = {}
        config = ["[gateway]\njournal = \"journal.jsonl\"\nrequest_timeout = 60\n"
                  "retry_first = 0.05\nretry_max = 0.5\n"
                  + ("" if args.dc3_reaction is None else
                     f"dc3_reaction = {args.dc3_reaction}\n")]
        for i in range(args.ports):
            text = program(args.blocks, 1000 + i)
            (tmp / "programs" / f"O{1000 + i}.nc").write_text(text)
            expected[i] = b"".join(d for _, d in Framer(settings).frames(split_lines([text])))
            config.append(f'[[port]]\nname = "m{i}"\nurl = "{tmp}/tty{i}"\n'
                          'profile = "fanuc-mill"\nprograms = "programs"\n'
                          f'receive = "received"\nserial = {{ baud = {args.baud} }}\n')
        (tmp / "gateway.toml").write_text("".join(config))
        env = dict(os.environ, PYTHONPATH=ROOT)
        service = subprocess.Popen([sys.executable, "-m", "tapegate", "serve", "--config",
                                    str(tmp / "gateway.toml"), "--log-level", "error"],
                                   env=env)
        time.sleep(1.0)  # the service opens its ports as they appear; give it a moment
        start = time.monotonic()
        context = multiprocessing.get_context("fork")
        with context.Pool(args.ports) as pool:
            results = pool.starmap(machine, [(cps, args.machining, 1000 + i,
                                              str(tmp / f"tty{i}"), expected[i])
                                             for i in range(args.ports)])
        wall = time.monotonic() - start
        cpu, peak = proc_stats(service.pid)
        service.send_signal(signal.SIGTERM)
        service.wait(30)
        exact = sum(r["exact"] for r in results)
        worst = max(r["most_after_dc3"] for r in results)
        alarms = sum(r["alarms"] for r in results)
        dc3 = sum(r["dc3"] for r in results)
        chars = sum(r["chars"] for r in results)
        utilisation = [r["utilisation"] for r in results]
        tail: dict[int, int] = {}
        for r in results:
            for count, times in r["tail"].items():
                tail[count] = tail.get(count, 0) + times
        sends = [t for t in read_journal(tmp / "journal.jsonl").transfers
                 if t.direction == "send" and t.result == "ok"]
    print(f"{args.ports} ports at {args.baud} baud, {args.blocks} blocks each "
          f"({len(expected[0])} bytes), controls machining at {args.machining:g} x the line "
          "speed")
    print(f"byte-exact: {exact}/{args.ports}; sends journalled ok: {len(sends)}")
    print(f"DC3 sent: {dc3}; most characters after a DC3: {worst} (allowance 10); "
          f"alarm 087: {alarms}")
    print("characters after a throttling DC3 (how many DC3s): "
          + ", ".join(f"{count}: {tail[count]}" for count in sorted(tail)))
    print(f"wall time {wall:.1f} s for {chars} characters ({chars / wall:,.0f} chars/s in all); "
          f"per-port utilisation while reading: mean {sum(utilisation) / len(utilisation):.1%}, "
          f"min {min(utilisation):.1%} (at most {args.machining:.0%}: the controls' speed)")
    if alarms:  # the controls read the same program in step: the same line is the same moment
        print("alarm 087 at program line: " + ", ".join(
            f"{line} (m{i})" for i, r in enumerate(results) for line in r["alarm_lines"]))
    print(f"service: {cpu:.1f} CPU s ({cpu / wall:.0%} of one core), peak RSS {peak:.0f} MB")


if __name__ == "__main__":
    main()
