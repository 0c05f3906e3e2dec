"""What ``tapegate check`` does, without click: :func:`run_check` is the command's body, which
click's command (:mod:`tapegate.check_cli`) and the one-file path of the entry point
(:mod:`tapegate.launch`) both call, so that the two cannot answer differently. A usage
problem found here is click's :class:`tapegate.options.UsageProblem` (imported when raised),
told by click in either case."""

from __future__ import annotations

import os
import sys

from formats.errors import TapegateError
from postproc import rules
from postproc.rules import SEVERITY_RANK
from tapegate.common import (
    echo,
    error_exit,
    get_profile,
    plural,
    readable_sized,
    shown,
    usage,
    user_errors_exiting,
)
from tapegate.launch import resume_collector

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Callable, Iterator
    from typing import Any

    from formats.profile import Profile
    from formats.profile_cache import Compiled
    from postproc.check import CheckStats
    from postproc.findings import Finding
    from postproc.report import SarifReport



def _ids(values: tuple[str, ...]) -> list[str]:
    ids = [v.strip().upper() for item in values for v in item.split(",") if v.strip()]
    for rule in ids:
        if not any(r.startswith(rule) for r in rules.RULES):
            raise usage(f"no rule {rule}; see docs/rules.md")
    return ids


@user_errors_exiting(2)
def run_check(files: tuple[str, ...], profile: str | None, fmt: str,
              select: tuple[str, ...], ignore: tuple[str, ...], fail_on: str,
              show_stats: bool, jobs: int | None, units: str | None = None,
              show_all: bool = False) -> None:
    """The body of ``tapegate check``: click's command (:mod:`tapegate.check_cli`) and the
    one-file path that reads its arguments without click (:mod:`tapegate.launch`) both call
    it, with the same arguments click would pass. Exits (``sys.exit``) with the check's code.
    The text report folds each rule's warnings and notes past the first five of a file into
    one line (the core's ``report::Writer::folded``) unless ``show_all`` (``--all``)."""
    from postproc import report

    given = files
    # A folder stands for its files (tapegate.workers.input_files); one file that is no folder
    # is taken as it is named, without loading the workers' module
    if len(files) > 1 or any(name != "-" and os.path.isdir(name) for name in files):
        from tapegate.workers import input_files

        files = tuple(input_files(files))
    if not files:
        raise usage(f"no file to check in {', '.join(given)}")
    parallel = len(files) > 1 and (jobs or _default_jobs()) > 1
    # a file's path, or why it is not read (a FIFO with no writer, a device: never opened),
    # told at its turn as a file that cannot be read
    paths: dict[str, str | OSError] = {}
    sizes: dict[str, int] = {}  # (-j's weights: tapegate.workers.first)
    for name in files:
        try:
            paths[name], sizes[name] = readable_sized(name)
        except OSError as exc:
            paths[name] = exc
    head = paths[files[0]]
    prof = _profile(profile, head if isinstance(head, str) else None,
                    quick=units is None and fmt != "sarif")
    if units is not None:  # the units the machine is set to at the start (--units)
        from formats.profile import with_start_units

        prof = with_start_units(prof, units)  # type: ignore[arg-type]  # (not quick: a Profile)
    selected, ignored = _ids(select), _ids(ignore)
    # Every format streams: a finding is written as it is found and only counted (for the
    # summary and the exit code), so memory does not grow with the number of findings.
    counts = dict.fromkeys(SEVERITY_RANK, 0)
    stats: dict[str, CheckStats] = {}
    out = sys.stdout
    writer = (report.JsonReport(out) if fmt == "json" else
              report.JsonLinesReport(out) if fmt == "jsonl" else
              report.SarifReport(out) if fmt == "sarif" else report.TextReport(out))
    unreadable = 0  # a file that cannot be read is told, and the others are checked
    receive: Callable[[Any], object] = (_adding(writer) if isinstance(writer, report.SarifReport)
                                        else writer.write)
    items = [(paths[name], shown(name)) for name in files]
    raw = writer.raw  # the core's slices as bytes, for a report written to a binary buffer
    fold = fmt == "text" and not show_all  # a rule repeated in a file told once past five
    resume_collector()  # (the entry point's start-up without the collector ends here)
    if parallel:  # the files in threads (tapegate.workers), the report written here in order
        from tapegate.workers import ordered_map, send

        # the long files first (SARIF's pieces, lists of findings, are not spilled: in order)
        weights = None if fmt == "sarif" else [sizes.get(name, 0) for name in files]
        done: Iterator[tuple[dict[str, int], CheckStats | None, str | None]] = ordered_map(
            lambda item: _check_one(item, prof, fmt, selected, ignored, send, show_stats, raw,
                                    fold),
            items,
            jobs or _default_jobs(), receive=receive, sizes=weights)
    else:
        done = (_check_one(item, prof, fmt, selected, ignored, receive, show_stats, raw, fold)
                for item in items)
    for name, (found, file_stats, error) in zip(files, done, strict=True):
        for severity, n in found.items():
            counts[severity] += n
        if error is not None:
            echo(error, err=True)
            unreadable += 1
        elif file_stats is not None:
            stats[name] = file_stats
    if isinstance(writer, report.JsonReport | report.JsonLinesReport):
        writer.close(stats if show_stats else None)
    elif isinstance(writer, report.SarifReport):
        writer.close()
    else:
        if show_stats:
            for name, s in stats.items():
                echo(report.stats_text(name, s), nl=False)
        writer.close()
        checked = plural(len(files) - unreadable, "file")
        not_read = f" ({unreadable} not read)" if unreadable else ""
        echo(f"{checked} checked{not_read}: {plural(counts['error'], 'error')}, "
                   f"{plural(counts['warning'], 'warning')}, "
                   f"{plural(counts['info'], 'note')}", err=True)
    sys.exit(_check_exit_code(counts, bool(unreadable), fail_on))


