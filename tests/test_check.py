"""`tapegate check` and `plot`: output formats, SARIF against the official schema, exit codes,
tape images, the modal state, robustness on random and mutated input."""

from __future__ import annotations

import json
import random
from decimal import Decimal
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from formats.errors import ProfileError
from formats.parser import parse_stream, parse_text
from formats.profile import NEUTRAL, load_profile, profile_from_text
from formats.tape import encode, iso_byte
from postproc.check import Checker, check_text, iter_check_file
from postproc.rules import markdown
from postproc.state import ModalMachine, state_at
from tapegate.cli import main
from tests.conftest import corpus_files

ROOT = Path(__file__).resolve().parents[1]
# The official OASIS SARIF 2.1.0 JSON schema, kept in the repository (tests/data/README.md says
# where it came from), so that the validation below always runs.
SCHEMA = Path(__file__).resolve().parent / "data" / "sarif-schema-2.1.0.json"
BAD = "%\nN1 G71\nN2 G01 X10\nN3 G02 X20 Y0 K5 F100\nN4 M30\n%\n"


def run(*args):
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


def test_text_output_is_compiler_style_and_exit_codes(tmp_path):
    bad = tmp_path / "bad.nc"
    bad.write_text(BAD)
    r = run("check", str(bad), "-p", "iso-mill")
    assert r.exit_code == 1
    assert f"{bad}:3:8: error TG401 feed motion with no feed rate in force [7]" in r.output
    assert "1 file checked: " in r.output
    good = tmp_path / "good.nc"
    good.write_text("%\nN1 G71\nN2 G01 X10 F100\nN3 M30\n%\n")
    assert run("check", str(good), "-p", "iso-mill").exit_code == 0
    warn = tmp_path / "warn.nc"
    warn.write_text("N1 G71\nN2 G01 X10 F100\nN3 M30\n%\n")  # TG110 (warning): no %
    assert run("check", str(warn), "-p", "iso-mill").exit_code == 0
    assert run("check", str(warn), "-p", "iso-mill", "--fail-on", "warning").exit_code == 1
    assert run("check", str(tmp_path / "missing.nc"), "-p", "iso-mill").exit_code == 2
    assert run("check", str(good), "-p", "no-such").exit_code == 2
    assert run("check", str(good), "-p", "iso-mill", "--select", "TG999").exit_code == 2


def test_select_and_ignore(tmp_path):
    bad = tmp_path / "bad.nc"
    bad.write_text(BAD)
    only = run("check", str(bad), "-p", "iso-mill", "--select", "TG404").output
    assert "TG404" in only and "TG401" not in only
    rest = run("check", str(bad), "-p", "iso-mill", "--ignore", "TG4")
    assert "TG40" not in rest.output and rest.exit_code == 0


def test_json_output_with_stats(tmp_path, sample_program):
    path = tmp_path / "p.nc"
    path.write_text(sample_program)
    data = json.loads(run("check", str(path), "-p", "iso-mill", "--format", "json",
                          "--stats").output)
    stats = data["stats"][str(path)]
    assert stats["bounding_box"]["X"] == [10, 100] and stats["tools"] == [1]
    assert stats["feed_length"] > stats["rapid_length"] > 0 and stats["cycle_time_seconds"] > 0
    assert {f["rule"] for f in data["findings"]} == {"TG133"}


def test_sarif_validates_against_the_official_schema(tmp_path):
    import jsonschema

    bad = tmp_path / "bad.nc"
    bad.write_text(BAD)
    r = run("check", str(bad), "-p", "iso-mill", "--format", "sarif")
    log = json.loads(r.output)
    schema = json.loads(SCHEMA.read_text(encoding="utf-8"))
    assert schema["title"] == "Static Analysis Results Format (SARIF) Version 2.1.0 JSON Schema"
    jsonschema.validate(log, schema)
    results = log["runs"][0]["results"]
    rules = log["runs"][0]["tool"]["driver"]["rules"]
    assert {res["ruleId"] for res in results} == {r["id"] for r in rules}
    first = next(res for res in results if res["ruleId"] == "TG401")
    assert first["locations"][0]["physicalLocation"]["region"] == {"startLine": 3,
                                                                   "startColumn": 8}


def test_tape_images_checked_with_parity(tmp_path):
    text = "%\nN1 G71\nN2 G01 X10 F100\nN3 M30\n%\n"
    data = bytearray(encode(text, "iso", leader=5))
    data[data.index(iso_byte("X"))] ^= 0x80  # flip the parity bit of the X on line 3
    path = tmp_path / "p.tap"
    path.write_bytes(bytes(data))
    r = run("check", str(path), "-p", "iso-mill")
    assert r.exit_code == 1 and "TG701" in r.output and ":3:" in r.output
    eia = tmp_path / "p.eia"
    eia.write_bytes(encode(text, "eia", leader=5))
    assert run("check", str(eia), "-p", "iso-mill").exit_code == 0


def test_plot_svg_and_png(tmp_path, sample_program):
    path = tmp_path / "p.nc"
    path.write_text(sample_program)
    for name in ("p.svg", "p.png"):
        r = run("plot", str(path), "-p", "iso-mill", "-o", str(tmp_path / name), "--view", "xy")
        assert r.exit_code == 0, r.output
    svg = (tmp_path / "p.svg").read_text()
    assert "<svg" in svg and "rapid (G00)" in svg and "feed (G01, arcs G02/G03)" in svg
    assert (tmp_path / "p.png").read_bytes()[:4] == b"\x89PNG"
    assert run("plot", str(path), "-p", "iso-mill", "-o", str(tmp_path / "p.gif")).exit_code == 2


def test_rules_catalogue_is_generated_from_the_registry():
    assert (ROOT / "docs" / "rules.md").read_text() == markdown()


# -- modal state --------------------------------------------------------------------------------


def test_modal_state_and_reset_after_m30():
    profile = load_profile("iso-lathe")
    machine = ModalMachine(profile)
    assert machine.state.spindle_mode == 97 and machine.state.motion == 1  # clause 14.4
    program = ("%\nN1 G70 G91 G95\nN2 G92 S2000\nN3 G96 S150 M03 M08\nN4 T0303\n"
               "N5 X1 Z-2\nN6 M30\n")
    blocks = parse_text(program)
    s = None
    for b in blocks[:6]:
        _, s = machine.step(b)
    assert s is not None
    assert (s.units, s.incremental, s.feed_mode, s.spindle_mode) == ("inch", True, 95, 96)
    assert (s.speed_limit, s.speed, s.spindle, s.coolant, s.tool) == (2000, 150, "cw", "flood",
                                                                       303)
    assert s.position == {"X": 1, "Z": -2}
    _, s = machine.step(blocks[6])
    assert s.ended and s.units == "metric" and not s.incremental and s.spindle == "stop"


def test_units_after_m30_are_kept_where_the_control_keeps_them():
    """A Haas keeps its units through M30 (Setting 9), so a local subprogram after M30 runs in
    its caller's: X600. is 600 mm here, inside the VF-2's 30 inches. Read in the reset state's
    G20 it was 600 inches, and TG601 said no work offset fits. Clause 14 (an ISO profile) and a
    Sinumerik return to the reset state's units."""
    haas = load_profile("haas-mill")
    program = ("%\nO1000\nG21 G90 G17\nT1 M06\nS1000 M03\nG0 X10. Y10.\nM97 P100\nM30\n"
               "N100 G01 X600. F500.\nM99\n%\n")
    assert not [f.rule for f in check_text(program, haas) if f.severity == "error"]
    blocks = parse_text(program, haas.dialect)
    assert state_at(blocks, haas, 10).units == "metric"
    for name, reset in (("haas-mill", "inch"), ("fanuc-mill", "metric"), ("linuxcnc", "metric")):
        profile = load_profile(name)
        kept = "metric" if reset == "inch" else "inch"
        code = "G21" if kept == "metric" else "G20"
        text = f"%\nO1\n{code}\nG0 X1.\nM30\nO2\nG0 X1.\n%\n"
        assert state_at(parse_text(text, profile.dialect), profile, 8).units == kept, name
    for name, code in (("iso-mill", "G70"), ("sinumerik-840d", "G70")):
        profile = load_profile(name)
        text = f"%\nN1 {code}\nN2 G0 X1.\nN3 M30\nN4 G0 X1.\n%\n"
        assert state_at(parse_text(text, profile.dialect), profile, 6).units == "metric", name


def test_a_subprogram_after_m30_is_read_in_the_units_of_its_calls(tmp_path: Path) -> None:
    """Review 38, finding 10: O1000 after M30, called by M98 under G21, runs in millimetres
    (a Haas's M98 keeps the caller's modes): X900. and F3000. fit the VF-2 in mm, where the
    reset state's G20 made them 900 inches and 3000 in/min (TG601, TG602). Called under G20
    they are inches, as before; its own G21 counts; an over-travel in the caller's mm is still
    found; calls in different units leave the units unknown until the subprogram writes them;
    a program no call names is read from the reset state as the file's first is, and says
    which units it assumed."""
    def limits(program: str) -> list[tuple[int, str, str]]:
        path = tmp_path / "p.nc"
        path.write_text(program)
        out = run("check", str(path), "-p", "haas-mill", "--select", "TG601,TG602",
                  "--format", "jsonl").stdout
        return [(f["line"], f["rule"], f["message"]) for f in map(json.loads, out.splitlines())]

    def sub(caller: str, body: str) -> str:
        return f"%\nO1\n{caller}\nG0 G90 G54 X0 Y0\nM98 P1000\nM30\nO1000\n{body}\nM99\n%\n"

    assert limits(sub("G21", "G1 X900. F3000.")) == []
    assert [f[:2] for f in limits(sub("G20", "G1 X900. F3000."))] == [(8, "TG601"), (8, "TG602")]
    assert limits(sub("G20", "G21\nG1 X900. F3000.")) == []
    over = limits(sub("G21", "G1 X2000. F30000."))
    assert [f[:2] for f in over] == [(8, "TG601"), (8, "TG602")]
    assert "30000 mm/min" in over[1][2]
    # called under G21 and under G20: not judged until its own G21
    both = ("%\nO1\nG21\nG0 G90 G54 X0 Y0\nM98 P1000\nG20\nM98 P1000\nM30\nO1000\n"
            "G1 X900. F3000.\nG21\nG1 X2000. F30000.\nM99\n%\n")
    assert [f[:2] for f in limits(both)] == [(12, "TG601"), (12, "TG602")]
    # no call names it: a program of its own, from the reset state, its assumed units said;
    # its span its own, not added to the main's (review 55b, F4): X900. alone fits, X900.
    # and X-400. (1300 in) do not, from its own G90 on (review 56b, F10: its caller's
    # G90/G91 is not known, and under G91 they are increments)
    alone = "%\nO1\nG21\nG0 G90 G54 X0 Y0\nM30\nO1000\nG90 G1 X900. F3000.\nM99\n%\n"
    assert [f[:2] for f in limits(alone)] == [(7, "TG602")]
    found = limits(alone.replace("F3000.\n", "F3000.\nX-400.\n"))
    assert [f[:2] for f in found] == [(7, "TG602"), (8, "TG601")]
    assert all("no units code by here" in f[2] for f in found)
    unsure = alone.replace("G90 G1", "G1").replace("F3000.\n", "F3000.\nX-400.\n")
    assert [f[:2] for f in limits(unsure)] == [(7, "TG602")]


def test_a_four_digit_fanuc_reads_m98_p_as_its_repeat_count_and_number(tmp_path: Path) -> None:
    """Review 39, finding 5: a FANUC without the 8-digit program number option (a profile
    whose O has four digits) reads `M98 P32000` as O2000 called three times (0i-F Operator's
    Manual, "Subprogram call (M98)": the repeat count above the number's four digits), so
    O2000 runs in the caller's inches: X -35 to 35 in is 1778 mm, more than the 1524 of X.
    With the 8-digit option (fanuc-mill's O08) P32000 is O32000, which the file does not
    hold: O2000 is a program of its own."""
    import tomllib

    import formats

    with open(Path(formats.__file__).parent / "profiles" / "fanuc-mill.toml", "rb") as f:
        fanuc = tomllib.load(f)
    four = tmp_path / "fm4.toml"
    four.write_text('name = "fm4"\nbase = "fanuc-mill"\n' + "".join(
        f'{key} = "{fanuc[key].replace("O08", "O04")}"\n'
        for key in ("detailed", "detailed_inch")))
    path = tmp_path / "p.nc"
    path.write_text("%\nO1000\nG20 G90 G54\nG0 X-35. Y0\nM98 P32000\nM30\nO2000\nG0 X35.\n"
                    "M99\n%\n")

    def spans(profile: str) -> list[tuple[int, str]]:
        out = run("check", str(path), "-p", profile, "--select", "TG601",
                  "--format", "jsonl").stdout
        return [(f["line"], f["rule"]) for f in map(json.loads, out.splitlines())]

    assert spans(str(four)) == [(8, "TG601")]
    assert spans("fanuc-mill") == []


def test_a_g92_and_a_call_under_a_shift_keep_the_span_of_where_the_tool_goes(
        tmp_path: Path) -> None:
    """Review 39: `G92 X0 Y0` where the position before it is not known puts the tool at X0
    of the new coordinates, which starts the new span (finding 1: `G0 X650` then passed a
    600 mm travel on a LinuxCNC profile of the user's; `G0 X1600.` the fanuc-mill's 1524);
    a subprogram after M30 runs under the G52 of its call, so its body is not read in the
    work system the Haas's M30 gives back (finding 2): read under the calls' shift where they
    agree, its span started again with a note where they do not."""
    def found(name: str, program: str, profile: str) -> list[tuple[int, str, str]]:
        path = tmp_path / name
        path.write_text(program)
        out = run("check", str(path), "-p", profile, "--select", "TG601,TG140",
                  "--format", "jsonl").stdout
        return [(f["line"], f["rule"], f["message"]) for f in map(json.loads, out.splitlines())]

    lc = tmp_path / "lc.toml"
    lc.write_text('name = "lc"\nbase = "linuxcnc"\n[limits]\nX = [-300, 300]\n'
                  'Y = [-300, 300]\nZ = [-300, 300]\n')
    g6 = found("g6.ngc", "G21 G90\nG92 X0 Y0\nG0 X650\nM2\n", str(lc))
    assert [f[:2] for f in g6] == [(3, "TG601")]
    assert "from 0 to 650" in g6[0][2]
    g91 = found("g7.ngc", "G21 G91\nG0 X-200 Y0\nG92 X-500\nG0 X650\nM2\n", str(lc))
    assert [f[:2] for f in g91] == [(4, "TG601")]
    assert "from -500 to 150" in g91[0][2]
    fanuc = found("f.nc", "%\nO1\nG21 G90\nG92 X0 Y0 Z0\nG0 X1600.\nM30\n%\n", "fanuc-mill")
    assert [f[:2] for f in fanuc] == [(5, "TG601")]
    # a FANUC lathe's G50 X Z (Z travel -800 to 300: 1100)
    lathe = found("l.nc", "%\nO1\nG21 G18\nG50 X0 Z0\nG0 Z1200.\nM30\n%\n", "fanuc-lathe")
    assert [f[:2] for f in lathe] == [(5, "TG601")]
    assert "from 0 to 1200" in lathe[0][2]
    # a G92 at a known position: where the tool stood, nothing new
    known = "%\nO1\nG21 G90\nG0 X700.\nG92 X0\nG0 X-100.\nM30\n%\n"
    assert found("k.nc", known, "fanuc-mill") == []
    h5 = ("%\nO1000\nG20 G90 G54\nG0 X-25. Y0\nG52 X30.\nG0 X0 Y0\nM97 P100\nM30\n"
          "N100 G0 X35.\nM99\n%\n")
    h5_found = [f for f in found("h5.nc", h5, "haas-mill") if f[1] == "TG601"]
    assert [f[:2] for f in h5_found] == [(9, "TG601")]
    assert "X spans 90 (from -25 to 65)" in h5_found[0][2]
    # the FANUC's: G52 X700. cancelled before M30, the sub still runs under it (X1600.)
    f2 = ("%\nO1000\nG21 G90 G54\nG0 X-600. Y0\nG52 X700.\nG0 X0 Y0\nM98 P2000\nG52 X0\n"
          "M30\nO2000\nG0 X900.\nM99\n%\n")
    f2_found = [f for f in found("f2.nc", f2, "fanuc-mill") if f[1] == "TG601"]
    assert [f[:2] for f in f2_found] == [(11, "TG601")]
    assert "X spans 2200 (from -600 to 1600)" in f2_found[0][2]
    # calls under two shifts: the span starts again at M30, noted with the first call
    two = h5.replace("M97 P100\nM30", "M97 P100\nG52 X0\nM97 P100\nM30")
    notes = [f for f in found("two.nc", two, "haas-mill") if f[2].startswith("M30")]
    assert [f[:2] for f in notes] == [(10, "TG140")]
    assert "(M97 P100 of line 7)" in notes[0][2]
    assert not [f for f in found("two.nc", two, "haas-mill") if f[1] == "TG601"]


