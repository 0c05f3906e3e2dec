"""Two builds of tapegate, the same output: every corpus program on every built-in profile.

    .venv/bin/python benchmarks/same_output.py OLD_TREE NEW_TREE [--corpus ../shared/corpus]

A tree is a checkout with its built extension in ``formats/`` (``git worktree add``, or ``git
archive`` and the ``.so`` copied in). Each tree runs in its own process, with the tree first on
``PYTHONPATH``, the commands in-process through click's test runner:

- ``parse FILE --reprint -p P`` and ``parse FILE --json -p P``;
- ``check FILE --format json -p P``;
- ``convert FILE --to P --verify -o OUT --force`` (the converted file included);
- ``diff FILE NEXT -p P`` (each program against the next one of the list).

Each case is kept as a hash of its exit code, standard output, standard error, the type of an
exception that escaped, and the converted file; the script prints the cases whose hashes differ
and exits 1 if there is any.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent


def programs(corpus: Path) -> list[Path]:
    found = []
    for folder in (corpus, corpus / "shops"):
        if folder.is_dir():
            found += sorted(p for p in folder.iterdir()
                            if p.is_file() and p.name != "SOURCES.md")
    return found


def run_cases(corpus: Path) -> dict[str, str]:
    """In the tree on sys.path: every case's hash."""
    from click.testing import CliRunner

    from formats.profile import builtin_names
    from tapegate.cli import main

    runner = CliRunner()
    scratch = Path(tempfile.mkdtemp(prefix="same-output-"))
    target = scratch / "out.nc"

    def digest(args: list[str], written: Path | None = None) -> str:
        result = runner.invoke(main, args)
        extra = [written.read_bytes() if written.exists() else b""] if written else []
        stderr = getattr(result, "stderr_bytes", None) or b""
        escaped = result.exception
        kind = "" if escaped is None or isinstance(escaped, SystemExit) else type(escaped).__name__
        h = hashlib.sha256()
        for part in (str(result.exit_code).encode(), result.stdout_bytes, stderr, kind.encode(),
                     *extra):
            h.update(part.replace(str(scratch).encode(), b"SCRATCH"))
            h.update(b"\0")
        return h.hexdigest()[:16]

    files = programs(corpus)
    cases = {}
    for i, path in enumerate(files):
        other = files[(i + 1) % len(files)]
        for profile in builtin_names():
            key = f"{path.relative_to(corpus)}|{profile}"
            cases[f"reprint|{key}"] = digest(["parse", str(path), "--reprint", "-p", profile])
            cases[f"json|{key}"] = digest(["parse", str(path), "--json", "-p", profile])
            cases[f"check|{key}"] = digest(["check", str(path), "--format", "json", "-p",
                                            profile])
            target.unlink(missing_ok=True)
            cases[f"convert|{key}"] = digest(["convert", str(path), "--to", profile, "--verify",
                                              "-o", str(target), "--force"], target)
            cases[f"diff|{key}"] = digest(["diff", str(path), str(other), "-p", profile])
    return cases


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("old", help="the tree before")
    parser.add_argument("new", help="the tree after")
    parser.add_argument("--corpus", default=str(HERE.parents[1] / "shared" / "corpus"))
    parser.add_argument("--run", help=argparse.SUPPRESS)  # internal: one tree's cases
    args = parser.parse_args()
    corpus = Path(args.corpus).resolve()
    if args.run:
        Path(args.run).write_text(json.dumps(run_cases(corpus)))
        return 0
    if not programs(corpus):
        print(f"no programs in {corpus}", file=sys.stderr)
        return 2
    results = []
    for tree in (args.old, args.new):
        out = Path(tempfile.mkstemp(suffix=".json")[1])
        env = {**os.environ, "PYTHONPATH": str(Path(tree).resolve())}
        subprocess.run([sys.executable, __file__, args.old, args.new, "--corpus", str(corpus),
                        "--run", str(out)], cwd=tree, env=env, check=True)
        results.append(json.loads(out.read_text()))
        out.unlink()
    old, new = results
    differ = sorted(k for k in old.keys() | new.keys() if old.get(k) != new.get(k))
    for key in differ:
        print(key)
    print(f"{len(old)} cases, {len(differ)} differ "
          f"({len(programs(corpus))} programs, {len(old) // max(1, len(programs(corpus))) // 5}"
          " profiles, 5 commands)")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
