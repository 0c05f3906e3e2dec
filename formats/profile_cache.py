"""The parsed TOML of each built-in profile and of each profile file, kept between runs in the
user's cache folder.

Reading a built-in profile's TOML took about a tenth of a one-file ``tapegate check``: importing
``tomllib`` and parsing the text (33M instructions of 300M; docs/benchmarks.md, "Start-up,
second pass"). A profile file (``--to machine.toml``) paid more: ``tomllib`` imports ``typing``,
``string`` and ``datetime``, 40M instructions of the 225M ``convert DIR -j 2`` ran before its
threads started (docs/benchmarks.md, "a conversion's start-up"). The
parsed table is a pure function of the text, so it is kept on disk with ``marshal`` (built into
Python, nothing to import) and read back next time; a profile file's entry is named ``file``
(``formats.profile.FILE_CACHE_NAME``) and its CRC, whatever file held the text:

- the file is ``$TAPEGATE_CACHE_DIR`` (an empty value: no cache), else
  ``$XDG_CACHE_HOME/tapegate``, else ``~/.cache/tapegate``, then
  ``profile-NAME-CRC.framed.marshal``, CRC the CRC-32 of the profile's text: a changed
  profile file has another name, and an entry is used only when the text it holds is the
  text read now, character for character (a stale or colliding entry is never used);
- every entry file is framed: its length and a checksum of all its bytes (:func:`_frame`),
  checked before ``marshal`` reads any of it, so that a damaged byte anywhere (the outer
  tuple's type or length byte too, which marshal read as a count of up to 2**31 items: 10-42 s
  of allocation before it failed) is no entry at once; a framed entry's name ends in
  :data:`SUFFIX`, apart from the names of the entries before the frame (``.marshal`` alone),
  which an older tapegate sharing the folder reads whole with ``marshal``: it would take a
  frame's first bytes for such a count (review 63 of io63, F1), and the two would rewrite
  each other's entries;
- an entry that cannot be read, is cut short, is not an entry of this format or of this Python,
  or whose frame or parsed table does not match the checksum or CRC-32 kept with it (a damaged
  byte) is ignored, and written again; anything but a regular file at an entry's path (a FIFO,
  a device, a folder) is no entry and is left as it is (opened without blocking: no wait);
- a folder that cannot be created or written (read-only, a file in the way) is no error: the
  profile is parsed as without a cache. The entry is written to a temporary file and renamed,
  so a reader never sees half of one.

The validated profile is not kept: it is made from the table each time. What the core's
machine is compiled from, its spec (:func:`formats.machine.machine_spec`: plain values), is
kept too, as ``machine-CRC.framed.marshal`` (:func:`load_spec`, :func:`store_spec`), keyed by
all that made it: the profile's table after its ``base`` was merged, its source and default
name (the profile's own inputs, :func:`spec_key`), and the code that turned them into the
spec -- the size and modification time of each module the profile and the spec are made
by, and of the core (:func:`_code`), as Python keys its ``.pyc`` files. An entry of another
key, of other code (an update of tapegate, a module edited), damaged or cut short
is ignored and written again; written as the tables are (a temporary file renamed).

For ``tapegate check`` with a built-in profile written on no ``base``, what the check takes of
the profile -- the machine spec and the dialect's flags -- is kept once more, as
``compiled-NAME.framed.marshal`` (:func:`store_compiled`, :func:`load_compiled`), keyed by the
profile file's bytes (held in the entry and compared whole) and by the same code: read back,
the check needs neither the profile's modules nor its validation (:class:`Compiled`).
"""

from __future__ import annotations

import _thread
import marshal
import os
import sys

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Callable, Iterable
    from typing import Any

__all__ = ["Compiled", "directory", "load", "load_compiled", "load_spec", "spec_key", "store",
           "store_compiled", "store_spec"]

# The end of a framed entry's file name (entries before the frame end in ".marshal" alone)
SUFFIX = ".framed.marshal"

# What an entry is, and for which Python it was written: another one is ignored
KEY = ("tapegate-profile-toml", 2, sys.version_info[:2], marshal.version)


def directory() -> str | None:
    """The cache folder, or None when the cache is off (``TAPEGATE_CACHE_DIR=""``, or no home
    folder to put it in)."""
    given = os.environ.get("TAPEGATE_CACHE_DIR")
    if given is not None:
        return given or None
    base = os.environ.get("XDG_CACHE_HOME")
    if not base:
        home = os.path.expanduser("~")
        if home.startswith("~"):  # no HOME and no home folder: no cache, not a "~" folder here
            return None
        base = os.path.join(home, ".cache")
    return os.path.join(base, "tapegate")


