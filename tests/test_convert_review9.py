"""Conversions that must move as the source does: a canned cycle ended by any motion-group
code, a dwell's point, the Haas lathe's G199/G107 words, the G code system a B or C target
needs told, and ``--verify`` reading a repeated cycle block and a decimal code as the
converter writes them."""

from __future__ import annotations

from pathlib import Path

import pytest

from formats.conversion import ConvertOptions
from formats.convert import convert_file, convert_text
from formats.errors import ConversionError
from formats.profile import load_profile


def options(source: str | None, target: str, units: str | None = None) -> ConvertOptions:
    return ConvertOptions(target=load_profile(target),
                          source=load_profile(source) if source else None, units=units)


def convert(text: str, source: str | None, target: str, units: str | None = None) -> str:
    out, _ = convert_text(text, options(source, target, units))
    return out


def proved(tmp_path: Path, text: str, source: str, target: str,
           units: str | None = None) -> str:
    """The conversion, read back and proved value by value (``convert --verify``)."""
    path = tmp_path / "p.nc"
    path.write_text(text)
    out = tmp_path / "out.nc"
    convert_file(str(path), str(out), options(source, target, units), verify=True,
                 overwrite=True)
    return out.read_text()


def lines(text: str) -> list[str]:
    return text.strip().splitlines()


# -- 1: a drilling cycle ends at every code of the motion group -----------------------------


THREAD_AFTER_PECK = """%
O8
G21 G99
G00 X0 Z5.
G83 Z-20. Q5000 R-2. F0.1
{code} X19. Z-15. F1.5 Q0
X18.5 Q90000
G00 X30.
M30
%
"""


@pytest.mark.parametrize("profile,code", [
    ("fanuc-lathe", "G32"), ("fanuc-lathe", "G92"), ("haas-lathe", "G92"),
    ("fanuc-lathe-b", "G78"), ("fanuc-lathe-c", "G21"),
])
def test_a_threading_code_ends_the_peck_cycle_and_keeps_its_start_angle(
        tmp_path, profile, code):
    text = THREAD_AFTER_PECK.format(code=code)
    out = lines(proved(tmp_path, text, profile, profile, "inch"))
    # the peck Q of the drilling cycle is a length: 5 mm is 0.1969 in
    assert any(line.startswith("G83") and "Q1969" in line for line in out)
    # Q of the threading code and of the block that repeats it: the start angle, unchanged
    assert any(line.startswith(code) and line.endswith("Q0") for line in out)
    assert "X0.7283 Q90000" in out


def test_a_block_under_the_cycle_still_repeats_it_with_its_roles(tmp_path):
    text = ("%\nO2\nG21 G99\nG00 X0 Z5.\nG98 G83 Z-20. Q5000 R-2. P500 F100.\n"
            "C90. Z-22. Q4000 R-3. P300 F120.\nC180.\nG80\nG00 X50.\nM30\n%\n")
    out = proved(tmp_path, text, "fanuc-lathe", "fanuc-lathe", "inch")
    assert "C90. Z-0.8661 Q1575 R-0.1181 P300 F4.7244" in lines(out)


def test_verify_reads_a_haas_lathe_repeated_peck_as_the_converter_does(tmp_path):
    text = ("%\nO3\nG20\nG00 X0 Z0.2\nG83 X0 Z-1. Q0.1 R0.1 F10.\nX0.5 Z-1.2 Q0.1 R0.05\n"
            "G80\nG00 X2. Z1.\nM30\n%\n")
    out = proved(tmp_path, text, "haas-lathe", "haas-lathe", "metric")
    assert "X12.7 Z-30.48 Q2.54 R1.27" in lines(out)


# -- 6: --verify renumbers the decimal codes between the systems ----------------------------


@pytest.mark.parametrize("source,target,written,expected", [
    ("fanuc-lathe", "fanuc-lathe-b", "G50.3", "G92.1"),
    ("fanuc-lathe", "fanuc-lathe-c", "G50.3", "G92.1"),
    ("fanuc-lathe-b", "fanuc-lathe", "G92.1", "G50.3"),
    ("fanuc-lathe-c", "fanuc-lathe-b", "G92.1", "G92.1"),
])
def test_the_coordinate_preset_is_renumbered_and_verified(
        tmp_path, source, target, written, expected):
    feed = "G99" if source == "fanuc-lathe" else "G95"
    text = f"%\nO1\nG21 {feed}\n{written} X0 Z0\nG00 X50. Z2.\nM30\n%\n"
    out = lines(proved(tmp_path, text, source, target))
    assert f"{expected} X0 Z0" in out


