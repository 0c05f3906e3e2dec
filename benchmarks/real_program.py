"""A large benchmark program built from a real CAM program of the corpus (shared/corpus).

    .venv/bin/python benchmarks/real_program.py [--blocks 1000000] [-o PATH] [--source FILE]

The source is ``Praktikum-CAD-CAM-Modul-12__1001.nc`` (Autodesk Fusion, Haas post, metric, 5
tools, pockets, contours, G18/G19 ramp arcs, G81 drilling and G84 tapping, N every 5, CRLF). The
corpus folder is ``../shared/corpus`` beside the repository, or ``$TAPEGATE_CORPUS`` when set;
the corpus is read, never copied into the project. Without it the script says so on one line and
exits with code 2.

The program is cut in three parts and put together again:

- header: every line before the first motion block (``%``, ``O01001``, the tool-list comments,
  ``N10 G90 G17``, ``N15 G21``), written once;
- body: from the first motion block (a block with G0..G3, a G73..G89 cycle or an axis word
  X Y Z A B C U V W; here ``N20 G53 G0 Z0.``) up to the block before the program end, repeated.
  Each copy starts with the retract and the tool change of the first operation, so every copy is
  a whole, valid run of the part;
- ending: the last block with M30 (or M02/M2) and everything after it (``N15635 M30``, an empty
  line, ``%``), written once.

Every line counts as one block, as ``tapegate parse`` counts them (the source's 3,157 lines are
3,157 blocks, empty lines and comment lines included). The output has exactly ``blocks`` lines:
the last copy of the body is cut where the count is reached, so the program may end mid-operation
(the closing M30 still ends it; the source has no cutter compensation that a cut could leave on).

Sequence numbers: when the source has N words, every numbered block after the header is
renumbered from a counter that starts at the first body block's number and goes up by the
source's usual step (5 here), so the first copy keeps its numbers. N never exceeds 5 digits: after
the largest multiple of the step not above 99999 (N99995) the counter WRAPS to the step (N5), as
CAM posts do; numbers are not dropped. Line ends (CRLF here) and the bytes of every other word
are the source's own.

LinuxCNC: ``rs274`` (LinuxCNC 2.9 standalone interpreter) reads this program as it is, CRLF,
``%`` lines, the bare ``O01001`` line (ignored) and G84 included, given a tool table with T1..T5,
so ``--linuxcnc`` strips nothing for this source (its output is byte-identical). For other
sources it strips the two things rs274 was seen to refuse ("Bad character"): the ``%`` in front
of other text on one line (``%O1200(TOKARKA)`` becomes ``O1200(TOKARKA)``) and DOS ^Z (0x1A)
bytes; see ``linuxcnc_line``.
"""

from __future__ import annotations

import argparse
import os
import re
import sys
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

SOURCE = "Praktikum-CAD-CAM-Modul-12__1001.nc"
MAX_N = 99999

_COMMENT = re.compile(rb"\([^)]*\)|;.*$")
_MOTION = re.compile(rb"(?<![A-Z])(?:G0*[0-3](?![0-9])|G(?:7[3-9]|8[0-9])(?![0-9])"
                     rb"|[XYZABCUVW][+-]?[0-9.])")
_END = re.compile(rb"(?<![A-Z])M0*(?:2|30)(?![0-9])")
_SEQ = re.compile(rb"^(\s*/?\s*)N([0-9]+)")


class CorpusMissing(FileNotFoundError):
    """The corpus folder (or the source program in it) is not there."""


@dataclass
class Built:
    path: str
    blocks: int
    bytes: int
    copies: float  # copies of the body, the cut last one counted as a fraction
    header_blocks: int
    body_blocks: int
    ending_blocks: int
    wraps: int  # times the N counter wrapped past N99999


def corpus_dir() -> Path:
    env = os.environ.get("TAPEGATE_CORPUS")
    if env:
        return Path(env)
    return Path(__file__).resolve().parents[1].parent / "shared" / "corpus"


def source_path(source: str | os.PathLike[str] = SOURCE) -> Path:
    p = Path(source)
    if p.is_absolute() or p.exists():
        if not p.is_file():
            raise CorpusMissing(f"source program not found: {p}")
        return p
    folder = corpus_dir()
    if not folder.is_dir():
        raise CorpusMissing(f"corpus folder not found: {folder} (set TAPEGATE_CORPUS to its path)")
    if not (folder / p).is_file():
        raise CorpusMissing(f"source program not found in the corpus: {folder / p}")
    return folder / p


def _code(line: bytes) -> bytes:
    """The line without its comments, upper case."""
    return _COMMENT.sub(b"", line).upper()


def linuxcnc_line(line: bytes) -> bytes:
    """The line without what rs274 (LinuxCNC 2.9.0~pre1) cannot read; tried one by one:

    - ``%O1200(TOKARKA)``: "Bad character '%' used"; the ``%`` is stripped, the rest kept (a
      bare ``O1200(TOKARKA)`` or ``O01001`` line is read and ignored; so is a closing ``%``
      without an opening one).
    - ^Z (0x1A) before the end: "Bad character '\\032' used"; stripped (after a closing ``%``
      rs274 reads no further, but it is stripped there too).
    A ``%`` alone on its line, CRLF line ends, comments and N words are read as they are.
    Nothing in the default source (1001.nc) matches, so its --linuxcnc output is the same file.
    """
    line = line.replace(b"\x1a", b"")
    stripped = line.lstrip()
    if stripped.startswith(b"%") and stripped[1:].strip():
        line = line[: len(line) - len(stripped)] + stripped[1:].lstrip()
    return line


