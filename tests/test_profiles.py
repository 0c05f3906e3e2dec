import re
from decimal import Decimal

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from formats.errors import ProfileError
from formats.profile import builtin_names, load_profile, profile_from_text


def test_five_builtin_profiles_that_differ_where_machines_differ():
    names = builtin_names()
    assert len(names) >= 5
    profiles = {n: load_profile(n) for n in names}
    # the strict profiles use a standard's table; a control family's is its own list
    assert {p.table.name for p in profiles.values()} == {"iso6983-1", "iso1056", "own"}
    assert all((p.table.name == "own") == (p.dialect.family != "iso")
               for p in profiles.values())
    assert {p.serial.code for p in profiles.values()} == {"iso", "eia"}
    assert {p.explicit for p in profiles.values()} == {True, False}
    # ("", ""): the Okuma OSP lathe's units are a machine parameter (its G20 a home return)
    assert {p.units_codes for p in profiles.values()} == {("G70", "G71"), ("G20", "G21"),
                                                           ("", "")}
    assert {p.control_type for p in profiles.values()} >= {"positioning", "contouring", "lathe"}
    assert profiles["fanuc-mill"].program_number == "O"
    assert profiles["fanuc-mill"].serial.tv_check
    assert profiles["sinumerik-7e2"].serial.eob == "crlf"
    assert str(profiles["pm322-eia"].general) == "PM 322"


def test_reset_states_of_clause_14():
    assert load_profile("iso-lathe").reset_state() == (
        "G01", "G40", "G71", "G80", "G90", "G94", "G97")
    assert load_profile("fanuc-mill").reset_state()[3] == "G21"
    assert load_profile("pm322-eia").reset_state()[0] == "G00"


@pytest.mark.parametrize("name", builtin_names())
def test_a_profiles_description_says_the_feed_mode_of_its_reset(name):
    """iso-lathe's description said "feed per revolution" while its reset (ISO 6983-1 clause
    14.4, contouring on lathes) is G94: a description that names a feed mode names the one
    the modal state starts in."""
    from postproc.state import ModalMachine
    profile = load_profile(name)
    mode = ModalMachine(profile).state.feed_mode
    text = profile.description.lower()
    if "feed per revolution" in text or "feed per minute" in text:
        said = 95 if "feed per revolution" in text else 94
        assert mode == said, (name, profile.description, mode)
    if name == "iso-lathe":
        assert mode == 94 and "feed per minute at reset (G94, clause 14.4)" in profile.description


def test_a_profile_states_its_own_reset_state():
    profile = profile_from_text('name = "x"\nreset = ["G00", "G17", "G40", "G71", "G80", "G90"]\n')
    assert profile.reset_state() == ("G00", "G17", "G40", "G71", "G80", "G90")
    with pytest.raises(ProfileError) as info:
        profile_from_text('name = "x"\nreset = ["G04"]\n')
    assert (info.value.code, info.value.key) == ("profile-value", "reset")


def test_user_file(tmp_path):
    path = tmp_path / "mine.toml"
    path.write_text('name = "mine"\ngeneral = "LM 221"\n[serial]\nbaud = 19200\n')
    profile = load_profile(str(path))
    assert profile.name == "mine" and profile.serial.baud == 19200


def test_dc3_reaction_is_left_to_the_command_unless_the_profile_says():
    assert load_profile("fanuc-mill").serial.dc3_reaction is None
    profile = profile_from_text('name = "x"\n[serial]\nbaud = 115200\ndc3_reaction = 0.002\n')
    assert profile.serial.dc3_reaction == 0.002


