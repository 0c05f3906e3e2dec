from decimal import Decimal

import pytest
from hypothesis import given
from hypothesis import strategies as st

from formats.classification import word_format_from_spec
from formats.errors import ConversionError
from formats.wordformat import Rounding, WordFormat, Zeros, format_explicit

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
    with pytest.raises(ConversionError, match="holds 8"):
        X_TRAILING.read("", "123456789", False)


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
    assert format_explicit(Decimal("12.500")) == "12.5"


def test_quantize_policies_and_overflow():
    assert X_LEADING.quantize(Decimal("1.0005"), Rounding.HALF_EVEN) == Decimal("1.000")
    assert X_LEADING.quantize(Decimal("1.0005"), Rounding.HALF_UP) == Decimal("1.001")
    with pytest.raises(ConversionError, match="rounding is not allowed"):
        X_LEADING.quantize(Decimal("1.0005"), Rounding.ERROR)
    with pytest.raises(ConversionError, match="digit overflow"):
        X_LEADING.quantize(Decimal("123456"), Rounding.HALF_EVEN)
    assert X_LEADING.quantize(Decimal("99999.999"), Rounding.ERROR) == Decimal("99999.999")


values = st.decimals(min_value=Decimal("-99999.999"), max_value=Decimal("99999.999"),
                     places=3, allow_nan=False, allow_infinity=False)


@given(values, st.sampled_from([X_LEADING, X_TRAILING, WordFormat("X", 5, 3, True, Zeros.NONE)]),
       st.booleans())
def test_write_then_read_is_identity(value, fmt, explicit):
    written = fmt.write(value, explicit)
    sign = written[0] if written[0] in "+-" else ""
    assert fmt.read(sign, written.lstrip("+-"), explicit) == value
