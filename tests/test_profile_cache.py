"""The built-in profiles' parsed TOML kept between runs (formats.profile_cache), and what a
one-file check imports."""

import datetime
import json
import marshal
import os
import subprocess
import sys
import tomllib
import zlib
from pathlib import Path

import pytest

from formats import profile as profile_module
from formats import profile_cache
from formats.errors import ProfileError
from formats.profile import builtin_text, load_profile, neutral, profile_from_text

ROOT = Path(__file__).resolve().parents[1]


def uncached(name: str):
    return profile_from_text(builtin_text(name), source="built-in", default_name=name)


def entry_path(name: str) -> Path:
    path = profile_cache._path(name, builtin_text(name))
    assert path is not None
    return Path(path)


def no_toml(monkeypatch):
    def refuse(*args, **kwargs):
        raise AssertionError("tomllib.loads called: the cache was not used")

    monkeypatch.setattr(tomllib, "loads", refuse)


def test_a_builtin_profile_is_parsed_once_then_read_from_the_cache(cache, monkeypatch):
    first = load_profile("fanuc-mill")
    assert first == uncached("fanuc-mill")
    files = sorted(p.name for p in cache.iterdir())
    assert len(files) == 1 and files[0].startswith("profile-fanuc-mill-")
    assert files[0].endswith(".marshal")
    no_toml(monkeypatch)
    again = load_profile("fanuc-mill")
    assert again == first and again is not first
    assert sorted(p.name for p in cache.iterdir()) == files  # nothing written again


def test_every_builtin_profile_reads_back_equal_from_the_cache(cache, monkeypatch):
    names = profile_module.builtin_names()
    made = {name: (load_profile(name), uncached(name)) for name in names}
    no_toml(monkeypatch)
    for name in names:
        assert load_profile(name) == made[name][0] == made[name][1], name


def test_a_changed_profile_text_is_parsed_again_never_taken_from_the_stale_entry(
        cache, monkeypatch):
    load_profile("fanuc-mill")
    stale = entry_path("fanuc-mill")
    text = builtin_text("fanuc-mill").replace('description = "', 'description = "changed: ', 1)
    assert text != builtin_text("fanuc-mill")
    monkeypatch.setattr(profile_module, "builtin_text", lambda name: text)
    changed = load_profile("fanuc-mill")
    assert changed.description.startswith("changed: ")
    assert stale.exists() and len(list(cache.iterdir())) == 2  # another CRC, another file


def entry(text: str, data: dict) -> bytes:
    """An entry as formats.profile_cache writes it: the key, the text, the CRC-32 of the
    marshalled table, the table."""
    table = marshal.dumps(data)
    return profile_cache._frame(marshal.dumps((profile_cache.KEY, text, zlib.crc32(table),
                                               table)))


def read_entry(path: Path) -> object:
    """What the entry file ``path`` holds, read inside its frame."""
    blob = profile_cache._unframe(path.read_bytes())
    assert blob is not None
    return marshal.loads(blob)


def test_a_profile_files_parsed_toml_is_kept_by_its_text(cache, monkeypatch, tmp_path):
    """A user's profile file (``--to machine.toml``) is parsed once, then read from the cache
    (no tomllib: with typing, string and datetime, 40M instructions of a conversion's start-up);
    the entry is the text's, whatever file holds it, and a changed file is parsed again."""
    text = ('name = "implicit-inch"\n'
            'detailed = "%:/ N07 G02 X+044 Y+044 Z+044 I+044 J+044 F042 S05 T02 M02*"\n'
            'units_codes = "G20/G21"\nunits = "inch"\n')
    first_file = tmp_path / "machine.toml"
    first_file.write_text(text)
    first = load_profile(str(first_file))
    assert first == profile_from_text(text, source=str(first_file), default_name="machine")
    files = sorted(p.name for p in cache.iterdir())
    assert len(files) == 1 and files[0].startswith(f"profile-{profile_module.FILE_CACHE_NAME}-")
    other_file = tmp_path / "other" / "copy.toml"  # the same text in another file
    other_file.parent.mkdir()
    other_file.write_text(text)
    with monkeypatch.context() as refused:
        no_toml(refused)
        again = load_profile(str(first_file))
        copy = load_profile(str(other_file))
    assert again == first and again is not first
    assert copy == profile_from_text(text, source=str(other_file), default_name="copy")
    assert sorted(p.name for p in cache.iterdir()) == files  # nothing written again
    first_file.write_text(text.replace("F042", "F052"))
    changed = load_profile(str(first_file))  # parsed again: a new entry beside the old
    assert changed != first and len(list(cache.iterdir())) == 2
    first_file.write_text("name = [")
    with pytest.raises(ProfileError, match="not valid TOML") as bad:  # (and nothing kept)
        load_profile(str(first_file))
    assert bad.value.file == str(first_file) and len(list(cache.iterdir())) == 2


