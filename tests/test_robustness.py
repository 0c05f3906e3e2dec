"""What the fuzzing of the Python API found (fuzz/, docs/robustness.md): each input ends in a
located, clear error or in the right result -- never a traceback."""

from __future__ import annotations

from decimal import Decimal

import pytest
from click.testing import CliRunner

from dnc.gateway_config import ConfigError, config_from_text
from dnc.requests import BadRequest, RequestRules, find_program, program_key, recognise
from formats.convert import ConvertOptions, convert_text
from formats.errors import ConversionError, ParseError
from formats.expr import evaluate
from formats.profile import load_profile
from formats.wordformat import WordFormat, Zeros
from tapegate.cli import main

# -- expressions (formats/expr.py) ------------------------------------------------------------


@pytest.mark.parametrize("expression, message", [
    ("SQRT[-1]", "SQRT[-1] has no value (outside the function's domain"),
    ("2 + SQRT[R1]", "SQRT[-4] has no value"),
    ("SPRT[2]", "unknown function SPRT; tapegate evaluates SIN, COS, TAN, ATAN, SQRT, ABS"),
    ("ABS[" + "9" * 400 + "]", "ABS[1.00000e+400] has no value"),
])
def test_an_expression_without_a_value_is_a_parse_error(expression, message):
    """Found as a lark VisitError (a math domain error, a KeyError inside the transformer)."""
    with pytest.raises(ParseError) as info:
        evaluate(expression, {"R1": Decimal(-4)})
    assert (info.value.code, info.value.clause) == ("TG100", "6.4.7")
    # no value, an unknown function: one code; the wording names the value and the functions
    assert message in info.value.message


def test_a_chain_of_twenty_thousand_terms_evaluates():
    """Found as a RecursionError: the tree of 1+1+... is as deep as it is long."""
    assert evaluate("+".join(["1"] * 20_000), {}) == 20_000
    assert evaluate("-".join(["R1"] * 5_000), {"R1": Decimal("0.5")}) == Decimal("-2499.0")


def test_a_heidenhain_formula_of_thousands_of_terms_is_checked_on_a_small_stack():
    """A formula's tree is as deep as the formula is long (1+1+... or ----1 in one block of
    64 KB); reading, evaluating and dropping it recursively overflowed a 512 KB thread stack
    (a segmentation fault)."""
    import threading

    from formats.parser import parse_text
    from postproc.check import Checker

    program = ("%LONG G71 *\nN10 Q1 = 10000" + "+1" * 32_000 + " *\nN20 Q2 = "
               + "-" * 60_000 + "1 *\nN30 G01 X+0 FQ1 *\nN40 M30 *\nN99999999 %LONG G71 *\n")
    profile = load_profile("heidenhain-iso")
    found: list[str] = []

    def check() -> None:
        blocks = parse_text(program, profile.dialect, errors="collect")
        found.extend(f.rule for f in Checker(profile).run(blocks))

    size = threading.stack_size(512 * 1024)
    try:
        thread = threading.Thread(target=check)
        thread.start()
        thread.join()
    finally:
        threading.stack_size(size)
    assert "TG602" in found  # FQ1 is 42000: known, and above the feed of 40000


def test_long_expressions_are_not_kept():
    """Found as an out-of-memory (over 256 MB): every tree parsed was cached, 4,096 of them, and
    a tree takes about 250 bytes per character -- 1 GB for distinct expressions of 900."""
    import tracemalloc

    from formats.expr import parse_expression

    tracemalloc.start()
    for i in range(150):
        parse_expression("+".join(["12.5*R1"] * 120) + f"+{i}")
    kept = tracemalloc.get_traced_memory()[0]
    tracemalloc.stop()
    assert kept < 3_000_000  # was 150 trees of 1 kB expressions, over 30 MB
    assert parse_expression("R1+R2") is parse_expression("R1+R2")  # short ones are cached


def test_evaluation_still_exact():
    assert evaluate("[1 + R2] * 3 / 4", {"R2": Decimal("0.2")}) == Decimal("0.9")
    assert evaluate("-SQRT[4] + ABS[-1.5]", {}) == Decimal("-0.5")


# -- parameter analysis (crates/core/src/lengths.rs) ----------------------------------------


def test_an_expression_the_core_cannot_read_is_located_in_a_units_conversion():
    """``Y##136`` passed the tokenizer under fanuc-mill, and the core's expression reader
    refused it with a bare ValueError from the parameter analysis. Macro B has no ``##n`` (it
    writes ``#[#n]``): the tokenizer now refuses it, at its column."""
    fanuc = load_profile("fanuc-mill")
    with pytest.raises((ConversionError, ParseError)) as info:
        convert_text("G0 Y1.\nG0 X#114 Y##136\n", ConvertOptions(target=fanuc, source=fanuc,
                                                                units="inch"), file="p.nc")
    assert (info.value.line, info.value.column) == (2, 11)


def test_the_cli_names_the_file_and_line(tmp_path):
    program = tmp_path / "p.nc"
    program.write_text("%\nG0 Y1.\nG0 Y##136\n%\n")
    result = CliRunner().invoke(main, ["convert", str(program), "-o", str(tmp_path / "o.nc"),
                                       "--from", "fanuc-mill", "--to", "fanuc-mill",
                                       "--units", "inch"], catch_exceptions=False)
    assert result.exit_code == 1 and f"{program}:3" in result.output
    assert "Traceback" not in result.output and not (tmp_path / "o.nc").exists()


