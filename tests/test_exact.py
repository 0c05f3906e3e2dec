"""A profile's exact numbers kept as their texts until read (formats.exact): every reader gets
the Decimal the field held before, the machine spec the same texts, and a check imports no
``decimal``."""

from __future__ import annotations

import ast
import copy
import dataclasses
import os
import pickle
import subprocess
import sys
import tomllib
from decimal import Decimal
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from formats.errors import ProfileError
from formats.exact import Text, Texts, plain_text, text
from formats.machine import machine_spec
from formats.profile import CheckSettings, Limits, RestartSettings, builtin_names, load_profile

ROOT = Path(__file__).resolve().parent.parent


@given(st.one_of(st.integers(), st.floats(allow_nan=False, allow_infinity=False)))
def test_a_numbers_text_is_written_as_its_decimal_writes_it(value):
    expected = str(Decimal(str(value)))
    found = plain_text(str(value))
    assert found is None or found == expected
    assert text(Limits(feed_max=Text(value)), "feed_max") == expected
    assert Limits(feed_max=Text(value)).feed_max == Decimal(str(value))


def test_plain_text_leaves_other_forms_to_the_decimal():
    for form in ("1e-05", "1.5e+20", "inf", "-nan", "1_000", "", "-", ".5", "5.", "１"):
        assert plain_text(form) is None
    assert plain_text("-400.0") == "-400.0" and plain_text("0") == "0"


def _numbers(table: dict[str, object], keys: tuple[str, ...]) -> dict[str, Decimal]:
    return {key: Decimal(str(table[key])) for key in keys if key in table}


@pytest.mark.parametrize("name", [*builtin_names(), "neutral"])
def test_a_builtin_profiles_numbers_are_the_decimals_of_its_toml(name):
    """Read by their fields, the limits and tolerances are ``Decimal(str(value))`` of the TOML
    values, as the profile made them before; the spec has their texts."""
    profile = load_profile(name)
    path = ROOT / "formats" / "profiles" / f"{name}.toml"
    data = tomllib.loads(path.read_text(encoding="utf-8")) if path.exists() else {}
    limits = data.get("limits", {})
    spec = machine_spec(profile)
    for key, value in _numbers(limits, ("feed_max", "spindle_max", "rapid_rate")).items():
        held = getattr(profile.limits, key)
        assert held == value and repr(held) == repr(value)
    for axis in "XYZUVWABC":
        if axis in limits:
            pair = tuple(Decimal(str(v)) for v in limits[axis])
            assert profile.limits.axes[axis] == pair
            assert (axis, *map(str, pair)) in spec["travel"]
    for key, value in _numbers(data.get("checks", {}),
                               ("arc_tolerance", "arc_tolerance_relative")).items():
        assert getattr(profile.checks, key) == value
    assert spec["feed_max"] == (None if profile.limits.feed_max is None
                                else str(profile.limits.feed_max))
    assert spec["rapid_rate"] == float(profile.limits.rapid_rate)
    assert spec["arc_tolerance"] == float(profile.checks.arc_tolerance)


EDGE = """\
base = "fanuc-mill"
name = "edge"
[limits]
X = [-1e-05, 1.5e+20]
Y = [-0.0, 0]
Z = [-400.50, 12]
feed_max = 0.0
spindle_max = "1_000.50"
rapid_rate = 2.5
[checks]
arc_tolerance = -0.0
arc_tolerance_relative = 1e-07
[restart]
clearance = 50.0
clearance_x = 0
[work_offsets]
G54 = { X = -400.0, Y = 1e-3, Z = 0 }
[serial]
xon_timeout = "0.5"
char_delay = -0.0
line_delay = 0.25
dc3_reaction = 3
"""


def test_a_profile_files_numbers_in_every_form(tmp_path):
    path = tmp_path / "edge.toml"
    path.write_text(EDGE)
    profile = load_profile(str(path))
    limits = profile.limits
    assert repr(limits.axes) == ("{'X': (Decimal('-0.00001'), Decimal('1.5E+20')), "
                                 "'Y': (Decimal('-0.0'), Decimal('0')), "
                                 "'Z': (Decimal('-400.5'), Decimal('12'))}")
    assert repr(limits.feed_max) == "Decimal('0.0')"
    assert repr(limits.spindle_max) == "Decimal('1000.50')"  # a string, read by Decimal
    assert repr(profile.checks.arc_tolerance) == "Decimal('0')"  # a zero is 0, as before
    assert repr(profile.checks.arc_tolerance_relative) == "Decimal('1E-7')"
    assert repr(profile.restart) == ("RestartSettings(clearance=Decimal('50.0'), "
                                     "clearance_x=Decimal('0'))")
    assert profile.work_offsets == {"G54": {"X": Decimal("-400.0"), "Y": Decimal("0.001"),
                                            "Z": Decimal(0)}}
    serial = profile.serial
    assert (serial.xon_timeout, serial.char_delay, serial.line_delay, serial.dc3_reaction) == (
        0.5, 0.0, 0.25, 3.0)
    assert repr(serial.char_delay) == "0.0"  # a zero is the default, as before
    spec = machine_spec(load_profile(str(path)))
    assert spec["travel"] == [("X", "-0.00001", "1.5E+20"), ("Y", "-0.0", "0"),
                              ("Z", "-400.5", "12")]
    assert spec["work_offsets"] == [(54, "X", "-400.0"), (54, "Y", "0.001"), (54, "Z", "0")]
    assert (spec["feed_max"], spec["spindle_max"], spec["rapid_rate"]) == ("0.0", "1000.50", 2.5)
    assert (spec["arc_tolerance"], spec["arc_tolerance_relative"]) == (0.0, 1e-07)


