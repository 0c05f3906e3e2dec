"""A G54-G59 selection keeps the machine position, across a call of a body written after the
main program's end (issue 32 item 4; review 78-lcnc78b H15).

Selecting another work system moves no axis: the tool's position in the new system is its
machine position minus the new offset (LinuxCNC interp_convert.cc
``convert_coordinate_system``; FANUC 0i-F/30i-B and Haas: G54-G59 select the work coordinate
system, no motion). A body written after the main program's end (a FANUC's or Haas's ``O2000``
after M30, a Haas's ``N100`` of an ``M97 P100``, LinuxCNC's ``o2000 sub`` or ``O2000`` after M2)
runs at its call, under the system in force there, before the main program's blocks after the
call -- which the checker reads first. Where both systems' values are known (the profile's
[work_offsets], nothing writes them) each position is judged as a machine position, and a
span across the two, in work coordinates, mixes positions of two offsets: the main program's
span is set aside where the body begins under the call's other system, as at a selection.

The profiles give G54 X 0 and G57 X -300 on a travel of -762 to 762 (the Haas's in mm). The
LinuxCNC forms are run on ``rs274 -g`` (where installed) with a var file holding G57's X
(parameter 5281 = 5221 + 20 * 3, in inches: -300 / 25.4): its STRAIGHT_TRAVERSE prints the work
position, the machine position is that plus the SET_G5X_OFFSET in force.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from formats.profile import load_profile
from postproc.check import check_text

from .conftest import rs274_output

LIMITS = ("[limits]\nX = [-762.0, 762.0]\nY = [-406.0, 406.0]\nZ = [-508.0, 10.0]\n"
          "[work_offsets]\nG54 = { X = 0.0, Y = 0.0, Z = 0.0 }\n"
          "G57 = { X = -300.0, Y = 0.0, Z = 0.0 }\n")

BASES = {"fanuc": "fanuc-mill", "haas": "haas-mill", "haas97": "haas-mill",
         "lcnc98": "linuxcnc", "lcnc": "linuxcnc"}


def profile(tmp_path: Path, form: str):
    path = tmp_path / f"{form}.toml"
    units = 'units = "metric"\n' if BASES[form] == "haas-mill" else ""
    path.write_text(f'name = "sel-{form}"\nbase = "{BASES[form]}"\n{units}{LIMITS}')
    return load_profile(str(path))


def program(form: str, main: str, body: str) -> str:
    """`main` (blocks split at ` / `, `CALL` the call, `WHILE` / `ENDW` a one-pass loop), M30,
    then `body` in the form's subprogram after the end."""
    call = {"lcnc": "o2000 call", "haas97": "M97 P100"}.get(form, "M98 P2000")
    lcnc = form.startswith("lcnc")
    loop = ("o100 while [#1 LT 1]", "o100 endwhile") if lcnc else ("WHILE [#1 LT 1] DO1", "END1")
    blocks = [{"CALL": call, "WHILE": loop[0], "ENDW": loop[1]}.get(b, b)
              for b in main.split(" / ")]
    head = ["G21 G17 G90"] if lcnc else ["O1000", "G21 G17 G90"]
    lines = body.split(" / ")
    if form == "lcnc":
        tail = ["o2000 sub", *lines, "o2000 endsub"]
    elif form == "haas97":
        tail = [f"N100 {lines[0]}", *lines[1:], "M99"]
    else:
        tail = ["O2000", *lines, "M99"]
    return "\n".join([*head, *blocks, "M30", *tail]) + "\n"


def errors(tmp_path: Path, form: str, main: str, body: str) -> list[tuple[int, str]]:
    text = program(form, main, body)
    return [(f.line, f.message) for f in check_text(text, profile(tmp_path, form))
            if f.severity == "error"]


