"""Byte identity of two builds: the CLI's output over the corpus, recorded and compared.

Issue 31 restructures the core and demands that the output stay byte-identical on the corpus for
``parse --reprint``, ``check --format json``, ``convert --verify`` and ``diff``. This tool records
what one build writes, and compares two records::

    PYTHONPATH=OLD python benchmarks/identity.py record old.jsonl [--corpus DIR ...]
    PYTHONPATH=NEW python benchmarks/identity.py record new.jsonl [--corpus DIR ...]
    python benchmarks/identity.py compare old.jsonl new.jsonl          # exit 1 if any differ
    PYTHONPATH=OLD python benchmarks/identity.py replay old/ --file F --profile P   # one case

``record`` imports ``tapegate`` from wherever ``PYTHONPATH`` points (this file's own checkout is
not put on the path), and runs every command in this one process through click's ``CliRunner``
on ``tapegate.cli.main``: the bytes a user sees with stdout and stderr redirected to files.

**What is run.** Every program file of each corpus folder (its files, not its subfolders, less
``*.md`` and ``*.tsv``; default ``../shared/corpus`` and ``../shared/corpus/shops`` beside the
checkout this tool is in) on every built-in profile of the build under test
(``formats/profiles/*.toml``) and on ``neutral`` (no ``--profile``: the neutral profile adjusted
to the program, as a user gets it by default). Per file and profile P:

- ``parse FILE -p P --reprint``;
- ``check FILE -p P --format json`` (for neutral also ``check FILE -p neutral --format json``,
  the unadjusted neutral profile, which only ``check`` accepts before issue 31);
- ``convert FILE -o OUT --from P --to T [...] --verify`` to three targets (see ``targets``):
  ``units`` (P itself in its other unit system), ``decimal`` (P itself in the other decimal
  style) and ``family`` (a control of another family, ``FAMILY``);
- ``diff FILE OUT --tolerance 0.5 --from P -p T`` against each conversion that wrote its
  output (half a step: what rounding to T's resolution leaves; no profiles for neutral);
- ``diff FILE CHANGED -p P`` against a copy with one word changed (``changed_word``), in text
  and as ``--format json --motion``.

Each entry is one JSON line: the key (command, file, profile, target), the argv, the exit code,
the SHA-256 of stdout, of stderr and of the output file (convert), and an exception's last line
if the command raised one (a traceback is a bug: it is recorded, not hidden). The commands run
in a scratch folder that holds the corpus folders as symbolic links (``corpus/``, ``shops/``) and
the outputs (``out/``, ``changed/``), named by relative paths; any remaining occurrence of the
scratch folder, a corpus folder or the build's checkout in the output is replaced by a
placeholder before hashing, so two checkouts (and two scratch folders) compare equal. Each
TOML text is parsed once in the process (``memoise_toml``; ``--no-memo`` to leave it alone).

``compare`` prints each entry that differs, with the command line that reproduces it (relative
to the scratch folder) and the ``replay`` command that runs it again; then the number of entries
compared. Exit 0 all equal, 1 any differ (or an entry is in one record only), 2 a record cannot
be read.

``replay DIR --file F --profile P`` runs the entries of one file and profile in DIR (kept), and
writes each one's stdout, stderr and exit code there: run it under each build and ``diff -r``.
"""

from __future__ import annotations

import argparse
import copy
import functools
import hashlib
import itertools
import json
import os
import platform
import re
import shlex
import shutil
import sys
import tempfile
import time
import tomllib
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TextIO

TOOL_ROOT = Path(__file__).resolve().parents[1]
SHARED_CORPUS = TOOL_ROOT.parent / "shared" / "corpus"
DEFAULT_CORPUS = (SHARED_CORPUS, SHARED_CORPUS / "shops")
NOT_PROGRAMS = (".md", ".tsv")
NEUTRAL = "neutral"

