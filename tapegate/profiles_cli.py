"""``tapegate classify`` and ``tapegate profiles``: classification strings explained, the
machine profiles listed and shown."""

from __future__ import annotations

from pathlib import Path

import click

# lark's classification grammar is imported by `classify` alone (start-up)
from formats.profile import builtin_names, builtin_text, load_profile, spindle_notes
from tapegate.common import table, user_errors


@click.command(short_help="Explain an Annex B or Annex C classification string.")
@click.argument("classification", nargs=-1, required=True)
@user_errors
def classify(classification: tuple[str, ...]) -> None:
    """Explain an Annex B ('PM 322') or Annex C ('%:/DS N03 ... M02*') classification."""
    from formats.classification import DetailedClassification, parse_classification

    parsed = parse_classification(" ".join(classification))
    if isinstance(parsed, DetailedClassification):
        click.echo(f"detailed format classification (ISO 6983-1 Annex C)\n  {parsed}\n")
    else:
        click.echo(f"general format classification (ISO 6983-1 Annex B)\n  {parsed}\n")
    rows = parsed.explain()
    click.echo(table(("item", "value", "meaning"), rows))


@click.group(invoke_without_command=True)
@click.pass_context
def profiles(ctx: click.Context) -> None:
    """List the built-in machine profiles."""
    if ctx.invoked_subcommand is None:
        rows = []
        for name in builtin_names():
            p = load_profile(name)
            rows.append((name, str(p.general), p.table.name, p.serial.code.upper(),
                         p.description))
        click.echo(table(("name", "class", "codes", "tape", "description"), rows))


@profiles.command("show")
@click.argument("name")
@user_errors
def profiles_show(name: str) -> None:
    """Print a profile's TOML (a built-in name or a file), after checking it loads."""
    prof = load_profile(name)
    text = builtin_text(name) if prof.source == "built-in" else Path(name).read_text()
    click.echo(text, nl=False)
    if not text.strip():
        click.echo(f"{name}: an empty profile: every setting at its default", err=True)
    for note in spindle_notes(prof):
        click.echo(f"{name}: {note}", err=True)