def machine_moves(tmp_path: Path, text: str) -> list[float]:
    """rs274's X of each STRAIGHT_TRAVERSE in machine coordinates (work + the G5X offset + the
    G92/G52 offset)."""
    var = tmp_path / "sel.var"
    lines = ["5220\t1.000000"] + [f"{n}\t{-300 / 25.4 if n == 5281 else 0.0:.9f}"
                                  for n in range(5221, 5390)]
    var.write_text("\n".join(lines) + "\n")
    out = rs274_output(tmp_path, text, ("-v", str(var)))
    assert "PROGRAM_END" in out, out
    offset, shift, moves = 0.0, 0.0, []
    for line in out.splitlines():
        if "SET_G5X_OFFSET(" in line:
            offset = float(line.split("SET_G5X_OFFSET(")[1].split(",")[1])
        elif "SET_G92_OFFSET(" in line:
            shift = float(line.split("SET_G92_OFFSET(")[1].split(",")[0])
        elif "STRAIGHT_TRAVERSE(" in line:
            work = float(line.split("STRAIGHT_TRAVERSE(")[1].split(",")[0])
            moves.append(work + offset + shift)
    return moves


FORMS = ["fanuc", "haas", "haas97", "lcnc98", "lcnc"]

# (main, body, the machine X of each move as rs274 runs it: all inside -762..762)
INSIDE = [
    # review 78-lcnc78b H15: the body's X-740 under the call's G54 (machine -740), then the
    # main's G57 X800 (800 - 300 = 500): was "X spans 1540" (LinuxCNC, Haas M97)
    ("G54 / CALL / G57 / G0 X800.", "G0 X-740.", [-740.0, 500.0]),
    # ... two moves each, and Y: -740, -700 under G54; 800 - 300 = 500, 700 - 300 = 400
    ("G54 / CALL / G57 / G0 X800. Y10. / G0 X700.", "G0 X-740. Y-5. / G0 X-700.",
     [-740.0, -700.0, 500.0, 400.0]),
    # review 78-lcnc78b F7: -650 under G54, then the body under the call's G57 (1000 - 300 =
    # 700)
    ("G54 / G0 X-650. / G57 / CALL", "G0 X1000.", [-650.0, 700.0]),
]


@pytest.mark.parametrize("main, body, machine", INSIDE)
@pytest.mark.parametrize("form", FORMS)
def test_positions_across_a_selection_are_judged_in_machine_coordinates(
        tmp_path: Path, form: str, main: str, body: str, machine: list[float]) -> None:
    assert errors(tmp_path, form, main, body) == []
    if form.startswith("lcnc"):
        assert machine_moves(tmp_path, program(form, main, body)) == machine


# (main, body, rs274's machine X of each move, {form: (line, start of the message), or None:
# not said}): real overtravels, each refused where main refuses it
BEYOND = [
    # the brief's loop: G54 X-650 (machine -650), the body under G57 (1000 - 300 = 700), then
    # the loop's X-1100 under G54: machine -1100, beyond -762. FANUC/Haas (M98 of a later O
    # program: the caller's G90/G91 is not known after it, TG140) by the span of -650 and
    # 1000 at the body's line, as before.
    ("G54 / G0 X-650. / G57 / CALL / G54 / #1=0 / WHILE / G0 X-1100. / #1=1 / ENDW",
     "G0 X1000.", [-650.0, 700.0, -1100.0],
     {"fanuc": (15, "X spans 1650"), "haas": (15, "X spans 1650"),
      "haas97": (14, "X spans 2100"), "lcnc98": (9, "X goes to -1100"),
      "lcnc": (9, "X goes to -1100")}),
    # the brief's increment: the body leaves the tool at G57 work 1000 (machine 700), the G91
    # X700 takes it to work 1700, machine 1400: by the span, as before, and where the caller's
    # moves after the body are judged, at the caller's X700 too (after a FANUC's or Haas's M98
    # of a later O program since calls82, the call's start the position the selection
    # re-expressed: 1000 + 700 = 1700 under G57 X -300)
    ("G54 / G0 X-650. / G57 / CALL / G91 / G0 X700.", "G0 X1000.", [-650.0, 700.0, 1400.0],
     {"fanuc": [(11, "X spans 1650"), (8, "X goes to 1400")],
      "haas": [(11, "X spans 1650"), (8, "X goes to 1400")],
      "haas97": [(10, "X spans 1650"), (8, "X goes to 1400")],
      "lcnc98": [(10, "X spans 1650"), (7, "X goes to 1400")],
      "lcnc": [(10, "X spans 1650"), (7, "X goes to 1400")]}),
    # the body writes G57's X (G10 L2 P4 X0: G57 X 0), so the main's G57 X800 runs at machine
    # 800: the span set aside joins the one in hand again at the G10, and X-740 makes it 1540
    ("G54 / CALL / G57 / G0 X800.", "G10 L2 P4 X0. / G0 X-740.", [-740.0, 800.0],
     {"fanuc": (None, ""), "haas": (None, ""), "haas97": (9, "X spans 1540"),
      "lcnc98": (9, "X spans 1540"), "lcnc": (9, "X spans 1540")}),
    # the body's own X-800 under G54: machine -800
    ("G54 / CALL / G57 / G0 X800.", "G0 X-800.", [-800.0, 500.0],
     {"fanuc": (9, "X goes to -800"), "haas": (9, "X goes to -800"),
      "haas97": (8, "X goes to -800"),
      "lcnc98": (8, "X goes to -800"), "lcnc": (8, "X goes to -800")}),
    # the main's X1100 under G57: machine 800
    ("G54 / CALL / G57 / G0 X1100.", "G0 X-740.", [-740.0, 800.0],
     {"fanuc": (None, ""), "haas": (None, ""), "haas97": (6, "X goes to 800"),
      "lcnc98": (5, "X goes to 800"), "lcnc": (5, "X goes to 800")}),
    # the main's X-740 under G57: machine -1040
    ("G54 / CALL / G57 / G0 X-740. / G0 X800.", "G0 X0.", [0.0, -1040.0, 500.0],
     {"fanuc": (None, ""), "haas": (None, ""), "haas97": (6, "X goes to -1040"),
      "lcnc98": (5, "X goes to -1040"), "lcnc": (5, "X goes to -1040")}),
]