# The "family" target of each built-in profile: a control of another family, of the same kind
# (a lathe for a lathe); an implicit-decimal ISO 1056 tape for an explicit-decimal control.
FAMILY = {
    "cm332-quadrant": "iso-mill",
    "fanuc-lathe": "haas-lathe",
    "fanuc-mill": "sinumerik-840d",
    "haas-lathe": "fanuc-lathe",
    "haas-mill": "fanuc-mill",
    "heidenhain-iso": "sinumerik-840d",
    "iso-lathe": "fanuc-lathe",
    "iso-mill": "fanuc-mill",
    "linuxcnc": "haas-mill",
    "pm322-eia": "fanuc-mill",
    "sinumerik-7e2": "heidenhain-iso",
    "sinumerik-840d": "fanuc-mill",
}
# Without --from (neutral: the source is detected) the targets are fixed profiles.
NEUTRAL_TARGETS = {
    "units": ["--to", "iso-mill", "--units", "inch"],
    "decimal": ["--to", "pm322-eia"],
    "family": ["--to", "fanuc-mill"],
}


class Problem(Exception):
    """A user error of this tool: one line on stderr, exit 2."""


# ---------------------------------------------------------------------------------------------
# what is run


@dataclass(frozen=True)
class ProfileInfo:
    name: str
    units: str  # "metric" or "inch": the profile's default
    explicit: bool  # a decimal sign (DS in the Annex C classification)


def profile_info(path: Path) -> ProfileInfo:
    """A profile's units and decimal style, read from its TOML file (not through the build's
    API, which the restructuring under test may change)."""
    data = tomllib.loads(path.read_text("utf-8"))
    detailed = str(data.get("detailed", ""))
    explicit = "DS" in detailed.split()[0] if detailed.strip() else True
    return ProfileInfo(str(data.get("name", path.stem)), str(data.get("units", "metric")),
                       explicit)


def targets(profile: ProfileInfo | None) -> dict[str, list[str]]:
    """The convert options of the three targets of a source profile (None: neutral)."""
    if profile is None:
        return {k: list(v) for k, v in NEUTRAL_TARGETS.items()}
    other_units = "inch" if profile.units == "metric" else "metric"
    other_decimal = "implicit" if profile.explicit else "explicit"
    family = FAMILY.get(profile.name, "iso-mill" if profile.name != "iso-mill" else "fanuc-mill")
    return {
        "units": ["--from", profile.name, "--to", profile.name, "--units", other_units],
        "decimal": ["--from", profile.name, "--to", profile.name, "--decimal", other_decimal],
        "family": ["--from", profile.name, "--to", family],
    }


NUMBER = rb"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)"
WORD = re.compile(rb"(?<![A-Za-z_#$])[XYZ]" + NUMBER)
ANY_WORD = re.compile(rb"(?<![A-Za-z_#$])[A-FH-LP-Z]" + NUMBER)  # not G M N O


def changed_word(data: bytes) -> tuple[bytes, str] | None:
    """The program with one word changed, and what changed; None if it has no word.

    The first X, Y or Z word with a number (else the first word of another letter than G, M,
    N and O), outside ``( )`` and before ``;``, in the lines from the middle of the file on
    (then from its start): its last digit plus one (9 becomes 0). Plain bytes, so the change
    does not depend on the build's reading.
    """
    lines = data.splitlines(keepends=True)
    middle = len(lines) // 2
    order = list(itertools.chain(range(middle, len(lines)), range(middle)))
    for pattern in (WORD, ANY_WORD):
        for i in order:
            line = lines[i]
            code = re.sub(rb"\([^)]*\)?", lambda m: b" " * len(m.group()), line)
            match = pattern.search(code.split(b";")[0])
            if match is None:
                continue
            word = match.group()
            at = max(j for j, c in enumerate(word) if chr(c).isdigit())
            new = word[:at] + bytes([ord("0") + (word[at] - ord("0") + 1) % 10]) + word[at + 1:]
            lines[i] = line[:match.start()] + new + line[match.end():]
            what = (f"line {i + 1} column {match.start() + 1}: "
                    f"{word.decode('ascii')} -> {new.decode('ascii')}")
            return b"".join(lines), what
    return None


@dataclass
class Entry:
    command: str
    file: str
    profile: str
    target: str
    argv: list[str]
    exit: int | None = None
    stdout: str | None = None
    stderr: str | None = None
    output: str | None = None
    exception: str | None = None
    skipped: str | None = None
    note: str | None = None
    ms: float | None = None  # how long the command took (not compared)
    raw: dict[str, bytes] = field(default_factory=dict, repr=False)

    def as_json(self) -> dict[str, Any]:
        data = {"command": self.command, "file": self.file, "profile": self.profile,
                "target": self.target, "argv": self.argv, "exit": self.exit,
                "stdout": self.stdout, "stderr": self.stderr, "output": self.output}
        for name in ("exception", "skipped", "note", "ms"):
            if getattr(self, name) is not None:
                data[name] = getattr(self, name)
        return data


