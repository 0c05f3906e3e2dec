"""Conversions that must not move the machine elsewhere: what the control reads is kept, or the
conversion is refused with a located reason (docs/convert.md, "What a word means").

Each program here is the smallest one that showed a wrong conversion: a G91 path across a
units code, counts and selectors of cycles written without a point, values with a point that
the conversion does not scale.
"""

from __future__ import annotations

import pytest

from formats.convert import ConvertOptions, convert_text
from formats.profile import load_profile


def convert(text: str, source: str, target: str | None = None, **kw) -> str:
    src = load_profile(source)
    dst = load_profile(target or source)
    out, _ = convert_text(text, ConvertOptions(target=dst, source=src, **kw))
    return out


def test_an_increment_after_a_units_code_moves_from_the_place_reached():
    """The machine keeps its place through G20/G21; the increment after it is in the new
    units: 10 mm, +1 in (35.4 mm), +1 mm (36.4 mm = 1.43307 in, written from 1.3937 in as
    +0.0394)."""
    src = "O1\nG21 G91\nG0 X10.\nG20\nX1.\nG21\nX1.\nM30\n"
    assert convert(src, "fanuc-mill", units="inch").splitlines()[2:] == [
        "G0 X0.3937", "G20", "X1.", "G20", "X0.0394", "M30"]
    back = "O1\nG20 G91\nG0 X1.\nG21\nX10.\nG20\nX1.\nM30\n"
    assert convert(back, "fanuc-mill", units="metric").splitlines()[2:] == [
        "G0 X25.4", "G21", "X10.", "G21", "X25.4", "M30"]
    # LinuxCNC reads G91 across G20/G21 the same way (rs274 -g: X 10 mm, 1.3937 in, 36.4 mm)
    ngc = "G21 G91\nG0 X10\nG20\nX1\nG21\nX1\nM2\n"
    assert convert(ngc, "linuxcnc", units="inch").splitlines()[-2] == "X0.03937"
    # without a change of units the program is kept as written
    assert convert(src, "fanuc-mill") == src


@pytest.mark.parametrize("profile, line, word", [
    # FANUC 0i-MF canned cycles: K the number of repeats
    ("fanuc-mill", "G81 X20. Y20. Z-5. R2. K2 F100.", "K2"),
    ("fanuc-mill", "G98 G83 X10. Y10. Z-20. R2. Q5. F100. K3", "K3"),
    # FANUC 0i-TF G73 first block: R the number of divisions
    ("fanuc-lathe", "G73 U5. W2. R3", "R3"),
    # Haas lathe G76 A the tool nose angle, "do not use a decimal point"; G71 R1 the type II
    # roughing selector
    ("haas-lathe", "G76 X0.9 Z-1. K0.06 D0.01 F0.0625 A60", "A60"),
    ("haas-lathe", "G71 P10 Q20 U0.02 W0.005 D0.1 F0.01 R1", "R1"),
    # Haas G84 J the retract multiple
    ("haas-mill", "G84 Z-0.5 R0.1 J2 F25.", "J2"),
])
def test_a_count_or_selector_of_a_cycle_is_kept_whole(profile, line, word):
    inch = profile.startswith("haas")
    text = f"O1\n{'G20' if inch else 'G21'}\n{line}\nM30\n"
    assert convert(text, profile) == text
    out = convert(text, profile, units="metric" if inch else "inch").splitlines()[2]
    assert word in out.split(), out


def test_the_repeat_count_stays_a_count_and_the_lengths_convert():
    out = convert("O1\nG21\nG81 X20. Y20. Z-5. R2. K2 F100.\nM30\n", "fanuc-mill", units="inch")
    assert out.splitlines()[2] == "G81 X0.7874 Y0.7874 Z-0.1969 R0.0787 K2 F3.937"
    # a Haas G83's I J K are peck depths, lengths
    out = convert("O1\nG20\nG83 Z-1. I0.2 J0.05 K0.1 R0.1 F10.\nM30\n", "haas-mill",
                  units="metric")
    assert out.splitlines()[2] == "G83 Z-25.4 I5.08 J1.27 K2.54 R2.54 F254."


@pytest.mark.parametrize("profile, line", [
    ("haas-mill", "G51 X0 Y0 P1.5"),     # Haas G51 P: the scale factor, 0.001 to 999.999
    ("haas-mill", "G04 P1.5"),           # Haas G04 P with a point: seconds
    ("haas-mill", "G82 Z-0.5 R0.1 P0.5 F10."),
    ("fanuc-mill", "G04 P1.5"),
])
def test_a_value_with_a_point_the_conversion_does_not_scale_is_kept(profile, line):
    inch = profile.startswith("haas")
    text = f"O1\n{'G20' if inch else 'G21'}\n{line}\nM30\n"
    assert convert(text, profile).splitlines()[2] == line
    p = line.split()[-1] if line.startswith(("G51", "G04")) else "P0.5"
    out = convert(text, profile, units="metric" if inch else "inch").splitlines()[2]
    assert p in out.split(), out
