"""The conformance matrix (docs/conformance.md) and the requirements it found untested.

The matrix maps every requirement of ISO 6983-1 and every code of both G/M tables to what
tapegate does and to a test. The tests here keep it honest: every node ID it names must be
collected by pytest, every rule ID must be in the registry, every code of both tables must have
its row, and each code row's status and duration must agree with the code tables tapegate
checks against. The rest of the file proves the rows no other test covered.
"""

from __future__ import annotations

import math
import re
import subprocess
import sys
from decimal import Decimal
from pathlib import Path

import pytest

from formats.classification import DetailedClassification
from formats.codes import TABLES
from formats.convert import ConvertOptions, convert_text
from formats.errors import FormatSpecError, ParseError
from formats.parser import parse_text
from formats.profile import load_profile, profile_from_text
from formats.tape import decode, encode
from formats.wordformat import Zeros
from postproc.check import Checker, check_text
from postproc.rules import RULES

ROOT = Path(__file__).resolve().parents[1]
MATRIX = ROOT / "docs" / "conformance.md"
ISO_MILL = load_profile("iso-mill")


def rules_of(text: str, profile: object = ISO_MILL) -> list[tuple[str, int]]:
    return [(f.rule, f.line) for f in check_text(text, profile)]  # type: ignore[arg-type]


# -- the matrix ---------------------------------------------------------------------------------


def matrix_rows() -> list[list[str]]:
    """The table rows of the matrix, as cells (the header and ruler rows left out)."""
    rows = []
    for line in MATRIX.read_text(encoding="utf-8").splitlines():
        if not line.startswith("| ") or line.startswith(("| ID ", "| table ")):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        rows.append(cells)
    return rows


def requirement_rows() -> list[list[str]]:
    return [r for r in matrix_rows() if re.fullmatch(r"[0-9A-E][0-9.]*-\d+", r[0])]


def code_rows() -> list[list[str]]:
    return [r for r in matrix_rows() if r[0] in TABLES]


NODE = re.compile(r"`(tests/[\w/]+\.py::[^`\s]+)`|`R\[(TG\d{3})\]`")
RULE_TEST = "tests/test_rules.py::test_rule_triggers_on_its_example[{}]"


def nodes(cell: str) -> list[str]:
    """The pytest node IDs a tests cell names (``R[TG130]`` is the rule's example test)."""
    return [node or RULE_TEST.format(rule) for node, rule in NODE.findall(cell)]


def test_matrix_names_only_tests_that_exist_and_rules_that_the_registry_has() -> None:
    rows = matrix_rows()
    assert len(rows) > 400
    named = {node for row in rows for node in nodes(row[-1])}
    files = sorted({node.split("::")[0] for node in named})
    collected = subprocess.run(
        [sys.executable, "-m", "pytest", "--collect-only", "-q", "-p", "no:cacheprovider",
         *files], cwd=ROOT, capture_output=True, text=True, timeout=120).stdout.split()
    existing = set(collected)
    # a node ID without parameters names every parametrised case of that test
    existing |= {node.split("[")[0] for node in collected}
    missing = sorted(named - existing)
    assert not missing, f"the matrix names tests that do not exist: {missing}"
    rule_ids = {rule for row in rows for cell in row for rule in re.findall(r"\bTG\d{3}\b", cell)}
    assert rule_ids and not rule_ids - set(RULES), sorted(rule_ids - set(RULES))


def test_every_requirement_row_has_a_test_or_a_reason() -> None:
    rows = requirement_rows()
    ids = [r[0] for r in rows]
    assert len(ids) == len(set(ids)), "duplicate requirement IDs"
    for row in rows:
        assert len(row) == 6, row
        ident, _, clause, force, does, tests = row
        assert force in ("shall", "should", "may", "is"), row
        assert nodes(tests), row
    clauses = {r[2].split(".")[0].split(" ")[0] for r in rows}
    wanted = {str(n) for n in range(4, 15)} | {"Annex"}
    assert wanted <= clauses | {"Annex"}, wanted - clauses
    annexes = {r[2] for r in rows if r[2].startswith("Annex")}
    assert {f"Annex {a}" for a in "ABCDE"} <= {a[:7] for a in annexes}


def test_every_code_of_both_tables_has_one_row() -> None:
    seen: dict[str, set[str]] = {name: set() for name in TABLES}
    for row in code_rows():
        assert row[1] not in seen[row[0]], f"{row[0]} {row[1]} twice"
        seen[row[0]].add(row[1])
    for name in TABLES:
        wanted = {f"{letter}{n:02d}" for letter in "GM" for n in range(100)}
        assert seen[name] == wanted, sorted(wanted ^ seen[name])


CODE_ROWS = code_rows() if MATRIX.exists() else []
PROFILE_OF = {"iso6983-1": "iso-mill", "iso1056": "cm332-quadrant"}


