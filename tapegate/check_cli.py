"""``tapegate check`` and ``tapegate plot``: findings against a machine profile, and the tool
path drawn with them. ``check`` reads its options here and runs
:func:`tapegate.checking.run_check`, its body, which a one-file check also reaches without
click (:mod:`tapegate.launch`)."""

from __future__ import annotations

import sys

import click

from formats.errors import OutputError
from formats.profile import load_profile
from postproc.rules import READING_RULES
from tapegate.checking import run_check
from tapegate.common import get_profile, input_path, plural, shown_output, user_errors
from tapegate.options import UsageProblem, profile_option


@click.command(short_help="Check programs against a machine profile.")
@click.argument("files", nargs=-1, required=True, type=click.Path())
@profile_option()
@click.option("--units", type=click.Choice(["metric", "inch"]), default=None,
              help="The units the machine is set to at the program's start: its parameter "
              "where no G code selects them (okuma-lathe), or those before the program's "
              "first units code (default: the profile's units).")
@click.option("--format", "fmt", type=click.Choice(["text", "json", "jsonl", "sarif"]),
              default="text", show_default=True,
              help="jsonl: JSON Lines, one finding per line.")
@click.option("--select", multiple=True, help="Only these rule IDs or prefixes (TG4,TG601).")
@click.option("--ignore", multiple=True, help="Skip these rule IDs or prefixes.")
@click.option("--fail-on", type=click.Choice(["error", "warning"]), default="error",
              show_default=True, help="Exit 1 on findings of this severity or worse.")
@click.option("--stats", "show_stats", is_flag=True,
              help="Bounding box, path lengths, cycle time, tools.")
@click.option("--all", "show_all", is_flag=True,
              help="Text: print every finding. Without it, past the first 5 warnings or "
              "notes of one rule in a file (of one code, for a rule about a code) the rest "
              "are one line, at the first left out, with their number and lines; errors are "
              "always all printed.")
@click.option("--jobs", "-j", type=click.IntRange(1), default=None,
              help="Files checked in parallel (default: the CPU count).")
def check(files: tuple[str, ...], profile: str | None, units: str | None, fmt: str,
          select: tuple[str, ...], ignore: tuple[str, ...], fail_on: str, show_stats: bool,
          show_all: bool, jobs: int | None) -> None:
    """Check programs (text or ISO/EIA tape images; a folder: every file in it) against a
    machine profile."""
    run_check(files, profile, fmt, select, ignore, fail_on, show_stats, jobs, units=units,
              show_all=show_all)


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
        from postproc.plot import backplot_file, default_view, transforms_note
        from postproc.plot import plot as draw
    except ImportError:
        raise UsageProblem("plot needs matplotlib, the optional 'plot' extra: "
                           "pip install 'tapegate[plot]'") from None

    path = input_path(file)  # (a pipe by its name read from a copy; a device refused)
    prof = load_profile(profile) if profile else get_profile(None, path)
    view = view or default_view(prof)
    bp = backplot_file(path, prof)
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
    if bp.transform_count:  # as the picture says it
        click.echo(f"{shown_output(file)}: {transforms_note(bp)}")
    # a block that cannot be read (the registry's reading rules): a file of only these is no
    # program to draw
    unreadable = sum(f.severity == "error" and f.rule in READING_RULES for f in bp.findings)
    if not bp.moves and unreadable:
        # an empty picture of a file that is no program is no answer: say so, exit 1
        click.echo(f"{shown_output(file)}: nothing to draw: "
                   f"{plural(unreadable, 'block')} cannot be read "
                   f"(tapegate check {shown_output(file)} shows why)", err=True)
        sys.exit(1)
