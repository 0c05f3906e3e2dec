"""The ``tapegate`` command line: options in, library calls, results out -- no work of its own.

Every user error (:class:`formats.errors.TapegateError`) is printed as one located line on
stderr, never as a traceback. Exit codes: 0 done, 1 the input is bad (parse, tape, conversion or
check findings), 2 usage error or unreadable file.
"""

from __future__ import annotations

import json
import sys
import time
from collections.abc import Callable, Sequence
from functools import wraps
from pathlib import Path
from typing import Any, TypeVar

import click

from formats.classification import DetailedClassification, GeneralClassification
from formats.errors import ProfileError, TapegateError
from formats.files import write_atomic
from formats.parser import BadBlock, parse_stream
from formats.printer import print_blocks
from formats.profile import NEUTRAL, Profile, builtin_names, builtin_text, load_profile
from formats.source import Source
from formats.tape import decode, detect, encode

F = TypeVar("F", bound=Callable[..., Any])


class UsageProblem(click.ClickException):
    exit_code = 2


def user_errors(func: F) -> F:
    """Turn a TapegateError into a located message and exit code 1 (2 for unreadable files)."""

    @wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return func(*args, **kwargs)
        except ProfileError as exc:
            click.echo(f"tapegate: {exc}", err=True)
            sys.exit(2)
        except TapegateError as exc:
            click.echo(str(exc), err=True)
            sys.exit(1)
        except (FileNotFoundError, IsADirectoryError, PermissionError) as exc:
            click.echo(f"tapegate: cannot read {exc.filename}: {exc.strerror}", err=True)
            sys.exit(2)
        except BrokenPipeError:
            sys.exit(0)

    return wrapper  # type: ignore[return-value]


def profile_option(required: bool = False, default: str | None = None) -> Callable[[F], F]:
    return click.option(
        "--profile", "-p", "profile", required=required, default=default,
        help="Machine profile: a built-in name (see `tapegate profiles`) or a .toml file.")


def get_profile(name: str | None) -> Profile:
    return NEUTRAL if name is None else load_profile(name)


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="tapegate")
def main() -> None:
    """tapegate: convert, check and drip-feed ISO 6983-1 NC programs."""


# ---------------------------------------------------------------------------------------------
# parse


@main.command()
@click.argument("file", type=click.Path(dir_okay=False))
@profile_option()
@click.option("--json", "as_json", is_flag=True, help="One JSON object per block (JSON Lines).")
@click.option("--summary", is_flag=True, help="Counts only (blocks, words, comments, speed).")
@click.option("--reprint", is_flag=True, help="Print the program back from the parsed model.")
@user_errors
def parse(file: str, profile: str | None, as_json: bool, summary: bool, reprint: bool) -> None:
    """Parse FILE (text or ISO/EIA tape image) into blocks of words."""
    prof = get_profile(profile)
    source = Source(file)
    blocks = parse_stream(source.chunks(), prof.dialect, file=file)
    out = sys.stdout
    if reprint:
        sys.stdout.flush()
        raw = sys.stdout.buffer
        for text in print_blocks(blocks):
            raw.write(text.encode("utf-8", errors="surrogateescape"))
        raw.flush()
    elif as_json:
        for block in blocks:
            out.write(json.dumps(block_json(block, prof), ensure_ascii=False) + "\n")
    else:
        start = time.perf_counter()
        counts = {"blocks": 0, "words": 0, "comments": 0}
        for block in blocks:
            counts["blocks"] += 1
            counts["words"] += len(block.words)
            if block.info is not None:
                counts["comments"] += len(block.info.comments)
        elapsed = time.perf_counter() - start
        rate = counts["blocks"] / elapsed if elapsed > 0 else 0.0
        click.echo(f"{file}: {counts['blocks']} blocks, {counts['words']} words, "
                   f"{counts['comments']} comments ({source.kind}) "
                   f"in {elapsed:.3f} s, {rate:,.0f} blocks/s")
        if not summary:
            click.echo("(use --json for the blocks, --reprint for the text)")
    for issue in source.issues:
        click.echo(f"{file}:{issue.line}:{issue.column}: tape {issue.message()} "
                   f"at byte {issue.offset}", err=True)
    if source.issues:
        sys.exit(1)


