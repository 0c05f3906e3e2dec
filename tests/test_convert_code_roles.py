"""The role of a word comes from a code of its block that gives it one (review 13, findings 1, 3
and 5): an M code's P, Q and R keep the M code's roles whatever G codes share the block
(`G90 M96 P100 Q8` is a block and an input number, never a length); FANUC `M98 Q` and Haas
`M96 P Q` are block and input numbers, kept exactly under a change of units and of decimal
style; and the words of a G code the list lacks and a G65 call's arguments go by the one rule
for a word of unknown role under a change of decimal style: kept where both controls read the
text as the same number, else refused at line:column. --verify reads them as the converter
does, so nothing rewritten is called "verified"."""

from __future__ import annotations

from pathlib import Path

import pytest

from formats.convert import ConvertOptions, convert_file
from formats.errors import ConversionError
from formats.profile import load_profile


def run(tmp_path: Path, text: str, profile: str, *, allow: bool = False, **options: str):
    """The converted text and the statistics of a verified conversion of `text`."""
    src, out = tmp_path / "p.nc", tmp_path / "o.nc"
    src.write_text(text)
    prof = load_profile(profile)
    stats = convert_file(str(src), str(out), ConvertOptions(target=prof, source=prof,
                                                            allow_unconverted=allow, **options),
                         verify=True, overwrite=True)
    return out.read_text(), stats


def refused(tmp_path: Path, text: str, profile: str, *, allow: bool = False,
            **options: str) -> str:
    with pytest.raises(ConversionError) as e:
        run(tmp_path, text, profile, allow=allow, **options)
    return str(e.value)


def haas(body: str, units: str = "G20") -> str:
    return f"%\nO01007\n{units}\n{body}\nM30\nN100 M30\n%\n"


STYLES = [{"units": "metric"}, {"units": "inch"}, {"decimal": "implicit"},
          {"decimal": "explicit"}]


# -- finding 1 and 3: Haas M96 P (a block) Q (an input), with or without a G code ------------


@pytest.mark.parametrize("options", STYLES, ids=lambda o: "-".join(o.values()))
@pytest.mark.parametrize("block", ["G90 M96 P100 Q8", "M96 P100 Q8", "G00 Z1. M96 P100 Q8"])
def test_haas_m96_keeps_its_block_and_input_numbers(tmp_path, block, options):
    """`G90 M96 P100 Q8` became `Q0.02` (or `Q80000`) and "verified": a G code in the block
    gave Q checks.pqr's length. The bare block was refused at P100."""
    out, stats = run(tmp_path, haas(block), "haas-mill", **options)
    assert any(line.endswith("M96 P100 Q8") for line in out.splitlines()), out
    assert stats.verified


def test_an_m96_input_number_with_its_point_is_kept_or_refused_never_rewritten(tmp_path):
    """`Q8.` is input 8 to the control: kept where the target writes points (a change of units
    kept it, Z beside it converted); an implicit-decimal target would write it `Q80000`, read
    as input 80000, so it is refused at its column."""
    out, stats = run(tmp_path, haas("G00 Z1. M96 P100 Q8."), "haas-mill", units="metric")
    assert "G00 Z25.4 M96 P100 Q8." in out.splitlines() and stats.verified
    said = refused(tmp_path, haas("G00 Z1. M96 P100 Q8."), "haas-mill", decimal="implicit")
    assert ":4:18: Q8.: a number the control reads whole here" in said


def test_a_haas_m96_p_names_a_block_of_the_program():
    """The profile gives M96's P N's format: the block it jumps to is searched (TG118)."""
    from postproc.check import check_text
    found = check_text(haas("M96 P100 Q8\nM96 P200 Q8"), load_profile("haas-mill"), file="p.nc")
    missing = [f for f in found if f.rule == "TG118"]
    assert [(f.line, f.column) for f in missing] == [(5, 5)]
    assert "no block N200" in missing[0].message


# -- finding 3: FANUC M98 Q, a call of a block by its sequence number --------------------------


FANUC_CALL = "%\nO0064\nG20 G90 G54\nG00 X1. Y1.\nM98 Q101\nM30\nN101 G90 G00 X2.\nM99\n%\n"


@pytest.mark.parametrize("options", STYLES, ids=lambda o: "-".join(o.values()))
def test_fanuc_m98_q_is_a_sequence_number_kept_as_written(tmp_path, options):
    """Doosan O0064's `M98Q101` calls N101 of the same program: under --decimal explicit it was
    refused as a word of unknown role (before review 12 it became a length, `Q0.0101`)."""
    out, stats = run(tmp_path, FANUC_CALL, "fanuc-mill", **options)
    assert "M98 Q101" in out.splitlines() and stats.verified


