"""What ``tapegate convert`` does, without click: :func:`run_convert` is the command's body,
which click's command (:mod:`tapegate.convert_cli`) and the entry point's own reading of a
plain ``convert`` (:mod:`tapegate.launch`) both call, so that the two cannot answer
differently. A usage problem found here is click's :class:`tapegate.options.UsageProblem`
(imported when raised), told by click in either case."""

from __future__ import annotations

import os
import sys

from formats.errors import OutputError, TapegateError
from formats.files import is_special
from formats.profile import load_profile
from formats.wordformat import Rounding, Zeros
from tapegate.common import (
    echo,
    input_path,
    readable,
    table,
    usage,
    user_errors,
    write_stream,
)

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Callable, Sequence
    from typing import Any

    from formats.convert import ConvertOptions, ConvertStats, Handover



@user_errors
def run_convert(inputs: tuple[str, ...], output: str | None, out_dir: str | None,
                to_profile: str, from_profile: str | None, from_decimal: str | None,
                from_zeros: str | None, from_units: str | None, decimal: str | None,
                zeros: str | None, units: str | None, eob: str | None, spacing: str, rounding: str,
                allow_unconverted: bool, jobs: int | None, verify: bool, dry_run: bool,
                force: bool, fmt: str = "text") -> None:
    """The body of ``tapegate convert``: click's command (:mod:`tapegate.convert_cli`) and the
    entry point's plain reading (:mod:`tapegate.launch`) both call it, with the same arguments
    click would pass. Exits 1 (``sys.exit``) when a file failed."""
    from formats.convert import ConvertOptions  # (only this command needs the converter)
    from formats.files import exit_on_termination

    exit_on_termination()

    names: dict[str, str] = {}
    if "-" in inputs:
        if len(inputs) != 1:
            raise usage("- (standard input) is the only input when it is given")
        inputs = (readable("-"),)
        names[inputs[0]] = "<stdin>"
    to_stdout = output == "-"
    spill = SpillFolder()  # a long file's notes wait there
    made: str | None = None  # (-o -: the folder the program is written in first)
    try:
        if to_stdout:
            import tempfile

            made = tempfile.mkdtemp(prefix="tapegate-")
            output = os.path.join(made, "out.nc")
        if out_dir and not dry_run:  # a file where the folder (or one above it) would be
            there = _existing(out_dir)
            if there is not None and not os.path.isdir(there):
                raise OutputError(f"cannot write {out_dir}: {there} is not a folder")
        jobs_list = batch_jobs(inputs, output, out_dir, dry_run, names)
        options = ConvertOptions(
            target=load_profile(to_profile),
            source=load_profile(from_profile) if from_profile else None,
            decimal=decimal, zeros=Zeros(zeros) if zeros else None, units=units, eob=eob,
            rounding=Rounding(rounding), spacing=spacing, allow_unconverted=allow_unconverted,
            from_decimal=from_decimal, from_zeros=Zeros(from_zeros) if from_zeros else None,
            from_units=from_units)
        from tapegate.launch import resume_collector
        from tapegate.workers import default_jobs

        resume_collector()  # (the entry point's start-up without the collector ends here)
        results = run_batch(jobs_list, options, jobs=jobs or default_jobs(), overwrite=force,
                            verify=verify, names=names, make_folders=out_dir is not None,
                            spill=spill)
        _report(results, output, to_stdout, dry_run, fmt)
    finally:
        spill.remove()
        if made is not None:
            # (-o -: the folder the program was written in before it went to stdout, with
            # what is left in it where ^C, SIGTERM or an error stopped the command before or
            # while it was copied; review 44, finding 4)
            import shutil

            shutil.rmtree(made, ignore_errors=True)


def _existing(name: str) -> str | None:
    """The first of ``name`` and the folders above it that exists (``Path(name)`` and its
    ``parents``), written as pathlib writes it; None if none does."""
    from formats.files import parent, pure

    path = pure(name)
    while not os.path.exists(path):
        up = parent(path)
        if up == path:
            return None
        path = up
    return path


