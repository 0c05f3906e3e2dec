"""``tapegate tape``: punched-tape images encoded, decoded and recognised."""

from __future__ import annotations

import sys
from collections.abc import Iterator

import click

# tape codes are imported by the command that runs (start-up)
from tapegate.common import readable, shown, shown_output, user_errors, write_stream


@click.group(short_help="Encode, decode and detect punched-tape images (ISO, EIA).")
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
    """Text program -> tape image (in flat memory, whatever its size). What the tape holds
    otherwise than as it was written (CR under EIA, NUL and DEL as tape fill) is counted on
    standard error."""
    from formats.parser import decode_chunks, read_chunks
    from formats.tape import EncodeNotes, encode_stream

    chunks = decode_chunks(read_chunks(readable(infile)))
    notes = EncodeNotes()
    data = encode_stream(chunks, code, leader=leader, trailer=trailer,  # type: ignore[arg-type]
                         file=shown(infile), notes=notes)
    size = write_stream(output, data)
    for line in notes.lines():
        click.echo(f"{shown(infile)}: {line}", err=True)
    click.echo(f"{shown_output(output)}: {size} bytes, {code.upper()} code",
               err=output == "-")


@tape.command("decode")
@click.argument("infile", type=click.Path(dir_okay=False))
@click.option("-o", "--output", required=True, type=click.Path(dir_okay=False))
@click.option("--code", type=click.Choice(["iso", "eia"]), default=None,
              help="Force the code instead of detecting it.")
@user_errors
def tape_decode(infile: str, output: str, code: str | None) -> None:
    """Tape image -> text; every parity error and illegal code located, the data kept (in flat
    memory: the errors are shown as they are found)."""
    from formats.parser import read_chunks
    from formats.tape import decode_stream

    decoder, texts = decode_stream(read_chunks(readable(infile)), code)  # type: ignore[arg-type]
    counts = {"characters": 0, "errors": 0}

    def encoded() -> Iterator[bytes]:
        for text in texts:
            counts["characters"] += len(text)
            for issue in decoder.issues:
                click.echo(f"{shown(infile)}:{issue.line}:{issue.column}: {issue.message()} "
                           f"at byte {issue.offset}", err=True)
            counts["errors"] += len(decoder.issues)
            decoder.issues.clear()
            yield text.encode("utf-8", errors="surrogateescape")

    write_stream(output, encoded())
    click.echo(f"{shown_output(output)}: {decoder.code.upper()} code, "
               f"{counts['characters']} characters, "
               f"{decoder.fill} fill characters removed, {counts['errors']} errors",
               err=output == "-")
    if decoder.code == "eia":
        # EIA has one end of block and no CR: what the text's line ends were is not on the tape
        click.echo(f"{shown(infile)}: every EOB decoded as LF (an EIA tape does not record "
                   "whether its text ended lines in CR LF, LF or CR)", err=True)
    if counts["errors"]:
        sys.exit(1)


@tape.command("detect")
@click.argument("infile", type=click.Path(dir_okay=False))
@user_errors
def tape_detect(infile: str) -> None:
    """Say whether a file is plain text, an ISO tape image or an EIA tape image (exit 0), or
    none of them: binary (exit 1)."""
    from formats.tape import identify

    with open(readable(infile), "rb") as f:
        sample = f.read(65536)
    content, foreign = identify(sample)
    click.echo(content)
    if content == "binary":
        click.echo(f"{shown(infile)}: {foreign} of the first {len(sample)} bytes are no "
                   "character of text, an ISO tape or an EIA tape", err=True)
        sys.exit(1)
