"""The machine: a profile compiled once into the core (formats.machine, core machine.rs)."""

from __future__ import annotations

import pickle
import time

import pytest

from formats.machine import machine, machine_spec
from formats.profile import builtin_names, load_profile


def test_a_profile_is_compiled_once_and_shared() -> None:
    profile = load_profile("fanuc-mill")
    assert machine(profile) is machine(profile)
    assert machine(load_profile("fanuc-mill")) is not machine(profile)  # another profile object


def test_threads_asking_at_once_share_one_machine_built_once(monkeypatch) -> None:
    """-j's threads ask for the machine at their first files at once: one builds it, the
    others wait for it (the interpreter switching threads every 10 us meanwhile)."""
    import sys
    import threading

    import formats.machine as machines

    built: list[int] = []
    real = machines.machine_spec

    def counted(profile):  # type: ignore[no-untyped-def]
        built.append(threading.get_ident())
        return real(profile)

    monkeypatch.setattr(machines, "machine_spec", counted)
    monkeypatch.setenv("TAPEGATE_CACHE_DIR", "")  # each profile's spec made, not read back
    interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-5)
    try:
        for _ in range(5):
            profile = load_profile("haas-mill")  # a new object each time
            got: list[object] = []
            start = threading.Barrier(4, timeout=30)

            def ask(profile=profile, got=got, start=start) -> None:  # type: ignore[no-untyped-def]
                start.wait()
                got.append(machines.machine(profile))

            # daemon threads, joined with one deadline for all: a thread stuck on the machine's
            # lock fails the test and does not keep pytest from exiting
            threads = [threading.Thread(target=ask, daemon=True) for _ in range(4)]
            for thread in threads:
                thread.start()
            deadline = time.monotonic() + 60
            for thread in threads:
                thread.join(timeout=max(0.0, deadline - time.monotonic()))
            stuck = [thread for thread in threads if thread.is_alive()]
            assert not stuck, "a thread never got its machine"
            assert len(got) == 4 and all(m is got[0] for m in got)
    finally:
        sys.setswitchinterval(interval)
    assert len(built) == 5  # once a profile


@pytest.mark.parametrize("name", builtin_names())
def test_every_built_in_profile_compiles(name: str) -> None:
    profile = load_profile(name)
    spec = machine_spec(profile)
    assert spec["family"] == profile.dialect.family
    assert spec["lathe"] == (profile.control_type == "lathe")
    compiled = machine(profile)
    # X is a diameter on a Fanuc, Haas or Okuma lathe: decided by the core, once
    lathe_of_diameters = profile.control_type == "lathe" and profile.dialect.family in (
        "fanuc", "haas", "okuma")
    assert compiled.diameter == lathe_of_diameters
    assert compiled.fanuc_lathe == (profile.control_type == "lathe"
                                    and profile.dialect.family in ("fanuc", "haas"))


def test_a_profile_travels_to_a_worker_without_its_compiled_machine() -> None:
    """A profile pickles (and copies) as its settings: the compiled machine is not pickled (it
    cannot be), and the process that loads the copy compiles its own."""
    profile = load_profile("haas-lathe") if "haas-lathe" in builtin_names() else load_profile(
        "fanuc-lathe")
    compiled = machine(profile)
    copy = pickle.loads(pickle.dumps(profile))
    assert copy == profile
    assert "_machine" not in copy.__dict__
    assert machine(copy).diameter == compiled.diameter