@pytest.mark.parametrize("text, code, key", [
    ("colour = 1", "profile-unknown-key", "colour"),
    ('general = "PM 232"', "profile-classification", "general"),
    ('detailed = "X+553*"', "profile-classification", "detailed"),
    ('code_table = "iso9999"', "profile-value", "code_table"),  # not one of the choices
    ("[serial]\nbaud = 1234", "profile-value", "serial.baud"),
    ("[serial]\ndata_bits = 6", "profile-value", "serial.data_bits"),
    ('[serial]\ncode = "eia"', "profile-value", "serial"),  # the EIA code needs more settings
    ("[limits]\nX = [5, 1]", "profile-value", "limits.X"),  # minimum above maximum
    ('[limits]\nfeed_max = "fast"', "profile-value", "limits.feed_max"),
    ("[checks]\nm_classes = [9]", "profile-value", "checks.m_classes"),
    ('[codes]\nQ12 = { function = "x" }', "profile-value", "codes.Q12"),  # not a G or M code
    ("this is not toml", "profile-toml", None),
    ('extra_characters = "A"', "profile-value", "extra_characters"),
    ("[serial]\ntv_check = 1", "profile-value", "serial.tv_check"),
    ("[serial]\ndc3_reaction = -0.001", "profile-value", "serial.dc3_reaction"),
    ('[serial]\ndc3_reaction = "soon"', "profile-value", "serial.dc3_reaction"),
    # checks.read_only: a variable or a range of them, each saying what it holds
    ('[checks.read_only]\n"3030-3020" = "x"', "profile-value", "checks.read_only.3030-3020"),
    ('[checks.read_only]\n"#3020" = "x"', "profile-value", "checks.read_only.#3020"),
    ('[checks.read_only]\n"3020" = ""', "profile-value", "checks.read_only.3020"),
    ('[checks.read_only]\n"3020" = 1', "profile-value", "checks.read_only.3020"),
    ("[checks]\nread_only = [3020]", "profile-value", "checks.read_only"),
])
def test_bad_profiles_name_the_key(text, code, key):
    with pytest.raises(ProfileError) as info:
        profile_from_text(text, source="bad.toml")
    assert (info.value.code, info.value.key, info.value.file) == (code, key, "bad.toml")
    assert str(info.value).startswith("bad.toml: ")


def test_unknown_profile_name_lists_builtins():
    with pytest.raises(ProfileError) as info:
        load_profile("no-such-machine")
    assert info.value.code == "profile-not-found"
    # what the user reads: the names they may choose instead (no field lists them)
    assert ("built-in profiles: cm332-quadrant, fanuc-lathe, fanuc-lathe-b, fanuc-lathe-c, "
            "fanuc-mill") in info.value.message


# The built-in dialect profiles (docs/dialects.md): each loads, and a few facts of each hold --
# its dialect, its units codes, how it reads a number without a point, and known codes with
# their modal groups (the group names every dialect profile shares).
DIALECT_PROFILES = {
    # name: (dialect, units codes, control type, without_point, {code: group})
    "fanuc-mill": ("fanuc", ("G20", "G21"), "contouring", "increments", {}),
    "fanuc-lathe": ("fanuc", ("G20", "G21"), "lathe", "increments",
                    {"G71": "TBO", "G98": "feed mode", "G99": "feed mode", "G96": "spindle mode",
                     "G90": "motion", "G50": "TBO", "G12.1": "polar interpolation"}),
    "fanuc-lathe-b": ("fanuc", ("G20", "G21"), "lathe", "increments",
                      {"G71": "TBO", "G94": "feed mode", "G95": "feed mode", "G77": "motion",
                       "G90": "distance", "G92": "TBO", "G98": "cycle return"}),
    "fanuc-lathe-c": ("fanuc", ("G70", "G71"), "lathe", "increments",
                      {"G73": "TBO", "G70": "units", "G20": "motion", "G24": "motion",
                       "G91": "distance", "G95": "feed mode", "G12.1": "polar interpolation"}),
    "haas-mill": ("haas", ("G20", "G21"), "contouring", "increments",
                  {"G187": "TBO", "G101": "TBO", "G83": "cycle", "G98": "cycle return",
                   "G154": "work offset", "M97": "TBO", "M88": "through-spindle coolant"}),
    "haas-lathe": ("haas", ("G20", "G21"), "lathe", "increments",
                   {"G71": "TBO", "G76": "TBO", "G99": "feed mode", "G50": "TBO",
                    "G96": "spindle mode", "M97": "TBO"}),
    "sinumerik-840d": ("sinumerik", ("G70", "G71"), "contouring", "whole",
                       {"G710": "units", "G700": "units", "G64": "path mode",
                        "G601": "stop criterion", "G505": "work offset", "G500": "work offset",
                        "G153": "TBO", "G96": "feed mode", "M17": "TBO"}),
    "heidenhain-iso": ("heidenhain", ("G70", "G71"), "contouring", "whole",
                       {"G71": "units", "G11": "motion", "G17": "plane", "G41": "cutter",
                        "G98": "TBO", "G99": "TBO", "G200": "TBO", "G79": "TBO"}),
    "linuxcnc": ("linuxcnc", ("G20", "G21"), "contouring", "whole",
                 {"G91.1": "arc distance", "G90": "distance", "G38.2": "motion",
                  "G33.1": "motion", "G81": "motion", "G64": "path mode", "G53": "non-modal",
                  "M02": "stop", "M60": "stop", "M66": "i/o"}),
}


