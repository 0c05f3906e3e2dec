"""A conversion says "ok" only for output the target reads: the target profile's own check, and
where the target is LinuxCNC its interpreter rs274 (the oracle, where installed), refuse
nothing the conversion carried.

1. `#` parameters and `[ ]` expressions: whether the target reads them is its profile's
   dialect (the characters it allows), not its family's. An ISO 6983-1 profile (iso-mill,
   iso-lathe, cm332-quadrant, pm322-eia, sinumerik-7e2) reads none of `#[]`: a FANUC
   `#1=2.5`, `X#1`, `X[#1*2]` converted for one said ok and its check refused the output
   (TG101, TG100). Refused at the source word now (docs/convert.md, "What the target reads").
"""

from __future__ import annotations

import pytest

from formats.convert import ConvertOptions, convert_text
from formats.errors import ConversionError
from formats.parser import parse_text
from formats.profile import builtin_names, builtin_text, load_profile
from postproc.check import Checker

PROFILES = builtin_names()
FANUC = "O1000\nG21 G90 G17\n"


def convert(text: str, source: str, target: str) -> str:
    out, _ = convert_text(text, ConvertOptions(target=load_profile(target),
                                               source=load_profile(source)))
    return out


def target_errors(text: str, target: str) -> list[str]:
    """The errors of the target profile's check of ``text``: each as ``line:rule``."""
    profile = load_profile(target)
    blocks = parse_text(text, profile.dialect, file="out.nc", errors="collect")
    return [f"{f.line}:{f.rule} {f.message}" for f in Checker(profile, file="out.nc").run(
        iter(blocks)) if f.severity == "error"]


def reads(target: str, character: str) -> bool:
    return character in load_profile(target).dialect.extra


# (program body after FANUC's head, the line and column of the refused character, which)
HASH_PROGRAMS = [
    ("#1=2.5\nG0 X0 Y0\nM30\n", 3, 1, "#"),
    ("G0 X0 Y0\nG1 X#1 F100\nM30\n", 4, 5, "#"),
    ("G0 X0 Y0\nG1 X[#1*2] F100\nM30\n", 4, 5, "["),
    ("G0 X0 Y0\nG1 X[1+2] F100\nM30\n", 4, 5, "["),
]


def test_the_profiles_that_read_no_hash_are_the_iso_ones_and_three_families():
    """The measure of the class: which built-in targets read `#` (their dialects), so that a
    new profile without `#` is covered by the tests below without a list to keep."""
    without = sorted(p for p in PROFILES if not reads(p, "#"))
    assert without == ["cm332-quadrant", "heidenhain-iso", "iso-lathe", "iso-mill",
                       "okuma-lathe", "okuma-mill", "pm322-eia", "sinumerik-7e2",
                       "sinumerik-840d"]
    # the ISO 6983-1 profiles among them are of the family that reads `#` where allowed
    assert {load_profile(p).dialect.family for p in without} >= {"iso"}


@pytest.mark.parametrize("target", [p for p in PROFILES
                                    if not reads(p, "#") and load_profile(p).dialect.family
                                    == "iso"])
@pytest.mark.parametrize("body, line, column, character", HASH_PROGRAMS)
def test_a_parameter_or_expression_is_refused_for_a_profile_whose_dialect_lacks_it(
        target, body, line, column, character):
    with pytest.raises(ConversionError) as err:
        convert(FANUC + body, "fanuc-mill", target)
    e = err.value
    assert (e.code, e.line, e.column) == ("conversion-dialect", line, column)
    assert "the target profile's dialect does not read" in e.message
    assert f"'{character}' is not among the characters it allows" in e.message
    # what the conversion refuses, the target's own check refuses in the source as written
    assert any(err.startswith(f"{line}:TG1") for err in target_errors(FANUC + body, target))


@pytest.mark.parametrize("target", ["sinumerik-840d", "okuma-mill"])
def test_a_family_that_reads_no_hash_still_names_both_families(target):
    with pytest.raises(ConversionError) as err:
        convert(FANUC + HASH_PROGRAMS[0][0], "fanuc-mill", target)
    assert (err.value.code, err.value.line, err.value.column) == ("conversion-dialect", 3, 1)
    assert "a parameter of Custom Macro B (Fanuc, Haas), which a" in err.value.message
    assert "control does not read" in err.value.message


@pytest.mark.parametrize("target", ["fanuc-mill", "haas-mill", "linuxcnc"])
@pytest.mark.parametrize("body", [b for b, *_ in HASH_PROGRAMS])
def test_a_target_that_reads_hash_and_brackets_is_given_them_and_reads_them(target, body):
    out = convert(FANUC + body, "fanuc-mill", target)
    assert "#" in out or "[" in out
    assert not [e for e in target_errors(out, target) if e.split()[0].split(":")[1][:3]
                in ("TG1", "TG2")]


def test_a_user_iso_profile_that_allows_hash_is_given_the_parameter(tmp_path):
    """The dialect decides, not the family: an ISO 6983-1 profile of a user's whose characters
    include `#[]*` reads the FANUC parameter, which is carried."""
    text = builtin_text("iso-mill").replace('name = "iso-mill"',
                                            'name = "iso-mill-hash"\nextra_characters = "#[]*"')
    path = tmp_path / "iso-mill-hash.toml"
    path.write_text(text)
    profile = load_profile(str(path))
    assert profile.dialect.hash_parameters and profile.dialect.family == "iso"
    src = FANUC + "#1=2.5\nG0 X#1 Y0\nM30\n"
    out, _ = convert_text(src, ConvertOptions(target=profile, source=load_profile("fanuc-mill")))
    assert "#1=2.5" in out and "X#1" in out
    blocks = parse_text(out, profile.dialect, file="out.nc", errors="collect")
    assert not [f for f in Checker(profile, file="out.nc").run(iter(blocks))
                if f.severity == "error" and f.rule[:3] in ("TG1", "TG2")]
