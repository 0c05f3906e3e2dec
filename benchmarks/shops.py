"""Do the shops' programs read completely on their family's built-in profile?

    .venv/bin/python benchmarks/shops.py [--json] [--shops DIR] [--only NAME-PART]

Every program of ``shared/corpus/shops`` (beside the project, as for the tests; ``--shops`` or
``TAPEGATE_SHOPS`` elsewhere) is read on the built-in profile of the family ``families.tsv``
gives it (``FAMILY_PROFILES``; "lathe" or "turn" as a word of the description picks the lathe
profile; a file this project found mislabelled is read on the profile of its real family, see
``RELABELLED``). Programs of unknown family (``?``) are listed and not counted.

Per program: whether it **reads completely** -- the reprint of the parsed model is byte-identical
to the file (what ``tapegate parse --reprint`` prints) and no reading error (a block the reader
could not read, unless the checker finds that no run reaches it, ``NEVER_RUN``; or an error of a
reading rule, ``READING``, from the checker as ``tapegate check`` runs it) -- and every rule
that fires, with its severity and count. The totals at the end are the measure of issue 32;
docs/benchmarks.md keeps the figures.

Exit code 0 always (a measurement); tests/test_shops.py asserts.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import sys
from collections import Counter
from dataclasses import asdict, dataclass, field
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))

from formats.parser import BadBlock, parse_stream  # noqa: E402
from formats.printer import program_text  # noqa: E402
from formats.profile import load_profile  # noqa: E402
from formats.source import Source  # noqa: E402
from postproc.check import Checker  # noqa: E402
from postproc.rules import rule_id  # noqa: E402

SHOPS = Path(os.environ.get("TAPEGATE_SHOPS", HERE.parents[1] / "shared" / "corpus" / "shops"))

# The rules a finding of which, as an error, means the program could not be read: characters,
# statements, number format (the same set as tests/test_dialects.py).
READING = frozenset(rule_id(name) for name in (
    "Unreadable", "CharacterOutsideSet", "CommentNotClosed", "NestedComment", "AlignmentNotFirst",
    "MixedDecimalStyles", "UnexpectedDecimalPoint", "TooManyDigits", "UnexpectedSign",
    "DigitOverflow", "IndexOutOfRange"))

# A line no run reaches, which the control stores and never reads: not a reading error.
NEVER_RUN = rule_id("NeverRun")

# family -> (mill profile, lathe profile)
FAMILY_PROFILES = {
    "fanuc": ("fanuc-mill", "fanuc-lathe"),
    "haas": ("haas-mill", "haas-lathe"),
    "sinumerik": ("sinumerik-840d", "sinumerik-840d"),
    "linuxcnc": ("linuxcnc", "linuxcnc"),
    "heidenhain": ("heidenhain-iso", "heidenhain-iso"),
    "okuma": ("okuma-mill", "okuma-lathe"),
}

# Files families.tsv puts in a family their own text shows they are not of:
# - the three Okuma OSP programs ("$NAME.MIN%" headers, OSP variables and statements), listed as
#   fanuc;
# - the two Fusion 360 "Tormach PCNC440" posts, listed as fanuc: a PCNC 440 runs PathPilot,
#   which is LinuxCNC;
# - the two MillMaster Pro programs, listed as fanuc: their own header says the control uses
#   G70/G71 for inch/metric and "//" comments, which no Fanuc reads (no profile here: "?").
RELABELLED = {
    "GCodeProjects__GCodeWorkShop__FLANGE.nc": "okuma",
    "GCodeProjects__GCodeWorkShop__OSP5020M.nc": "okuma",
    "GCodeProjects__GCodeWorkShop__OSP7000L.nc": "okuma",
    "LMHDPRO__MAC__1002.nc": "linuxcnc",
    "LMHDPRO__MAC__Titan1M_1001_NoEdit.nc": "linuxcnc",
    "JonahTsai__F16__carriage-center-hole.nc": "?",
    "JonahTsai__F16__carriage-slot.nc": "?",
}


@dataclass
class Result:
    name: str
    family: str
    profile: str
    reprint: bool = False
    unread: int = 0
    first_unread: str = ""
    reading_errors: int = 0
    first_reading_error: str = ""
    rules: dict[str, int] = field(default_factory=dict)
    failure: str = ""

    @property
    def complete(self) -> bool:
        return self.reprint and not self.unread and not self.reading_errors and not self.failure


def entries(shops: Path) -> list[tuple[str, str, str]]:
    """(file, family, description) of families.tsv, the family corrected by RELABELLED."""
    out = []
    for line in (shops / "families.tsv").read_text(encoding="utf-8").splitlines():
        if not line.strip():
            continue
        family, name, description = (line.split("\t") + ["", ""])[:3]
        out.append((name, RELABELLED.get(name, family), description))
    return out


# "lathe" or "turn" as a word of the description marks a turning program (``turn-mill``,
# ``mill-turn``, ``turning`` too); as part of another word (``returns``, ``its accents
# turned to``) it does not: held10's Haas mill practical was read on the lathe profile so.
TURNING = re.compile(r"\b(lathes?|turn|turning)\b")


def profile_for(family: str, description: str) -> str | None:
    """The built-in profile of a family, the lathe one where the description says turning."""
    if family not in FAMILY_PROFILES:
        return None
    mill, lathe = FAMILY_PROFILES[family]
    return lathe if TURNING.search(description.lower()) else mill


def measure(path: Path, family: str, profile_name: str) -> Result:
    result = Result(path.name, family, profile_name)
    try:
        profile = load_profile(profile_name)
    except Exception as exc:  # a profile not built yet: the program is not read
        result.failure = f"profile {profile_name}: {exc}"
        return result
    read = list(parse_stream(Source(str(path)).chunks(), profile.dialect, file=path.name,
                             errors="collect"))
    result.reprint = program_text(read).encode("utf-8", "surrogateescape") == path.read_bytes()
    found = list(Checker(profile, file=path.name).run(iter(read)))
    # a line the reader could not read that no run reaches (TG108, FANUC and Haas) is kept as
    # written and said as a warning: the control stores it and never reads it
    never_run = {f.line for f in found if f.rule == NEVER_RUN}
    bad = [b for b in read if isinstance(b, BadBlock) and b.line not in never_run]
    result.unread = len(bad)
    if bad:
        result.first_unread = f"line {bad[0].line}: {bad[0].error}"
    rules: Counter[str] = Counter()
    for finding in found:
        rules[f"{finding.rule} {finding.severity}"] += 1
        if finding.rule in READING and finding.severity == "error":
            result.reading_errors += 1
            if not result.first_reading_error:
                result.first_reading_error = (f"line {finding.line}: {finding.rule} "
                                              f"{finding.message}")
    result.rules = dict(sorted(rules.items()))
    return result


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--json", action="store_true", help="one JSON object per program")
    parser.add_argument("--shops", type=Path, default=SHOPS)
    parser.add_argument("--only", help="only files whose name holds this")
    args = parser.parse_args(argv)
    if not (args.shops / "families.tsv").is_file():
        print(f"no families.tsv in {args.shops}", file=sys.stderr)
        return 0
    results, unknown = [], []
    for name, family, description in entries(args.shops):
        if args.only and args.only not in name:
            continue
        profile = profile_for(family, description)
        if profile is None:
            unknown.append(name)
            continue
        result = measure(args.shops / name, family, profile)
        results.append(result)
        if args.json:
            print(json.dumps({**asdict(result), "complete": result.complete}))
        else:
            state = "complete" if result.complete else "INCOMPLETE"
            print(f"{state:10} {profile:15} {name}")
            if not result.reprint:
                print("           reprint differs")
            for text in (result.failure, result.first_unread, result.first_reading_error):
                if text:
                    print(f"           {text}")
            errors = [f"{r.split()[0]}x{n}" for r, n in result.rules.items() if r.endswith("error")]
            if errors:
                print(f"           errors: {' '.join(errors)}")
    complete = sum(r.complete for r in results)
    by_family = Counter(r.family for r in results)
    done = Counter(r.family for r in results if r.complete)
    summary = {f: f"{done[f]}/{n}" for f, n in sorted(by_family.items())}
    if args.json:
        print(json.dumps({"complete": complete, "programs": len(results),
                          "by_family": summary, "unknown_family": len(unknown)}))
    else:
        print(f"\n{complete} of {len(results)} programs read completely "
              f"({', '.join(f'{f} {s}' for f, s in summary.items())}); "
              f"{len(unknown)} of unknown family not read")
    return 0


if __name__ == "__main__":
    sys.exit(main())
