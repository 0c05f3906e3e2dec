"""A word whose role is not known (review 10, findings 1-5 and 8): a change of units never
scales it, rounds it or reads it in increments to write it anew. Without --allow-unconverted it
is refused at its line and column; with it, its text is kept exactly, each such word named by
line and column, and refused where the target would read the same text as another number.
--verify compares it as written, so a changed number is no "verified"."""

from __future__ import annotations

from pathlib import Path

import pytest

from formats.convert import ConvertOptions, convert_file, convert_text
from formats.errors import ConversionError
from formats.profile import load_profile
from formats.verify import verify_conversion
from postproc.check import check_text


def convert(text: str, profile_name: str, units: str, allow: bool = False,
            target: str | None = None) -> tuple[str, list[str]]:
    source = load_profile(profile_name)
    options = ConvertOptions(target=load_profile(target or profile_name), source=source,
                             units=units, allow_unconverted=allow)
    out, stats = convert_text(text, options)
    return out, list(stats.notes)


def refusal(text: str, profile_name: str, units: str, allow: bool = False,
            target: str | None = None) -> str:
    with pytest.raises(ConversionError) as e:
        convert(text, profile_name, units, allow, target)
    return str(e.value)


def haas(body: str, units: str = "G20") -> str:
    return f"%\nO01008\n{units} G90 G54\nG00 X1. Y1.\n{body}\nM30\n%\n"


# -- 1: a variable read by a word of unknown role ----------------------------------------------


@pytest.mark.parametrize("allow", [False, True])
def test_a_variable_read_by_a_word_of_unknown_role_is_not_scaled_behind_it(allow):
    """`M19 R#2` with #2=3.: R's role is not known, and the analysis converts #2 as a length, so
    kept as written R would read 76.2 for 3. (it did, and said so "left as written")."""
    text = haas("#2=3.\nM19 R#2")
    said = refusal(text, "haas-mill", "metric", allow)
    assert ":6:5: R#2: the source control's manual" in said
    if allow:
        assert "reads #2, which this conversion converts as a length: its value would change" \
            in said


def test_a_variable_read_by_no_length_is_kept_with_the_word():
    """#3 read only by a dwell's P is no length: the word and its parameter are kept alike."""
    out, _ = convert(haas("#3=2.\nG04 P#3"), "haas-mill", "metric")
    assert "#3=2." in out.splitlines() and "G04 P#3" in out.splitlines()


# -- 2 and 10: G268 as the Autodesk Haas post writes it ----------------------------------------

POST = "G268 X0. Y0. Z0. I0. J-90. K0. Q123 (ENABLE FCS)\nG01 X2. Y1. F10.\nG269"


@pytest.mark.parametrize("units, to, expected", [
    ("G21", "inch", "G268 X0 Y0 Z0 I0. J-90. K0. Q123 (ENABLE FCS)"),
    ("G20", "metric", "G268 X0 Y0 Z0 I0. J-90. K0. Q123 (ENABLE FCS)"),
])
def test_the_posts_g268_converts_its_origin_and_keeps_its_angles_and_order(units, to, expected):
    """X Y Z the origin (lengths), I J K angles, Q123 the rotation order: Q123 was Q0.123 one
    way and refused the other, and the block was refused without the option."""
    out, _ = convert(haas(POST, units), "haas-mill", to)
    assert expected in out.splitlines()
    moved, _ = convert(haas("G268 X1. Y2. Z0. I0. J45. K0. Q123\nG269"), "haas-mill", "metric")
    assert "G268 X25.4 Y50.8 Z0 I0. J45. K0. Q123" in moved.splitlines()


def test_a_changed_selector_is_no_verified_conversion(tmp_path: Path):
    profile = load_profile("haas-mill")
    src, out = tmp_path / "p.nc", tmp_path / "o.nc"
    src.write_text(haas(POST, "G21"))
    options = ConvertOptions(target=profile, source=profile, units="inch",
                             allow_unconverted=True)
    stats = convert_file(str(src), str(out), options, verify=True)
    assert stats.verified
    out.write_text(out.read_text().replace("Q123", "Q0.123"))
    with pytest.raises(ConversionError) as e:
        verify_conversion(str(src), str(out), profile, options, stats, file="p.nc")
    assert e.value.code == "conversion-verify" and e.value.line == 5


# -- 3: a user M code's P Q R ------------------------------------------------------------------