class SpillFolder:
    """The temporary folder where the notes of a file beyond its first thousand wait until the
    summary prints them (formats.conversion.ConvertStats), made when a file first needs it:
    most batches need none, and ``tempfile``'s import (with ``shutil``, ``random``, ``bz2``,
    ``lzma``) and a folder made and removed were part of every conversion's start-up, which
    its threads cannot share (docs/benchmarks.md, "the serial ends of `-j 2`"). Called by the
    threads of ``-j``: made once, under a lock."""

    def __init__(self) -> None:
        import _thread  # (threading's import, 4M instructions, is for nothing here)

        self.path: str | None = None
        self._lock = _thread.allocate_lock()

    def __call__(self) -> str:
        with self._lock:
            if self.path is None:
                import tempfile

                self.path = tempfile.mkdtemp(prefix="tapegate-notes-")
            return self.path

    def remove(self) -> None:
        """The folder and what is left in it (the notes of a batch stopped before its
        summary), if it was made."""
        if self.path is not None:
            import shutil

            shutil.rmtree(self.path, ignore_errors=True)


def _report(results: list[ConvertStats], output: str | None, to_stdout: bool,
            dry_run: bool, fmt: str = "text") -> None:
    """The converted program on stdout (``-o -``), each file's error and notes, the summary
    (a table, or with ``fmt`` "json" one JSON document); exit 1 if a file failed."""
    if to_stdout and output is not None:
        if os.path.exists(output):
            from formats.parser import read_chunks

            write_stream("-", read_chunks(output))
            os.unlink(output)
        os.rmdir(os.path.dirname(output))
    rows = []
    failed = 0
    told = False  # (a spill of notes that failed: told once, before the first notes held)
    for stats in results:
        letter, worst = stats.largest_rounding_text()
        if stats.error:
            failed += 1
            echo(stats.error, err=True)
        if stats.notes_unspilled and not told:
            told = True
            echo(f"tapegate: {stats.notes_unspilled}", err=True)
        for note in stats.notes:
            echo(f"{stats.file}: {note}", err=True)
        # the notes after the first thousand, as they are printed: spilled, or held in memory
        # where the spill failed
        for piece in stats.notes_after():
            echo(piece, err=True, nl=False)
        rows.append((stats.file, str(stats.blocks), str(stats.changed),
                     f"{letter} {worst}" if letter else "0", result_of(stats)))
    total_blocks = sum(s.blocks for s in results)
    total_changed = sum(s.changed for s in results)
    if fmt == "json":
        echo(summary_json(results, dry_run), err=to_stdout)
        if failed:
            sys.exit(1)
        return
    if len(rows) > 1 or failed or not sys.stdout.isatty():
        files = f"{len(results)} file{'' if len(results) == 1 else 's'}"
        rows.append((f"total: {files}", str(total_blocks), str(total_changed), "",
                     f"{failed} failed"))
    echo(table(("file", "blocks", "words changed", "largest rounding", "result"), rows),
               err=to_stdout)
    if dry_run:
        echo("dry run: nothing written", err=to_stdout)
    if failed:
        sys.exit(1)


def result_of(stats: ConvertStats) -> str:
    """The summary's result for one file. The proof's verdict comes from its counts alone
    (the statements it could not read, the words the core left as written where the units
    change), never from the notes' wording."""
    unread = len(stats.not_compared) if stats.proved else 0
    left = stats.left_as_written if stats.proved else 0
    statements = stats.left_statements if left else 0
    words = left - statements
    kept = " and ".join(
        ([f"{words} word{'s' if words > 1 else ''}"] if words else [])
        + ([f"{statements} statement{'s' if statements > 1 else ''}"] if statements else []))
    partly = "; ".join(
        ([f"{unread} statement{'s' if unread > 1 else ''} not compared"] if unread else [])
        + ([f"{kept} left as written"] if left else []))
    return ("FAILED" if stats.error else
            f"partly verified: {partly}" if partly else
            f"verified ({stats.verified_assuming} assumed)" if stats.verified_assuming
            else "verified" if stats.verified else "ok")


