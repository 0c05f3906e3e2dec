"""The classes benchmarks/convert_targets.py --all left "ok but refused" (docs/benchmarks.md, "The
65 left"): each conversion now refuses at the source word, located, where the target's own check
would refuse the output; or carries the meaning exactly.

1. A code the target's ISO 6983-1 table leaves permanently unassigned (Annex E; `G28`, a FANUC's
   reference return): refused at the code (TG303 on the target).
"""

from __future__ import annotations

import pytest

from formats.errors import ConversionError

from .test_convert_target_reads import FANUC, convert, target_errors


def refusal(text: str, source: str, target: str) -> ConversionError:
    with pytest.raises(ConversionError) as err:
        convert(text, source, target)
    return err.value


# -- 1. a code the ISO 6983-1 target's table leaves permanently unassigned ----------------------



@pytest.mark.parametrize("source", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("target", ["iso-mill", "iso-lathe", "sinumerik-7e2"])
def test_a_code_the_iso_table_leaves_permanently_unassigned_is_refused_at_the_code(
        source, target):
    text = FANUC + "G0 X0 Y0\nG91 G28 Z0.\nM30\n"
    # the target's check refuses the code as written (TG303)
    assert any(e.startswith("4:TG303 G28") for e in target_errors(text, target))
    e = refusal(text, source, target)
    assert (e.code, e.line, e.column) == ("conversion", 4, 5)
    assert "G28:" in e.message
    assert "permanently unassigned (Annex E)" in e.message
    # without it the program converts, and the target's check reads the output
    out = convert(text.replace("G91 G28 Z0.\n", ""), source, target)
    assert not target_errors(out, target)


def test_the_same_code_is_carried_where_the_target_table_assigns_it():
    text = FANUC + "G0 X0 Y0\nG91 G28 Z0.\nM30\n"
    out = convert(text, "fanuc-mill", "haas-mill")
    assert "G28" in out and not target_errors(out, "haas-mill")


def test_a_code_the_source_table_lacks_is_refused_where_the_iso_table_leaves_it_unassigned():
    """A SINUMERIK's table has no G28 (its check names it, TG307); the ISO target refuses it."""
    text = "N10 G17 G90 G71\nN20 G91 G28 Z0.0\nN30 M30\n"
    assert any(e.startswith("2:TG303 G28") for e in target_errors(text, "iso-lathe"))
    e = refusal(text, "sinumerik-840d", "iso-lathe")
    assert (e.code, e.line, e.column) == ("conversion", 2, 9)
    assert "no code of its profile's table on the source" in e.message


# -- 4. a FANUC lathe's T word (tool and offset) for a target that reads one tool number ---------

LATHE = "O0001\nG21\nT0101\nG00 X20. Z2.\nM30\n"


@pytest.mark.parametrize("target", ["iso-lathe", "iso-mill", "fanuc-mill", "haas-mill",
                                    "linuxcnc"])
def test_a_lathe_tool_and_offset_word_is_refused_for_a_target_that_reads_one_number(target):
    e = refusal(LATHE, "fanuc-lathe", target)
    assert (e.code, e.line, e.column) == ("conversion", 3, 1)
    assert e.message.startswith("T0101: a FANUC or Haas lathe's T word is the tool number")
    assert "has no place in it for the offset" in e.message


@pytest.mark.parametrize("source, target", [("fanuc-lathe", "haas-lathe"),
                                            ("haas-lathe", "fanuc-lathe"),
                                            ("fanuc-lathe", "fanuc-lathe-b")])
def test_a_lathe_tool_and_offset_word_is_carried_between_lathes_that_read_it_alike(
        source, target):
    out = convert(LATHE, source, target)
    assert "T0101" in out
    assert not [e for e in target_errors(out, target) if ":TG604 " in e]


def test_a_macro_calls_t_argument_is_no_tool_word():
    text = "O0001\nG21\nG65 P9010 T3.\nM30\n"
    assert "G65 P9010 T3." in convert(text, "fanuc-lathe", "fanuc-mill")


# -- 5. a FANUC's text after '%' for a target that reads it as words -----------------------------

PERCENT = "%O0003(ABC)\nG0 X0 Y0\nM30\n%\n"


@pytest.mark.parametrize("target", ["haas-mill", "iso-mill", "linuxcnc"])
def test_words_after_the_percent_the_fanuc_skips_are_refused_for_a_target_that_reads_them(
        target):
    # (a Haas: TG137, a warning, which the conversion refuses to write all the same)
    if target == "haas-mill":
        assert not target_errors(PERCENT, target)
    else:
        assert any(e.startswith("1:TG111 ") or e.startswith("1:TG412 ")
                   for e in target_errors(PERCENT, target))
    e = refusal(PERCENT, "fanuc-mill", target)
    assert (e.code, e.line, e.column) == ("conversion", 1, 2)
    assert e.message.startswith('"O0003(ABC)": text after the first \'%\', which the source')
    # on a line of its own the number converts, and the target's check reads the '%' line
    split = PERCENT.replace("%O0003", "%\nO0003")
    out = convert(split, "fanuc-mill", target)
    assert not [x for x in target_errors(out, target) if x.startswith("1:")]


@pytest.mark.parametrize("source, target, line", [
    ("fanuc-mill", "fanuc-mill", "%O0003(ABC)"),    # one control: carried as it is
    ("fanuc-mill", "sinumerik-840d", "%O0003(ABC)"),  # the % line names the program there
    ("haas-mill", "iso-mill", "%(ABC)"),            # a comment, no word
])
def test_a_percent_line_is_carried_where_the_target_reads_it_as_the_source_does(
        source, target, line):
    text = PERCENT.replace("%O0003(ABC)", line)
    assert convert(text, source, target).splitlines()[0] == line


# -- 2. two codes of one modal group in the target's table ---------------------------------------

ONE_GROUP = "O1000\nG21 G90 G17\nG49 G40 G80\nG0 X0 Y0\nM30\n"


def test_two_codes_the_target_puts_in_one_modal_group_are_refused_at_the_second():
    assert any(e.startswith("3:TG304 G49 and G40") for e in target_errors(ONE_GROUP, "pm322-eia"))
    e = refusal(ONE_GROUP, "haas-mill", "pm322-eia")
    assert (e.code, e.line, e.column) == ("conversion", 3, 5)
    assert e.message.startswith("G40: the target's code table puts this code and G49 of the "
                                "same block in one modal group (d), the source's in two")
    # in two blocks they convert (the block's other codes are the conversion's to judge)
    two = ONE_GROUP.replace("G49 G40 G80", "G49\nG40")
    assert not [x for x in target_errors(convert(two, "haas-mill", "pm322-eia"), "pm322-eia")
                if ":TG304 " in x]


@pytest.mark.parametrize("target", ["iso-mill", "fanuc-mill"])
def test_two_codes_of_two_groups_on_both_tables_are_carried(target):
    out = convert(ONE_GROUP, "haas-mill", target)
    assert "G49 G40 G80" in out
    assert not [x for x in target_errors(out, target) if ":TG304 " in x]


def test_a_units_code_beside_a_motion_code_is_the_converters_to_write():
    """System C's G20 is a turning cycle (A's G90), in the motion group with G00; a mill's
    `G20 G00` is written with the lathe's own inch code, so the two are no pair."""
    out = convert("O1000\nG20 G00 Z1.\nM30\n", "fanuc-mill", "fanuc-lathe-c")
    assert "G20" not in out and "G70 G00" in out


# -- 3. a mill's program for a lathe that reads X as a diameter ----------------------------------

MILL = "O1000\nG21 G17\nG00 X0. Y0.\nG01 X10. Y0. F100.\nG02 X20. Y10. I5. J5.\nM30\n"
# (no F: a mill's F by its reset feed per minute is refused for a lathe first)
AFTER_G80 = "O1000\nG21\nG00 Z1.\nG81 Z-1. R1.\nG80\nX5. Z5.\nM30\n"


@pytest.mark.parametrize("target", ["fanuc-lathe", "fanuc-lathe-b", "fanuc-lathe-c",
                                    "haas-lathe"])
def test_a_mill_programs_x_is_refused_for_a_lathe_that_reads_x_as_a_diameter(target):
    # carried, the target's check reads the arc with X a diameter (TG403): another arc
    assert any(":TG403 " in e for e in target_errors(MILL, target))
    e = refusal(MILL, "fanuc-mill", target)
    # (X0. is the spindle axis under both readings: the first X of another value is refused)
    assert (e.code, e.line, e.column) == ("conversion", 4, 5)
    assert e.message.startswith("X10.: the source reads X as a length from the origin (a mill), "
                                "the target lathe as a diameter")
    # a move after G80 with no motion mode (TG411 on a FANUC lathe) is refused at its X too
    assert any(e.startswith("6:TG411 ") for e in target_errors(AFTER_G80, target)) == (
        target != "haas-lathe")
    e = refusal(AFTER_G80, "fanuc-mill", target)
    assert (e.line, e.column) == (6, 1)


@pytest.mark.parametrize("text", ["O1000\nG21\nG04 X1.5\nG00 Z1.\nM30\n",
                                  "O1000\nG21\nG65 P9010 X1.5\nM30\n"])
def test_a_dwell_or_macro_calls_x_is_no_position(text):
    out = convert(text, "fanuc-mill", "fanuc-lathe-b")
    assert "X1.5" in out


def test_a_lathe_program_between_lathes_keeps_its_x():
    text = "O0001\nG21\nG00 X20. Z2.\nM30\n"
    assert "X20." in convert(text, "fanuc-lathe", "fanuc-lathe-b")


# -- the mirror: a lathe's program (X a diameter, the reset feed per revolution) for a target
# -- that reads X as a length and feeds per minute at reset (review 26, finding 5)

LATHE_X = ("O1000\nG21 G18 G40 G97\nG0 X20. Z5.\nS500 M3\nG1 X10. Z-5. F0.2\n"
           "G2 X20. Z-10. R5.\nM30\n")


@pytest.mark.parametrize("source", ["fanuc-lathe", "fanuc-lathe-b", "haas-lathe"])
@pytest.mark.parametrize("target", ["linuxcnc", "fanuc-mill", "iso-mill"])
def test_a_lathe_programs_x_is_refused_for_a_target_that_reads_x_as_a_length(source, target):
    text = LATHE_X
    e = refusal(text, source, target)
    assert (e.line, e.column) == (3, 4), e
    assert e.message.startswith("X20.: the source lathe reads X as a diameter, the target as a "
                                "length from the origin"), e.message


def test_a_lathe_program_with_x_for_linuxcnc_is_what_rs274_refuses(tmp_path):
    """Carried as written: LinuxCNC reads X as a radius (G8), the arc's end 20 from its start
    while its R is 5."""
    from tests.conftest import rs274_output
    out = rs274_output(tmp_path, LATHE_X.replace("O1000\n", "").replace("M30", "M2"))
    assert "Arc radius too small to reach end point" in out


@pytest.mark.parametrize("source", ["fanuc-lathe", "haas-lathe"])
@pytest.mark.parametrize("target", ["linuxcnc", "fanuc-mill"])
def test_a_feed_per_revolution_by_the_reset_state_is_refused_at_its_f(source, target):
    text = "O1000\nG21 G18\nG0 Z5.\nS500 M3\nG1 Z-5. F0.2\nM30\n"
    e = refusal(text, source, target)
    assert (e.line, e.column) == (5, 9), e
    assert e.message.startswith("F0.2: a feed per revolution by the source control's reset "
                                "state"), e.message


def test_a_feed_mode_written_before_the_f_is_read_by_its_code():
    # system A's G98 (per minute) is a return level on a mill: refused at the code itself,
    # not at the F that follows it
    text = "O1000\nG21 G18\nG98\nG0 Z5.\nG1 Z-5. F100.\nM30\n"
    e = refusal(text, "fanuc-lathe", "linuxcnc")
    assert (e.line, e.column) == (3, 1), e
    # system B's G94 is LinuxCNC's G94: carried, and its F with it
    text = "O1000\nG21 G18\nG94\nG0 Z5.\nG1 Z-5. F100.\nM30\n"
    assert "F100." in convert(text, "fanuc-lathe-b", "linuxcnc")


def test_a_lathe_program_between_lathes_keeps_its_feed():
    text = "O0001\nG21\nG00 Z2.\nG01 Z-5. F0.2\nM30\n"
    assert "F0.2" in convert(text, "fanuc-lathe", "haas-lathe")