def test_a_subprogram_before_its_call_runs_in_the_call_s_units_and_shift(
        tmp_path: Path) -> None:
    """Review 39, finding 4: a memory backup lists O0002 before the O1000 that calls it; the
    control runs it in the caller's units and under its shift, wherever it stands in the
    file. Its positions were read in the reset units, and a G20 caller's TG601 was missed."""
    def found(program: str, profile: str) -> list[tuple[int, str, str]]:
        path = tmp_path / "p.nc"
        path.write_text(program)
        out = run("check", str(path), "-p", profile, "--select", "TG6,TG140",
                  "--format", "jsonl").stdout
        return [(f["line"], f["rule"], f["message"]) for f in map(json.loads, out.splitlines())
                if not f["message"].startswith("M98 (subprogram call)")
                and "whose G90/G91 the checker does not know" not in f["message"]]

    sf = "%\nO0002\nG0 X35.\nM99\nO1000\nG20 G90 G54\nG0 X-35. Y0\nM98 P2\nM30\n%\n"
    got = found(sf, "fanuc-mill")
    # said at the call, naming the body's line (review 42, findings 0 and 2)
    assert [f[:2] for f in got] == [(8, "TG601")]
    assert "X spans 1778 (from -889 to 889)" in got[0][2]
    assert "O0002 runs in inches as called by M98 P2 of line 8, its position of line 3" in got[0][2]
    # the same with the subprogram after M30: as before
    after = "%\nO1000\nG20 G90 G54\nG0 X-35. Y0\nM98 P2\nM30\nO0002\nG0 X35.\nM99\n%\n"
    assert [f[:2] for f in found(after, "fanuc-mill")] == [(8, "TG601")]
    # under the call's G52 X30.: X35. is 65 in from the work zero
    shifted = sf.replace("M98 P2\n", "G52 X30.\nM98 P2\nG52 X0\n").replace("X-35.", "X-25.")
    got = found(shifted, "fanuc-mill")
    assert [f[:2] for f in got] == [(9, "TG601")]
    assert "X spans 2286 (from -635 to 1651)" in got[0][2]
    # a G21 caller on the Haas (reset in inches): X35. and X-30. are mm, inside the travel
    # (read in the reset inches, 65 in: a false TG601)
    mm = "%\nO0002\nG0 X35.\nG0 X-30.\nM99\nO1000\nG21 G90 G54\nG0 X0 Y0\nM98 P2\nM30\n%\n"
    assert found(mm, "haas-mill") == []
    # no call names it: a program of its own, read in the reset inches as before, from its
    # own G90 on (review 56b, F10)
    alone = mm.replace("M98 P2\n", "")
    assert found(alone, "haas-mill") == []
    absolute = alone.replace("O0002\nG0", "O0002\nG90 G0")
    assert [f[:2] for f in found(absolute, "haas-mill")] == [(4, "TG601")]
    # calls in both units: each judged where it is made (review 42, finding 9), the G20's
    both = sf.replace("M98 P2\nM30", "M98 P2\nG21\nM98 P2\nM30")
    assert [f[:2] for f in found(both, "fanuc-mill")] == [(8, "TG601")]
    # its own G21: read as before (900 mm each way, past the 1524 mm)
    own = ("%\nO0002\nG21\nG0 X900.\nG0 X-900.\nM99\nO1000\nG20 G90 G54\nG0 X0 Y0\n"
           "M98 P2\nM30\n%\n")
    assert [f[:2] for f in found(own, "fanuc-mill")] == [(5, "TG601")]


def test_review_41_spans_of_a_g92_beside_a_units_code_and_of_a_lathe_s_u_and_w(
        tmp_path: Path) -> None:
    """Review 41. Finding 1: `G21 G90 G92 X0 Y0 Z0`, the commonest header, puts the tool at X0
    of the new coordinates as a G92 on its own line does, its words in the units the block
    sets (LinuxCNC sets the length units before G92's offsets: `rs274 -g` of `G20 G90`,
    `G21 G92 X0 Y0`, `G0 X650` traverses 650 mm). Finding 2: a lathe's U and W (FANUC system
    A, Haas, Okuma) move X and Z, and the positions they reach go to X's and Z's spans.
    Finding 6: the Okuma lathe's list lacks G92 (TG307): its block's axes are not known
    after it, as any lacked code's, and no position of its words starts a span."""
    def found(name: str, program: str, profile: str) -> list[tuple[int, str, str]]:
        path = tmp_path / name
        path.write_text(program)
        out = run("check", str(path), "-p", profile, "--select", "TG601,TG140",
                  "--format", "jsonl").stdout
        return [(f["line"], f["rule"], f["message"]) for f in map(json.loads, out.splitlines())]

    def fanuc(*body: str) -> str:
        return "%\nO1\n" + "\n".join(body) + "\nM30\n%\n"

    # finding 1: the header form, a code that changes nothing, and the G92 on its own line
    for header in (["G21 G90 G92 X0 Y0 Z0"], ["G21 G90", "G21 G92 X0 Y0 Z0"],
                   ["G21 G90", "G92 X0 Y0 Z0"]):
        spans = found("b.nc", fanuc(*header, "G0 X1600."), "fanuc-mill")
        assert [f[:2] for f in spans] == [(3 + len(header), "TG601")], header
        assert "X spans 1600 (from 0 to 1600)" in spans[0][2]
    assert found("b.nc", fanuc("G21 G90 G92 X0 Y0 Z0", "G0 X1500."), "fanuc-mill") == []
    lc = tmp_path / "lc.toml"
    lc.write_text('name = "lc"\nbase = "linuxcnc"\n[limits]\nX = [-300, 300]\n'
                  'Y = [-300, 300]\nZ = [-300, 300]\n')
    mm = found("a2.ngc", "G20 G90\nG21 G92 X0 Y0\nG0 X650\nM2\n", str(lc))
    assert [f[:2] for f in mm] == [(3, "TG601")] and "from 0 to 650" in mm[0][2]
    inch = found("a1.ngc", "G21 G90\nG20 G92 X0 Y0\nG0 X25\nM2\n", str(lc))
    assert [f[:2] for f in inch] == [(3, "TG601")] and "from 0 to 635" in inch[0][2]
    assert found("a3.ngc", "G21 G90\nG20 G92 X0 Y0\nG0 X23\nM2\n", str(lc)) == []

    # finding 2: U and W beside X and Z moves, out of the travel and in it
    # (fanuc-lathe X -10 to 500, Z -800 to 300; haas-lathe Z -22 to 12 in; okuma-lathe Z
    # -100 to 1100)
    for profile, body, axis in [
            ("fanuc-lathe", ["G21", "G0 X100. Z0", "G0 U520."], "X spans 520 (from 100 to 620)"),
            ("fanuc-lathe", ["G21", "G0 X100. Z0", "G1 W-800. F0.2", "G0 X120. W-400."],
             "Z spans 1200 (from -1200 to 0)"),
            ("haas-lathe", ["G20", "G0 X1. Z0", "G0 W40."], "Z spans 40 (from 0 to 40)"),
            ("okuma-lathe", ["G0 X100. Z0", "G0 W1300."], "Z spans 1300 (from 0 to 1300)")]:
        spans = found("l.nc", fanuc(*body), profile)
        assert [f[:2] for f in spans] == [(2 + len(body), "TG601")], (profile, body)
        assert axis in spans[0][2], spans
    inside = {"fanuc-lathe": ["G21", "G0 X100. Z0", "G1 U300. W-500. F0.2", "G0 X20.",
                              "U-20. W700."],
              "haas-lathe": ["G20", "G0 X1. Z0", "G1 U5. W-20. F0.01", "G0 W30."],
              "okuma-lathe": ["G0 X100. Z0", "G1 U900. W1000. F0.2", "G0 W-1100."]}
    for profile, body in inside.items():
        assert found("i.nc", fanuc(*body), profile) == [], profile
    # a FANUC lathe's dwell U is its time, no move
    dwell = fanuc("G21", "G0 X100. Z0", "G04 U1500.", "G0 X100.")
    assert found("d.nc", dwell, "fanuc-lathe") == []

    # finding 6: okuma-lathe's G92 (not in its list) sets no position; G50 is its zero offset
    ol1 = fanuc("G92 X0 Z0", "G0 X1200. Z0")
    assert found("ol1.nc", ol1, "okuma-lathe") == []
    mill = found("om.nc", fanuc("G21 G90", "G92 X0 Y0 Z0", "G0 X1300."), "okuma-mill")
    assert [f[:2] for f in mill] == [(5, "TG601")]


def test_issue_32_a_lathe_s_thread_and_single_cycles_reach_the_spans(tmp_path: Path) -> None:
    """Issue 32 (thr42): a FANUC or Haas lathe's threading G32 (G34) cuts to its end point
    and stays there, U and W its increments as in G01; the single cycles G90, G92, G94 go from
    the start point to the end point X(U) Z(W) and back (FANUC 0i-TF operator's manual,
    "Thread cutting G32", "Outer diameter/internal diameter cutting cycle G90", "Thread
    cutting cycle G92", "End face turning cycle G94"): the end point goes to the spans, the
    tool stands at the start point after the cycle. fanuc-lathe X -10 to 500, Z -800 to 300;
    haas-lathe (inches) X -1 to 16, Z -22 to 12."""
    def spans(profile: str, *body: str) -> list[tuple[int, int]]:
        path = tmp_path / "t.nc"
        path.write_text("%\nO1\n" + "\n".join(body) + "\nM30\n%\n")
        out = run("check", str(path), "-p", profile, "--select", "TG601",
                  "--format", "jsonl").stdout
        return [(f["line"], f["column"]) for f in map(json.loads, out.splitlines())]

    head = ("G21 G18 G99", "G0 X60. Z2.")
    # the thread: by W, and by Z (which already fired)
    assert spans("fanuc-lathe", *head, "G32 W-1200. F1.5") == [(5, 5)]
    assert spans("fanuc-lathe", *head, "G32 W-10. F1.5") == []
    assert spans("fanuc-lathe", *head, "G32 Z-1200. F1.5") == [(5, 5)]
    assert spans("fanuc-lathe", *head, "G32 Z-10. F1.5") == []
    assert spans("haas-lathe", "G20 G18", "G0 X2. Z0.1", "G32 W-35. F0.0625") == [(5, 5)]
    for cycle in ("G90", "G92", "G94"):
        # the end point out of Z's travel, by W and by Z
        assert spans("fanuc-lathe", *head, f"{cycle} U-10. W-1200. F0.2") == [(5, 11)], cycle
        assert spans("fanuc-lathe", *head, f"{cycle} X50. Z-1200. F0.2") == [(5, 10)], cycle
        # the modal repeat: a block with only X or U after the cycle's block
        assert spans("fanuc-lathe", *head, f"{cycle} X50. Z-10. F0.2", "X-600.") == [(6, 1)]
        assert spans("fanuc-lathe", *head, f"{cycle} U-10. W-10. F0.2", "U-600.") == [(6, 1)]
        # inside: Z 2 to -700, each W from the start point (Z2.), where the tool returns
        inside = (*head, f"{cycle} U-10. W-702. F0.2", "U-20.", "X30.", "G0 W-702.")
        assert spans("fanuc-lathe", *inside) == [], cycle
        assert spans("haas-lathe", "G20 G18", "G0 X2. Z0.1", f"{cycle} U-0.5 W-35. F0.01") \
            == [(5, 11)], cycle



def test_review_44_a_lathe_s_repetitive_cycles_tapers_and_okuma_threads_reach_the_spans(
    tmp_path: Path,
) -> None:
    """Review 44, F5, F1, F2: the end point X(U) Z(W) of a FANUC or Haas lathe's G74, G75,
    G76 (FANUC 0i-TF operator's manual, "Multiple repetitive cycle (G70-G76)"; Haas's one
    block), a single cycle's taper corner (FANUC R; Haas I, and K for G94) and an Okuma
    lathe's G33 (OSP-P200L 5238-E, 2-1: back at the starting point, its taper I) reach the
    TG601 spans; an Okuma G71 thread cycle is said not to be compared (TG140). fanuc-lathe X
    -10 to 500, Z -800 to 300; haas-lathe (inches) X -1 to 16, Z -22 to 12; okuma-lathe X
    -10 to 1100, Z -100 to 1100."""
    def found(profile: str, *body: str) -> list[tuple[int, int, str]]:
        path = tmp_path / "t.nc"
        path.write_text("%\nO1\n" + "\n".join(body) + "\nM30\n%\n")
        out = run("check", str(path), "-p", profile, "--select", "TG601,TG140",
                  "--format", "jsonl").stdout
        return [(f["line"], f["column"], f["rule"]) for f in map(json.loads, out.splitlines())]

    head = ("G21 G18 G99", "G0 X60. Z5.")
    # F5: the review's programs
    assert found("fanuc-lathe", *head, "G76 P010060 Q100 R0.05",
                 "G76 X50. Z-1200. P1000 Q300 F1.5") == [(6, 10, "TG601")]
    assert found("fanuc-lathe", *head, "G75 R0.5", "G75 X-600. Z-30. P1000 Q2000 F0.1") \
        == [(6, 5, "TG601")]
    assert found("fanuc-lathe", *head, "G74 R0.5", "G74 Z-1200. Q5000 F0.1") \
        == [(6, 5, "TG601")]
    assert found("haas-lathe", "G20 G18", "G0 X2. Z0.1", "G76 X1.8 Z-35. K0.05 D0.01 F0.0625") \
        == [(5, 10, "TG601")]
    # the tool back at Z5. after G76: W-800. from there stays inside (-795)
    assert found("fanuc-lathe", *head, "G76 P010060 Q100 R0.05",
                 "G76 X50. Z-30. P1000 Q300 F1.5", "G0 W-800.") == []
    # F1: the review's taper programs
    assert found("fanuc-lathe", "G21 G18 G99", "G0 X60. Z50.", "G90 X50. Z-30. R-300. F0.2",
                 "G0 X100. Z100.") == [(5, 5, "TG601")]
    assert found("fanuc-lathe", "G21 G18 G99", "G0 X60. Z50.", "G94 X20. Z0 R-1100. F0.2",
                 "G0 X100. Z100.") == [(5, 10, "TG601")]
    assert found("haas-lathe", "G20 G18", "G0 X2. Z0.1", "G90 X1.8 Z-1. I-9. F0.01") \
        == [(5, 5, "TG601")]
    assert found("haas-lathe", "G20 G18", "G0 X2. Z0.1", "G94 X1. Z0 K-35. F0.01") \
        == [(5, 9, "TG601")]
    # F2: Okuma G33 returns to its start point (1), (2), its taper I (3), G71 said (4)
    okuma = ("G0 X60. Z50.", "G33 X50. Z-30. F1.5")
    assert found("okuma-lathe", *okuma, "G0 W1130.") == [(5, 4, "TG601")]
    assert found("okuma-lathe", *okuma, "G0 W-1130.", "G0 X100. Z100.") == []
    assert found("okuma-lathe", "G0 X60. Z50.", "G33 X50. Z-30. I-600. F1.5") \
        == [(4, 5, "TG601")]
    assert found("okuma-lathe", "G0 X60. Z50.", "G71 X50. Z-1200. K2. D0.5 F1.5") \
        == [(4, 1, "TG140")]


