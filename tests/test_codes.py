from formats.codes import TABLES
from formats.profile import load_profile


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
    fanuc = load_profile("fanuc-mill")
    assert fanuc.code("G", 20).duration == "units"
    assert fanuc.code("G", 28).function == "automatic return to reference position"
    assert fanuc.code("G", 1).function == "linear interpolation"
    # a code of the table the profile does not list keeps the table's entry
    assert fanuc.code("G", 6).function == load_profile("iso-mill").code("G", 6).function
    assert load_profile("iso-mill").code("G", 28).status == "permanent"