def _profile(name: str | None, head: str | None, quick: bool) -> Profile | Compiled:
    """The profile ``--profile`` names, or without it the neutral one adjusted to the first
    file (``head``). ``quick`` (a check that takes only the profile's machine and flags: not
    SARIF's findings, no ``--units``): a built-in profile read back as the cache keeps it for a
    check (:func:`formats.profile_cache.load_compiled`), without ``formats.profile``'s modules
    and the profile's validation, where it keeps one; where not, the profile is loaded, and
    kept so for the next check (:func:`formats.machine.keep_compiled`)."""
    if not name:
        return get_profile(None, head)
    if not quick:
        return get_profile(name)
    from formats.profile_cache import load_compiled

    compiled = load_compiled(name, lambda: get_profile(name))
    if compiled is not None:
        return compiled
    from formats.machine import keep_compiled

    prof = get_profile(name)
    keep_compiled(name, prof)
    return prof


def _check_one(item: tuple[str | OSError, str], prof: Profile | Compiled, fmt: str,
               select: list[str], ignore: list[str], send: Callable[[Any], object],
               show_stats: bool, raw: bool = False, fold: bool = False
               ) -> tuple[dict[str, int], CheckStats | None, str | None]:
    """Check one file (path, name as reported), its findings handed to ``send`` as the
    report's ``write`` takes them (text, JSON, JSON Lines: the core's slices) or, for SARIF,
    in lists of findings for the report's ``add``: (the findings by severity, the statistics,
    the message of the error that stopped it). The same for one file and for ``-j``'s
    threads, which hand ``send``'s pieces to the main thread; ``raw``: the core's pieces as
    bytes (the report's :attr:`~postproc.report.JsonReport.raw`); ``fold``: the text report's
    repeated warnings and notes folded (:class:`postproc.check.Checker`). The statistics are
    kept only for ``show_stats`` (``--stats``; else None): working them out costs every
    move."""
    from postproc.check import Checker, iter_check_file

    path, name = item
    counts = dict.fromkeys(SEVERITY_RANK, 0)
    if not isinstance(path, str):  # refused unread (run_check)
        return counts, None, f"tapegate: cannot read {name}: {path.strerror or path}"
    try:
        if fmt == "sarif":
            checker, found = iter_check_file(path, prof,  # type: ignore[arg-type]  # (a Profile)
                                             display=name, select=select,
                                             ignore=ignore, stats=show_stats)
            batch: list[Finding] = []
            try:
                for finding in found:
                    counts[finding.severity] += 1
                    batch.append(finding)
                    if len(batch) == _SARIF_BATCH:
                        send(batch)
                        batch = []
            finally:  # the findings before an error are reported too
                if batch:
                    send(batch)
        else:  # text, JSON, JSON Lines: the core writes the findings as it finds them
            checker = Checker(prof, name, select=select, ignore=ignore, report=fmt,
                              stats=show_stats, fold=fold)
            try:
                checker.report_file(path, send, raw)
            finally:  # what was written before an error is counted too
                counts.update(checker.counts)
    except BrokenPipeError:  # the output closed: not a file that cannot be read
        raise
    except OSError as exc:
        return counts, None, f"tapegate: cannot read {name}: {exc.strerror or exc}"
    except TapegateError as exc:  # e.g. not an NC program at all
        return counts, None, error_exit(exc.located(file=name), input_exit=2)[0]
    return counts, checker.stats if show_stats else None, None


_SARIF_BATCH = 4096  # findings handed over at a time for the SARIF report


def _adding(writer: SarifReport) -> Callable[[list[Finding]], None]:
    """The SARIF report's ``receive``: each finding of a list added (its rules are numbered
    in the order they first appear, so in the main thread, in the files' order)."""
    add = writer.add

    def receive(batch: list[Finding]) -> None:
        for finding in batch:
            add(finding)

    return receive


def _default_jobs() -> int:
    from tapegate.workers import default_jobs

    return default_jobs()


def _check_exit_code(counts: dict[str, int], unreadable: bool, fail_on: str) -> int:
    if unreadable:
        return 2
    worst_found = max((SEVERITY_RANK[k] for k, n in counts.items() if n), default=-1)
    return 1 if worst_found >= SEVERITY_RANK[fail_on] else 0