@pytest.mark.parametrize("row", CODE_ROWS, ids=[f"{r[0]}-{r[1]}" for r in CODE_ROWS])
def test_code_row(row: list[str]) -> None:
    """The row says what the standard says; the table agrees, and the checker acts on it."""
    table_name, name, _function, duration, status, _rest = row[:6]
    letter, number = name[0], int(name[1:])
    code = TABLES[table_name].lookup(letter, number)
    assert code is not None
    assert code.status == status, f"{name}: the table has {code.status}, the standard {status}"
    group = re.search(r"\(\*?([a-z])\)|^([a-z])$", duration)
    if duration == "TBO":
        assert code.duration == "TBO"
    elif group:
        assert code.duration == (group.group(1) or group.group(2))
    elif duration.startswith("modal"):
        assert code.modal
    profile = load_profile(PROFILE_OF[table_name])
    findings = check_text(f"%\nN1 G90 G17\nN2 {name}\nN99 M30\n%\n", profile)
    on_line = {f.rule for f in findings if f.line == 3}
    designated = name in profile.units_codes
    if status in ("assigned", "conditional") or designated:
        assert not on_line & {"TG301", "TG302", "TG303"}, on_line
    elif status == "unassigned":
        assert "TG302" in on_line
    else:
        assert "TG303" in on_line
    others = [c for c in (TABLES[table_name].g if letter == "G" else TABLES[table_name].m).values()
              if c.modal and c.duration == code.duration and c.number != number and c.usable]
    if code.modal and code.usable and others and letter == "G":
        pair = f"%\nN1 G90 G17\nN2 {name} {others[0].name}\nN99 M30\n%\n"
        assert "TG304" in {f.rule for f in check_text(pair, profile)}


# -- clause 4: program format ------------------------------------------------------------------

LABEL = "%(part 7; rev b$)"  # lower case and characters outside Annex A: skipped, never read


def test_the_label_is_carried_unchanged_by_convert_and_left_alone_by_check() -> None:
    program = f"{LABEL}\nN1 G71 G90 G17\nN2 G00 X1.5 Y2\nN3 M30\n%\n"
    out, _ = convert_text(program, ConvertOptions(load_profile("cm332-quadrant"),
                                                  source=ISO_MILL))
    assert out.splitlines()[0] == LABEL
    assert out.splitlines()[2] == "N2 G00 X150 Y200"  # the blocks did convert
    assert not [f for f in check_text(program, ISO_MILL) if f.line == 1]


def test_the_label_is_an_identification_not_a_block() -> None:
    (first, *_), = [parse_text(f"{LABEL}\nN1 X1\n%\n")[:1]]
    assert first.percent and first.info is not None and first.info.ident == LABEL[1:]
    assert first.words == []


def test_non_printing_characters_are_ignored() -> None:
    """TAB, CR, SP and DEL are not data (clause 4): the words are the same without them. On a
    tape image DEL (an erased character) is removed wherever it stands, even inside a word."""
    plain = parse_text("N1 G01 X10 Y20\n")[0].words
    assert parse_text("N1\tG01 X10\x7f  Y20\r\n")[0].words == plain
    tape = encode("N1 G01 X1", "iso") + b"\x7f" + encode("0 Y20\n", "iso")
    decoded = decode(tape, "iso")
    assert decoded.fill == 1 and parse_text(decoded.text)[0].words == plain


# -- clause 5: word order ----------------------------------------------------------------------


def test_interpolation_words_follow_their_axis_group_as_in_the_standard() -> None:
    """5.2's own example: I J follow the X Y group they belong to, before Z."""
    good = "%\nN10 G17\nN15 G01 G90 X0 Y0 Z0 F50\nN20 G02 X20 Y20 I20 J0 Z10\nN99 M30\n%\n"
    assert "TG130" not in {r for r, _ in rules_of(good)}
    bad = good.replace("G02 X20 Y20 I20 J0 Z10", "G02 X20 Y20 Z10 F50 I20 J0")
    assert ("TG130", 4) in rules_of(bad)


# -- clause 6: words ---------------------------------------------------------------------------


def test_indexed_addresses_and_work_groups_of_6_2() -> None:
    block = parse_text("G00 X1=123.456 Y1=234 Z2=10.1 F100 S1000\n")[0]
    assert block.words == ["G00", "X1=123.456", "Y1=234", "Z2=10.1", "F100", "S1000"]
    program = "%\nN1 G00 X1=1 Y1=2 M1=3 S1=200\nN2 X2=1 Y2=2 M2=3 S2=200\nN99 M30\n%\n"
    assert not {"TG100", "TG206"} & {r for r, _ in rules_of(program)}


