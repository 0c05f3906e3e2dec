"""Review 27's findings, each a conversion that said "ok" for output the target reads otherwise
(or refused one it reads alike): the reset feed mode both ways, the text after a FANUC's `%`,
a lathe's X0, a code the target's table lacks, and G10's X between a lathe and a mill
(docs/convert.md)."""

from __future__ import annotations

import pytest

from formats.errors import ConversionError
from formats.profile import load_profile
from postproc.check import check_text

from .test_convert_target_reads import convert, target_errors


def refusal(text: str, source: str, target: str) -> ConversionError:
    with pytest.raises(ConversionError) as err:
        convert(text, source, target)
    return err.value


# -- 1. the reset feed mode, both ways (findings 1, 3 and 5) ----------------------------------

MILL_Z = "O1000\nG40\nG0 Z0.2\nG1 Z-0.5 F20.\nG0 Z1.\nM30\n"


@pytest.mark.parametrize("source", ["haas-mill", "fanuc-mill", "linuxcnc"])
@pytest.mark.parametrize("target", ["haas-lathe", "fanuc-lathe", "fanuc-lathe-b",
                                    "okuma-lathe"])
def test_a_feed_per_minute_by_the_reset_state_is_refused_for_a_lathe_that_feeds_per_rev(
        source, target):
    """A mill's F20. (in/min at its reset G94) read by the lathe's reset G99/G95 is 20 in a
    revolution: refused at the F, as the other direction is."""
    text = MILL_Z if source != "linuxcnc" else MILL_Z.replace("O1000\n", "")
    e = refusal(text, source, target)
    line = 4 if source != "linuxcnc" else 3
    assert (e.line, e.column) == (line, 10), e
    assert e.message.startswith("F20.: a feed per minute by the source control's reset state "
                                "(no feed mode code written before it), where the target's "
                                "reset feeds per revolution"), e.message


def test_the_advice_names_a_code_both_read_alike_or_says_the_program_cannot_be_converted():
    text = "G21 G17 G40\nG0 Z5.\nG1 Z-5. F100.\nM30\n"
    # system B's G94 is LinuxCNC's: the advice names it, and following it converts
    e = refusal(text, "linuxcnc", "fanuc-lathe-b")
    assert e.message.endswith("write G94 before the first F in the source (both controls read "
                              "it so)"), e.message
    out = convert(text.replace("G0 Z5.", "G94\nG0 Z5."), "linuxcnc", "fanuc-lathe-b")
    assert "G94" in out and "F100." in out
    # a system A lathe's per-minute code is G98, a mill's return level: no code converts
    e = refusal(text, "linuxcnc", "fanuc-lathe")
    assert "the program cannot be converted to this target as it stands" in e.message
    # the other way: system B's G95 is carried to LinuxCNC, system A's G99 is not
    lathe = "O1000\nG21 G18 G40 G97\nG0 Z5.\nG1 Z-5. F0.2\nM30\n"
    e = refusal(lathe, "fanuc-lathe-b", "linuxcnc")
    assert e.message.endswith("write G95 before the first F in the source (both controls read "
                              "it so)"), e.message
    assert "F0.2" in convert(lathe.replace("G0 Z5.", "G95\nG0 Z5."), "fanuc-lathe-b",
                             "linuxcnc")
    e = refusal(lathe, "fanuc-lathe", "linuxcnc")
    assert "cannot be converted to this target" in e.message
    assert "write G99" not in e.message


def test_iso_lathe_resets_to_feed_per_minute_by_clause_14_4():
    """iso-lathe lists no reset: ISO 6983-1 14.4 (contouring on lathes) gives G94, so a FANUC
    lathe's reset feed per revolution is refused there and an Okuma lathe's (G95) too, and a
    LinuxCNC program (G94) is carried."""
    lathe = "O1000\nG18 G40 G97\nG0 Z5.\nG1 Z-5. F0.2\nM30\n"
    e = refusal(lathe, "fanuc-lathe", "iso-lathe")
    assert (e.line, e.column) == (4, 9), e
    assert "where the target's reset feeds per minute" in e.message
    assert "F0.2" in convert(lathe, "fanuc-lathe", "okuma-lathe")
    out = convert("G7 G18 G21\nG0 X20. Z5.\nG1 X10. Z-5. F100.\nM30\n", "linuxcnc", "iso-lathe")
    assert "F100." in out


