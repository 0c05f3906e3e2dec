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


def test_a_replaced_file_keeps_its_mode_owner_and_group(tmp_path: Path) -> None:
    """--force onto a 0640 program made it 0644 and the runner's (review 42, finding 5): the
    file that replaces a regular file takes its permission bits and, where the system allows
    it (root here, or the group of a member), its owner and group -- one commit's and a
    batch's alike; a new file next to it still follows the umask."""
    from formats import _core

    old = os.umask(0o022)
    try:
        for batch in (False, True):
            target = tmp_path / f"O{int(batch)}.nc"
            target.write_bytes(b"old\n")
            target.chmod(0o640)
            owner = (65534, 65534) if os.geteuid() == 0 else (os.getuid(), os.getgid())
            if os.geteuid() == 0:
                os.chown(target, *owner)
            pending = PendingFile(tmp_path, target.name)
            pending.write(b"N1 X1.\n")
            if batch:
                commits = _core.Commits(1)
                commits.wait(commits.submit(pending.hand_over(), pending.tmp, str(target),
                                            True))
                commits.close()
            else:
                pending.commit(target, overwrite=True)
            after = target.stat()
            assert target.read_bytes() == b"N1 X1.\n"
            assert oct(after.st_mode & 0o7777) == "0o640"
            assert (after.st_uid, after.st_gid) == owner
        new = write_atomic(tmp_path / "new.nc", b"N1\n", overwrite=True)
        assert oct(new.stat().st_mode & 0o777) == "0o644"
    finally:
        os.umask(old)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["O0.nc", "O1.nc", "new.nc"]


def test_a_symbolic_link_replaced_by_force_is_replaced_as_before(tmp_path: Path) -> None:
    """A symbolic link where the output goes is not followed by the commit: the rename puts the
    new file in the link's place (the file it led to untouched), made as a new file is (0666
    and the umask), not with the mode of the file the link led to. (A FIFO or a device there
    is written into: test_a_fifo_is_written_into_never_replaced.)"""
    led_to = tmp_path / "kept.nc"
    led_to.write_bytes(b"kept\n")
    led_to.chmod(0o600)
    link = tmp_path / "out.nc"
    link.symlink_to(led_to.name)
    old = os.umask(0o022)
    try:
        write_atomic(link, b"N1\n", overwrite=True)
    finally:
        os.umask(old)
    assert not link.is_symlink() and link.read_bytes() == b"N1\n"
    assert oct(link.stat().st_mode & 0o777) == "0o644"
    assert led_to.read_bytes() == b"kept\n" and oct(led_to.stat().st_mode & 0o777) == "0o600"


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


def test_a_version_name_is_the_first_free_one_and_a_broken_link_is_passed_over(
        tmp_path: Path) -> None:
    """The core names a file (formats._core.commit_file, the steps a batch's commit threads
    run): with a version name wanted, the first of NAME, STEM.1.EXT, STEM.2.EXT... a link can
    take, the stem and extension as pathlib reads them. A symbolic link that leads nowhere
    takes its name (os.path.exists said free, the link said taken: the loop before went round
    for ever)."""
    (tmp_path / "O1234.nc").write_bytes(b"0\n")
    (tmp_path / "O1234.1.nc").write_bytes(b"1\n")
    (tmp_path / "O1").symlink_to(tmp_path / "nowhere")
    (tmp_path / ".x").write_bytes(b"x\n")
    (tmp_path / "a.b.nc").write_bytes(b"ab\n")
    written = {name: write_atomic(tmp_path / name, name.encode(), overwrite=False).name
               for name in ("O1234.nc", "O1", ".x", "a.b.nc", "new.nc")}
    assert written == {"O1234.nc": "O1234.2.nc", "O1": "O1.1", ".x": ".x.1",
                       "a.b.nc": "a.b.1.nc", "new.nc": "new.nc"}
    assert (tmp_path / "O1234.2.nc").read_bytes() == b"O1234.nc"
    assert (tmp_path / "O1234.nc").read_bytes() == b"0\n" and os.path.islink(tmp_path / "O1")
    assert not [p for p in os.listdir(tmp_path) if p.endswith(".part")]
    # --force: replaced, the link itself too (not the file it names)
    assert write_atomic(tmp_path / "O1", b"forced\n").name == "O1"
    assert not os.path.islink(tmp_path / "O1") and (tmp_path / "O1").read_bytes() == b"forced\n"


