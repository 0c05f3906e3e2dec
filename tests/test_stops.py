"""A stop (^C, SIGTERM) whose exception the interpreter swallowed is still obeyed.

A signal's handler raises its exception wherever Python code runs next; where that is a
finalizer (a ``__del__``, a weak reference's callback: an import's module lock freed, a
collection), the interpreter prints it as "Exception ignored" and goes on. A command then
waiting on a FIFO whose writer never ends, or on a pipe nobody reads, waited for ever: 1 in some
hundred CI runs (the ^C of `check FIFO`, the SIGTERM of `convert -o -`). The handlers note the
signal, and the waits ask first (``formats.stops``). The finalizer here takes the
signal on purpose, so the swallow happens every time."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

SWALLOW = """
import os, sys
from formats.files import exit_on_termination
from formats.stops import note_interrupts
exit_on_termination()
note_interrupts()
class Finalized:
    def __del__(self):
        os.kill(os.getpid(), {signum})
        for _ in range(10000):  # the handler runs here, in the finalizer: its exception is lost
            pass
Finalized()
print("swallowed", file=sys.stderr, flush=True)
"""


def _run(script: str, stdout: int = subprocess.PIPE) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run([sys.executable, "-c", script], stdout=stdout, stderr=subprocess.PIPE,
                          timeout=60, env={**os.environ, "PYTHONPATH": str(ROOT)}, check=False,
                          preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_a_swallowed_stop_ends_a_write_into_a_pipe_nobody_reads(signum: int) -> None:
    reader, writer = os.pipe()  # (nobody reads it: the write would wait for ever)
    try:
        script = SWALLOW.format(signum=int(signum)) + (
            "from tapegate.common import write_stream\n"
            "try:\n"
            "    write_stream('-', [b'x' * 1_000_000])\n"
            "except KeyboardInterrupt:\n"
            "    sys.exit(1)\n"
            "print('not stopped', file=sys.stderr)\n")
        done = _run(script, stdout=writer)
    finally:
        os.close(reader)
        os.close(writer)
    assert b"swallowed" in done.stderr and b"not stopped" not in done.stderr
    assert done.returncode == (1 if signum == signal.SIGINT else 128 + signal.SIGTERM)


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_a_swallowed_stop_ends_the_copy_of_a_fifo_whose_writer_never_ends(
        tmp_path: Path, signum: int) -> None:
    fifo = tmp_path / "f.nc"
    os.mkfifo(fifo)
    writer = os.open(fifo, os.O_RDWR)  # (a writer that never closes)
    try:
        os.write(writer, b"%\nO1000\n")
        script = SWALLOW.format(signum=int(signum)) + (
            "from tapegate.common import input_path\n"
            "try:\n"
            f"    input_path({str(fifo)!r})\n"
            "except KeyboardInterrupt:\n"
            "    sys.exit(1)\n"
            "print('not stopped', file=sys.stderr)\n")
        done = _run(script)
    finally:
        os.close(writer)
    assert b"swallowed" in done.stderr and b"not stopped" not in done.stderr
    assert done.returncode == (1 if signum == signal.SIGINT else 128 + signal.SIGTERM)


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_a_swallowed_stop_is_not_told_with_a_traceback(signum: int) -> None:
    """The command's own process (quiet_swallowed_stops, set by tapegate.launch): the stop a
    finalizer swallowed prints no "Exception ignored ... Traceback" (it is obeyed at the next
    wait); another exception of a finalizer is reported as before."""
    script = ("from formats.stops import quiet_swallowed_stops\nquiet_swallowed_stops()\n"
              + SWALLOW.format(signum=int(signum)) + (
                  "class Broken:\n"
                  "    def __del__(self):\n"
                  "        raise ValueError('a finalizer of its own')\n"
                  "Broken()\n"
                  "from formats.stops import heed_stops\n"
                  "try:\n"
                  "    heed_stops()\n"
                  "except KeyboardInterrupt:\n"
                  "    sys.exit(1)\n"
                  "print('not stopped', file=sys.stderr)\n"))
    done = _run(script)
    err = done.stderr.decode()
    assert "swallowed" in err and "not stopped" not in err
    assert done.returncode == (1 if signum == signal.SIGINT else 128 + signal.SIGTERM)
    # only the other finalizer's exception is reported, once
    assert err.count("Exception ignored") == 1 and "ValueError: a finalizer of its own" in err
    assert "KeyboardInterrupt" not in err and "SystemExit" not in err
    # without the hook, the swallowed stop is reported (what the CI's run printed)
    done = _run(SWALLOW.format(signum=int(signal.SIGINT)))
    assert b"Exception ignored" in done.stderr and b"KeyboardInterrupt" in done.stderr


def test_a_stop_taken_as_usual_is_not_raised_twice() -> None:
    """The note is only read before a wait: a command that handled its stop (the exception
    raised where it should be) ends with it once."""
    script = ("import os, signal, sys\n"
              "from formats.stops import note_interrupts\nnote_interrupts()\n"
              "try:\n    os.kill(os.getpid(), signal.SIGINT)\n"
              "    for _ in range(10000): pass\n"
              "except KeyboardInterrupt:\n    print('taken', file=sys.stderr)\n")
    done = _run(script)
    assert done.returncode == 0 and done.stderr == b"taken\n"


def test_a_stop_is_raised_once_and_a_new_command_forgets_the_last_ones() -> None:
    """Review 53, F10: after one ^C, a caller's next command (``main(clean_exit=True)``) was
    stopped at its first wait by the first's note."""
    from formats import stops

    before = signal.getsignal(signal.SIGINT)
    try:
        stops.TAKEN.append(signal.SIGINT)
        with pytest.raises(KeyboardInterrupt):
            stops.heed_stops()
        stops.heed_stops()  # (raised once)
        stops.TAKEN.append(signal.SIGTERM)
        stops.note_interrupts()  # (a new command's start)
        stops.heed_stops()
        assert stops.TAKEN == []
    finally:
        stops.TAKEN.clear()
        signal.signal(signal.SIGINT, before)


