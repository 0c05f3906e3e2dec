"""``tapegate parse``: a program read into blocks of words, as JSON, counts or reprinted."""

from __future__ import annotations

import sys
from typing import TYPE_CHECKING, Any

import click

from formats.errors import TapegateError

# the parser's streams and the printer are imported by the command that runs (start-up)
if TYPE_CHECKING:
    from formats.profile import Profile
from tapegate.common import get_profile, plural, readable, shown, user_errors
from tapegate.options import profile_option


@click.command(short_help="Read a program (text or tape image) into blocks of words.")
@click.argument("file", type=click.Path(dir_okay=False))
@profile_option()
@click.option("--json", "as_json", is_flag=True, help="One JSON object per block (JSON Lines).")
@click.option("--summary", is_flag=True, help="Counts only (blocks, words, comments, speed).")
@click.option("--reprint", is_flag=True, help="Print the program back from the parsed model.")
@user_errors
def parse(file: str, profile: str | None, as_json: bool, summary: bool, reprint: bool) -> None:
    """Parse FILE (text or ISO/EIA tape image, - for standard input) into blocks of words."""
    import json
    import time

    from formats.parser import BadBlock, count_blocks, parse_stream
    from formats.printer import print_blocks
    from formats.source import Source

    path, file = readable(file), shown(file)
    prof = get_profile(profile, path)
    source = Source(path)
    # A block the profile cannot read is kept as it is (and reported on stderr): the reprint is
    # the whole file, byte for byte, and the JSON has every block.
    unreadable: list[BadBlock] = []

    def noted(blocks: Any) -> Any:
        for block in blocks:
            if isinstance(block, BadBlock):
                unreadable.append(block)
            yield block

    blocks = noted(parse_stream(source.chunks(), prof.dialect, file=file, errors="collect"))
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
        n_blocks, n_words, n_comments = count_blocks(source.chunks(), prof.dialect, file=file)
        elapsed = time.perf_counter() - start
        rate = n_blocks / elapsed if elapsed > 0 else 0.0
        click.echo(f"{file}: {plural(n_blocks, 'block')}, {plural(n_words, 'word')}, "
                   f"{plural(n_comments, 'comment')} ({source.kind}) in {elapsed:.3f} s, "
                   f"{rate:,.0f} blocks/s")
        if not summary:
            click.echo("(use --json for the blocks, --reprint for the text)")
    for bad in unreadable:
        click.echo(str(bad.error), err=True)
    for issue in source.issues:
        click.echo(f"{file}:{issue.line}:{issue.column}: tape {issue.message()} "
                   f"at byte {issue.offset}", err=True)
    if source.issues or unreadable:
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
    if block.skip_within is not None:
        column, mark = block.skip_within
        result["skip_within"] = {"column": column, "text": mark}
    if block.comments:
        result["comments"] = [{"column": c, "text": t} for c, t in block.comments]
    if block.percent:
        result["percent"] = True
        result["ident"] = block.info.ident
    from formats.parser import BadBlock

    if isinstance(block, BadBlock):
        result["error"] = str(block.error)
    return result