def test_a_feed_mode_code_the_target_does_not_read_so_is_refused_at_the_code():
    """A system A lathe's G99 written as the refusal used to advise: ISO 6983-1's table leaves
    G99 unassigned (iso-lathe's check: TG302), so the F after it would be per minute there."""
    text = "O1000\nG18 G40 G97 G99\nG0 Z5.\nG1 Z-5. F0.2\nM30\n"
    assert any("G99" in w for w in _warnings(text, "iso-lathe"))
    e = refusal(text, "fanuc-lathe", "iso-lathe")
    assert (e.line, e.column) == (2, 13), e
    assert e.message.startswith("G99: the source's code of feed per revolution, whose number "
                                "the target reads as another code or none"), e.message
    # system B's G95 is ISO 6983-1's G95: carried
    out = convert(text.replace("G99", "G95"), "fanuc-lathe-b", "iso-lathe")
    assert "G95" in out and "F0.2" in out


def test_a_lathe_program_with_the_same_reset_feed_mode_keeps_its_f():
    text = "O0001\nG21\nG00 Z2.\nG01 Z-5. F0.2\nM30\n"
    assert "F0.2" in convert(text, "fanuc-lathe", "fanuc-lathe-b")
    assert "F0.2" in convert(text.replace("G21\n", ""), "haas-lathe", "okuma-lathe")
    mill = "O0001\nG21 G17\nG00 Z2.\nG01 Z-5. F100.\nM30\n"
    assert "F100." in convert(mill, "fanuc-mill", "haas-mill")


def _warnings(text: str, target: str) -> list[str]:
    from formats.parser import parse_text
    from formats.profile import load_profile
    from postproc.check import Checker
    profile = load_profile(target)
    blocks = parse_text(text, profile.dialect, file="out.nc", errors="collect")
    return [f"{f.line}:{f.rule} {f.message}" for f in Checker(profile, file="out.nc").run(
        iter(blocks)) if f.severity == "warning"]


# -- 2. the text after a FANUC's leader `%`, as the target reads it (findings 2 and 6) --------

BODY = "O0003\nG21 G17 G40 G80 G90\nG0 X0 Y0\nM30\n%\n"


@pytest.mark.parametrize("leader", ["%(TITLE)", "%:0003", "%;", "%TITLE", "%O0003",
                                    "%(A)(B)"])
def test_any_text_after_the_leader_is_refused_for_linuxcnc(leader, tmp_path):
    from tests.conftest import rs274_output
    text = leader + "\n" + BODY
    # LinuxCNC refuses the line as written (rs274, and its check's TG412)
    assert "Bad character '%' used" in rs274_output(tmp_path, text.replace("M30", "M2"))
    assert any(e.startswith("1:TG412 ") for e in target_errors(text, "linuxcnc"))
    e = refusal(text, "fanuc-mill", "linuxcnc")
    assert (e.line, e.column) == (1, 2), e
    assert e.message.startswith(f"\"{leader[1:]}\": text after the first '%'"), e.message
    assert "LinuxCNC reads no text after it (rs274: \"Bad character '%' used\"" in e.message


@pytest.mark.parametrize("target", ["haas-mill", "iso-mill", "pm322-eia"])
@pytest.mark.parametrize("leader, rule", [("%TITLE", "TG112"), ("%;X1", "TG112"),
                                          ("%O0003", "TG111"), ("% X-1", "TG111")])
def test_a_leader_the_iso_reader_takes_for_words_or_letters_is_refused(target, leader, rule):
    """A Haas's check gives TG137, a warning (no Haas source says what the control does with
    the text); the conversion refuses to write the text all the same."""
    text = leader + "\n" + BODY
    if target == "haas-mill":
        rule = "TG137"
    else:
        assert any(e.startswith(f"1:{rule} ") for e in target_errors(text, target))
    e = refusal(text, "fanuc-mill", target)
    assert e.line == 1 and e.column == leader.index(leader[1:].strip()) + 1, e
    assert "text after the first '%'" in e.message
    assert f"its check: {rule})" in e.message


