"""^C in the middle of `tapegate convert DIR --out-dir OUT -j 2` (review 39, finding 7): the
command says "Aborted!" and exits 1, every output already named is complete, and no temporary
file of the run (a hidden `.NAME.XXXXXXXX.part`) is left, at whatever moment the signal
lands. Each temporary file is entered in the core's list of them in the step that makes it,
and what is left of the list at the exit is removed (formats.files, crates/python/src/
commits.rs)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
VARIANTS = 4  # programs that differ, so that an output named from the wrong input shows


def _program(variant: int, blocks: int) -> str:
    lines = ["%", f"O{1000 + variant}", "G21 G90 G94 G17", "T1 M06", "S2000 M03",
             "G00 X0. Y0. Z5."]
    lines += [f"G01 X{(i + variant) % 97}.{i % 10} Y{(i * 7) % 89}.25 F{100 + i % 50}."
              for i in range(blocks)]
    return "\n".join([*lines, "M05", "M30", "%"]) + "\n"


def _exe() -> str:
    return str(Path(sys.executable).with_name("tapegate"))


ARGS = ["--from", "fanuc-mill", "--to", "fanuc-mill", "--units", "inch"]


def _default_sigint() -> None:
    # (a test run in the background may inherit SIGINT ignored: Python then leaves it so)
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def _wait_for(condition, proc: subprocess.Popen[bytes], timeout: float) -> bool:
    """Polls ``condition`` until it holds (True) or the process ended or ``timeout`` passed."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return True
        if proc.poll() is not None:
            return False
        time.sleep(0.0005)
    return False


