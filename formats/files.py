"""Writing files so that nothing is ever half-written or silently replaced."""

from __future__ import annotations

import hashlib
import os
import tempfile
from pathlib import Path


class PendingFile:
    """A file written in pieces and named only at the end (:meth:`commit`).

    Until then the data lives in a hidden temporary file in the target folder; :meth:`discard`
    (or an exception in a ``with`` block) leaves nothing behind. Used where the name depends on
    what arrives (a received program is named from its program number) and where the data is too
    big for memory.
    """

    def __init__(self, folder: Path, hint: str = "tapegate"):
        self.folder = Path(folder)
        self.folder.mkdir(parents=True, exist_ok=True)
        fd, self.tmp = tempfile.mkstemp(prefix=f".{hint}.", suffix=".part", dir=self.folder)
        self.file = os.fdopen(fd, "wb")
        self.size = 0

    def write(self, data: bytes) -> None:
        self.file.write(data)
        self.size += len(data)

    def commit(self, path: Path, *, overwrite: bool = False) -> Path:
        """fsync and give the file its name; with ``overwrite`` False an existing file is kept
        and a new version name is used (``NAME.1.EXT``...). Returns the path written."""
        path = Path(path)
        self.file.flush()
        os.fsync(self.file.fileno())
        self.file.close()
        os.chmod(self.tmp, 0o666 & ~_umask())  # mkstemp makes 0600; a program is for sharing
        try:
            if overwrite:
                os.replace(self.tmp, path)
                return path
            while True:
                path = next_free_name(path)
                try:
                    os.link(self.tmp, path)  # fails if the name was taken meanwhile
                    break
                except FileExistsError:
                    continue
            os.unlink(self.tmp)
            return path
        except BaseException:
            self.discard()
            raise

    def discard(self) -> None:
        if not self.file.closed:
            self.file.close()
        if os.path.exists(self.tmp):
            os.unlink(self.tmp)

    def __enter__(self) -> PendingFile:
        return self

    def __exit__(self, kind: object, *rest: object) -> None:
        if kind is not None or not self.file.closed:
            self.discard()


def write_atomic(path: Path, data: bytes, *, overwrite: bool = True) -> Path:
    """Write ``data`` to ``path`` through a temporary file, fsync and rename.

    With ``overwrite`` False an existing file is kept and the data goes to a new version name
    (``NAME.1.EXT``, ``NAME.2.EXT``...); the path actually written is returned.
    """
    path = Path(path)
    with PendingFile(path.parent, path.name) as pending:
        pending.write(data)
        return pending.commit(path, overwrite=overwrite)


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def next_free_name(path: Path) -> Path:
    if not path.exists():
        return path
    stem, suffix = path.stem, path.suffix
    n = 1
    while True:
        candidate = path.with_name(f"{stem}.{n}{suffix}")
        if not candidate.exists():
            return candidate
        n += 1


def sha256_of(path: Path) -> str:
    """The SHA-256 of a file, read in chunks (for the transfer journal)."""
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 16), b""):
            digest.update(chunk)
    return digest.hexdigest()


def count_lines(path: Path) -> int:
    """Line ends in a file, read in chunks."""
    with open(path, "rb") as f:
        return sum(chunk.count(b"\n") for chunk in iter(lambda: f.read(1 << 16), b""))