@pytest.mark.parametrize("main, body, machine, said", BEYOND)
@pytest.mark.parametrize("form", FORMS)
def test_a_real_overtravel_across_a_selection_stays_refused(
        request: pytest.FixtureRequest, tmp_path: Path, form: str, main: str, body: str,
        machine: list[float],
        said: dict[str, tuple[int | None, str] | list[tuple[int, str]]]) -> None:
    want = said[form]
    wanted = want if isinstance(want, list) else [want]
    line = wanted[0][0]
    found = errors(tmp_path, form, main, body)
    if line is None:
        # A known gap, held as one (strict: a fix of it fails here until the case is given its
        # line): after a FANUC's or Haas's M98 of an O program written later, the caller's
        # moves after a selection are not compared with the travel until its own G90/G91
        # (TG140), so this real overtravel is not said, as on main.
        request.applymarker(pytest.mark.xfail(
            strict=True, reason="the caller's moves after an M98 of a later O program and a "
                                "selection are not judged (TG140)"))
        assert found, "a real overtravel is not said"
    else:
        assert len(found) == len(wanted), found
        assert [(n, m[:len(start)])
                for (n, m), (_, start) in zip(found, wanted, strict=True)] == wanted, found
    if form.startswith("lcnc"):
        assert machine_moves(tmp_path, program(form, main, body)) == machine


# (body, rs274's machine X of the main program's G57 X800 after the call, or None where rs274
# does not run it): a body that does more than move (G0-G3 by numbers) may change where the
# main program's positions after the call run, so the span set aside at its start joins the
# one in hand again at that block, fit or not, and is said there (review 80-sel80 R5-R12)
CHANGED = [
    # G57's X written after the move (G10 L2 P4 X0: machine 800 + 0)
    ("G0 X-740. / G10 L2 P4 X0.", 800.0),
    # ... by its parameter (#5281 = G57's X: 0)
    ("G0 X-740. / #5281=0.", 800.0),
    # ... by a G10 whose P is a parameter
    ("G0 X-740. / #1=4 / G10 L2 P#1 X0.", 800.0),
    # G10 L20 P4 X-1100. at machine -740: G57's X becomes -740 + 1100 = 360, so 800 + 360
    ("G0 X-740. / G10 L20 P4 X-1100.", 1160.0),
    # a G52 local shift of 400 left on: 800 - 300 + 400
    ("G0 X-740. / G52 X400.", 900.0),
    # G92 X-1100. at machine -740 (work -740): a shift of 360: 800 - 300 + 360
    ("G0 X-740. / G92 X-1100.", 860.0),
    # G20 left in force: the main's X800 is 800 in (rs274 prints inches), far beyond
    ("G0 X-740. / G20", None),
]


