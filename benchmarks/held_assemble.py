"""Assemble the held-out sets of issue 32 from their rows, for ``benchmarks/shops.py --shops``.

    .venv/bin/python benchmarks/held_assemble.py --snapshots SNAP --out OUT [--union] [SET ...]

Each row of ``benchmarks/unseen/<SET>.tsv`` (family, file, repository, commit, path,
description) names one program. Its bytes are taken with ``git show COMMIT:PATH`` from the
repository's snapshot, ``SNAP/<owner>+<name>/repo`` (a git directory, or a work tree holding
``.git``), and written to ``OUT/<SET>/<file>``; a file already there is kept (the rows whose
repository has no snapshot, or whose commit the snapshot lacks, are written by hand from the
text index and said so in the manifest). ``OUT/<SET>/families.tsv`` holds the first, second and
last columns, as ``shops.py --shops`` reads them; ``OUT/manifest.tsv`` each file's size, lines,
git blob hash and where its bytes came from (``snapshot`` when they are the blob at the row's
commit, byte for byte). ``--union`` also makes ``OUT/all``: every set's files (hard links; the
file names are unique across the sets) under one ``families.tsv``.

With no SET, every ``held*.tsv`` (dev is the development set: name it to assemble it). The
programs are never part of the project; docs/benchmarks.md keeps the figures.
"""

from __future__ import annotations

import argparse
import hashlib
import os
import subprocess
import sys
from pathlib import Path

UNSEEN = Path(__file__).resolve().parent / "unseen"


def rows(name: str) -> list[list[str]]:
    """The rows of one set's TSV: family, file, repository, commit, path, description."""
    out = []
    for line in (UNSEEN / f"{name}.tsv").read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.startswith("#"):
            out.append(line.split("\t"))
    return out


def git_dir(snapshots: Path, repository: str) -> Path | None:
    repo = snapshots / repository.replace("/", "+") / "repo"
    if (repo / ".git").is_dir():
        return repo / ".git"
    return repo if repo.is_dir() else None


def git(directory: Path, *args: str) -> subprocess.CompletedProcess[bytes]:
    return subprocess.run(["git", "--git-dir", str(directory), *args], capture_output=True,
                          check=False)


def blob_hash(path: Path) -> str:
    """The git blob hash of the file's bytes as they are (SHA-1 of ``blob <size>\\0`` and the
    bytes), computed here: ``git hash-object`` would apply the filters of whatever repository
    and configuration it runs in (``core.autocrlf`` turns CR LF into LF), and a CR LF program
    would carry a hash other than its blob's."""
    data = path.read_bytes()
    return hashlib.sha1(b"blob %d\0" % len(data) + data).hexdigest()


def assemble(name: str, snapshots: Path, out: Path) -> list[list[str]]:
    """Write one set's files and families.tsv; the manifest rows of its files."""
    folder = out / name
    folder.mkdir(parents=True, exist_ok=True)
    families, manifest = [], []
    for family, file, repository, commit, path, *rest in rows(name):
        description = rest[-1] if rest else ""
        families.append(f"{family}\t{file}\t{description}\n")
        target = folder / file
        directory = git_dir(snapshots, repository)
        shown = git(directory, "show", f"{commit}:{path}") if directory else None
        if shown is not None and shown.returncode == 0:
            target.write_bytes(shown.stdout)
            source = "snapshot"
        elif target.is_file():
            why = "no snapshot" if directory is None else "commit not in the snapshot"
            source = f"written by hand ({why})"
        else:
            why = "no snapshot" if directory is None else "commit not in the snapshot"
            print(f"missing\t{name}\t{file}\t{repository}\t{commit}\t{path}\t{why}",
                  file=sys.stderr)
            continue
        data = target.read_bytes()
        manifest.append([name, file, str(len(data)), str(data.count(b"\n")), blob_hash(target),
                         source])
    (folder / "families.tsv").write_text("".join(families), encoding="utf-8")
    return manifest


def union(names: list[str], out: Path) -> None:
    """OUT/all: every set's files under one families.tsv."""
    folder = out / "all"
    folder.mkdir(parents=True, exist_ok=True)
    families = []
    for name in names:
        for line in (out / name / "families.tsv").read_text(encoding="utf-8").splitlines():
            file = line.split("\t")[1]
            if not (out / name / file).is_file():
                continue
            target = folder / file
            if not target.exists():
                os.link(out / name / file, target)
            families.append(line + "\n")
    (folder / "families.tsv").write_text("".join(families), encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--snapshots", type=Path, required=True)
    parser.add_argument("--out", type=Path, required=True)
    parser.add_argument("--union", action="store_true")
    parser.add_argument("sets", nargs="*")
    args = parser.parse_args(argv)
    names = args.sets or sorted((p.stem for p in UNSEEN.glob("held*.tsv")),
                                key=lambda s: int(s[4:] or 1))
    manifest = []
    for name in names:
        manifest += assemble(name, args.snapshots, args.out)
    (args.out / "manifest.tsv").write_text(
        "set\tfile\tbytes\tlines\tblob\tsource\n" + "".join("\t".join(r) + "\n" for r in manifest),
        encoding="utf-8")
    if args.union:
        union(names, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