def summary_json(results: list[ConvertStats], dry_run: bool) -> str:
    """``convert --format json``: the summary table's facts, and the counts the verdict is
    decided from, as one JSON document (docs/convert.md, "The summary as JSON")."""
    import json

    def place(at: tuple[int, int] | None) -> dict[str, int] | None:
        return None if at is None else {"line": at[0], "column": at[1]}

    files = []
    for stats in results:
        letter, worst = stats.largest_rounding_text()
        files.append({
            "file": stats.file, "output": stats.output or None, "blocks": stats.blocks,
            "words_changed": stats.changed,
            "largest_rounding": {"address": letter, "error": str(worst)} if letter else None,
            "result": result_of(stats), "error": stats.error or None,
            # None where --verify was not given
            "verified": stats.verified if stats.proved and not stats.error else None,
            "verified_assuming": stats.verified_assuming or None,
            "not_compared": [{"line": line, "text": text} for line, text in stats.not_compared],
            "left_as_written": {"count": stats.left_as_written,
                                "statements": stats.left_statements,
                                "first": place(stats.left_at)},
            "never_read": {"count": stats.never_read, "first": place(stats.never_read_at)},
        })
    return json.dumps({"files": files, "total": {
        "files": len(results), "blocks": sum(s.blocks for s in results),
        "words_changed": sum(s.changed for s in results),
        "failed": sum(1 for s in results if s.error)}, "dry_run": dry_run}, indent=2)


def batch_jobs(inputs: Sequence[str], output: str | None, out_dir: str | None,
               dry_run: bool, names: dict[str, str] | None = None
               ) -> list[tuple[str, str | None]]:
    """(input file, output file or None) for every file named by the inputs. The paths are
    written as ``pathlib`` writes them (:func:`formats.files.pure`), without its objects
    (a tenth of a 200-file batch's serial start-up went to them). An input named that is a
    pipe with a writer (``<(cmd)``) is read from a copy (:func:`tapegate.common.input_path`;
    its name in ``names``, the copy's path its job's); a FIFO no program writes, a device or
    a socket is refused with an ``OSError`` before anything is read (a folder's listing has
    none of them: only files and links are listed)."""
    from formats.files import joined, pure
    from tapegate.workers import folder_files

    files: list[tuple[str, str]] = []  # (file, path relative to the output folder)
    streams: dict[str, str] = {}  # a pipe named: the copy it is read from
    for name in inputs:
        if os.path.isdir(name or "."):  # ("": pathlib's ".")
            files.extend(folder_files(name))
        elif os.path.exists(name):
            path = pure(name)
            files.append((path, os.path.basename(path)))
            if is_special(path):  # a pipe given by its name: copied, as - is; else refused
                streams[path] = input_path(path)
                if names is not None:
                    names[streams[path]] = path
        else:  # a pattern (a shell that does not expand them): glob only here
            import glob
            from pathlib import Path

            matches = sorted(Path(m) for m in glob.glob(name, recursive=True))
            matches = [m for m in matches if m.is_file()]
            if not matches:
                raise usage(f"no such file or directory: {name}")
            files.extend((str(m), m.name) for m in matches)
    if output and (len(files) != 1 or os.path.isdir(inputs[0] or ".")):
        raise usage("-o names one output file; use --out-dir for several inputs")
    if output and out_dir:
        raise usage("give -o or --out-dir, not both")
    if not (output or out_dir or dry_run):
        raise usage("say where to write: -o FILE, --out-dir DIR, or --dry-run")
    jobs: list[tuple[str, str | None]] = []
    seen: set[str] = set()
    folder = pure(out_dir or ".")
    real: dict[str, str] = {}
    for path, relative in files:
        target = None if dry_run else pure(output) if output else joined(folder, relative)
        if target is not None:
            if _real(target, real) == _real(path, real):
                raise usage(f"{path}: the output would replace the input")
            if target in seen:
                raise usage(f"two inputs would both be written to {target}")
            seen.add(target)
        jobs.append((streams.get(path, path), target))
    return jobs