@pytest.mark.parametrize("name", sorted(DIALECT_PROFILES))
def test_dialect_profiles_load_with_their_facts(name):
    dialect, units_codes, control_type, without_point, groups = DIALECT_PROFILES[name]
    profile = load_profile(name)
    assert name in builtin_names()
    assert profile.source == "built-in"
    assert profile.dialect.family == dialect
    assert profile.units_codes == units_codes
    assert profile.control_type == control_type
    assert profile.numbers.without_point == without_point
    assert profile.explicit
    for code, group in groups.items():
        letter, number = code[0], code[1:]
        found = (profile.extra_codes.get(code) if "." in number
                 else profile.code(letter, int(number)))
        assert found is not None, code
        assert found.duration == group, code
    # the units codes are the profile's own, in one modal group
    inch, metric = (profile.code("G", int(c[1:])) for c in units_codes)
    assert inch.modal and inch.duration == metric.duration
    # the reset state names only modal codes of the profile
    for code in profile.reset_state():
        assert profile.code("G", int(code[1:])).modal, code


def test_dialect_profiles_share_group_names():
    """Where two controls have the same modal group, their profiles give it the same name."""
    def group(name, code):
        return load_profile(name).code("G", code).duration

    mills = ["haas-mill", "sinumerik-840d", "heidenhain-iso", "linuxcnc"]
    assert {group(n, 17) for n in mills} == {"plane"}
    assert {group(n, 41) for n in mills} == {"cutter"}
    assert {group(n, 90) for n in mills} == {"distance"}
    assert {group(n, 1) for n in mills + ["fanuc-lathe", "haas-lathe"]} == {"motion"}
    assert {group(n, 54) for n in ["fanuc-lathe", "haas-mill", "haas-lathe", "sinumerik-840d",
                                   "linuxcnc"]} == {"work offset"}
    assert {group(n, 43) for n in ["haas-mill", "linuxcnc"]} == {"length"}
    assert {group(n, 99) for n in ["fanuc-lathe", "haas-lathe"]} == {"feed mode"}
    assert {group(n, 99) for n in ["haas-mill", "linuxcnc"]} == {"cycle return"}


def test_dialect_profiles_read_numbers_as_their_controls_do():
    # Haas and Fanuc lathes: least increments (0.001 mm, 0.0001 in), P and Q whole
    assert load_profile("haas-mill").value("X10000", "metric") == 10
    assert load_profile("haas-mill").value("X10000", "inch") == 1
    assert load_profile("haas-mill").value("F12", "inch") == Decimal("0.0012")  # Setting 77
    assert load_profile("haas-lathe").value("P45") == 45
    assert load_profile("fanuc-lathe").value("Z-5000") == -5
    assert load_profile("fanuc-lathe").value("G21") == 21  # G031 admits G12.1; G is whole
    assert load_profile("fanuc-lathe").value("G12.1") == Decimal("12.1")
    # Siemens, Heidenhain, LinuxCNC: whole numbers
    for name in ("sinumerik-840d", "heidenhain-iso", "linuxcnc"):
        assert load_profile(name).value("X10") == 10


