"""A built-in profile kept for ``tapegate check`` as the check needs it (formats.profile_cache's
``compiled-*`` entries, :class:`formats.profile_cache.Compiled`): its machine spec and its
dialect's flags, read back without the profile's modules; keyed by the profile file's bytes and
by the code; a stale, damaged, cut-short or foreign entry ignored; a check's output the same
with the entry as without the cache."""

from __future__ import annotations

import marshal
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from formats import profile_cache
from formats.machine import keep_compiled, machine_spec
from formats.profile import builtin_names, load_profile

ROOT = Path(__file__).resolve().parent.parent


def entries(folder: Path) -> list[Path]:
    return sorted(folder.glob(f"compiled-*{profile_cache.SUFFIX}")) if folder.exists() else []


def kept(name: str) -> profile_cache.Compiled | None:
    """The entry of ``name`` written from its loaded profile, then read back."""
    keep_compiled(name, load_profile(name))
    return load(name)


def load(name: str) -> profile_cache.Compiled | None:
    return profile_cache.load_compiled(name, lambda: load_profile(name))


def unframed(path: Path) -> bytes:
    """The marshalled entry inside the frame of the file ``path``."""
    blob = profile_cache._unframe(path.read_bytes())
    assert blob is not None
    return bytes(blob)


def write_framed(path: Path, blob: bytes) -> None:
    """``blob`` written as an entry file, in a frame that agrees with it."""
    path.write_bytes(profile_cache._frame(blob))


@pytest.mark.parametrize("name", builtin_names())
def test_an_entry_reads_back_the_profiles_flags_and_spec(cache, name):
    profile = load_profile(name)
    found = kept(name)
    if name in ("fanuc-lathe-b", "fanuc-lathe-c"):  # written on a base: no entry
        assert found is None and entries(cache) == []
        return
    assert found is not None and len(entries(cache)) == 1
    built, flags = found.compiled()
    assert flags == profile.dialect.flags
    assert found._spec == machine_spec(profile)
    assert found.compiled()[0] is built  # one machine, built once
    # anything else is the profile's own, loaded when asked
    assert found.name == profile.name and found.dialect == profile.dialect
    assert found.full() is found.full()


def test_no_entry_for_what_is_no_built_in_profiles_name(cache, tmp_path):
    assert kept("haas-mill") is not None
    for name in ("", "neutral", ".hidden", "../formats/profiles/haas-mill",
                 "profiles/haas-mill", "no-such-profile", "haas\0mill"):
        assert load(name) is None
    mine = tmp_path / "mine.toml"
    mine.write_text('name = "mine"\n')
    keep_compiled(str(mine), load_profile(str(mine)))
    assert [p.name for p in entries(cache)] == [entries(cache)[0].name]  # haas-mill's only


def test_no_entry_with_the_cache_off(monkeypatch):
    monkeypatch.setenv("TAPEGATE_CACHE_DIR", "")
    keep_compiled("haas-mill", load_profile("haas-mill"))
    assert load("haas-mill") is None


def test_the_checksum_tells_any_one_byte_changed():
    blob = marshal.dumps(machine_spec(load_profile("haas-mill")))
    first = profile_cache._checksum(blob)
    for at in range(0, len(blob), 7):
        for bit in (0x01, 0x80):
            changed = blob[:at] + bytes([blob[at] ^ bit]) + blob[at + 1:]
            assert profile_cache._checksum(changed) != first


def test_another_text_of_the_profile_is_not_read_back(cache, tmp_path, monkeypatch):
    folder = tmp_path / "profiles"
    folder.mkdir()
    text = (Path(profile_cache._BUILTIN) / "haas-mill.toml").read_bytes()
    (folder / "haas-mill.toml").write_bytes(text)
    monkeypatch.setattr(profile_cache, "_BUILTIN", str(folder))
    assert kept("haas-mill") is not None
    (folder / "haas-mill.toml").write_bytes(text + b"\n# edited\n")
    assert load("haas-mill") is None
    # the entry of the first text under the second's name: its text is compared whole
    old, = entries(cache)
    found = profile_cache._compiled_path("haas-mill")
    assert found is not None
    Path(found[0]).write_bytes(old.read_bytes())
    assert load("haas-mill") is None


