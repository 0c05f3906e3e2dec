import pytest

from formats.errors import ProfileError
from formats.profile import builtin_names, load_profile, profile_from_text


def test_five_builtin_profiles_that_differ_where_machines_differ():
    names = builtin_names()
    assert len(names) >= 5
    profiles = {n: load_profile(n) for n in names}
    assert {p.table.name for p in profiles.values()} == {"iso6983-1", "iso1056"}
    assert {p.serial.code for p in profiles.values()} == {"iso", "eia"}
    assert {p.explicit for p in profiles.values()} == {True, False}
    assert {p.units_codes for p in profiles.values()} == {("G70", "G71"), ("G20", "G21")}
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


def test_a_profile_states_its_own_reset_state():
    profile = profile_from_text('name = "x"\nreset = ["G00", "G17", "G40", "G71", "G80", "G90"]\n')
    assert profile.reset_state() == ("G00", "G17", "G40", "G71", "G80", "G90")
    with pytest.raises(ProfileError, match="reset: G04 is not a modal code"):
        profile_from_text('name = "x"\nreset = ["G04"]\n')


def test_user_file(tmp_path):
    path = tmp_path / "mine.toml"
    path.write_text('name = "mine"\ngeneral = "LM 221"\n[serial]\nbaud = 19200\n')
    profile = load_profile(str(path))
    assert profile.name == "mine" and profile.serial.baud == 19200


def test_dc3_reaction_is_left_to_the_command_unless_the_profile_says():
    assert load_profile("fanuc-mill").serial.dc3_reaction is None
    profile = profile_from_text('name = "x"\n[serial]\nbaud = 115200\ndc3_reaction = 0.002\n')
    assert profile.serial.dc3_reaction == 0.002


@pytest.mark.parametrize("text, message", [
    ("colour = 1", "unknown key 'colour'"),
    ('general = "PM 232"', "general: "),
    ('detailed = "X+553*"', "detailed: "),
    ('code_table = "iso9999"', "code_table = 'iso9999': choose one of"),
    ("[serial]\nbaud = 1234", "serial.baud = 1234"),
    ("[serial]\ndata_bits = 6", "serial.data_bits"),
    ('[serial]\ncode = "eia"', "EIA code needs"),
    ("[limits]\nX = [5, 1]", "limits.X: minimum 5 is above maximum 1"),
    ('[limits]\nfeed_max = "fast"', "limits.feed_max must be a number"),
    ("[checks]\nm_classes = [9]", "checks.m_classes"),
    ('[codes]\nQ12 = { function = "x" }', "not a G or M code"),
    ("this is not toml", "not valid TOML"),
    ('extra_characters = "A"', "cannot be an extra character"),
    ("[serial]\ntv_check = 1", "serial.tv_check must be bool"),
    ("[serial]\ndc3_reaction = -0.001", "serial.dc3_reaction must be at least 0"),
    ('[serial]\ndc3_reaction = "soon"', "serial.dc3_reaction must be a number"),
])
def test_bad_profiles_name_the_key(text, message):
    with pytest.raises(ProfileError, match=message) as info:
        profile_from_text(text, source="bad.toml")
    assert str(info.value).startswith("bad.toml: ")


def test_unknown_profile_name_lists_builtins():
    with pytest.raises(ProfileError, match="built-in profiles: cm332-quadrant, fanuc-mill"):
        load_profile("no-such-machine")
