"""Shared fixtures. The real-program corpus lives beside the project (never copied into it)."""

from __future__ import annotations

import os
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from hypothesis import HealthCheck, settings

# Hypothesis's own clocks are timed assertions (an example's 200 ms deadline; the health check
# that fails a test whose examples take long to generate): under load they fail a test whose
# behaviour is right (test_classification.py's 3,000 strings failed "too_slow" beside the
# suite). Speed is measured by benchmarks; a hang is caught by the test's timeout.
settings.register_profile("suite", deadline=None,
                          suppress_health_check=[HealthCheck.too_slow])
settings.load_profile("suite")

_RS274_HOME: list[str] = []


def rs274_env() -> dict[str, str]:
    """The environment to run LinuxCNC's rs274 in: rs274 maps its tool table to
    ``$HOME/.tool.mmap`` (created and truncated at start), so two runs at once with one HOME
    share it (a tool "not found", a bus error, a message missing). One HOME of its own per test
    process: the runs of one suite follow each other, and two suites at once do not meet."""
    if not _RS274_HOME:
        import tempfile

        _RS274_HOME.append(tempfile.mkdtemp(prefix="tapegate-rs274-home-"))
    return {**os.environ, "HOME": _RS274_HOME[0]}

# The serial tests run the emulated control as a thread beside the sender (or the gateway's port
# threads): a control that has read the byte filling its buffer must send its DC3 at once, as a
# UART interrupt would, not after another thread's 5 ms time slice. The gateway itself sets the
# same interval (dnc.gateway.Gateway.start).
sys.setswitchinterval(0.0005)

# A test's timeout guards against a hang, never its speed (speed is measured by benchmarks). A
# test whose work takes many seconds has a timeout proportional to that work: the CPU seconds it
# takes alone, times the most wall time a CPU second was seen to take in a suite on a loaded
# 2-core machine (19 s, with three busy loops beside it on a machine already at load 20),
# with room over it.
WALL_PER_CPU_SECOND = 30


def timeout_for_work(cpu_seconds: float) -> pytest.MarkDecorator:
    """The timeout of a test that takes ``cpu_seconds`` of CPU alone (at least the suite's
    default of 60 s)."""
    return pytest.mark.timeout(max(60, round(cpu_seconds * WALL_PER_CPU_SECOND)))



@pytest.fixture(autouse=True, scope="session")
def profile_cache_of_the_session(tmp_path_factory: pytest.TempPathFactory) -> Iterator[None]:
    """The built-in profiles' parsed TOML (formats.profile_cache) kept in a folder of the test
    session, not the user's cache: the tests and the commands they start share it."""
    before = os.environ.get("TAPEGATE_CACHE_DIR")
    os.environ["TAPEGATE_CACHE_DIR"] = str(tmp_path_factory.mktemp("profile-cache"))
    yield
    if before is None:
        del os.environ["TAPEGATE_CACHE_DIR"]
    else:
        os.environ["TAPEGATE_CACHE_DIR"] = before


CORPUS = Path(__file__).resolve().parents[2] / "shared" / "corpus"


def corpus_files() -> list[Path]:
    if not CORPUS.is_dir():
        return []
    return sorted(p for p in CORPUS.iterdir() if p.is_file() and p.name != "SOURCES.md")


needs_corpus = pytest.mark.skipif(not corpus_files(), reason="shared/corpus is not present")

# A user's ISO 6983-1 mill whose characters add `#[]*` to iso-mill's (the built-in one reads
# none of them): the rules between families that read `#` parameters and `[ ]` expressions,
# with an ISO 6983-1 target, are reached only through such a profile.
ISO_MACROS = "iso-mill-macros"


def profile(name: str):  # type: ignore[no-untyped-def]
    """A built-in profile by name, or :data:`ISO_MACROS`."""
    from formats.profile import builtin_text, load_profile, profile_from_text

    if name != ISO_MACROS:
        return load_profile(name)
    text = builtin_text("iso-mill").replace(
        'name = "iso-mill"', f'name = "{ISO_MACROS}"\nextra_characters = "#[]*"', 1)
    return profile_from_text(text, ISO_MACROS)


@pytest.fixture
def cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A profile cache folder of the test's own (not made yet), as TAPEGATE_CACHE_DIR."""
    folder = tmp_path / "cache" / "tapegate"
    monkeypatch.setenv("TAPEGATE_CACHE_DIR", str(folder))
    return folder


@pytest.fixture
def sample_program() -> str:
    from importlib import resources

    return (resources.files("tapegate") / "examples" / "bracket.nc").read_text("ascii")


def rs274_output(tmp_path: Path, text: str, flags: tuple[str, ...] = ()) -> str:
    """What LinuxCNC's ``rs274 -g`` prints for ``text`` (the independent oracle), stdout then
    stderr; ``flags`` before ``-g`` (``-b``: the block delete switch on). The test is skipped
    where rs274 is not installed."""
    import shutil
    import subprocess

    if shutil.which("rs274") is None:
        pytest.skip("LinuxCNC's rs274 is not installed")
    path = tmp_path / "program.ngc"
    path.write_text(text)
    # (rs274 keeps its tool table in $HOME/.tool.mmap: a HOME of its own, so that two runs at
    # once do not share it)
    run = subprocess.run(["rs274", *flags, "-g", str(path)], capture_output=True, text=True,
                         timeout=30, input="", env={**os.environ, "HOME": str(tmp_path)})
    return run.stdout + run.stderr


@pytest.fixture(autouse=True)
def no_stop_left_by_a_test() -> Iterator[None]:
    """A stop (^C, SIGTERM, SIGHUP) a test raised in this process, or a handler of one a
    command it ran installed, is not the next test's: the
    command's entry point forgets the stops noted before at each start
    (formats.stops.note_interrupts), but a test that calls a command's click function directly
    does not pass through it, and its first wait (formats.stops.heed_stops) exited with 128 +
    the signal a test before had sent (test_workers' SIGHUP, then a conversion: exit 129)."""
    import signal

    from formats import stops

    # (and the handlers a command installs in the test's process, formats.files'
    # exit_on_termination for SIGTERM and SIGHUP: left, a later test's stray signal raised its
    # exit inside hypothesis's drawing, a failure of another test)
    handlers = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)}
    yield
    stops.TAKEN.clear()
    for s, handler in handlers.items():
        if signal.getsignal(s) is not handler and handler is not None:
            signal.signal(s, handler)