@pytest.mark.parametrize(("line", "message"), [
    ("feed_max = -1", "limits.feed_max must be at least 0, not -1"),
    ("feed_max = \"-0.5\"", "limits.feed_max must be at least 0, not -0.5"),
    ("rapid_rate = 0.5", "limits.rapid_rate must be at least 1, not 0.5"),
    ("feed_max = \"abc\"", "limits.feed_max must be a number, not 'abc'"),
    ("feed_max = \"inf\"", "limits.feed_max must be a finite number, not 'inf'"),
    ("feed_max = inf", "limits.feed_max must be a finite number, not inf"),
    ("rapid_rate = true", "limits.rapid_rate must be a number, not True"),
    ("X = [3, 2.5]", "limits.X: minimum 3 is above maximum 2.5"),
    ("X = [1e-05, -3e-06]", "limits.X: minimum 0.00001 is above maximum -0.000003"),
])
def test_a_wrong_number_is_told_as_before(tmp_path, line, message):
    path = tmp_path / "bad.toml"
    path.write_text(f'base = "fanuc-mill"\nname = "bad"\n[limits]\n{line}\n')
    with pytest.raises(ProfileError, match="^" + str(path).replace(".", r"\.") + ": "
                       + message.replace("[", r"\[").replace(".", r"\.") + "$"):
        load_profile(str(path))


def test_a_value_given_to_a_record_is_kept_as_it_is():
    assert Limits(feed_max=Decimal("1.50")).feed_max == Decimal("1.50")
    assert Limits(feed_max="12").feed_max == "12"  # a plain str is no text to read
    assert Limits().rapid_rate == Decimal(5000) and type(Limits().rapid_rate) is Decimal
    assert CheckSettings().arc_tolerance == Decimal("0.0282843")
    assert RestartSettings().clearance is None
    held = Limits(axes=Texts({"X": (Text("-1"), Text("2.5"))}), feed_max=Text("10"))
    assert held.__dict__["feed_max"] == "10" and type(held.__dict__["feed_max"]) is Text
    assert held.feed_max == Decimal(10) and type(held.__dict__["feed_max"]) is Decimal
    assert held.axes == {"X": (Decimal(-1), Decimal("2.5"))} and type(held.axes) is dict
    # what reads every field (repr, ==, pickle, copy, dataclasses) reads the Decimals
    fresh = Limits(axes=Texts({"X": (Text("-1"), Text("2.5"))}), feed_max=Text("10"))
    assert pickle.loads(pickle.dumps(fresh)) == held == copy.deepcopy(fresh)
    assert dataclasses.replace(fresh, tool_max=3).axes == held.axes
    assert dataclasses.asdict(fresh)["feed_max"] == Decimal(10)
    with pytest.raises(dataclasses.FrozenInstanceError):
        fresh.feed_max = Decimal(1)  # type: ignore[misc]
    unset = Limits.__new__(Limits)  # (no field set yet: a missing attribute, not a KeyError)
    assert not hasattr(unset, "feed_max") and getattr(unset, "axes", None) is None


def test_the_fields_stay_exact_after_dataclasses_registers_the_class():
    """dataclasses takes a class's attribute away where a field's default is a factory; the
    registration puts the descriptor back, so a profile loaded after it reads the same."""
    dataclasses.fields(Limits)
    dataclasses.fields(load_profile("fanuc-mill"))
    profile = load_profile("haas-mill")
    assert profile.limits.axes["X"] == (Decimal(-30), Decimal(30))
    assert type(Limits.__dict__["axes"]).__name__ == "Exact"


PROBE = """\
import os, sys
sys.argv = ["tapegate", *sys.argv[1:]]
from tapegate.launch import main
try:
    main(clean_exit=True)
except SystemExit:
    pass
print(repr(sorted(m for m in sys.modules if "decimal" in m)), flush=True)
"""


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_check_imports_no_decimal(tmp_path, jobs):
    """Neither before its threads nor in them (the machine spec takes the texts) does a check
    of a profile with limits make a Decimal (``--stats`` does, in the workers: the core gives
    the lowest and highest positions as Decimals)."""
    for n in range(3):
        (tmp_path / f"p{n}.nc").write_text("%\nN1 G21 G90\nN2 G00 X1. F100.\nN3 M30\n%\n")
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    for args in (["-p", "haas-mill", "--format", "json"], ["-p", "fanuc-mill"]):
        done = subprocess.run([sys.executable, "-P", "-c", PROBE, "check", str(tmp_path),
                               *args, "-j", jobs], env=env, capture_output=True, text=True,
                              timeout=60)
        assert ast.literal_eval(done.stdout.splitlines()[-1]) == [], done.stderr