def test_g53_under_g91_and_x_with_u_in_one_block_are_not_judged(tmp_path: Path) -> None:
    """Review 46, F3; review 44, F7 (lathe48): no page at hand says what a FANUC, Haas or
    SINUMERIK does with G53 under G91 (a 9/Series ignores the block, a Mitsubishi M700V moves
    by the increment), nor which of X and U (Z and W) in one lathe block the control takes:
    neither is judged as a position, one TG140 a file says so; under G90, and with X alone, the
    same positions are judged. fanuc-mill X -762 to 762; fanuc-lathe X -10 to 500."""
    def found(name: str, profile: str, program: str) -> list[tuple[int, int, str, str]]:
        path = tmp_path / name
        path.write_text(program)
        out = run("check", str(path), "-p", profile, "--select", "TG601,TG140",
                  "--format", "jsonl").stdout
        return [(f["line"], f["column"], f["rule"], f["message"])
                for f in map(json.loads, out.splitlines())
                if "reads the program in file order" not in f["message"]]

    inline = "%\nO1000\nG21 G91 G54\nG53 G0 X-800.\nM30\n%\n"
    got = found("inl53.nc", "fanuc-mill", inline)
    assert [f[:3] for f in got] == [(4, 1, "TG140")]
    assert got[0][3].startswith("G53 under G91")
    assert [f[:3] for f in found("abs53.nc", "fanuc-mill", inline.replace("G91", "G90"))] \
        == [(4, 8, "TG601")]
    # a body's G53 called under G91 (review 46's sub53g91.nc); under G90 judged at the call
    body = ("%\nO0002\nG53 G0 X-800.\nM99\nO1000\nG21 G90 G54\nG0 X0 Y0\nG91\nM98 P2\n"
            "G90\nM30\n%\n")
    got = found("sub53g91.nc", "fanuc-mill", body)
    assert [f[:3] for f in got] == [(9, 5, "TG140")]
    assert "writes a G53 before a G90 or G91 of its own" in got[0][3]
    assert [f[:3] for f in found("sub53g90.nc", "fanuc-mill",
                                 body.replace("G91\nM98", "G90\nM98"))] == [(9, 5, "TG601")]
    # X and U in one block: not judged (it was X620); X then U alone is
    xu = "%\nO1000\nG0 X0 Z0\nG0 X100. U520.\nM30\n%\n"
    got = found("xu.nc", "fanuc-lathe", xu)
    assert [f[:3] for f in got] == [(4, 1, "TG140")]
    assert "writes X and U" in got[0][3]
    assert [f[:3] for f in found("u.nc", "fanuc-lathe", xu.replace("X100. U520.", "U520."))] \
        == [(4, 4, "TG601")]
    # U from a position not known (after G28 U0 W0): no position judged, but a U longer than
    # X's whole travel (510 mm) is out of travel wherever it starts (incr48); one that fits
    # says nothing
    g28 = "%\nO1000\nG0 X0 Z0\nG28 U0 W0\nG0 U520.\nM30\n%\n"
    got = found("g28.nc", "fanuc-lathe", g28)
    assert [f[:3] for f in got] == [(5, 4, "TG601")]
    assert got[0][3].startswith(
        "X moves 520 (U520.) with its start not known: more than its whole travel of 510 "
        "(-10 to 500), out of travel wherever it starts")
    assert found("g28fits.nc", "fanuc-lathe", g28.replace("U520.", "U500.")) == []
    # a U whose value is not known leaves X not known, as G91 X#1 does on a mill (review 48,
    # F12: X at 0, U#1, U400., X-200. was "X spans 600"); a plain U after a known X is judged
    u1 = "%\nO1000\nG21 G40 G99\nG0 X0. Z5.\nG0 U#1\nG0 U400.\nG0 X-200.\nM30\n%\n"
    assert found("u1.nc", "fanuc-lathe", u1) == []
    got = found("u400.nc", "fanuc-lathe", u1.replace("G0 U#1\n", ""))
    assert [f[:3] for f in got] == [(6, 4, "TG601")]
    assert got[0][3].startswith("X spans 600 (from -200 to 400)")


def test_increments_wider_than_the_travel_from_a_start_not_known(tmp_path: Path) -> None:
    """Issue 32 (incr48): an axis whose position is not known (after G91 G28, a parameter's
    X#1) moved by G91 increments whose running sum, 0 included, reaches further than its whole
    travel is out of travel wherever it started (TG601 once a run); a run that fits, or that
    an absolute position interrupts, is not. fanuc-mill X -762 to 762 (1524 mm wide)."""
    def found(name: str, program: str) -> list[tuple[int, int, str, str]]:
        path = tmp_path / name
        path.write_text(program)
        out = run("check", str(path), "-p", "fanuc-mill", "--select", "TG601",
                  "--format", "jsonl").stdout
        return [(f["line"], f["column"], f["rule"], f["message"])
                for f in map(json.loads, out.splitlines())]

    run_ = "%\nO1000\nG21 G90 G54\nG0 X#1 Y0\nG91 G0 X800.\nY10.\nX800.\nG90\nM30\n%\n"
    got = found("run.nc", run_)
    assert [f[:3] for f in got] == [(7, 1, "TG601")]
    assert got[0][3].startswith("X moves over 1600 mm in 2 increments in a row (the last X800.) "
                                "with its start not known: more than its whole travel of 1524")
    # back and forth within the travel: nothing; an absolute X between: nothing
    assert found("back.nc", run_.replace("\nX800.", "\nX-800.")) == []
    assert found("abs.nc", run_.replace("Y10.", "G90 X0\nG91")) == []
    # in inches: 61 in is 1549.4 mm, 59 in 1498.6 mm
    inch = "%\nO1000\nG20 G90 G54\nG0 X#1 Y0\nG91 G0 X61.\nG90\nM30\n%\n"
    assert [f[:3] for f in found("inch.nc", inch)] == [(5, 8, "TG601")]
    assert found("inch59.nc", inch.replace("X61.", "X59.")) == []


def test_review_48_a_body_s_g53_at_each_call_and_the_mode_after_a_later_program(
        tmp_path: Path) -> None:
    """Review 48, F7: a body's G53 written before its own G90/G91 is judged at a G90 call even
    where a G91 call of it came first. F11: a program written after its call may leave G91
    (M99 restores no mode): the caller's next position is not judged as absolute until it
    writes its own G90/G91; one TG140 a file. F17: the sample machine's hint on the file's
    first TG601 said, a body's at its call. fanuc-mill X -762 to 762."""
    def found(name: str, program: str) -> list[tuple[int, int, str, str]]:
        path = tmp_path / name
        path.write_text(program)
        out = run("check", str(path), "-p", "fanuc-mill", "--select", "TG601,TG140",
                  "--format", "jsonl").stdout
        return [(f["line"], f["column"], f["rule"], f["message"])
                for f in map(json.loads, out.splitlines())
                if "reads the program in file order" not in f["message"]]

    g3 = ("%\nO2000\nG53 G0 X-800.\nM99\nO1000\nG21 G90 G54\nG91\nM98 P2000\nG90\n"
          "M98 P2000\nM30\n%\n")
    assert [f[:3] for f in found("g3.nc", g3)] == [(8, 5, "TG140"), (10, 5, "TG601")]
    q1 = "%\nO1000\nG21 G90 G54 G17\nG0 X700. Y0\nM98 P3000\nG0 X-900.\nM30\nO3000\nG91\nM99\n%\n"
    got = found("q1.nc", q1)
    assert [f[:3] for f in got] == [(5, 5, "TG140")]
    assert "whose G90/G91 the checker does not know" in got[0][3]
    assert [f[:3] for f in found("q1g90.nc", q1.replace("G0 X-900.", "G90 G0 X-900."))] \
        == [(5, 5, "TG140"), (6, 8, "TG601")]
    # F17: a body's TG601 at its call, the file's first said, carries the sample machine's
    # hint (the body's own finding, held and taken out at its M99, had spent it)
    sp2 = ("%\nO2000\nG90\nG0 X700.\nG0 X-900.\nM99\nO1000\nG21 G90 G54 G17\nG0 X0. Y0\n"
           "M98 P2000\nM30\n%\n")
    got = found("sp2.nc", sp2)
    assert [f[:3] for f in got] == [(10, 5, "TG601")]
    assert got[0][3].endswith(
        "(the built-in profile's limits are a typical machine of the family: a profile of your "
        "machine, `base` and its [limits], checks against yours; said once)")


def test_a_linuxcnc_definition_before_its_call_runs_under_the_call_s_shift_and_units(
        tmp_path: Path) -> None:
    """Review 41, finding 4: LinuxCNC's `o<s> sub` at the top of the file runs where it is
    called, in the units and under the G92 in force there (`rs274 -g ls1.ngc`: X-250,
    SET_G92_OFFSET(150), X250 at 400, 650 mm of a 600 mm travel). It was read at its place,
    under no shift: no TG601."""
    def found(name: str, program: str) -> list[tuple[int, str, str]]:
        path = tmp_path / name
        path.write_text(program)
        out = run("check", str(path), "-p", str(lc), "--select", "TG601,TG140",
                  "--format", "jsonl").stdout
        return [(f["line"], f["rule"], f["message"]) for f in map(json.loads, out.splitlines())
                if "reads the program in file order" not in f["message"]]

    lc = tmp_path / "lc.toml"
    lc.write_text('name = "lc"\nbase = "linuxcnc"\n[limits]\nX = [-300, 300]\n'
                  'Y = [-300, 300]\nZ = [-300, 300]\n')
    ls1 = "o<s> sub\nG0 X250\no<s> endsub\nG21 G90\nG0 X-250 Y0\nG92 X-400\no<s> call\nM2\n"
    got = found("ls1.ngc", ls1)
    assert [f[:2] for f in got] == [(7, "TG601")]
    assert "X spans 650 (from -250 to 400)" in got[0][2]
    assert "o<s> runs as called by o<s> call of line 7" in got[0][2]
    # inline, the same span (as before)
    inline = found("ls2.ngc", "G21 G90\nG0 X-250 Y0\nG92 X-400\nG0 X250\nM2\n")
    assert [f[:2] for f in inline] == [(4, "TG601")]
    # under G20 in a file that starts G21 (rs274: USE_LENGTH_UNITS inches, X15): 381 mm
    g20 = "o<s> sub\nG0 X15\no<s> endsub\nG21 G90\nG0 X-250 Y0\nG20\no<s> call\nM2\n"
    got = found("g20.ngc", g20)
    assert [f[:2] for f in got] == [(7, "TG601")]
    assert "X spans 631 (from -250 to 381)" in got[0][2] and "in inches" in got[0][2]
    # X10 in is 254 mm: -250 to 254, inside
    assert found("g20b.ngc", g20.replace("X15", "X10")) == []
    # no shift at the call, or never called: as before (500 mm, inside)
    assert found("plain.ngc", ls1.replace("G92 X-400\n", "")) == []
    assert found("never.ngc", ls1.replace("o<s> call\n", "")) == []
    # calls under two shifts: each judged where it is made (review 42, finding 9; rs274
    # runs the body at 400, then at 250), and the G92 after the first call, where the tool
    # stands is not known, starts the spans again: noted
    two = ls1.replace("o<s> call\n", "o<s> call\nG92 X-250\no<s> call\n")
    notes = found("two.ngc", two)
    assert [f[:2] for f in notes] == [(7, "TG601"), (8, "TG140")]
    # a body that sets its own G91: no absolute position of its own to judge
    own = ls1.replace("G0 X250\n", "G91 G0 X100\nG90\n")
    assert found("own.ngc", own) == []


def test_a_call_whose_number_is_not_known_leaves_the_programs_it_may_run_unjudged(
        tmp_path: Path) -> None:
    """Review 41, finding 5: `M98 P#1` may run O2000 in the caller's inches (X -35..35 in,
    1778 mm past the 1524 mm): it was read in the reset mm, inside. Not judged now, one TG140
    naming the call; with #1 known (`#1=2000`) it is judged as `M98 P2000` is."""
    def found(program: str) -> list[tuple[int, str, str]]:
        path = tmp_path / "p.nc"
        path.write_text(program)
        out = run("check", str(path), "-p", "fanuc-mill", "--select", "TG6,TG140",
                  "--format", "jsonl").stdout
        return [(f["line"], f["rule"], f["message"]) for f in map(json.loads, out.splitlines())
                if "(subprogram call)" not in f["message"]
                and "whose G90/G91 the checker does not know" not in f["message"]]

    pv4 = "%\nO1000\nG20 G90 G54\nG0 X-35. Y0\nM98 P#1\nM30\nO2000\nG0 X35.\nM99\n%\n"
    got = found(pv4)
    assert [f[:2] for f in got] == [(5, "TG140")]
    assert got[0][2].startswith("M98 P#1 calls a program whose number is not known")
    g65 = found(pv4.replace("M98 P#1", "G65 P#1 A1."))
    assert [f[:2] for f in g65] == [(5, "TG140")]
    known = found(pv4.replace("M98 P#1", "#1=2000\nM98 P#1"))
    assert [f[:2] for f in known] == [(9, "TG601")]
    assert "X spans 1778 (from -889 to 889)" in known[0][2]
    assert [f[:2] for f in found(pv4.replace("P#1", "P2000"))] == [(8, "TG601")]

def test_review_42_a_subprogram_before_its_call_keeps_every_tg601(tmp_path: Path) -> None:
    """Review 42, findings 0, 1, 7, 8: a body written before its call is judged at the call,
    with the spans as they stand there; its G53 position said where the call's units are
    those it was read in; its own G52 replaces the call's; a nested call's extent joins its
    caller's. Each gave a TG601 before sub41 and none with it. Finding 2: in line order."""
    def found(program: str) -> list[tuple[int, str, str]]:
        path = tmp_path / "p.nc"
        path.write_text(program)
        out = run("check", str(path), "-p", "fanuc-mill", "--select", "TG6,TG140",
                  "--format", "jsonl").stdout
        return [(f["line"], f["rule"], f["message"]) for f in map(json.loads, out.splitlines())]

    def tg601(program: str) -> list[tuple[int, str]]:
        got = found(program)
        lines = [f[0] for f in got]
        assert lines == sorted(lines), got
        return [(f[0], f[2].split(",")[0]) for f in got if f[1] == "TG601"]

    rs1 = ("%\nO0002\nG0 X900.\nM99\nO1000\nG21 G90 G54\nG0 X-700. Y0\nM98 P2\nG92 X0\n"
           "G0 X10.\nM30\n%\n")
    assert tg601(rs1) == [(8, "X spans 1600 (from -700 to 900)")]
    rs3 = ("%\nO0002\nG0 X900.\nM99\nO1000\nG21 G90 G54\nG0 X-700. Y0\nM98 P2\nM30\n"
           "O0003\nG52 X100.\nG0 X0\nM30\n%\n")
    assert tg601(rs3) == [(8, "X spans 1600 (from -700 to 900)")]
    g53 = "%\nO0002\nG53 G0 X-900.\nM99\nO1000\nG21 G90 G54\nM98 P2\nM30\n%\n"
    assert tg601(g53) == [(7, "X goes to -900 in machine coordinates (G53)")]
    g52own = ("%\nO0002\nG52 X0\nG0 X750.\nM99\nO1000\nG21 G90 G54\nG52 X-100.\n"
              "G0 X-700. Y0\nM98 P2\nG52 X0\nM30\n%\n")
    assert [f[1] for f in tg601(g52own)] == ["X spans 1550 (from -800 to 750)"]
    nest = ("%\nO0002\nG0 X900.\nM99\nO0003\nM98 P2\nM99\nO1000\nG21 G90 G54\n"
            "G0 X-700. Y0\nM98 P3\nM30\n%\n")
    assert tg601(nest) == [(11, "X spans 1600 (from -700 to 900)")]
    said = [f[2] for f in found(nest) if f[1] == "TG601"]
    assert "O0003 runs as called by M98 P3 of line 11, its position of line 6" in said[0]


