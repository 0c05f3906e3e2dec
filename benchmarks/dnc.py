"""DNC benchmarks: line utilisation, characters after DC3, CPU per MB, memory for a big program.

    .venv/bin/python benchmarks/dnc.py [--seconds 3] [--memory-mb 100]

* **Utilisation**: a non-throttling emulated control on a pty reads a program lasting about
  ``--seconds`` of wire time at 9600, 38400 and 115200 baud; utilisation is characters ÷ what the
  wire carries from the first character to the last (the emulator's wire model).
* **Paced**: the same at 115200 baud with ``dc3_reaction`` 4 ms (the gateway's default): the
  sender paces itself at (allowance 10 - 5 ahead) / 4 ms = 1,250 characters a second, 12 % of
  the line; the utilisation it reaches (the figure ``tests/test_dnc_serial.py`` no longer
  asserts: a test on a loaded machine asserts the pace as a bound, never a throughput).
* **After DC3**: a control with a 64-character buffer machining at a quarter of the line speed,
  4800 to 115200 baud; the most characters that arrived after any DC3 (allowance 10).
* **CPU per MB**: CPU seconds of the sending thread per MB sent (the emulator thread excluded).
* **Memory**: peak RSS of a fresh process that frames and sends ``--memory-mb`` MB through the
  sans-I/O sender with a fake clock and a null link (the port adds nothing that grows with the
  program), compared with a program a tenth of the size.
"""

from __future__ import annotations

import argparse
import io
import json
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import replace

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, ROOT)

from benchmarks.program import write  # noqa: E402
from dnc.control import Control  # noqa: E402
from dnc.emulator import Emulator  # noqa: E402
from dnc.framing import Framer, split_lines  # noqa: E402
from dnc.link import chars_per_second, open_port  # noqa: E402
from dnc.sender import FlowSettings  # noqa: E402
from dnc.session import send_frames  # noqa: E402
from formats.profile import load_profile  # noqa: E402
from formats.source import Source  # noqa: E402


def one_run(path: str, baud: int, *, buffer: int, rate_share: float | None,
            reaction: float = 0.0) -> dict[str, float]:
    s = replace(load_profile("fanuc-mill").serial, baud=baud)
    cps = chars_per_second(s)
    control = Control(cps=cps, buffer=buffer, rate=None if rate_share is None else
                      cps * rate_share, allowance=s.overrun_allowance, tv_check=s.tv_check,
                      dc1_every=0.05, keep_text=False, sink=io.BytesIO())
    emulator = Emulator(control)
    try:
        port = open_port(emulator.path, s)
        framer = Framer(s)
        cpu = time.thread_time()
        result = send_frames(port, framer.frames(split_lines(Source(path).chunks())),
                             FlowSettings(cps=cps, xon_timeout=30, reaction=reaction),
                             leader=framer.leader(), trailer=framer.trailer())
        cpu = time.thread_time() - cpu
        port.close()
        emulator.wait(5)
    finally:
        emulator.stop()
    st = control.stats
    return {"baud": baud, "bytes": result.sent, "seconds": round(result.elapsed, 2),
            "utilisation": round(st.utilisation(cps), 4), "dc3": st.dc3,
            "most_after_dc3": st.most_after_dc3, "alarm_087": st.alarms_087,
            "cpu_s_per_mb": round(cpu / (result.sent / 1e6), 1)}


MEMORY = """
import resource, sys
sys.path.insert(0, {root!r})
from dnc.framing import Framer, split_lines
from dnc.sender import FlowSettings, Sender, Write
from formats.profile import load_profile
from formats.source import Source
s = load_profile("fanuc-mill").serial
framer = Framer(s)
frames = framer.frames(split_lines(Source({path!r}).chunks()))
sender = Sender(FlowSettings(cps=1e9, ahead=4096, wait_for_dc1=False), 0.0)
t = 0.0
sent = 0
while True:
    while sender.wants_data:
        item = next(frames, None)
        if item is None:
            sender.finish()
            break
        sender.feed(item[1])
    actions = sender.time_passed(t)
    if not actions:
        if sender.state == "done":
            break
        t += 1e-6
        continue
    for a in actions:
        if isinstance(a, Write):
            sender.bytes_accepted(len(a.data), t)
            sent += len(a.data)
    t += 4096e-9
print(sent, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
"""


def memory(path: str) -> tuple[int, float]:
    out = subprocess.run([sys.executable, "-c", MEMORY.format(root=ROOT, path=path)],
                         capture_output=True, text=True, check=True).stdout.split()
    return int(out[0]), int(out[1]) / 1024


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--seconds", type=float, default=3.0)
    parser.add_argument("--memory-mb", type=int, default=100)
    args = parser.parse_args()
    folder = tempfile.mkdtemp()
    results = []
    for baud in (9600, 38400, 115200):
        path = os.path.join(folder, f"u{baud}.nc")
        write(path, int(baud / 11 * args.seconds / 26))  # blocks of about 26 characters
        results.append({"job": "utilisation"} | one_run(path, baud, buffer=4096,
                                                       rate_share=None))
        print(json.dumps(results[-1]), flush=True)
    path = os.path.join(folder, "p115200.nc")
    write(path, int(1250 * args.seconds / 26))  # about --seconds at the pace
    results.append({"job": "paced", "dc3_reaction": 0.004} | one_run(
        path, 115200, buffer=4096, rate_share=None, reaction=0.004))
    print(json.dumps(results[-1]), flush=True)
    for baud in (4800, 9600, 19200, 38400, 57600, 115200):
        path = os.path.join(folder, f"t{baud}.nc")
        write(path, int(baud / 11 * args.seconds / 4 / 26))
        results.append({"job": "after_dc3"} | one_run(path, baud, buffer=64, rate_share=0.25))
        print(json.dumps(results[-1]), flush=True)
    for mb in (args.memory_mb // 10, args.memory_mb):
        path = os.path.join(folder, f"m{mb}.nc")
        write(path, mb * 1_000_000 // 26)
        start = time.perf_counter()
        sent, rss = memory(path)
        print(json.dumps({"job": "memory", "bytes": sent, "peak_rss_mb": round(rss, 1),
                          "seconds": round(time.perf_counter() - start, 1)}), flush=True)
        os.unlink(path)


if __name__ == "__main__":
    main()
