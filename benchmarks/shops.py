"""Do the shops' programs read completely on their family's built-in profile?

    .venv/bin/python benchmarks/shops.py [--json] [--shops DIR ...] [--only NAME-PART]
                                         [--ledger benchmarks/unseen/ledger.tsv]

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

``--ledger`` names the ledger of the programs that do not read (``benchmarks/unseen/ledger.tsv``:
set, program, profile, line:column and code of the first reading error, class P/F/D/T, evidence)
and adds the figure as the issue asks it: read completely / all, and read completely / (all -
P - F), by family and in total, with the D and T programs listed. A program whose row the ledger
has but which reads completely counts as complete ("ledger row stale"); one that does not read
and has no row is "unclassified" and stays in the denominator; a row whose first error is no
longer where the ledger puts it is "ledger row moved" (counted by its class still). ``--shops``
given more than once measures every folder, so one run gives the figure over all of them.

Each program is counted once, by its name: a name met again (the same folder given twice, a
union folder beside one of its sets) is dropped, and the run says how many were and which. The
ledger's ``set`` column is checked against the set a program came from where the folders say it:
a folder named as a set (``held3``, as ``held_assemble.py`` writes ``OUT/<SET>``; ``shops``)
holds that set, and a union folder (``OUT/all``) holds, of each program a sibling set folder
lists, that set. A row of another set is not applied ("ledger row of another set"): the program
counts as unclassified, since a row judged for one file says nothing of another of its name.

Exit code 0 (a measurement: tests/test_shops.py asserts), 2 where the ledger cannot be read or
a folder has no ``families.tsv`` (nothing is measured then: a partial run has no figure).
"""

from __future__ import annotations

import argparse
import json
import os
import re
import sys
from collections import Counter
from dataclasses import asdict, astuple, dataclass, field
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
UNSEEN = HERE / "unseen"

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
#   G70/G71 for inch/metric and "//" comments, which no Fanuc reads (no profile here: "?");
# - five wolkolak/EZ_machining examples of held15-held17, listed as fanuc from the repository's
#   earlier rows (its FANUC macros): their own words are a SINUMERIK 840D's (CYCLE800, TRAFOOF,
#   $TC_DP6, T="name", WORKPIECE(), R parameters, labels with GOTOF/GOTOB, REPEAT, CASE .. OF,
#   ';' comments), read by no FANUC; the ledger had them F, while their form is one of the five
#   families' documented ones (audit 48).
RELABELLED = {
    "GCodeProjects__GCodeWorkShop__FLANGE.nc": "okuma",
    "GCodeProjects__GCodeWorkShop__OSP5020M.nc": "okuma",
    "GCodeProjects__GCodeWorkShop__OSP7000L.nc": "okuma",
    "LMHDPRO__MAC__1002.nc": "linuxcnc",
    "LMHDPRO__MAC__Titan1M_1001_NoEdit.nc": "linuxcnc",
    "JonahTsai__F16__carriage-center-hole.nc": "?",
    "JonahTsai__F16__carriage-slot.nc": "?",
    **{f"wolkolak__EZ_machining__examples__{name}": "sinumerik"
       for name in ("022_FASKA_REZB_S_KOR.MPF", "REPEAT_cycle21.txt", "case.MPF",
                    "repeat_pos1_pos2.MPF", "repeat_pos1_pos2_cycle.MPF")},
}