@pytest.mark.parametrize("body, machine", CHANGED)
@pytest.mark.parametrize("form", ["haas97", "lcnc98", "lcnc"])
def test_a_body_that_may_change_the_mains_positions_joins_the_span(
        tmp_path: Path, form: str, body: str, machine: float | None) -> None:
    main = "G54 / CALL / G57 / G0 X800."
    found = errors(tmp_path, form, main, body)
    # (said at the body's second block, line 9: the span of -740 and 800, as main said it)
    assert [(n, m[:12]) for n, m in found] == [(9, "X spans 1540")], found
    if form.startswith("lcnc") and machine is not None:
        assert machine_moves(tmp_path, program(form, main, body))[-1] == pytest.approx(machine)


def test_a_body_calling_a_program_not_in_the_file_joins_the_span(tmp_path: Path) -> None:
    # (O9999 is not in the file: it may write any offset or shift; kept as main, the span of
    # -740 and 800 said at the call's line 9)
    for form in ("haas97", "lcnc98"):
        found = errors(tmp_path, form, "G54 / CALL / G57 / G0 X800.", "G0 X-740. / M98 P9999")
        assert [(n, m[:12]) for n, m in found] == [(9, "X spans 1540")], (form, found)


def test_a_haas_return_to_a_sequence_number_joins_the_span(tmp_path: Path) -> None:
    # `M99 P20` returns to the caller's N20 (Haas Mill Operator's Manual, M99): past the main
    # program's G57, so its X800 runs under G54 at machine 800, beyond; said at line 9
    found = errors(tmp_path, "haas97", "G54 / CALL / G57 / N20 G0 X800.", "G0 X-740. / M99 P20")
    assert [(n, m[:12]) for n, m in found] == [(9, "X spans 1540")], found


def inline(form: str, main: str) -> str:
    """`main` (blocks split at ` / `) as a program of its own, ended by M30 (M2 for LinuxCNC)."""
    head = ["G21 G17 G90"] if form == "lcnc" else ["O1000", "G21 G17 G90"]
    end = "M2" if form == "lcnc" else "M30"
    return "\n".join([*head, *main.split(" / "), end]) + "\n"


