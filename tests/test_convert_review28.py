"""Review 28 (from fix27's report): a lathe's W, an increment of Z, carried "ok" to a mill
where W is an axis of its own, and a mill's Y carried "ok" to a lathe. Refused by the rule
that refuses a lathe's X and U across the diameter/length change (`same_x_reading`)."""

from __future__ import annotations

import pytest

from formats.errors import ConversionError

from .test_convert_target_reads import convert

LATHE = "O1000\nG21 G40\nG0 X0 Z5.\n{}\nG0 Z5.\nM30\n"  # the block is line 4


def refusal(text: str, source: str, target: str) -> ConversionError:
    with pytest.raises(ConversionError) as err:
        convert(text, source, target)
    return err.value


@pytest.mark.parametrize("source", ["fanuc-lathe", "fanuc-lathe-b", "haas-lathe"])
@pytest.mark.parametrize("target", ["fanuc-mill", "iso-mill"])
@pytest.mark.parametrize("block, word", [("G0 W-10.", "W-10."), ("G0 Z1. W2.", "W2."),
                                         ("G0 W0", "W0")])
def test_a_lathes_moving_w_is_refused_for_a_mill(source, target, block, word):
    e = refusal(LATHE.format(block), source, target)
    assert (e.line, e.column) == (4, block.index(word) + 1), e
    assert e.message.startswith(f"{word}: the source lathe reads W as an increment of Z, the "
                                "target as an axis of its own"), e.message


def test_a_lathes_w_for_linuxcnc_keeps_its_own_refusal_and_a_cycles_w_is_no_move():
    e = refusal(LATHE.format("G0 W-10."), "fanuc-lathe", "linuxcnc")
    assert "LinuxCNC reads them as axes of their own" in e.message
    # W0 moves nothing on the lathe and moves the mill's W axis to 0: refused too
    e = refusal(LATHE.format("G0 W0"), "fanuc-lathe", "fanuc-mill")
    assert e.message.startswith("W0: the source lathe reads W as an increment of Z")


MILL = "O1000\nG21\nG0 Z5.\n{}\nM30\n"