# Programs whose set's description calls them mill programs, while their own words are a
# lathe's (audit 37, finding G): the family stays, the lathe profile is taken. The reason is
# added to the description (``entries``), where ``profile_for`` reads "turning".
# - eight mark-brannan Haas programs: ``G50 S2000`` (the lathe's spindle speed clamp),
#   ``G96`` and ``T0100``/``T0101`` (a lathe's tool and offset, read as tool 100 on a mill);
# - two wolkolak FANUC programs: ``G18 G99``, ``G71 U.. R..`` (the lathe's stock removal
#   cycle) and ``T2002``, whose X is a diameter.
_HAAS_LATHE = "G50 S, G96 and T0100/T0101 are a Haas lathe's"
_FANUC_LATHE = "G18 G99, G71 U R (stock removal) and T2002 are a FANUC lathe's"
TURNED = {
    **{f"mark-brannan__mfgt_haas_cnc_class_assignments__SB_{name}.nc": _HAAS_LATHE
       for name in ("SC_spacer12_Op2_v11_09a", "SC_spacer25_Op2_v11_15",
                    "SClampDriveClevisOp2_v11_15", "SClampEndClevisOp1_v11_15",
                    "SClampEndClevisOp2_v11_15", "SClampSpacer625Op1_v11_15",
                    "SClampSpacer880Op1_v11_15", "SClampSpacer890Op1_v11_15")},
    "wolkolak__EZ_machining__examples__O1151.MPF": _FANUC_LATHE,
    "wolkolak__EZ_machining__examples__O6233_musor.MPF": _FANUC_LATHE,
}


@dataclass
class Result:
    name: str
    family: str
    profile: str
    # the set of the folder the program came from, where the folders say it (``folder_sets``)
    set: str = ""
    reprint: bool = False
    unread: int = 0
    first_unread: str = ""
    reading_errors: int = 0
    first_reading_error: str = ""
    rules: dict[str, int] = field(default_factory=dict)
    failure: str = ""
    # the first reading error by place, as the ledger names it: "line:column" and its rule
    # (a block left unread carries the finding the reader gave it, whatever its severity;
    # "reprint" where only the reprint differs)
    first_at: str = ""
    first_code: str = ""

    @property
    def complete(self) -> bool:
        return self.reprint and not self.unread and not self.reading_errors and not self.failure


def entries(shops: Path) -> list[tuple[str, str, str]]:
    """(file, family, description) of families.tsv, the family corrected by RELABELLED and
    the description by TURNED."""
    return map_entries(shops / "families.tsv")


def map_entries(path: Path) -> list[tuple[str, str, str]]:
    """:func:`entries` of a map written as families.tsv is (family, file, description a
    line, tab-separated), wherever it is."""
    out = []
    for line in path.read_text(encoding="utf-8").splitlines():
        if not line.strip():
            continue
        family, name, description = (line.split("\t") + ["", ""])[:3]
        if name in TURNED:
            description = f"{description}; turning: {TURNED[name]}"
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


def set_names() -> frozenset[str]:
    """The sets a ledger row can name: benchmarks/unseen's held and dev sets, and the shops
    folder."""
    return frozenset({p.stem for p in UNSEEN.glob("*.tsv") if p.stem != "ledger"} | {"shops"})


def folder_sets(folder: Path) -> dict[str, str]:
    """The set of each program of ``folder``, where the folders say it: all of them where the
    folder is named as a set (``OUT/held3``, the shops folder); in a union folder, each
    program a sibling folder named as a set lists in its families.tsv (``OUT/all`` beside
    ``OUT/held`` ... ``OUT/held10``). A program not found so has no known set."""
    sets = set_names()
    if folder.name in sets:
        return {name: folder.name for name, _, _ in entries(folder)}
    known: dict[str, str] = {}
    for sibling in sorted(folder.resolve().parent.iterdir()):
        if sibling.name in sets and (sibling / "families.tsv").is_file():
            for name, _, _ in entries(sibling):
                known.setdefault(name, sibling.name)
    return known


@dataclass
class Program:
    """One program to measure: its folder, name, family, description and set ("" unknown)."""
    folder: Path
    name: str
    family: str
    description: str
    set: str


@dataclass
class Dropped:
    """A program name met again after its first folder: not measured, not counted."""
    name: str
    folder: Path
    first: Path  # the folder whose program of that name is counted
    same: bool  # whether the two files hold the same bytes