def _path(name: str, text: str) -> str | None:
    folder = directory()
    if folder is None:
        return None
    from zlib import crc32

    return os.path.join(folder, f"profile-{name}-{crc32(text.encode('utf-8')):08x}{SUFFIX}")


def _unmarshal(path: str | None = None, blob: bytes = b"") -> Any:
    """What marshal reads from the entry file ``path`` (or from ``blob``), or None where it
    cannot: the file missing, unreadable or no regular file (:func:`_read`), its frame's
    length or checksum not its bytes' (:func:`_unframe`: checked before marshal reads
    anything, so that a damaged type or length byte is not taken for a count of millions of
    items), the bytes damaged (marshal may raise SystemError too, or any other error: a cache
    never decides a run)."""
    try:
        if path is not None:
            framed = _read(path)
            found = None if framed is None else _unframe(framed)
            if found is None:
                return None
            return marshal.loads(found)
        return marshal.loads(blob)
    except Exception:
        return None


def _read(path: str) -> bytes | None:
    """The bytes of the file ``path``, or None where it is no regular file: opened without
    blocking and asked (``fstat``) before anything is read, so that a FIFO, a device, a
    folder or a symbolic link (not followed) at an entry's path is no entry, not a wait for
    ever (review 62c, its note: a FIFO at ``compiled-NAME.marshal`` hung ``check -p NAME`` in
    ``open()``)."""
    fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_NOFOLLOW | os.O_CLOEXEC)
    try:
        if os.fstat(fd).st_mode & _S_IFMT != _S_IFREG:
            return None
        pieces: list[bytes] = []
        while True:
            piece = os.read(fd, 1 << 16)
            if not piece:
                return b"".join(pieces)
            pieces.append(piece)
    finally:
        os.close(fd)


_S_IFMT, _S_IFREG = 0o170000, 0o100000  # (stat's, without its functions)

# An entry file is a frame: 4 bytes of the checksum (:func:`_checksum`) of what follows, 4
# bytes of its length (both little-endian), then the marshalled entry


def _frame(blob: bytes) -> bytes:
    """``blob`` (a marshalled entry) in its frame, as it is written."""
    return (_checksum(blob) | len(blob) << 32).to_bytes(8, "little") + blob


def _unframe(data: bytes) -> memoryview | None:
    """The marshalled entry inside the frame ``data``, or None where the length or the
    checksum the frame holds is not its bytes' (one byte changed anywhere, cut short, an
    entry of a format before the frame)."""
    if len(data) < 8:
        return None
    head = int.from_bytes(data[:8], "little")
    blob = memoryview(data)[8:]
    if head >> 32 != len(blob) or head & 0xFFFFFFFF != _checksum(blob):
        return None
    return blob


def load(name: str, text: str) -> dict[str, Any] | None:
    """The parsed TOML kept for the profile ``name`` whose text is ``text``, or None
    (no entry, another text, an entry that cannot be read)."""
    path = _path(name, text)
    if path is None:
        return None
    entry = _unmarshal(path)
    if not (type(entry) is tuple and len(entry) == 4 and entry[0] == KEY and entry[1] == text
            and type(entry[3]) is bytes):
        return None
    from zlib import crc32

    if crc32(entry[3]) != entry[2]:  # the table damaged on disk: parsed again, and rewritten
        return None
    data = _unmarshal(blob=entry[3])
    return data if type(data) is dict else None


def store(name: str, text: str, data: dict[str, Any]) -> None:
    """Keep ``data``, the parsed ``text`` of the profile ``name``; quietly nothing
    where the folder cannot be written."""
    path = _path(name, text)
    if path is None:
        return
    from zlib import crc32

    try:
        table = marshal.dumps(data)
    except ValueError:  # a value marshal cannot hold (a TOML date): parsed each time
        return
    _write(path, marshal.dumps((KEY, text, crc32(table), table)))


# What a machine spec entry is, and for which Python it was written
SPEC_KEY = ("tapegate-machine-spec", 1, sys.version_info[:2], marshal.version)
# The modules the profile and its machine spec are made by (their code is in the key)
_SPEC_MODULES = ("formats.machine", "formats.profile", "formats.codes", "formats.classification",
                 "formats.wordformat", "formats.parser", "formats.exact", "formats.records",
                 "formats.choices", "formats.errors", "formats.profile_cache", "formats._core")


def _code() -> tuple[tuple[str, int, int], ...] | None:
    """The code that made a spec: (path, size, modification time in ns) of each module of
    :data:`_SPEC_MODULES`, the core's build among them; None where one cannot be read. An
    update of tapegate writes them anew (tapegate's version is read only from its installed
    metadata, ``importlib.metadata``: more than the spec costs to make); an edited module has
    another size or time."""
    return _stats(getattr(sys.modules.get(name), "__file__", None) for name in _SPEC_MODULES)


