"""FTP benchmark: the gateway's FTP server beside pyftpdlib's own plain server, with curl.

    .venv/bin/python benchmarks/ftp.py [--mb 10] [--runs 3] [--machines 20] [--machine-mb 1]

Two servers run as their own processes on loopback, in the same run:

* ``tapegate serve`` with FTP machines (``check = true``, ``compare = true``, the journal on):
  a download is checked, hashed and journalled, an upload written through a hidden temporary
  file, fsync'd, renamed, compared with the program folder's copy and journalled;
* ``python -m pyftpdlib`` on a plain folder: the same protocol library with nothing of ours.

curl (the client a shell script on a cell controller would use) downloads and uploads one
``--mb`` program ``--runs`` times on each; reported are the best and the median throughput and
the ratio gateway / plain. Then ``--machines`` curl processes at once, one per FTP machine, each
download their own ``--machine-mb`` program and upload it back: wall time, all byte-exact, the
journal's records. The service's CPU time comes from /proc.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, ROOT)

from benchmarks.program import blocks  # noqa: E402
from dnc.journal import read_journal  # noqa: E402
from dnc.passwords import hash_password  # noqa: E402

PASSWORD = "bench-pass"


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def write_program(path: Path, megabytes: float, number: int) -> bytes:
    """A clean synthetic program (the check passes) of about ``megabytes``."""
    out: list[str] = []
    size = 0
    for line in blocks(int(megabytes * 1e6 / 25) + 10, seed=number, clean=True):
        out.append(line)
        size += len(line) + 1
        if size >= megabytes * 1e6:
            break
    text = ("\n".join(out).replace("O1000 (BENCH)", f"O{number} (BENCH)")
            .replace("S12000", "S8000") + "\nM30\n%\n")  # fanuc-mill: 10,000 rpm at most
    path.write_text(text)
    return text.encode()


def wait_listening(port: int, timeout: float = 30) -> None:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        with socket.socket() as s:
            if s.connect_ex(("127.0.0.1", port)) == 0:
                return
        time.sleep(0.05)
    raise SystemExit(f"nothing listening on port {port}")


def cpu_seconds(pid: int) -> float:
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def curl(url: str, user: str, *args: str) -> float:
    """One curl run: the seconds it measured, from connecting to the end (login, the transfer,
    and the gateway's check of a download or compare of an upload, all in)."""
    done = subprocess.run(["curl", "-sS", "--max-time", "300", "-u", f"{user}:{PASSWORD}",
                           "-w", "%{time_total}", *args, url], capture_output=True, text=True,
                          check=True)
    return float(done.stdout.strip().splitlines()[-1])


def measure(base: str, user: str, upload: Path, received: Path | None, size: int, runs: int,
            name: str) -> tuple[list[float], list[float], list[float]]:
    """MB/s of each download and upload of ``name``, and the seconds of a listing of the
    folder (connect, login, one LIST: what a transfer costs besides its bytes); what the gateway
    received is removed after each run (the next upload is no new version)."""
    down, up, listing = [], [], []
    for _ in range(runs):
        down.append(size / 1e6 / curl(f"{base}/{name}", user, "-o", os.devnull))
        up.append(size / 1e6 / curl(f"{base}/{name}", user, "-T", str(upload)))
        listing.append(curl(f"{base}/", user, "-o", os.devnull))
        for leftover in received.iterdir() if received else ():
            leftover.unlink()
    return down, up, listing


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mb", type=float, default=10)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--machines", type=int, default=20)
    parser.add_argument("--machine-mb", type=float, default=1)
    a = parser.parse_args()
    if shutil.which("curl") is None:
        raise SystemExit("curl is needed (Debian: apt-get install curl)")
    tmp = Path(tempfile.mkdtemp(prefix="tapegate-ftp-bench-"))
    programs, plain = tmp / "programs", tmp / "plain"
    programs.mkdir()
    plain.mkdir()
    data = write_program(programs / "O1000.nc", a.mb, 1000)
    shutil.copy(programs / "O1000.nc", plain / "O1000.nc")
    upload = tmp / "upload.nc"
    upload.write_bytes(data)
    small = {i: write_program(programs / f"O{2000 + i}.nc", a.machine_mb, 2000 + i)
             for i in range(a.machines)}
    stored = hash_password(PASSWORD)
    gw_port, plain_port = free_port(), free_port()
    config = [f'[gateway]\njournal = "journal.jsonl"\n\n[ftp]\nenabled = true\n'
              f'listen = "127.0.0.1:{gw_port}"\n']
    for i in range(a.machines + 1):
        config.append(f'\n[[port]]\nname = "m{i}"\nurl = "ftp"\nftp_user = "m{i}"\n'
                      f'ftp_password_hash = "{stored}"\nprofile = "fanuc-mill"\n'
                      f'programs = "programs"\nreceive = "received/m{i}"\ncheck = true\n'
                      f'compare = true\nmax_upload = {int(a.mb * 2e6)}\n')
    # the same transfers without the check and the compare: the protocol, the journal, the
    # hidden temporary file, fsync and rename alone
    config.append(f'\n[[port]]\nname = "raw"\nurl = "ftp"\nftp_user = "raw"\n'
                  f'ftp_password_hash = "{stored}"\nprofile = "fanuc-mill"\n'
                  f'programs = "programs"\nreceive = "received/raw"\ncheck = false\n'
                  f'compare = false\nmax_upload = {int(a.mb * 2e6)}\n')
    (tmp / "gateway.toml").write_text("".join(config))
    env = dict(os.environ, PYTHONPATH=ROOT)
    gateway = subprocess.Popen([sys.executable, "-m", "tapegate", "serve", "--config",
                                str(tmp / "gateway.toml"), "--log-level", "warning"], env=env)
    server = subprocess.Popen([sys.executable, "-m", "pyftpdlib", "-i", "127.0.0.1", "-p",
                               str(plain_port), "-d", str(plain), "-w", "-u", "bench", "-P",
                               PASSWORD], stderr=subprocess.DEVNULL)
    try:
        wait_listening(gw_port)
        wait_listening(plain_port)
        cpu0 = cpu_seconds(gateway.pid)
        g_down, g_up, g_before = measure(f"ftp://127.0.0.1:{gw_port}", "m0", upload,
                               tmp / "received" / "m0", len(data), a.runs, "O1000.nc")
        cpu1 = cpu_seconds(gateway.pid)
        r_down, r_up, _ = measure(f"ftp://127.0.0.1:{gw_port}", "raw", upload,
                               tmp / "received" / "raw", len(data), a.runs, "O1000.nc")
        p_down, p_up, p_before = measure(f"ftp://127.0.0.1:{plain_port}", "bench", upload, None,
                               len(data), a.runs, "O1000.nc")
        print(f"{len(data) / 1e6:.1f} MB program, {a.runs} runs, MB/s from connecting to the "
              "end, best / median:")
        for label, g, r, p in (("download", g_down, r_down, p_down),
                               ("upload", g_up, r_up, p_up)):
            print(f"  {label:8}  gateway {max(g):6.1f} / {statistics.median(g):6.1f}   "
                  f"without check and compare {max(r):6.1f} / {statistics.median(r):6.1f}   "
                  f"plain pyftpdlib {max(p):6.1f} / {statistics.median(p):6.1f}   "
                  f"ratios (median) {statistics.median(g) / statistics.median(p):.2f}, "
                  f"{statistics.median(r) / statistics.median(p):.2f}")
        print(f"  gateway CPU for the {2 * a.runs} checked transfers: {cpu1 - cpu0:.2f} s")
        print(f"  a listing (connect, login, LIST), median: gateway "
              f"{statistics.median(g_before) * 1e3:.0f} ms (the login's scrypt hash), plain "
              f"{statistics.median(p_before) * 1e3:.0f} ms")

        # -- the machines at once
        start = time.monotonic()
        cpu2 = cpu_seconds(gateway.pid)
        jobs = []
        for i in range(a.machines):
            got = tmp / f"got{i}.nc"
            script = (f"curl -sS --max-time 300 -u m{i + 1}:{PASSWORD} "
                      f"ftp://127.0.0.1:{gw_port}/O{2000 + i} -o {got} && "
                      f"curl -sS --max-time 300 -u m{i + 1}:{PASSWORD} -T {got} "
                      f"ftp://127.0.0.1:{gw_port}/O{2000 + i}.nc")
            jobs.append(subprocess.Popen(["sh", "-c", script]))
        failed = sum(job.wait() != 0 for job in jobs)
        wall = time.monotonic() - start
        cpu3 = cpu_seconds(gateway.pid)
        exact = sum((tmp / f"got{i}.nc").read_bytes() == small[i]
                    and (tmp / "received" / f"m{i + 1}" / f"O{2000 + i}.nc").read_bytes()
                    == small[i] for i in range(a.machines))
        records = read_journal(tmp / "journal.jsonl").transfers
        ok = sum(t.result == "ok" for t in records if t.port not in ("m0", "raw"))
        total = sum(len(v) for v in small.values()) * 2
        print(f"{a.machines} machines at once, {a.machine_mb:g} MB each, down and up: "
              f"{wall:.2f} s wall, {total / 1e6 / wall:.1f} MB/s together, "
              f"{exact}/{a.machines} byte-exact both ways, {failed} curl failures, "
              f"{ok} journal records ok, gateway CPU {cpu3 - cpu2:.2f} s")
        digest = hashlib.sha256(data).hexdigest()
        sends = [t for t in records if t.port == "m0" and t.direction == "send"]
        assert all(t.sha256 == digest for t in sends), "a download's SHA-256 differs"
    finally:
        for process in (gateway, server):
            process.terminate()
            process.wait(30)
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