def test_an_entry_of_other_code_or_another_name_is_ignored(cache, monkeypatch):
    assert kept("haas-mill") is not None
    code = profile_cache._module_files()
    assert code is not None and len(code) == len(profile_cache._SPEC_MODULES)
    assert all(os.path.exists(path) for path, _, _ in code)
    changed = ((code[0][0], code[0][1] + 1, code[0][2]), *code[1:])
    monkeypatch.setattr(profile_cache, "_module_files", lambda: changed)
    assert load("haas-mill") is None
    monkeypatch.undo()
    monkeypatch.setenv("TAPEGATE_CACHE_DIR", str(cache))
    assert load("haas-mill") is not None
    # fanuc-mill's entry under haas-mill's name: the name kept in it is compared
    entry, = entries(cache)
    fields = list(marshal.loads(unframed(entry)))
    fields[2] = "fanuc-mill"
    write_framed(entry, marshal.dumps(tuple(fields)))
    assert load("haas-mill") is None


@pytest.mark.parametrize("damage", ["byte", "short", "empty", "foreign"])
def test_a_damaged_entry_is_ignored_and_written_again(cache, damage):
    assert kept("haas-mill") is not None
    entry, = entries(cache)
    data = entry.read_bytes()
    if damage == "byte":  # a byte of the spec's blob changed: its checksum differs
        data = data[:-10] + bytes([data[-10] ^ 0x20]) + data[-9:]
    elif damage == "short":
        data = data[: len(data) // 2]
    elif damage == "empty":
        data = b""
    else:
        data = profile_cache._frame(marshal.dumps(("tapegate-compiled-profile", 0)))
    entry.write_bytes(data)
    assert load("haas-mill") is None
    assert kept("haas-mill") is not None  # written again


# A program whose last line has no LF (the core leaves it to Python, with the full dialect),
# one with a finding, and one in another family's words
PROGRAMS = {
    "a.nc": "%\nO1000\nG21 G90 G17\nG0 X10. Y10.\nG1 Z-1. F100.\nG2 X20. Y10. R5.\nM30\n%\n",
    "b.nc": "%\nO1001\nG20 G90\nG0 X1. Y1.\nG1 X2. F10.\nM30\n%",
    "c.nc": "%\nO1002\nG21 G90\nG0 X1. Y1. G0 G1\nT1 M6\nS1000 M3\nG1 X5. F50.\nM30\n%\n",
}


def _check(folder: Path, cache_dir: str, *args: str,
           timeout: float = 120) -> tuple[int, str, str]:
    env = {**os.environ, "PYTHONPATH": str(ROOT), "TAPEGATE_CACHE_DIR": cache_dir}
    done = subprocess.run([sys.executable, "-P", "-m", "tapegate", "check", str(folder),
                           *args], env=env, capture_output=True, text=True, timeout=timeout)
    return done.returncode, done.stdout, done.stderr


@pytest.mark.parametrize("args", [
    ("--format", "json", "-j", "2"), ("--format", "json", "-j", "1"),
    ("--format", "text", "-j", "2"), ("--format", "jsonl", "-j", "2"),
    ("--format", "json", "--stats", "-j", "2"), ("--format", "text", "--stats", "-j", "2"),
    ("--format", "text", "--all", "-j", "1"),
])
@pytest.mark.parametrize("profile", ["haas-mill", "fanuc-mill"])
def test_a_check_with_the_entry_writes_what_it_writes_without_the_cache(tmp_path, args,
                                                                        profile):
    folder = tmp_path / "programs"
    folder.mkdir()
    for name, text in PROGRAMS.items():
        (folder / name).write_text(text)
    cache_dir = tmp_path / "cache"
    plain = _check(folder, "", "-p", profile, *args)
    first = _check(folder, str(cache_dir), "-p", profile, *args)  # writes the entry
    assert len(list(cache_dir.glob(f"compiled-*{profile_cache.SUFFIX}"))) == 1
    second = _check(folder, str(cache_dir), "-p", profile, *args)  # reads it back
    assert plain[1] and plain == first == second


def test_units_and_sarif_load_the_profile(tmp_path):
    """--units and SARIF take more of the profile than the entry holds: no entry used or
    written, the same output."""
    folder = tmp_path / "programs"
    folder.mkdir()
    for name, text in PROGRAMS.items():
        (folder / name).write_text(text)
    cache_dir = tmp_path / "cache"
    for args in (("--units", "inch", "--format", "json"), ("--format", "sarif")):
        plain = _check(folder, "", "-p", "haas-mill", *args)
        cached = _check(folder, str(cache_dir), "-p", "haas-mill", *args)
        assert plain[1] and plain == cached
    assert list(cache_dir.glob(f"compiled-*{profile_cache.SUFFIX}")) == []


def _system_error_bytes() -> bytes:
    """Bytes marshal.loads raises SystemError on (a code object without its reference flag),
    as one damaged byte of an entry made it raise (review 62c F2)."""
    code = marshal.dumps(compile("1", "p", "eval"))
    bad = bytes([code[0] ^ 0x80]) + code[1:]
    try:
        marshal.loads(bad)
    except SystemError:
        return bad
    except Exception:
        pass
    pytest.skip("this Python's marshal raises no SystemError on these bytes")


def _an_entry(cache: Path, kind: str) -> tuple[Path, Callable[[], Any], Callable[[], None]]:
    """haas-mill's entry of ``kind`` (``compiled``, ``table``, ``spec``) written: its path,
    what reading it back gives (None: no entry), and what writes it again (as a run does on
    finding none)."""
    name = "haas-mill"
    profile = load_profile(name)
    text = (Path(profile_cache._BUILTIN) / f"{name}.toml").read_text()
    if kind == "compiled":
        assert kept(name) is not None
        path, = entries(cache)
        return (path, lambda: (lambda c: c and (c._flags, c._spec))(load(name)),
                lambda: keep_compiled(name, load_profile(name)))
    if kind == "table":
        table = profile_cache.load(name, text)
        assert table is not None
        return (Path(profile_cache._path(name, text) or ""),
                lambda: profile_cache.load(name, text),
                lambda: profile_cache.store(name, text, table))
    key = profile.__dict__["_spec_key"]
    profile_cache.store_spec(key, machine_spec(profile))
    return (Path(profile_cache._spec_path(key) or ""), lambda: profile_cache.load_spec(key),
            lambda: profile_cache.store_spec(key, machine_spec(profile)))


@pytest.mark.parametrize("where", ["file", "blob"])
@pytest.mark.parametrize("kind", ["compiled", "table", "spec"])
def test_an_entry_marshal_raises_any_error_on_is_ignored_and_written_again(cache, kind, where):
    """A cache never decides a run: any exception of reading an entry back (here SystemError)
    is an entry not there, in load_compiled, load and load_spec alike, and it is written
    again."""
    bad = _system_error_bytes()
    path, value, again = _an_entry(cache, kind)
    before = value()
    assert before
    good = unframed(path)
    if where == "file":  # the whole entry, its frame made to agree
        write_framed(path, bad)
    elif kind == "compiled":  # the spec, the frame made to agree
        fields = list(marshal.loads(good))
        head = marshal.dumps(tuple(fields[:5]))  # a small tuple: its type, its count 5
        assert head[0] & 0x7F == ord(")") and head[1] == 5
        write_framed(path, head[:1] + bytes([6]) + head[2:] + bad)
    else:  # the inner blob, with its CRC-32 and the frame made to agree
        import zlib

        fields = list(marshal.loads(good))
        fields[-2], fields[-1] = zlib.crc32(bad), bad
        write_framed(path, marshal.dumps(tuple(fields)))
    assert value() is None
    again()  # (what a run does on finding none)
    assert value() == before  # written again



def test_no_one_byte_change_of_an_entry_is_trusted(cache):
    """Every byte the entry is trusted for -- the dialect's flags as much as the spec -- is
    under its frame's checksum (review 62c F1: a flag flipped from True to False was read
    back, wrong findings on every run): one byte changed anywhere in the file is no entry,
    never an error."""
    name = "haas-mill"
    assert kept(name) is not None
    entry, = entries(cache)
    good = entry.read_bytes()
    trusted = []
    # (each byte of the head, the key, the code and the text; every 61st after it: the
    # checksum's own test tells each byte of a spec)
    for at in [*range(min(len(good), 2000)), *range(2000, len(good), 61)]:
        for bit in (0x01, ord("T") ^ ord("F")):
            entry.write_bytes(good[:at] + bytes([good[at] ^ bit]) + good[at + 1:])
            if load(name) is not None:
                trusted.append((at, bit))
    assert trusted == []
    entry.write_bytes(good)
    assert load(name) is not None


class _Marshal:
    """profile_cache's marshal, its loads counted."""

    def __init__(self) -> None:
        self.loads_called = 0

    def loads(self, data):
        self.loads_called += 1
        return marshal.loads(data)

    dumps = staticmethod(marshal.dumps)


@pytest.mark.parametrize("where", ["checksum", "length", "type", "count", "payload", "last",
                                   "cut", "longer"])
@pytest.mark.parametrize("kind", ["compiled", "table", "spec"])
def test_a_damaged_frame_is_no_entry_before_marshal_reads_it(cache, monkeypatch, kind, where):
    """The frame's length and checksum are checked before marshal reads a byte: a damaged
    outer type byte (the tuple's ``)`` made ``(``, whose 4-byte count marshal took for up to
    2**31 items: 10-42 s of allocation before it failed) or any other byte is no entry at
    once, for each kind of entry, and it is written again."""
    path, value, again = _an_entry(cache, kind)
    before = value()
    assert before
    good = path.read_bytes()
    assert good[8] & 0x7F == ord(")")  # the entry: a small tuple, its count next
    at = {"checksum": 1, "length": 5, "type": 8, "count": 9, "payload": len(good) // 2,
          "last": len(good) - 1}.get(where)
    if at is not None:
        flip = 0x01 if where != "length" else 0x40
        bad = good[:at] + bytes([good[at] ^ flip]) + good[at + 1:]
    else:
        bad = good[:-1] if where == "cut" else good + b"\0"
    if where == "type":  # ')' -> '(': a tuple whose count is 4 bytes
        assert bad[8] & 0x7F == ord("(")
    path.write_bytes(bad)
    spy = _Marshal()
    monkeypatch.setattr(profile_cache, "marshal", spy)
    assert value() is None
    assert spy.loads_called == 0  # dropped before marshal read anything
    monkeypatch.setattr(profile_cache, "marshal", marshal)
    again()  # (what a run does on finding none)
    assert path.read_bytes() != bad and value() == before  # written again


@pytest.mark.parametrize("kind", ["fifo", "folder", "link"])
def test_no_regular_file_at_an_entrys_path_is_no_entry_and_left_there(cache, tmp_path, kind):
    """A FIFO (or a folder) where the entry should be: the check does not wait on it (opened
    without blocking, fstat'd before it is read), reads it as no entry, and leaves it in place
    rather than replacing it; the command's output is what it is without the cache."""
    folder = tmp_path / "programs"
    folder.mkdir()
    for name, text in PROGRAMS.items():
        (folder / name).write_text(text)
    cache.mkdir(parents=True)
    found = profile_cache._compiled_path("haas-mill")
    assert found is not None
    path = Path(found[0])
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "folder":
        path.mkdir()
    else:  # a link to a FIFO: not followed
        os.mkfifo(tmp_path / "fifo")
        path.symlink_to(tmp_path / "fifo")
    assert load("haas-mill") is None  # (in process: no wait either)
    keep_compiled("haas-mill", load_profile("haas-mill"))
    args = ("-p", "haas-mill", "--format", "json")
    plain = _check(folder, "", *args)
    for _ in range(2):  # (the second run would read an entry written by the first)
        # (the old tree waited in open() for ever: TimeoutExpired)
        assert _check(folder, str(cache), *args, timeout=60) == plain
    assert {"fifo": path.is_fifo, "folder": path.is_dir, "link": path.is_symlink}[kind]()
    assert sorted(p.name for p in cache.iterdir() if p.name.startswith("compiled-")) == [
        path.name]  # nothing written beside it either


def test_framed_entries_are_named_apart_from_the_entries_before_the_frame(cache):
    """A tapegate before the frame reads ``compiled-NAME.marshal``, ``profile-NAME-CRC.marshal``
    and ``machine-CRC.marshal`` whole with marshal, which takes a frame's first bytes (its
    checksum's) for a type and a count: one in about a hundred made it allocate GBs for seconds
    (review 63 of io63, F1). Framed entries have other names: an older entry in the same folder
    is neither read nor written, and each kind written here ends in the framed suffix."""
    name = "haas-mill"
    old = cache / f"compiled-{name}.marshal"
    cache.mkdir(parents=True)
    old_bytes = marshal.dumps(("tapegate-compiled-profile", 2, "an older tapegate's entry"))
    old.write_bytes(old_bytes)
    for kind in ("compiled", "table", "spec"):
        path, value, _ = _an_entry(cache, kind)
        assert path.name.endswith(profile_cache.SUFFIX) and value()
    assert old.read_bytes() == old_bytes
    written = sorted(p.name for p in cache.iterdir())
    assert len(written) == 4 and all(n.endswith(profile_cache.SUFFIX) for n in written
                                      if n != old.name), written
