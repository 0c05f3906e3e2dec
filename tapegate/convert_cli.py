"""``tapegate convert``: programs converted to another machine's format, in a batch. The
options are read here and :func:`tapegate.converting.run_convert`, the command's body, does the
rest; a plain ``convert`` also reaches it without click (:mod:`tapegate.launch`)."""

from __future__ import annotations

import click

from formats.wordformat import Rounding
from tapegate.converting import run_convert


@click.command(short_help="Convert programs to another machine's format, exactly.")
@click.argument("inputs", nargs=-1, required=True)
@click.option("-o", "--output", type=click.Path(dir_okay=False),
              help="Output file (one input file only).")
@click.option("--out-dir", type=click.Path(file_okay=False),
              help="Output folder; directories keep their relative layout.")
@click.option("--to", "to_profile", required=True, help="Target machine profile.")
@click.option("--from", "from_profile", default=None,
              help="Source machine profile (default: detect decimal points and units codes).")
@click.option("--from-decimal", type=click.Choice(["explicit", "implicit", "increments"]),
              default=None, help="Read the source's words without a decimal point as whole "
              "numbers (explicit), by its word formats (implicit) or as least increments "
              "(increments: X10000 = 10.000, as a Fanuc reads it).")
@click.option("--from-zeros", type=click.Choice(["leading", "trailing", "none"]), default=None,
              help="Which zeros the source's implicit-decimal words omit.")
@click.option("--from-units", type=click.Choice(["metric", "inch"]), default=None,
              help="The units the source machine is set to at the program's start: its "
              "parameter where no G code selects them (okuma-lathe), or those before the "
              "program's first units code (default: the source profile's units).")
@click.option("--decimal", type=click.Choice(["explicit", "implicit"]), default=None,
              help="Override the target's decimal sign style.")
@click.option("--zeros", type=click.Choice(["leading", "trailing", "none"]), default=None,
              help="Override which zeros implicit-decimal words omit.")
@click.option("--units", type=click.Choice(["metric", "inch"]), default=None,
              help="Convert to these units (default: keep the program's units).")
@click.option("--eob", type=click.Choice(["lf", "crlf"]), default=None,
              help="Rewrite every end of block (default: keep as written).")
@click.option("--spacing", type=click.Choice(["keep", "remove", "insert"]), default="keep",
              show_default=True, help="Spaces between words.")
@click.option("--round", "rounding", type=click.Choice([r.value for r in Rounding]),
              default="half-even", show_default=True,
              help="Rounding to the target resolution; 'error' refuses any rounding.")
@click.option("--allow-unconverted", is_flag=True,
              help="Keep parameters and words of unknown role exactly as written, each named by "
                   "line and column (one the target would read as another number is still "
                   "refused).")
@click.option("--jobs", "-j", type=click.IntRange(1), default=None,
              help="Files converted in parallel (default: the CPU count).")
@click.option("--verify", is_flag=True, help="Read the output back and prove every value.")
@click.option("--dry-run", is_flag=True, help="Convert and report, write nothing.")
@click.option("--force", is_flag=True, help="Overwrite existing outputs.")
@click.option("--format", "fmt", type=click.Choice(["text", "json"]), default="text",
              show_default=True, help="The summary as a table or as one JSON document.")
def convert(inputs: tuple[str, ...], output: str | None, out_dir: str | None, to_profile: str,
            from_profile: str | None, from_decimal: str | None, from_zeros: str | None,
            from_units: str | None, decimal: str | None, zeros: str | None,
            units: str | None, eob: str | None, spacing: str, rounding: str,
            allow_unconverted: bool, jobs: int | None, verify: bool, dry_run: bool,
            force: bool, fmt: str) -> None:
    """Convert programs to another machine's format: decimal style, zeros, units, exactly.

    INPUTS are files, folders or patterns; - reads standard input, and -o - writes the result
    to standard output (the summary then goes to standard error)."""
    run_convert(inputs, output, out_dir, to_profile, from_profile, from_decimal, from_zeros,
                from_units, decimal, zeros, units, eob, spacing, rounding, allow_unconverted, jobs,
                verify, dry_run, force, fmt)