def test_review_42_the_hold_of_a_program_read_apart_is_bounded(tmp_path: Path) -> None:
    """Review 42, finding 3: a program with no units code whose first findings are TG601
    held every later finding to its end (3.6 GB on a 75 MB file). Past 1024 held findings it
    is read as before, its findings streamed in line order; a later call of it is noted."""
    lines = ["%", "O0002", "G90 G54", "G0 X-700. Y0", "G0 X900."]
    lines += ["G1 X1. F20000.", "S99999 M3"] * 2000
    lines += ["M99", "O1000", "G21 G90 G54", "M98 P2", "M30", "%"]
    path = tmp_path / "big.nc"
    path.write_text("\n".join(lines) + "\n")
    out = run("check", str(path), "-p", "fanuc-mill", "--select", "TG6,TG140",
              "--format", "jsonl").stdout
    got = [json.loads(line) for line in out.splitlines()]
    at = [f["line"] for f in got]
    assert at == sorted(at)
    assert (5, "TG601") in [(f["line"], f["rule"]) for f in got]
    assert len([f for f in got if f["rule"] == "TG605"]) == 2000
    call = len(lines) - 2
    assert [f["message"][:45] for f in got if f["line"] == call and f["rule"] == "TG140"
            and f["message"].startswith("M98 P2 calls")] == [
        "M98 P2 calls O0002, read from the reset state"]


def _review_43(tmp_path: Path, program: str, select: str = "TG6,TG140"
               ) -> tuple[list[tuple[int, int, str, str]], list[tuple[int, int, str, str]]]:
    """The findings of ``program`` on fanuc-mill through the CLI (a report written as the lines
    are checked) and through the Python API's ``check_text`` (the core's findings taken once a
    chunk; ``iter_check_file`` alike): (line, column, rule, message) each."""
    path = tmp_path / "p.nc"
    path.write_text(program)
    out = run("check", str(path), "-p", "fanuc-mill", "--select", select, "--all",
              "--format", "jsonl").stdout
    cli = [(f["line"], f["column"], f["rule"], f["message"])
           for f in map(json.loads, out.splitlines())]
    profile = load_profile("fanuc-mill")
    api = [(f.line, f.column, f.rule, f.message)
           for f in check_text(program, profile, select=select.split(","))]
    _, streamed = iter_check_file(str(path), profile, select=select.split(","))
    assert [(f.line, f.column, f.rule, f.message) for f in streamed] == api
    return cli, api


def _machine_body(number: str, n: int) -> list[str]:
    return [number, "G1 X0 Y0 F100."] + ["G53 G0 X-900."] * n + ["M99"]


def test_review_43_b_the_hold_s_bound_is_the_same_through_the_cli_and_the_api(
        tmp_path: Path) -> None:
    """Review 43, finding B: bound.nc, a body of 1100 ``G53 G0 X-900.`` read apart: the CLI
    gave 1100 TG601 and the note of its call, check_text (the core taken once a chunk) none.
    The bound is counted where a finding is held, whatever takes them or is selected."""
    lines = ["%"] + _machine_body("O0002", 1100) + ["O1000", "G20 G90 G54", "M98 P2", "M30", "%"]
    bound = "\n".join(lines) + "\n"
    cli, api = _review_43(tmp_path, bound)
    assert cli == api
    assert len([f for f in cli if f[2] == "TG601"]) == 1100
    call = len(lines) - 2
    assert [f[:3] for f in cli if f[3].startswith("M98 P2 calls O0002, read from the reset")] \
        == [(call, 5, "TG140")]
    # the same note with TG140 alone: the bound does not count what the selection says
    cli, api = _review_43(tmp_path, bound, "TG140")
    assert cli == api
    assert [f[:3] for f in cli if f[3].startswith("M98 P2 calls O0002, read from the reset")] \
        == [(call, 5, "TG140")]
    # 1000 of them: held, said at the call in its units, through both
    small = bound.replace("G53 G0 X-900.\n" * 100, "", 1)
    cli, api = _review_43(tmp_path, small)
    assert cli == api
    assert len([f for f in cli if f[2] == "TG601"]) == 1000
    assert all("as called by M98 P2 of line 1007" in f[3] for f in cli if f[2] == "TG601")


def test_review_43_e_each_program_given_up_is_noted_at_its_calls(tmp_path: Path) -> None:
    """Review 43, finding E: two.nc, O0002 and O0003 each of 1100 G53 lines: the note of the
    first given up was lost to the second's. Each call of each now has its own."""
    lines = (["%"] + _machine_body("O0002", 1100) + _machine_body("O0003", 1100)
             + ["O1000", "G20 G90 G54", "M98 P2", "M98 P3", "M30", "%"])
    cli, api = _review_43(tmp_path, "\n".join(lines) + "\n")
    assert cli == api
    notes = [(f[0], f[3][:15]) for f in cli if "held more than 1024 findings of the travel" in f[3]]
    assert notes == [(len(lines) - 3, "M98 P2 calls O0"), (len(lines) - 2, "M98 P3 calls O0")]


def test_review_43_d_a_call_under_g91_runs_the_body_incremental(tmp_path: Path) -> None:
    """Review 43, finding D: callg91b.nc, ``G0 X900.`` of a body read apart, called under
    G91 after ``G0 X-700.``: the body runs incremental (G90/G91 are modal and a call changes
    none), so "X spans 1600" was false. A TG140 at the call says its positions are not known
    there; a body that writes its own G90 first is judged as before."""
    callg91b = ("%\nO0002\nG0 X900.\nM99\nO1000\nG21 G90 G54\nG0 X-700. Y0\nG91\nM98 P2\n"
                "G90\nM30\n%\n")
    cli, api = _review_43(tmp_path, callg91b)
    assert cli == api
    assert not [f for f in cli if f[2] == "TG601"]
    assert [f[:3] for f in cli if f[3].startswith("M98 P2 runs O0002 under the G91")] == [
        (9, 5, "TG140")]
    own = callg91b.replace("O0002\n", "O0002\nG90\n")
    cli, api = _review_43(tmp_path, own)
    assert cli == api
    assert [(f[0], f[3].split(",")[0]) for f in cli if f[2] == "TG601"] == [
        (10, "X spans 1600 (from -700 to 900)")]


def test_review_43_a_a_machine_position_is_judged_in_the_call_s_units(tmp_path: Path) -> None:
    """Review 43, finding A's remainder: a body's ``G53 G0 X-700.``, within the travel as read
    in mm, runs to -700 in (-17780 mm) under a G20 call: said at the call (g53in.nc gave
    nothing); under G21 nothing, as before."""
    g53in = "%\nO0002\nG53 G0 X-700.\nM99\nO1000\nG20 G90 G54\nG0 X0 Y0\nM98 P2\nM30\n%\n"
    cli, api = _review_43(tmp_path, g53in)
    assert cli == api
    said = [f for f in cli if f[2] == "TG601"]
    assert [f[:2] for f in said] == [(8, 5)]
    assert said[0][3].startswith("X goes to -700 in (-17780 mm) in machine coordinates (G53)")
    assert "O0002 runs in inches as called by M98 P2 of line 8, its position of line 3" \
        in said[0][3]
    cli, _ = _review_43(tmp_path, g53in.replace("G20", "G21"))
    assert not [f for f in cli if f[2] == "TG601"]


def test_review_47_f1_a_nested_call_s_own_g90_is_seen_by_its_caller(tmp_path: Path) -> None:
    """Review 47, F1: n2.nc, O1000 calls O0002 under G91 after X700.; O0002 calls O0003, whose
    own G90 makes its X-900. absolute: X spans 1600 at the G91 call, where only a TG140 was
    said. A call whose program the checker does not read there (O0003 after the caller) is
    named in the G91 note rather than promised followed."""
    n2 = ("%\nO0003\nG90\nG0 X-900.\nM99\nO0002\nG0 X5.\nM98 P3\nM99\nO1000\nG21 G90 G54\n"
          "G0 X700. Y0\nG91\nM98 P2\nG90\nM30\n%\n")
    cli, api = _review_43(tmp_path, n2)
    assert cli == api
    assert [(f[0], f[1], f[3].split(",")[0]) for f in cli if f[2] == "TG601"] == [
        (14, 5, "X spans 1600 (from -900 to 700)")]
    # three levels deep
    deep = ("%\nO0004\nG90\nG0 X-900.\nM99\nO0003\nG0 X1.\nM98 P4\nM99\nO0002\nG0 X5.\n"
            "M98 P3\nM99\nO1000\nG21 G90 G54\nG0 X700. Y0\nG91\nM98 P2\nG90\nM30\n%\n")
    cli, api = _review_43(tmp_path, deep)
    assert cli == api
    assert [f[3].split(",")[0] for f in cli if f[2] == "TG601"] == [
        "X spans 1600 (from -900 to 700)"]
    # O0003 after its caller: not read at O0002's call, and said so
    later = ("%\nO0002\nG0 X5.\nM98 P3\nM99\nO1000\nG21 G90 G54\nG0 X700. Y0\nG91\nM98 P2\n"
             "G90\nM30\nO0003\nG90\nG0 X-900.\nM99\n%\n")
    cli, api = _review_43(tmp_path, later)
    assert cli == api
    notes = [f for f in cli if f[3].startswith("M98 P2 runs O0002 under the G91")]
    assert [f[:2] for f in notes] == [(10, 5)]
    assert "the G90 or G91 of a program its M98 P3 of line 4 runs is not followed" in notes[0][3]


def test_review_46_f6_a_program_given_up_names_the_bound_it_passed(tmp_path: Path) -> None:
    """Review 46, F6: bound4k.nc, a body with one TG601 then 4200 warnings, given up past 4096
    findings of any rule: its call's note named the 1024 of its limits'."""
    lines = (["%", "O0002", "G53 G0 X-800."] + ["M456"] * 4200
             + ["G0 X700.", "G0 X-700.", "M99", "O1000", "G20 G90 G54", "G0 X0 Y0", "M98 P2",
                "M30", "%"])
    cli, api = _review_43(tmp_path, "\n".join(lines) + "\n", "TG6,TG140,TG307")
    assert cli == api
    notes = [f[3] for f in cli if f[3].startswith("M98 P2 calls O0002, read from the reset")]
    assert len(notes) == 1
    assert "more than 4096 findings of any rule were made after its first finding" in notes[0]
    assert "1024" not in notes[0]


def test_a_units_change_keeps_where_the_machine_is():
    """G20/G21 change the numbers, not the machine's place: X-700. mm then G20 G91 X60.5 is
    at 836.7 mm (the 60.5 inches added to the position in inches), a span of 1536.7 mm past the
    fanuc-mill's 1524; added to -700 as if it were mm it was -639.5, and the error was missed.
    X100. then G20 G91 X1. is 125.4 mm, no span error (it was 2565.4, a false TG601)."""
    fanuc = load_profile("fanuc-mill")
    far = "%\nO1\nG21 G90 G17\nG0 X-700. Y0 Z50.\nG20\nG91 G0 X60.5\nG90\nM30\n%\n"
    found = [(f.rule, f.line) for f in check_text(far, fanuc) if f.rule == "TG601"]
    assert found == [("TG601", 6)]
    near = far.replace("X-700.", "X100.").replace("X60.5", "X1.")
    assert not [f for f in check_text(near, fanuc) if f.rule == "TG601"]
    state = state_at(parse_text(near, fanuc.dialect), fanuc, 7)
    assert state.units == "inch" and state.position["X"] == Decimal("4.937007874")


def test_restart_state():
    """The state in force at a block (the preamble that restores it: tests/test_restart.py)."""
    profile = load_profile("fanuc-mill")
    program = ("%\nO1000\nN1 G20 G17 G90 G54\nN2 T5 M06\nN3 G43 D5\nN4 S3000 M03 M08\n"
               "N5 G01 X1. F20.\nN6 X2.\n")
    state = state_at(parse_text(program, profile.dialect), profile, 8)
    assert state.position["X"] == 1
    assert (state.units, state.plane, state.incremental, state.zero_shift) == ("inch", 17, False,
                                                                               54)
    assert (state.tool, state.offset, state.length_offset) == (5, 5, 43)
    assert (state.speed, state.spindle, state.coolant) == (3000, "cw", "flood")
    assert (state.motion, state.feed) == (1, 20)


# -- robustness ---------------------------------------------------------------------------------


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.binary(max_size=400))
def test_checker_never_crashes_on_random_bytes(data):
    text = data.decode("latin-1")
    for profile in (NEUTRAL, load_profile("fanuc-mill")):
        findings = check_text(text, profile)
        assert all(f.line >= 1 and f.column >= 1 for f in findings)


ALPHABET = "NGXYZIJKFSTMDR0123456789.-+ ()%:/\n=#[]"


@settings(max_examples=200, deadline=None)
@given(st.text(alphabet=ALPHABET, max_size=300))
def test_checker_never_crashes_on_nc_like_text(text):
    check_text(text, load_profile("iso-mill"))
    check_text(text, load_profile("pm322-eia"))


@pytest.mark.skipif(not corpus_files(), reason="shared/corpus is not present")
def test_checker_on_mutated_real_programs():
    rng = random.Random(7)
    for path in corpus_files():
        text = path.read_bytes().decode("utf-8", errors="surrogateescape")[:20000]
        for _ in range(5):
            chars = list(text)
            for _ in range(20):
                if chars:
                    chars[rng.randrange(len(chars))] = rng.choice(ALPHABET)
            checker = Checker(NEUTRAL, path.name)
            list(checker.run(parse_text("".join(chars), NEUTRAL.dialect, errors="collect")))


def test_a_comment_line_is_a_block_for_the_tv_check_and_the_comment_rules():
    """A line holding only a comment is punched and read like any block: the TV check counts
    its characters, and a '%' in it stops a transfer. A ':' in it is what an ISO tape reader
    would take for alignment; a Fanuc reads everything in a comment as text (one note)."""
    text = "%\nO1234\n(SET UP: VISE)\nN10 G00 X0\n(50% FEED)\n(AB)\n(ROUGH)\nN20 M30\n%\n"
    found = [(f.rule, f.severity, f.line, f.column)
             for f in check_text(text, load_profile("fanuc-mill"))]
    # the TV check is said once, at the first odd block ("O1234"), counting "(ROUGH)" and
    # "N20 M30" too
    assert found == [("TG122", "error", 5, 4), ("TG703", "info", 2, 5),
                     ("TG126", "info", 3, 8)]
    tv = [f for f in check_text(text, load_profile("fanuc-mill")) if f.rule == "TG703"]
    assert tv[0].message.startswith("3 blocks have an odd number of characters")
    iso = [(f.rule, f.line, f.column) for f in check_text(text, load_profile("iso-mill"))
           if f.rule.startswith("TG12")]
    assert iso == [("TG122", 3, 8), ("TG122", 5, 4)]


# A CAM program with a time stamp in every tool change comment.
STAMPED = ("%\nO1\n(PROGRAM 1 - 21:09)\nG21 G90 G17\n(T1 FLAT 10 - 21:09:14)\nT1 M06\n"
           "G00 X0 Y0\n(T2 DRILL 6 - 21:11)\nT2 M06\nM30\n%\n")


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill", "sinumerik-840d", "linuxcnc",
                                     "heidenhain-iso", "cm332-quadrant"])