@pytest.mark.parametrize("target", ["haas-mill", "iso-mill"])
@pytest.mark.parametrize("leader", ["%(TITLE)", "%:0003", "%;", "%  "])
def test_a_leader_the_iso_reader_takes_for_its_identification_is_carried(target, leader):
    text = leader + "\n" + BODY
    out = convert(text, "fanuc-mill", target)
    assert out.splitlines()[0] == leader.rstrip() or out.splitlines()[0] == leader
    assert not target_errors(out, target)


@pytest.mark.parametrize("source, target", [
    ("haas-mill", "haas-mill"), ("haas-mill", "okuma-mill"), ("okuma-mill", "haas-mill"),
    ("okuma-mill", "okuma-mill"), ("haas-mill", "linuxcnc")])
def test_a_haas_or_okuma_leader_with_text_is_refused_whatever_the_source(source, target):
    """Review 51, F16: a Haas's own `% O1000 (TEXT)` (its check: TG137, no source says what
    the control does with the text) was written as it stands for a Haas: the target's
    reading of it is not known, and it is refused at its first character after the `%`,
    as a FANUC source's is; no word of the FANUC's skipping where the source is no FANUC."""
    text = "% O1000 (TEXT)\nO01000\nG20 G90\nG0 X0 Y0\nM30\n%\n"
    e = refusal(text, source, target)
    assert (e.line, e.column) == (1, 3), e
    assert e.message.startswith("\"O1000 (TEXT)\": text after the first '%', "), e.message
    assert "source control skips" not in e.message
    assert "write the '%' on a line of its own" in e.message
    if target != "linuxcnc":
        assert "no source of the target's says what it does; its check: TG137)" in e.message
    # the way the message gives: the `%` alone, the text on the next line
    out = convert(text.replace("% O1000 (TEXT)", "%\n(TEXT)"), source, target)
    assert out.splitlines()[:2] == ["%", "(TEXT)"]


@pytest.mark.parametrize("target", ["linuxcnc", "haas-mill", "iso-mill"])
def test_text_after_the_closing_percent_is_carried(target, tmp_path):
    """Only the leader is the skipped text: the closing `%` ends the program on every target
    (rs274 stops there), so what follows it is read by none."""
    text = "%\nO1000\nG21\nG0 X0\nM30\n%O1000\n"
    out = convert(text, "fanuc-mill", target)
    assert out.splitlines()[-1] == "%O1000"
    assert not target_errors(out, target)
    if target == "linuxcnc":
        from tests.conftest import rs274_output
        assert "error" not in rs274_output(tmp_path, out).lower()


# -- 4. a lathe's X0: the spindle axis as a diameter and as a radius (finding 4) ---------------

LATHE_B = "O1000\nG21 G40 G97 S500 M3\nG95\nG0 Z5.\n{}\nG1 Z-10. F0.1\nG0 Z5.\nM30\n"


@pytest.mark.parametrize("block", ["G0 X0 Z5.", "G0 X-0. Z5.", "G0 X0.000", "G28 X0",
                                   "G53 X0", "M3 S500 X0"])
@pytest.mark.parametrize("target", ["linuxcnc", "fanuc-mill", "iso-mill"])
def test_a_lathes_x0_is_carried_where_the_readings_agree(block, target, tmp_path):
    if target == "iso-mill" and block.startswith(("G28", "G53")):
        pytest.skip("G28 and G53 are other codes of ISO 6983-1's table: refused at the code")
    out = convert(LATHE_B.format(block), "fanuc-lathe-b", target)
    assert block.split()[-1] in out or block.split()[-2] in out
    if target == "linuxcnc":
        from tests.conftest import rs274_output
        ran = rs274_output(tmp_path, out.replace("O1000\n", "").replace("M30", "M2"))
        assert "error" not in ran.lower() and "PROGRAM_END" in ran


@pytest.mark.parametrize("block, word", [("G0 X0.001 Z5.", "X0.001"), ("G0 X#1 Z5.", "X#1"),
                                         ("G0 X[0] Z5.", "X[0]"), ("G28 X2.", "X2."),
                                         ("G0 U5. Z1.", "U5."), ("G0 U0 Z1.", "U0")])
