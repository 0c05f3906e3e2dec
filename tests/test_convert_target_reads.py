"""A conversion says "ok" only for output the target reads: the target profile's own check, and
where the target is LinuxCNC its interpreter rs274 (the oracle, where installed), refuse
nothing the conversion carried.

1. `#` parameters and `[ ]` expressions: whether the target reads them is its profile's
   dialect (the characters it allows), not its family's. An ISO 6983-1 profile (iso-mill,
   iso-lathe, cm332-quadrant, pm322-eia, sinumerik-7e2) reads none of `#[]`: a FANUC
   `#1=2.5`, `X#1`, `X[#1*2]` converted for one said ok and its check refused the output
   (TG101, TG100). Refused at the source word now (docs/convert.md, "What the target reads").
2. A FANUC word rs274 refuses with the motion in force (`G1 X1 R5`, `G0 X1 P2`, `L`, `Q`, I J K
   outside arcs): refused at the word with rs274's message (docs/convert.md, "A letter
   LinuxCNC reads otherwise").
"""

from __future__ import annotations

import pytest

from formats.convert import ConvertOptions, convert_text
from formats.errors import ConversionError
from formats.parser import parse_text
from formats.profile import builtin_names, builtin_text, load_profile
from postproc.check import Checker

PROFILES = builtin_names()
FANUC = "O1000\nG21 G90 G17\n"


def convert(text: str, source: str, target: str) -> str:
    out, _ = convert_text(text, ConvertOptions(target=load_profile(target),
                                               source=load_profile(source)))
    return out


def target_errors(text: str, target: str) -> list[str]:
    """The errors of the target profile's check of ``text``: each as ``line:rule message``."""
    profile = load_profile(target)
    blocks = parse_text(text, profile.dialect, file="out.nc", errors="collect")
    return [f"{f.line}:{f.rule} {f.message}" for f in Checker(profile, file="out.nc").run(
        iter(blocks)) if f.severity == "error"]


def reads(target: str, character: str) -> bool:
    return character in load_profile(target).dialect.extra


# (program body after FANUC's head, the line and column of the refused character, which)
HASH_PROGRAMS = [
    ("#1=2.5\nG0 X0 Y0\nM30\n", 3, 1, "#"),
    ("G0 X0 Y0\nG1 X#1 F100\nM30\n", 4, 5, "#"),
    ("G0 X0 Y0\nG1 X[#1*2] F100\nM30\n", 4, 5, "["),
    ("G0 X0 Y0\nG1 X[1+2] F100\nM30\n", 4, 5, "["),
]


def test_the_profiles_that_read_no_hash_are_the_iso_ones_and_three_families():
    """The measure of the class: which built-in targets read `#` (their dialects), so that a
    new profile without `#` is covered by the tests below without a list to keep."""
    without = sorted(p for p in PROFILES if not reads(p, "#"))
    assert without == ["cm332-quadrant", "heidenhain-iso", "iso-lathe", "iso-mill",
                       "okuma-lathe", "okuma-mill", "pm322-eia", "sinumerik-7e2",
                       "sinumerik-840d"]
    # the ISO 6983-1 profiles among them are of the family that reads `#` where allowed
    assert {load_profile(p).dialect.family for p in without} >= {"iso"}


@pytest.mark.parametrize("target", [p for p in PROFILES
                                    if not reads(p, "#") and load_profile(p).dialect.family
                                    == "iso"])
@pytest.mark.parametrize("body, line, column, character", HASH_PROGRAMS)
def test_a_parameter_or_expression_is_refused_for_a_profile_whose_dialect_lacks_it(
        target, body, line, column, character):
    with pytest.raises(ConversionError) as err:
        convert(FANUC + body, "fanuc-mill", target)
    e = err.value
    assert (e.code, e.line, e.column) == ("conversion-dialect", line, column)
    assert "the target profile's dialect does not read" in e.message
    assert f"'{character}' is not among the characters it allows" in e.message
    # what the conversion refuses, the target's own check refuses in the source as written
    assert any(err.startswith(f"{line}:TG1") for err in target_errors(FANUC + body, target))


@pytest.mark.parametrize("target", ["sinumerik-840d", "okuma-mill"])
def test_a_family_that_reads_no_hash_still_names_both_families(target):
    with pytest.raises(ConversionError) as err:
        convert(FANUC + HASH_PROGRAMS[0][0], "fanuc-mill", target)
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-dialect", 3, 1)
    assert "a parameter of Custom Macro B (Fanuc, Haas), which a" in err.value.message
    assert "control does not read" in err.value.message