def test_a_harmless_colon_in_comments_is_one_note_per_file_with_a_count(profile):
    """Where the control reads a comment as text, the time stamps stop nothing: one note at
    the first, with how many comments hold a ':' -- not an error, and not one per tool."""
    text, line = STAMPED, 3
    if profile == "linuxcnc":  # no O number: the stamp is on line 2
        text, line = text.replace("O1\n", ""), 2
    found = [f for f in check_text(text, load_profile(profile)) if f.rule.startswith("TG12")]
    assert [(f.rule, f.severity, f.line, f.column) for f in found] == [("TG126", "info", line,
                                                                        16)]
    assert found[0].message.startswith(f"3 comments hold ':' (the first, line {line})")


def test_a_colon_in_a_comment_is_an_error_where_the_tape_reader_stops_there():
    """An ISO 6983-1 control with the alignment function searches the tape for ':': each
    comment that holds one is an error of its own line."""
    found = [(f.rule, f.severity, f.line, f.column)
             for f in check_text(STAMPED, load_profile("iso-mill")) if f.rule.startswith("TG12")]
    assert found == [("TG122", "error", 3, 16), ("TG122", "error", 5, 17),
                     ("TG122", "error", 8, 17)]
    # once per comment, at its first ':'
    assert sum(f.rule == "TG122" for f in check_text(STAMPED, load_profile("iso-mill"))) == 3


def test_the_comment_colon_setting_overrides_the_default():
    stop = profile_from_text('dialect = "fanuc"\n[checks]\ncomment_colon = "stop"\n')
    text_ = profile_from_text('[checks]\ncomment_colon = "text"\n')
    assert (stop.comment_colon(), text_.comment_colon()) == ("stop", "text")
    assert load_profile("iso-mill").comment_colon() == "stop"  # its classification has ':'
    assert load_profile("pm322-eia").comment_colon() == "text"  # no alignment function
    assert load_profile("fanuc-mill").comment_colon() == "text"
    assert [f.rule for f in check_text(STAMPED, stop) if f.rule.startswith("TG12")] == \
        ["TG122"] * 3
    assert [f.rule for f in check_text(STAMPED, text_) if f.rule.startswith("TG12")] == \
        ["TG126"]
    with pytest.raises(ProfileError) as info:
        profile_from_text('[checks]\ncomment_colon = "yes"\n')
    assert (info.value.code, info.value.key) == ("profile-value", "checks.comment_colon")
    assert "choose one of stop, text" in info.value.message  # the choices the user is offered


def test_the_lines_before_a_runaway_block_are_checked_and_it_is_placed_right():
    """A chunk that ends in more than MAX_BLOCK characters without LF (binary data, a missing
    end of block) still has its whole lines checked, and the runaway block is reported on its
    own line, as block by block."""
    text = "%\nN1 X1.5 Y2. Z3.\nN2 X1.55555555\n" + "A" * 70000
    profile = load_profile("fanuc-mill")
    found = [(f.line, f.rule) for f in check_text(text, profile)]
    reference = Checker(profile)
    expected = [(f.line, f.rule) for f in reference.run(
        parse_stream([text], profile.dialect, errors="collect"))]
    assert found == expected
    # X1.55555555: decimals past IS-B, which a Fanuc is not documented to alarm on (TG208)
    assert (3, "TG208") in found and (4, "TG100") in found


def test_a_decimal_g_code_is_a_code_of_its_own():
    """G91.1 is not G91: the moves after it stay absolute, and a profile may name it."""
    program = "%\nN1 G21 G90 G17\nN2 G91.1\nN3 G01 X10. F100.\nN4 X20.\nN5 M30\n%\n"
    profile = load_profile("iso-mill")
    checker = Checker(profile)
    found = list(checker.run_stream([program], profile.dialect))
    assert checker.stats.high["X"] == 20  # 30 if G91.1 were read as G91
    assert [(f.rule, f.line) for f in found if f.rule == "TG301"] == [("TG301", 3)]
    named = profile_from_text('[codes]\n"G91.1" = { function = "arc centres incremental", '
                              'duration = "arc" }\n')
    assert not [f for f in check_text(program, named) if f.rule == "TG301"]


def test_an_arc_radius_under_linuxcncs_threshold_is_zero():
    """0.00127 mm (0.00005 in): LinuxCNC's zero-radius threshold, in both units. (On linuxcnc,
    which reads any decimals: iso-mill's inch format holds four, and refuses I0.00004, whose
    arc is then measured from no centre.)"""
    def zero_radius(units: str, i: str) -> bool:
        program = f"%\nN1 {units} G90 G17\nN2 G00 X0 Y0\nN3 G02 X0 Y0 I{i} J0 F100\nN99 M30\n%\n"
        return "TG405" in {f.rule for f in check_text(program, load_profile("linuxcnc"))}
    assert zero_radius("G21", "0.001") and not zero_radius("G21", "0.0013")
    assert zero_radius("G20", "0.00004") and not zero_radius("G20", "0.00006")


def test_tape_findings_follow_the_core_selection() -> None:
    """TG701/TG702 are found while decoding, in Python, but selected by the core's selection
    (--select/--ignore prefixes), as every other rule is."""
    from formats.profile import load_profile
    from postproc.check import Checker

    profile = load_profile("fanuc-mill")
    assert Checker(profile).enabled("TG701")
    assert not Checker(profile, select=["TG1"]).enabled("TG701")
    assert Checker(profile, select=["TG7"]).enabled("TG701")
    assert not Checker(profile, ignore=["TG70"]).enabled("TG702")


# A non-modal code that takes its block's axis words runs no arc: `G91 G28 Z0` after a G02 is
# a Fanuc program's everyday end, not an "arc without I J" (FANUC 0i-MF: group 00 acts in its
# block, G28's words are the intermediate point).
NON_MODAL_AFTER_ARC = {
    "fanuc-mill": ["G91 G28 Z0", "G30 G91 Z0", "G53 Z0", "G92 X0 Y0", "G10 L2 P1 X0",
                   "G52 X1.", "G31 X5.", "G27 X0", "G65 P9000 A1.", "G07.1 C57.3"],
    "haas-mill": ["G91 G28 Z0", "G53 Z0", "G92 X0 Y0", "G10 L2 P1 X0", "G52 X1.", "G31 X5.",
                  "G101 X0", "G47 P0 X0 Y0 I45. J0.5 R0.1 Z-0.01 F10. E5. (ABC)"],
    "okuma-mill": ["G30 P1 X0", "G31 X5.", "G71 Z5."],
    "iso-mill": ["G92 X0 Y0"],
}
NON_MODAL_AFTER_LATHE_ARC = {
    "fanuc-lathe": ["G28 U0 W0", "G50 X100. Z50.", "G71 U2. R1.", "G71 P10 Q20 U0.5 W0.1 F0.2",
                    "G76 X18. Z-20. P011060 Q100 R0.2 F1.5"],
    "haas-lathe": ["G28 U0 W0", "G50 X100. Z50.", "G71 P10 Q20 U0.02 W0.005 D0.1 F0.01"],
}


def _arc_then(profile: str, block: str, lathe: bool) -> list[str]:
    units = "" if profile == "iso-mill" else "G21 "
    arc = ("G18 G00 X0 Z10.\nG01 Z-1. F0.1\nG02 X10. Z-6. R5.\n" if lathe
           else "G00 X0 Y0 Z10.\nG01 Z-1. F100.\nG02 X10. Y0 R5.\n")
    text = f"%\nO1000\n{units}G90\n{arc}{block}\nG90\nM30\n%\n"
    return [f.rule for f in check_text(text, load_profile(profile)) if f.line == 7]


@pytest.mark.parametrize("profile,block", [(p, b) for p, bs in NON_MODAL_AFTER_ARC.items()
                                           for b in bs])
def test_a_non_modal_code_after_an_arc_is_no_arc(profile, block):
    assert not {"TG404", "TG401", "TG403", "TG410"} & set(_arc_then(profile, block, False))


@pytest.mark.parametrize("profile,block", [(p, b) for p, bs in NON_MODAL_AFTER_LATHE_ARC.items()
                                           for b in bs])
def test_a_non_modal_code_after_a_lathe_arc_is_no_arc(profile, block):
    assert not {"TG404", "TG401", "TG403", "TG410"} & set(_arc_then(profile, block, True))


# A code of a lathe's motion group of its own (group 01: threading, the single cycles) replaces
# the arc mode: its X Z are the thread's or the cycle's end point and its R, I, K a taper
# (FANUC 0i-TF "G code list"; Haas lathe "G-codes", group 01: G00-G03, G32, G90, G92, G94).
LATHE_MOTION_AFTER_ARC = {
    "fanuc-lathe": ["G32 Z-20. F1.5", "G92 X29. Z-20. F1.5", "G90 X35. Z-20. F0.2",
                    "G90 X35. Z-20. R-2. F0.2", "G94 X10. Z-2. R-1. F0.2"],
    "haas-lathe": ["G32 Z-20. F1.5", "G92 X29. Z-20. F1.5", "G90 X35. Z-20. I-2. F0.2",
                   "G94 X10. Z-2. K-1. F0.2", "G90 X35. Z-20. R-2. F0.2"],
}


@pytest.mark.parametrize("profile,block", [(p, b) for p, bs in LATHE_MOTION_AFTER_ARC.items()
                                           for b in bs])
def test_a_lathe_cycle_of_the_motion_group_after_an_arc_is_no_arc(profile, block):
    """The cycle's block and its modal repeat (`X30.`) are no arc; a G02 after it is one."""
    arc = "G18 G00 X0 Z10.\nG01 Z-1. F0.1\nG02 X10. Z-6. R5.\n"
    text = f"%\nO1000\nG21\n{arc}{block}\nX30.\nG02 X40. Z-30.\nM30\n%\n"
    found = [(f.rule, f.line) for f in check_text(text, load_profile(profile))
             if f.severity == "error"]
    assert found == [("TG404", 9)]


def test_okuma_lathe_cycles_after_an_arc_are_no_arc():
    """An OSP lathe's LAP call after a contour that ends on an arc (the everyday two-contour
    program), its fixed thread, compound thread and M-tool drilling cycles (5238-E sections 7
    and 8) run no arc; an arc without its radius after them still is one (TG404)."""
    for block in ["G85 NLAP2 D3. F0.3 U0.4 W0.1", "G32 X10. Z-1. F1.5",
                  "G71 X27.835 Z-25. B60 D0.4 U0.05 H1.083 F1.5 J1",
                  "G181 X0 Z-20. R5. F100.", "G73 X47. Z-20. K2.79 D4. F0.1"]:
        text = (f"G00 X20. Z2.\nG01 Z-20. F0.2\nG02 X40. Z-30. L10.\n{block}\n"
                "G02 X50. Z-40.\nM02\n")
        found = [(f.rule, f.line) for f in check_text(text, load_profile("okuma-lathe"))
                 if f.severity == "error"]
        assert found == [("TG404", 5)], block


def test_haas_pocket_with_its_compensation_side_after_an_arc():
    """Haas G150 takes its block's axis words and G41 D as the pocket's (NGC mill manual,
    "G150 General Purpose Pocket Milling"): no TG501 after a G02; G41 on a real arc is one."""
    head = "%\nO1\nG20 G17 G40 G80 G90\nG00 X0 Y0 Z1.\nG01 Z-0.1 F20.\nG02 X1. Y0 R0.5\n"
    pocket = "G150 X1. Y1. Z-0.5 G41 D01 P200 Q0.1 R0.1 I0.3 J0.3 K0.01 F15.\n"
    found = check_text(f"{head}{pocket}G40\nM30\n%\n", load_profile("haas-mill"))
    assert [f.rule for f in found if f.rule == "TG501"] == []
    found = check_text(f"{head}G41 D01 X2. Y1. R0.5\nG40 G01 X3.\nM30\n%\n",
                       load_profile("haas-mill"))
    assert [(f.rule, f.line, f.column) for f in found if f.rule == "TG501"] == [("TG501", 7, 1)]


def test_a_code_that_acts_on_the_motion_in_force_is_still_an_arc():
    """G09 (exact stop) runs the block's move in the motion mode in force: here an arc
    without its centre."""
    assert "TG404" in _arc_then("fanuc-mill", "G09 X20.", False)


def test_sending_a_program_that_ends_with_g28_after_an_arc_needs_no_force(tmp_path):
    path = tmp_path / "end.nc"
    path.write_text("%\nO1000\nG21 G90 G17\nG0 X0 Y0 Z10.\nG1 Z-1. F100.\nG2 X10. Y0 R5.\n"
                    "G91 G28 Z0\nG90\nM30\n%\n")
    result = run("check", str(path), "-p", "fanuc-mill")
    assert result.exit_code == 0, result.output
    assert "TG404" not in result.output


@pytest.mark.parametrize("profile,text,limited", [
    ("linuxcnc", "G21 G90\nG96 D2000 S200 M3\nM2\n", True),
    ("linuxcnc", "G21 G90\nG96 S200 M3\nM2\n", False),
    ("sinumerik-840d", "G96 S200 LIMS=3000 M3\nM30\n", True),
    ("sinumerik-840d", "LIMS=3000\nG96 S200 M3\nM30\n", True),
    ("sinumerik-840d", "G26 S3000\nG96 S200 M3\nM30\n", True),
    ("sinumerik-840d", "G96 S200 M3\nM30\n", False),
    ("okuma-lathe", "G50 S3000\nG96 S200 M03\nM02\n", True),
    ("okuma-lathe", "G96 S200 M03\nM02\n", False),
    ("fanuc-lathe", "%\nO1\nG50 S3000\nG96 S200 M03\nM30\n%\n", True),
    ("haas-lathe", "%\nO1\nG50 S2000\nG96 S200 M03\nM30\n%\n", True),
    ("fanuc-mill", "%\nO1\nG92 S3000\nG96 S200 M03\nM30\n%\n", True),
])
def test_each_family_limits_the_speed_in_its_own_form(profile, text, limited):
    """TG521 knows each control's spindle speed limit, and names the family's own form."""
    found = [f for f in check_text(text, load_profile(profile)) if f.rule == "TG521"]
    assert (not found) == limited, found
    if profile == "linuxcnc" and found:
        assert "D word" in found[0].message and "G92" not in found[0].message
    if profile == "sinumerik-840d" and found:
        assert "LIMS=" in found[0].message


def test_fanuc_parameter_input_blocks_are_data_not_program():
    """FANUC G10 L50 ... G11 (programmable parameter input): N a parameter number, R its value
    in the parameter's own unit, an integer as a rule: no word of the program's decimal style
    (TG201), no sequence number. The same block outside the mode is the program's."""
    text = ("%\nO1\nG21 G90\nG0 X1. Y1.\nG10 L50\nN1420 R15000\nN1422 P1 R20000\nG11\n"
            "G0 X10.\nM30\n%\n")
    fanuc = load_profile("fanuc-mill")
    rules = [f.rule for f in check_text(text, fanuc)]
    assert "TG201" not in rules, rules
    outside = [(f.rule, f.line) for f in check_text(text.replace("G10 L50\n", "G04 X1.\n"),
                                                    fanuc)]
    assert ("TG201", 6) in outside, outside


# The checker reads a word's format by the role the block's code gives it, from the table the
# converter reads (convert::code_meanings): a count, an angle or a selector of a cycle is read
# whole, never in least input increments (TG201), and a Haas reads a time or a factor P with
# its point (TG208).
def _mill(block: str) -> str:
    return f"%\nO1\nG20 G17\nG0 X0. Y0.\nG1 Z0. F10.\n{block}\nG80\nM30\n%\n"


def _lathe(block: str) -> str:
    return f"%\nO1\nG20 G99\nG0 X2. Z0.1\nG1 Z0. F0.01\n{block}\nN10 G1 X1.\nN20 Z-1.\nM30\n%\n"