def sha(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def memoise_toml() -> None:
    """Parse each TOML text once: every command loads its profiles again (a dozen built-in
    ones, 18,000 commands), and ``tomllib.loads`` took about 30 % of the time on small programs.
    It is a pure function of its text, so each call gets a deep copy of the first parse: what
    a parse of its own would return. (``--no-memo`` leaves it alone.)"""
    original = tomllib.loads
    first = functools.lru_cache(maxsize=256)(original)

    def loads(s: str, /, *, parse_float: Any = float) -> dict[str, Any]:
        if parse_float is not float:
            return original(s, parse_float=parse_float)
        return copy.deepcopy(first(s))

    tomllib.loads = loads  # type: ignore[assignment]


class Runner:
    """The commands of one build, run in one process in a scratch folder."""

    def __init__(self, work: Path, folders: dict[str, Path]):
        from click.testing import CliRunner

        try:
            import tapegate
            from tapegate.cli import main
        except ImportError as exc:
            raise Problem(f"cannot import the build to record ({exc}): run with "
                          "PYTHONPATH=<checkout with its built extension>") from None

        self.cli = main
        try:
            self.runner = CliRunner(mix_stderr=False)  # type: ignore[call-arg]  # click < 8.2
        except TypeError:
            self.runner = CliRunner()  # click 8.2 and later keep stderr apart
        self.work = work
        self.checkout = Path(tapegate.__file__).resolve().parents[1]
        # longest first, so that a folder inside another is replaced by its own name
        places: dict[str, str] = {}
        for label, folder in folders.items():
            for form in {str(folder), str(folder.resolve())}:
                places[form] = f"<{label}>"
        for form in {str(work), str(work.resolve())}:
            places[form] = "<work>"
        places[str(self.checkout)] = "<checkout>"
        self.places = sorted(((k.encode(), v.encode()) for k, v in places.items()),
                             key=lambda kv: -len(kv[0]))

    def normalise(self, data: bytes) -> bytes:
        for path, label in self.places:
            data = data.replace(path, label)
        return data

    def run(self, entry: Entry, output: str | None = None) -> Entry:
        start = time.perf_counter()
        result = self.runner.invoke(self.cli, entry.argv, catch_exceptions=True)
        entry.ms = round((time.perf_counter() - start) * 1000, 1)
        entry.exit = result.exit_code
        out = self.normalise(result.stdout_bytes)
        err = self.normalise(result.stderr_bytes or b"")
        entry.stdout, entry.stderr = sha(out), sha(err)
        entry.raw = {"stdout": out, "stderr": err}
        if result.exception is not None and not isinstance(result.exception, SystemExit):
            text = f"{type(result.exception).__name__}: {result.exception}"
            entry.exception = self.normalise(text.encode()).decode("utf-8", "replace")
        if output is not None:
            path = self.work / output
            if path.is_file():
                data = path.read_bytes()
                entry.output = sha(self.normalise(data))
                entry.raw["output"] = data
        return entry


def program_files(folder: Path) -> list[Path]:
    return sorted(p for p in folder.iterdir()
                  if p.is_file() and not p.name.startswith(".")
                  and not p.name.lower().endswith(NOT_PROGRAMS))


def labelled(folders: Iterable[Path]) -> dict[str, Path]:
    """Each corpus folder under a name of its own: its last component (``corpus``, ``shops``),
    numbered where two share one."""
    result: dict[str, Path] = {}
    for folder in folders:
        if not folder.is_dir():
            raise Problem(f"{folder}: no such folder (give the corpus with --corpus DIR)")
        base = re.sub(r"[^A-Za-z0-9_.-]", "_", folder.name) or "corpus"
        label, n = base, 1
        while label in result:
            n += 1
            label = f"{base}{n}"
        result[label] = folder
    return result


def built_in_profiles() -> dict[str, ProfileInfo]:
    import formats

    folder = Path(formats.__file__).resolve().parent / "profiles"
    return {p.stem: profile_info(p) for p in sorted(folder.glob("*.toml"))}


def entries(runner: Runner, label: str, path: Path, profiles: dict[str, ProfileInfo],
            only: Callable[[str], bool] = lambda name: True) -> Iterator[Entry]:
    """Run every command on one file, profile by profile, and yield the entries."""
    name = f"{label}/{path.name}"
    changed = changed_word(path.read_bytes())
    changed_name = f"changed/{name}"
    if changed is not None:
        target = runner.work / changed_name
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(changed[0])
    for prof in [*profiles, NEUTRAL]:
        if not only(prof):
            continue
        info = profiles.get(prof)
        p_opt = [] if prof == NEUTRAL else ["-p", prof]
        yield runner.run(Entry("parse", name, prof, "", ["parse", name, *p_opt, "--reprint"]))
        yield runner.run(Entry("check", name, prof, "",
                               ["check", name, *p_opt, "--format", "json"]))
        if prof == NEUTRAL:
            yield runner.run(Entry("check", name, prof, "-p neutral",
                                   ["check", name, "-p", NEUTRAL, "--format", "json"]))
        for target, options in targets(info).items():
            out = f"out/{prof}/{target}/{name}"
            (runner.work / out).parent.mkdir(parents=True, exist_ok=True)
            converted = runner.run(Entry("convert", name, prof, target,
                                         ["convert", name, "-o", out, *options, "--verify"]),
                                   output=out)
            yield converted
            diff = Entry("diff", name, prof, f"vs {target}",
                         ["diff", name, out, "--tolerance", "0.5"])
            if prof != NEUTRAL:
                diff.argv += ["--from", prof, "-p", options[options.index("--to") + 1]]
            if converted.output is None:
                diff.skipped = "the conversion wrote no output"
                yield diff
            else:
                yield runner.run(diff)
        for target, extra in (("changed word", []),
                              ("changed word json", ["--format", "json", "--motion"])):
            diff = Entry("diff", name, prof, target, ["diff", name, changed_name, *p_opt, *extra])
            if changed is None:
                diff.skipped = "no word to change"
                yield diff
            else:
                diff.note = changed[1]
                yield runner.run(diff)


# ---------------------------------------------------------------------------------------------
# record, compare, replay


def meta(runner: Runner, folders: dict[str, Path], profiles: dict[str, ProfileInfo]
         ) -> dict[str, Any]:
    import formats

    core = sorted(Path(formats.__file__).resolve().parent.glob("_core*"))
    return {"meta": {
        "tool": "benchmarks/identity.py",
        "tapegate": str(runner.checkout),
        "core": {p.name: sha(p.read_bytes()) for p in core},
        "python": platform.python_version(),
        "corpus": {label: str(folder) for label, folder in folders.items()},
        "profiles": [*profiles, NEUTRAL],
        "started": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
    }}


def record(out: Path, corpus: list[Path], file_filter: str | None = None,
           profile_filter: str | None = None, keep: Path | None = None,
           memo: bool = True) -> int:
    folders = labelled(corpus)
    out = out.absolute()  # the commands run in the scratch folder
    if memo:
        memoise_toml()
    try:
        f = open(out, "w", encoding="utf-8")  # noqa: SIM115 (closed below)
    except OSError as exc:
        raise Problem(f"cannot write {out}: {exc.strerror}") from None
    work = keep or Path(tempfile.mkdtemp(prefix="tapegate-identity-"))
    previous = os.getcwd()
    try:
        with f:
            work.mkdir(parents=True, exist_ok=True)
            for label, folder in folders.items():
                link = work / label
                if link.is_symlink() or link.exists():
                    link.unlink()
                link.symlink_to(folder.resolve(), target_is_directory=True)
            os.chdir(work)  # the commands name every file relative to the scratch folder
            _record(f, str(out), Runner(work, folders), folders, file_filter, profile_filter,
                    keep is not None)
    except BaseException:
        out.unlink(missing_ok=True)  # no half record that compare could take for a whole one
        raise
    finally:
        os.chdir(previous)
        if keep is None:
            shutil.rmtree(work, ignore_errors=True)
    return 0


def _record(f: TextIO, out: str, runner: Runner, folders: dict[str, Path],
            file_filter: str | None, profile_filter: str | None, keep: bool) -> None:
    profiles = built_in_profiles()
    if profile_filter and profile_filter not in [*profiles, NEUTRAL]:
        raise Problem(f"no profile {profile_filter!r} in {[*profiles, NEUTRAL]}")
    files = [(label, p) for label, folder in folders.items() for p in program_files(folder)
             if file_filter in (None, f"{label}/{p.name}")]
    if not files:
        raise Problem(f"no program file {file_filter or ''} in "
                      f"{', '.join(map(str, folders.values()))}")
    print(f"identity: tapegate from {runner.checkout}; {len(files)} files, "
          f"{len(profiles) + 1} profiles; scratch folder {runner.work}", file=sys.stderr)
    start, cpu = time.perf_counter(), time.process_time()
    count = exceptions = 0
    spent: dict[str, float] = {}
    f.write(json.dumps(meta(runner, folders, profiles)) + "\n")
    for i, (label, path) in enumerate(files, 1):
        for entry in entries(runner, label, path, profiles,
                             lambda p: profile_filter in (None, p)):
            f.write(json.dumps(entry.as_json(), ensure_ascii=False) + "\n")
            count += 1
            exceptions += entry.exception is not None
            spent[entry.command] = spent.get(entry.command, 0) + (entry.ms or 0) / 1000
            if keep:
                keep_entry(runner.work, count, entry)
        f.flush()
        print(f"identity: {i}/{len(files)} {label}/{path.name} "
              f"({time.perf_counter() - start:.0f} s)", file=sys.stderr)
    elapsed, cpu = time.perf_counter() - start, time.process_time() - cpu
    print(f"identity: {count} entries ({len(files)} files x {len(profiles) + 1} profiles) "
          f"in {elapsed:.1f} s ({cpu:.1f} s CPU; "
          + ", ".join(f"{c} {t:.1f} s" for c, t in sorted(spent.items()))
          + f"); {exceptions} raised an exception; written to {out}", file=sys.stderr)


def keep_entry(work: Path, n: int, entry: Entry) -> None:
    """replay: an entry's normalised stdout and stderr, exit code and command line, in files."""
    folder = work / "results"
    folder.mkdir(exist_ok=True)
    base = folder / f"{n:03d}-{entry.command}-{re.sub(r'[^a-z0-9]+', '-', entry.target)}"
    base = Path(str(base).rstrip("-"))
    for stream in ("stdout", "stderr"):
        Path(f"{base}.{stream}").write_bytes(entry.raw.get(stream, b""))
    Path(f"{base}.exit").write_text(
        f"{entry.exit}\n" if entry.skipped is None else f"skipped: {entry.skipped}\n")
    Path(f"{base}.cmd").write_text(command_line(entry.argv) + "\n")


def command_line(argv: list[str]) -> str:
    return shlex.join(["tapegate", *argv])


def load(path: Path) -> tuple[dict[str, Any], dict[tuple[str, ...], dict[str, Any]]]:
    try:
        text = path.read_text("utf-8")
    except OSError as exc:
        raise Problem(f"{path}: cannot read: {exc.strerror}") from None
    except UnicodeDecodeError:
        raise Problem(f"{path}: not a record (not UTF-8 text)") from None
    head: dict[str, Any] = {}
    found: dict[tuple[str, ...], dict[str, Any]] = {}
    for n, line in enumerate(text.splitlines(), 1):
        if not line.strip():
            continue
        try:
            item = json.loads(line)
            if "meta" in item:
                head = item["meta"]
                continue
            key = (item["command"], item["file"], item["profile"], item["target"])
        except (json.JSONDecodeError, TypeError, KeyError) as exc:
            raise Problem(f"{path}:{n}: not an entry of identity.py record "
                          f"({type(exc).__name__}: {exc})") from None
        if key in found:
            raise Problem(f"{path}:{n}: the entry {' '.join(key)} twice")
        found[key] = item
    if not head:
        raise Problem(f"{path}: no meta line: not written by identity.py record")
    return head, found


COMPARED = ("exit", "stdout", "stderr", "output", "exception", "skipped", "argv")


def compare(path_a: Path, path_b: Path) -> int:
    head_a, a = load(path_a)
    head_b, b = load(path_b)
    for name, head in ((path_a, head_a), (path_b, head_b)):
        print(f"{name}: tapegate {head.get('tapegate')}, core "
              f"{', '.join(v[:12] for v in head.get('core', {}).values()) or '?'}, "
              f"recorded {head.get('started')}")
    if head_a.get("core") == head_b.get("core"):
        print("note: both records were made with the same core extension (the same build?)")
    differing = 0
    by_command: dict[str, int] = {}
    by_profile: dict[str, int] = {}
    for key in sorted(a.keys() | b.keys()):
        ea, eb = a.get(key), b.get(key)
        if ea is not None and eb is not None:
            what = [f for f in COMPARED if ea.get(f) != eb.get(f)]
            if not what:
                continue
            detail = "; ".join(
                f"exit {ea.get('exit')} -> {eb.get('exit')}" if f == "exit" else
                f"{f}: {ea.get(f)!r} -> {eb.get(f)!r}" if f in ("exception", "skipped") else f
                for f in what)
        else:
            detail = f"only in {path_a if eb is None else path_b}"
        differing += 1
        by_command[key[0]] = by_command.get(key[0], 0) + 1
        by_profile[key[2]] = by_profile.get(key[2], 0) + 1
        entry = ea if ea is not None else eb
        assert entry is not None
        command, file, profile, target = key
        label = f"{command} {file} [{profile}]" + (f" {target}" if target else "")
        print(f"DIFFERS {label}: {detail}")
        print(f"    {command_line(entry['argv'])}")
        if entry.get("note"):
            print(f"    (changed word: {entry['note']})")
        corpus = " ".join(f"--corpus {shlex.quote(v)}"
                          for v in (head_a.get("corpus") or {}).values())
        print(f"    replay: PYTHONPATH=CHECKOUT python benchmarks/identity.py replay DIR "
              f"--file {shlex.quote(file)} --profile {profile} {corpus}")
    total = len(a.keys() | b.keys())
    if differing:
        for name, counts in (("command", by_command), ("profile", by_profile)):
            print(f"differing entries by {name}: "
                  + ", ".join(f"{k} {n}" for k, n in sorted(counts.items())))
    print(f"{total} entries compared ({len(a)} in {path_a}, {len(b)} in {path_b}): "
          + (f"{differing} differ" if differing else "all byte-identical"))
    return 1 if differing else 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description="Record a build's CLI output over the corpus; compare two records.")
    sub = parser.add_subparsers(dest="action", required=True)
    rec = sub.add_parser("record", help="run every command on every file and profile")
    rec.add_argument("out", type=Path, help="the record to write (JSON Lines)")
    rep = sub.add_parser("replay", help="run one file's entries again, keeping their output")
    rep.add_argument("dir", type=Path, help="a folder to keep the scratch files and results in")
    rep.add_argument("--file", required=True, help="as the record names it: corpus/NAME")
    rep.add_argument("--profile", help="only this profile (default: all)")
    for p in (rec, rep):
        p.add_argument("--corpus", type=Path, action="append",
                       help="a folder of programs (repeat; default: ../shared/corpus and "
                            "../shared/corpus/shops beside the checkout)")
    rec.add_argument("--file", help="only this file (as the record names it: corpus/NAME)")
    rec.add_argument("--profile", help="only this profile")
    rec.add_argument("--no-memo", dest="memo", action="store_false",
                     help="parse every profile's TOML anew for each command (slower)")
    cmp_ = sub.add_parser("compare", help="print the entries of two records that differ")
    cmp_.add_argument("a", type=Path)
    cmp_.add_argument("b", type=Path)
    args = parser.parse_args(argv)
    try:
        if args.action == "compare":
            return compare(args.a, args.b)
        corpus = args.corpus or list(DEFAULT_CORPUS)
        if args.action == "record":
            return record(args.out, corpus, args.file, args.profile, memo=args.memo)
        if args.dir.exists() and any(args.dir.iterdir()):
            raise Problem(f"{args.dir}: not empty; replay into a new folder")
        args.dir.mkdir(parents=True, exist_ok=True)
        code = record(args.dir / "record.jsonl", corpus, args.file, args.profile,
                      keep=args.dir.resolve())
        print(f"identity: results in {args.dir / 'results'} (stdout, stderr, exit, cmd each)",
              file=sys.stderr)
        return code
    except Problem as exc:
        print(f"identity: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