def test_how_the_control_answers_an_unknown_code_is_profile_data():
    """checks.unknown_g / unknown_m: "alarm" makes an unknown code an error (TG306), "warn" a
    warning; absent, the dialect families alarm on G codes, ISO warns."""
    from postproc.check import check_text

    program = "%\nO1\nG21 G90 G00 X0\nG130 X1.\nM30\n%\n"
    alarm = profile_from_text('dialect = "fanuc"\nunits_codes = "G20/G21"\n')
    assert "TG306" in {f.rule for f in check_text(program, alarm)}
    # fanuc-mill warns: parameters 6050-6059 may make G130 a macro call (TG307, whether ISO
    # 6983-1 leaves the code to individual use, as G130, or has it not, as G12.7: the
    # standard's statuses say nothing of a Fanuc)
    rules = {f.rule for f in check_text(program, load_profile("fanuc-mill"))}
    assert "TG306" not in rules and "TG302" not in rules and "TG307" in rules
    rules = {f.rule for f in check_text(program.replace("G130", "G12.7"),
                                        load_profile("fanuc-mill"))}
    assert "TG301" not in rules and "TG307" in rules
    warn = profile_from_text('dialect = "fanuc"\nunits_codes = "G20/G21"\n[checks]\n'
                             'unknown_g = "warn"\n')
    assert "TG306" not in {f.rule for f in check_text(program, warn)}
    assert "TG306" not in {f.rule for f in check_text(program.replace("O1\n", ""),
                                                      load_profile("iso-mill"))}
    with pytest.raises(ProfileError) as info:
        profile_from_text('[checks]\nunknown_m = "sometimes"\n')
    assert (info.value.code, info.value.key) == ("profile-value", "checks.unknown_m")


def test_a_name_too_long_for_the_system_is_no_profile():
    """A fuzzing find: Path.exists() raised OSError (File name too long)."""
    with pytest.raises(ProfileError) as info:
        load_profile("x" * 300)
    assert info.value.code == "profile-not-found"


@pytest.mark.parametrize("section, line, message", [
    ("limits", "feed_max = nan", "limits.feed_max must be a finite number"),
    ("limits", "X = [-10, inf]", r"limits.X must be \[minimum, maximum\]"),
    ("checks", "arc_tolerance = inf", "checks.arc_tolerance must be a finite number"),
    ("work_offsets", "G54 = { X = nan }", "work_offsets.G54.X must be a number"),
    ("restart", "clearance = -inf", "restart.clearance must be a number"),
])
def test_toml_nan_and_inf_are_no_numbers_of_a_profile(section, line, message):
    """TOML reads nan and inf as floats: a limit, offset or tolerance of NaN gave a traceback
    in the core."""
    text = f'name = "p"\n[{section}]\n{line}\n'
    if section == "work_offsets":
        text = f'name = "p"\n[limits]\nX = [-10, 10]\n[work_offsets]\n{line}\n'
    with pytest.raises(ProfileError) as info:
        profile_from_text(text)
    assert (info.value.code, info.value.key) == ("profile-value", message.split(" ")[0])


def test_a_profile_lists_its_control_s_read_only_variables():
    """checks.read_only lists a control's read-only variables beside the family's."""
    from formats.profile import load_profile

    listed = profile_from_text('dialect = "haas"\n[checks.read_only]\n"3020" = "the power-on '
                               'timer"\n"11000-11255" = "a discrete input"\n')
    assert listed.checks.read_only == ((3020, 3020, "the power-on timer"),
                                       (11000, 11255, "a discrete input"))
    assert profile_from_text('dialect = "haas"\n').checks.read_only is None
    assert load_profile("fanuc-mill").checks.read_only is None
    haas = load_profile("haas-lathe").checks.read_only
    assert haas is not None and (3020, 3020, "the power-on timer") in haas