@pytest.mark.parametrize("profile,text", [
    ("fanuc-mill", _mill("G81 X1. Y1. Z-1. R0.1 F10. K3")),
    ("haas-mill", _mill("G81 X1. Y1. Z-1. R0.1 F10. L3")),
    ("haas-mill", _mill("G84 X1. Y1. Z-1. R0.1 J2 F10.")),
    ("fanuc-lathe", _lathe("G73 U0.2 W0.1 R3")),
    ("haas-lathe", _lathe("G71 P10 Q20 U0.02 W0.005 D0.1 R1 F0.01")),
    ("haas-lathe", _lathe("G76 X0.9 Z-1. K0.06 D0.012 F0.0625 A60 P2")),
    ("haas-mill", _mill("G04 P1.5")),
    ("haas-mill", _mill("G51 X0 Y0 P1.5")),
    ("haas-mill", _mill("G82 X1. Y1. Z-1. R0.1 P0.5 F10.")),
    ("haas-lathe", _lathe("G04 P1.5")),
])
def test_a_count_angle_or_time_of_a_code_is_read_by_its_meaning(profile, text):
    found = [f.rule for f in check_text(text, load_profile(profile))]
    assert not {"TG201", "TG208"} & set(found), found


@pytest.mark.parametrize("profile,text,rule,column", [
    # a FANUC reads G68's R in 0.001 deg: R45 is 0.045 deg (FANUC 0i-MF, coordinate rotation)
    ("fanuc-mill", _mill("G68 X0 Y0 R45"), "TG201", 11),
    # a length of the same block without its point is still read in increments
    ("haas-mill", _mill("G81 X1 Y1. Z-1. R0.1 F10. K3"), "TG201", 5),
    # a FANUC's G04 P takes no point ("decimal point not permitted"): still TG208
    ("fanuc-mill", _mill("G04 P1.5"), "TG208", 5),
    # a length of a Haas cycle: its format's decimals hold
    ("haas-mill", _mill("G81 X1. Y1. Z-1. R0.12345 F10."), "TG208", 18),
])
def test_a_length_and_a_fanuc_dwell_keep_their_format(profile, text, rule, column):
    found = [(f.rule, f.line, f.column) for f in check_text(text, load_profile(profile))
             if f.rule == rule]
    assert found == [(rule, 6, column)]


@pytest.mark.parametrize("profile,block", [
    ("fanuc-lathe", "G32 Z-20. F1.5 Q180000"),
    ("fanuc-lathe", "G92 X29. Z-20. F1.5 Q180000"),
    ("haas-lathe", "G32 Z-20. F1.5 Q180000"),
    ("haas-lathe", "G76 X25. Z-20. K1. D0.3 F1.5 A60 P2 Q180000"),
])
def test_a_thread_start_angle_is_read_by_its_meaning_in_check_and_convert(profile, block):
    """Q of a lathe's G32/G92 (Haas: and its one-block G76) is the thread's start angle in
    0.001 deg, 0 to 360000 (FANUC 0i-TF "Threading (G32)"; Haas lathe G32/G76 "Q - Thread
    Start Angle (do not use a decimal point)"): a 2-start thread's second start Q180000 is no
    TG205, and convert keeps it as written in any units."""
    from formats.convert import ConvertOptions, convert_text
    text = f"%\nO1\nG21 G99\nG0 X30. Z2.\n{block}\nG0 X100. Z100.\nM30\n%\n"
    found = [(f.rule, f.column) for f in check_text(text, load_profile(profile))
             if f.severity == "error"]
    assert found == []
    for units in (None, "inch"):
        src = load_profile(profile)
        out, _ = convert_text(text, ConvertOptions(target=src, source=src, units=units))
        assert out.splitlines()[4].endswith(" Q180000"), out
    over = text.replace("Q180000", "Q360001")
    found = [(f.rule, f.line) for f in check_text(over, load_profile(profile))
             if f.severity == "error"]
    assert found == [("TG205", 5)]
    # written with a point: no form the manuals give (Haas: "do not use a decimal point")
    pointed = text.replace("Q180000", "Q180.")
    found = [(f.rule, f.line, f.severity) for f in check_text(pointed, load_profile(profile))
             if f.rule == "TG208"]
    assert found == [("TG208", 5, "warning")]


_LIVE_TOOL = ("%\nO1\nG20\nT101\nG97 S500 M03\nG00 X1. Z0.1\n"
              "G92 X0.9 Z-0.5 F0.05 Q0\n"           # 7: a thread, Q its start angle
              "G243 X0.5 Z-0.2 R1.1 Q0.1 F5.\n"     # 8: radial peck drilling, Q the peck
              "X0.8 Q0.15\n"                        # 9: the cycle repeated
              "Z-0.4 Q0.05\n"                       # 10
              "G80\n"                               # 11: the thread back in group 01
              "X0.8 Q0.15\n"                        # 12: a pass of the thread
              "M30\n%\n")


@pytest.mark.parametrize("text,said", [
    (_LIVE_TOOL, [12]),
    # a second live tool cycle over the same thread, and a G241 (no Q of its own) first
    (_LIVE_TOOL.replace("G243 X0.5 Z-0.2 R1.1 Q0.1", "G241 X0.5 Z-0.2 R1.1\nG243 X0.5 "
                        "Z-0.3 R1.1 Q0.1"), [13]),
    # a G32 thread in force: the same
    (_LIVE_TOOL.replace("G92 X0.9 Z-0.5", "G32 Z-0.5"), [12]),
    # a G01 after the cycle replaces it: G80 then puts back no thread
    (_LIVE_TOOL.replace("G80\n", "G01 X0.7 F0.01\nG80\n"), []),
])
def test_a_haas_lathe_live_tool_cycle_s_q_after_a_thread_is_not_its_start_angle(text, said):
    """Review 59c, F1: on a Haas lathe a block of words alone after a radial live tool cycle
    G241-G249 (Lathe Operator's Manual, group 09, cancelled by G80; G243's Q the peck)
    repeats the cycle, even with a thread G92 or G32 (group 01) in force before it: its Q is
    no start angle (TG208 "a thread's start angle ... 0.15 deg" was said at each repeat).
    After G80 the thread is in force again and its pass's pointed Q is said, as before."""
    found = [f.line for f in check_text(text, load_profile("haas-lathe"))
             if f.rule == "TG208" and "start angle" in f.message]
    assert found == said


def _tg118(text: str, profile: str) -> list[tuple[int, int]]:
    return [(f.line, f.column) for f in check_text(text, load_profile(profile))
            if f.rule == "TG118"]


@pytest.mark.parametrize("profile", ["fanuc-lathe", "haas-lathe"])
def test_a_cycle_whose_contour_block_is_missing_is_an_error_at_its_word(profile):
    """G70-G73 P ns Q nf: the control searches the program for N ns and N nf and alarms
    where one is missing (FANUC PS0063); found at the Q word."""
    body = ("%\nO1\nG21 G99\nG0 X52. Z2.\nG71 P10 Q30 U0.4 W0.1 D1. F0.25\nN10 G0 X20.\n"
            "G1 Z-20. F0.1\nN20 X52.\nG70 P10 Q30\nM30\n%\n")
    assert _tg118(body, profile) == [(5, 9), (9, 9)]
    assert _tg118(body.replace("N20", "N30"), profile) == []
    # leading zeros name the same block; a target written as an expression is not followed
    assert _tg118(body.replace("N20", "N0030"), profile) == []
    assert _tg118(body.replace("Q30", "Q#1"), profile) == []


def test_a_haas_local_subprogram_and_a_goto_must_find_their_block():
    text = ("%\nO1\nG20\nM97 P500\nM97 P1000 L2\n#1 = 1\nIF [#1 EQ 1] GOTO 77\nGOTO 10\n"
            "N10 G0 X0\nM30\nN1000 G01 X1. F10.\nM99\n%\n")
    assert _tg118(text, "haas-mill") == [(4, 5), (7, 14)]


@pytest.mark.parametrize("profile", ["haas-mill", "haas-lathe", "fanuc-mill"])
def test_a_jump_s_run_into_a_haas_local_subprogram_after_m30_is_checked(profile):
    """Review 50, F9: a jump's run that reads a Haas local subprogram after M30 (its findings
    held for the program read apart) panicked the core ("capacity overflow"): the run's list
    of findings was emptied without the index of the held ones. Checked now, the jump noted."""
    text = ("%\nO0001\nG90\nG0 X100. Y0\n#9=0\nIF[#6EQ1]GOTO100\nM30\nN100 G1 X#9 F#9\n"
            "M99\n%\n")
    found = check_text(text, load_profile(profile))
    assert ("TG140", 6, 1) in [(f.rule, f.line, f.column) for f in found]
    # the run's finding, held as the file's own where no units code is written yet: on the
    # Haas mill (inches, X travel 60) X0 after X100. is out of it, said with the jump
    spans = [f for f in found if f.rule == "TG601"]
    if profile == "haas-mill":
        assert [(f.line, f.column) for f in spans] == [(8, 9)]
        assert "X#9 is 0 where the jump of line 6 is taken" in spans[0].message
    # the CLI the review ran: a report and its exit code, no traceback
    result = CliRunner().invoke(main, ["check", "-p", profile, "-"], input=text)
    assert result.exit_code == (1 if spans else 0), result.output
    assert isinstance(result.exception, (SystemExit, type(None))), result.exception
    assert "IF[#6EQ1]GOTO100" in result.output


@pytest.mark.parametrize("profile", ["fanuc-mill", "haas-mill", "iso-mill"])
def test_an_end_block_s_own_move_is_judged_before_the_reset(profile):
    """An M02/M30 resets the state once its block's words are done: the block's own move is
    judged with its own motion and feed. `G01 X1. M30` with no F in force is a feed move with
    none (FANUC PS0011), though the reset state's motion is G00 on these FANUC and Haas
    profiles; `G00 X1. M30` after a `G01` is a rapid, though iso-mill's reset motion is G01."""
    def tg401(body: str) -> list[tuple[int, int]]:
        text = f"%\nO1\nG21\n{body}\n%\n"
        return [(f.line, f.column) for f in check_text(text, load_profile(profile))
                if f.rule == "TG401"]
    assert tg401("G00 X0\nG01 X1. M30") == [(5, 5)]
    assert tg401("G01 X0 F100.\nG00 X1. M30") == []
    assert tg401("G01 X0 F100.\nG01 X1. M30") == []


def test_a_repeat_count_of_a_modal_cycle_s_block_is_a_count():
    """Audit 50, B9: K of a block of hole positions under a modal canned cycle is its number of
    repeats (FANUC 0i-MF "Canned cycle": `G91 X10. K4` repeats the G81 four times 10 mm
    apart), a whole number as in the cycle's own block: no TG201 "read as 0.004". A block that
    writes a motion code leaves the cycle: its K is the profile's."""
    def tg201(blocks: str) -> list[tuple[int, int]]:
        text = (f"%\nO1\nG21 G90 G0 X0 Y0 Z10.\nG81 X10. Y10. Z-5. R2. F100. K3\n{blocks}\n"
                "G80\nM30\n%\n")
        return [(f.line, f.column) for f in check_text(text, load_profile("fanuc-mill"))
                if f.rule == "TG201"]
    assert tg201("G91 X10. K4\nG90 X30. Y30. K2") == []
    assert tg201("X20. K2") == []
    # planes alone keep the cycle (review 51, F10); a motion code leaves it
    assert tg201("G17 X20. K2") == []
    assert tg201("G00 X20. K2") == [(5, 10)]
    # review 52, F10: an arc's K in the block that ends the cycle is a length too, whatever
    # else the block writes (a plane, the distance mode; the code first or last)
    assert tg201("G18 G02 X10. Z0 I5. K5") == [(5, 21)]
    assert tg201("G02 G18 X10. Z0 I5. K5") == [(5, 21)]
    assert tg201("G91 G18 G03 X10. Z0 I5. K5") == [(5, 25)]
    assert tg201("X20. K2\nG18 G02 X10. Z0 I5. K5") == [(6, 21)]


def test_the_mixed_style_warning_and_the_arc_s_hint_are_said_once_a_file():
    """Review 52, F10, read again: in its program the second `G18 G02 ... K5` (ending a G81)
    got TG403 without TG201 nor the hint in TG403's text, as the first arc after G80 had both:
    TG201 is said once a file (6.1, the program mixes the two styles) and the hint with the
    file's first arc error, wherever a cycle is; the second arc's K is read as 0.005 all the
    same (its radius error the same)."""
    text = ("%\nO1000\nG21 G17 G90 G54\nG0 X0 Y0 Z5.\nG81 X0 Y0 Z-5. R2. F100.\nG80\n"
            "G18 G02 X10. Z0 I5. K5\nG17\nG81 X0 Y0 Z-5. R2. F100.\nG18 G02 X10. Z0 I5. K5\n"
            "G80\nM30\n%\n")
    found = [(f.rule, f.line, f.message) for f in check_text(text, load_profile("fanuc-mill"))
             if f.rule in ("TG201", "TG403")]
    assert [(r, n) for r, n, _ in found] == [("TG201", 7), ("TG403", 7), ("TG403", 10)]
    assert "(TG201: K5 on line 7, read as 0.005)" in found[1][2]
    assert found[1][2].split(";")[0] == found[2][2]


def test_a_haas_cycle_s_k_is_a_peck_depth_not_a_count(tmp_path):
    """Review 51, F15: a Haas's repeat count is L (Haas mill operator's manual, G81-G89); its
    G73/G83's K is the least peck depth, a length, in a block of hole positions too. `K4`
    there has no point: TG201 says it is read in increments, and a change of units converts it
    (it was kept as a FANUC repeat count)."""
    text = ("%\nO01000\nG20 G17 G90 G54\nG0 X0 Y0 Z1.\n"
            "G83 X0 Y0 Z-0.5 R0.1 Q0.1 I0.1 J0.02 K0.05 F10.\nG91 X1. K4\nG90 G80\nM30\n%\n")
    assert [(f.rule, f.line) for f in check_text(text, load_profile("haas-mill"))
            if f.rule == "TG201"] == [("TG201", 6)]
    path = tmp_path / "hk.nc"
    path.write_text(text)
    out = run("convert", str(path), "--from", "haas-mill", "--to", "haas-mill", "--units",
              "metric", "-o", "-")
    assert "G83 X0 Y0 Z-12.7 R2.54 Q2.54 I2.54 J0.508 K1.27 F254." in out.output
    assert "\nG91 X25.4 K0.01\n" in out.output  # 0.0004 in, at the metric format's 0.01


@pytest.mark.parametrize(("profile", "count", "units", "start", "step"), [
    ("fanuc-mill", "K8", "G21", "X-700.", "X200."),
    ("fanuc-mill", "K8.", "G21", "X-700.", "X200."),
    ("haas-mill", "L8", "G20", "X-25.", "X8."),
])
def test_a_repeat_count_under_g91_steps_the_holes_through_the_travel(profile, count, units,
                                                                     start, step):
    """Review 51, F5: under G91 a canned cycle's repeat count (FANUC K, Haas L) drills that many
    holes, each the increment from the last (FANUC 0i-MF "Canned cycle"; Haas NGC mill
    operator's manual, G81): eight holes 200 mm apart from X0 reach X1600, past the travel,
    as the same moves written one a block do (TG601). Before, the position moved once. The
    count of a FANUC K without a point is a count (eight), not 0.008 in increments."""
    def tg601(blocks: str) -> list[int]:
        text = (f"%\nO1\n{units} G17 G90 G54\nG0 {start} Y0 Z1.\nG81 X0 Y0 Z-0.1 R0.1 F10.\n"
                f"{blocks}\nG90 G80\nM30\n%\n")
        return [f.line for f in check_text(text, load_profile(profile)) if f.rule == "TG601"]
    assert tg601(f"G91 {step} {count}") == [6]
    assert tg601(f"G91 {step}") == []
    # under G90 the repeats drill the same hole; a count not known leaves X not followed
    assert tg601(f"{step} {count}") == []
    assert tg601(f"G91 {step} {count[0]}#1") == []


@pytest.mark.parametrize("ending", ["G1 X1 F100 M2", "G0 X1 M2", "G0 X2 M30",
                                    "G2 X2 Y0 R1 F100 M2", "G81 X1 Y1 Z-1 R2 F100 M2"])
