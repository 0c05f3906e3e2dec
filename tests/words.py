"""Hypothesis strategies for plain words, shared by the tests that compare a fast path (arrays)
with the block path."""

from __future__ import annotations

from hypothesis import strategies as st

FRACTIONS = ["", "0", "5", "25", "125", "0001", "1234", "00000"]


def plain_word(letters: str, wholes: list[str], signs: list[str]) -> st.SearchStrategy[str]:
    """A word of one of ``letters``: a sign, then a number with or without a decimal sign
    (leading and trailing zeros, ``.5``, ``12.``)."""

    @st.composite
    def word(draw: st.DrawFn) -> str:
        letter = draw(st.sampled_from(letters))
        sign = draw(st.sampled_from(signs))
        whole = draw(st.sampled_from(wholes))
        fraction = draw(st.sampled_from(FRACTIONS))
        dot = draw(st.booleans()) or not whole
        if not whole and not fraction:
            whole = "0"
        return letter + sign + whole + ("." + fraction if dot else "")

    return word()