@pytest.mark.skipif(not Path(_exe()).exists(), reason="needs the tapegate command")
def test_ctrl_c_mid_batch_leaves_no_temporary_file_and_only_whole_outputs(tmp_path):
    started = time.monotonic()
    cam = tmp_path / "cam"
    cam.mkdir()
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    # each variant's single conversion: what every output of that input must be, byte for byte
    expected: dict[int, bytes] = {}
    for variant in range(VARIANTS):
        (tmp_path / f"v{variant}.nc").write_text(_program(variant, 300))
        done = subprocess.run([_exe(), "convert", str(tmp_path / f"v{variant}.nc"), "-o",
                               str(tmp_path / f"r{variant}.nc"), *ARGS], env=env,
                              capture_output=True, timeout=60, check=False)
        assert done.returncode == 0, done.stderr
        expected[variant] = (tmp_path / f"r{variant}.nc").read_bytes()
    count = 1500
    for n in range(count):
        (cam / f"p{n:04d}.nc").write_text(_program(n % VARIANTS, 300))
    scratch = tmp_path / "tmp"  # the batch's spilled notes, if any: nothing may stay there
    scratch.mkdir()
    moments = (0, 1, 2, 5, 20, 60)
    interrupted = 0
    for moment in moments:
        out = tmp_path / f"out{moment}"
        out.mkdir()

        def named(out: Path = out, moment: int = moment) -> bool:
            # the outputs named (a temporary file is hidden), or for 0 the first temporary
            return sum(1 for name in os.listdir(out)
                       if (name.startswith(".") if moment == 0 else
                           not name.startswith("."))) >= max(moment, 1)

        proc = subprocess.Popen([_exe(), "convert", str(cam), "--out-dir", str(out), *ARGS,
                                 "-j", "2"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                env={**env, "TMPDIR": str(scratch)},
                                preexec_fn=_default_sigint)
        try:
            reached = _wait_for(named, proc, 30)
            if reached:
                proc.send_signal(signal.SIGINT)
            _, err = proc.communicate(timeout=60)
        finally:
            if proc.poll() is None:
                proc.kill()
                proc.wait()
        if reached and proc.returncode != 0:
            interrupted += 1
            # the documented ^C exit (README, "Exit codes"): 1, "Aborted!", no traceback
            assert proc.returncode == 1, err
            assert err.rstrip().endswith(b"Aborted!"), err
            assert b"Traceback" not in err
        else:  # the batch ended before the signal reached it: it must have done it all
            assert proc.returncode == 0, err
        names = sorted(os.listdir(out))
        assert [n for n in names if not n.startswith("p")] == [], (moment, names)
        if reached:
            assert len(names) >= (moment if moment else 0)
        for name in names:
            variant = int(name[1:5]) % VARIANTS
            assert (out / name).read_bytes() == expected[variant], (moment, name)
        assert list(scratch.iterdir()) == []
    # the signal landed mid-batch in most runs (a loaded machine may end a batch first)
    assert interrupted >= len(moments) // 2
    assert time.monotonic() - started < 60


def _parts(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.endswith(".part"))


def test_sigterm_where_a_command_writes_files_is_an_exit_that_removes_its_temporary_file(
        tmp_path):
    """formats.files.exit_on_termination: SIGTERM's default action runs no exit function, so
    a temporary file made before it stayed; as an exit with 128 + 15 the core's sweep runs."""
    script = (
        "import os, signal\n"
        "from formats.files import PendingFile, exit_on_termination\n"
        "exit_on_termination()\n"
        f"p = PendingFile({str(tmp_path)!r}, 'out.nc')\n"
        "p.write(b'G0 X1\\n')\n"
        "os.kill(os.getpid(), signal.SIGTERM)\n"
        "print('not reached')\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, timeout=60,
                          env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert done.returncode == 128 + signal.SIGTERM
    assert b"not reached" not in done.stdout
    assert list(tmp_path.iterdir()) == []
    # a handler the caller set is kept
    script = ("import signal\n"
              "signal.signal(signal.SIGTERM, signal.SIG_IGN)\n"
              "from formats.files import exit_on_termination\n"
              "exit_on_termination()\n"
              "print(signal.getsignal(signal.SIGTERM) is signal.SIG_IGN)\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, timeout=60,
                          env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert done.stdout.strip() == b"True"


@pytest.mark.skipif(not Path(_exe()).exists(), reason="needs the tapegate command")
def test_sigterm_mid_one_file_conversion_leaves_no_temporary_file(tmp_path):
    """Review 42, finding 4: a CI job's timeout on a large one-file `convert -o` left a
    hidden `.out.nc.XXXXXXXX.part` of tens of MB in the output folder."""
    source = tmp_path / "big.nc"
    source.write_text(_program(0, 1_200_000))
    out = tmp_path / "out"
    out.mkdir()
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    proc = subprocess.Popen([_exe(), "convert", str(source), "-o", str(out / "out.nc"), *ARGS],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
    try:
        if not _wait_for(lambda: _parts(out), proc, 60):
            pytest.skip("the conversion ended before its temporary file was seen")
        proc.send_signal(signal.SIGTERM)
        proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    if proc.returncode == 0:
        pytest.skip("the conversion ended before the signal")
    assert proc.returncode in (128 + signal.SIGTERM, -signal.SIGTERM)
    assert proc.returncode == 128 + signal.SIGTERM, "ended by the signal's default action"
    assert _parts(out) == []
    assert list(out.iterdir()) == []


@pytest.mark.skipif(not Path(_exe()).exists(), reason="needs the tapegate command")
@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_a_conversion_to_stdout_stopped_leaves_no_temporary_folder(tmp_path, signum):
    """Review 44, finding 4: `convert -o -` writes the program into a temporary folder, then
    copies it to stdout; stopped while stdout is written (a reader that does not read: a
    pager, a DNC pipe), the folder and the whole converted program were left in $TMPDIR."""
    source = tmp_path / "big.nc"
    source.write_text(_program(0, 300_000))
    temp = tmp_path / "temp"
    temp.mkdir()
    env = {**os.environ, "PYTHONPATH": str(ROOT), "TMPDIR": str(temp)}
    # stdout a pipe nobody reads: the copy blocks once the pipe is full
    proc = subprocess.Popen([_exe(), "convert", str(source), "-o", "-", *ARGS],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=env,
                            preexec_fn=_default_sigint)
    try:
        def copying() -> bool:
            return any((d / "out.nc").exists() for d in temp.iterdir())

        if not _wait_for(copying, proc, 60):
            pytest.skip("the conversion ended before its temporary file was seen")
        # (the pipe's 64 kB fill before the copy waits; the file is then whole)
        proc.send_signal(signum)
        proc.wait(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
        assert proc.stdout is not None
        proc.stdout.close()
    assert proc.returncode in (1, 128 + signal.SIGTERM), proc.returncode
    assert list(temp.iterdir()) == []
