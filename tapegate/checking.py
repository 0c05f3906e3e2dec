"""What ``tapegate check`` does, without click: :func:`run_check` is the command's body, which
click's command (:mod:`tapegate.check_cli`) and the one-file path of the entry point
(:mod:`tapegate.launch`) both call, so that the two cannot answer differently. A usage
problem found here is click's :class:`tapegate.options.UsageProblem` (imported when raised),
told by click in either case."""

from __future__ import annotations

import os
import sys
from typing import TYPE_CHECKING

from formats.errors import TapegateError
from formats.profile import load_profile
from postproc.rules import RULES, SEVERITY_RANK
from tapegate.common import (
    echo,
    error_exit,
    get_profile,
    plural,
    readable,
    shown,
    user_errors_exiting,
)

if TYPE_CHECKING:
    from postproc.check import CheckStats


def _usage(message: str) -> Exception:
    from tapegate.options import UsageProblem

    return UsageProblem(message)


def _ids(values: tuple[str, ...]) -> list[str]:
    ids = [v.strip().upper() for item in values for v in item.split(",") if v.strip()]
    for rule in ids:
        if not any(r.startswith(rule) for r in RULES):
            raise _usage(f"no rule {rule}; see docs/rules.md")
    return ids


@user_errors_exiting(2)
def run_check(files: tuple[str, ...], profile: str | None, fmt: str,
              select: tuple[str, ...], ignore: tuple[str, ...], fail_on: str,
              show_stats: bool, jobs: int | None) -> None:
    """The body of ``tapegate check``: click's command (:mod:`tapegate.check_cli`) and the
    one-file path that reads its arguments without click (:mod:`tapegate.launch`) both call
    it, with the same arguments click would pass. Exits (``sys.exit``) with the check's code."""
    from postproc import report
    from postproc.check import Checker, iter_check_file

    given = files
    # A folder stands for its files (tapegate.workers.input_files); one file that is no folder
    # is taken as it is named, without loading the workers' module
    if len(files) > 1 or any(name != "-" and os.path.isdir(name) for name in files):
        from tapegate.workers import input_files

        files = tuple(input_files(files))
    if not files:
        raise _usage(f"no file to check in {', '.join(given)}")
    parallel = len(files) > 1 and (jobs or _default_jobs()) > 1
    paths = {name: readable(name) for name in files}
    prof = load_profile(profile) if profile else get_profile(None, paths[files[0]])
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
    for name in () if parallel else files:
        try:
            if isinstance(writer, report.SarifReport):
                checker, found = iter_check_file(paths[name], prof, display=shown(name),
                                                 select=selected, ignore=ignored)
                for finding in found:
                    counts[finding.severity] += 1
                    writer.add(finding)
            else:  # text, JSON, JSON Lines: the core writes the findings as it finds them
                checker = Checker(prof, shown(name), select=selected, ignore=ignored,
                                  report=fmt)
                try:
                    checker.report_file(paths[name], writer.write)
                finally:  # what was written before an error is counted too
                    for severity, n in checker.counts.items():
                        counts[severity] += n
        except BrokenPipeError:  # the output closed: not a file that cannot be read
            raise
        except OSError as exc:
            echo(f"tapegate: cannot read {name}: {exc.strerror or exc}", err=True)
            unreadable += 1
            continue
        except TapegateError as exc:  # e.g. not an NC program at all
            echo(error_exit(exc.located(file=name), input_exit=2)[0], err=True)
            unreadable += 1
            continue
        stats[name] = checker.stats
    if parallel:  # the same, file by file in worker processes (tapegate.workers)
        from tapegate.workers import check_files

        items = [(paths[name], shown(name)) for name in files]
        for done, name in zip(check_files(items, prof, fmt=fmt, select=selected,
                                          ignore=ignored, jobs=jobs or _default_jobs(),
                                          writer=writer), files, strict=True):
            for severity, n in done.counts.items():
                counts[severity] += n
            if done.error:
                echo(done.error, err=True)
                unreadable += 1
            elif done.stats is not None:
                stats[name] = done.stats
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


def _default_jobs() -> int:
    from tapegate.workers import default_jobs

    return default_jobs()


def _check_exit_code(counts: dict[str, int], unreadable: bool, fail_on: str) -> int:
    if unreadable:
        return 2
    worst_found = max((SEVERITY_RANK[k] for k, n in counts.items() if n), default=-1)
    return 1 if worst_found >= SEVERITY_RANK[fail_on] else 0