@pytest.mark.parametrize("target", ["fanuc-mill", "haas-mill", "linuxcnc"])
@pytest.mark.parametrize("body", [b for b, *_ in HASH_PROGRAMS])
def test_a_target_that_reads_hash_and_brackets_is_given_them_and_reads_them(target, body):
    out = convert(FANUC + body, "fanuc-mill", target)
    assert "#" in out or "[" in out
    assert not [e for e in target_errors(out, target) if e.split()[0].split(":")[1][:3]
                in ("TG1", "TG2")]


def test_a_user_iso_profile_that_allows_hash_is_given_the_parameter(tmp_path):
    """The dialect decides, not the family: an ISO 6983-1 profile of a user's whose characters
    include `#[]*` reads the FANUC parameter, which is carried."""
    text = builtin_text("iso-mill").replace('name = "iso-mill"',
                                            'name = "iso-mill-hash"\nextra_characters = "#[]*"')
    path = tmp_path / "iso-mill-hash.toml"
    path.write_text(text)
    profile = load_profile(str(path))
    assert profile.dialect.hash_parameters and profile.dialect.family == "iso"
    src = FANUC + "#1=2.5\nG0 X#1 Y0\nM30\n"
    out, _ = convert_text(src, ConvertOptions(target=profile, source=load_profile("fanuc-mill")))
    assert "#1=2.5" in out and "X#1" in out
    blocks = parse_text(out, profile.dialect, file="out.nc", errors="collect")
    assert not [f for f in Checker(profile, file="out.nc").run(iter(blocks))
                if f.severity == "error" and f.rule[:3] in ("TG1", "TG2")]



def nomacro(tmp_path):
    """A FANUC without Custom Macro B (docs/profiles.md, ``extra_characters``): the built-in
    fanuc-mill profile with ``;`` its only character beyond the ISO set."""
    text = builtin_text("fanuc-mill").replace('name = "fanuc-mill"', 'name = "fanuc-nomacro"')
    assert 'extra_characters = "#[]*;"' in text
    path = tmp_path / "fanuc-nomacro.toml"
    path.write_text(text.replace('extra_characters = "#[]*;"', 'extra_characters = ";"'))
    profile = load_profile(str(path))
    assert not profile.dialect.hash_parameters and profile.dialect.family == "fanuc"
    return profile


# (a statement of the source's family after FANUC's head and `G0 X0 Y0 Z5.`, line, column, the
# character refused)  review 26, finding 4: these were carried "ok" and the target's check
# refused the `#` (TG100)
STATEMENTS = [
    ("IF[#1EQ0]GOTO10\nG1 X1. F100.\nN10 M30\n", 4, 3, "["),
    ("WHILE[#1LT10]DO1\nG1 X1. F100.\nEND1\nM30\n", 4, 6, "["),
    ("G1 X1. F100.\nGOTO#2\nM30\n", 5, 5, "#"),
]