def test_a_named_parameter_with_an_at_sign_is_one_parameter():
    """``#<a@1>`` (LinuxCNC) is a parameter like any other. The Python analysis keyed a
    program's own local variables ``name@line`` and read this name as such a key: a
    ``ValueError`` traceback from any units conversion that read it."""
    linuxcnc = load_profile("linuxcnc")
    program = "G21\n#1=5\nG1 X#1 Y#<a@1>\n"
    with pytest.raises(ConversionError) as info:
        convert_text(program, ConvertOptions(linuxcnc, linuxcnc, units="inch"), file="p.ngc")
    assert (info.value.code, info.value.line, info.value.column) == (
        "conversion-unprovable", 3, 8)
    assert "#<a@1> is read as a length (line 3) but not set in this program" in str(info.value)
    out, stats = convert_text(program, ConvertOptions(linuxcnc, linuxcnc, units="inch",
                                                      allow_unconverted=True), file="p.ngc")
    assert out == "G20\n#1=0.19685\nG1 X#1 Y#<a@1>\n"
    assert stats.notes[0].startswith("line 3: Y#<a@1> left unconverted: #<a@1> is read as")


# -- numbers of any length (formats/wordformat.py) ---------------------------------------------


def test_leading_zeros_beyond_the_int_conversion_limit():
    """int() refuses a string of more than 4,300 digits, leading zeros included."""
    zeros = "0" * 5_000
    assert WordFormat("X", 5, 3).read("", zeros + "1", False) == Decimal("0.001")
    assert WordFormat("X", 5, 3).read("-", zeros + "1", True) == Decimal(-1)
    assert WordFormat("X", 5, 3).read("", zeros + "1000", True, increments=True) == 1
    assert WordFormat("X", 5, 3, zeros=Zeros.TRAILING).read("", "001", False) == 100  # 00100000
    assert WordFormat("G", 3, decimal=False).read("", zeros + "1", True) == 1
    fanuc = load_profile("fanuc-mill")
    assert fanuc.value("G" + zeros + "1") == 1 and fanuc.value("X" + zeros + "1.") == 1


def test_too_many_significant_digits_still_name_the_limit():
    with pytest.raises(ConversionError) as info:
        WordFormat("X", 5, 3).read("", "1" * 60_000, True)
    assert info.value.code == "conversion-format"
    # naming the limit is the point of the test (and tells it from an overflow, one code)
    assert "more than the 38 significant digits" in info.value.message


# -- the gateway configuration (dnc/gateway_config.py) -------------------------------------------


@pytest.mark.parametrize("profile, programs, code, key, line, why", [
    ("fanuc-mill", "p/" + "x" * 300, "config-no-folder", "port[0].programs", 5,
     "File name too long"),
    ("x" * 300, "p", "config-profile", "port[0].profile", 4, "built-in profiles"),
])
def test_a_name_too_long_for_the_system_is_a_config_error(tmp_path, profile, programs, code,
                                                           key, line, why):
    """Found as an OSError (ENAMETOOLONG) from Path.is_dir and the profile lookup (which now
    takes such a name for no profile, and lists the built-in ones)."""
    (tmp_path / "p").mkdir()
    text = (f'[[port]]\nname = "m"\nurl = "loop://"\nprofile = "{profile}"\n'
            f'programs = "{programs}"\nreceive = "r"\n')
    with pytest.raises(ConfigError) as info:
        config_from_text(text, tmp_path / "gateway.toml")
    assert (info.value.code, info.value.key, info.value.line) == (code, key, line)
    assert info.value.file == str(tmp_path / "gateway.toml")
    assert why in info.value.message  # the system's reason (or the names to choose from)


# -- remote requests (dnc/requests.py) -----------------------------------------------------------


@pytest.mark.parametrize("text, number", [
    ("(/REQ A /BL \u00b2)", None),  # str.isdigit() says yes, int() says no
    ("(/REQ A /BL " + "1" * 5_000 + ")", "O9999"),  # a numbered request is read whole
])
def test_a_block_that_is_no_sequence_number_is_a_bad_request(text, number):
    with pytest.raises(BadRequest) as info:
        recognise(text, len(text), number, RequestRules())
    assert info.value.code == "request-bad"
    # journalled and answered to the operator as written: the wording is what they read
    assert "/BL needs a block number such as /BL 120" in info.value.message


def test_block_numbers_still_read():
    request = recognise("(/REQ O1234 /BL n120)", 21, None, RequestRules())
    assert request is not None and (request.program, request.block) == ("O1234", 120)


def test_a_number_of_thousands_of_digits_is_no_program_number(tmp_path):
    assert program_key("O" + "1" * 5_000) is None and program_key(":0012") == ("O", 12)
    assert recognise("(PRG=12)", 8, "O" + "9" * 5_000, RequestRules()) is not None
    (tmp_path / "O0012.nc").write_text("%\nM30\n%\n")
    assert find_program(tmp_path, "12").name == "O0012.nc"
    with pytest.raises(Exception) as info:
        find_program(tmp_path, "1" * 5_000)
    assert type(info.value).__name__ == "NotFound"
    assert getattr(info.value, "code", None) == "request-not-found"