def _fed(proc: subprocess.Popen[bytes], until: Callable[[], bool] | None = None,
         timeout: float = 60) -> tuple[int, bytes]:
    """``proc`` (a `check -`) given a program's first lines on its standard input, which is
    then left open (the copy of it waits for more, as of a writer that never ends); once
    ``until`` holds (looked at every 10 ms: it may send the signal), its exit code within
    ``timeout`` seconds and its standard error. Killed past the timeout (TimeoutExpired
    raised), its pipes closed either way (tests.test_convert_interrupt.ended)."""
    from tests.test_convert_interrupt import ended

    assert proc.stdin is not None
    try:
        proc.stdin.write(b"%\nO1000\nG0 X0\n")
        proc.stdin.flush()  # (and left open)
        deadline = time.monotonic() + 60
        while until is not None and not until():
            assert proc.poll() is None and time.monotonic() < deadline
            time.sleep(0.01)
    except BaseException:
        proc.kill()
        ended(proc, 60)
        raise
    return ended(proc, timeout)


def test_sigterm_to_a_check_of_standard_input_leaves_no_copy(tmp_path: Path) -> None:
    """Review 53, F14: `check -` stopped by SIGTERM left its copy of standard input in the
    temporary folder; the copy's making makes SIGTERM an exit, which removes it."""
    temp = tmp_path / "temp"
    temp.mkdir()
    exe = Path(sys.executable).with_name("tapegate")
    if not exe.exists():
        pytest.skip("needs the tapegate command")
    proc = subprocess.Popen([str(exe), "check", "-p", "fanuc-mill", "-"], stdin=subprocess.PIPE,
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            env={**os.environ, "PYTHONPATH": str(ROOT), "TMPDIR": str(temp)})

    def copying() -> bool:
        if list(temp.iterdir()):
            proc.send_signal(signal.SIGTERM)
            return True
        return False

    code, err = _fed(proc, copying)
    assert code == 128 + signal.SIGTERM, err
    assert b"Traceback" not in err
    assert list(temp.iterdir()) == []