# -- 2: a target of G code system B or C needs the source's system --------------------------


@pytest.mark.parametrize("target", ["fanuc-lathe-b", "fanuc-lathe-c"])
def test_a_b_or_c_target_without_from_is_refused_before_anything_is_written(target):
    with pytest.raises(ConversionError) as info:
        options(None, target)
    assert info.value.code == "conversion-option"
    assert "--from" in info.value.message and "system" in info.value.message


def test_a_b_target_with_from_renumbers_as_before():
    text = "%\nO5\nG21 G98\nG00 X50. Z2.\nG90 X45. Z-20. F150.\nX40.\nM30\n%\n"
    out = lines(convert(text, "fanuc-lathe", "fanuc-lathe-b"))
    assert "G21 G94" in out and "G77 X45. Z-20. F150." in out


def test_a_system_a_target_may_still_detect_its_source():
    out = convert("%\nO1\nG21\nG00 X50. Z2.\nM30\n%\n", None, "fanuc-lathe")
    assert "G00 X50. Z2." in out


# -- 3: a dwell's P with a point is seconds, never written without it -----------------------


@pytest.mark.parametrize("source,target,block,expected", [
    ("haas-mill", "haas-mill", "G04 P1.0", "G04 P1000"),
    ("haas-mill", "fanuc-mill", "G04 P1.0", "G04 P1000"),
    ("haas-mill", "haas-mill", "G04 P2.5", "G04 P2500"),
    ("haas-mill", "haas-mill", "G04 P1500", "G04 P1500"),
    ("haas-mill", "haas-mill", "G82 X0 Y0 Z-0.5 R0.1 P1.0 F10.", "G82 X0 Y0 Z-0.5 R0.1 P1000 F10."),
    ("haas-lathe", "haas-lathe", "G249 X1. Z-0.5 C0 R2.1 P1.0 F10.",
     "G249 X1. Z-0.5 C0 R2.1 P1000 F10."),
])
def test_a_dwell_in_seconds_is_written_in_milliseconds(tmp_path, source, target, block, expected):
    text = f"%\nO9\nG20 G98\nG00 X2. Z0.1\n{block}\nG80\nM30\n%\n"
    if source.endswith("mill"):
        text = text.replace("G98", "G17 G90").replace("X2. Z0.1", "X0 Y0 Z1.")
    assert expected in lines(proved(tmp_path, text, source, target))


def test_a_cycle_s_dwell_in_seconds_is_milliseconds_under_a_change_of_units(tmp_path):
    text = "%\nO1\nG20 G17 G90\nG82 Z-0.5 R0.1 P0.5 F10.\nG80\nM30\n%\n"
    out = lines(proved(tmp_path, text, "haas-mill", "haas-mill", "metric"))
    assert "G82 Z-12.7 R2.54 P500 F254." in out


def test_a_dwell_finer_than_a_millisecond_is_refused():
    with pytest.raises(ConversionError) as info:
        convert("%\nO1\nG20\nG04 P1.0005\nM30\n%\n", "haas-mill", "fanuc-mill")
    assert "milliseconds" in info.value.message


def test_a_dwell_in_seconds_still_converts_to_linuxcnc_seconds():
    out = convert("%\nO1\nG20\nG04 P1.0\nM30\n%\n", "haas-mill", "linuxcnc")
    assert "P1.0" in out


# -- 4: the Haas lathe's G199 R (degrees) and G107 Q R ---------------------------------------


def test_g199_r_is_a_phase_angle_kept_under_a_change_of_units(tmp_path):
    text = "%\nO9\nG20 G98\nG199 R45.\nG199 R90\nM30\n%\n"
    out = lines(proved(tmp_path, text, "haas-lathe", "haas-lathe", "metric"))
    assert "G199 R45." in out and "G199 R90" in out


def test_g107_q_and_r_are_refused_under_a_change_of_units():
    text = "%\nO9\nG20 G98\nG107 C0. R1.0 Q2.0\nM30\n%\n"
    with pytest.raises(ConversionError) as info:
        convert(text, "haas-lathe", "haas-lathe", "metric")
    assert info.value.message.startswith("R1.0")
    assert info.value.code == "conversion-unprovable"
    # without one nothing is scaled
    assert "G107 C0. R1.0" in convert(text, "haas-lathe", "haas-lathe")