def test_a_profile_without_units_codes_leaves_them_to_the_machine():
    """``units_codes = "none"``: no G code selects the units (an Okuma OSP lathe's unit system is
    a parameter, its G20 a home return): none is designated, the reset state has none, and the
    core is told no code number (-1) so that no G code changes the units."""
    from formats.machine import machine_spec

    profile = profile_from_text('name = "x"\nunits_codes = "none"\nunits = "inch"\n')
    assert profile.units_codes == ("", "") and not profile.units_by_code
    assert profile.default_units == "inch"
    # nothing designated (G20 stays ISO 6983-1's unassigned code); the table's own G70/G71
    # stay listed, and a profile whose control lacks them marks them unassigned in [codes]
    assert not profile.code("G", 20).usable and profile.code("G", 70).usable
    assert "G71" not in profile.reset_state() and "G70" not in profile.reset_state()
    assert profile.reset_state() == tuple(c for c in load_profile("iso-mill").reset_state()
                                          if c != "G71")
    spec = machine_spec(profile)
    assert (spec["inch"], spec["metric"], spec["inch_code"]) == (-1, -1, "")
    with pytest.raises(ProfileError) as bad:
        profile_from_text('name = "x"\nunits_codes = "parameter"\n')
    assert "none" in str(bad.value)


_NUMBERS = st.text(alphabet="0123456789\u0663\u00b2a", max_size=10)
_DIGITS_AND_MORE = st.one_of(
    st.text(alphabet="G0123456789.-abz-\u0663\u00b2 xA", max_size=12),
    st.builds(lambda *parts: "".join(parts), st.sampled_from(["G", "", "M", "g"]), _NUMBERS,
              st.sampled_from([".", "", "-", "..", "--"]), _NUMBERS))


@settings(max_examples=2000)
@given(_DIGITS_AND_MORE)
def test_the_keys_are_read_as_their_regular_expressions_read_them(text):
    """The profile's keys and values read character by character (a check loads no `re`),
    held to the regular expressions they replaced: \\d any Unicode decimal digit, [0-9] an
    ASCII one."""
    import re

    from formats import profile

    g = re.fullmatch(r"G(\d{2,3})", text)
    assert profile._g_code(text) == (int(g[1]) if g else None)
    d = re.fullmatch(r"G(\d+)\.(\d)", text)
    assert profile._decimal_code(text) == ((int(d[1]), d[2]) if d else None)
    assert profile._is_meaning(text) == bool(re.fullmatch(r"[a-z0-9]+(?:-[a-z0-9]+)*", text))
    v = re.fullmatch(r"([0-9]{1,9})(?:-([0-9]{1,9}))?", text)
    assert profile._variables(text) == ((int(v[1]), int(v[2] or v[1])) if v else None)


def test_the_keys_read_by_hand_take_what_the_profiles_write():
    from formats import profile

    assert profile._g_code("G90") == 90 and profile._g_code("G9") is None
    assert profile._decimal_code("G91.1") == (91, "1") and profile._decimal_code("G91") is None
    assert profile._is_meaning("text-engraving") and not profile._is_meaning("Text")
    assert profile._variables("11000-11255") == (11000, 11255)
    assert profile._variables("3020") == (3020, 3020) and profile._variables("1-") is None