def test_a_ctrl_c_in_the_start_up_is_told_as_the_commands_own(
        monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    """Review 53, F11: a ^C while the command's modules were imported printed a traceback."""
    from tapegate import launch

    def interrupted(argv: list[str]) -> None:
        raise KeyboardInterrupt

    before = signal.getsignal(signal.SIGINT)
    monkeypatch.setattr(launch, "plain", interrupted)
    monkeypatch.setattr(sys, "argv", ["tapegate", "check", "x.nc"])
    try:
        with pytest.raises(SystemExit) as done:
            launch.main(clean_exit=True)
    finally:
        signal.signal(signal.SIGINT, before)
    assert done.value.code == 1
    assert capsys.readouterr().err == "\nAborted!\n"


AIMED_READ = """
import signal, sys, threading, time
main_thread = threading.get_native_id()

def asleep() -> bool:
    with open(f"/proc/self/task/{{main_thread}}/stat") as stat:
        return stat.read().rsplit(")", 1)[1].split()[0] == "S"

def aim() -> None:
    while not (sys.modules.get("tempfile") and asleep()):  # (the copy of stdin begun)
        time.sleep(0.001)
    time.sleep(0.05)  # (the main thread's own waits before the read are short)
    while not asleep():
        time.sleep(0.001)
    print("aimed", file=sys.stderr, flush=True)
    signal.pthread_kill(threading.get_ident(), {signum})

threading.Thread(target=aim, daemon=True).start()
sys.argv = ["tapegate", "check", "-p", "fanuc-mill", "-"]
from tapegate.launch import main
main()
"""


@pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="needs Linux's /proc")
@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_a_signal_that_never_interrupts_the_read_of_stdin_still_stops_it(
        tmp_path: Path, signum: int) -> None:
    """The lost wake-up of the copy of standard input (tests/test_convert_interrupt.py, AIMED,
    tells it for the write): a signal whose C handler runs but that interrupts no system call
    of the main thread (here: handed to another thread, as the kernel may) left the read of a
    pipe whose writer never ends waiting for ever. The read now begins only once a poll on the
    pipe and on the signal's wakeup fd says so (formats.stops.read_some)."""
    temp = tmp_path / "temp"
    temp.mkdir()
    proc = subprocess.Popen([sys.executable, "-c", AIMED_READ.format(signum=int(signum))],
                            stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE,
                            env={**os.environ, "PYTHONPATH": str(ROOT), "TMPDIR": str(temp)},
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    code, err = _fed(proc, timeout=30)  # (the command's own thread sends the signal)
    assert err.startswith(b"aimed\n"), err
    assert code == (1 if signum == signal.SIGINT else 128 + signum), err
    assert list(temp.iterdir()) == []


# -- a pipe written through its non-blocking twin (review 62c F4) -------------------------------


@pytest.mark.skipif(not Path("/proc/self/fd").is_dir(), reason="needs Linux's /proc")
def test_a_pipes_twin_is_non_blocking_and_leaves_the_pipes_own_description_blocking(
        tmp_path: Path) -> None:
    """The twin is a new open file description of the same pipe: O_NONBLOCK on it alone, the
    descriptor's own (shared with the shell and the other processes) untouched; none for a
    regular file or a socket (their write stays the polled one)."""
    import fcntl
    import socket

    from formats import stops

    reader, writer = os.pipe()
    twin = stops._twin(writer)
    try:
        assert twin >= 0 and twin != writer
        assert fcntl.fcntl(twin, fcntl.F_GETFL) & os.O_NONBLOCK
        assert not fcntl.fcntl(writer, fcntl.F_GETFL) & os.O_NONBLOCK
        assert not os.get_inheritable(twin)
        os.write(twin, b"one ")
        os.write(writer, b"two")
        assert os.read(reader, 100) == b"one two"  # (one pipe)
        size = fcntl.fcntl(writer, 1032)  # F_GETPIPE_SZ
        with pytest.raises(BlockingIOError):  # full: the twin never waits
            while True:
                os.write(twin, b"x" * 65536)
        assert os.read(reader, 65536) and size > 0
    finally:
        for fd in (reader, writer, twin):
            os.close(fd)
    with open(tmp_path / "f", "wb") as f:
        assert stops._twin(f.fileno()) == -1
    left, right = socket.socketpair()
    with left, right:
        assert stops._twin(left.fileno()) == -1


def written(how: str, writer: int, data: bytes) -> None:
    """``data`` written into the pipe ``writer``, whole, by ``write_all`` (a report's pieces) or
    by a guarded stdout's raw writer (``how``: "write_all" or "guarded")."""
    from formats import stops

    if how == "write_all":
        assert stops.write_all(writer, [data[:1000], data[1000:]]) == len(data)
    else:
        with stops._Wakeup() as wakeup:
            raw = stops._PolledWriter(writer, wakeup)
            assert raw.write(data) == len(data)  # (whole: a text layer over it loses none)
            raw.close()


def read_slowly(reader: int, writer: int, write: Callable[[], None]) -> tuple[bytes, list[int]]:
    """What ``write()`` puts into the pipe ``writer`` (closed after it, and ``reader`` once
    read to its end), read by a thread slower than it is written, so that the pipe fills:
    (the bytes read, each read's size)."""
    import threading

    got = bytearray()
    reads: list[int] = []

    def read() -> None:
        while piece := os.read(reader, 1 << 16):
            reads.append(len(piece))
            got.extend(piece)
            time.sleep(0.0005)

    thread = threading.Thread(target=read)
    thread.start()
    try:
        write()
    finally:
        os.close(writer)
        thread.join(timeout=60)
        os.close(reader)
    return bytes(got), reads


@pytest.mark.skipif(not Path("/proc/self/fd").is_dir(), reason="needs Linux's /proc")
@pytest.mark.parametrize("how", ["write_all", "guarded"])
def test_a_big_write_into_a_pipe_goes_in_large_writes_and_whole(
        monkeypatch: pytest.MonkeyPatch, how: str) -> None:
    """A big report into a pipe read slower than it is written: written in writes as large
    as the pipe takes (not 4,096 bytes each after a poll: 22-33 % more CPU, review 62c F4),
    a poll only where the pipe was full, every byte in order."""
    from formats import stops

    data = bytes(range(256)) * 16384  # 4 MiB
    reader, writer = os.pipe()
    sizes: list[int] = []
    polls: list[int] = []
    real_write, real_ready = os.write, stops._ready

    def write(fd: int, piece: bytes) -> int:
        sizes.append(len(piece))
        return real_write(fd, piece)

    def ready(fd: int, events: int, wakeup: object) -> bool:
        polls.append(fd)
        return real_ready(fd, events, wakeup)  # type: ignore[arg-type]

    def counted() -> None:
        monkeypatch.setattr(os, "write", write)
        monkeypatch.setattr(stops, "_ready", ready)
        written(how, writer, data)
        monkeypatch.undo()

    got, _ = read_slowly(reader, writer, counted)
    assert got == data
    assert max(sizes) > stops.PIPE_BUF
    assert len(sizes) < len(data) // stops.PIPE_BUF // 4  # (was one a 4,096 bytes)
    assert len(polls) < len(sizes)  # (a poll only on a full pipe)


@pytest.mark.skipif(not Path("/proc/self/fd").is_dir(), reason="needs Linux's /proc")
@pytest.mark.parametrize("how", ["write_all", "guarded"])
def test_a_pipe_in_packet_mode_keeps_its_packets(how: str) -> None:
    """A pipe made in packet mode (``pipe2(O_DIRECT)``) gets no twin: a description opened
    anew would write without ``O_DIRECT``, its writes running together, where a reader of the
    packets gets one packet (at most 4,096 bytes) a read. Its own descriptor's writes keep
    them (``pwritev2(RWF_NOWAIT)`` where the kernel's pipes take it, else polled): every read
    at most 4,096 bytes, every byte in order (review 63's N2)."""
    from formats import stops

    try:
        reader, writer = os.pipe2(os.O_DIRECT)
    except OSError as exc:  # (a kernel without packet-mode pipes: before Linux 3.4)
        pytest.skip(f"no packet-mode pipe: {exc}")
    assert stops._twin(writer) == -1
    data = bytes(range(256)) * 1024  # 256 KiB, four times a pipe's room
    # (a slow reader: the pipe fills, the writes poll)
    got, reads = read_slowly(reader, writer, lambda: written(how, writer, data))
    assert got == data
    assert max(reads) <= stops.PIPE_BUF


def _nowait_on_pipes() -> bool:
    """Whether this kernel's pipes take ``pwritev2``'s RWF_NOWAIT (EOPNOTSUPP where not)."""
    if not hasattr(os, "RWF_NOWAIT"):
        return False
    reader, writer = os.pipe()
    try:
        return os.pwritev(writer, [b"x"], -1, os.RWF_NOWAIT) == 1
    except OSError:
        return False
    finally:
        os.close(reader)
        os.close(writer)


@pytest.mark.skipif(os.name != "posix" or not hasattr(os, "geteuid") or os.geteuid() != 0
                    or not _nowait_on_pipes(),
                    reason="needs root (to make another user's pipe) and RWF_NOWAIT on pipes")
@pytest.mark.parametrize("how", ["write_all", "guarded"])
def test_another_users_pipe_is_written_in_large_writes_without_a_twin(how: str) -> None:
    """Review 63's N4: ``sudo -u USER tapegate ... | cat`` from root's shell gives the command
    a pipe root made: its inode root's, mode 0600, so the twin's open of /proc/self/fd/1 is
    refused (EACCES) and every write went 4,096 bytes after a poll. Now such a pipe is written
    on its own description by ``pwritev2(RWF_NOWAIT)``: as much as the pipe takes at once,
    never waiting, its flags (shared with the shell) untouched. A forked child that became
    ``nobody`` writes 4 MiB into a pipe this process (root) made."""
    import fcntl
    import json

    from formats import stops

    data = bytes(range(256)) * 16384  # 4 MiB
    reader, writer = os.pipe()
    told_r, told_w = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: nobody, writing; its result on told_w
        code = 1
        try:
            os.close(reader)
            os.close(told_r)
            os.setgid(65534)
            os.setuid(65534)
            sizes: list[int] = []
            pwritev = os.pwritev

            def counted(fd: int, buffers: list[bytes], at: int, flags: int = 0) -> int:
                n = pwritev(fd, buffers, at, flags)
                sizes.append(n)
                return n

            os.pwritev = counted  # type: ignore[assignment]
            twin = stops._twin(writer)
            written(how, writer, data)
            blocking = not fcntl.fcntl(writer, fcntl.F_GETFL) & os.O_NONBLOCK
            os.write(told_w, json.dumps([twin, len(sizes), max(sizes, default=0),
                                         blocking]).encode())
            code = 0
        except BaseException as exc:
            os.write(told_w, repr(exc).encode())
        finally:
            os._exit(code)
    os.close(writer)
    os.close(told_w)
    got = bytearray()
    while piece := os.read(reader, 1 << 16):
        got.extend(piece)
    os.close(reader)
    _, status = os.waitpid(pid, 0)
    with os.fdopen(told_r, "rb") as told:
        result = told.read().decode()
    assert os.waitstatus_to_exitcode(status) == 0, result
    twin, writes, largest, blocking = json.loads(result)
    assert twin == -1  # (refused: another user's pipe)
    assert bytes(got) == data
    assert largest > stops.PIPE_BUF and writes < len(data) // stops.PIPE_BUF // 4
    assert blocking  # (the description the shell shares keeps its flags)


@pytest.mark.parametrize("how", ["write_all", "guarded"])
def test_a_kernel_that_refuses_rwf_nowait_on_a_pipe_leaves_the_polled_writes(
        monkeypatch: pytest.MonkeyPatch, how: str) -> None:
    """Where the pipe has no twin and the kernel refuses RWF_NOWAIT on pipes (EOPNOTSUPP,
    before writing a byte), the writes go 4,096 bytes after a poll, as before: whole, in
    order."""
    import errno

    from formats import stops

    def refused(fd: int, buffers: object, at: int, flags: int = 0) -> int:
        raise OSError(errno.EOPNOTSUPP, os.strerror(errno.EOPNOTSUPP))

    monkeypatch.setattr(stops, "_twin", lambda fd: -1)
    monkeypatch.setattr(os, "RWF_NOWAIT", 8, raising=False)
    monkeypatch.setattr(os, "pwritev", refused)
    data = bytes(range(256)) * 1024  # 256 KiB, four times a pipe's room
    reader, writer = os.pipe()
    assert stops._nowait(writer)
    got, _ = read_slowly(reader, writer, lambda: written(how, writer, data))
    assert got == data


@pytest.mark.skipif(not Path("/proc/self/fd").is_dir(), reason="needs Linux's /proc")
def test_a_guarded_stdout_pointed_elsewhere_writes_there_and_not_into_its_pipe() -> None:
    """A stopped command's stdout is made /dev/null (tapegate.launch._drop_pipes) so that the
    exit's flush never waits on the pipe: the twin, a description of the pipe, must not go on
    writing into it. The writer sees the descriptor changed and drops the twin."""
    from formats import stops

    reader, writer = os.pipe()
    spare = os.dup(writer)
    try:
        with stops._Wakeup() as wakeup:
            raw = stops._PolledWriter(writer, wakeup)
            assert raw._twin >= 0
            raw.write(b"before\n")
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, writer)
            os.close(devnull)
            raw.write(b"after\n" * 100_000)  # (into a full pipe: would wait for ever)
            assert raw._twin == -1
            raw.close()
        os.close(spare)
        spare = -1
        os.close(writer)
        writer = -1
        assert os.read(reader, 1 << 20) == b"before\n"
    finally:
        for fd in (reader, writer, spare):
            if fd >= 0:
                os.close(fd)