USER_M = "%\nO0011\nG21 G90 G54\nG00 X10. Y10. Z5.\nM100 P1 Q2.5 R3.123\nM30\n%\n"


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill"])
def test_an_unlisted_m_code_s_words_are_refused_or_kept_exactly(profile, tmp_path: Path):
    """M100 is no code of the list (a builder's, or a macro call by parameters 6080-6089): its
    P Q R were converted as lengths (Q0.0984 R0.123), silently."""
    said = refusal(USER_M, profile, "inch")
    assert ":5:6: P1: the source control's manual, as tapegate has it, does not say what P" in said
    out, notes = convert(USER_M, profile, "inch", allow=True)
    assert "M100 P1 Q2.5 R3.123" in out.splitlines()
    assert [n for n in notes if "left as written" in n] == [
        f"line 5:{c}: {w} left as written (its role here is not known; --allow-unconverted)"
        for c, w in ((6, "P1"), (9, "Q2.5"), (14, "R3.123"))]
    # verify compares them as written: the old output is a changed number, not verified
    p = load_profile(profile)
    src, dst = tmp_path / "p.nc", tmp_path / "o.nc"
    src.write_text(USER_M)
    options = ConvertOptions(target=p, source=p, units="inch", allow_unconverted=True)
    stats = convert_file(str(src), str(dst), options, verify=True)
    # kept as written under a change of units: compared as written, so "partly verified"
    assert not stats.verified and stats.left_as_written == 3
    dst.write_text(dst.read_text().replace("Q2.5", "Q0.0984"))
    with pytest.raises(ConversionError) as e:
        verify_conversion(str(src), str(dst), p, options, stats, file="p.nc")
    assert e.value.line == 5


def test_a_listed_m_code_and_a_cycle_keep_their_roles():
    """M98 P is a program number and a drilling cycle's R a length, M08 beside it or not."""
    text = "%\nO0012\nG21 G90 G54\nM98 P1000\nG81 X10. Y10. Z-5. R2. F100. M08\nG80\nM30\n%\n"
    out, _ = convert(text, "fanuc-mill", "inch")
    assert "M98 P1000" in out.splitlines()
    assert "G81 X0.3937 Y0.3937 Z-0.1969 R0.0787 F3.937 M08" in out.splitlines()


def test_an_okuma_spindle_orientation_r_is_not_scaled():
    """OSP M19 R90. became R3.5433, on no source."""
    text = "%\nO0013\nG21 G90\nG00 X10. Y10.\nM19 R90.\nM30\n%\n"
    assert ":5:5: R90.: the source control's manual" in refusal(text, "okuma-mill", "inch")
    out, _ = convert(text, "okuma-mill", "inch", allow=True)
    assert "M19 R90." in out.splitlines()


# -- 4: checks.pqr = "parameter" ---------------------------------------------------------------

ISO = ("%\nN10 G71 G90\nN20 G00 X10. Y10. R0.00005\nN30 G81 X20. Y20. Z-5. R2.12345 F100.\n"
       "N40 G80\nN50 M30\n")


def test_a_parameter_word_is_kept_exactly_not_rounded_to_the_target_format():
    """iso-mill's R (checks.pqr R = "parameter") was rounded to R+054: R0 and R2.1234."""
    assert ":3:19: R0.00005: the source profile does not say whether R is a length" in refusal(
        ISO, "iso-mill", "inch")
    out, notes = convert(ISO, "iso-mill", "inch", allow=True)
    lines = out.splitlines()
    assert "N20 G00 X0.394 Y0.394 R0.00005" in lines
    assert "N30 G81 X0.787 Y0.787 Z-0.197 R2.12345 F3.9" in lines
    assert "line 4:24: R2.12345 left as written (its role here is not known; " \
        "--allow-unconverted)" in notes


def test_a_pointless_word_of_unknown_role_read_in_increments_is_refused():
    """FANUC lathe `G51.2 P1 Q2 R10` metric: R10 is 0.010 mm only if R is a length in increments,
    the role nothing gives it; it was written R0.01 (R100 with implicit decimals). Written with
    a point it is kept."""
    text = "%\nO0012\nG21 G90\nG00 X10. Z5.\nG51.2 P1 Q2 R10\nG50.2\nM30\n%\n"
    said = refusal(text, "fanuc-lathe", "inch", allow=True)
    assert ":5:13: R10: a word whose role" in said and "least input increments" in said
    out, _ = convert(text.replace("R10", "R10."), "fanuc-lathe", "inch", allow=True)
    assert "G51.2 P1 Q2 R10." in out.splitlines()


# -- 5: TG201 on a word of unknown role --------------------------------------------------------


@pytest.mark.parametrize("block, word", [("M19 R90", "R90"), ("G268 X1. Y2. Z0. I0. J45 K0. Q1",
                                                              "J45")])
def test_a_word_of_unknown_role_without_a_point_is_tg201_as_the_profile_reads_it(block, word):
    """Haas reads these letters in increments with Setting 162 off, whatever the code: the
    warning is back, and it claims no role."""
    hits = [f for f in check_text(haas(block), load_profile("haas-mill")) if f.rule == "TG201"]
    assert [(f.line, f.message.split(" ")[0]) for f in hits] == [(5, word)]