# (the program's blocks, rs274's machine X of each move, the error said: (line in the LinuxCNC
# form, start of the message), a line one more in the FANUC's and Haas's for their O1000; or
# None): a selection re-expresses the position held in the new system, new work = old work +
# old offset - new offset, so an increment after it runs from the machine position the tool
# kept (review 80-sel80 R2)
INLINE = [
    # machine -700 kept across G57 (work -400), +100: machine -600, inside; was "X goes to
    # -900" (work -600 + G57 offset -300)
    ("G54 / G0 X-700. / G57 / G91 G0 X100. / G90", [-700.0, -600.0], None),
    # its twin: machine 700 kept (G57 work 1000), +100: machine 800, beyond; was not said
    # (work 800 + -300 = 500)
    ("G54 / G0 X700. / G57 / G91 G0 X100. / G90", [700.0, 800.0], (5, "X goes to 800")),
    # the selection and the increment in one block: the selection first, then the move
    ("G54 / G0 X700. / G57 G91 G0 X100. / G90", [700.0, 800.0], (4, "X goes to 800")),
    # under G91 at the selection
    ("G54 / G0 X700. / G91 / G57 / G0 X100. / G90", [700.0, 800.0], (6, "X goes to 800")),
    # from G57 to G54: machine -700 (G57 work -400) kept, G54 work -700, -100: machine -800
    ("G57 / G0 X-400. / G54 / G91 G0 X-100. / G90", [-700.0, -800.0], (5, "X goes to -800")),
    # ... machine 700 kept, -100: 600, inside; was "X goes to 900" (work 900 + G54's 0)
    ("G57 / G0 X1000. / G54 / G91 G0 X-100. / G90", [700.0, 600.0], None),
    # then an absolute move under G57 (1000 - 300 = 700): -700, -600, 700 all inside, no span
    # of the two systems' work positions (-700 to 1000 would be 1700)
    ("G54 / G0 X-700. / G57 / G91 G0 X100. / G90 G0 X1000.", [-700.0, -600.0, 700.0], None),
    # a G10 of G57's X with a value known (-500): the value written, not the profile's:
    # machine -700 is G57 work -200, +100: machine -600, inside; was "X goes to -1100"
    ("G54 / G0 X-700. / G10 L2 P4 X-500. / G57 / G91 G0 X100. / G90", [-700.0, -600.0],
     None),
    # ... from machine 700: G57 work 1200, +100: machine 800, beyond; was not said
    ("G54 / G0 X700. / G10 L2 P4 X-500. / G57 / G91 G0 X100. / G90", [700.0, 800.0],
     (6, "X goes to 800")),
    # G58, not in the profile (rs274's var file: 0), then G57: the machine position is not
    # re-expressed from a value not known; the span of -700, 800 and the increment's 30 (the
    # machine's span whatever G58's offset) is said, as main said it
    ("G58 / G0 X-700. / G0 X800. / G57 / G91 G0 X30. / G90", [-700.0, 800.0, 830.0],
     (6, "X spans 1530")),
    # re-expressed into G57 (work -400), then G58, not in the profile, then G54: the position
    # held is G57's through G58 (a selection moves no axis: machine -700 throughout), so G54
    # re-expresses it from G57, -400 + -300 - 0 = -700; -100 from there is -800, beyond; was
    # silent (G57's -400 taken for G54's work value from G58, which re-expresses nothing: -500)
    ("G54 / G0 X-700. / G57 / G58 / G54 / G91 G0 X-100. / G90", [-700.0, -800.0],
     (7, "X goes to -800")),
    # its twin from 700 (G57 work 1000): +100 is 800, beyond; was "X goes to 1100"
    ("G54 / G0 X700. / G57 / G58 / G54 / G91 G0 X100. / G90", [700.0, 800.0],
     (7, "X goes to 800")),
    # ... from -600: -700, inside
    ("G54 / G0 X-600. / G57 / G58 / G54 / G91 G0 X-100. / G90", [-600.0, -700.0], None),
    # back to G57 itself: its work value 1000 kept (machine 700), +100 is 800, beyond (review
    # 82-sel82 R1: taking the re-expression back at G58 made it G54's 700, machine 400)
    ("G54 / G0 X700. / G57 / G58 / G57 / G91 G0 X100. / G90", [700.0, 800.0],
     (7, "X goes to 800")),
    # ... from -700 (G57 work -400): -100 is -800, beyond
    ("G54 / G0 X-700. / G57 / G58 / G57 / G91 G0 X-100. / G90", [-700.0, -800.0],
     (7, "X goes to -800")),
    # ... +100 from -700: -600, inside
    ("G54 / G0 X-700. / G57 / G58 / G57 / G91 G0 X100. / G90", [-700.0, -600.0], None),
]


@pytest.mark.parametrize("main, machine, said", INLINE)
@pytest.mark.parametrize("form", ["fanuc", "haas", "lcnc"])
def test_a_selection_re_expresses_the_position_held(
        tmp_path: Path, form: str, main: str, machine: list[float],
        said: tuple[int, str] | None) -> None:
    text = inline(form, main)
    found = [(f.line, f.message) for f in check_text(text, profile(tmp_path, form))
             if f.severity == "error"]
    if said is None:
        assert found == []
    else:
        line = said[0] + (form != "lcnc")
        assert [(n, m[:len(said[1])]) for n, m in found] == [(line, said[1])], found
    if form == "lcnc":
        assert machine_moves(tmp_path, text) == pytest.approx(machine)


