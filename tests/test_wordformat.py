from decimal import Decimal

import pytest
from hypothesis import given
from hypothesis import strategies as st

from formats.classification import word_format_from_spec
from formats.convert import ConvertOptions, convert_text
from formats.errors import ConversionError
from formats.profile import NEUTRAL, load_profile
from formats.wordformat import Rounding, WordFormat, Zeros

X_LEADING = word_format_from_spec("X", True, "053")
X_TRAILING = word_format_from_spec("X", True, "530")


def test_annex_c_leading_zero_reading():
    assert X_LEADING.read("", "1030", False) == Decimal("1.030")
    assert X_LEADING.read("-", "12", False) == Decimal("-0.012")
    assert X_LEADING.read("", "10300", False) == Decimal("10.300")
    assert X_LEADING.read("", "0", False) == 0


def test_annex_c_trailing_zero_reading():
    assert X_TRAILING.read("", "000103", False) == Decimal("10.300")
    assert X_TRAILING.read("", "1030", False) == Decimal("10300.000")
    assert X_TRAILING.read("", "0", False) == 0


def test_explicit_decimal_reading():
    # 6.1: in explicit mode a word without a decimal sign is a whole number
    assert X_LEADING.read("", "1030", True) == Decimal(1030)
    assert X_LEADING.read("", ".03", True) == Decimal("0.03")
    assert X_LEADING.read("-", "1.", False) == Decimal(-1)


def test_trailing_digit_overflow_is_an_error():
    with pytest.raises(ConversionError) as err:
        X_TRAILING.read("", "123456789", False)
    assert (err.value.code, err.value.clause) == ("conversion-format", "Annex C")
    assert "holds 8" in err.value.message  # the capacity the format has: no field holds it


def test_holds_counts_the_digits_before_the_decimal_sign():
    """What an operator's number (send --clearance) must be to be written in the word: finite,
    with no more digits before the decimal sign than the format has."""
    fmt = WordFormat("Z", 5, 3, signed=True)
    for fits in ("0", "-0", "99999.999", "-99999.999", "0.0001", "1E+4", "12345"):
        assert fmt.holds(Decimal(fits)), fits
    for not_held in ("100000", "-100000.0", "1E+5", "1E+999", "NaN", "sNaN", "Infinity",
                     "-Infinity"):
        assert not fmt.holds(Decimal(not_held)), not_held


def test_count_words():
    n = word_format_from_spec("N", False, "03")
    assert (n.before, n.decimal, n.zeros) == (3, False, Zeros.LEADING)
    assert n.read("", "010", False) == 10
    s = word_format_from_spec("S", False, "40")  # trailing zeros omitted: S12 is 1200
    assert s.read("", "12", False) == 1200
    assert s.write(Decimal(1200), False) == "12"


def test_writing_each_style():
    assert X_LEADING.write(Decimal("1.030"), False) == "1030"
    assert X_LEADING.write(Decimal("-0.012"), False) == "-12"
    assert X_TRAILING.write(Decimal("10.3"), False) == "000103"
    assert X_LEADING.write(Decimal(0), False) == "0"
    assert X_TRAILING.write(Decimal(0), False) == "0"
    assert X_LEADING.write(Decimal("10"), True) == "10."
    assert X_LEADING.write(Decimal("0.03"), True) == "0.03"
    assert X_LEADING.write(Decimal("5"), True, plus=True) == "+5."
    none = WordFormat("X", 3, 2, True, Zeros.NONE)
    assert none.write(Decimal("1.5"), False) == "00150"
    assert X_LEADING.write(Decimal("12.500"), True) == "12.5"


def test_a_zero_is_one_zero_in_every_style():
    # ISO 6983-1 6.1: a value of only zeros is written with at least one zero; Annex C: "a
    # value of zero is written X0" whichever zeros are omitted. The count words follow the
    # dimension words: the converter (the core) and this writer write 0, never 00 or 000.
    for zeros in Zeros:
        count = WordFormat("M", 2, 0, False, zeros, decimal=False)
        assert count.write(Decimal(0), False) == "0", zeros
        assert WordFormat("X", 3, 2, True, zeros).write(Decimal(0), False) == "0", zeros
    assert WordFormat("T", 4, 0, False, Zeros.NONE, decimal=False).write(
        Decimal(12), False) == "0012"
    # the same as the converter writes it for a target whose words omit no zeros
    none = ConvertOptions(load_profile("iso-mill"), source=NEUTRAL, decimal="implicit",
                          zeros=Zeros.NONE)
    assert convert_text("N1 M0 X0\n", none)[0] == "N1 M0 X0\n"


def _rounded(value: str, rounding: Rounding) -> str:
    """``X`` at ``value`` converted to iso-mill's X+053 (5.3, explicit): the target format's
    resolution applied as the converter applies it."""
    out, _ = convert_text(f"N1 X{value}\n", ConvertOptions(load_profile("iso-mill"),
                                                            source=NEUTRAL, rounding=rounding))
    return out


def test_quantize_policies_and_overflow():
    assert _rounded("1.0005", Rounding.HALF_EVEN) == "N1 X1.\n"
    assert _rounded("1.0005", Rounding.HALF_UP) == "N1 X1.001\n"
    with pytest.raises(ConversionError) as err:
        _rounded("1.0005", Rounding.ERROR)
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-format", 1, 4)
    # one code for a refused rounding and an overflow: only the wording tells them apart
    assert "rounding is not allowed" in err.value.message
    with pytest.raises(ConversionError) as err:
        _rounded("123456.", Rounding.HALF_EVEN)
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-format", 1, 4)
    assert "digit overflow" in err.value.message
    assert _rounded("99999.999", Rounding.ERROR) == "N1 X99999.999\n"


values = st.decimals(min_value=Decimal("-99999.999"), max_value=Decimal("99999.999"),
                     places=3, allow_nan=False, allow_infinity=False)


@given(values, st.sampled_from([X_LEADING, X_TRAILING, WordFormat("X", 5, 3, True, Zeros.NONE)]),
       st.booleans())
def test_write_then_read_is_identity(value, fmt, explicit):
    written = fmt.write(value, explicit)
    sign = written[0] if written[0] in "+-" else ""
    assert fmt.read(sign, written.lstrip("+-"), explicit) == value