@pytest.mark.parametrize("profile, text, at", [
    ("fanuc-mill", "%\nO1\nG21 G90 G54\n#1=2.5\nG00 X1. Y1.\nG05.1 Q#1\nM30\n%\n", ":6:7:"),
    ("haas-mill", haas("#1=2.5\nG268 X1. Y2. Z0. I0. J45. K0. Q#1\nG269"), ":6:31:"),
])
@pytest.mark.parametrize("allow", [False, True])
def test_a_selector_reading_a_parameter_scaled_as_a_length_is_refused(profile, text, at, allow):
    """`G05.1 Q#1` (and G268's Q#1): the analysis takes #1 for a length by Q's profile role, so
    #1=2.5 became 0.0984 while the selector read it (on main too, and silently); kept as
    written, the word reads the new value, so --allow-unconverted cannot keep it either."""
    said = refusal(text, profile, "inch" if "G21" in text else "metric", allow)
    assert f"{at} Q#1 reads #1, which this conversion converts as a length" in said


# -- review 12, 1: a change of decimal style rewrites no word of unknown role -------------------


def to_implicit(text: str, target: str = "haas-mill", allow: bool = False):
    options = ConvertOptions(target=load_profile(target), source=load_profile("haas-mill"),
                             decimal="implicit", allow_unconverted=allow)
    return convert_text(text, options)


@pytest.mark.parametrize("target", ["haas-mill", "fanuc-mill"])
def test_a_decimal_style_change_refuses_an_m_codes_q_and_r_at_their_column(target):
    """`M199 Q10. R2.5` to implicit decimals became `Q10000 R2500`: haas-mill's checks.pqr calls
    Q and R lengths, but an M code's words have no role the profile gives."""
    with pytest.raises(ConversionError) as e:
        to_implicit(haas("M199 Q10. R2.5", "G21"), target)
    said = str(e.value)
    assert ":5:6: Q10.: a word whose role the source control's manual" in said
    assert "Q10000" in said and "cannot hold it as written" in said


def test_with_allow_unconverted_a_word_the_implicit_target_cannot_hold_is_refused():
    """An implicit-decimal target writes Q without its point: `Q10.` cannot be kept as written."""
    with pytest.raises(ConversionError) as e:
        to_implicit(haas("M199 P5.5 Q10. R2.5", "G21"), allow=True)
    assert ":5:11: Q10.: " in str(e.value)
    assert "cannot hold it as written" in str(e.value)


@pytest.mark.parametrize("allow", [False, True])
def test_a_word_both_controls_read_alike_keeps_its_text(allow):
    """Haas reads P whole with or without implicit decimals: `M199 P5.5` keeps its text (it
    was about to be rounded to P6), named in a note under --allow-unconverted; `M199 P7 Q3`
    keeps Q3 (the same digits, no point to lose)."""
    out, stats = to_implicit(haas("M199 P5.5\nM199 P7 Q3", "G21"), allow=allow)
    lines = out.splitlines()
    assert "M199 P5.5" in lines and "M199 P7 Q3" in lines
    assert any("5:6: P5.5 left as written" in n for n in stats.notes) == allow


def test_a_listed_m_codes_q_and_r_are_not_lengths_under_a_change_of_units():
    """Haas M130 is listed (display media) but the profile gives no role to its Q and R: they
    were scaled as lengths (Q0.3937) under --units inch."""
    said = refusal(haas("M130 P5. Q10. R2.", "G21"), "haas-mill", "inch")
    assert ":5:6: P5.: the source control's manual" in said


# -- review 12, 4: words left as written under a change of units are no "verified" -----------


def test_words_left_as_written_under_a_change_of_units_are_partly_verified(tmp_path: Path):
    """`#1=10.` kept and `X#1` reading it: 10 in where it was 10 mm. The notes named it, yet
    the result said "verified"; now it is not, and the summary says how many words were left."""
    from click.testing import CliRunner

    from tapegate.cli import main
    profile = load_profile("haas-mill")
    src, out = tmp_path / "p.nc", tmp_path / "o.nc"
    src.write_text(haas("#1=10.\nG00 X#1\nM199 P#1\nM19 R90.5", "G21"))
    options = ConvertOptions(target=profile, source=profile, units="inch",
                             allow_unconverted=True)
    stats = convert_file(str(src), str(out), options, verify=True)
    assert not stats.verified and stats.left_as_written >= 2
    run = CliRunner().invoke(main, ["convert", str(src), "--from", "haas-mill", "--to",
                                    "haas-mill", "--units", "inch", "--allow-unconverted",
                                    "--verify", "-o", str(tmp_path / "c.nc")])
    assert run.exit_code == 0, run.output
    assert f"partly verified: {stats.left_as_written} words left as written" in run.output
    # without a word left the same file is verified
    src.write_text(haas("G00 X10.", "G21"))
    assert convert_file(str(src), str(tmp_path / "o2.nc"), options, verify=True).verified