def programs(folders: list[Path], only: str | None = None) -> tuple[list[Program],
                                                                    list[Dropped]]:
    """Each program of the folders once, by its name, in the order given; the names met again
    are dropped and returned (a program counted twice would count its class twice). A folder
    with no families.tsv is an error (ValueError): a run that measures only some folders has
    no figure."""
    missing = [folder for folder in folders if not (folder / "families.tsv").is_file()]
    if missing:
        raise ValueError(f"no families.tsv in {', '.join(map(str, missing))}: nothing measured")
    kept: list[Program] = []
    dropped: list[Dropped] = []
    first: dict[str, Path] = {}
    for folder in folders:
        sets = folder_sets(folder)
        for name, family, description in entries(folder):
            if only and only not in name:
                continue
            if name in first:
                here, there = folder / name, first[name] / name
                same = here.is_file() and there.is_file() and \
                    here.read_bytes() == there.read_bytes()
                dropped.append(Dropped(name, folder, first[name], same))
                continue
            first[name] = folder
            kept.append(Program(folder, name, family, description, sets.get(name, "")))
    return kept, dropped


def measure(path: Path, family: str, profile_name: str, set_name: str = "") -> Result:
    result = Result(path.name, family, profile_name, set_name)
    try:
        profile = load_profile(profile_name)
    except Exception as exc:  # a profile not built yet: the program is not read
        result.failure = f"profile {profile_name}: {exc}"
        result.first_at, result.first_code = "0:0", "profile"
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
    unread_at = {b.line: str(b.error) for b in bad}
    first: list[tuple[int, int, str]] = []
    for finding in found:
        rules[f"{finding.rule} {finding.severity}"] += 1
        if finding.rule in READING and finding.severity == "error":
            result.reading_errors += 1
            first.append((finding.line, finding.column, finding.rule))
            if not result.first_reading_error:
                result.first_reading_error = (f"line {finding.line}: {finding.rule} "
                                              f"{finding.message}")
        elif finding.message and finding.message in unread_at.get(finding.line, ""):
            first.append((finding.line, finding.column, finding.rule))
    # a block left unread that no finding names still counts, at its line
    named = {line for line, _, _ in first}
    first += [(line, 0, "unread") for line in unread_at if line not in named]
    result.rules = dict(sorted(rules.items()))
    if first:
        line, column, code = min(first)
        result.first_at, result.first_code = f"{line}:{column}", code
    elif not result.reprint:
        result.first_at, result.first_code = f"{first_difference(read, path)}:0", "reprint"
    return result


def first_difference(read: list, path: Path) -> int:
    """The first line where the reprint and the file differ."""
    printed = program_text(read).encode("utf-8", "surrogateescape").splitlines()
    written = path.read_bytes().splitlines()
    for number, (a, b) in enumerate(zip(printed, written, strict=False), 1):
        if a != b:
            return number
    return min(len(printed), len(written)) + 1


# -- the ledger: every program that does not read, classed ---------------------------------------

# P: the program's own error (the control alarms; the source in the evidence); F: a form of
# another control or tool, read by no built-in profile; D: doubtful, no source at hand settles
# it; T: tapegate's (the commit that fixed it, or "open"). P and F leave the issue's
# denominator, as the shops folder's measure counts; D and T stay in it.
CLASSES = ("P", "F", "D", "T")
LEDGER_COLUMNS = ("set", "program", "profile", "at", "code", "class", "evidence")


@dataclass
class LedgerRow:
    set: str
    program: str
    profile: str
    at: str
    code: str
    klass: str
    evidence: str


def read_ledger(path: Path) -> dict[str, LedgerRow]:
    """The ledger's rows by program; a malformed row, an unknown class or a program named
    twice is an error (a ledger that silently loses a row would count its program wrongly)."""
    rows: dict[str, LedgerRow] = {}
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        cells = line.split("\t")
        if len(cells) != len(LEDGER_COLUMNS) or not all(c.strip() for c in cells):
            raise ValueError(f"{path}:{number}: {len(LEDGER_COLUMNS)} cells, none empty, "
                             f"expected ({', '.join(LEDGER_COLUMNS)})")
        row = LedgerRow(*cells)
        if row.klass not in CLASSES:
            raise ValueError(f"{path}:{number}: class {row.klass!r} is none of {CLASSES}")
        if row.program in rows:
            raise ValueError(f"{path}:{number}: {row.program} has a row already")
        rows[row.program] = row
    return rows