def test_a_commit_that_cannot_name_the_file_says_why_and_leaves_nothing(tmp_path: Path) -> None:
    """A step of the core's commit that fails is an OSError of its own kind (here the target
    is a folder: a link to it is refused as the name is taken, a rename over it as a folder),
    and the temporary file is gone."""
    (tmp_path / "dir").mkdir()
    for overwrite in (False, True):
        pending = PendingFile(tmp_path, "dir")
        pending.write(b"N1\n")
        with pytest.raises(FileExistsError if not overwrite else IsADirectoryError):
            pending.name_as(tmp_path / "dir", overwrite=overwrite, version=False)
    assert sorted(os.listdir(tmp_path)) == ["dir"]


def test_the_temporary_files_left_are_removed_at_the_exit(tmp_path: Path) -> None:
    """A file made and never named nor discarded (a ^C between the two) is in the core's list
    of temporary files from the step that made it: formats.files.sweep (run at the exit)
    removes it, and no file named; a child forked from the process removes none of its
    parent's."""
    from formats.files import sweep

    sweep()  # (whatever earlier tests left in this process)
    kept = PendingFile(tmp_path, "kept.nc")
    kept.write(b"N1\n")
    kept.name_as(tmp_path / "kept.nc")
    left = PendingFile(tmp_path, "left.nc")
    left.write(b"N1\n")
    left.file.flush()
    child = os.fork()
    if child == 0:  # pragma: no cover (the child)
        os._exit(10 + sweep())
    _, status = os.waitpid(child, 0)
    assert os.WEXITSTATUS(status) == 10 and os.path.exists(left.tmp)
    assert sweep() == 1
    assert sorted(os.listdir(tmp_path)) == ["kept.nc"]
    assert sweep() == 0
    left.discard()  # (gone already: nothing to do, no error)


def test_a_process_that_exits_with_a_file_not_named_leaves_nothing(tmp_path: Path) -> None:
    """The interpreter's own exit (no tapegate.launch.leave: a script of the API, click's
    commands) removes the temporary files it never named: the core's exit function, run by
    the C library's exit after the interpreter's finalization."""
    import subprocess
    import sys

    code = ("import sys\nfrom formats.files import PendingFile\n"
            "p = PendingFile(sys.argv[1], 'O1.nc')\np.write(b'N1\\n')\np.file.flush()\n"
            "print(p.tmp)\n")
    done = subprocess.run([sys.executable, "-c", code, str(tmp_path)], capture_output=True,
                          text=True, timeout=60, check=False,
                          env={**os.environ, "PYTHONPATH": str(Path(__file__).parents[1])})
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().endswith(".part")  # (it was there)
    assert list(tmp_path.iterdir()) == []


NO_LINKS = """
#include <errno.h>
int link(const char *a, const char *b) { errno = EPERM; return -1; }
int linkat(int fa, const char *a, int fb, const char *b, int flags) { errno = EPERM; return -1; }
"""


