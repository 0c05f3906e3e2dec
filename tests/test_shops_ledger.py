"""The ledger of issue 32's measure (``benchmarks/shops.py --ledger``): how the programs that do
not read are counted against it, on a folder of this file's own small programs.

A program that reads counts as complete, with or without a row (a row for it is stale); a P or
F program leaves the issue's denominator; a D or T program stays in it and is listed; a program
that does not read and has no row is unclassified and stays in the denominator.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from .test_shops import DOUBTFUL, GAPS, SHOPS, TRUE_ERRORS, needs_shops, shops_module

PROGRAMS = {
    # family, file: the program
    ("fanuc", "good.nc"): "%\nO1000\nG21 G90 G17 G00 X0 Y0 Z10.\nM30\n%\n",
    ("fanuc", "stale.nc"): "%\nO1001\nG21 G90 G17 G00 X0 Y0 Z10.\nG01 X5. F100.\nM30\n%\n",
    # the letter O typed for a zero: G with no number
    ("fanuc", "letter_o.nc"): "%\nO1002\nG21 G90 G17 G00 X0 Y0 Z10.\nGOO Z1.\nM30\n%\n",
    # WH for WHILE, refused by name
    ("fanuc", "wh.nc"): "%\nO1003\nG21 G90 G17 G00 X0 Y0 Z10.\n#1=1\nWH[#1GT0]DO1\n#1=#1-1\n"
                        "END1\nM30\n%\n",
    # two decimal points, no row in the ledger
    ("fanuc", "twopoints.nc"): "%\nO1004\nG21 G90 G17 G00 X0 Y0 Z10.\nX1.2.\nM30\n%\n",
    # a stray ':' at the end of an assignment: a block left unread whose finding is a warning
    ("fanuc", "colon.nc"): "%\nO1005\nG21 G90 G17 G00 X0 Y0 Z10.\n#1=#1-#11:\nM30\n%\n",
    # a simulator's line
    ("haas", "sim.nc"): "%\nO01006\nG20 G90 G17 G00 X0 Y0 Z1.\n$AddRegPart 1 X1. Y1.\nM30\n%\n",
    # an address apart from its number
    ("haas", "apart.nc"): "%\nO01007\nG20 G90 G17 G00 X0 Y0 Z1.\nX 1.\nM30\n%\n",
}

HEADER = "# set\tprogram\tprofile\tat\tcode\tclass\tevidence\n"
ROWS = [
    ("s1", "stale.nc", "fanuc-mill", "4:1", "TG100", "T", "open"),
    ("s1", "letter_o.nc", "fanuc-mill", "4:2", "TG100", "P", "GOO: the letter O for a zero"),
    ("s1", "wh.nc", "fanuc-mill", "5:1", "TG100", "D", "WH: no source documents it"),
    ("s1", "colon.nc", "fanuc-mill", "4:11", "TG125", "P", "a stray ':'"),
    ("s2", "sim.nc", "haas-mill", "4:1", "TG101", "F", "a simulator's line"),
    # the first error is at 4:2, not where this row puts it
    ("s2", "apart.nc", "haas-mill", "4:9", "TG100", "T", "open"),
    ("s3", "elsewhere.nc", "fanuc-mill", "1:1", "TG100", "P", "a program not measured here"),
]


def folder(tmp_path: Path, programs: dict[tuple[str, str], str], name: str = "set") -> Path:
    out = tmp_path / name
    out.mkdir()
    families = []
    for (family, file), text in programs.items():
        (out / file).write_text(text, encoding="ascii")
        families.append(f"{family}\t{file}\ta hand-made mill program\n")
    (out / "families.tsv").write_text("".join(families), encoding="utf-8")
    return out


def ledger(tmp_path: Path, rows=ROWS, name: str = "ledger.tsv") -> Path:
    path = tmp_path / name
    path.write_text(HEADER + "".join("\t".join(row) + "\n" for row in rows), encoding="utf-8")
    return path


@pytest.fixture
def shops():
    return shops_module()


@pytest.fixture
def report(tmp_path, shops):
    root = folder(tmp_path, PROGRAMS)
    results = [shops.measure(root / file, family, shops.profile_for(family, "mill"))
               for family, file in PROGRAMS]
    return results, shops.ledger_report(results, shops.read_ledger(ledger(tmp_path)))


def test_the_first_reading_error_is_named_by_place_and_rule(report):
    results, _ = report
    first = {r.name: (r.complete, r.first_at, r.first_code) for r in results}
    assert first == {
        "good.nc": (True, "", ""),
        "stale.nc": (True, "", ""),
        "letter_o.nc": (False, "4:2", "TG100"),
        "wh.nc": (False, "5:1", "TG100"),
        "twopoints.nc": (False, "4:5", "TG100"),
        # the block is left unread, and the reader's finding for it is a warning (TG125)
        "colon.nc": (False, "4:11", "TG125"),
        "sim.nc": (False, "4:1", "TG101"),
        "apart.nc": (False, "4:2", "TG100"),
    }


def test_each_family_is_counted_against_the_ledger(report):
    _, got = report
    fanuc, haas, total = got.tallies["fanuc"], got.tallies["haas"], got.total
    # fanuc: good and stale read; letter_o and colon P; wh D; twopoints unclassified
    assert (fanuc.programs, fanuc.complete, fanuc.counted) == (6, 2, 4)
    assert dict(fanuc.classes) == {"P": 2, "D": 1} and fanuc.unclassified == 1
    # haas: sim F; apart T
    assert (haas.programs, haas.complete, haas.counted) == (2, 0, 1)
    assert dict(haas.classes) == {"F": 1, "T": 1} and haas.unclassified == 0
    assert (total.programs, total.complete, total.counted, total.unclassified) == (8, 2, 5, 1)


def test_stale_unclassified_moved_and_listed_rows_are_reported(report):
    _, got = report
    assert [row.program for row in got.stale] == ["stale.nc"]
    assert [r.name for r in got.unclassified] == ["twopoints.nc"]
    assert [(row.program, r.first_at) for row, r in got.moved] == [("apart.nc", "4:2")]
    assert sorted((row.klass, row.program) for row in got.listed) == [
        ("D", "wh.nc"), ("T", "apart.nc")]
    assert got.elsewhere == 1


def test_the_command_prints_the_issue_s_figure(tmp_path, shops, capsys):
    root = folder(tmp_path, PROGRAMS)
    assert shops.main(["--shops", str(root), "--ledger", str(ledger(tmp_path))]) == 0
    out = capsys.readouterr().out
    assert "2 of 8 programs read completely" in out
    lines = {line.split()[0]: line for line in out.splitlines() if line.split()}
    assert lines["total"].split()[1:9] == ["2/8", "(25.0", "%)", "2/5", "(40.0", "%)", "2", "1"]
    assert lines["fanuc"].split()[1:4] == ["2/6", "(33.3", "%)"]
    assert "unclassified: twopoints.nc (fanuc-mill) 4:5 TG100" in out
    assert "ledger row stale: stale.nc (s1, T) now reads completely" in out
    assert "ledger row moved: apart.nc: the ledger has haas-mill 4:9 TG100, now haas-mill " \
           "4:2 TG100" in out
    assert "D s1      wh.nc 5:1 TG100\n           WH: no source documents it" in out


def test_several_folders_are_counted_as_one_and_json_carries_the_figure(tmp_path, shops,
                                                                          capsys):
    items = list(PROGRAMS.items())
    one = folder(tmp_path, dict(items[:4]), "one")
    two = folder(tmp_path, dict(items[4:]), "two")
    assert shops.main(["--json", "--shops", str(one), "--shops", str(two),
                       "--ledger", str(ledger(tmp_path))]) == 0
    last = json.loads(capsys.readouterr().out.splitlines()[-1])["ledger"]
    assert last["total"] == {"programs": 8, "complete": 2, "counted": 5,
                             "classes": {"T": 1, "P": 2, "D": 1, "F": 1}, "unclassified": 1}
    assert last["unclassified"] == ["twopoints.nc"] and last["stale"] == ["stale.nc"]
    assert sorted((row["class"], row["program"], row["at"]) for row in last["listed"]) == [
        ("D", "wh.nc", "5:1"), ("T", "apart.nc", "4:9")]
    assert last["moved"] == ["apart.nc"] and last["elsewhere"] == 1


@pytest.mark.parametrize("row, message", [
    (("s1", "a.nc", "fanuc-mill", "1:1", "TG100", "X", "?"), "class 'X' is none of"),
    (("s1", "a.nc", "fanuc-mill", "1:1", "TG100", "P"), "7 cells"),
    (("s1", "a.nc", "fanuc-mill", "1:1", "TG100", "P", " "), "7 cells"),
])
def test_a_ledger_row_it_cannot_read_is_refused(tmp_path, shops, capsys, row, message):
    root = folder(tmp_path, PROGRAMS)
    path = ledger(tmp_path, [row])
    with pytest.raises(ValueError, match=message):
        shops.read_ledger(path)
    assert shops.main(["--shops", str(root), "--ledger", str(path)]) == 2
    assert message in capsys.readouterr().err


def test_a_program_named_twice_is_refused(tmp_path, shops):
    with pytest.raises(ValueError, match="letter_o.nc has a row already"):
        shops.read_ledger(ledger(tmp_path, [ROWS[1], ROWS[1]]))


def test_the_project_s_ledger_reads_and_names_each_program_of_a_set_once(shops):
    """benchmarks/unseen/ledger.tsv: every row of a set the tsv files list, a class, an
    evidence; the held files are outside the project, so their counting is not tested here."""
    unseen = Path(__file__).resolve().parents[1] / "benchmarks" / "unseen"
    rows = shops.read_ledger(unseen / "ledger.tsv")
    listed: dict[str, str] = {}
    for tsv in unseen.glob("held*.tsv"):
        for line in tsv.read_text(encoding="utf-8").splitlines():
            if line.strip() and not line.startswith("#"):
                listed[line.split("\t")[1]] = tsv.stem
    for row in rows.values():
        if row.set == "shops":
            continue
        assert listed.get(row.program) == row.set, row.program
        assert row.profile in {p for pair in shops.FAMILY_PROFILES.values() for p in pair}


@needs_shops
def test_the_ledger_classes_every_shops_program_that_does_not_read(shops):
    """The ledger's shops rows are tests/test_shops.py's lists: P its true errors, D its
    doubtful ones; no program of the folder is unclassified, and no row is stale."""
    unseen = Path(__file__).resolve().parents[1] / "benchmarks" / "unseen"
    rows = shops.read_ledger(unseen / "ledger.tsv")
    mine = {row.program: row.klass for row in rows.values() if row.set == "shops"}
    assert {p for p, k in mine.items() if k == "P"} == TRUE_ERRORS
    assert {p for p, k in mine.items() if k == "D"} == DOUBTFUL
    assert {p for p, k in mine.items() if k == "T"} == GAPS
    results = [shops.measure(SHOPS / name, family, profile)
               for name, family, description in shops.entries(SHOPS)
               if (profile := shops.profile_for(family, description))]
    got = shops.ledger_report(results, rows)
    assert got.unclassified == [] and got.stale == [] and got.moved == []


@pytest.mark.parametrize("printed, line", [("a\nb\nX\n", 3), ("a\nb\n", 3), ("a\nX\nc\n", 2)])
def test_a_reprint_that_differs_is_placed_at_its_first_differing_line(tmp_path, shops,
                                                                      monkeypatch, printed,
                                                                      line):
    """Where only the reprint differs (no reading error names a place), the ledger's place is
    the first line the reprint and the file do not share."""
    path = tmp_path / "p.nc"
    path.write_bytes(b"a\nb\nc\n")
    monkeypatch.setattr(shops, "program_text", lambda read: printed)
    assert shops.first_difference([], path) == line


def test_a_block_left_unread_that_no_finding_names_is_placed_at_its_line(tmp_path, shops,
                                                                          monkeypatch):
    """The checker names every block the reader left; were one left unnamed, the ledger's
    place is still its line, with the code 'unread', not a program counted as reading."""
    class Silent:
        def __init__(self, *args, **kwargs):
            pass

        def run(self, blocks):
            return iter(())

    path = tmp_path / "p.nc"
    path.write_text(PROGRAMS[("fanuc", "letter_o.nc")], encoding="ascii")
    monkeypatch.setattr(shops, "Checker", Silent)
    result = shops.measure(path, "fanuc", "fanuc-mill")
    assert not result.complete and result.unread == 1
    assert (result.first_at, result.first_code) == ("4:0", "unread")


# -- each program counted once; the ledger's set checked against the folder's -----------------


def test_a_folder_given_twice_is_counted_once_and_the_dropped_are_said(tmp_path, shops, capsys):
    root = folder(tmp_path, PROGRAMS)
    path = ledger(tmp_path)
    assert shops.main(["--shops", str(root), "--ledger", str(path)]) == 0
    once = capsys.readouterr().out
    assert shops.main(["--shops", str(root), "--shops", str(root), "--ledger", str(path)]) == 0
    twice = capsys.readouterr().out
    assert "2 of 8 programs read completely" in twice
    total = [line for line in twice.splitlines() if line.startswith("total")]
    assert total == [line for line in once.splitlines() if line.startswith("total")]
    assert total[0].split()[1:9] == ["2/8", "(25.0", "%)", "2/5", "(40.0", "%)", "2", "1"]
    assert "8 programs were given again and dropped (each program is counted once, by its " \
           "name):" in twice
    assert f"  dropped: wh.nc in {root} (the same bytes as the one counted, in {root})" in twice
    assert twice.count("dropped: ") == 8 and "given again" not in once
    # each program's line is printed once: the second copy is not measured
    assert twice.count("INCOMPLETE fanuc-mill      wh.nc") == 1


def test_a_union_folder_beside_its_set_counts_the_set_once_in_json(tmp_path, shops, capsys):
    """A union folder already holds the four programs of the folder given after it: they are
    dropped, and the JSON figure is the one of the eight programs."""
    items = list(PROGRAMS.items())
    union = folder(tmp_path, PROGRAMS, "all")
    two = folder(tmp_path, dict(items[4:]), "two")
    assert shops.main(["--json", "--shops", str(union), "--shops", str(two),
                       "--ledger", str(ledger(tmp_path))]) == 0
    lines = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert sorted(lines[-2]["dropped"]) == sorted(file for (_, file), _ in items[4:])
    assert lines[-2]["programs"] == 8
    assert lines[-1]["ledger"]["total"]["programs"] == 8


def test_the_same_name_with_other_bytes_is_dropped_and_said_so(tmp_path, shops, capsys):
    one = folder(tmp_path, {("fanuc", "p.nc"): PROGRAMS[("fanuc", "good.nc")]}, "one")
    two = folder(tmp_path, {("fanuc", "p.nc"): PROGRAMS[("fanuc", "twopoints.nc")]}, "two")
    assert shops.main(["--shops", str(one), "--shops", str(two)]) == 0
    out = capsys.readouterr().out
    # the first folder's program is the one counted: it reads
    assert "1 of 1 programs read completely" in out
    assert f"  dropped: p.nc in {two} (OTHER BYTES as the one counted, in {one})" in out


SETS = {
    # a folder named as a set holds that set's programs; the ledger puts them in these sets
    "held3": {("fanuc", "letter_o.nc"): PROGRAMS[("fanuc", "letter_o.nc")]},
    "held4": {("fanuc", "wh.nc"): PROGRAMS[("fanuc", "wh.nc")]},
}
SET_ROWS = [
    ("held3", "letter_o.nc", "fanuc-mill", "4:2", "TG100", "P", "GOO: the letter O for a zero"),
    # the ledger says held3, the program is held4's: the row is not applied
    ("held3", "wh.nc", "fanuc-mill", "5:1", "TG100", "D", "WH: no source documents it"),
]


@pytest.mark.parametrize("union", [False, True])
def test_a_ledger_row_of_another_set_is_not_applied(tmp_path, shops, capsys, union):
    """The set a program came from is known from its folder's name (OUT/held4) or, in a union
    folder (OUT/all), from the sibling set folder listing it; a row of another set names
    another program of the same name: the program counts as unclassified, and the run says
    why."""
    out = tmp_path / "out"
    out.mkdir()
    folders = [folder(out, programs, name) for name, programs in SETS.items()]
    if union:
        folders = [folder(out, {k: v for p in SETS.values() for k, v in p.items()}, "all")]
    assert {k: v for f in folders for k, v in shops.folder_sets(f).items()} == {
        "letter_o.nc": "held3", "wh.nc": "held4"}
    argv = [arg for f in folders for arg in ("--shops", str(f))]
    assert shops.main([*argv, "--ledger", str(ledger(tmp_path, SET_ROWS))]) == 0
    printed = capsys.readouterr().out
    assert "ledger row of another set: wh.nc: the ledger's row is held3's, the program came " \
           "from held4: not applied" in printed
    assert "unclassified: wh.nc (fanuc-mill) 5:1 TG100" in printed
    total = next(line for line in printed.splitlines() if line.startswith("total"))
    # letter_o P (out of the denominator), wh unclassified (in it)
    assert total.split()[1:] == ["0/2", "(0.0", "%)", "0/1", "(0.0", "%)", "1", "0", "0", "0",
                                 "1"]


def test_a_folder_of_no_set_checks_no_set(tmp_path, shops):
    """A folder whose name is no set's, with no set folder beside it: the sets are not known,
    and the ledger's rows apply by name."""
    root = folder(tmp_path, SETS["held4"], "mine")
    assert shops.folder_sets(root) == {}
    result = shops.measure(root / "wh.nc", "fanuc", "fanuc-mill")
    got = shops.ledger_report([result], {row[1]: shops.LedgerRow(*row) for row in SET_ROWS})
    assert got.other_set == [] and [row.program for row in got.listed] == ["wh.nc"]


def test_a_folder_without_families_tsv_among_several_is_an_error(tmp_path, shops, capsys):
    """Nothing is measured and the exit is 2: a run over some folders only would print a
    figure for fewer programs, or, as before, none with exit 0."""
    root = folder(tmp_path, PROGRAMS)
    empty = tmp_path / "empty"
    empty.mkdir()
    assert shops.main(["--shops", str(root), "--shops", str(empty),
                       "--ledger", str(ledger(tmp_path))]) == 2
    got = capsys.readouterr()
    assert got.err == f"no families.tsv in {empty}: nothing measured\n"
    assert got.out == ""
    with pytest.raises(ValueError, match="no families.tsv in"):
        shops.programs([empty])