def _split(data: bytes) -> tuple[list[bytes], bytes, bool]:
    eol = b"\r\n" if b"\r\n" in data else b"\n"
    final_eol = data.endswith(b"\n")
    lines = data.split(b"\n")
    if final_eol:
        lines.pop()
    lines = [ln[:-1] if ln.endswith(b"\r") else ln for ln in lines]
    return lines, eol, final_eol


def _parts(lines: list[bytes]) -> tuple[int, int]:
    """Index of the first motion block and of the program-end block."""
    first = next((i for i, ln in enumerate(lines) if _MOTION.search(_code(ln))), None)
    if first is None:
        raise ValueError("the source has no motion block")
    end = next((i for i in range(len(lines) - 1, first, -1) if _END.search(_code(lines[i]))),
               None)
    if end is None:
        raise ValueError("the source has no M30/M02 program end after its first motion block")
    return first, end


def _step(lines: list[bytes]) -> int:
    numbers = [int(m.group(2)) for ln in lines if (m := _SEQ.match(ln))]
    steps = Counter(b - a for a, b in zip(numbers, numbers[1:], strict=False) if b > a)
    return steps.most_common(1)[0][0] if steps else 1


def build(path_out: str | os.PathLike[str], blocks: int = 1_000_000,
          source: str | os.PathLike[str] = SOURCE, linuxcnc: bool = False) -> Built:
    """Write the program of ``blocks`` lines to ``path_out``; see the module's docstring."""
    data = source_path(source).read_bytes()
    lines, eol, final_eol = _split(data)
    first, end = _parts(lines)
    header, body, ending = lines[:first], lines[first:end], lines[end:]
    if linuxcnc:
        header, body, ending = ([linuxcnc_line(ln) for ln in part]
                                for part in (header, body, ending))
    room = blocks - len(header) - len(ending)
    if room < 1:
        raise ValueError(f"{blocks} blocks is fewer than the header and ending "
                         f"({len(header) + len(ending)}) plus one body block")

    numbered = any(_SEQ.match(ln) for ln in body + ending)
    step = _step(lines)
    top = MAX_N - MAX_N % step
    # each line as (prefix up to N, rest after the number) when numbered, else (line, None)
    template: list[tuple[bytes, bytes | None]] = []
    for ln in body:
        m = _SEQ.match(ln) if numbered else None
        template.append((m.group(1), ln[m.end():]) if m else (ln, None))
    start = next((int(m.group(2)) for ln in body if (m := _SEQ.match(ln))), step)
    counter = start
    wraps = 0

    def number(prefix: bytes, rest: bytes) -> bytes:
        nonlocal counter, wraps
        out = b"%sN%d%s" % (prefix, counter, rest)
        counter += step
        if counter > top:
            counter = step
            wraps += 1
        return out

    size = 0
    with open(path_out, "wb") as f:
        def flush(batch: list[bytes]) -> None:
            nonlocal size
            chunk = eol.join(batch) + eol
            size += len(chunk)
            f.write(chunk)
            batch.clear()

        batch = list(header)
        left = room
        while left > 0:
            for prefix, rest in template[:left]:
                batch.append(prefix if rest is None else number(prefix, rest))
            left -= min(left, len(template))
            if len(batch) >= 50_000:
                flush(batch)
        for ln in ending:
            m = _SEQ.match(ln) if numbered else None
            batch.append(number(m.group(1), ln[m.end():]) if m else ln)
        chunk = eol.join(batch) + (eol if final_eol else b"")
        size += len(chunk)
        f.write(chunk)
    return Built(str(path_out), blocks, size, room / len(template), len(header), len(body),
                 len(ending), wraps)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--blocks", type=int, default=1_000_000,
                        help="lines (blocks) in the program (default 1,000,000)")
    parser.add_argument("-o", "--output", default="real_program.nc", help="file to write")
    parser.add_argument("--source", default=SOURCE,
                        help="corpus file name (or a path) of the program to repeat")
    parser.add_argument("--linuxcnc", action="store_true",
                        help="strip what LinuxCNC's rs274 cannot read (nothing for 1001.nc)")
    args = parser.parse_args(argv)
    try:
        b = build(args.output, args.blocks, args.source, linuxcnc=args.linuxcnc)
    except CorpusMissing as e:
        print(f"real_program: {e}", file=sys.stderr)
        return 2
    except ValueError as e:
        print(f"real_program: {e}", file=sys.stderr)
        return 1
    print(f"{b.path}: {b.blocks:,} blocks, {b.bytes / 1e6:.1f} MB; header {b.header_blocks}, "
          f"body {b.body_blocks} x {b.copies:.2f}, ending {b.ending_blocks}; "
          f"N wrapped {b.wraps} times")
    return 0


if __name__ == "__main__":
    sys.exit(main())
