import pytest

from formats.codes import TABLES
from formats.profile import load_profile, profile_from_text


def test_iso6983_annex_e():
    t = TABLES["iso6983-1"]
    assert t.lookup("G", 1).duration == "a" and t.lookup("G", 4).duration == "TBO"
    assert t.lookup("G", 71).function == "dimension input metric"
    assert t.lookup("G", 26).status == "permanent" and t.lookup("G", 37).status == "permanent"
    assert t.lookup("G", 20).status == "unassigned"
    assert t.lookup("G", 90).status == "conditional"
    assert t.lookup("M", 30).function.startswith("end of data")
    assert t.lookup("M", 12).status == "unassigned"


def test_iso1056_differs_where_the_standards_differ():
    t = TABLES["iso1056"]
    assert t.lookup("G", 70).status == "unassigned"  # inch/metric only in ISO 6983-1
    assert t.lookup("G", 8).function == "acceleration"
    assert t.lookup("G", 9).function == "deceleration"
    assert t.lookup("M", 13).function == "spindle clockwise and coolant on"
    assert t.lookup("M", 25).status == "permanent"
    # The copy of ISO 1056 ends at M47: nothing is invented beyond it.
    assert "not confirmed" in t.lookup("M", 50).function


def test_profiles_add_codes_on_top_of_the_table():
    """E-03: a profile built on a standard's table designates codes over it (its [codes], its
    units codes); what it does not designate keeps the table's entry."""
    iso = load_profile("iso-mill")
    assert iso.code("G", 28).status == "permanent"
    custom = profile_from_text('dialect = "fanuc"\nunits_codes = "G20/G21"\n[codes]\n'
                               'G28 = { function = "home", duration = "TBO" }\n')
    assert custom.code("G", 28).function == "home"
    assert custom.code("G", 20).usable and custom.code("G", 20).duration == "m"
    assert custom.code("G", 6).function == iso.code("G", 6).function


def test_a_family_profile_is_its_own_list_not_the_table():
    """A control family's profile is the control's list (`code_table = "own"`): a code it does
    not hold is no code of it, whatever ISO 6983-1 says of the number: FANUC's G06 is no
    parabola, its G70/G71 no units codes, its M07 the machine builder's."""
    fanuc = load_profile("fanuc-mill")
    assert fanuc.table.name == "own"
    assert fanuc.code("G", 20).duration == "units"
    assert fanuc.code("G", 28).function == "automatic return to reference position"
    assert fanuc.code("G", 1).function == "linear interpolation"
    iso = load_profile("iso-mill")
    for letter, number in (("G", 6), ("G", 70), ("G", 71), ("M", 7), ("M", 10)):
        assert fanuc.code(letter, number) is None and iso.code(letter, number).usable


def test_a_listing_makes_the_codes_of_its_ranges_when_looked_up_and_lists_every_code():
    """The unassigned and permanently unassigned numbers are ranges, made into codes when asked
    for: the same code each time, and the whole table iterates as the standard has it."""
    g = TABLES["iso6983-1"].g
    assert "_made_codes" not in g.__dict__ or 500 not in g._made()
    code = g.get(500)
    assert code is not None and code is g.get(500) is g[500]
    assert (code.letter, code.number, code.status) == ("G", 500, "unassigned")
    assert g.get(1000) is None and g.get(-1) is None and g.get(1000, code) is code
    assert len(g) == 1000 and list(g) == list(g.keys())
    assert list(g)[:3] == [0, 1, 2]  # the listed codes first, in the standard's order
    assert g[26].status == "permanent"  # the first range holding a number decides
    m = TABLES["iso1056"].m
    assert m[40].function.startswith("gear change") and m[25].status == "permanent"
    assert m[47].status == "unassigned" and "not confirmed" in m[48].function
    try:
        m[100]
    except KeyError as exc:
        assert exc.args == (100,)
    else:
        raise AssertionError("M100 is not in ISO 1056")


def test_the_states_the_core_is_told_are_the_codes_looked_up_one_by_one():
    for table in TABLES.values():
        for listing, count in ((table.g, 1000), (table.m, 100), (table.m, 1000)):
            expected = [None if listing.get(n) is None
                        else (listing[n].status, listing[n].duration) for n in range(count)]
            assert listing.states(count) == expected


def test_a_machine_is_told_each_code_as_the_profile_finds_it():
    """machine_spec reads the table's states and lays the profile's own codes over them: the
    same as asking the profile for each number (the designated units codes included)."""
    from formats.machine import machine_spec
    from formats.profile import NEUTRAL, builtin_names, with_units_codes

    profiles = [load_profile(name) for name in builtin_names()]
    profiles += [NEUTRAL, with_units_codes(NEUTRAL, "G20", "G21")]
    for profile in profiles:
        spec = machine_spec(profile)
        for letter, states in (("G", spec["g_codes"]), ("M", spec["m_codes"])):
            codes = [profile.code(letter, n) for n in range(len(states))]
            assert states == [None if c is None else (c.status, c.duration) for c in codes], (
                profile.name, letter)


def test_the_standards_tables_are_made_when_first_asked_for_and_once():
    """A profile of a control family lists its own codes: a check of it does not make the
    standards' tables (0.2 ms at every start-up); asked for, each is made once, shared, and the
    names are the two standards' whether made or not."""
    import subprocess
    import sys

    probe = ("import formats.codes as c, formats.profile as p\n"
             "p.load_profile('fanuc-mill')\n"
             "print(sorted(c.TABLES._made), sorted(c.TABLES))\n"
             "p.load_profile('iso-mill')\n"
             "print(sorted(c.TABLES._made), c.TABLES['iso6983-1'] is c.TABLES['iso6983-1'])\n")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True,
                          check=True, timeout=60)
    assert done.stdout.splitlines() == ["[] ['iso1056', 'iso6983-1']", "['iso6983-1'] True"]
    assert len(TABLES) == 2 and TABLES["iso1056"].name == "iso1056"
    with pytest.raises(KeyError):
        TABLES["iso9999"]  # noqa: B018