def block_json(block: Any, prof: Profile) -> dict[str, Any]:
    words = []
    for w in block.word_objects():
        item: dict[str, Any] = {"address": w.address, "column": w.column}
        if w.index:
            item["index"] = w.index
        if w.expression:
            item["expression"] = w.expression
        else:
            item["sign"] = w.sign
            item["number"] = w.number
            try:
                item["value"] = str(prof.value(w.token))
            except TapegateError as exc:
                item["error"] = exc.message
        words.append(item)
    result: dict[str, Any] = {"line": block.line, "text": block.text, "words": words}
    if block.skip:
        result["skip"] = block.skip
    if block.comments:
        result["comments"] = [{"column": c, "text": t} for c, t in block.comments]
    if block.percent:
        result["percent"] = True
        result["ident"] = block.info.ident
    if isinstance(block, BadBlock):
        result["error"] = str(block.error)
    return result


# ---------------------------------------------------------------------------------------------
# tape


@main.group()
def tape() -> None:
    """Encode and decode punched-tape images (ISO even parity, EIA RS-244)."""


@tape.command("encode")
@click.argument("infile", type=click.Path(dir_okay=False))
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False))
@click.option("--code", type=click.Choice(["iso", "eia"]), default="iso", show_default=True)
@click.option("--leader", type=click.IntRange(0), default=0, help="Blank characters before.")
@click.option("--trailer", type=click.IntRange(0), default=0, help="Blank characters after.")
@user_errors
def tape_encode(infile: str, output: str, code: str, leader: int, trailer: int) -> None:
    """Text program -> tape image."""
    text = Path(infile).read_bytes().decode("utf-8", errors="surrogateescape")
    data = encode(text, code, leader=leader, trailer=trailer, file=infile)  # type: ignore[arg-type]
    write_atomic(Path(output), data)
    click.echo(f"{output}: {len(data)} bytes, {code.upper()} code")


@tape.command("decode")
@click.argument("infile", type=click.Path(dir_okay=False))
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False))
@click.option("--code", type=click.Choice(["iso", "eia"]), default=None,
              help="Force the code instead of detecting it.")
@user_errors
def tape_decode(infile: str, output: str, code: str | None) -> None:
    """Tape image -> text; every parity error and illegal code located, the data kept."""
    data = Path(infile).read_bytes()
    result = decode(data, code)  # type: ignore[arg-type]
    write_atomic(Path(output), result.text.encode("utf-8", errors="surrogateescape"))
    for issue in result.issues:
        click.echo(f"{infile}:{issue.line}:{issue.column}: {issue.message()} at byte "
                   f"{issue.offset}", err=True)
    click.echo(f"{output}: {result.code.upper()} code, {len(result.text)} characters, "
               f"{result.fill} fill characters removed, {len(result.issues)} errors")
    if result.issues:
        sys.exit(1)


@tape.command("detect")
@click.argument("infile", type=click.Path(dir_okay=False))
@user_errors
def tape_detect(infile: str) -> None:
    """Say whether a file is plain text, an ISO tape image or an EIA tape image."""
    with open(infile, "rb") as f:
        click.echo(detect(f.read(65536)))


# ---------------------------------------------------------------------------------------------
# classify and profiles


@main.command()
@click.argument("classification", nargs=-1, required=True)
@user_errors
def classify(classification: tuple[str, ...]) -> None:
    """Explain an Annex B ('PM 322') or Annex C ('%:/DS N03 ... M02*') classification."""
    text = " ".join(classification)
    if "*" in text:
        detailed = DetailedClassification.parse(text)
        click.echo(f"detailed format classification (ISO 6983-1 Annex C)\n  {detailed}\n")
        rows = detailed.explain()
    else:
        general = GeneralClassification.parse(text)
        click.echo(f"general format classification (ISO 6983-1 Annex B)\n  {general}\n")
        rows = general.explain()
    click.echo(table(("item", "value", "meaning"), rows))


def table(header: tuple[str, ...], rows: Sequence[tuple[str, ...]]) -> str:
    widths = [max(len(str(r[i])) for r in [header, *rows]) for i in range(len(header))]
    lines = ["  ".join(str(c).ljust(w) for c, w in zip(header, widths, strict=True)).rstrip()]
    lines.append("  ".join("-" * w for w in widths))
    for row in rows:
        lines.append("  ".join(str(c).ljust(w) for c, w in zip(row, widths, strict=True)).rstrip())
    return "\n".join(lines)


@main.group(invoke_without_command=True)
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


if __name__ == "__main__":  # pragma: no cover
    main()
