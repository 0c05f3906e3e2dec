"""Codes whose number two families give different functions, from the profiles' code tables
(each code's ``meaning`` key, docs/profiles.md): a conversion between two controls refuses a
code both profiles list under different keys, naming the two functions, over every pair of
built-in profiles; a code both give one key is converted.
"""

from __future__ import annotations

import itertools
import os

import pytest

from formats.codes import Code
from formats.convert import ConvertOptions, convert_text
from formats.errors import ConversionError, ProfileError
from formats.profile import Profile, builtin_names, load_profile, profile_from_text

from .conftest import CORPUS

SHOPS = CORPUS / "shops"
GRINDER = "zhituaishangc__SK7420_750_N12_FANUC_HuBeiHengLong__O0100"
NAMES = builtin_names()
PROFILES = {name: load_profile(name) for name in NAMES}
# a handful of codes that some families share and others give another function
CODES = ["G47", "G28", "G76", "G87", "G89", "M97", "M99"]


def _code(profile: Profile, code: str) -> Code | None:
    found = profile.code(code[0], int(code[1:]))
    return found if found is not None and found.status != "unassigned" else None


def _group(duration: str) -> str:
    """The modal group as the core compares it (machine::differing_codes)."""
    if duration in ("", "TBO", "non-modal"):
        return ""
    return "motion" if duration in ("cycle", "motion", "cycle cancel") else duration


def _groups_differ(source: Profile, target: Profile, code: str) -> bool:
    a, b = _code(source, code), _code(target, code)
    if a is None or b is None or len(a.duration) == 1 or len(b.duration) == 1:
        return False
    if code[0] == "M" and _family(source) != _family(target):
        return False  # M codes' groups are compared within a family only
    return _group(a.duration) != _group(b.duration)


def _family(profile: Profile) -> str:
    family = profile.dialect.family
    return "fanuc" if family == "haas" else family  # one language, Custom Macro B


def _same_machine(source: Profile, target: Profile) -> bool:
    """One control and one kind of machine: no code is compared (the same tables)."""
    return (source.dialect.family, source.control_type) == (target.dialect.family,
                                                             target.control_type)


# a lathe's multiple repetitive cycles: one key on FANUC, Haas and LinuxCNC, but each control
# writes the cycle's words in a form of its own (FANUC's two blocks, Haas's one, LinuxCNC's
# o-word contour); only FANUC's and Haas's G70 P Q is one form (docs/convert.md)
OWN_FORMS = {"stock-removal-turning", "stock-removal-facing", "pattern-repeating",
             "face-peck-cycle", "grooving-cycle", "multi-pass-threading", "finishing-cycle"}


def _own_form(source: Profile, target: Profile, meaning: str) -> bool:
    controls = {source.dialect.family, target.dialect.family}
    return (meaning in OWN_FORMS and len(controls) == 2
            and not (meaning == "finishing-cycle" and controls == {"fanuc", "haas"}))


PAIRS = [(a, b, code) for a, b in itertools.permutations(NAMES, 2) for code in CODES
         if not _same_machine(PROFILES[a], PROFILES[b])
         and (ca := _code(PROFILES[a], code)) is not None and ca.meaning
         and (cb := _code(PROFILES[b], code)) is not None and cb.meaning]


def test_the_pairs_cover_codes_both_ways():
    """The parametrised pairs below are not empty by accident: each code has pairs of both
    outcomes, or one where only one is possible."""
    differing = {code for a, b, code in PAIRS
                 if PROFILES[a].code(code[0], int(code[1:])).meaning  # type: ignore[union-attr]
                 != PROFILES[b].code(code[0], int(code[1:])).meaning}  # type: ignore[union-attr]
    assert differing >= {"G47", "G28", "G76", "G87", "G89", "M97", "M99"}
    assert len(PAIRS) > 60


