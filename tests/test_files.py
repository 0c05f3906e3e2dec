"""formats.files: the one atomic write."""

from __future__ import annotations

import errno
import os
import re
import stat
import threading
from pathlib import Path

import pytest

from formats.errors import OutputError
from formats.files import PendingFile, write_atomic


def test_a_failed_close_still_leaves_nothing_behind(tmp_path: Path) -> None:
    """A full disk fails the write and then the close again: the temporary file must still go
    (it stayed as .received.*.part)."""
    pending = PendingFile(tmp_path, "received")
    pending.write(b"N1 X1.\n" * 100)
    real_close = pending.file.close

    def full(*_: object) -> None:
        real_close()
        raise OSError(errno.ENOSPC, "No space left on device")

    pending.file.close = full  # type: ignore[method-assign]
    pending.discard()
    assert list(tmp_path.iterdir()) == []


def test_no_name_is_replaced_unless_asked(tmp_path: Path) -> None:
    target = tmp_path / "O1234.nc"
    write_atomic(target, b"first\n")
    second = write_atomic(target, b"second\n", overwrite=False)
    assert second.name == "O1234.1.nc" and target.read_bytes() == b"first\n"
    with PendingFile(tmp_path, "x") as pending:
        pending.write(b"third\n")
        with pytest.raises(FileExistsError):
            pending.commit(target, version=False)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["O1234.1.nc", "O1234.nc"]


def test_a_file_handed_over_is_committed_by_the_core_as_commit_would(tmp_path: Path) -> None:
    """PendingFile.hand_over gives a descriptor of the taker's own, the data flushed (written
    in pieces the file object still buffered), and closes its file; the core's Commits
    (formats._core) then names it as PendingFile.commit does: a link that refuses a name taken
    (the temporary file removed), a rename where it may replace."""
    from formats import _core

    target = tmp_path / "O1.nc"
    target.write_bytes(b"there\n")
    commits = _core.Commits(1)
    tickets = []
    for overwrite in (False, True):
        pending = PendingFile(tmp_path, "O1.nc")
        pending.write(b"N1 X1.\n")
        pending.write(b"N2 X2.\n")
        fd = pending.hand_over()
        assert pending.file.closed and os.fstat(fd).st_size == 14
        tickets.append(commits.submit(fd, pending.tmp, str(target), overwrite))
    with pytest.raises(FileExistsError):
        commits.wait(tickets[0])
    assert commits.wait(tickets[1]) is None
    commits.close()
    assert target.read_bytes() == b"N1 X1.\nN2 X2.\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["O1.nc"]
    with pytest.raises(ValueError):  # (each ticket is waited for once)
        commits.wait(tickets[1])


def test_the_mode_follows_the_umask_without_changing_it(tmp_path: Path) -> None:
    old = os.umask(0o027)
    try:
        path = write_atomic(tmp_path / "p.nc", b"N1\n")
        assert oct(path.stat().st_mode & 0o777) == "0o640"
        assert os.umask(0o027) == 0o027  # still the caller's
    finally:
        os.umask(old)


def test_a_missing_folder_is_an_output_error(tmp_path: Path) -> None:
    with pytest.raises(OutputError) as info:
        write_atomic(tmp_path / "nowhere" / "p.nc", b"N1\n")
    assert info.value.code == "output"
    # named by the file the user gave (no `file` field is set): the message is where it is told
    assert re.search(r"cannot write .*nowhere.*p\.nc: no such folder", info.value.message)
    assert not (tmp_path / "nowhere").exists()


def _read_fifo(path: Path, into: list[bytes]) -> threading.Thread:
    def read() -> None:
        with open(path, "rb") as fifo:
            into.append(fifo.read())

    thread = threading.Thread(target=read, daemon=True)
    thread.start()
    return thread


def test_a_fifo_is_written_into_never_replaced(tmp_path: Path) -> None:
    """A target that is no regular file is written into, as a shell's `>` does: a rename over
    it would leave a regular file where the FIFO (or, as root, /dev/null) was."""
    fifo = tmp_path / "out"
    os.mkfifo(fifo)
    got: list[bytes] = []
    reader = _read_fifo(fifo, got)
    assert write_atomic(fifo, b"G0 X1\n", overwrite=False) == fifo
    reader.join(10)
    assert got == [b"G0 X1\n"] and stat.S_ISFIFO(os.stat(fifo).st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]  # no temporary left


def test_convert_writes_into_a_device_it_is_given(tmp_path: Path) -> None:
    """`tapegate convert ... -o /dev/null --force` as root replaced /dev/null with a regular
    file (found when a later cargo read the junk written to it). A character device of our own
    (root only: mknod) stays a device, with or without --force, and takes the output."""
    from formats.convert import ConvertOptions, convert_file
    from formats.profile import load_profile

    null = tmp_path / "null"
    try:
        os.mknod(null, 0o666 | stat.S_IFCHR, os.makedev(1, 3))
    except PermissionError:
        pytest.skip("making a device needs root")
    source = tmp_path / "p.nc"
    source.write_text("%\nO1\nG21 G90\nG0 X10.\nM30\n%\n")
    fanuc = load_profile("fanuc-mill")
    for overwrite in (False, True):
        convert_file(str(source), str(null), ConvertOptions(fanuc, fanuc), overwrite=overwrite)
        assert stat.S_ISCHR(os.stat(null).st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["null", "p.nc"]