def test_parameters_of_6_4_7_need_their_index() -> None:
    program = "%\nN1 R11 = 22.2\nN2 R29 = R9 + R15\nN3 X2 = 105 + R9\nN99 M30\n%\n"
    blocks = parse_text(program)
    assert [b.words[1:] for b in blocks[1:4]] == [["R11=22.2"], ["R29=R9+R15"],
                                                   ["X2=105+R9"]]
    assert not {"TG100", "TG206"} & {r for r, _ in rules_of(program)}
    with pytest.raises(ParseError) as err:
        parse_text("N1 R = 5\n")
    assert (err.value.code, err.value.clause) == ("TG100", "6.4.7")
    assert (err.value.line, err.value.column) == (1, 6)
    assert "index" in err.value.message  # a missing index, within TG100's unreadable words


# -- clause 7: interpolation -------------------------------------------------------------------


def test_the_helical_example_of_7_3() -> None:
    """N20 G2 X20 Y20 I20 J0 Z10: clockwise 90 degrees about (20, 0), radius 20, Z rising."""
    program = "%\nN10 G17\nN15 G1 G90 X0 Y0 Z0 F50\nN20 G2 X20 Y20 I20 J0 Z10\nN99 M30\n%\n"
    checker = Checker(ISO_MILL, record_path=True)
    findings = list(checker.run(parse_text(program)))
    assert [f.rule for f in findings if f.line == 4] == ["TG406"]  # helical: noted, not wrong
    assert checker.path is not None
    arc = checker.path[-1]
    assert arc.kind == "arc" and arc.clockwise and arc.centre == (20.0, 0.0, 0.0)
    quarter = math.hypot(math.pi / 2 * 20, 10)
    assert checker.stats.feed_length == pytest.approx(quarter, rel=1e-6)


def test_a_full_circle_in_one_block() -> None:
    program = "%\nN1 G17 G90\nN2 G01 X20 Y0 F100\nN3 G02 X20 Y0 I-20 J0\nN99 M30\n%\n"
    checker = Checker(ISO_MILL, record_path=True)
    assert not [f for f in checker.run(parse_text(program)) if f.rule.startswith("TG40")]
    assert checker.stats.feed_length == pytest.approx(20 + 2 * math.pi * 20, rel=1e-6)


def test_arc_centres_in_the_alternative_readings_of_7_3() -> None:
    absolute = profile_from_text('name = "abs"\n[checks]\nijk = "absolute"\n')
    program = "%\nN1 G17 G90\nN2 G01 X20 Y0 F100\nN3 G03 X0 Y20 I0 J0\nN99 M30\n%\n"
    assert not {"TG403", "TG404"} & {r for r, _ in rules_of(program, absolute)}
    assert ("TG405", 4) in rules_of(program)  # read incrementally, the centre is the start
    quadrant = load_profile("cm332-quadrant")
    unsigned = "%\nN1 G17 G90\nN2 G01 X2000 Y0 F100\nN3 G03 X0 Y2000 I2000 J0\nN99 M30\n%\n"
    assert not {"TG403", "TG409"} & {r for r, _ in rules_of(unsigned, quadrant)}
    halfway = unsigned.replace("X0 Y2000 I2000 J0", "X-2000 Y0 I2000 J0")
    assert ("TG409", 4) in rules_of(halfway, quadrant)


# -- Annex C -----------------------------------------------------------------------------------


def test_a_format_omits_leading_or_trailing_zeros_never_both() -> None:
    with pytest.raises(FormatSpecError) as info:
        DetailedClassification.parse("%:/DS N03 X+0530*")
    assert (info.value.code, info.value.clause) == ("classification", "Annex C")
    assert "unexpected '0'" in info.value.message  # one code for all faults: this is the one
    assert DetailedClassification.parse("N03 X+530*").formats["X"].zeros == Zeros.TRAILING


def test_a_value_of_zero_is_written_with_one_zero() -> None:
    out, _ = convert_text("%\nN1 G71\nN2 X0.000 Y-0.0\nN3 M30\n%\n",
                          ConvertOptions(load_profile("cm332-quadrant"), source=ISO_MILL))
    assert "N2 X0 Y0" in out.splitlines()


def test_indexed_g_words_are_left_to_the_profile() -> None:
    program = "%\nN1 G1=1 X1=5 F100\nN99 M30\n%\n"
    assert ("TG207", 2) in rules_of(program)
    allowed = profile_from_text('name = "g"\n[checks]\nindex_g = true\n')
    assert "TG207" not in {r for r, _ in rules_of(program, allowed)}


def test_decimal_arithmetic_is_exact() -> None:
    """1 in = 25.4 mm exactly (clause 4, 6.3): no binary floating point on the way."""
    out, _ = convert_text("%\nN1 G70\nN2 X0.1 Y3.3333\nN3 M30\n%\n",
                          ConvertOptions(ISO_MILL, source=ISO_MILL, units="metric"))
    assert "N2 X2.54 Y84.666" in out and Decimal("3.3333") * Decimal("25.4") == Decimal(
        "84.66582")
