"""Forms of the controls' programs read as each control's documentation and interpreter read them
(issue 32's last review): one small program per rule, error paths with their code, line and
column. Where LinuxCNC's ``rs274`` is installed, the LinuxCNC cases are run through it too."""

from __future__ import annotations

from pathlib import Path

import pytest

from formats.convert import ConvertOptions, convert_text
from formats.errors import ConversionError
from formats.parser import BadBlock, parse_text
from formats.profile import load_profile
from postproc.check import Checker

from .conftest import rs274_output


def bad_blocks(text: str, profile: str) -> list[tuple[str, int, int, str]]:
    """The reading errors of ``text``: code, line, column, message."""
    read = parse_text(text, load_profile(profile).dialect, errors="collect")
    return [(b.error.code, b.error.line, b.error.column, b.error.message)
            for b in read if isinstance(b, BadBlock)]


def findings(text: str, profile: str, file: str = "<input>") -> list:
    prof = load_profile(profile)
    return list(Checker(prof, file).run(parse_text(text, prof.dialect, errors="collect")))


def rs274(tmp_path: Path, text: str) -> tuple[bool, str]:
    """Whether rs274 runs ``text`` through, and its output; skipped where it is absent."""
    out = rs274_output(tmp_path, text)
    return "PROGRAM_END" in out, out


# -- 1. LinuxCNC: blanks inside a parameter reference ------------------------------------------

@pytest.mark.parametrize("body", [
    "# <x> = 1\nG0 X# < x >\nM2\n",
    "# < x y > = 2\nG0 X#<xy>\nM2\n",
    "#1 = 2\n# #1 = 7\nG0 X#2\nM2\n",
    "# [1 + 1] = 5\nG0 X#2\nM2\n",
    "#<x> = 1\no100 if [# <x> GT 0]\nG0 X1\no100 endif\nM2\n",
    "o<s> sub\nG0 X1\no<s> endsub\nO <S> call\no 1 0 0 if [1 GT 0]\nG0 X2\no100 endif\nM2\n",
])
def test_linuxcnc_reads_blanks_inside_a_parameter_reference(tmp_path, body):
    """rs274ngc drops every blank outside comments before it reads a line (close_and_downcase),
    so ``# <x> = 1`` is ``#<x>=1`` and ``##1 = 7`` sets the parameter #1 names."""
    ran, out = rs274(tmp_path, body)
    assert ran, out
    assert bad_blocks(body, "linuxcnc") == []
    assert not [f for f in findings(body, "linuxcnc") if f.severity == "error"]


@pytest.mark.parametrize("body, column, message", [
    ("# <x = 1\nM2\n", 1, "named parameter '#<' without its closing '>'"),
    ("# <x> 1\nM2\n", 7, "a parameter must be set as #n = value"),
])
def test_linuxcnc_a_broken_parameter_reference_is_located(tmp_path, body, column, message):
    ran, _ = rs274(tmp_path, body)
    assert not ran
    assert bad_blocks(body, "linuxcnc") == [("TG100", 1, column, message)]


@pytest.mark.parametrize("body, moves", [
    ("#1=2\n#2=3\nG0 X# 1\nG0 X[#1 + # 2]\nM2\n", ["2.0000", "5.0000"]),
    ("#12=2\nG0 X#1 2\nM2\n", ["2.0000"]),
    ("G0 X1 0\nG0 X1 . 5\nG0 X[1 2 + 0 . 5]\nM2\n", ["10.0000", "1.5000", "12.5000"]),
])
def test_linuxcnc_reads_blanks_inside_a_value(tmp_path, body, moves):
    """The blanks rs274ngc drops are dropped in a word's value too: ``X# 1`` is X#1 and
    ``X1 0`` is X10 (rs274 moves there); the program is reprinted byte for byte."""
    ran, out = rs274(tmp_path, body)
    assert ran, out
    assert [line.split("(")[1].split(",")[0] for line in out.splitlines()
            if "STRAIGHT_TRAVERSE" in line] == moves
    assert bad_blocks(body, "linuxcnc") == []
    assert not [f for f in findings(body, "linuxcnc") if f.severity == "error"]
    same = ConvertOptions(load_profile("linuxcnc"), load_profile("linuxcnc"))
    assert convert_text(body, same)[0] == body