@pytest.mark.parametrize(("code", "message"), [
    ('M10 = { function = "f", status = "gone" }', "codes.M10.status = 'gone': choose one of"),
    ('M10 = { function = "f", status = 1 }', "codes.M10.status must be str, not 1"),
    ('M98 = { function = "call", words = { P = "X" } }', 'codes.M98.words.P must be "N"'),
    ('M98 = { function = "call", words = "P" }', "codes.M98.words must be dict"),
    ('M10 = { function = "f", meaning = "Text" }', "codes.M10.meaning 'Text' must be lower"),
    ('M10 = { function = "f", meaning = 3 }', "codes.M10.meaning must be str, not 3"),
])
def test_a_code_s_status_words_and_meaning_are_read_when_given(code, message):
    """A code's keys left out read as their defaults without a look (half a profile's loading
    was its 200 codes); given, each is read and its error told as before."""
    base = 'name = "x"\ndetailed = "N04 G02 X+053 M02*"\n[codes]\n'
    with pytest.raises(ProfileError, match=re.escape(message)):
        profile_from_text(base + code + "\n")
    plain = profile_from_text(base + 'M10 = { function = "f" }\n').extra_codes["M10"]
    assert (plain.status, plain.words, plain.meaning) == ("assigned", (), "")


_CODE_SPECS = [
    '{ function = "f", duration = "motion", meaning = "rapid-positioning" }',
    '{ function = "f", duration = "motion", meaning = "Bad" }',
    '{ function = "f", duration = "motion", meaning = "a--b" }',
    '{ function = "f", duration = "motion", meaning = 3 }',
    '{ function = 1, duration = "motion" }', '{ function = "f", duration = true }',
    '{ function = "f", duration = "motion", meanin = "x" }', '{ function = "f" }', "{ }",
    '{ duration = "x", meaning = "a-1" }',
    '{ function = "f", duration = "motion", status = "unassigned" }',
    '{ function = "f", duration = "TBO", words = { P = "N" } }',
]


def test_a_plain_code_is_read_as_keys_reads_it(monkeypatch):
    """A code of function, duration and meaning as strings is read without Keys
    (formats.profile._PLAIN_CODE_KEYS): every built-in profile's codes, and each code table
    below (good, or wrong in its key, type or meaning), the same with the short way off: the
    same codes, or the same error naming the same key."""
    import formats.profile as profile

    head = ('name = "x"\ndetailed = "%:/ N04 G02 X+043 Y+043 Z+043 F042 S04 T02 M02*"\n'
            "[codes]\n")

    def read() -> list[object]:
        found: list[object] = [load_profile(name).extra_codes for name in builtin_names()]
        for letter in ("G01", "M07"):
            for spec in _CODE_SPECS:
                try:
                    found.append(profile_from_text(f"{head}{letter} = {spec}\n",
                                                   source="t").extra_codes)
                except ProfileError as exc:
                    found.append((str(exc), exc.key))
        return found

    short = read()
    assert sum(isinstance(x, tuple) for x in short) == 12  # 6 refusals, for G01 and M07
    monkeypatch.setattr(profile, "_PLAIN_CODE_KEYS", frozenset())
    assert read() == short


def test_fanuc_mill_powers_on_in_g00(tmp_path):
    """FANUC parameter No. 3402 at its usual values gives G00, G17 and G90 at power-on and
    reset (audit 50, B7): a first axis move without a motion code is a rapid, not a feed
    move without a feed rate; a G01 without F is still TG401 at its place. The units code
    follows the profile's units."""
    from click.testing import CliRunner

    from tapegate.cli import main

    reset = load_profile("fanuc-mill").reset_state()
    assert reset[:3] == ("G00", "G15", "G17") and {"G90", "G94", "G40", "G49", "G80"} <= set(reset)
    inch = profile_from_text('name = "x"\nbase = "fanuc-mill"\nunits = "inch"\n')
    assert "G20" in inch.reset_state() and "G21" not in inch.reset_state()
    program = tmp_path / "z.nc"
    program.write_text("%\nO1000\nZ10.\nG43 H1 Z20.\nG01 X5.\nM30\n%\n")
    out = CliRunner().invoke(main, ["check", str(program), "-p", "fanuc-mill"]).output
    assert [line for line in out.splitlines() if "TG401" in line] == [
        f"{program}:5:5: error TG401 feed motion with no feed rate in force [7]"]