@pytest.mark.parametrize("source, target, code", PAIRS)
def test_a_code_of_another_meaning_is_refused_naming_both_functions(source, target, code):
    a, b = _code(PROFILES[source], code), _code(PROFILES[target], code)
    assert a is not None and b is not None
    text = f"N1\n{code}\n"
    options = ConvertOptions(PROFILES[target], PROFILES[source])
    if PROFILES[target].dialect.family == "heidenhain" != PROFILES[source].dialect.family:
        # no other family's program is written for a TNC (its program frame): refused whole,
        # before any code (test_between_families)
        with pytest.raises(ConversionError) as whole:
            convert_text(text, options)
        assert (whole.value.code, whole.value.line, whole.value.column) == \
            ("conversion-dialect", 1, 1), whole.value.message
        return
    own_form = a.meaning == b.meaning and _own_form(PROFILES[source], PROFILES[target], a.meaning)
    if a.meaning == b.meaning and not own_form:
        if _groups_differ(PROFILES[source], PROFILES[target], code):
            return  # refused by its groups (test_convert_lathes)
        try:
            convert_text(text, options)
        except ConversionError as exc:
            assert not exc.message.startswith(f"{code}: "), exc.message
        return
    with pytest.raises(ConversionError) as refused:
        convert_text(text, options)
    error = refused.value
    assert (error.line, error.column, error.clause) == (2, 1, "codes"), error.message
    assert error.message.startswith(f"{code}: the source and target controls give this code "
                                    "different meanings ("), error.message
    if own_form and not _groups_differ(PROFILES[source], PROFILES[target], code):
        assert f'("{a.function}" with its words in ' in error.message, error.message
        assert f'"{b.function}" with its words in ' in error.message, error.message
    elif not _groups_differ(PROFILES[source], PROFILES[target], code):
        assert f'("{a.function}" on the source, "{b.function}" on the target, by their ' \
               'profiles)' in error.message


def test_haas_g47_engraving_is_refused_for_a_fanuc_and_converted_for_a_haas():
    """The case the hand-kept list missed: Haas's G47 (text engraving) and FANUC's G47 (tool
    offset double increase), both of no modal group."""
    text = "%\nO1\nG21 G90\nG00 X0 Y0\nG47 P0 (ABC) X0 Y0 I0 J0.5 R0.05 Z-0.005 F15.\nM30\n%\n"
    haas = load_profile("haas-mill")
    with pytest.raises(ConversionError) as refused:
        convert_text(text, ConvertOptions(load_profile("fanuc-mill"), haas))
    assert refused.value.message == (
        'G47: the source and target controls give this code different meanings ("text '
        'engraving" on the source, "tool offset double increase" on the target, by their '
        "profiles); tapegate does not translate it: write the target's code for it")
    assert (refused.value.line, refused.value.column) == (5, 1)
    out, _ = convert_text(text, ConvertOptions(haas, haas, units="inch"))
    assert "G47 P0 (ABC) X0 Y0 I0 J0.0197 R0.002 Z-0.0002 F0.59" in out


def test_a_code_one_profile_gives_no_meaning_is_compared_by_its_function():
    """Between two control families a code without a key on one side is refused unless both
    profiles word its function alike: a user's FANUC profile without G47's key still differs
    from the Haas's engraving. An ISO 6983-1 profile (the standard's codes) compares by groups
    alone, as before."""
    with open(os.path.join(os.path.dirname(__file__), "..", "formats", "profiles",
                           "fanuc-mill.toml"), encoding="utf-8") as toml:
        text = toml.read()
    plain = profile_from_text(text.replace(', meaning = "tool-offset-double-increase"', ""))
    assert plain.code("G", 47).meaning == ""  # type: ignore[union-attr]
    program = "G47\n"
    with pytest.raises(ConversionError) as refused:
        convert_text(program, ConvertOptions(plain, load_profile("haas-mill")))
    assert refused.value.message.startswith(
        'G47: the source and target controls give this code different meanings ("text '
        'engraving" on the source, "tool offset double increase" on the target'), \
        refused.value.message
    # worded alike (case and blanks aside), no key is needed
    alike = profile_from_text(text.replace(
        'function = "tool offset double increase", duration = "TBO", '
        'meaning = "tool-offset-double-increase"', 'function = "Text  engraving"'))
    out, _ = convert_text(program, ConvertOptions(alike, load_profile("haas-mill")))
    assert out == program
    iso = profile_from_text('name = "i"\ndescription = "i"\n[codes]\n'
                            'G47 = { function = "my own function" }\n')
    out, _ = convert_text(program, ConvertOptions(load_profile("haas-mill"), iso))
    assert out == program