def test_a_linuxcnc_end_block_s_own_motion_mode_is_in_force(ending):
    """Review 51, F7: an M2/M30 resets the modes once its block's words are done (LinuxCNC
    interp_convert.cc, program end), so the block's own axis words move under the motion code
    it writes or has in force: no TG411 "no motion mode in force". rs274 -g runs each."""
    text = f"G21 G90 G17\nG0 X0 Y0 Z0\n{ending}\n"
    assert [f.rule for f in check_text(text, load_profile("linuxcnc"))
            if f.severity == "error"] == []
    assert [f.line for f in check_text("G21 G90\nX1 M2\n", load_profile("linuxcnc"))
            if f.rule == "TG411"] == [2]


@pytest.mark.parametrize(("source", "target", "block", "word"), [
    ("fanuc-mill", "haas-mill", "G91 G83 X20. Y0 Z-15. R-8. Q3. K4 F100.", "K4"),
    ("haas-mill", "fanuc-mill", "G83 X1. Y0 Z-0.5 R0.1 Q0.1 K0.05 F10.", "K0.05"),
    ("haas-mill", "fanuc-mill", "G81 X1. Y0 Z-0.5 R0.1 F10. L3", "L3"),
    ("linuxcnc", "fanuc-mill", "G91 G81 X1 Y0 Z-0.5 R0.1 F10 L3", "L3"),
])
def test_a_cycle_s_repeat_count_is_refused_between_controls_that_write_it_apart(
        tmp_path, source, target, block, word):
    """Review 52, F6: a FANUC counts a canned cycle's repeats in K, a Haas and LinuxCNC in L,
    and a Haas's G73/G83 K is the least peck depth: carried as written, the target drills
    another number of holes (converted "ok" before). Refused at the word; between two
    controls of one reading the block converts."""
    head = "G21 G90 G17\nG0 X0 Y0 Z10.\n"
    if source != "linuxcnc":
        head = "%\nO1000\n" + head
    tail = "G80\nM2\n" if source == "linuxcnc" else "G80\nM30\n%\n"
    path = tmp_path / ("p.ngc" if source == "linuxcnc" else "p.nc")
    path.write_text(head + block + "\n" + tail)
    out = run("convert", str(path), "--from", source, "--to", target, "-o", "-")
    assert out.exit_code == 1
    assert f"{word}: " in out.output and "canned cycle's repeats" in out.output
    same = run("convert", str(path), "--from", source, "--to", source, "-o", "-")
    assert same.exit_code == 0, same.output


@pytest.mark.parametrize(("profile", "block", "column", "says"), [
    ("fanuc-mill", "G91 X10. K2.5", 10, "what it does with one that is not"),
    ("fanuc-mill", "G91 X10. K0", 10, "stores the cycle's data and drills no hole"),
    ("fanuc-mill", "G91 G81 X10. Y0 Z-5. R2. K2.5 F100.", 26, "what it does with one"),
    ("haas-mill", "G91 X10. L2.5", 10, "the Haas reads L as the cycle's number of holes"),
    ("haas-mill", "G91 X10. L0", 10, "no source at hand says"),
])
def test_a_repeat_count_that_is_no_whole_number_is_a_warning_at_the_word(profile, block, column,
                                                                          says):
    """Review 52, F11: a FANUC's K (0i-MF "Canned cycle": the number of repeats; K0 stores the
    cycle, no hole) or a Haas's L that is not a whole number of one or more passed in silence,
    the plane's axes no longer followed. TG544 at the word says what is not known; a whole
    count, an unknown one (`K#1`) and a Haas G83's K (a length) are not told."""
    units = "G21" if profile == "fanuc-mill" else "G20"
    def tg544(blocks: str) -> list[tuple[int, int, str]]:
        text = (f"%\nO1\n{units} G17 G90 G54\nG0 X0 Y0 Z5.\nG81 X0 Y0 Z-5. R2. F100.\n"
                f"{blocks}\nG90 G80\nM30\n%\n")
        return [(f.line, f.column, f.message) for f in check_text(text, load_profile(profile))
                if f.rule == "TG544"]
    found = tg544(block)
    assert [(line, col) for line, col, _ in found] == [(6, column)], found
    assert says in found[0][2] and "not followed after it" in found[0][2], found
    letter = "K" if profile == "fanuc-mill" else "L"
    assert tg544(f"G91 X10. {letter}2") == []
    assert tg544(f"G91 X10. {letter}#1") == []
    # a motion code ends the cycle: its K is no count
    assert tg544("G91 G1 X10. K0") == []
    if profile == "haas-mill":
        assert tg544("G83 X0 Y0 Z-0.5 R0.1 Q0.1 K0.05 F10.") == []


@pytest.mark.parametrize(("source", "block", "word"), [
    ("fanuc-mill", "G91 X10. K2.5", "K2.5"),
    ("fanuc-mill", "G91 G81 X10. Y0 Z-5. R2. K2.5 F100.", "K2.5"),
    # a FANUC G73/G83's K is its count beside I or J too, with a point or without (review
    # 56a, F3, F8)
    ("fanuc-mill", "G91 G83 X10. Y0 Z-5. R2. I1. J0.5 K2.5 F100.", "K2.5"),
    ("fanuc-mill", "G91 G73 X10. Y0 Z-5. R2. Q1. K0.5 F100.", "K0.5"),
    ("haas-mill", "G91 X10. L2.5", "L2.5"),
])
def test_a_repeat_count_that_is_no_whole_number_is_not_converted(tmp_path, source, block, word):
    """Review 52, F11: `convert --units inch` kept `K2.5` as a count no one knows the reading
    of; refused at the word, between controls of one reading too. K0, a whole count, is kept."""
    path = tmp_path / "p.nc"
    def convert(blocks: str):
        path.write_text("%\nO1000\nG21 G90 G17\nG0 X0 Y0 Z10.\nG81 X0 Y0 Z-5. R2. F100.\n"
                        f"{blocks}\nG80\nM30\n%\n")
        return run("convert", str(path), "--from", source, "--to", source, "--units", "inch",
                   "-o", "-")
    out = convert(block)
    assert out.exit_code == 1, out.output
    assert f"{word}: a canned cycle's repeat count that is not a whole number" in out.output
    assert ":6:" in out.output, out.output
    letter = word[0]
    kept = convert(f"G91 X10. {letter}0")
    assert kept.exit_code == 0, kept.output
    assert f"{letter}0\n" in kept.output


@pytest.mark.parametrize("k", ["K3", "K3."])
def test_a_fanuc_peck_cycle_s_k_is_its_count_beside_i_and_j(tmp_path, k):
    """Review 56a, F3: a FANUC's G73/G83 has no I or J peck words (0i-MF, 30i-MB: G83 X Y Z R Q
    F K); its K is the repeat count whether or not the block writes them. `convert --units
    inch --verify` scaled `K2` beside I and J as a length, K0.0001, and verify passed it,
    while the checker (TG544 on K0.002) and the FANUC count the holes. Now the converter
    keeps the count as written, verify holds it to its bytes, and the checker counts the
    holes, no TG544 (three 635 mm apart span more than the travel: TG601). A Haas's K there
    stays the least peck depth, a length, scaled."""
    path = tmp_path / "p.nc"
    path.write_text("%\nO1000\nG21 G17 G90 G54\nG0 X-300. Y0 Z10. S1000 M3\n"
                    f"G91 G83 X635. Z-5. R-3. I1. J0.5 {k} F100.\nG90 G80\nM30\n%\n")
    out = run("convert", str(path), "--from", "fanuc-mill", "--to", "fanuc-mill", "--units",
              "inch", "--verify", "-o", "-")
    assert out.exit_code == 0, out.output
    assert f"G91 G83 X25. Z-0.1968 R-0.1181 I0.0394 J0.0197 {k} F3.937\n" in out.output
    found = [(f.rule, f.line) for f in check_text(path.read_text(), load_profile("fanuc-mill"))
             if f.rule in ("TG544", "TG601")]
    assert found == [("TG601", 5)]
    haas = tmp_path / "h.nc"
    haas.write_text("%\nO1000\nG20 G17 G90 G54\nG0 X0 Y0 Z0.4 S1000 M3\n"
                    "G83 X1. Z-0.5 R0.1 I0.1 J0.02 K0.05 F10.\nG80\nM30\n%\n")
    out = run("convert", str(haas), "--from", "haas-mill", "--to", "haas-mill", "--units",
              "metric", "--verify", "-o", "-")
    assert out.exit_code == 0, out.output
    assert "G83 X25.4 Z-12.7 R2.54 I2.54 J0.508 K1.27 F254.\n" in out.output


def test_a_return_to_a_block_is_searched_in_a_main_program_only():
    """M99 P returns to the caller's block: a subprogram's is another program's (no TG118);
    a main program's M99 P loops in its own (FANUC PS0060 where it is missing)."""
    sub = "%\nO2000\nG21\nG0 X1.\nM99 P50\n%\n"
    assert _tg118(sub, "fanuc-mill") == []
    main = "%\nO1\nG21\nN10 G0 X1.\n/M99 P20\nM30\n%\n"
    assert _tg118(main, "fanuc-mill") == [(5, 6)]
    assert _tg118(main.replace("P20", "P10"), "fanuc-mill") == []


def test_each_program_of_a_file_has_its_own_blocks():
    text = ("%\nO1\nG21 G99\nG70 P10 Q20\nM30\nO2\nN10 G0 X1.\nN20 G1 Z-1. F0.1\nM30\n%\n")
    assert _tg118(text, "fanuc-lathe") == [(4, 5), (4, 9)]


@pytest.mark.parametrize("profile", ["fanuc-lathe", "haas-lathe"])
def test_a_lathe_s_g28_through_the_work_zero_is_a_warning(profile):
    """G28's words are the intermediate point; on a lathe X and Z are absolute, so G28 X0 Z0
    rapids to the part zero first (Haas G28: "moves to X0 Y0 Z0 in the current work coordinate
    system then to machine zero"). G28 U0 W0 is the return from where the tool stands."""
    def tg418(block: str) -> list[tuple[int, int]]:
        text = f"%\nO1\nG21 G99\nG0 X50. Z2.\n{block}\nM30\n%\n"
        return [(f.line, f.column) for f in check_text(text, load_profile(profile))
                if f.rule == "TG418"]
    assert tg418("G28 X0 Z0") == [(5, 5)]
    assert tg418("G28 X100. Z0") == [(5, 11)]
    assert tg418("G28 U0 W0") == tg418("G28 W0") == tg418("G28 X100. Z50.") == []


def test_an_okuma_program_name_with_a_letter_after_its_digits_is_a_name():
    """OSP: O and alphanumerics name a program (`O12A` as `OSTRT`): no TG100 "address A has no
    value", no TG134 for an A of `O1A2`."""
    for name in ("O12A", "O1234A", "O1A2", "OA12"):
        found = check_text(f"{name}\nG00 X100. Z100.\nM02\n", load_profile("okuma-lathe"))
        assert [f.rule for f in found if f.severity != "info"] == [], name


@pytest.mark.parametrize("profile", ["haas-lathe", "fanuc-lathe"])
def test_a_length_of_a_cycle_has_a_length_s_digits(profile):
    """A word the block's code makes a length (G83's peck Q, from the converter's cycle table)
    whose address's format holds no decimals (Q05, block numbers): with its point it has the
    digits of a length (Haas lathe G83 "Q - pecking depth"), not TG208 "Q05 holds 0"."""
    def tg208(block: str) -> list[tuple[int, int]]:
        text = f"%\nO1\nG20 G99\nG0 X2. Z0.1\n{block}\nG80\nM30\n%\n"
        return [(f.line, f.column) for f in check_text(text, load_profile(profile))
                if f.rule == "TG208"]
    assert tg208("G83 Z-1. R0.1 Q0.1 F5.") == []
    assert tg208("G83 Z-1. R0.1 Q0.12345 F5.") == [(5, 15)]


def test_a_block_that_cannot_be_read_is_still_there_for_the_search():
    """`N200 G00 3.7347` (a number without its address, a real lathe program's typo) is its
    own error; G71 P200 finds it, and the Q201 its contour lacks is TG118."""
    text = ("%\nO1\nG20 G99\nG0 X2. Z0.1\nG71 U0.06 R0.05\nG71 P200 Q201 U0.04 W0.01 F0.01\n"
            "N200 G00 3.7347\nG01 Z0\nN101 G00 X2.\nM30\n%\n")
    assert _tg118(text, "fanuc-lathe") == [(6, 10)]


def test_a_parameter_input_mode_without_its_g11_is_an_error_at_its_g10():
    """A program word inside G10 L50 ... (its G11 missing): the control alarms at that block,
    as convert refuses it; check reports TG119 at the G10 that opened the mode."""
    text = "%\nO1000\nG21\nG10 L50\nN1420 R15000\nN1422 P1 R20000\nG00 X10. Y10.\nM30\n%\n"
    found = [f for f in check_text(text, load_profile("fanuc-mill")) if f.rule == "TG119"]
    assert [(f.line, f.column, f.severity) for f in found] == [(4, 1, "error")], found
    assert "G11 is missing" in found[0].message and "line 7" in found[0].message
    closed = text.replace("G00 X10.", "G11\nG00 X10.")
    assert not [f for f in check_text(closed, load_profile("fanuc-mill")) if f.rule == "TG119"]
    shared = text.replace("G00 X10.", "G11 G00 X10.")
    found = [f for f in check_text(shared, load_profile("fanuc-mill")) if f.rule == "TG119"]
    assert "G11 shares its block" in found[0].message and "missing" not in found[0].message
    unended = "%\nO1000\nG21\nG10 L50\nN1420 R15000\n"  # the file ends inside the mode
    found = [f for f in check_text(unended, load_profile("fanuc-mill")) if f.rule == "TG119"]
    assert [(f.line, f.severity) for f in found] == [(4, "error")]
    assert "file ends inside it" in found[0].message


def test_a_haas_has_no_fanuc_data_input_mode_as_convert_says():
    """A Haas's G10 takes L2, L10-L13 and L20 (operator's manuals, G10): G10 L50 and G10 L3 are
    an error at their L on haas-mill and haas-lathe, as convert refuses them for a Haas target;
    the blocks after it are read as program. A FANUC reads the mode."""
    text = "%\nO1000\nG21 G90 G17\nG10 L50\nN1420 R15000\nG11\nG00 X0 Y0\nM30\n%\n"
    for name in ("haas-mill", "haas-lathe"):
        found = [f for f in check_text(text, load_profile(name)) if f.rule == "TG119"]
        assert [(f.line, f.column, f.severity) for f in found] == [(4, 5, "error")], found
        assert "a Haas does not have" in found[0].message
        life = text.replace("L50\nN1420 R15000", "L3\nP1 L500 Q1")
        assert [f.line for f in check_text(life, load_profile(name)) if f.rule == "TG119"] == [4]
    assert not [f for f in check_text(text, load_profile("fanuc-mill")) if f.rule == "TG119"]


def test_check_units_gives_the_units_the_machine_is_set_to(tmp_path):
    """An OSP lathe selects its units by a machine parameter (okuma-lathe: metric): X0 to X50.
    on an inch machine spans 1270 mm, more than its X travel (1110 mm), which only --units inch
    shows.
    On a control with units codes --units is the start units, and the program's G21 wins."""
    path = tmp_path / "i.min"
    path.write_text("O1\nG00 X0 Z2.\nG01 X50. F0.01\nM02\n")
    metric = CliRunner().invoke(main, ["check", str(path), "-p", "okuma-lathe", "--select",
                                       "TG601"], catch_exceptions=False)
    assert metric.exit_code == 0, metric.output
    inch = CliRunner().invoke(main, ["check", str(path), "-p", "okuma-lathe", "--units", "inch",
                                     "--select", "TG601"], catch_exceptions=False)
    assert inch.exit_code == 1
    assert "i.min:3:5: error TG601" in inch.output, inch.output
    fanuc = tmp_path / "f.nc"
    fanuc.write_text("%\nO1\nG21\nG00 X50. Z2.\nM30\n%\n")
    kept = CliRunner().invoke(main, ["check", str(fanuc), "-p", "fanuc-lathe", "--units",
                                     "inch", "--stats", "--format", "json"],
                              catch_exceptions=False)
    assert json.loads(kept.output)["stats"][str(fanuc)]["units"] == "metric"
    bad = CliRunner().invoke(main, ["check", str(path), "-p", "okuma-lathe", "--units", "feet"])
    assert bad.exit_code == 2