def test_linuxcnc_a_value_read_with_blanks_converts():
    """Where the value as written holds blanks the expression reader of 6.4.7 does not read,
    the word is converted as the control reads it, without them."""
    body = "G21\n#1=2 0\n#2=3\nG0 X# 1 Y[#1 + # 2] Z1 0\nM2\n"
    out = convert_text(body, LINUXCNC_INCH)[0]
    assert out == "G20\n#1=0.787402\n#2=0.11811\nG0 X# 1 Y[#1 + # 2] Z0.393701\nM2\n"


def test_linuxcnc_a_read_only_parameter_written_with_blanks_is_still_read_only(tmp_path):
    body = "# <_x> = 1\n# 5420 = 2\nM2\n"
    ran, _ = rs274(tmp_path, body)
    assert not ran
    found = [(f.rule, f.line, f.column) for f in findings(body, "linuxcnc") if f.rule == "TG209"]
    assert found == [("TG209", 1, 1), ("TG209", 2, 1)]


# -- 2. The parameter analysis sees statements, calls and indirect targets ----------------------

LINUXCNC_INCH = ConvertOptions(load_profile("linuxcnc"), load_profile("linuxcnc"), units="inch")
FANUC_INCH = ConvertOptions(load_profile("fanuc-mill"), load_profile("fanuc-mill"),
                            units="inch")


def refused(src: str, options: ConvertOptions = LINUXCNC_INCH) -> ConversionError:
    with pytest.raises(ConversionError) as info:
        convert_text(src, options)
    assert (info.value.code, info.value.clause) == ("conversion-unprovable", "6.4.7")
    return info.value


def test_a_call_argument_is_the_subroutine_s_parameter(tmp_path):
    """``o<s> call [#<d>]`` sets the subroutine's #1 (LinuxCNC "O Codes"): where the
    subroutine reads #1 as a length, #<d> is one and is converted."""
    src = ("G21 G90\no<s> sub\nG1 X#1 F100\no<s> endsub\n#<d> = 2.54\no<s> call [#<d>]\n"
           "M2\n")
    ran, out = rs274(tmp_path, src)
    assert ran, out
    lines = convert_text(src, LINUXCNC_INCH)[0].splitlines()
    assert lines[4] == "#<d> = 0.1"


def test_a_call_argument_of_another_class_stops_the_conversion():
    """#<n> is a length (X#<n>) and is passed to a subroutine that takes its #1 as a spindle
    speed: converted, the subroutine would get another speed."""
    error = refused("G21\no<s> sub\nS#1\no<s> endsub\n#<n> = 4\no<s> call [#<n>]\n"
                    "G1 X#<n> F100\nM2\n")
    assert error.message.endswith(
        "#<n> is used both as a length and as something else (line 6)")


def test_a_parameter_compared_in_a_condition_shares_the_class_of_what_it_is_compared_with():
    error = refused("G21\n#<a> = 2\n#<n> = 3\no100 if [#<a> GT #<n>]\nG1 X#<a> F100\n"
                    "o100 endif\nS#<n>\nM2\n")
    assert "is compared on line 4 with a parameter of another class" in error.message
    # a loop counter read nowhere else is no length: the program converts
    src = "G21\n#<n> = 3\no1 while [#<n> GT #<z>]\n#<n> = [#<n> - 1]\no1 endwhile\nM2\n"
    assert convert_text("G21\n#<z> = 0\n" + src[4:], LINUXCNC_INCH)[0]


@pytest.mark.parametrize("src, line", [
    ("G21\n#1 = 2\n#[#1] = 5\nG1 X#2 F100\nM2\n", 3),
    ("G21\n#1 = 2\n##1 = 5\nG1 X#2 F100\nM2\n", 3),
])
def test_an_indirect_assignment_makes_every_class_unknown(tmp_path, src, line):
    ran, out = rs274(tmp_path, src)
    assert ran, out
    error = refused(src)
    assert f"line {line} sets a parameter chosen by a value" in error.message


