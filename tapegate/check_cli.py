"""``tapegate check`` and ``tapegate plot``: findings against a machine profile, and the tool
path drawn with them."""

from __future__ import annotations

import os
import sys
from typing import TYPE_CHECKING

import click

from formats.errors import OutputError, TapegateError
from formats.profile import load_profile
from postproc.rules import READING_RULES, RULES, SEVERITY_RANK
from tapegate.common import (
    UsageProblem,
    error_exit,
    get_profile,
    plural,
    profile_option,
    readable,
    shown,
    shown_output,
    user_errors,
    user_errors_exiting,
)

if TYPE_CHECKING:
    from postproc.check import CheckStats


def _ids(values: tuple[str, ...]) -> list[str]:
    ids = [v.strip().upper() for item in values for v in item.split(",") if v.strip()]
    for rule in ids:
        if not any(r.startswith(rule) for r in RULES):
            raise UsageProblem(f"no rule {rule}; see docs/rules.md")
    return ids


@click.command(short_help="Check programs against a machine profile.")
@click.argument("files", nargs=-1, required=True, type=click.Path())
@profile_option()
@click.option("--format", "fmt", type=click.Choice(["text", "json", "jsonl", "sarif"]),
              default="text", show_default=True,
              help="jsonl: JSON Lines, one finding per line.")
@click.option("--select", multiple=True, help="Only these rule IDs or prefixes (TG4,TG601).")
@click.option("--ignore", multiple=True, help="Skip these rule IDs or prefixes.")
@click.option("--fail-on", type=click.Choice(["error", "warning"]), default="error",
              show_default=True, help="Exit 1 on findings of this severity or worse.")
@click.option("--stats", "show_stats", is_flag=True,
              help="Bounding box, path lengths, cycle time, tools.")
@click.option("--jobs", "-j", type=click.IntRange(1), default=None,
              help="Files checked in parallel (default: the CPU count).")
@user_errors_exiting(2)
def check(files: tuple[str, ...], profile: str | None, fmt: str, select: tuple[str, ...],
          ignore: tuple[str, ...], fail_on: str, show_stats: bool, jobs: int | None) -> None:
    """Check programs (text or ISO/EIA tape images; a folder: every file in it) against a
    machine profile."""
    from postproc import report
    from postproc.check import Checker, iter_check_file

    given = files
    # A folder stands for its files (tapegate.workers.input_files); one file that is no folder
    # is taken as it is named, without loading the workers' module
    if len(files) > 1 or any(name != "-" and os.path.isdir(name) for name in files):
        from tapegate.workers import input_files

        files = tuple(input_files(files))
    if not files:
        raise UsageProblem(f"no file to check in {', '.join(given)}")
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
            click.echo(f"tapegate: cannot read {name}: {exc.strerror or exc}", err=True)
            unreadable += 1
            continue
        except TapegateError as exc:  # e.g. not an NC program at all
            click.echo(error_exit(exc.located(file=name), input_exit=2)[0], err=True)
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
                click.echo(done.error, err=True)
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
                click.echo(report.stats_text(name, s), nl=False)
        writer.close()
        checked = plural(len(files) - unreadable, "file")
        not_read = f" ({unreadable} not read)" if unreadable else ""
        click.echo(f"{checked} checked{not_read}: {plural(counts['error'], 'error')}, "
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



@click.command(short_help="Draw the tool path, with the findings marked.")
@click.argument("file", type=click.Path(dir_okay=False))
@profile_option()
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False),
              help="Image file: .svg or .png.")
@click.option("--view", type=click.Choice(["xy", "xz", "yz", "iso"]), default=None,
              help="The plane drawn  [default: xy; xz on a lathe, Z across and X up]")
@click.option("--findings/--no-findings", default=True, show_default=True,
              help="Mark the findings (one marker set and legend entry per rule).")
@user_errors
def plot(file: str, profile: str | None, output: str, view: str | None,
         findings: bool) -> None:
    """Draw the tool path: rapids dashed, feeds solid, true arcs, findings marked."""
    from pathlib import Path

    if Path(output).suffix.lower() not in (".svg", ".png"):
        raise UsageProblem("the output must end in .svg or .png")
    folder = Path(output).resolve().parent
    if not folder.is_dir():  # one rule: a missing folder is no output
        raise OutputError(f"cannot write {output}: "
                          + (f"{folder} is not a folder" if folder.exists() else "no such folder"))
    try:
        from postproc.plot import backplot_file, default_view
        from postproc.plot import plot as draw
    except ImportError:
        raise UsageProblem("plot needs matplotlib, the optional 'plot' extra: "
                           "pip install 'tapegate[plot]'") from None

    prof = load_profile(profile) if profile else get_profile(None, file)
    view = view or default_view(prof)
    bp = backplot_file(file, prof)
    marked = draw(bp, output, view=view, title=f"{file} ({view})", findings=findings)
    impossible = sum(m.impossible for m in bp.moves)
    arcs = sum(m.arc for m in bp.moves) - impossible  # as --stats counts them: chords are none
    total = len(bp.findings)
    shown = (f"{total} findings not shown" if not findings
             else f"{marked} findings marked" if marked == total
             else f"{marked} of {total} findings marked (the rest have no position)")
    click.echo(f"{output}: {len(bp.moves)} moves, {shown}; {plural(arcs, 'arc')}"
               + (f", {impossible} R arcs that cannot exist drawn as chords" if impossible
                  else "")
               + (f"; not drawn: {' '.join(bp.not_drawn)}" if bp.not_drawn else ""))
    # a block that cannot be read (the registry's reading rules): a file of only these is no
    # program to draw
    unreadable = sum(f.severity == "error" and f.rule in READING_RULES for f in bp.findings)
    if not bp.moves and unreadable:
        # an empty picture of a file that is no program is no answer: say so, exit 1
        click.echo(f"{shown_output(file)}: nothing to draw: "
                   f"{plural(unreadable, 'block')} cannot be read "
                   f"(tapegate check {shown_output(file)} shows why)", err=True)
        sys.exit(1)