def test_a_g_code_the_target_does_not_list_is_refused_between_families():
    """LinuxCNC's G90.1 (a decimal code) and Okuma's G15 H (a whole one) to a profile that lists
    neither number's function: one rule, the code refused at its column (review: G90.1 was
    carried to a FANUC whose check says TG307, while G5.1 was refused)."""
    linuxcnc, okuma = load_profile("linuxcnc"), load_profile("okuma-mill")
    for source, target, text, column in (
            (linuxcnc, "fanuc-mill", "G21 G90 G17 G90.1\nG2 X20 Y0 I15 J0 F100\nM2\n", 13),
            (linuxcnc, "haas-mill", "G21 G90 G17 G90.1\nG2 X20 Y0 I15 J0 F100\nM2\n", 13),
            (okuma, "linuxcnc", "G15 H1\nG90 G00 X0 Y0\nM02\n", 1),
            # a SINUMERIK applies a length by D, and has no G43
            (load_profile("fanuc-mill"), "sinumerik-840d", "G43 H1 Z50.\nM30\n", 1)):
        with pytest.raises(ConversionError) as refused:
            convert_text(text, ConvertOptions(load_profile(target), source))
        error = refused.value
        assert (error.line, error.column, error.clause) == (1, column, "codes"), error.message
        assert "no such code (its profile's code list has none)" in error.message


@pytest.mark.parametrize("source, target, code, target_means", [
    # a FANUC grinder builder's M39 is a Haas's turret rotation
    ("fanuc-mill", "haas-mill", "M39", "rotate tool turret (T)"),
    ("fanuc-mill", "haas-mill", "M17", "APC pallet unclamp and APC door open"),
    ("fanuc-mill", "haas-mill", "M21", "optional user M code with M-fin"),
    ("fanuc-mill", "sinumerik-840d", "M17", "end of subprogram"),
    # a G code the FANUC mill lacks alarms there; a Haas mills a circular pocket
    ("fanuc-mill", "haas-mill", "G12", "circular pocket milling CW"),
    ("haas-mill", "fanuc-mill", "G12.1", "polar coordinate interpolation (also G112)"),
])
def test_a_code_only_the_target_lists_is_refused_between_families(source, target, code,
                                                                   target_means):
    """A code the source's table does not list goes to the machine builder's PLC (an M code)
    or alarms (a G code) on the source; the target runs its own function for it: refused at the
    code, naming the target's function (review 6, finding 10)."""
    text = f"G21 G90 G17\nG0 X0. Y0. Z5.\n{code} X0. Y0. I10. F100.\nM30\n"
    if code.startswith("M"):
        text = f"G21 G90 G17\nG0 X0. Y0. Z5.\n{code}\nM30\n"
    with pytest.raises(ConversionError) as refused:
        convert_text(text, ConvertOptions(PROFILES[target], PROFILES[source]))
    error = refused.value
    assert (error.line, error.column, error.clause) == (3, 1, "codes"), error.message
    whose = ("the machine builder's M function, handed to its PLC" if code.startswith("M")
             else "an alarm, or an option")
    assert error.message.startswith(
        f"{code}: the source and target controls give this code different meanings ({whose} "
        "(its profile lists no such code) on the source, "
        f'"{target_means}" on the target'), error.message