def test_a_fanuc_then_assignment_is_an_assignment():
    """``IF [..] THEN #3 = #1`` sets #3 (Custom Macro B): #1 is a length through it, and the
    compared #2 and #4, read nowhere else, are no length."""
    src = "%\nO1\nG21\n#1=2.54\n#2=1\n#4=1\nIF [#2 EQ #4] THEN #3=#1\nG01 X#3 F100.\nM30\n%\n"
    lines = convert_text(src, FANUC_INCH)[0].splitlines()
    assert lines[3:6] == ["#1=0.1", "#2=1", "#4=1"]


# -- 3. SINUMERIK: its own program ends and subprogram calls ------------------------------------

ARC_AFTER = "G0 X10 Y10\n{call}\nG2 X30 Y10 I5 J0 F100\nM30\n"


@pytest.mark.parametrize("call, kind", [
    ("L100", "subprogram call"), ("L785 P2", "subprogram call"), ("MYSUB", "call"),
    ('CALL "PART_2"', "call"), ("PCALL MYSUB", "call"), ('EXTCALL "ROUGH"', "call"),
    ("G0SUPAZ0", "call"),
])
def test_a_sinumerik_subprogram_call_leaves_the_position_unknown(call, kind):
    """A subprogram called by its L number or its name (or CALL, PCALL, EXTCALL) runs where
    the checker does not follow: the arc after it is not measured from X10 Y10. `G0SUPAZ0`
    is the one identifier SUPAZ0 (no separator inside an identifier): a call by that name."""
    found = findings(ARC_AFTER.format(call=call), "sinumerik-840d")
    assert [(f.rule, f.line) for f in found] == [("TG140", 2)]
    assert f"({kind})" in found[0].message


@pytest.mark.parametrize("instruction", ["G0 SUPA Z0", "STOPRE", "SETAL(61000)", "WAITM(1,1,2)"])
def test_a_sinumerik_instruction_is_no_call(instruction):
    found = findings(ARC_AFTER.format(call=instruction), "sinumerik-840d")
    assert [(f.rule, f.line, f.severity) for f in found] == [("TG403", 3, "error")]


@pytest.mark.parametrize("between", [
    "POSA[X]=20\nWAITP(X)", "POSA[X]=20", "POS[X]=20\nWAITP(X)", "POS[X]=20",
])
def test_a_sinumerik_positioning_axis_leaves_its_position_unknown(between):
    """POS[X]= and POSA[X]= move X as a positioning axis (POSA on across the blocks after it,
    until WAITP(X)): the arc after it is not measured from X10, where the path left X. WAITP
    alone waits and changes nothing: the arc is measured and its end is off its circle."""
    text = f"G0 X10 Y10\n{between}\nG2 X30 Y10 I5 J0 F100\nM30\n"
    assert findings(text, "sinumerik-840d") == []
    waited = findings(ARC_AFTER.format(call="WAITP(X)"), "sinumerik-840d")
    assert [(f.rule, f.line, f.column) for f in waited] == [("TG403", 3, 1)]


@pytest.mark.parametrize("procedure, what", [
    ("GEOAX(1,XX)", "changes the axis configuration"),
    ("LEADON(A,X,1)", "couples axes or spindles"),
    ("PRESETON(X,0)", "sets actual values"),
])
def test_a_sinumerik_procedure_that_changes_the_axes_leaves_the_position_unknown(procedure, what):
    """A predefined procedure that couples, reconfigures or sets axes (list of operations, type
    P; docs/dialects.md, class (b)): the arc after it is not measured from X10 Y10, and the
    note names the procedure, not a call."""
    found = findings(ARC_AFTER.format(call=procedure), "sinumerik-840d")
    assert [(f.rule, f.line, f.column) for f in found] == [("TG140", 2, 1)]
    assert found[0].message.startswith(f"{procedure} (predefined procedure): it {what}")


@pytest.mark.parametrize("transformation", ["TRACYL(400)", "TRAORI", "transmit(1)"])
def test_a_sinumerik_transformation_leaves_the_position_unknown(transformation):
    """A kinematic transformation programs the axes in other coordinates until TRAFOOF (docs/
    dialects.md): the arc after it is not measured from X10 Y10, and no note is said (the
    travel comparison ends, as --stats says); a TRAFOOF with none in force changes nothing."""
    assert findings(ARC_AFTER.format(call=transformation), "sinumerik-840d") == []
    opening = findings(ARC_AFTER.format(call="TRAFOOF"), "sinumerik-840d")
    assert [(f.rule, f.line) for f in opening] == [("TG403", 3)]