UNBUFFERED = """
import sys
from formats.stops import guard_stdout
guard_stdout()
sys.stdout.write("line one\\n")  # (no flush)
print("written", file=sys.stderr, flush=True)
sys.stdin.read()  # (until the test has looked)
"""


@pytest.mark.parametrize("how", ["PYTHONUNBUFFERED", "-u", "buffered"])
def test_a_guarded_stdout_is_unbuffered_where_python_made_it_so(how: str) -> None:
    """Review 62c F5: ``PYTHONUNBUFFERED=1`` or ``python -u`` make standard output unbuffered
    (a service's log seen at once, ``2>&1`` in order); the guarded stream kept a buffer all the
    same. Now it writes each write at once where Python's own stream did, and buffers where
    that one did (the line waits for the exit's flush)."""
    import select

    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    env.pop("PYTHONUNBUFFERED", None)
    if how == "PYTHONUNBUFFERED":
        env["PYTHONUNBUFFERED"] = "1"
    args = [sys.executable, *(["-u"] if how == "-u" else []), "-c", UNBUFFERED]
    proc = subprocess.Popen(args, stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, env=env)
    assert proc.stdin is not None and proc.stdout is not None and proc.stderr is not None
    try:
        assert proc.stderr.readline() == b"written\n"  # (after the write to stdout)
        ready, _, _ = select.select([proc.stdout], [], [], 0)
        seen = os.read(proc.stdout.fileno(), 100) if ready else b""
        assert proc.poll() is None  # (still running: no exit's flush yet)
        proc.stdin.close()
        rest = proc.stdout.read()
        assert proc.wait(timeout=60) == 0
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        proc.stdout.close()
        proc.stderr.close()
    assert seen + rest == b"line one\n"
    assert seen == (b"" if how == "buffered" else b"line one\n")