def _stats(paths: Iterable[str | None]) -> tuple[tuple[str, int, int], ...] | None:
    """(path, size, modification time in ns) of each of ``paths``; None where one is None or
    cannot be read."""
    found: list[tuple[str, int, int]] = []
    for path in paths:
        if path is None:
            return None
        try:
            info = os.stat(path)
        except OSError:
            return None
        found.append((path, info.st_size, info.st_mtime_ns))
    return tuple(found)


def spec_key(data: dict[str, Any], source: str, default_name: str,
             sample: list[str] | None = None) -> bytes | None:
    """What a profile made from ``data`` (its table, ``base`` merged), ``source``,
    ``default_name`` and its sample limits (``sample``: the limits its own file did not set,
    ``Profile.sample_limits``) keeps its spec under, or None (the cache off, a value marshal
    cannot hold)."""
    if directory() is None:
        return None
    try:
        return marshal.dumps((data, source, default_name, sample or []))
    except ValueError:
        return None


def _spec_path(key: bytes) -> str | None:
    folder = directory()
    if folder is None:
        return None
    from zlib import crc32

    return os.path.join(folder, f"machine-{crc32(key):08x}{SUFFIX}")


def load_spec(key: bytes) -> dict[str, Any] | None:
    """The machine spec kept under ``key`` by this code (:func:`_code`), or None."""
    path = _spec_path(key)
    code = _code()
    if path is None or code is None:
        return None
    entry = _unmarshal(path)
    if not (type(entry) is tuple and len(entry) == 5 and entry[0] == SPEC_KEY
            and entry[1] == code and entry[2] == key and type(entry[4]) is bytes):
        return None
    from zlib import crc32

    if crc32(entry[4]) != entry[3]:  # damaged on disk: made again, and rewritten
        return None
    spec = _unmarshal(blob=entry[4])
    return spec if type(spec) is dict else None


def store_spec(key: bytes, spec: dict[str, Any]) -> None:
    """Keep ``spec`` under ``key``; quietly nothing where the folder cannot be written."""
    path = _spec_path(key)
    code = _code()
    if path is None or code is None:
        return
    from zlib import crc32

    try:
        table = marshal.dumps(spec)
    except ValueError:
        return
    _write(path, marshal.dumps((SPEC_KEY, code, key, crc32(table), table)))


def _write(path: str, blob: bytes) -> None:
    """``blob`` (a marshalled entry) as the file ``path``, in its frame (:func:`_frame`):
    written to a temporary file and renamed. Where something other than a regular file is at
    ``path`` (a FIFO, a device, a folder, a symbolic link: someone put it there), it is left as
    it is and nothing is written: the entry is made each time, as without a cache."""
    temporary = f"{path}.{os.getpid()}.{_thread.get_ident()}.tmp"
    try:
        try:
            if os.lstat(path).st_mode & _S_IFMT != _S_IFREG:
                return
        except FileNotFoundError:
            pass
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(temporary, "wb") as f:
            f.write(_frame(blob))
        os.replace(temporary, path)
    except (OSError, OverflowError):  # (OverflowError: an entry of 4 GiB, not framed)
        import contextlib  # (here only: the cache folder could not be written)

        with contextlib.suppress(OSError):
            os.unlink(temporary)


# What a compiled built-in profile's entry is (load_compiled), and for which Python it was written
COMPILED_KEY = ("tapegate-compiled-profile", 3, sys.version_info[:2], marshal.version)
# The built-in profiles' folder, as formats.profile finds it (its _BUILTIN)
_BUILTIN = os.path.join(os.path.dirname(os.path.realpath(__file__)), "profiles")


def _module_files() -> tuple[tuple[str, int, int], ...] | None:
    """:func:`_code` without importing the modules: (path, size, modification time in ns) of
    each module of :data:`_SPEC_MODULES`, their paths this package's folder and the module's
    name (the core's, the path it was loaded from); None where one cannot be read (a module
    kept only as its ``.pyc``: no entry)."""
    folder = os.path.dirname(__file__)
    core = getattr(sys.modules.get("formats._core"), "__file__", None)
    return _stats(core if name == "formats._core"
                  else os.path.join(folder, name.rpartition(".")[2] + ".py")
                  for name in _SPEC_MODULES)


def _compiled_path(name: str) -> tuple[str, bytes] | None:
    """(the entry's path, the built-in profile's text as bytes) for the built-in profile
    ``name``, or None: the cache off, a name that is no built-in profile's file name (a path,
    ``neutral``), a file that cannot be read."""
    folder = directory()
    if folder is None or not name or name[0] == "." or "/" in name or os.sep in name or (
            os.altsep is not None and os.altsep in name):
        return None
    try:
        with open(os.path.join(_BUILTIN, f"{name}.toml"), "rb") as f:
            text = f.read()
    except (OSError, ValueError):  # (ValueError: a NUL in the name)
        return None
    # (one entry a profile's name, its text compared whole: no CRC-32 in the name, and no zlib
    # imported on a check's way, 0.2 ms)
    return os.path.join(folder, f"compiled-{name}{SUFFIX}"), text