def test_an_entry_holding_another_text_under_the_same_name_is_not_used(cache):
    """The CRC names the file; the text inside decides: a collision is a miss."""
    path = entry_path("fanuc-mill")
    path.parent.mkdir(parents=True)
    other = uncached("iso-mill")
    path.write_bytes(entry("name = \"iso-mill\"\n", tomllib.loads(builtin_text("iso-mill"))))
    profile = load_profile("fanuc-mill")
    assert profile.name == "fanuc-mill" and profile != other
    assert read_entry(path)[1] == builtin_text("fanuc-mill")  # written again


@pytest.mark.parametrize("content", [
    b"", b"not marshal at all", None, profile_cache._frame(marshal.dumps(["a", "list"])),
    profile_cache._frame(marshal.dumps((("tapegate-profile-toml", 0, (3, 0), 0), "x", {}))),
    marshal.dumps((profile_cache.KEY, "x", 0, b"")),
], ids=["empty", "garbage", "cut-short", "not-an-entry", "another-format", "not-framed"])
def test_a_corrupt_entry_is_ignored_and_written_again(cache, content):
    good = entry(builtin_text("fanuc-mill"), tomllib.loads(builtin_text("fanuc-mill")))
    path = entry_path("fanuc-mill")
    path.parent.mkdir(parents=True)
    path.write_bytes(good[:len(good) // 2] if content is None else content)
    assert load_profile("fanuc-mill") == uncached("fanuc-mill")
    assert path.read_bytes() == good


def test_a_damaged_byte_of_the_kept_table_is_found_and_the_entry_written_again(cache):
    """The CRC-32 kept with the table finds a byte changed on disk (here a format X+053 made
    X+033, which would refuse X1234.5): the profile is parsed again and the entry rewritten."""
    load_profile("fanuc-mill")
    path = entry_path("fanuc-mill")
    blob = path.read_bytes()
    at = blob.rindex(b"X+053")
    path.write_bytes(blob[:at] + b"X+033" + blob[at + 5:])
    assert load_profile("fanuc-mill") == uncached("fanuc-mill")
    assert path.read_bytes() == blob  # written again


def test_a_folder_that_cannot_be_made_is_no_error(tmp_path, monkeypatch):
    blocker = tmp_path / "a-file"
    blocker.write_text("in the way")
    monkeypatch.setenv("TAPEGATE_CACHE_DIR", str(blocker / "tapegate"))
    assert load_profile("haas-mill") == uncached("haas-mill")
    assert blocker.read_text() == "in the way"


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into a read-only folder all the same")
def test_a_read_only_folder_is_no_error(cache):
    cache.mkdir(parents=True)
    cache.chmod(0o555)
    try:
        assert load_profile("haas-mill") == uncached("haas-mill")
        assert list(cache.iterdir()) == []
    finally:
        cache.chmod(0o755)


def test_a_failed_write_leaves_no_temporary_file(cache, monkeypatch):
    def refuse(src, dst):
        raise PermissionError(13, "Permission denied", dst)

    monkeypatch.setattr(os, "replace", refuse)
    assert load_profile("haas-mill") == uncached("haas-mill")
    assert list(cache.iterdir()) == []


def test_the_cache_is_off_with_an_empty_folder_name(tmp_path, monkeypatch):
    monkeypatch.setenv("TAPEGATE_CACHE_DIR", "")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert profile_cache.directory() is None
    assert load_profile("haas-mill") == uncached("haas-mill")
    assert list(tmp_path.iterdir()) == []


def test_the_folder_is_the_xdg_cache_or_the_home_cache(tmp_path, monkeypatch):
    monkeypatch.delenv("TAPEGATE_CACHE_DIR", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    assert profile_cache.directory() == str(tmp_path / "xdg" / "tapegate")
    monkeypatch.delenv("XDG_CACHE_HOME")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert profile_cache.directory() == str(tmp_path / "home" / ".cache" / "tapegate")


def test_no_home_folder_is_no_cache_not_a_folder_named_tilde(tmp_path, monkeypatch):
    monkeypatch.delenv("TAPEGATE_CACHE_DIR", raising=False)
    monkeypatch.delenv("XDG_CACHE_HOME", raising=False)
    monkeypatch.delenv("HOME", raising=False)
    monkeypatch.setattr(os.path, "expanduser", lambda path: path)  # no password entry either
    monkeypatch.chdir(tmp_path)
    assert profile_cache.directory() is None
    assert load_profile("haas-mill") == uncached("haas-mill")
    assert list(tmp_path.iterdir()) == []


def test_a_value_marshal_cannot_hold_is_not_kept(cache):
    profile_cache.store("x", "when = 1979-05-27\n", {"when": datetime.date(1979, 5, 27)})
    assert not cache.exists() or list(cache.iterdir()) == []


def test_bad_toml_in_a_builtin_text_is_still_a_located_profile_error(cache, monkeypatch):
    from formats.errors import ProfileError

    monkeypatch.setattr(profile_module, "builtin_text", lambda name: "name = \n")
    with pytest.raises(ProfileError) as info:
        load_profile("fanuc-mill")
    assert (info.value.code, info.value.file) == ("profile-toml", "built-in")


def test_the_neutral_profile_is_made_once_when_first_asked_for():
    assert neutral() is neutral() is profile_module.NEUTRAL is load_profile("neutral")
    with pytest.raises(AttributeError, match="NOTHING"):
        profile_module.NOTHING  # noqa: B018


PROBE = """
import atexit, sys
listing = sys.argv[1]
def modules():
    with open(listing, "w") as f:
        f.write("\\n".join(sorted(sys.modules)))
atexit.register(modules)
sys.argv = ["tapegate", "check", sys.argv[2], "-p", "fanuc-mill"]
from tapegate.cli import main
main()
"""


def run_check(tmp_path: Path, cache_dir: str, program: Path) -> tuple[set[str], bytes, bytes]:
    listing = tmp_path / "modules.txt"
    env = {**os.environ, "PYTHONPATH": str(ROOT), "TAPEGATE_CACHE_DIR": cache_dir}
    done = subprocess.run([sys.executable, "-c", PROBE, str(listing), str(program)], env=env,
                          capture_output=True, timeout=60, check=False)
    assert done.returncode == 0, done.stderr
    return set(listing.read_text().split()), done.stdout, done.stderr


def test_a_one_file_check_loads_only_what_it_uses(tmp_path):
    """tapegate check FILE -p PROFILE, the second time with a cache: no TOML parser, no
    pathlib, no JSON (the text report's writer is postproc.report's, which loads json only for
    the other formats), no worker pool, no lark, no DNC layer, no tape reading (a plain text
    file is read by the core); the same output as without the cache."""
    program = tmp_path / "p.nc"
    program.write_text("%\nO1\nN1 G21 G90 G17\nN2 G0 X10. Y5.\nN3 G1 X20. F100\nN4 M30\n%\n")
    cache_dir = str(tmp_path / "cache")
    cold = run_check(tmp_path, cache_dir, program)
    warm = run_check(tmp_path, cache_dir, program)
    off = run_check(tmp_path, "", program)
    assert cold[1:] == warm[1:] == off[1:]
    assert b"1 file checked" in warm[2]
    assert "tomllib" in cold[0] and "tomllib" in off[0]
    unused = {"tomllib", "pathlib", "json", "tapegate.workers", "tapegate.convert_cli",
              "tapegate.diff_cli", "lark", "dnc", "serial", "multiprocessing",
              "formats.convert", "formats.source", "formats.tape"}
    assert warm[0] & unused == set()
    assert {"tapegate.check_cli", "postproc.check", "formats.profile_cache"} <= warm[0]


LAUNCH_PROBE = """
import atexit, sys
listing = sys.argv[1]
def modules():
    with open(listing, "w") as f:
        f.write("\\n".join(sorted(sys.modules)))
atexit.register(modules)
sys.argv = ["tapegate", *sys.argv[2:]]
from tapegate.launch import main
main(prog_name="tapegate")
"""


def test_a_folder_checked_in_threads_imports_no_typing(tmp_path):
    """``tapegate check FOLDER -j 2`` as the console script runs it (without click): the
    threads run, and nothing on the way imports typing (its import, 2.6 ms, was a tenth of the
    start-up no thread shares: annotations only, behind ``TYPE_CHECKING = False``), contextlib
    (the cache's failed write only) or tempfile (the threads' spill files are made without it
    where the system offers O_TMPFILE) or signal (SIGTERM's handler is set by its C part),
    or re (the classification strings and the profile's keys are read by hand), once the
    profile's cache is written."""
    folder = tmp_path / "cam"
    folder.mkdir()
    for n in range(3):
        (folder / f"p{n}.nc").write_text(f"%\nO{n + 1}\nN1 G21 G90 G17\nN2 G0 X1{n}.\nN3 M30\n%\n")
    listing = tmp_path / "modules.txt"
    env = {**os.environ, "PYTHONPATH": str(ROOT), "TAPEGATE_CACHE_DIR": str(tmp_path / "c")}
    for warm in (False, True):  # the cache written (tomllib imports typing), then read
        done = subprocess.run([sys.executable, "-c", LAUNCH_PROBE, str(listing), "check",
                               str(folder), "-p", "fanuc-mill", "--format", "json", "-j", "2"],
                              env=env,
                              capture_output=True, timeout=60, check=False)
        assert done.returncode == 0, done.stderr
        json.loads(done.stdout)  # the report, whole
        loaded = set(listing.read_text().split())
        # the threads ran, as _thread's: threading is not imported (tapegate.workers)
        assert "tapegate.workers" in loaded and "threading" not in loaded
        assert loaded & {"tempfile", "click", "formats.source", "formats.tape"} == set()
        if warm:
            assert loaded & {"typing", "contextlib", "tomllib", "signal", "re"} == set()


def test_a_folder_converted_in_threads_imports_no_typing(tmp_path):
    """``tapegate convert FOLDER --out-dir OUT --to FILE.toml -j 2`` as the console script runs
    it: the threads run, the files are written, and typing is not imported (once the
    profiles' cache is written)."""
    folder = tmp_path / "cam"
    folder.mkdir()
    for n in range(3):
        (folder / f"p{n}.nc").write_text(f"%\nO{n + 1}\nN1 G21 G90\nN2 G0 X1{n}.5\nN3 M30\n%\n")
    listing = tmp_path / "modules.txt"
    env = {**os.environ, "PYTHONPATH": str(ROOT), "TAPEGATE_CACHE_DIR": str(tmp_path / "c")}
    target = tmp_path / "fanuc.toml"  # a profile file, as a shop's own
    target.write_text('base = "fanuc-mill"\nname = "shop-fanuc"\n')
    for _ in range(2):  # the cache written, then read
        done = subprocess.run([sys.executable, "-c", LAUNCH_PROBE, str(listing), "convert",
                               str(folder), "--out-dir", str(tmp_path / "out"), "--force",
                               "--from", "fanuc-mill", "--to", str(target), "--units", "inch",
                               "-j", "2"], env=env, capture_output=True, timeout=60,
                              check=False)
        assert done.returncode == 0, done.stderr
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["p0.nc", "p1.nc", "p2.nc"]
    assert "N2 G0 X0.4134\n" in (tmp_path / "out" / "p0.nc").read_text()  # 10.5 mm in inches
    loaded = set(listing.read_text().split())
    assert "tapegate.workers" in loaded and "formats.convert" in loaded
    # nor dataclasses (with inspect, ast, dis: 41M instructions; the conversion's records are
    # formats.records'), nor glob (for a pattern only), nor, with the profile file's TOML
    # kept, tomllib
    assert loaded & {"typing", "click", "dataclasses", "inspect", "glob", "tomllib"} == set()