@pytest.mark.parametrize("target", ["linuxcnc", "fanuc-mill"])
def test_a_lathes_x_of_another_or_an_unknown_value_stays_refused(block, word, target):
    e = refusal(LATHE_B.format(block), "fanuc-lathe-b", target)
    assert (e.line, e.column) == (5, block.index(word) + 1), e
    assert e.message.startswith(f"{word}: the source lathe reads "), e.message


def test_a_lathes_u_that_moves_is_refused_for_a_mill_and_a_dwells_u_is_no_move():
    e = refusal(LATHE_B.format("G0 U5. Z1."), "fanuc-lathe", "fanuc-mill")
    assert e.message.startswith("U5.: the source lathe reads U as an increment of X, a "
                                "diameter"), e.message
    # a dwell's U is its time, no move; a mill reads U as an axis, so its G04 would have no
    # time (the target's check: TG532): refused at the U (review 29, finding 4: carried "ok")
    plain = "O1000\nG21\nS500 M3\nG0 X0 Z2.\nG04 U1.5\nG0 Z5.\nM30\n"
    for target in ("fanuc-mill", "haas-mill", "iso-mill", "okuma-mill"):
        e = refusal(plain, "fanuc-lathe", target)
        assert (e.line, e.column) == (5, 5), e
        assert e.message.startswith("U1.5: the source lathe's dwell time by U, which the "
                                    "target reads as an axis"), e.message
    # a dwell by X is carried to a FANUC mill, which reads G04 X as the time too
    assert "G04 X1.5" in convert(LATHE_B.format("G04 X1.5"), "fanuc-lathe-b", "fanuc-mill")
    # LinuxCNC's dwell conversion writes the time as P (rs274 runs it)
    assert "G04 P1.5" in convert(LATHE_B.format("G04 U1.5"), "fanuc-lathe-b", "linuxcnc")


def test_a_mills_x0_is_carried_for_a_lathe_and_its_next_x_refused():
    text = "O1000\nG21 G17\nG00 X0. Z5.\nG01 X10. Z0.\nM30\n"
    e = refusal(text, "fanuc-mill", "fanuc-lathe-b")
    assert (e.line, e.column) == (4, 5), e
    assert e.message.startswith("X10.: the source reads X as a length from the origin")


# -- 5. a G code neither profile lists, for a target that alarms on a code it lacks -----------

HAAS = "%\nO1000\nG21 G17 G40\n{}\nG0 X0 Y0\nM30\n%\n"


@pytest.mark.parametrize("code", ["G15", "G16", "G45", "G46", "G11", "G39"])
def test_a_code_neither_table_lists_is_refused_for_linuxcnc(code, tmp_path):
    from tests.conftest import rs274_output
    # LinuxCNC refuses it as written (rs274), unless a configuration remaps it (its check's
    # TG307, a warning naming REMAP): a remap would be the configuration's own function, no
    # reason to take it for the source's
    text = f"G21 G17 G40\n{code}\nG0 X0 Y0\nM2\n"
    assert "Unknown g code used" in rs274_output(tmp_path, text)
    assert not target_errors(text, "linuxcnc")
    warned = [f for f in check_text(text, load_profile("linuxcnc")) if f.rule == "TG307"]
    assert len(warned) == 1 and "REMAP" in warned[0].message, warned
    e = refusal(HAAS.format(code), "haas-mill", "linuxcnc")
    assert (e.line, e.column) == (4, 1), e
    assert e.message.startswith(f"{code}: neither the source's nor the target's profile lists "
                                "this code, and the target control alarms on a G code its "
                                "table lacks unless its configuration remaps it"), e.message


def test_a_code_neither_table_lists_is_refused_for_sinumerik_and_carried_for_iso():
    e = refusal(HAAS.format("G15"), "haas-mill", "sinumerik-840d")
    assert (e.line, e.column) == (4, 1), e
    assert any(":TG306 G15" in x for x in target_errors("N10 G15\nN20 M30\n", "sinumerik-840d"))
    # ISO 6983-1 leaves such a code to individual use (a warning, no alarm): carried
    out = convert(HAAS.format("G15"), "haas-mill", "iso-mill")
    assert "G15" in out and not target_errors(out, "iso-mill")