def test_m99_is_no_sinumerik_program_end(tmp_path):
    """M17 and RET return, M2/M30 end; M99 is a PLC's M function on a SINUMERIK (TG307), so
    what follows it is the same program's."""
    text = "G0 X10 Y10\nM99\nG2 X30 Y10 I5 J0 F100\nM30\n"
    found = findings(text, "sinumerik-840d")
    assert [(f.rule, f.line) for f in found] == [("TG307", 2), ("TG403", 3)]
    ended = findings(text.replace("M99", "M17"), "sinumerik-840d")
    assert "TG403" not in [f.rule for f in ended]


# -- 4. Okuma OSP: a value ends before the block's next address word ----------------------------

@pytest.mark.parametrize("block, column, message", [
    ("G01 X=VC1+ Z5. F100", 10,
     "'+' without an operand after it: Z5. is the block's next address word, not a value"),
    ("G01 X=VC1* Y10 F100", 10,
     "'*' without an operand after it: Y10 is the block's next address word, not a value"),
    ("VC1=VC2+", 9, "expression ends without an operand"),
    ("G01 X=[VC1+ Z5.] F100", 11,
     "'+' without an operand after it: Z5. is an address word, not a value (a variable's name "
     "begins with two letters)"),
])
def test_okuma_a_dangling_operator_is_located(block, column, message):
    text = f"$T.MIN%\nO1\n{block}\nM02\n"
    assert bad_blocks(text, "okuma-mill") == [("TG100", 3, column, message)]


def test_okuma_an_address_word_after_a_value_is_the_block_s_next_word():
    text = "$T.MIN%\nO1\nVC2=1.5\nG01 X=VC1+VC2 Z5. F100\nG01 X = VC1 + 2 Y10\nM02\n"
    assert bad_blocks(text, "okuma-mill") == []


# -- 5. --decimal implicit for a control that reads no implicit decimals -----------------------

@pytest.mark.parametrize("target, name", [
    ("linuxcnc", "a LinuxCNC"), ("sinumerik-840d", "a SINUMERIK"),
    ("heidenhain-iso", "a HEIDENHAIN"), ("okuma-mill", "an Okuma OSP"),
])
def test_implicit_decimals_are_refused_for_a_control_reading_whole_numbers(tmp_path, target,
                                                                           name):
    from click.testing import CliRunner

    from tapegate.cli import main

    with pytest.raises(ConversionError) as info:
        ConvertOptions(load_profile(target), decimal="implicit")
    assert info.value.code == "conversion-option"
    assert f"{target} is {name} control" in info.value.message
    src = tmp_path / "p.nc"
    src.write_text("G0 X10.5\nM30\n")
    out = tmp_path / "out.nc"
    run = CliRunner().invoke(main, ["convert", str(src), "--to", target, "--decimal",
                                    "implicit", "-o", str(out)])
    assert run.exit_code == 2
    assert run.output.startswith(f"tapegate: --decimal implicit: {target} is {name} control")
    assert not out.exists()


def test_implicit_decimals_stay_allowed_where_the_control_reads_them(tmp_path):
    for target in ("fanuc-mill", "iso-mill", "haas-mill"):
        ConvertOptions(load_profile(target), decimal="implicit")


# -- 6. A read-only variable chosen by a value a jump may change --------------------------------

@pytest.mark.parametrize("body, rule, severity", [
    # a forward jump to N10 may arrive with #1 = 100: the value known is not the only one
    ("#1 = 100\nIF [#2 GT 0] GOTO 10\n#1 = 5021\nN10 #[#1] = 10.\n", "TG210", "warning"),
    ("#1 = 100\nIF [#2 GT 0] GOTO #3\n#1 = 5021\nN10 #[#1] = 10.\n", "TG210", "warning"),
    # no jump names N10 before it: the first pass alarms whatever comes after
    ("#1 = 100\n#1 = 5021\nN10 #[#1] = 10.\n#1 = 100\nGOTO 10\n", "TG209", "error"),
    # set again after the label: the value is the one the control has
    ("IF [#2 GT 0] GOTO 10\nN10 #1 = 5021\n#[#1] = 10.\n", "TG209", "error"),
])
def test_an_uncertain_index_under_a_jump_is_a_warning(body, rule, severity):
    text = "%\nO1\nG21 G90 G00 X0\n" + body + "M30\n%\n"
    found = [(f.rule, f.severity) for f in findings(text, "fanuc-mill")
             if f.rule in ("TG209", "TG210")]
    assert found == [(rule, severity)]
    if rule == "TG210":
        message = next(f.message for f in findings(text, "fanuc-mill") if f.rule == "TG210")
        assert message.endswith("a jump to N10 (line 7) may arrive with another value of #1")


