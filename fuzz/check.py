"""Fuzz target: the checker over a program, every rule on, under each built-in profile (and the
neutral one), with the path recorded for the backplot and the reports written.

Byte 0 selects: bits 0-2 the profile, bit 3 the block path (``Checker.run`` over parsed
blocks, bad blocks kept) instead of the text path (``run_stream``), bit 4 chunks of 64 bytes,
bit 5 the JSON and SARIF reports written, bit 6 the first number stretched to over 5,000
digits.
What must hold: no exception (a program that cannot be read is findings, not an error); every
finding names the file, a line of the program (or the line after its last, for the program's
end) and a column >= 1, and a rule the catalogue knows with its clause; the statistics, the
path and the text, JSON (valid JSON) and SARIF reports can be made from them.
"""

from __future__ import annotations

import json

from fuzz import _harness
from fuzz._harness import FILE, check

with _harness.instrumented():
    from formats.parser import decode_chunks, parse_stream
    from postproc.check import Checker
    from postproc.report import as_json, sarif, stats_dict, stats_text, text
    from postproc.rules import RULES

PROFILES = _harness.profiles()



def one_input(data: bytes) -> None:
    if not data:
        return
    selector, body = data[0], data[1:]
    profile = PROFILES[(selector & 7) % len(PROFILES)]
    if selector & 64:
        body = _harness.stretch(body)
    chunks = decode_chunks(_harness.split(body, 64) if selector & 16 else [body])
    checker = Checker(profile, FILE, record_path=True)
    if selector & 8:
        findings = list(checker.run(parse_stream(chunks, profile.dialect, file=FILE,
                                                 errors="collect")))
    else:
        findings = list(checker.run_stream(chunks, profile.dialect))
    lines = body.count(b"\n") + 1
    for f in findings:
        check(f.file == FILE and 1 <= f.line <= lines + 1 and f.column >= 1,
              f"finding out of the program ({lines} lines): {f}")
        check(f.rule in RULES and f.clause == RULES[f.rule].clause and bool(f.message),
              f"finding with an unknown rule or clause: {f}")
    stats = checker.stats
    text(findings)
    stats_text(FILE, stats)
    stats_dict(stats)
    if selector & 32:  # one input in two: the SARIF writer reads the package's version each time
        json.loads(as_json(findings, {FILE: stats}))
        json.loads(sarif(findings))
    check(checker.path is not None, "no path recorded")


def seeds() -> list[bytes]:
    return [bytes([i % 64]) + piece for i, piece in enumerate(_harness.pieces())]


if __name__ == "__main__":
    _harness.main(one_input, seeds, max_seeds=150)
