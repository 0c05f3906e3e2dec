"""``tapegate diff``: two programs compared as NC -- blocks, words and values, not text."""

from __future__ import annotations

import json
import sys
from itertools import islice
from typing import Any

import click

from formats.profile import Profile, load_profile
from formats.source import Source
from tapegate.common import plural, readable, shown, user_errors_exiting
from tapegate.options import UsageProblem


@click.command(short_help="Compare two programs as NC: blocks, words and values, not text.")
@click.argument("file_a", metavar="A", type=click.Path(dir_okay=False))
@click.argument("file_b", metavar="B", type=click.Path(dir_okay=False))
@click.option("--profile", "-p", "profile", default=None,
              help="B's machine profile, and A's without --from (default: the neutral "
                   "profile, with the units codes and decimal style detected in each program).")
@click.option("--from", "from_profile", default=None, help="A's machine profile.")
@click.option("--tolerance", default="0", show_default=True, metavar="STEPS",
              help="Largest difference accepted, in resolution steps of B's word format "
                   "(0.5: what rounding to B's resolution may leave).")
@click.option("--ignore-comments", is_flag=True, help="Comments and comment-only blocks too.")
@click.option("--motion", is_flag=True,
              help="Also compare the modal state and end point after every block.")
@click.option("--pair", type=click.Choice(["auto", "number", "position"]), default="auto",
              show_default=True, help="Pair blocks by sequence number or by position.")
@click.option("--format", "fmt", type=click.Choice(["text", "json"]), default="text",
              show_default=True)
@user_errors_exiting(2)
def diff(file_a: str, file_b: str, profile: str | None, from_profile: str | None,
         tolerance: str, ignore_comments: bool, motion: bool, pair: str, fmt: str) -> None:
    """Compare program A with program B as NC: the same blocks, words and values, whatever
    the spacing, zeros, decimal style, units (and, with --ignore-comments, comments).

    Exit 0 the same, 1 different, 2 an error (a file that cannot be read, with its line and
    column)."""
    from decimal import Decimal, InvalidOperation

    from formats.diff import Differ, DiffOptions, diff_files

    try:
        steps = Decimal(tolerance)
        if not steps.is_finite() or steps < 0:
            raise InvalidOperation
    except InvalidOperation:
        raise UsageProblem(f"--tolerance {tolerance}: give a number of steps, 0 or more"
                           ) from None
    if file_a == file_b == "-":
        raise UsageProblem("- (standard input) can be one of the two programs, not both")
    name_a, name_b = shown(file_a), shown(file_b)
    path_a, path_b = readable(file_a), readable(file_b)
    prof_a = _diff_profile(from_profile or profile, path_a, name_a)
    prof_b = _diff_profile(profile, path_b, name_b)
    options = DiffOptions(tolerance=steps, ignore_comments=ignore_comments, motion=motion,
                          pair=pair)  # type: ignore[arg-type]
    differ = Differ(options, prof_b)
    found = diff_files(path_a, path_b, prof_a, prof_b, options, name_a=name_a,
                       name_b=name_b, differ=differ)
    out = sys.stdout
    if fmt == "json":
        head = {"a": {"file": name_a, "profile": prof_a.name},
                "b": {"file": name_b, "profile": prof_b.name},
                "options": {"tolerance": tolerance, "motion": motion,
                            "ignore_comments": ignore_comments, "pair": pair}}
        out.write(json.dumps(head)[:-1] + ', "differences": [')
        for i, item in enumerate(found):
            out.write((",\n  " if i else "\n  ") + json.dumps(item.as_json()))
        out.write('\n], "summary": ' + json.dumps(differ.summary.as_json()) + "}\n")
    else:
        for item in found:
            out.write(_diff_text(item, name_a, name_b))
        out.write(_diff_summary(differ, name_a, name_b) + "\n")
    same = differ.summary.same
    if same and profile is None and from_profile is None:
        same = _same_in_increments(path_a, path_b, prof_a, prof_b, options, name_a, name_b,
                                   fmt)
    out.flush()
    sys.exit(0 if same else 1)