@pytest.mark.parametrize("source", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("target", ["fanuc-lathe", "fanuc-lathe-b", "haas-lathe"])
def test_a_mills_y_is_refused_for_a_lathe(source, target):
    e = refusal(MILL.format("G0 Y10."), source, target)
    assert (e.line, e.column) == (4, 4), e
    assert e.message.startswith("Y10.: the source mill moves Y, an axis the target lathe's "
                                "plane (G18, X and Z) does not hold"), e.message
    # Y0 (the origin, as X0 the spindle axis) is carried, and a mill program without X or Y
    # still converts
    assert "G0 Y0" in convert(MILL.format("G0 Y0"), source, target)
    assert "G0 Z1." in convert(MILL.format("G0 Z1."), source, target)


def test_two_mills_and_two_lathes_keep_their_y_and_w():
    assert "G0 Y10." in convert(MILL.format("G0 Y10."), "fanuc-mill", "haas-mill")
    assert "G0 W-10." in convert(LATHE.format("G0 W-10."), "fanuc-lathe-b", "fanuc-lathe")


REPEATED_CALL = ("O1000\nG21 G90 G17 G94\nG0 X0 Y0\n{call}\nM30\n")


@pytest.mark.parametrize("call, word", [("M98 P20100", "P20100"), ("M98 P51002", "P51002")])
def test_a_fanucs_m98_with_its_repetitions_in_p_is_refused_for_linuxcnc(call, word):
    """Review 29, finding 3: on a FANUC the digits of M98's P before the last four are the
    number of repetitions (0i-MB Operator's Manual B-64124EN/01, 12.3: `M98 P51002` calls
    O1002 five times); LinuxCNC reads the whole P as the program number ("Failed to find sub
    'O20100'"). Refused at the P, with the target's form named."""
    e = refusal(REPEATED_CALL.format(call=call), "fanuc-mill", "linuxcnc")
    assert (e.line, e.column) == (4, 5), e
    assert e.message.startswith(
        f"{word}: M98's P of more than four digits reads as the number of repetitions and the "
        "program number on a FANUC without the 8-digit program number option (M98 P51002 calls "
        "O1002 five times: B-64124EN/01, 12.3), or as the program number, the repetitions by "
        "L, on one with it (0i-F, 30i: O51002 once; the FANUC profiles' O08) on the source and "
        "as the program number, the repetitions by L on the target; which of the two readings "
        "a FANUC takes, the program does not show"), e.message
    assert "(M98 P1002 L5)" in e.message


def test_a_fanucs_m98_with_four_digits_and_l_is_carried_and_runs_on_rs274(tmp_path):
    """The program number alone (four digits or fewer, leading zeros not counted) and the
    repetitions by L are read alike: carried, and rs274 calls the subprogram twice."""
    from tests.conftest import rs274_output
    text = REPEATED_CALL.format(call="M98 P0100 L2") + "O0100\nG91 G0 X1.\nG90\nM99\n"
    out = convert(text, "fanuc-mill", "linuxcnc")
    assert "M98 P0100 L2" in out
    ran = rs274_output(tmp_path, out.replace("O1000\n", "").replace("M30", "M2"))
    assert "error" not in ran.lower(), ran


@pytest.mark.parametrize("source, target", [("fanuc-mill", "haas-mill"),
                                            ("haas-mill", "fanuc-mill")])
def test_an_m98_p_of_more_than_four_digits_is_refused_between_fanuc_and_haas(source, target):
    """FANUC's P51002 is O1002 five times (B-64124EN/01, 12.3), a Haas's P51002 the program
    51002, its repetitions by L (96-8000, "M98 Sub Program Call"): refused both ways at the P;
    the same control's profiles, and a P of four digits with L, carry it."""
    e = refusal(REPEATED_CALL.format(call="M98 P51002"), source, target)
    assert (e.line, e.column) == (4, 5), e
    assert e.message.startswith("P51002: M98's P of more than four digits reads as "), e.message
    advice = "(M98 P1002 L5)" if source == "fanuc-mill" else "a number of four digits"
    assert advice in e.message, e.message
    assert "M98 P1002 L5" in convert(REPEATED_CALL.format(call="M98 P1002 L5"), source, target)
    assert "M98 P51002" in convert(REPEATED_CALL.format(call="M98 P51002"), source, source)


@pytest.mark.parametrize("source, target, call, refused", [
    ("linuxcnc", "fanuc-mill", "M98 P12345", "P12345"),      # O12345 on LinuxCNC, O2345 once
    ("linuxcnc", "fanuc-mill", "M98 P12345 L2", "P12345"),
    ("fanuc-mill", "haas-mill", "P51002 M98", "P51002"),      # the P before the M98
    ("fanuc-mill", "linuxcnc", "M98 P+51002", "P+51002"),     # a sign
    ("haas-mill", "linuxcnc", "M98 P51002", None),            # both the program 51002
    ("linuxcnc", "haas-mill", "M98 P51002 L2", None),
    ("fanuc-mill", "fanuc-mill", "M98 P51002", None),
])
def test_m98s_long_p_is_refused_where_the_two_controls_read_it_apart(source, target, call,
                                                                     refused):
    """Review 30, findings 1, 3, 4: one predicate by how each control reads the P (FANUC:
    repetitions and program; Haas, LinuxCNC: the program, repetitions by L), the P found
    wherever it stands in the block."""
    text = REPEATED_CALL.format(call=call)
    if refused is None:
        assert call.split()[1] in convert(text, source, target) or call in convert(
            text, source, target)
        return
    e = refusal(text, source, target)
    assert (e.line, e.column) == (4, call.index(refused) + 1), e
    assert e.message.startswith(f"{refused}: M98's P of more than four digits reads "), e.message
    # both FANUC readings are said, whichever side the FANUC is on
    assert "without the 8-digit program number option" in e.message, e.message
    assert "as the program number, the repetitions by L, on one with it" in e.message


INCH_DWELL = "O1000\nG20\nG0 Z1.\n{}\nM30\n"


@pytest.mark.parametrize("source", ["fanuc-mill", "haas-mill"])
@pytest.mark.parametrize("target", ["fanuc-mill", "haas-mill", "iso-mill", "okuma-mill"])
def test_an_inch_dwells_x_without_a_point_is_refused_where_written_anew(source, target):
    """`G20 G04 X1500` is 0.15 s by X's inch length format and 1.5 s by the increment system
    alone, and no source says which a FANUC or Haas control takes; `diff` never calls it the
    same and the statistics leave it out. It was written `G04 X0.15` for a Haas (the inch
    reading stated as fact): refused at the word wherever its text would change."""
    e = refusal(INCH_DWELL.format("G04 X1500"), source, target)
    assert (e.line, e.column) == (4, 5), e
    assert e.message.startswith("X1500: a dwell's X without a decimal point under G20"), e
    # with its point, or under G21, the time is known and converted
    assert "G04 X1.5" in convert(INCH_DWELL.format("G04 X1.5"), source, target)
    assert "X1.5" in convert(INCH_DWELL.replace("G20", "G21").format("G04 X1500"), source,
                             "haas-mill")


def test_an_inch_lathe_dwells_u_without_a_point_is_refused_too():
    e = refusal("O1000\nG20\nG0 Z1.\nG04 U1500\nM30\n", "fanuc-lathe", "haas-lathe")
    assert e.message.startswith("U1500: a dwell's U without a decimal point under G20"), e