# -- 6. G10's X across the diameter/length change (doubtful item) ------------------------------

@pytest.mark.parametrize("source, target", [("fanuc-mill", "fanuc-lathe"),
                                            ("haas-mill", "haas-lathe"),
                                            ("fanuc-mill", "fanuc-lathe-b")])
def test_a_mills_g10_x_is_refused_for_a_lathe(source, target):
    text = "%\nO1000\nG21\nG10 L2 P1 X100. Z-50.\nG0 Z5.\nM30\n%\n"
    e = refusal(text, source, target)
    assert (e.line, e.column) == (4, 11), e
    assert e.message.startswith("X100.: G10's offset value on the X axis"), e.message
    if target.startswith("fanuc"):
        # the FANUC page says so of a FANUC lathe
        assert "a FANUC lathe reads an offset's X as a diameter or a radius by its " \
            "parameters (B-63444EN/01, 8.4: the tool offset's by parameter No. 5004#1)" \
            in e.message, e.message
    else:
        # no page at hand says it of a Haas lathe: refused on the safe side, and said so
        assert "no source at hand says whether a Haas lathe's G10 reads an offset's X as a " \
            "diameter or a radius" in e.message, e.message
        assert "tapegate does not halve nor double it, and it is refused on the safe side" \
            in e.message
    # its X0 is the same offset either way: carried
    out = convert(text.replace("X100.", "X0"), source, target)
    assert "G10 L2 P1 X0 Z-50." in out


# (G10 L10, a tool offset's, is refused for LinuxCNC by the G10 rules first: its L10 sets the
# tool table from the current position)
@pytest.mark.parametrize("block, word, target", [("G10 L2 P1 X20. Z0", "X20.", "linuxcnc"),
                                                 ("G10 L10 P1 X20.", "X20.", "fanuc-mill"),
                                                 ("G10 P1 U0.2", "U0.2", "fanuc-mill")])
def test_a_lathes_g10_x_is_refused_for_a_target_that_reads_x_as_a_length(block, word, target):
    text = f"O1000\nG21 G40 G97 S500 M3\nG95\nG0 Z5.\n{block}\nM30\n"
    e = refusal(text, "fanuc-lathe-b", target)
    assert (e.line, e.column) == (5, block.index(word) + 1), e
    assert e.message.startswith(f"{word}: G10's offset value on the X axis"), e.message


@pytest.mark.parametrize("source, target, says", [
    ("haas-lathe", "haas-mill", "no source at hand says whether a Haas lathe's G10"),
    ("haas-lathe", "linuxcnc", "no source at hand says whether a Haas lathe's G10"),
    ("fanuc-lathe", "haas-mill", "a FANUC lathe reads an offset's X as a diameter or a radius"),
    ("okuma-lathe", "okuma-mill", "no source at hand says whether an Okuma lathe's G10"),
])
def test_the_g10_x_refusal_names_the_source_it_follows_for_the_lathe(source, target, says):
    """fix28's doubt: the refusal applied a FANUC page (B-63444EN 8.4) to the Haas lathe too.
    No Haas page at hand says how a Haas lathe's G10 reads X (the Haas G10 pages found are the
    mill's), so a Haas or Okuma lathe's G10 X is still refused, on the safe side, and the
    message says it follows no source there; a FANUC lathe's names the FANUC page."""
    text = "O1000\nG21 G40\nG0 Z5.\nG10 L2 P1 X20. Z0\nM30\n"
    if source.startswith("okuma"):
        text = "G0 Z5.\nG10 L2 P1 X20. Z0\nM02\n"
    e = refusal(text, source, target)
    assert e.line == text.split("\n").index("G10 L2 P1 X20. Z0") + 1, e
    assert says in e.message, e.message
    assert ("B-63444EN" in e.message) == source.startswith("fanuc") or "FANUC's" in e.message


def test_g10_between_two_mills_keeps_its_x():
    text = "%\nO1000\nG21\nG10 L2 P1 X100. Z-50.\nG0 Z5.\nM30\n%\n"
    assert "X100." in convert(text, "fanuc-mill", "haas-mill")