def _same_in_increments(path_a: str, path_b: str, prof_a: Profile, prof_b: Profile,
                        options: Any, name_a: str, name_b: str, fmt: str) -> bool:
    """Two programs found the same under the neutral profile (a number without a point is a
    whole number, as ISO 6983-1, SINUMERIK and LinuxCNC read it) compared again as a FANUC,
    Haas or Okuma reads them: a number without a point in least input increments (``X10``
    is 0.010 mm, ``X10.`` 10 mm; the FANUC profile's ``[numbers]``). Where that reading finds
    a difference, the default must not hide it: it is shown (text) or said on stderr
    (JSON), and the programs are not the same (exit 1) until ``-p`` names the machine."""
    import dataclasses

    from formats.diff import Differ, diff_files
    from formats.errors import TapegateError

    fanuc = load_profile("fanuc-mill")  # its word formats (IS-B) and its [numbers]
    fanuc_reading = {"numbers": fanuc.numbers, "detailed": fanuc.detailed,
                     "detailed_inch": fanuc.detailed_inch}
    as_a = dataclasses.replace(prof_a, **fanuc_reading)
    as_b = dataclasses.replace(prof_b, **fanuc_reading)
    differ = Differ(options, as_b)
    try:
        found = list(islice(diff_files(path_a, path_b, as_a, as_b, options, name_a=name_a,
                                       name_b=name_b, differ=differ), _SHOWN))
    except TapegateError:  # a word FANUC's formats cannot hold: the programs are no FANUC's
        return True
    if not found:
        return True
    note = (f"tapegate: {name_a} and {name_b} are the same only where a number without a "
            "decimal point is a whole number (ISO 6983-1, SINUMERIK, LinuxCNC); on a control "
            "that reads it in least input increments (FANUC, Haas, Okuma: X10 is 0.010 mm, "
            "X10. is 10 mm) they differ; give -p for the machine")
    click.echo(note, err=True)
    if fmt == "text":
        sys.stdout.write("read as a control that reads a number without a point in least "
                         "input increments (-p fanuc-mill):\n")
        for item in found:
            sys.stdout.write(_diff_text(item, name_a, name_b))
        more = " (the first ones)" if len(found) == _SHOWN else ""
        sys.stdout.write(f"{name_a} and {name_b} differ in increments{more}\n")
    return False


_SHOWN = 20  # differences shown of the reading in increments


def _diff_profile(name: str | None, path: str, shown_name: str) -> Profile:
    """A named profile, or the neutral one adjusted to what the program shows (said on
    stderr, naming the file: two programs may be read two ways)."""
    if name is not None:
        return load_profile(name)
    from formats.convert import detect_source

    head = next(iter(Source(path).chunks()), "")
    prof, detected = detect_source(head[:1 << 20])
    notes = ["the neutral profile"] + [note.removeprefix("source: ") for note in detected]
    click.echo(f"tapegate: {shown_name}: " + "; ".join(notes), err=True)
    return prof


def _diff_text(item: Any, name_a: str, name_b: str) -> str:
    if item.kind == "removed":
        return f"{name_a}:{item.a.line}: only in {name_a}: {item.a.shown}\n"
    if item.kind == "added":
        return f"{name_b}:{item.b.line}: only in {name_b}: {item.b.shown}\n"
    lines = [f"{name_a}:{item.a.line}: changed: {item.a.shown}",
             f"{name_b}:{item.b.line}:     is: {item.b.shown}"]
    lines += [f"    {detail}" for detail in item.details()]
    return "\n".join(lines) + "\n"


def _diff_summary(differ: Any, name_a: str, name_b: str) -> str:
    s = differ.summary
    paired = f"{plural(s.paired, 'block')} paired by {s.pairing}"
    if s.same:
        return f"{name_a} and {name_b} are the same program ({paired})"
    parts = [f"{plural(s.changed, 'block')} changed" if s.changed else "",
             f"{s.removed} only in {name_a}" if s.removed else "",
             f"{s.added} only in {name_b}" if s.added else ""]
    text = f"{name_a} and {name_b} differ: {', '.join(p for p in parts if p)} ({paired})"
    if s.largest:
        from formats.diff import steps_text

        key, size = max(s.largest.items(), key=lambda kv: kv[1])
        text += f"; largest difference: {key} {steps_text(size).lstrip('+')}"
        from fractions import Fraction

        if (max(s.largest.values()) <= Fraction(1, 2) and not differ.options.tolerance
                and not (s.added or s.removed or s.other)):
            text += " (within half a step: --tolerance 0.5 accepts a rounding)"
    return text