@dataclass
class Tally:
    """One family's (or the total's) counts against the ledger."""
    programs: int = 0
    complete: int = 0
    classes: Counter[str] = field(default_factory=Counter)
    unclassified: int = 0

    @property
    def counted(self) -> int:
        """The issue's denominator: every program but the P and F ones."""
        return self.programs - self.classes["P"] - self.classes["F"]


def percent(part: int, whole: int) -> str:
    return f"{part}/{whole} ({100 * part / whole:.1f} %)" if whole else f"{part}/0"


@dataclass
class LedgerReport:
    tallies: dict[str, Tally]  # by family
    total: Tally
    stale: list[LedgerRow]  # rows of programs that read completely
    unclassified: list[Result]  # programs that do not read and have no row
    moved: list[tuple[LedgerRow, Result]]  # rows whose first error is no longer theirs
    listed: list[LedgerRow]  # the D and T rows of programs measured
    elsewhere: int  # rows of programs not measured in this run
    # rows of a set other than the one the program came from: not applied
    other_set: list[tuple[LedgerRow, Result]] = field(default_factory=list)


def ledger_report(results: list[Result], ledger: dict[str, LedgerRow]) -> LedgerReport:
    """The issue's figure against the ledger: read completely / all, and read completely /
    (all - P - F), by family and in total. A program that reads completely counts as
    complete whatever the ledger says (its row is stale); one that does not read and has no
    row, or a row of another set than the one it came from, is unclassified and stays in the
    denominator. ``results`` name each program once (``programs``)."""
    tallies: dict[str, Tally] = {}
    total = Tally()
    stale: list[LedgerRow] = []
    unclassified: list[Result] = []
    moved: list[tuple[LedgerRow, Result]] = []
    listed: list[LedgerRow] = []
    other_set: list[tuple[LedgerRow, Result]] = []
    for r in results:
        row = ledger.get(r.name)
        if row is not None and r.set and row.set != r.set:
            other_set.append((row, r))
            row = None
        for tally in (tallies.setdefault(r.family, Tally()), total):
            tally.programs += 1
            if r.complete:
                tally.complete += 1
            elif row is None:
                tally.unclassified += 1
            else:
                tally.classes[row.klass] += 1
        if r.complete:
            if row is not None:
                stale.append(row)
            continue
        if row is None:
            unclassified.append(r)
            continue
        if (row.at, row.code, row.profile) != (r.first_at, r.first_code, r.profile):
            moved.append((row, r))
        if row.klass in ("D", "T"):
            listed.append(row)
    names = {r.name for r in results}
    return LedgerReport(dict(sorted(tallies.items())), total, stale, unclassified, moved, listed,
                        sum(1 for name in ledger if name not in names), other_set)


def print_ledger(report: LedgerReport, path: Path) -> None:
    print(f"\nagainst the ledger {path.name} ({report.elsewhere} of its rows name programs "
          f"not measured here):")
    print(f"{'family':12} {'read completely / all':24} {'/ (all - P - F)':24} "
          f"{'P':>3} {'F':>3} {'D':>3} {'T':>3} {'unclassified':>12}")
    for family, t in [*report.tallies.items(), ("total", report.total)]:
        print(f"{family:12} {percent(t.complete, t.programs):24} "
              f"{percent(t.complete, t.counted):24} {t.classes['P']:3} {t.classes['F']:3} "
              f"{t.classes['D']:3} {t.classes['T']:3} {t.unclassified:12}")
    for row in sorted(report.listed, key=lambda row: (row.klass, row.set, row.program)):
        print(f"{row.klass} {row.set:7} {row.program} {row.at} {row.code}\n"
              f"           {row.evidence}")
    for r in report.unclassified:
        print(f"unclassified: {r.name} ({r.profile}) {r.first_at} {r.first_code}")
    for row in report.stale:
        print(f"ledger row stale: {row.program} ({row.set}, {row.klass}) now reads completely")
    for row, r in report.moved:
        print(f"ledger row moved: {row.program}: the ledger has {row.profile} {row.at} "
              f"{row.code}, now {r.profile} {r.first_at} {r.first_code}")
    for row, r in report.other_set:
        print(f"ledger row of another set: {row.program}: the ledger's row is {row.set}'s, "
              f"the program came from {r.set}: not applied")