@pytest.mark.parametrize("source", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("body, line, column, character", STATEMENTS)
def test_a_macro_statement_is_refused_for_a_same_family_profile_whose_dialect_lacks_it(
        tmp_path, source, body, line, column, character):
    target = nomacro(tmp_path)
    text = FANUC + "G0 X0 Y0 Z5.\n" + body
    with pytest.raises(ConversionError) as err:
        convert_text(text, ConvertOptions(target=target, source=load_profile(source)))
    e = err.value
    assert (e.code, e.line, e.column) == ("conversion-dialect", line, column)
    assert "a statement with" in e.message
    assert f"'{character}' is not among the characters it allows" in e.message
    # the same program to the source's own profile is carried as written
    assert body.split("\n")[0] in convert(text, source, source)


@pytest.mark.parametrize("body, line, column, character", STATEMENTS + [
    # no `#` in it: the `[` alone (the check passed it, the converter refused it)
    ("WHILE[1LT10]DO1\nG1 X1. F100.\nEND1\nM30\n", 4, 6, "["),
    ("IF[1EQ0]GOTO10\nG1 X1. F100.\nN10 M30\n", 4, 3, "["),
    ("G1 X1. F100.\nGOTO[2*5]\nN10 M30\n", 5, 5, "["),
])
def test_the_check_reports_the_statement_where_the_converter_refuses_it(
        tmp_path, body, line, column, character):
    """One predicate (`Dialect::unread_character`): the check on a profile whose dialect
    lacks `#` / `[ ]` reports the macro statement at the character the conversion for that
    profile refuses, TG101 with file:line:col."""
    target = nomacro(tmp_path)
    text = FANUC + "G0 X0 Y0 Z5.\n" + body
    with pytest.raises(ConversionError) as err:
        convert_text(text, ConvertOptions(target=target, source=load_profile("fanuc-mill")))
    assert (err.value.line, err.value.column) == (line, column)
    blocks = parse_text(text, target.dialect, file="in.nc", errors="collect")
    found = [(f.rule, f.file, f.line, f.column, f.message)
             for f in Checker(target, file="in.nc").run(iter(blocks)) if f.severity == "error"]
    assert found == [("TG101", "in.nc", line, column,
                      f"character {character} of a macro statement is not among the characters "
                      "the profile allows: a control without it has no such statement and "
                      "refuses the block")], found
    # the source's own profile reads the statement
    fanuc = load_profile("fanuc-mill")
    blocks = parse_text(text, fanuc.dialect, file="in.nc", errors="collect")
    assert not [f for f in Checker(fanuc, file="in.nc").run(iter(blocks))
                if f.rule in ("TG100", "TG101")]


def test_a_statement_is_refused_at_the_first_character_of_the_block(tmp_path):
    """A word before the statement with `#` is refused first, where the block reads it."""
    target = nomacro(tmp_path)
    text = FANUC + "#1=0\nWHILE[#1LT10]DO1\nEND1\nM30\n"
    with pytest.raises(ConversionError) as err:
        convert_text(text, ConvertOptions(target=target, source=load_profile("fanuc-mill")))
    assert (err.value.line, err.value.column) == (3, 1)
    assert "a `#` parameter, which" in err.value.message


def test_a_statement_without_those_characters_is_carried(tmp_path):
    """A FANUC GOTO with a plain number has no `#` or `[ ]`: carried, and read by the target."""
    target = nomacro(tmp_path)
    text = FANUC + "G0 X0 Y0 Z5.\nGOTO10\nG1 X1. F100.\nN10 M30\n"
    out, _ = convert_text(text, ConvertOptions(target=target, source=load_profile("fanuc-mill")))
    assert "GOTO10" in out
    blocks = parse_text(out, target.dialect, file="out.nc", errors="collect")
    assert not [f for f in Checker(target, file="out.nc").run(iter(blocks))
                if f.severity == "error"]


# -- 2. words LinuxCNC refuses with the motion in force ---------------------------------------

LETTERS_REFUSED = [
    # (the FANUC block after `G0 X0 Y0 Z5.`, the refused word, the motion LinuxCNC runs)
    ("G1 X1. R5. F100.", "R5.", "G1"),
    ("G0 X1. P2", "P2", "G0"),
    ("G1 X1. L2 F100.", "L2", "G1"),
    ("G1 X1. Q2. F100.", "Q2.", "G1"),
    ("G1 X1. I1. F100.", "I1.", "G1"),
    ("G0 X1. J1.", "J1.", "G0"),
    ("G1 X1. K1. F100.", "K1.", "G1"),
    ("G2 X1. Y1. R1. L2 F100.", "L2", "G2"),
    ("G2 X1. Y1. R1. Q2. F100.", "Q2.", "G2"),
    ("G81 X1. Y1. Z-1. R1. P1000 F100.", "P1000", "G81"),  # G81 has no dwell on LinuxCNC
    ("G81 X1. Y1. Z-1. R1. Q1. F100.", "Q1.", "G81"),
    ("G81 X1. Y1. Z-1. R1. K2 F100.", "K2", "G81"),  # FANUC's repeat count: LinuxCNC's is L
    ("G1 X2. F100.\nX3. R1.", "R1.", "G1"),  # the motion in force
    ("G1 X2. F100.\nR1.", "R1.", None),  # no axis word: no motion runs the block
    ("M99 P10", "P10", None),  # FANUC's return to N10
]

LETTERS_CARRIED = [
    "G2 X1. Y1. R1. F100.",
    "G2 X1. Y1. I0 J1. F100.",
    "G1 X2. F100.\nG2 X3. Y1. I.5 J.5",
    "G81 X1. Y1. Z-1. R1. F100.\nX2. R2.",  # the cycle in force reads R
    "G82 X1. Y1. Z-1. R1. P1000 F100.",
    "G83 X1. Y1. Z-1. R1. Q.5 F100.",
    "G73 X1. Y1. Z-1. R1. Q.5 F100.",
    "G4 P1000",
    "G10 L2 P1 X1.",
    "G43 H1 Z10.",
]


def linuxcnc_program(block: str) -> str:
    return f"{FANUC}G0 X0 Y0 Z5.\n{block}\nM30\n"


@pytest.mark.parametrize("block, word, runs", LETTERS_REFUSED)
def test_a_word_linuxcnc_refuses_with_the_motion_in_force_is_refused_at_the_word(
        tmp_path, block, word, runs):
    text = linuxcnc_program(block)
    with pytest.raises(ConversionError) as err:
        convert(text, "fanuc-mill", "linuxcnc")
    e = err.value
    lines = text.splitlines()
    line = max(i for i, t in enumerate(lines, 1) if word in t.split())
    column = lines[line - 1].split().index(word)
    column = len(" ".join(lines[line - 1].split()[:column])) + (2 if column else 1)
    assert (e.code, e.line, e.column) == ("conversion-meaning", line, column)
    letter = word[0]
    said = e.message.split(" (rs274ngc)")[0]
    assert said.startswith(f"{word}: {letter} word with no ")
    assert (f"which runs {runs} there" if runs else "which runs no motion there") in e.message
    # the oracle: rs274 refuses the block written as it stands, with the message the
    # conversion gives
    from tests.conftest import rs274_output
    ngc = text.replace("O1000\n", "").replace("M30", "M2")
    assert said.split(": ", 1)[1] in rs274_output(tmp_path, ngc)


@pytest.mark.parametrize("block", ["G05.1 Q1", "G05.1 Q1 R5", "G05.1 Q0"])
@pytest.mark.parametrize("source", ["fanuc-mill", "haas-mill"])
def test_a_code_of_another_meaning_is_refused_as_such_before_linuxcnc_reads_its_words(
        source, block):
    """Review 26 (doubtful list): a FANUC `G05.1 Q1` (AI contour control) was refused at the
    Q with a reason of LinuxCNC's G5.1 (a quadratic spline), which is not what the block
    means on the source. The code is refused first, as the two controls' profiles give it
    different meanings."""
    with pytest.raises(ConversionError) as err:
        convert(linuxcnc_program(block), source, "linuxcnc")
    e = err.value
    assert (e.code, e.line, e.column) == ("conversion", 4, 1)
    assert e.message.startswith("G05.1: the source and target controls give this code "
                                "different meanings")
    assert "G5.1" not in e.message and "Q word" not in e.message


@pytest.mark.parametrize("block, column", [
    ("G2 X1. Y1. R1. P1 F100.", 16),
    ("G1 X2. F100.\nG3 X3. Y1. I.5 J.5 Z-1. P2", 25),
    ("G2 X1. Y1. R1. F100.\nX0 Y0 R1. P3", 11),  # the arc in force
])
@pytest.mark.parametrize("source", ["fanuc-mill", "haas-mill"])
def test_an_arc_s_p_is_refused_where_linuxcnc_reads_it_as_the_helix_s_turns(
        tmp_path, source, block, column):
    """Review 26 (doubtful list): a FANUC or Haas `G2 ... P1` was carried as written, and
    rs274 runs it, P the number of turns of the helix (LinuxCNC G-code reference, G2/G3);
    neither the FANUC tape format list nor the Haas G02/G03 page gives P a meaning in an arc,
    so the output would cut another path. Refused at the P."""
    from tests.conftest import rs274_output
    text = linuxcnc_program(block)
    with pytest.raises(ConversionError) as err:
        convert(text, source, "linuxcnc")
    e = err.value
    assert (e.code, e.line, e.column) == ("conversion-meaning", text.count("\n") - 1, column)
    assert "P in an arc is the number of the helix's turns on LinuxCNC" in e.message
    # rs274 runs the block as written (no refusal of its own): the meaning differs, not the
    # reading
    said = rs274_output(tmp_path, text.replace("O1000\n", "").replace("M30", "M2"))
    assert " word with no " not in said and "ERROR" not in said.upper(), said


def test_an_arc_s_p_is_carried_between_linuxcnc_profiles_and_a_dwell_s_p_beside_none():
    out = convert("G21 G90 G17\nG0 X0 Y0 Z5.\nG2 X1. Y1. R1. P2 F100.\nM2\n", "linuxcnc",
                  "linuxcnc")
    assert "P2" in out
    out = convert(linuxcnc_program("G1 X1. F100.\nG04 P1000"), "fanuc-mill", "linuxcnc")
    assert "P1." in out


@pytest.mark.parametrize("block", LETTERS_CARRIED)
def test_a_word_a_code_of_its_block_uses_is_carried_and_rs274_reads_it(tmp_path, block):
    from tests.conftest import rs274_output
    out = convert(linuxcnc_program(block), "fanuc-mill", "linuxcnc")
    said = rs274_output(tmp_path, out)
    assert " word with no " not in said, said
    # and the target's own check reads it as rs274 does
    assert not [e for e in target_errors(out, "linuxcnc") if " word with no " in e]


def test_the_check_refuses_what_the_conversion_refuses():
    """One predicate (meaning::linuxcnc_word_used) for both readers: each block the conversion
    refuses, written as it stands for LinuxCNC, is refused by the check's TG412 with the
    same rs274 message, on the same line; each block it carries is not."""
    for block, word, _ in LETTERS_REFUSED:
        ngc = f"G21 G90 G17\nG0 X0 Y0 Z5.\n{block}\nM2\n"
        found = [e for e in target_errors(ngc, "linuxcnc") if f"{word[0]} word with no " in e]
        assert found and found[0].split()[0].endswith(":TG412"), (block, found)
    for block in LETTERS_CARRIED:
        ngc = f"G21 G90 G17\nG0 X0 Y0 Z5.\n{block}\nM2\n"
        assert not [e for e in target_errors(ngc, "linuxcnc") if " word with no " in e], block


# -- 3. what the sweep (benchmarks/convert_targets.py) found besides ---------------------------


@pytest.mark.parametrize("target", ["iso-mill", "iso-lathe", "sinumerik-7e2", "cm332-quadrant",
                                    "pm322-eia"])
def test_an_arc_by_its_radius_is_refused_for_a_profile_whose_r_is_a_parameter(target):
    """iso-mill's checks.pqr makes R a parameter: its check finds no centre for `G2 X.. R..`
    (TG404 "arc without I J (or R)"), which the conversion carried and called ok."""
    profile = load_profile(target)
    assert profile.checks.pqr.get("R") != "length"
    text = FANUC + "G0 X0 Y0\nG2 X20. Y0 R10. F100.\nM30\n"
    assert any(":TG404 " in e for e in target_errors(text, target))
    with pytest.raises(ConversionError) as err:
        convert(text, "fanuc-mill", target)
    e = err.value
    assert (e.code, e.line, e.column) == ("conversion", 4, 12)
    assert "the target profile reads no radius (its R is a parameter" in e.message
    # by its centre the arc converts, and the target's check reads it
    by_centre = text.replace("R10.", "I10. J0")
    if target not in ("cm332-quadrant",):  # (its I J are sign-less quadrant values: refused)
        out = convert(by_centre, "fanuc-mill", target)
        assert not [x for x in target_errors(out, target) if ":TG40" in x]


@pytest.mark.parametrize("target", [p for p in PROFILES if p in (
    "iso-mill", "iso-lathe", "sinumerik-7e2")])
def test_a_colon_in_a_comment_is_refused_for_a_tape_reader_that_stops_there(target):
    """ISO 6983-1 5.1: ':' is the alignment function (the rewind stop); the ISO profiles' check
    refuses it in a comment (TG122). A FANUC `(T1: 10 MM DRILL)` was carried and called ok."""
    text = FANUC + "(T1: 10 MM DRILL)\nG0 X0 Y0\nM30\n"
    assert any(":TG122 " in e for e in target_errors(text, target))
    with pytest.raises(ConversionError) as err:
        convert(text, "fanuc-mill", target)
    e = err.value
    assert (e.code, e.line, e.column) == ("conversion-dialect", 3, 4)
    assert "a ':' in a comment, which the target's tape reader takes for the alignment" in (
        e.message)
    # without the ':' it converts, and to a control that does not stop there it is carried
    assert "(T1 10 MM DRILL)" in convert(text.replace(":", ""), "fanuc-mill", target)
    assert "(T1: 10 MM DRILL)" in convert(text, "fanuc-mill", "haas-mill")