@pytest.mark.skipif(not Path("/proc/self/fd").is_dir(), reason="needs Linux's /proc")
def test_a_pipes_read_end_given_as_stdout_is_not_written_into() -> None:
    """Standard output the read end of a pipe (``1<&0``): a twin opened anew through /proc
    for writing would write the report into the pipe the command was given to read, and the
    guarded writer's poll for room waited for ever (review 63 of io63, N1). No twin, no
    guard: the write fails with EBADF at once, as before hang62 (exit 2, told)."""
    from formats import stops

    reader, writer = os.pipe()
    try:
        assert stops._twin(reader) == -1
        with pytest.raises(OSError):
            stops.write_all(reader, [b"x" * 100_000])
        done = subprocess.run([sys.executable, "-c", "import sys\n"
                               "sys.argv = ['tapegate', 'check', '-p', 'fanuc-mill', '-']\n"
                               "from tapegate.launch import main\nmain()\n"],
                              input=b"%\nO1000\nG0 X1\nM30\n%\n", stdout=reader,
                              stderr=subprocess.PIPE, timeout=60,
                              env={**os.environ, "PYTHONPATH": str(ROOT)})
        assert done.returncode != 0 and b"Bad file descriptor" in done.stderr, done.stderr
        os.set_blocking(reader, False)
        with pytest.raises(BlockingIOError):  # nothing written into the pipe
            os.read(reader, 100)
    finally:
        os.close(reader)
        os.close(writer)