# -- finding 1: a listed M code's words beside a G code that reads no P, Q or R ---------------


@pytest.mark.parametrize("block", ["G90 M130 P5. Q10. R2.", "M130 P5. Q10. R2."])
def test_a_listed_m_codes_words_beside_g90_are_not_lengths_under_a_change_of_units(
        tmp_path, block):
    """`G90 M130 P5. Q10. R2.` became `Q254. R50.8`, "verified", where the bare block was
    refused: G90 gives P, Q and R no role."""
    said = refused(tmp_path, haas(block), "haas-mill", units="metric")
    assert "P5.: the source control's manual, as tapegate has it, does not say" in said
    out, stats = run(tmp_path, haas(block), "haas-mill", units="metric", allow=True)
    assert block in out.splitlines()
    assert not stats.verified and stats.left_as_written == 3


def test_a_listed_m_codes_words_beside_g90_are_refused_under_a_change_of_decimal_style(
        tmp_path):
    """To implicit decimals it was `G90 M130 P5. Q100000 R20000`, "verified"."""
    said = refused(tmp_path, haas("G90 M130 P5. Q10. R2."), "haas-mill", decimal="implicit")
    assert ":4:14: Q10.: a word whose role the source control's manual" in said
    assert "cannot hold it as written" in said


def test_a_cycles_and_an_arcs_r_beside_an_m_code_keep_their_length(tmp_path):
    """A code that reads R gives it its role: a drilling cycle's R plane and an arc's radius
    beside M08 are lengths, converted and verified."""
    text = haas("G00 X0 Y0 Z1.\nG81 X1. Y1. Z-0.5 R0.1 F10. M08\nG80\n"
                "G01 X0 F10.\nG02 X2. Y0 R1. M08")
    out, stats = run(tmp_path, text, "haas-mill", units="metric")
    lines = out.splitlines()
    assert "G81 X25.4 Y25.4 Z-12.7 R2.54 F254. M08" in lines
    assert "G02 X50.8 Y0 R25.4 M08" in lines
    assert stats.verified


# -- finding 5: an unlisted G code's words and G65 arguments under a change of decimal style --


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
def test_an_unlisted_g_codes_words_are_not_rewritten_by_a_decimal_style(tmp_path, profile):
    """`G310 Q2.5 R1.` to implicit decimals was `Q2500 R1000`, "verified": what Q and R are to
    the control is not known, so the one rule applies, refused at the column, with the option
    too. On haas-mill a G code past the end of its list (G269) was taken for one of it."""
    text = "%\nO1006\nG21\nG00 X1. Y1.\nG310 Q2.5 R1.\nM30\n%\n"
    for allow in (False, True):
        said = refused(tmp_path, text, profile, decimal="implicit", allow=allow)
        assert ":5:6: Q2.5: a word whose role the source control's manual" in said
    # and under a change of units, refused at the block as a code the list lacks
    said = refused(tmp_path, text, profile, units="inch")
    assert ":5:6: Q2.5 R1.: G310 is not in the source control's G code list" in said


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
def test_an_unlisted_g_codes_word_both_controls_read_alike_is_kept_and_named(tmp_path, profile):
    """P is whole on both: `G310 P5.5` would be rounded to P6 by its format; both controls read
    the text as 5.5, so it is kept exactly, and --allow-unconverted names it."""
    text = "%\nO1006\nG21\nG00 X1. Y1.\nG310 P5.5 Q2.5\nM30\n%\n"
    for allow in (False, True):
        out, stats = run(tmp_path, text, profile, decimal="explicit", allow=allow)
        assert "G310 P5.5 Q2.5" in out.splitlines() and stats.verified
        named = [n for n in stats.notes if "5:6: P5.5 left as written" in n]
        assert len(named) == (1 if allow else 0)


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
def test_macro_call_arguments_are_not_rewritten_by_a_decimal_style(tmp_path, profile):
    """`G65 P9010 A1.5 B2. R3.` to implicit decimals was `A1500 B2000 R3000`, "verified", where
    `M199 Q10.` (an M code macro call, the same argument rule) was refused."""
    text = "%\nO1006\nG21\nG65 P9010 A1.5 B2. R3.\nM30\n%\n"
    said = refused(tmp_path, text, profile, decimal="implicit")
    assert ":4:11: A1.5: a word whose role the source control's manual" in said
    out, stats = run(tmp_path, text, profile, decimal="explicit")
    assert "G65 P9010 A1.5 B2. R3." in out.splitlines() and stats.verified
