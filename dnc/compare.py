"""A received program compared with the program folder's copy, as NC (:mod:`formats.diff`).

The gateway's auto-receive asks whether what came back from the control is the same program:
the same blocks, words and values, whatever a transfer or the control's editor may change without
changing the program (end of block, spacing, leader, leading zeros, decimal style). Both files
are read under the port's profile; a block that the profile cannot read (a parity error kept in
the text) is compared as text. One line per difference, for the log and the journal.
"""

from __future__ import annotations

from pathlib import Path

from formats.diff import BlockDiff, DiffOptions, diff_files
from formats.errors import TapegateError
from formats.profile import NEUTRAL, Profile


def compare_programs(expected: Path, received: Path, most: int = 20,
                     profile: Profile | None = None) -> list[str]:
    """The differences between the program folder's copy and a received program, at most
    ``most`` of them; [] when they are the same program."""
    prof = profile or NEUTRAL
    out: list[str] = []
    try:
        for found in diff_files(str(expected), str(received), prof, prof,
                                DiffOptions(errors="collect"), name_a=expected.name,
                                name_b=received.name):
            out.append(_line(found, expected.name))
            if len(out) >= most:
                break
    except (TapegateError, OSError) as exc:
        out.append(f"cannot compare with {expected.name}: {exc}")
    return out


def _line(found: BlockDiff, name: str) -> str:
    if found.b is None:
        assert found.a is not None
        return f"line {found.a.line} of {name}: {found.a.shown!r} not received"
    if found.a is None:
        return f"line {found.b.line} received: {found.b.shown!r} (not in {name})"
    return (f"line {found.a.line} of {name}: {found.a.shown!r} received as {found.b.shown!r} "
            f"(line {found.b.line}): " + "; ".join(found.details()))
