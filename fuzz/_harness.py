"""What every fuzz target shares: instrumentation, the rule for errors, seeds, the entry point.

A target is a module with ``one_input(data: bytes) -> None`` and ``seeds() -> Iterable[bytes]``
that ends with ``main(one_input, seeds)``. ``one_input`` drives the public API with the bytes
and returns normally, or raises: any exception is a find (libFuzzer keeps the input in
``fuzz/artifacts/<target>/``). The one exception that is not a find is a documented error --
a :class:`formats.errors.TapegateError` of the class the API names -- that says where the input
is wrong: :func:`allowed` checks that, and re-raises anything else.

Hangs and memory are libFuzzer's: ``fuzz/run.py`` passes ``-timeout=5`` (seconds per input)
and ``-rss_limit_mb=256``.

The seeds are made at run time from ``../shared/corpus`` (``TAPEGATE_CORPUS`` overrides) and
from the project's own files (built-in profiles, docs); they are written to a temporary folder
by ``python -m fuzz.<target> --write-seeds FOLDER`` and never kept.
"""

from __future__ import annotations

import contextlib
import os
import re
import sys
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent.parent
FILE = "fuzz.nc"  # the file name every target gives the API, checked in the errors
MAX_SEEDS = 800  # libFuzzer runs each seed once before mutating: a few hundred start it fast


def instrumented() -> contextlib.AbstractContextManager[Any]:
    """Import the project's modules inside this to give atheris their coverage (the Rust core
    is not instrumented: it has its own cargo-fuzz targets)."""
    try:
        import atheris
    except ImportError:  # replaying inputs without atheris
        return contextlib.nullcontext()
    return atheris.instrument_imports(include=["formats", "postproc", "dnc"])


class Find(AssertionError):
    """An input that breaks a rule the API documents (not a located error of its own)."""


def allowed(exc: BaseException, kinds: type | tuple[type, ...], *, line: bool = False,
            column: bool = False, code: bool = False,
            file: str | tuple[str | None, ...] | None = None, clause: bool = False) -> None:
    """Return if ``exc`` is a documented error: an instance of ``kinds`` with a message and the
    position fields asked for (``file``: the name, or the names it may carry); otherwise raise
    (``exc`` itself, or a :class:`Find` naming the missing field)."""
    if not isinstance(exc, kinds):
        raise exc
    from formats.errors import TapegateError

    assert isinstance(exc, TapegateError)
    missing = []
    if not exc.message:
        missing.append("message")
    if line and not (exc.line is not None and exc.line >= 1):
        missing.append("line")
    if column and not (exc.column is not None and exc.column >= 1):
        missing.append("column")
    if code and not (exc.code and re.fullmatch(r"TG\d{3}", exc.code)):
        missing.append("code")
    if file is not None and exc.file not in (file if isinstance(file, tuple) else (file,)):
        missing.append(f"file {file!r} (has {exc.file!r})")
    if clause and not exc.clause:
        missing.append("clause")
    if missing:
        raise Find(f"{type(exc).__name__} without {', '.join(missing)}: {exc}") from exc


# Finds in code this harness's authors do not own (the Rust core, and modules being written
# beside it), reported in docs/robustness.md with their reproducers: tolerated so that a run
# goes on past them. Each is (exception type, pattern of its message). Remove an entry when
# its find is fixed.
KNOWN: list[tuple[str, str]] = [
    # none open: the core panic and the diff/verify finds of 2026-12-01 are fixed
]


def known(exc: BaseException) -> bool:
    return any(type(exc).__name__ == kind and re.search(pattern, str(exc))
               for kind, pattern in KNOWN)