def ledger_json(report: LedgerReport) -> dict:
    def tally(t: Tally) -> dict:
        return {"programs": t.programs, "complete": t.complete, "counted": t.counted,
                "classes": dict(t.classes), "unclassified": t.unclassified}
    return {"ledger": {
        "by_family": {f: tally(t) for f, t in report.tallies.items()},
        "total": tally(report.total),
        "listed": [dict(zip(LEDGER_COLUMNS, astuple(row), strict=True)) for row in report.listed],
        "unclassified": [r.name for r in report.unclassified],
        "stale": [row.program for row in report.stale],
        "moved": [row.program for row, _ in report.moved],
        "other_set": [row.program for row, _ in report.other_set],
        "elsewhere": report.elsewhere}}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--json", action="store_true", help="one JSON object per program")
    parser.add_argument("--shops", type=Path, action="append",
                        help="a folder with families.tsv (again for several; default the "
                             "shops folder)")
    parser.add_argument("--only", help="only files whose name holds this")
    parser.add_argument("--ledger", type=Path,
                        help="benchmarks/unseen/ledger.tsv: the issue's figure against it")
    args = parser.parse_args(argv)
    folders = args.shops or [SHOPS]
    try:
        ledger = read_ledger(args.ledger) if args.ledger else None
    except (OSError, ValueError) as exc:
        print(f"ledger: {exc}", file=sys.stderr)
        return 2
    try:
        todo, dropped = programs(folders, args.only)
    except ValueError as exc:
        print(exc, file=sys.stderr)
        return 2
    results, unknown = [], []
    for program in todo:
        profile = profile_for(program.family, program.description)
        if profile is None:
            unknown.append(program.name)
            continue
        result = measure(program.folder / program.name, program.family, profile, program.set)
        results.append(result)
        if args.json:
            print(json.dumps({**asdict(result), "complete": result.complete}))
        else:
            print_result(result)
    complete = sum(r.complete for r in results)
    by_family = Counter(r.family for r in results)
    done = Counter(r.family for r in results if r.complete)
    summary = {f: f"{done[f]}/{n}" for f, n in sorted(by_family.items())}
    report = ledger_report(results, ledger) if ledger is not None else None
    if args.json:
        print(json.dumps({"complete": complete, "programs": len(results),
                          "by_family": summary, "unknown_family": len(unknown),
                          "dropped": [d.name for d in dropped]}))
        if report is not None:
            print(json.dumps(ledger_json(report)))
    else:
        print(f"\n{complete} of {len(results)} programs read completely "
              f"({', '.join(f'{f} {s}' for f, s in summary.items())}); "
              f"{len(unknown)} of unknown family not read")
        print_dropped(dropped)
        if report is not None:
            print_ledger(report, args.ledger)
    return 0


def print_dropped(dropped: list[Dropped]) -> None:
    if not dropped:
        return
    print(f"{len(dropped)} program{'s were' if len(dropped) != 1 else ' was'} given again and "
          f"dropped (each program is counted once, by its name):")
    for d in dropped:
        how = "the same bytes" if d.same else "OTHER BYTES"
        print(f"  dropped: {d.name} in {d.folder} ({how} as the one counted, in {d.first})")


def print_result(result: Result) -> None:
    state = "complete" if result.complete else "INCOMPLETE"
    print(f"{state:10} {result.profile:15} {result.name}")
    if not result.reprint:
        print("           reprint differs")
    for text in (result.failure, result.first_unread, result.first_reading_error):
        if text:
            print(f"           {text}")
    if not result.complete:
        print(f"           first: {result.first_at} {result.first_code}")
    errors = [f"{r.split()[0]}x{n}" for r, n in result.rules.items() if r.endswith("error")]
    if errors:
        print(f"           errors: {' '.join(errors)}")


if __name__ == "__main__":
    sys.exit(main())