SEQPACKET = """
import sys
from formats.stops import guard_stdout, write_all
guard_stdout()
print("report", flush=True)
write_all(1, [b"copy"])
"""


@pytest.mark.parametrize("kind", ["SOCK_SEQPACKET", "SOCK_DGRAM"])
def test_a_packet_socket_as_stdout_gets_no_empty_packet(kind: str) -> None:
    """Stdout a packet socket: the probe for a pipe's read end (a zero-length write) is made
    on pipes only -- on a SOCK_SEQPACKET socket it sends an empty packet, which its reader
    takes for the end, and on a datagram socket an empty datagram (review 63 of io63, F3)."""
    import socket

    left, right = socket.socketpair(socket.AF_UNIX, getattr(socket, kind))
    with left, right:
        done = subprocess.run([sys.executable, "-c", SEQPACKET], stdout=left.fileno(),
                              stderr=subprocess.PIPE, timeout=60,
                              env={**os.environ, "PYTHONPATH": str(ROOT)})
        assert done.returncode == 0, done.stderr
        left.close()
        right.setblocking(False)
        got = []  # (every packet the command sent: it has ended)
        while True:
            try:
                got.append(right.recv(65536))
            except BlockingIOError:
                break
            if kind == "SOCK_SEQPACKET" and got[-1] == b"" and len(got) > 1 and b"copy" in got:
                got.pop()  # (the end, once the sender's socket is closed)
                break
    assert b"" not in got and b"".join(got) == b"report\ncopy", got