def test_a_code_neither_profile_lists_is_carried_with_a_note():
    """An M code neither table lists is the machine builder's on both: carried as written, with
    a note naming it at its first line; a code both lists hold (the everyday codes) is carried
    without one, and one control's profiles note nothing. A FANUC's M07 is its builder's (the
    CNC does not decode it), a Haas's the shower coolant: refused, not carried."""
    text = "G21 G90 G17\nG0 X0. Y0. Z5.\nM43\nM08 M43\nM09\nM30\n"
    fanuc, haas = PROFILES["fanuc-mill"], PROFILES["haas-mill"]
    out, stats = convert_text(text, ConvertOptions(haas, fanuc))
    assert out == text
    # once per code (a builder's M code may stand at every tool change), at its first line
    noted = [n for n in stats.notes if "neither the source's nor the target's profile" in n]
    assert noted == [
        "line 3: M43: neither the source's nor the target's profile lists this code; its "
        "meaning is the machine builder's M function (its PLC decodes it), carried as written "
        "here and wherever it stands: check that the target machine's builder gives it the "
        "same function"], stats.notes
    _, same = convert_text(text, ConvertOptions(fanuc, fanuc))
    assert not any("neither the source's" in n for n in same.notes), same.notes
    with pytest.raises(ConversionError) as refused:
        convert_text("G21 G90 G17\nM07\nM30\n", ConvertOptions(haas, fanuc))
    assert refused.value.message.startswith("M07: the source and target controls give this "
                                            "code different meanings"), refused.value.message
    assert '"shower coolant on" on the target' in refused.value.message


@pytest.mark.skipif(not (SHOPS / GRINDER).is_file(), reason="shops corpus not present")
def test_the_shops_grinder_program_is_refused_for_a_haas():
    """The shops' FANUC grinder program (its builder's M21, M35, M39, M43) converted to a Haas
    mill `ok` before: its M21 is a Haas's user M-fin relay; refused at the first such code."""
    text = (SHOPS / GRINDER).read_text(encoding="latin-1")
    with pytest.raises(ConversionError) as refused:
        convert_text(text, ConvertOptions(PROFILES["haas-mill"], PROFILES["fanuc-mill"]))
    assert refused.value.message.startswith("M21: the source and target controls give this "
                                            "code different meanings"), refused.value.message


def test_a_meaning_is_lower_case_words_joined_by_hyphens():
    text = 'name = "m"\ndescription = "m"\n[codes]\nG47 = { function = "x", meaning = "Text" }\n'
    with pytest.raises(ProfileError) as bad:
        profile_from_text(text)
    assert bad.value.key == "codes.G47.meaning"


def test_every_code_the_listing_leaves_unkeyed_is_refused_between_families():
    """benchmarks/code_meanings.py lists, for each pair of built-in profiles of two families,
    the G codes without a key on one side whose functions differ and those one side lacks:
    each is refused by the converter, both ways, at the code (a program of another family
    for a HEIDENHAIN is refused whole, before any code)."""
    from benchmarks.code_meanings import rows

    dialects = [PROFILES[n] for n in NAMES if PROFILES[n].dialect.family != "iso"]
    checked = 0
    for a, b in itertools.permutations(dialects, 2):
        if a.dialect.family == b.dialect.family:
            continue
        for code, source, _ in rows(a, b, missing=True):
            # (the source's units code is the converter's to write: the target's own)
            if not code.startswith("G") or source == "-" or code in (a.inch_code,
                                                                     a.metric_code):
                continue
            text = f"{code}\n"
            with pytest.raises(ConversionError) as refused:
                convert_text(text, ConvertOptions(b, a))
            error = refused.value
            if b.dialect.family == "heidenhain":
                assert error.code == "conversion-dialect", error.message
                continue
            assert (error.line, error.column) == (1, 1), (a.name, b.name, error.message)
            # (a units code to an OSP lathe, whose units are a parameter, is refused by the
            # units rule first: at the code all the same)
            assert error.message.startswith(f"{code}: "), error.message
            checked += 1
    assert checked > 500