def test_a_jump_in_one_program_does_not_reach_the_next():
    """A GOTO searches its sequence number in the program it runs: the second program's N10
    is no arrival of the first program's jump, so its read-only target is an error (TG209)."""
    text = ("%\nO1\nG21 G90 G00 X0\nIF [#2 GT 0] GOTO 10\nN10 G0 X1\nM99\n%\n"
            "O2\nG21 G90 G00 X0\n#1 = 5021\nN10 #[#1] = 10.\nM30\n%\n")
    found = [(f.rule, f.line, f.column, f.severity) for f in findings(text, "fanuc-mill")
             if f.rule in ("TG209", "TG210")]
    assert found == [("TG209", 11, 5, "error")]


@pytest.mark.parametrize("body, rule, message, said", [
    ("#1=5420\n# #1 = 4\nM2\n", "TG209", "##1 (#5420) is the current position, read only",
     "Parameter is readonly"),
    ("#1=6000\n##1 = 4\nM2\n", "TG206", "index #1 (#6000) of #: allowed 1 to 5601",
     "Parameter number out of range"),
    ("#1=5420\n#[#1] = 4\nM2\n", "TG209", "#[#1] (#5420) is the current position, read only",
     "Parameter is readonly"),
    ("#1=6000\n#[#1] = 4\nM2\n", "TG206", "index [#1] (#6000) of #: allowed 1 to 5601",
     "Parameter number out of range"),
])
def test_linuxcnc_a_parameter_chosen_by_a_parameter_is_checked(tmp_path, body, rule, message,
                                                               said):
    """rs274ngc's read_parameter_setting reads any value after the `#` of an assignment:
    `##1 = 4` sets the parameter #1 names, as `#[#1] = 4` does, under the same rules."""
    ran, out = rs274(tmp_path, body)
    assert not ran and said in out
    found = [(f.rule, f.line, f.column, f.severity) for f in findings(body, "linuxcnc")
             if f.severity == "error"]
    assert found == [(rule, 2, 1, "error")]
    assert next(f.message for f in findings(body, "linuxcnc")
                if f.rule == rule).startswith(message)


def test_linuxcnc_a_parameter_chosen_by_an_unknown_value_says_nothing():
    body = "##2 = 4\nM2\n"
    assert [f for f in findings(body, "linuxcnc") if f.rule in ("TG206", "TG209")] == []


@pytest.mark.parametrize("sub, end, call", [
    ("o0100 sub", "o0100 endsub", "o100 call"),
    ("o100 sub", "o100 endsub", "O 0 1 0 0 call"),
    ("o<Sq> sub", "o<sq> endsub", "O<SQ> call"),
])
def test_linuxcnc_an_o_label_is_a_number_or_a_name_in_any_case(tmp_path, sub, end, call):
    """rs274ngc reads a numbered o-word as a number (o0100 is o100) and a named one in lower
    case: the call reaches the subroutine, so the argument it passes converts as a length."""
    body = f"G21\n#<d>=2\n{sub}\nG0 X#1\n{end}\n{call} [#<d>]\nM2\n"
    ran, out = rs274(tmp_path, body)
    assert ran and "STRAIGHT_TRAVERSE(2.0000" in out, out
    assert not [f for f in findings(body, "linuxcnc") if f.severity == "error"]
    lines = convert_text(body, LINUXCNC_INCH)[0].splitlines()
    assert lines[:2] == ["G20", "#<d>=0.07874"]
    assert lines[2:] == body.splitlines()[2:]


def test_linuxcnc_a_call_to_another_label_is_still_refused():
    body = "G21\n#<d>=2\no0100 sub\nG0 X#1\no0100 endsub\no101 call [#<d>]\nM2\n"
    assert "o101, a subroutine not defined in this file" in str(refused(body))