# The modulus of an entry's checksum (_checksum): the largest prime below 2**30, one digit of
# Python's integers (the remainder by one digit is a single pass: a 42 KB entry in 0.09 ms,
# where a 61-bit prime took 0.2 ms)
_PRIME = (1 << 30) - 35


def _checksum(blob: bytes | memoryview) -> int:
    """``blob`` read as one little-endian number, modulo a prime larger than a byte: any one
    byte changed changes it (by d * 256**k, with 0 < |d| < 256, which the prime does not
    divide), as a CRC-32 would tell, without importing zlib (its import, 0.2 ms, was a tenth of
    what reading the entry back costs)."""
    return int.from_bytes(blob, "little") % _PRIME


class Compiled:
    """A built-in profile as ``tapegate check`` needs it, read back from the cache
    (:func:`load_compiled`): the core's machine spec and the dialect's flags the core's reader
    is given, so that a check of many files does not import ``formats.profile`` and the nine
    modules it is made by, nor validate the profile's table again -- 28M instructions, about
    4 ms before a batch's first file, work no ``-j`` worker shares (docs/benchmarks.md,
    jobs62). :meth:`compiled` is what :class:`postproc.check.Checker` takes from it; anything
    else asked of it (a tape image's or a last line's dialect, ``--stats``' work offsets) is
    the profile's own, loaded then (:meth:`full`)."""

    __slots__ = ("_load", "_flags", "_spec", "_machine", "_profile", "_lock")

    def __init__(self, load: Callable[[], Any], flags: tuple[Any, ...],
                 spec: dict[str, Any]) -> None:
        self._load = load
        self._flags = flags
        self._spec: Any = spec
        self._machine: Any = None
        self._profile: Any = None
        self._lock = _thread.allocate_lock()

    def compiled(self) -> tuple[Any, tuple[Any, ...]]:
        """(the core's machine, built once and shared by every file and thread, the dialect's
        flags)."""
        if self._machine is None:
            with self._lock:
                if self._machine is None:
                    from formats import _core

                    self._machine = _core.Machine(self._spec)
        return self._machine, self._flags

    def full(self) -> Any:
        """The profile itself, loaded once (by the ``load`` :func:`load_compiled` was given)."""
        if self._profile is None:
            with self._lock:
                if self._profile is None:
                    self._profile = self._load()
        return self._profile

    def __getattr__(self, attr: str) -> Any:
        if attr.startswith("__"):  # (copy's and pickle's questions: not the profile's)
            raise AttributeError(attr)
        return getattr(self.full(), attr)


def load_compiled(name: str, load: Callable[[], Any]) -> Compiled | None:
    """The built-in profile ``name`` as a check needs it (:class:`Compiled`; ``load``: what
    loads the profile itself, when more of it is asked for), from the entry
    :func:`store_compiled` wrote, or None: no entry, one written for another text of the
    profile, by other code (:data:`_SPEC_MODULES`, the core), by another Python, damaged, or
    cut short; the cache off; a name that is no built-in profile's."""
    found = _compiled_path(name)
    if found is None:
        return None
    path, text = found
    code = _module_files()
    if code is None:
        return None
    entry = _unmarshal(path)  # (its frame's checksum covers all of it: the flags and the spec)
    if not (type(entry) is tuple and len(entry) == 6 and entry[0] == COMPILED_KEY
            and entry[1] == code and entry[2] == name and entry[3] == text
            and type(entry[5]) is dict):
        return None
    flags, spec = entry[4], entry[5]
    if not (type(flags) is tuple and len(flags) == 7 and type(flags[6]) is str
            and all(type(flag) is bool for flag in flags[:6])):
        return None  # (the shape formats.parser.Dialect.flags gives)
    return Compiled(load, flags, spec)


def store_compiled(name: str, flags: tuple[Any, ...], spec: Any) -> None:
    """Keep what :func:`load_compiled` gives for the built-in profile ``name`` (written on no
    ``base``: the entry is keyed by the profile's own text): its dialect's ``flags`` and its
    machine ``spec`` (:func:`formats.machine.keep_compiled` gives them); quietly nothing where
    the folder cannot be written."""
    found = _compiled_path(name)
    code = _module_files()
    if found is None or code is None:
        return
    path, text = found
    try:
        entry = marshal.dumps((COMPILED_KEY, code, name, text, tuple(flags), spec))
    except ValueError:
        return
    _write(path, entry)