# (a loop of two passes of `G57` / `G91 G0 X-50.` / `G90` / `G54` from machine -700: rs274
# runs -750 on the first pass, -800, beyond, on the second, which the checker does not read;
# the selection inside a loop, or after a sequence number a later jump may go back to, is not
# re-expressed, and the first pass's increment is judged from the work value held, as main
# judged it (work -750 + G57 offset -300), which refuses the program; review 81-sel81 R1.
# A FANUC's or Haas's selection after a sequence number is re-expressed (the first pass runs
# at -750), main's judgement of the position kept beside it and said at the block that may
# take the run back to the sequence number, the GOTO: review 81-sel81 R6, review 82-sel82)
LOOPS = {
    "lcnc": ("G21 G17 G90\nG54\nG0 X-700.\n#1=0\no100 while [#1 LT 2]\nG57\nG91 G0 X-50.\n"
             "G90\nG54\n#1=[#1+1]\no100 endwhile\nM2\n", 7),
    "fanuc": ("O1000\nG21 G17 G90\nG54\nG0 X-700.\n#1=0\nN10 G57\nG91 G0 X-50.\nG90\nG54\n"
              "#1=#1+1\nIF [#1 LT 2] GOTO10\nM30\n", 11),
    # the loop, or the sequence number a jump goes back to, after the selection: there the
    # re-expression is taken back (review 81-sel81 R5)
    "lcnc-after": ("G21 G17 G90\nG54\nG0 X-700.\n#1=0\nG57\no100 while [#1 LT 2]\n"
                   "G91 G0 X-50.\nG90\n#1=[#1+1]\no100 endwhile\nM2\n", 7),
    # a round trip G57 / G54 / G57 whose X was placed between (G0 X-700.) while Y stayed
    # held: the undo takes back the last re-expression only (review 81-sel81 R7)
    "lcnc-stale": ("G21 G17 G90\nG57\nG0 X-400. Y0\nG54\nG0 X-700.\nG57\n"
                   "o100 repeat [2]\nG91 G0 X-50.\nG90\no100 endrepeat\nM2\n", 8),
    "fanuc-after": ("O1000\nG21 G17 G90\nG54\nG0 X-700.\n#1=0\nG57\nN20 G91 G0 X-50.\nG90\n"
                    "#1=#1+1\nIF [#1 LT 2] GOTO20\nM30\n", 10),
}


@pytest.mark.parametrize("form", list(LOOPS))
def test_a_selection_a_loop_may_run_again_keeps_the_work_value(
        tmp_path: Path, form: str) -> None:
    text, line = LOOPS[form]
    base = form.split("-")[0]
    found = [(f.line, f.message) for f in check_text(text, profile(tmp_path, base))
             if f.severity == "error"]
    assert [(n, m[:20]) for n, m in found] == [(line, "X goes to -1050 in m")], found
    if base == "lcnc":
        moves = [-700.0, -750.0, -800.0]
        assert machine_moves(tmp_path, text) == pytest.approx(moves[:1] * (form == "lcnc-stale")
                                                              + moves)


@pytest.mark.parametrize("form", ["haas97", "lcnc98", "lcnc"])
def test_a_body_that_turns_the_spindle_on_keeps_the_span_set_aside(
        tmp_path: Path, form: str) -> None:
    # (S and the spindle's and coolant's M3-M5, M7-M9 move no axis and write no offset: the
    # body's X-740 under the call's G54 (machine -740) and the main's G57 X800 (500) are
    # each judged as machine positions, inside; was "X spans 1540"; review 80-sel80 R16)
    main, body = "G54 / CALL / G57 / G0 X800.", "S1000 M3 M8 / G0 X-740. / M5 M9"
    assert errors(tmp_path, form, main, body) == []
    if form.startswith("lcnc"):
        assert machine_moves(tmp_path, program(form, main, body)) == [-740.0, 500.0]


def numbered(main: str) -> str:
    """`main` (blocks split at ` / `) as an O1000 every block of which is numbered, N201 on,
    but those that carry their own N (and a later program's O)."""
    blocks = [b if b[0] in "NO" else f"N{201 + i} {b}"
              for i, b in enumerate(["G21 G17 G90", *main.split(" / ")])]
    return "\n".join(["O1000", *blocks]) + "\n"