def _real(path: str, folders: dict[str, str]) -> str:
    """``os.path.realpath(path)`` (what ``Path.resolve`` compares), each folder resolved once
    in ``folders``: the real path of a name is its folder's joined with it, unless the name
    is itself a symbolic link."""
    folder, name = os.path.split(path)
    if name in ("", ".", ".."):
        return os.path.realpath(path)
    parent = folders.get(folder)
    if parent is None:
        parent = folders[folder] = os.path.realpath(folder or ".")
    full = os.path.join(parent, name)
    return os.path.realpath(full) if os.path.islink(full) else full


def _convert_one(job: tuple[str, str | None, str], options: ConvertOptions, overwrite: bool,
                 verify: bool, make_folder: bool, spill: str | Callable[[], str] | None,
                 commits: Commits | None = None) -> tuple[ConvertStats, Commit | None]:
    """(the file's statistics, its output's fsync and rename handed to ``commits``, or None
    when they were done here, when nothing is written or when the conversion failed)."""
    from formats.convert import convert_file

    path, output, name = job
    handed: list[Commit] = []
    try:
        # the folders are fsync'd once for the batch (run_batch), not once per file
        stats = convert_file(path, output, options, overwrite=overwrite, verify=verify,
                             display=name, make_folder=make_folder, sync_folder=False,
                             notes_spill=spill,
                             commit=None if commits is None else
                             lambda handover: handed.append(commits.submit(handover)))
    except (TapegateError, OSError) as exc:
        return _failed(name, output, exc), None
    return stats, handed[0] if handed else None


def _failed(name: str, output: str | None, exc: BaseException) -> ConvertStats:
    """The statistics of a file whose conversion or commit raised ``exc``: its error alone
    (what is not a user's error, or a file's, is raised)."""
    from formats.convert import ConvertStats

    if isinstance(exc, TapegateError):
        return ConvertStats(file=name, output=output or "", error=str(exc.located(file=name)))
    if isinstance(exc, OSError):
        import errno

        reason = exc.strerror or str(exc)
        # (the errors of a write that finds no room: a full disk, a quota, a file size limit)
        if exc.filename is None and exc.errno in (errno.ENOSPC, errno.EDQUOT, errno.EFBIG):
            # (no read fails so: the output's write or its fsync, told as the output's, not
            # as the input's "FILE: No space left on device")
            if output:
                reason = f"cannot write {output}: {reason}"
            else:
                import tempfile

                reason = (f"cannot write its dry run's output to the temporary folder "
                          f"{tempfile.gettempdir()}: {reason}")
        return ConvertStats(file=name, output=output or "", error=f"{name}: {reason}")
    raise exc


class Commit:
    """One output's commit (its fsync and its name), handed to :class:`Commits`: :meth:`wait`
    gives what it raised, None once the output has its name."""

    __slots__ = ("_commits", "_ticket", "_refused", "error")

    def __init__(self, commits: Any, ticket: int, refused: Callable[[], BaseException],
                 error: BaseException | None = None) -> None:
        self._commits = commits  # the core's Commits, None once waited for (or done here)
        self._ticket = ticket
        self._refused = refused
        self.error = error

    def done(self) -> bool:
        return self._commits is None or bool(self._commits.done(self._ticket))

    def wait(self) -> BaseException | None:
        commits, self._commits = self._commits, None
        if commits is not None:
            try:
                commits.wait(self._ticket)
            except FileExistsError:  # the name taken meanwhile (no --force)
                self.error = self._refused()
            except OSError as exc:
                self.error = exc
        return self.error