def stretch(data: bytes) -> bytes:
    """``data`` with its first run of digits repeated to more than 5,000 digits: numbers beyond
    Python's int() guard of 4,300 digits, which libFuzzer's inputs (``-max_len=2048``) cannot
    reach otherwise."""
    m = re.search(rb"[0-9]+", data)
    if not m:
        return data
    run = m.group(0)
    return data[:m.start()] + run * (5001 // len(run) + 1) + data[m.end():]


def check(condition: bool, message: str) -> None:
    if not condition:
        raise Find(message)


# ---------------------------------------------------------------------------------------------
# Seeds


def corpus_folder() -> Path:
    return Path(os.environ.get("TAPEGATE_CORPUS", ROOT.parent / "shared" / "corpus"))


def corpus_programs() -> list[bytes]:
    """The real programs, whole (none if the corpus is missing: the targets still run)."""
    folder = corpus_folder()
    if not folder.is_dir():
        print(f"fuzz: no corpus at {folder}; seeding from the project's own files only",
              file=sys.stderr)
        return []
    return [p.read_bytes() for p in sorted(folder.iterdir())
            if p.is_file() and p.suffix != ".md"]


def pieces(size: int = 600) -> Iterator[bytes]:
    """The real programs cut at ends of block into pieces of at most ``size`` bytes (small
    inputs keep the Python targets fast; ``run.py`` lets libFuzzer grow them to -max_len=2048),
    and the hand-written programs of the core's fuzz seeds."""
    programs = corpus_programs()
    programs += [p.read_bytes() for p in sorted((ROOT / "crates/fuzz/seeds/programs").glob("*"))]
    for program in programs:
        start = 0
        while start < len(program):
            end = program.rfind(b"\n", start, start + size) + 1
            if end <= start or start + size >= len(program):
                end = min(start + size, len(program))
            yield program[start:end]
            start = end


def expressions() -> Iterator[bytes]:
    """The values of ``=`` words and the bracketed groups of the real programs, and the core's
    expression seeds."""
    for path in sorted((ROOT / "crates/fuzz/seeds/expr").glob("*")):
        yield path.read_bytes().strip()
    seen: set[bytes] = set()
    for program in corpus_programs():
        for m in re.finditer(rb"=([^ ()=;\r\n]+)|(\[[^\]();\r\n]*\])", program):
            value = m.group(1) or m.group(2)
            if value not in seen and len(seen) < 400:
                seen.add(value)
                yield value


def builtin_profile_texts() -> list[bytes]:
    return sorted(p.read_bytes() for p in (ROOT / "formats/profiles").glob("*.toml"))


def profiles() -> list[Any]:
    """Every built-in profile, then the neutral one: a selector byte picks one."""
    from formats.profile import NEUTRAL, builtin_names, load_profile

    return [load_profile(name) for name in builtin_names()] + [NEUTRAL]


def split(data: bytes, size: int) -> list[bytes]:
    """``data`` in pieces of ``size`` bytes (at least one piece)."""
    return [data[i:i + size] for i in range(0, len(data), size)] or [b""]


# ---------------------------------------------------------------------------------------------
# Entry point


def main(one_input: Callable[[bytes], None], seeds: Callable[[], Iterable[bytes]],
         max_seeds: int = MAX_SEEDS) -> None:
    """``--write-seeds FOLDER`` writes the seeds (at most ``max_seeds``: a slow target has
    fewer, or it spends its time running them); anything else is libFuzzer's command line."""
    if sys.argv[1:2] == ["--write-seeds"]:
        folder = Path(sys.argv[2])
        folder.mkdir(parents=True, exist_ok=True)
        chosen = list(seeds())
        chosen = chosen[::max(1, len(chosen) // max_seeds)]  # evenly, from every program
        for n, seed in enumerate(chosen, 1):
            (folder / f"seed-{n:05d}").write_bytes(seed)
        print(f"{len(chosen)} seeds")
        return
    import atheris

    def tolerant(data: bytes) -> None:
        try:
            one_input(data)
        except BaseException as exc:  # a Rust panic is a BaseException
            if not known(exc):
                raise

    atheris.Setup(sys.argv, tolerant)
    atheris.Fuzz()