# (a FANUC's or Haas's program numbered in every block, as CAM output is: the blocks, the
# error said (its line, counting O1000 as line 1, and the start of its message) or None.
# A sequence number is only a label until a jump to it is read: the selection is
# re-expressed, and main's judgement of a position after a sequence number (the work value
# kept) is said where a block may take the run back to one; review 81-sel81 R6, review
# 82-sel82)
NUMBERED = [
    # machine 700 kept across G57 (work 1000), +100: machine 800, beyond; was not said (main
    # kept the work value 700: 800 + -300 = 500)
    ("G54 / G0 X700. / G57 / G91 G0 X100. / G90 / M30", (6, "X goes to 800 in machine")),
    # from -700: -600, inside; was "X goes to -900" (work -600 + G57 offset -300)
    ("G54 / G0 X-700. / G57 / G91 G0 X100. / G90 / M30", None),
    # a jump back to N10, the selection's block, by M99 P10 in the main program (0i-F: a
    # main's M99 P n goes to its sequence number n): pass 1 machine -700 -> -750 (inside),
    # pass 2 -750 -> -800, beyond, not read; main's "-1050" (work -750 + G57 offset -300) of
    # line 7 is said at the first block that may take the run back, the forward GOTO of line
    # 11 (the M99 P10 after it is not reached when the GOTO is taken)
    ("G54 / G0 X-700. / #100=0 / N10 G57 / G91 G0 X-50. / G90 / G54 / #100=#100+1 / "
     "IF [#100 GE 2] GOTO 99 / M99 P10 / N99 M30",
     (11, "X goes to -1050 in machine coordinates at line 7")),
    # the same return made by a subprogram's M99 P10 (it returns to the caller's N10): said
    # at the call, line 10
    ("G54 / G0 X-700. / #100=0 / N10 G57 / G91 G0 X-50. / G90 / G54 / M98 P2000 / M30 / "
     "O2000 / N1 #100=#100+1 / N2 IF [#100 GE 2] GOTO 4 / N3 M99 P10 / N4 M99",
     (10, "X goes to -1050 in machine coordinates at line 7")),
    # main's "-900" kept after N205 (-600 inside in truth) is dropped at the main program's
    # end: no jump of it runs after M30, and the Haas body after it, which nothing calls, ends
    # with an M99 that takes no run back here (review 82-sel82 R5)
    ("G54 / G0 X-700. / G57 / G91 G0 X100. / G90 / M30 / N100 G0 X0. / M99", None),
    # an M30 the block skip may pass over (`/M30`) is no end: main's "-1050" of line 7 is said
    # at the GOTO after it (review 82-sel82 n29blockdel)
    ("G54 / G0 X-700. / #1=0 / N10 G57 / G91 G0 X-50. / G90 / G54 / #1=#1+1 / /M30 / "
     "IF [#1 LT 2] GOTO10 / M30",
     (12, "X goes to -1050 in machine coordinates at line 7")),
]


@pytest.mark.parametrize("main, said", NUMBERED)
@pytest.mark.parametrize("form", ["fanuc", "haas"])
def test_a_numbered_program_re_expresses_until_a_jump_may_come_back(
        tmp_path: Path, form: str, main: str, said: tuple[int, str] | None) -> None:
    text = numbered(main)
    found = [(f.line, f.message) for f in check_text(text, profile(tmp_path, form))
             if f.severity == "error"]
    if said is None:
        assert found == []
    else:
        assert [(n, m[:len(said[1])]) for n, m in found] == [said], found


def test_a_linuxcnc_n_word_is_no_label(tmp_path: Path) -> None:
    """rs274 jumps to no N word (o-words only): a numbered LinuxCNC program keeps no judgement
    of main's beside the re-expression (review 82-sel82 R6). Machine -700 kept across G57
    (work -400), +100: machine -600, inside; main's work value would say "-900" (work -600 +
    G57 offset -300), and was said at the `o100 if` line."""
    text = ("N1 G21 G17 G90\nN2 G54\nN3 G0 X-700.\nN4 G57\nN5 G91 G0 X100.\nN6 G90\n"
            "o100 if [1 EQ 1]\nN7 G0 Z0\no100 endif\nN8 M2\n")
    found = [(f.line, f.message) for f in check_text(text, profile(tmp_path, "lcnc"))
             if f.severity == "error"]
    assert found == []
    assert machine_moves(tmp_path, text)[:2] == pytest.approx([-700.0, -600.0])
