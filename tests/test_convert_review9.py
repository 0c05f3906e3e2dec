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