def test_a_file_system_without_hard_links_still_gets_whole_files_never_replaced(
        tmp_path: Path) -> None:
    """Review 44, finding 6: FAT and exFAT (the USB stick a shop carries to the control) have
    no hard links, and Linux's link(2) gives EPERM there; the commit named every new file by a
    link alone, so each output failed. Where the link is refused so, the core renames without
    replacing (renameat2 RENAME_NOREPLACE): the same names, versions and refusals. Shown with
    the C library's link() and linkat() made to fail as on FAT (a preloaded library built
    here; skipped where no C compiler is installed)."""
    import shutil
    import subprocess
    import sys

    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None or sys.platform != "linux":
        pytest.skip("needs a C compiler on Linux to build the link-refusing library")
    (tmp_path / "nolink.c").write_text(NO_LINKS)
    shim = tmp_path / "nolink.so"
    subprocess.run([cc, "-shared", "-fPIC", "-o", str(shim), str(tmp_path / "nolink.c")],
                   check=True, timeout=60)
    out = tmp_path / "out"
    out.mkdir()
    (out / "kept.nc").write_bytes(b"old\n")
    script = (
        "import os, sys\n"
        "from formats.files import PendingFile, write_atomic\n"
        "out = sys.argv[1]\n"
        "try:\n"
        "    os.link(os.path.join(out, 'kept.nc'), os.path.join(out, 'probe'))\n"
        "    print('linked')\n"
        "except PermissionError:\n"
        "    print('no links')\n"
        "print(write_atomic(os.path.join(out, 'new.nc'), b'new\\n', overwrite=False).name)\n"
        "print(write_atomic(os.path.join(out, 'kept.nc'), b'v\\n', overwrite=False).name)\n"
        "p = PendingFile(out, 'kept.nc')\n"
        "p.write(b'x\\n')\n"
        "try:\n"
        "    p.name_as(os.path.join(out, 'kept.nc'), overwrite=False, version=False)\n"
        "except FileExistsError:\n"
        "    print('refused')\n"
        "print(write_atomic(os.path.join(out, 'kept.nc'), b'forced\\n').name)\n")
    root = Path(__file__).resolve().parent.parent
    run = subprocess.run([sys.executable, "-c", script, str(out)], capture_output=True,
                         text=True, timeout=60,
                         env={**os.environ, "PYTHONPATH": str(root), "LD_PRELOAD": str(shim)})
    assert run.returncode == 0, run.stderr
    assert run.stdout.split() == ["no", "links", "new.nc", "kept.1.nc", "refused", "kept.nc"]
    assert (out / "new.nc").read_bytes() == b"new\n"
    assert (out / "kept.1.nc").read_bytes() == b"v\n"
    assert (out / "kept.nc").read_bytes() == b"forced\n"
    assert sorted(p.name for p in out.iterdir()) == ["kept.1.nc", "kept.nc", "new.nc"]


def test_a_file_of_another_owner_replaced_is_never_wider(tmp_path: Path) -> None:
    """Review 45, finding H1, and review 47, F2: a user who may not give the file its old
    owner and group (not root) replaces it with a file of their own; its bits are never wider
    than the old file's (made as a new file, 0666 and the umask, a 0600 program became
    world-readable): the new group's bits no more than the others' (0640 becomes 0600; the
    old owner reads it only as others may). Shown with
    fchown() refused as for a user who is not root (a preloaded library built here: skipped
    where no C compiler is installed), the file another user's (uid and gid 1000)."""
    import shutil
    import subprocess
    import sys

    cc = shutil.which("cc") or shutil.which("gcc")
    if cc is None or sys.platform != "linux":
        pytest.skip("needs a C compiler on Linux to build the fchown-refusing library")
    (tmp_path / "nochown.c").write_text(
        "#include <errno.h>\n#include <sys/types.h>\n"
        "int fchown(int fd, uid_t u, gid_t g) { errno = EPERM; return -1; }\n")
    shim = tmp_path / "nochown.so"
    subprocess.run([cc, "-shared", "-fPIC", "-o", str(shim), str(tmp_path / "nochown.c")],
                   check=True, timeout=60)
    out = tmp_path / "out"
    out.mkdir()
    theirs, mine = out / "theirs.nc", out / "mine.nc"
    for target in (theirs, mine):
        target.write_bytes(b"old\n")
        target.chmod(0o640)
    if os.geteuid() == 0:
        os.chown(theirs, 1000, 1000)
    script = ("import os, sys\n"
              "os.umask(0o022)\n"
              "from formats.files import write_atomic\n"
              "for name in sys.argv[1:]:\n"
              "    write_atomic(name, b'new\\n')\n")
    root = Path(__file__).resolve().parent.parent
    run = subprocess.run([sys.executable, "-c", script, str(theirs), str(mine)],
                         capture_output=True, text=True, timeout=60,
                         env={**os.environ, "PYTHONPATH": str(root), "LD_PRELOAD": str(shim)})
    assert run.returncode == 0, run.stderr
    assert theirs.read_bytes() == mine.read_bytes() == b"new\n"
    if os.geteuid() == 0:  # (the owner and group could not be kept: never wider, review 47)
        assert (theirs.stat().st_uid, theirs.stat().st_gid) == (0, 0)
        assert oct(theirs.stat().st_mode & 0o777) == "0o600"
    # the runner's own file keeps its bits
    assert oct(mine.stat().st_mode & 0o777) == "0o640"
