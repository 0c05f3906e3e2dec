"""The core's machine spec kept between runs (formats.profile_cache's ``machine-*`` entries):
read back the same as made, keyed by the profile's table, source and name and by the code
that made it; a damaged, cut-short, foreign or stale entry ignored and written again."""

from __future__ import annotations

import marshal
import os
from pathlib import Path

import pytest

from formats import machine as machine_module
from formats import profile_cache
from formats.machine import machine, machine_spec
from formats.profile import builtin_names, load_profile, with_start_units


def spec_files(folder: Path) -> list[Path]:
    return sorted(folder.glob(f"machine-*{profile_cache.SUFFIX}")) if folder.exists() else []


def no_spec_made(monkeypatch):
    def refuse(profile):
        raise AssertionError("machine_spec called: the kept spec was not used")

    monkeypatch.setattr(machine_module, "machine_spec", refuse)


@pytest.mark.parametrize("name", builtin_names())
def test_a_kept_spec_reads_back_as_it_was_made(cache, monkeypatch, name):
    made = machine_spec(load_profile(name))
    machine(load_profile(name))  # made and kept
    assert len(spec_files(cache)) == 1
    no_spec_made(monkeypatch)
    kept = machine_module._spec(load_profile(name))
    assert kept == made and repr(kept) == repr(made)
    machine(load_profile(name))  # compiled from the kept spec


def test_each_profile_has_its_own_entry_and_a_file_profile_by_its_table(cache, tmp_path):
    machine(load_profile("fanuc-mill"))
    machine(load_profile("haas-mill"))
    assert len(spec_files(cache)) == 2
    path = tmp_path / "mine.toml"
    path.write_text('base = "fanuc-mill"\nname = "mine"\n[limits]\nfeed_max = 500\n')
    assert machine_module._spec(load_profile(str(path)))["feed_max"] == "500"
    path.write_text('base = "fanuc-mill"\nname = "mine"\n[limits]\nfeed_max = 600\n')
    assert machine_module._spec(load_profile(str(path)))["feed_max"] == "600"  # not the 500's
    assert len(spec_files(cache)) == 4


def test_a_profile_made_from_another_has_no_key_and_no_entry(cache, monkeypatch):
    inch = with_start_units(load_profile("fanuc-mill"), "inch")
    assert "_spec_key" not in inch.__dict__
    assert machine_module._spec(inch)["default_units"] == "inch"
    assert spec_files(cache) == []


def test_the_spec_of_other_code_is_not_used(cache, monkeypatch):
    """A module of the code that made it changed (its size or time, as an update or an edit
    leaves it): the entry is made again and rewritten."""
    machine(load_profile("fanuc-mill"))
    [entry] = spec_files(cache)
    before = entry.read_bytes()
    code = profile_cache._code()
    assert code is not None
    path, size, mtime = code[0]  # type: ignore[misc]
    monkeypatch.setattr(profile_cache, "_code", lambda: ((path, size, mtime + 1), *code[1:]))
    calls = []
    real = machine_module.machine_spec
    monkeypatch.setattr(machine_module, "machine_spec",
                        lambda profile: calls.append(1) or real(profile))
    machine_module._spec(load_profile("fanuc-mill"))
    assert calls == [1] and entry.read_bytes() != before


def test_the_code_names_every_module_by_size_and_time():
    code = profile_cache._code()
    assert code is not None and len(code) == len(profile_cache._SPEC_MODULES)
    for (path, size, mtime), name in zip(code, profile_cache._SPEC_MODULES, strict=True):
        info = os.stat(path)
        assert (size, mtime) == (info.st_size, info.st_mtime_ns)
        assert Path(path).stem.split(".")[0] == name.rsplit(".", 1)[1]


@pytest.mark.parametrize("damage", ["cut", "byte", "garbage", "empty", "other key", "not dict"])
def test_a_damaged_or_foreign_entry_is_ignored_and_written_again(cache, monkeypatch, damage):
    profile = load_profile("haas-mill")
    made = machine_spec(profile)
    machine(profile)
    [entry] = spec_files(cache)
    blob = entry.read_bytes()
    inner = profile_cache._unframe(blob)
    assert inner is not None
    kind, code, key, crc, table = marshal.loads(inner)
    framed = profile_cache._frame
    if damage == "cut":
        entry.write_bytes(blob[: len(blob) // 2])
    elif damage == "byte":  # a byte of the table changed: its CRC tells
        at = len(table) // 2
        bad = table[:at] + bytes([table[at] ^ 0x01]) + table[at + 1:]
        entry.write_bytes(framed(marshal.dumps((kind, code, key, crc, bad))))
    elif damage == "garbage":
        entry.write_bytes(b"\x00not marshal\xff" * 10)
    elif damage == "empty":
        entry.write_bytes(b"")
    elif damage == "other key":  # another profile's spec under this name (a CRC collision)
        other = marshal.dumps({"family": "linuxcnc"})
        import zlib

        entry.write_bytes(framed(marshal.dumps((kind, code, key + b"x", zlib.crc32(other),
                                                  other))))
    else:
        import zlib

        other = marshal.dumps([1, 2])
        entry.write_bytes(framed(marshal.dumps((kind, code, key, zlib.crc32(other), other))))
    again = machine_module._spec(load_profile("haas-mill"))
    assert again == made
    assert entry.read_bytes() == blob  # written again, whole


def test_the_cache_off_keeps_nothing(tmp_path, monkeypatch):
    monkeypatch.setenv("TAPEGATE_CACHE_DIR", "")
    profile = load_profile("fanuc-mill")
    assert "_spec_key" not in profile.__dict__
    machine(profile)
    assert list(tmp_path.iterdir()) == []


def test_a_folder_that_cannot_be_made_is_no_error(tmp_path, monkeypatch):
    blocker = tmp_path / "file"
    blocker.write_text("in the way")
    monkeypatch.setenv("TAPEGATE_CACHE_DIR", str(blocker / "tapegate"))
    profile = load_profile("fanuc-mill")
    assert machine_module._spec(profile) == machine_spec(profile)
    assert machine(profile) is machine(profile)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["file"]


def test_a_pickled_profile_carries_neither_its_machine_nor_its_specs_key(cache):
    import pickle

    profile = load_profile("fanuc-mill")
    machine(profile)
    assert {"_machine", "_spec_key"} <= set(profile.__dict__)
    again = pickle.loads(pickle.dumps(profile))
    assert again == profile and not {"_machine", "_spec_key"} & set(again.__dict__)
    assert machine_module._spec(again) == machine_spec(again)  # made, not read back