class Commits:
    """The commits of a batch's outputs, run by up to ``threads`` threads of the core
    (``formats._core.Commits``) in the order they are handed over, with the GIL released: the
    fsync of the temporary file's data, then its name by a rename (``--force``) or a link
    that never replaces a file, the temporary file removed if a step fails -- the steps of
    ``formats.files.PendingFile.commit`` for a regular file. A worker that did its own fsync
    left its core idle for the disk's 2-4 ms a file, a third of a short file's time with one
    worker (docs/benchmarks.md, "the conversion's fsync"); here the next file is converted
    meanwhile, and several outputs' fsyncs in flight at once are written by the file system
    together. The threads never take the GIL: Python threads did, five times a commit, woken
    by the disk while the workers wanted it (docs/benchmarks.md, "the commits without the
    GIL"). A target that is not a regular file (a device, a FIFO) is written into by the
    worker (:meth:`PendingFile.commit`). :meth:`close` runs every commit handed over before
    it returns (a file converted is written, as when each worker wrote its own)."""

    def __init__(self, threads: int) -> None:
        from formats import _core

        self.threads = max(1, threads)
        self._core = _core.Commits(self.threads)

    def submit(self, handover: Handover) -> Commit:
        """``handover``'s output committed by the threads; a device or a FIFO written into
        here, by ``handover.finish``."""
        if is_special(handover.target):
            try:
                handover.finish()
            except (TapegateError, OSError) as exc:
                return Commit(None, 0, handover.refused, exc)
            return Commit(None, 0, handover.refused)
        pending = handover.pending
        ticket = self._core.submit(pending.hand_over(), pending.tmp, str(handover.target),
                                   handover.overwrite)
        return Commit(self._core, ticket, handover.refused)

    def close(self) -> None:
        """Every commit handed over run, the threads ended."""
        self._core.close()


# The outputs converted whose commit has not been waited for, at most, before the main thread
# waits for the oldest: a few a commit thread, so that the threads always have the next.
HELD = 4


def run_batch(jobs_list: list[tuple[str, str | None]], options: ConvertOptions, *, jobs: int,
              overwrite: bool, verify: bool, names: dict[str, str] | None = None,
              make_folders: bool = False,
              spill: str | Callable[[], str] | None = None) -> list[ConvertStats]:
    """Convert every file (in ``jobs`` threads), with a progress bar on a terminal;
    ``make_folders`` creates the output folders (the layout under --out-dir); a folder that
    ``-o`` names must exist, as for every command. Each output is fsync'd before its rename
    (by :class:`Commits`, while the next files are converted; a file's result is taken once
    its output has its name), and each output folder once when the batch is done (the names
    on disk). ``spill``: a folder where a file's notes beyond the first thousand wait, or a
    function that gives it (:class:`SpillFolder`; see ConvertStats)."""
    names = names or {}
    from formats.convert import sync_folders
    from tapegate.workers import file_sizes, ordered_map

    work = [(path, out, names.get(path, path)) for path, out in jobs_list]
    if len(work) == 1:  # one file: no progress bar, no thread, nothing more to start
        results = [_convert_one(work[0], options, overwrite, verify, make_folders, spill)[0]]
    else:
        # as many commits in flight as workers, and two at least, so that -j 1 too converts
        # while an output is written
        commits = Commits(max(2, jobs))

        def one(job: tuple[str, str | None, str]) -> tuple[ConvertStats, Commit | None]:
            return _convert_one(job, options, overwrite, verify, make_folders, spill, commits)

        bar = None
        if sys.stderr.isatty():  # (tqdm is imported only to show: 18 ms before the threads)
            from tqdm import tqdm

            bar = tqdm(total=len(work), unit="file", file=sys.stderr)
        results = []
        # (a list: it holds HELD * threads + 1 at most, and collections is not imported for
        # a deque; docs/benchmarks.md, perf40)
        waiting: list[tuple[ConvertStats, Commit | None]] = []

        def settle() -> None:
            stats, commit = waiting.pop(0)
            error = commit.wait() if commit is not None else None
            if error is not None:
                stats.drop_notes()
                stats = _failed(stats.file, stats.output, error)
            results.append(stats)
            if bar is not None:
                bar.update()

        # in order, the long files started first
        done = ordered_map(one, work, jobs, sizes=file_sizes(p for p, _, _ in work))
        try:
            for converted in done:
                waiting.append(converted)
                while waiting and (len(waiting) > HELD * commits.threads
                                   or waiting[0][1] is None or waiting[0][1].done()):
                    settle()
            while waiting:
                settle()
        finally:
            done.close()  # (its threads stopped: no commit is handed over after this)
            commits.close()
            if bar is not None:
                bar.close()
    sync_folders(s.output for s in results if s.output and not s.error)
    return results