def test_a_word_is_read_by_the_meaning_its_own_control_gives_it():
    """A Haas G84's J is the retract multiple (Haas mill operator's manual, G84); a FANUC G84
    has no J (0i-MF: X Y Z R P Q F K), so there J2 is a length in least input increments and
    TG201 says so. A block of words alone in a cycle's mode repeats the cycle: its repeat count
    is one there too, no length (FANUC's K; a Haas's is L, review 51 F15)."""
    def text(count: str) -> str:
        return ("%\nO1000\nG21 G90 G17 G54\nT1 M06\nG00 G43 H1 Z50.\nS1000 M03\nG00 X0. Y0.\n"
                f"G98 G81 X1. Y1. Z-1. R0.1 F10.\nX2. Y2. {count}3\nG80\n"
                "G98 G84 X1. Y1. Z-1. R2. F100. J2\nX3. J2\nG80\nM30\n%\n")
    fanuc = [(f.line, f.message.split()[0])
             for f in check_text(text("K"), load_profile("fanuc-mill")) if f.rule == "TG201"]
    assert fanuc == [(11, "J2")]
    haas = load_profile("haas-mill")
    assert not [f for f in check_text(text("L"), haas) if f.rule == "TG201"]
    assert [f.line for f in check_text(text("K"), haas) if f.rule == "TG201"] == [9]


# A word the control refuses (a reading error at the word, or a whole block it cannot read)
# leaves what it would set unknown: the arc after it is measured from no guessed start. Each
# program's arc closes from X20 (the refused word's value) and not from X10 (the one before):
# measured from the old X it would be a false TG403. (The shops program FGodoy27 1001, a Fusion
# 360 Haas post's `N80 X 45. F300.` then `N85 G2 ...`, was the case found.)
REFUSED_THEN_ARC = {
    # Haas NGC: a blank between the address and its number alarms (TG100, the whole block)
    "haas-mill": ("%\nO1\nG21 G90 G17\nG0 X0 Y0\nG1 Z-1. F100.\nX10. Y0\nX 20.\n"
                  "G2 X29. Y9. I0 J9.\nM30\n%\n", ("TG100", 7, 2)),
    # FANUC: six digits before the point where X+053 holds five (TG205, the word alone)
    "fanuc-mill": ("%\nO1\nG21 G90 G17\nG0 X0 Y0\nG1 Z-1. F100.\nX10. Y0\nX123456.\n"
                   "G2 X29. Y9. I0 J9.\nM30\n%\n", ("TG205", 7, 1)),
    # LinuxCNC: an unclosed bracket (rs274: the block is not read)
    "linuxcnc": ("G21 G90 G17\nG0 X0 Y0\nG1 Z-1 F100\nX10 Y0\nX[20\nG2 X29 Y9 I0 J9\nM2\n",
                 ("TG100", 5, 5)),
}


@pytest.mark.parametrize("name", sorted(REFUSED_THEN_ARC))
def test_a_refused_word_leaves_its_axis_unknown(name):
    text, refusal = REFUSED_THEN_ARC[name]
    profile = load_profile(name)
    errors = [(f.rule, f.line, f.column) for f in check_text(text, profile)
              if f.severity == "error"]
    assert errors == [refusal]
    # the same arc after a plain move to X20: it closes, so no finding above came of it
    plain = text.replace("X 20.", "X20.").replace("X123456.", "X20.").replace("X[20", "X20")
    assert not [f for f in check_text(plain, profile) if f.severity == "error"]
    # and the arc measured from the X before the refused word is the one that does not close
    before = text.replace("X 20.\n", "").replace("X123456.\n", "").replace("X[20\n", "")
    assert "TG403" in {f.rule for f in check_text(before, profile)}



def test_a_refused_block_forgets_what_it_may_set():
    """A block the control cannot read that writes only an axis leaves the other axes known
    (the arc after it is still measured, and found not to close); one that writes a code as
    well may have changed any mode (here G91): every position is forgotten, no arc measured."""
    haas = load_profile("haas-mill")
    head = "%\nO1\nG21 G90 G17\nG0 X0 Y0\nG1 Z-1. F100.\nX10. Y0\n"
    axis = head + "Z 1.\nG2 X29. Y9. I0 J9.\nM30\n%\n"
    found = [(f.rule, f.line) for f in check_text(axis, haas) if f.severity == "error"]
    assert found == [("TG100", 7), ("TG403", 8)]
    code = head + "G91 Z 1.\nG90 G2 X29. Y9. I0 J9.\nM30\n%\n"
    found = [(f.rule, f.line) for f in check_text(code, haas) if f.severity == "error"]
    assert found == [("TG100", 7)]


def test_an_arc_to_an_end_point_set_by_a_parameter_is_not_measured():
    """An arc whose end the checker cannot evaluate (X#1) is measured against no end point:
    taking the start's X for it made a false zero radius or radius mismatch."""
    fanuc = load_profile("fanuc-mill")
    text = "%\nO1\nG21 G90 G17\nG0 X0 Y0\nG1 Z-1. F100.\nX10. Y0\nG2 X#1 Y9. I0 J9.\nM30\n%\n"
    rules = {f.rule for f in check_text(text, fanuc)}
    assert not rules & {"TG403", "TG405", "TG410"}, rules
    # the same arc to a plain end that does not close is found
    plain = text.replace("X#1", "X29.")
    assert "TG403" in {f.rule for f in check_text(plain, fanuc)}


def test_a_program_starts_where_its_caller_left_the_machine():
    """A FANUC, Haas or Okuma subprogram in G91 draws its first arc from where its caller left
    the tool: no error, whether it is alone in its file or after another program (alone it
    was an 'arc start point unknown' error, TG408, which send refused)."""
    main = "%\nO1000\nG21 G90 G17\nG00 X100. Y100. Z5.\nG01 X50. F100.\nM30\n%\n"
    for name, end in (("fanuc-mill", "M99"), ("haas-mill", "M99"), ("okuma-mill", "RTS")):
        profile = load_profile(name)
        for body in ("G91 G02 X10. Y0 R5. F100.\nG90 G01 X0 Y0",
                     "G21\nG01 X10. F100.\nG02 X20. Y0 R5."):
            sub = f"%\nO2000\n{body}\n{end}\n%\n"
            # (the motion rules, TG4nn: an Okuma reads no O number after M30 as a new program)
            alone = [(f.rule, f.line) for f in check_text(sub, profile)
                     if f.severity == "error" and f.rule.startswith("TG4")]
            after = [(f.rule, f.line - main.count("\n")) for f in check_text(main + sub, profile)
                     if f.severity == "error" and f.rule.startswith("TG4")]
            assert alone == after == [], (name, body)
    # once the program has given its start, the arc is checked
    found = check_text("G21 G90 G17\nG00 X0 Y0\nG02 X10. Y0 I3. J0 F100.\nM30\n",
                       load_profile("fanuc-mill"))
    assert [f.line for f in found if f.rule == "TG403"] == [3]


# G10 L2/L20 sets a work system's origin: only the system in force moves this program's
# coordinates (FANUC 0i-MF "Changing workpiece coordinate system (G10 L2, L20)"; Haas "G10 Set
# Offsets", L2 P1-P6 and L20 for G154 P; LinuxCNC G-code reference, G10 L2/L20, P0 the active
# system). The arc after it (radius 5 at its start, 15 at its end: FANUC alarm PS0020) is
# measured where the G10 sets another system, and not where it may set the one in force.
_G10_ARC = ("{head}G0 X10. Y10. Z5.\nG1 Z-1. F100.\n{g10}\nG2 X30. Y10. I5. J0\n"
            "M30\n{tail}")


@pytest.mark.parametrize("profile, head, tail", [
    ("fanuc-mill", "%\nO1\nG21 G17 G90 G54\n", "%\n"),
    ("haas-mill", "%\nO1\nG21 G17 G90 G54\n", "%\n"),
    ("linuxcnc", "G21 G17 G90 G54\n", ""),
])
@pytest.mark.parametrize("g10, measured", [
    ("G10 L2 P2 X100. Y0 Z0", True),     # G55: not in force
    ("G10 L2 P6 X100. Y0", True),       # G59
    ("G10 L2 P1 X100. Y0 Z0", False),   # G54, in force: the position moves
    ("G10 L2 P0 X100. Y0 Z0", False),   # FANUC external offset, Haas G52, LinuxCNC active
    ("G10 L2 P#1 X100. Y0", False),     # a system by a parameter: not known
    ("G10 L11 P1 R0.1", True),          # tool data: no axis word
])
def test_a_g10_for_a_work_system_not_in_force_keeps_the_position(profile, head, tail, g10,
                                                                 measured):
    text = _G10_ARC.format(head=head, g10=g10, tail=tail)
    lines = 1 + head.count("\n") + 2
    found = {(f.rule, f.line) for f in check_text(text, load_profile(profile))}
    assert (("TG403", lines + 1) in found) == measured, sorted(found)


@pytest.mark.parametrize("profile, head, select, g10", [
    # L20: FANUC's G54.1 P, Haas's G154 P; in force only under them
    ("fanuc-mill", "%\nO1\nG21 G17 G90 ", "G54", "G10 L20 P1 X100. Y0"),
    ("haas-mill", "%\nO1\nG21 G17 G90 ", "G54", "G10 L20 P1 X100. Y0"),
    # LinuxCNC's L20 P2 (G55) and P7 (G59.1) while G54 is in force
    ("linuxcnc", "G21 G17 G90 ", "G54", "G10 L20 P2 X100. Y0"),
    ("linuxcnc", "G21 G17 G90 ", "G54", "G10 L2 P7 X100. Y0"),
])
def test_g10_l20_and_the_systems_beyond_g59(profile, head, select, g10):
    """A G10 for another system than G54 in force keeps the arc measured; under a system the
    modal state does not number (G54.1 P1, Haas G154 P1, LinuxCNC G59.1) the same G10 may set
    the one in force: not measured."""
    tail = "%\n" if head.startswith("%") else ""
    profile = load_profile(profile)
    for system, measured in [(select, True), (
            {"fanuc-mill": "G54.1 P1", "haas-mill": "G154 P1"}.get(profile.name, "G59.1"),
            False)]:
        if profile.name == "linuxcnc" and system == "G59.1" and "P7" in g10:
            measured = False  # G59.1 is P7: the system in force
        text = _G10_ARC.format(head=head + system + "\n", g10=g10, tail=tail)
        found = {f.rule for f in check_text(text, profile)}
        assert ("TG403" in found) == measured, (system, g10, sorted(found))


def test_sarif_quotes_a_file_name_that_is_not_utf8_by_its_bytes(tmp_path, monkeypatch):
    # review 23, finding 3: a relative name holding the byte 0xFF (Python's surrogate \udcff)
    # raised UnicodeEncodeError in the URI's quoting; the absolute one was p%FF.ngc already
    import os
    from urllib.parse import unquote_to_bytes

    name = os.fsdecode(b"p\xff.ngc")
    try:
        (tmp_path / name).write_text(BAD)
    except (OSError, UnicodeEncodeError):
        pytest.skip("the file system takes no name that is not UTF-8")
    monkeypatch.chdir(tmp_path)
    for where, expected in [(".", "p%FF.ngc"), (str(tmp_path), (tmp_path / name).as_uri())]:
        r = run("check", where, "-p", "iso-mill", "--format", "sarif")
        assert r.exception is None or isinstance(r.exception, SystemExit), r.exception
        results = json.loads(r.output)["runs"][0]["results"]
        uris = {res["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
                for res in results}
        assert uris == {expected}, uris
    assert unquote_to_bytes("p%FF.ngc") == os.fsencode(name)


@pytest.mark.parametrize("name", ["part #2 100%.nc", "my part?.nc", "p\u00e9 a:b.nc", "plain.nc"])
def test_sarif_uris_are_uri_references_that_give_the_file_names_back(tmp_path, monkeypatch,
                                                                     name):
    # review 21, finding 4: SARIF 2.1.0's artifactLocation.uri is a URI reference (RFC 3986);
    # a relative path is a relative reference, an absolute one a file: URI, each percent-encoded
    from urllib.parse import unquote, urlsplit
    from urllib.request import url2pathname

    (tmp_path / "sub dir").mkdir()
    (tmp_path / "sub dir" / name).write_text(BAD)
    monkeypatch.chdir(tmp_path)
    relative = Path("sub dir") / name
    absolute = tmp_path / "sub dir" / name
    r = run("check", str(relative), str(absolute), "-p", "iso-mill", "--format", "sarif")
    uris = {res["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
            for res in json.loads(r.output)["runs"][0]["results"]}
    assert len(uris) == 2, uris
    for uri in uris:
        parts = urlsplit(uri)
        assert parts.query == "" and parts.fragment == "" and "#" not in uri, uri
        assert " " not in uri and all(ord(c) < 128 for c in uri), uri
        if parts.scheme:
            assert parts.scheme == "file" and parts.netloc == "", uri
            assert Path(url2pathname(parts.path)) == absolute
        else:
            assert not parts.netloc and not uri.startswith("/"), uri
            assert Path(unquote(parts.path)) == relative


def test_review_43_a_machine_position_of_a_body_read_before_its_call_in_other_units(
        tmp_path: Path) -> None:
    """Review 43, finding A: `G53 G0 X-900.` in O0002, called under G20 from a later O1000,
    runs at -900 in, beyond the travel as -900 mm already is: said, naming the call (sub43
    had dropped it, where the check before sub41 said it). Called under G21 on an inch
    profile, its value is judged in mm there (fix44, finding A's remainder; a TG140 said it
    was not): X-40. is inside, X-800. beyond."""
    path = tmp_path / "g53.nc"
    path.write_text("%\nO0002\nG53 G0 X-900.\nM99\nO1000\nG20 G90 G54\nM98 P2\nM30\n%\n")
    out = run("check", str(path), "-p", "fanuc-mill", "--select", "TG601,TG140",
              "--format", "jsonl").stdout
    found = [json.loads(line) for line in out.splitlines()]
    errors = [f for f in found if f["rule"] == "TG601"]
    assert [(f["line"], f["column"]) for f in errors] == [(3, 8)]
    assert "runs in inches as called by M98 P2 of line 7" in errors[0]["message"]
    path.write_text("%\nO0002\nG53 G0 X-40.\nM99\nO1000\nG21 G90 G54\nM98 P2\nM30\n%\n")
    out = run("check", str(path), "-p", "haas-mill", "--select", "TG601,TG140",
              "--format", "jsonl").stdout
    found = [json.loads(line) for line in out.splitlines()]
    assert [f for f in found if f["rule"] == "TG601"] == []
    assert not [f for f in found if "machine positions" in f["message"]]
    path.write_text("%\nO0002\nG53 G0 X-800.\nM99\nO1000\nG21 G90 G54\nM98 P2\nM30\n%\n")
    out = run("check", str(path), "-p", "haas-mill", "--select", "TG601,TG140",
              "--format", "jsonl").stdout
    errors = [json.loads(line) for line in out.splitlines() if '"TG601"' in line]
    assert [(f["line"], f["column"]) for f in errors] == [(7, 5)]
    assert errors[0]["message"].startswith(
        "X goes to -800 mm (-31.496063 in) in machine coordinates (G53)")
    assert "O0002 runs in millimetres as called by M98 P2 of line 7" in errors[0]["message"]
