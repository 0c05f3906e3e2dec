"""A conversion's roundings kept as exact integer pairs (:attr:`ConvertStats.rounding`), and
the summary's text of the largest made from them as the ``Decimal`` of three significant
digits, rounded up, wrote it (docs/benchmarks.md, perf40)."""

from __future__ import annotations

from decimal import ROUND_UP, Decimal, localcontext
from fractions import Fraction

from hypothesis import given, settings
from hypothesis import strategies as st

from formats.conversion import ConvertOptions, ConvertStats, rounding_text
from formats.convert import _lowest, convert_text
from formats.profile import load_profile


def _decimal_text(num: int, den: int) -> str:
    """What the summary wrote before: ``Decimal(num) / Decimal(den)`` at precision 3, rounded
    up, normalized."""
    with localcontext() as ctx:
        ctx.prec = 3
        ctx.rounding = ROUND_UP
        return str((Decimal(num) / Decimal(den)).normalize())


@settings(max_examples=3000, deadline=None)
@given(st.integers(min_value=-10**30, max_value=10**30), st.integers(min_value=1, max_value=10**20))
def test_the_rounding_text_is_decimals(num: int, den: int) -> None:
    assert rounding_text(num, den) == _decimal_text(num, den)


def test_the_rounding_text_at_the_edges() -> None:
    """Exact values, values rounded up to the next power of ten, E notation both ways."""
    for num, den in [(0, 1), (0, 7), (1, 2), (1, 2000), (63, 1270000), (1, 3), (2, 3),
                     (999, 1000), (9995, 10000), (99951, 100000), (9991, 10), (10, 1),
                     (100, 1), (1234, 1), (1, 10**6), (1, 10**7), (127, 10**9), (-1, 3),
                     (99999, 10**11), (5, 254), (1, 254000)]:
        assert rounding_text(num, den) == _decimal_text(num, den), (num, den)
    assert [rounding_text(1, 3), rounding_text(1, 10**7), rounding_text(10, 1)] == [
        "0.334", "1E-7", "1E+1"]


def test_the_pairs_are_in_lowest_terms() -> None:
    for num, den in [(5, 10000), (0, 9), (-6, 4), (6, -4), (7, 1), (1270000, 63)]:
        pair = _lowest(num, den)
        assert pair[1] > 0 and (pair[0], pair[1]) == (Fraction(num, den).numerator,
                                                      Fraction(num, den).denominator)


def test_the_largest_is_the_first_largest_as_max_found_it() -> None:
    stats = ConvertStats(rounding={"X": (1, 2000), "Y": (1, 3000), "Z": (2, 4000), "F": (0, 1)})
    assert stats.largest_rounding_pair() == ("X", (1, 2000))  # Z's equal value comes later
    assert stats.largest_rounding_text() == ("X", "0.0005")
    assert stats.largest_rounding() == ("X", Decimal("0.0005"))
    empty = ConvertStats()
    assert (empty.largest_rounding_text(), empty.largest_rounding()) == (("", "0"),
                                                                         ("", Decimal(0)))


def test_a_conversions_roundings_are_the_fractions_of_its_errors() -> None:
    """25.4 mm is 1 in exactly, 30 mm 1.1811 in written for 1.18110236...: the pair is the
    written value's distance from the exact one."""
    fanuc = load_profile("fanuc-mill")
    _, stats = convert_text("G21\nG1 X25.4 Y30. F254.\nM30\n",
                            ConvertOptions(fanuc, fanuc, units="inch"))
    assert Fraction(*stats.rounding.get("X", (0, 1))) == 0
    assert Fraction(*stats.rounding["Y"]) == abs(Fraction("1.1811") - Fraction(30) / Fraction(
        "25.4"))
    assert stats.largest_rounding_text() == ("Y", rounding_text(*stats.rounding["Y"]))
