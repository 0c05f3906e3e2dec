"""LinuxCNC: what rs274ngc refuses in a body written after the main program's end where a call
of the main program surely runs it (issue 32 item 4, lcnc81; review 78-lcnc78b M4, M15, M18,
A29, A83, A36).

rs274 runs the body's lines one after the other where the main program's ``M98 P300`` (or
``o300 call``) seeks it after the M2 (interp_o_word.cc ``control_back_to``,
``convert_control_functions``), and stops at the first it refuses. Each refusal is TG412 at the
line rs274 names, only where the line surely runs (the main program's first call, no end
before it; every block of the body open known to run from numbers alone, no line before it
that may leave the body). Each program is run in ``rs274 -g`` (where installed) and its message
asserted, so that the checker and the oracle are seen to agree on the same text.
"""

from __future__ import annotations

import pytest

from .conftest import rs274_output
from .test_linuxcnc_later_bodies import errors

HEAD = "G21 G17 G90\nG0 X0 Y0\nM98 P300\nG0 X5\nM2\nO300\nG0 X1\n"


def refusals(text: str) -> list[tuple[int, str]]:
    return [(line, message) for rule, line, message in errors(text) if rule == "TG412"]


# (the body after HEAD's `G0 X1`, the TG412 said: its line and the start of its message, and
# rs274 -g's own message, None where it runs to its end)
REFUSED = [
    # M4: rs274 "Fanuc 'O....' subroutine definition must end with 'M99'" at the return
    ("o300 return\nM99\n", (8, "Fanuc 'O....' subroutine definition must end with 'M99'"),
     "Fanuc 'O....' subroutine definition must end with 'M99'"),
    # ... any label's return, and one in an `if` known true
    ("o5 return\nM99\n", (8, "Fanuc 'O....' subroutine definition must end with 'M99'"),
     "Fanuc 'O....' subroutine definition must end with 'M99'"),
    ("o1 if [2 GT 1]\no300 return\no1 endif\nM99\n",
     (9, "Fanuc 'O....' subroutine definition must end with 'M99'"),
     "Fanuc 'O....' subroutine definition must end with 'M99'"),
    # ... not in an `if` known false (rs274 skips it: X1, X5, the end)
    ("o1 if [0]\no300 return\no1 endif\nM99\n", None, None),
    # M18: a stray `o2 endif`, "8: undefined O-word label: 'o2 endif'"
    ("o2 endif\nM99\n", (8, "undefined O-word label"), "8: undefined O-word label: 'o2 endif'"),
    ("o2 else\nM99\n", (8, "undefined O-word label"), "8: undefined O-word label: 'o2 else'"),
    # A29: an o-word definition inside the FANUC-style program, "'O.... sub' subroutine must
    # be called with 'O.... call'" at it
    ("o400 sub\nG0 X2\no400 endsub\nM99\n",
     (8, "'O.... sub' subroutine must be called with 'O.... call'"),
     "'O.... sub' subroutine must be called with 'O.... call'"),
    # ... and one of the body's own label (review 81-lcnc81 A29): said once, at the `o300
    # sub` where rs274 stops, not again at the `o300 endsub` that closes the program
    ("o300 sub\nG0 X2\no300 endsub\nM99\n",
     (8, "'O.... sub' subroutine must be called with 'O.... call'"),
     "'O.... sub' subroutine must be called with 'O.... call'"),
    # M15: the only M99 in `o1 if [0]`: rs274 runs on to the file's end (X1, then the end),
    # "File ended with no percent sign or program end", said at the last line where nothing
    # but the ends of the body's blocks follows the M99 (an M99 alone on its line still
    # closes the program for the checker's reading: review 81-lcnc81 R2, R4, R6)
    ("o1 if [0]\nM99\no1 endif\n", (10, "File ended with no percent sign or program end"),
     "File ended with no percent sign or program end"),
    # ... nested in a block known to run, blank lines and a comment after: the same
    ("o2 repeat [2]\no1 if [1 EQ 2]\nM99\no1 endif\n\n(end)\no2 endrepeat\n",
     (14, "File ended with no percent sign or program end"),
     "File ended with no percent sign or program end"),
    # ... an `else` whose M99 runs returns (X1, X5, the end), and an M2 after the block ends
    # the run: neither is said
    ("o1 if [0]\nM99\no1 else\nM99\no1 endif\n", None, None),
    ("o1 if [0]\nM99\no1 endif\nM2\n", None, None),
    # ... where the M99 runs (`if [1]`), it returns: X1, X5, the end
    ("o1 if [1]\nM99\no1 endif\n", None, None),
    # ... no M99 at all (review 81-lcnc81 R3: said so, not "each is in a block")
    ("G0 X2\n", (8, "File ended with no percent sign or program end"),
     "File ended with no percent sign or program end"),
]


@pytest.mark.parametrize("body, said, oracle", REFUSED)
def test_a_refusal_in_a_body_the_call_surely_runs(tmp_path, body: str, said, oracle) -> None:
    text = HEAD + body
    found = refusals(text)
    if said is None:
        assert found == []
    else:
        line, start = said
        assert [(n, m[:len(start)]) for n, m in found] == [(line, start)]
    out = rs274_output(tmp_path, text)
    if oracle is None:
        assert "PROGRAM_END" in out
    else:
        assert oracle in out and "PROGRAM_END" not in out


# (a program whose body rs274 would refuse, where the refusal is not sure: silent)
NOT_SURE = [
    # an M2 of the main program in a condition not known before the call (rs274 -g: #5420 is
    # 0, the M2 runs, O300 never does)
    "G21 G17 G90\nG0 X0 Y0\no1 if [#5420 LT 1000]\nM2\no1 endif\nM98 P300\nM2\nO300\n"
    "o300 return\nM99\n",
    # a call before it of a body that may end the program (rs274 -g: it does)
    "o100 sub\no1 if [#5420 LT 1000]\nM2\no1 endif\no100 endsub\nG21 G17 G90\nG0 X0 Y0\n"
    "o100 call\nM98 P300\nM2\nO300\no300 return\nM99\n",
    # the return in an `if` on the position: rs274 -g skips it (#5420 is 0, not above 1)
    f"{HEAD}o1 if [#5420 GT 1]\no300 return\no1 endif\nM99\n",
    # the only M99 in such an `if`: rs274 -g refuses at the end, a machine where X is above 1
    # returns there
    f"{HEAD}o1 if [#5420 GT 1]\nM99\no1 endif\n",
    # the file closed by `%`: rs274 stops there (no refusal)
    f"%\n{HEAD}o1 if [0]\nM99\no1 endif\n%\n",
    # the call under a block delete: rs274 -g (the switch off) refuses at the return, rs274
    # -b -g (on) skips the call and runs to the end; the switch is the operator's, and the
    # call is taken as not run (docs/dialects.md)
    HEAD.replace("M98", "/M98") + "o300 return\nM99\n",
    # a program after the dead M99: rs274 runs on into it and returns at its M99
    f"{HEAD}o1 if [0]\nM99\no1 endif\nO400\nG0 X2\nM99\n",
]


@pytest.mark.parametrize("text", NOT_SURE)
def test_a_refusal_not_sure_is_not_said(text: str) -> None:
    assert refusals(text) == []


def test_an_m98_in_a_later_body_of_a_program_passed_over_is_refused(tmp_path) -> None:
    # review 78-lcnc78b A83: the main program's `o100 call` seeks o100 past O300 without
    # recording it; o100's `M98 P300` seeks from its own line to the file's end: rs274 -g
    # "EOF in file ... seeking o-word: o<300> from line: 9"
    text = ("G21 G17 G90\no100 call\nG0 X5\nM2\nO300\nG0 X1\nM99\no100 sub\nM98 P300\n"
            "o100 endsub\n")
    found = refusals(text)
    assert [(n, m[:26]) for n, m in found] == [(9, "EOF in file seeking o-word")]
    assert "seeking o-word: o<300> from line: 9" in rs274_output(tmp_path, text)
    # the main program's M98 P300 before it finds O300 first, and rs274 keeps its place: the
    # body's call runs it (X1 twice)
    text = text.replace("o100 call\n", "M98 P300\no100 call\n")
    assert refusals(text) == []
    assert "PROGRAM_END" in rs274_output(tmp_path, text)
    # an O300 after the body is found by the body's search
    text = ("G21 G17 G90\no100 call\nG0 X5\nM2\nO300\nG0 X1\nM99\no100 sub\nM98 P300\n"
            "o100 endsub\nO300\nG0 X3\nM99\n")
    assert refusals(text) == []
    assert "PROGRAM_END" in rs274_output(tmp_path, text)


@pytest.mark.parametrize("before, call", [
    # the o-word form (review 81-lcnc81, A83's o-call form): the main program's `o300 call`
    # seeks o300 past `o400 sub` without recording it, and o300's `o400 call` seeks from its
    # own line to the file's end: rs274 -g "EOF in file ... seeking o-word: o<400> from line:
    # 11"
    ("o400 sub\nG0 X3\no400 endsub\n", "o400 call"),
    # ... an `o400 call` of an `O400` passed over, and an `M98 P400` of an `o400 sub`: the
    # same search, the same refusal
    ("O400\nG0 X3\nM99\n", "o400 call"),
    ("o400 sub\nG0 X3\no400 endsub\n", "M98 P400"),
])
def test_a_call_in_a_later_body_of_a_definition_passed_over_is_refused(tmp_path, before,
                                                                        call) -> None:
    text = (f"G21 G17 G90\nG0 X0 Y0\no300 call\nG0 X5\nM2\n{before}o300 sub\nG0 X1\n"
            f"{call}\nG0 X2\no300 endsub\n")
    found = refusals(text)
    assert [(n, m[:26]) for n, m in found] == [(11, "EOF in file seeking o-word")]
    assert f"this {call} runs in a body" in found[0][1]
    assert "seeking o-word: o<400> from line: 11" in rs274_output(tmp_path, text)
    # a definition of the call's form after the body is found by the body's search (X1, X3,
    # X2, X5: the end); a call in a block known not to run is skipped
    form = "O400\nG0 X3\nM99\n" if call.startswith("M98") else "o400 sub\nG0 X3\no400 endsub\n"
    later = f"{text}{form}"
    assert refusals(later) == []
    assert "PROGRAM_END" in rs274_output(tmp_path, later)
    skipped = text.replace(f"{call}\n", f"o1 if [0]\n{call}\no1 endif\n")
    assert refusals(skipped) == []
    assert "PROGRAM_END" in rs274_output(tmp_path, skipped)


def test_a_call_of_a_label_the_file_never_defines_is_no_refusal(tmp_path) -> None:
    # review 78-lcnc78b A36: rs274 -g "EOF in file ... seeking o-word: o<100>", but a machine
    # runs 100.ngc from its SUBROUTINE_PATH (rs274 -i with such a path runs it): what the path
    # is for (LinuxCNC O codes, "Calling Files")
    text = "G21 G17 G90\no100 call\nG0 X5\nM2\n"
    assert refusals(text) == []
    assert "seeking o-word: o<100>" in rs274_output(tmp_path, text)


def test_the_lines_after_the_end_name_no_body_where_no_call_seeks_one(tmp_path) -> None:
    # review 81-lcnc81 (R4-80's text): where the main program makes no call, no body after its
    # end runs, and TG117 says the lines after it are never read without naming one
    from postproc.check import check_text

    from .test_linuxcnc_later_bodies import profile

    text = "G21 G17 G90\nG0 X1.\nM30\nG0 X2.\n%\n"
    said = [f for f in check_text(text, profile()) if f.rule == "TG117"]
    assert [f.line for f in said] == [4]
    assert said[0].message.startswith(
        "line 4 and the lines after it that are not O-word lines are never read: LinuxCNC "
        "stops at the M2/M30 on line 3")
    assert "but for the body" not in said[0].message
    assert "STRAIGHT_TRAVERSE(2.0000" not in rs274_output(tmp_path, text)


def test_a_later_program_called_by_a_parameter_is_named_by_its_number(tmp_path) -> None:
    # review 80-lcnc80 R9: `M98 P#1` with #1 = 300 runs O300 under the call's G55 (X -100):
    # rs274 -g with G55 X -100 runs X-700 at machine -800; TG601 named the body "O#1"
    text = "G21 G17 G90 G55\nG0 X0 Y0\n#1=300\nM98 P#1\nM2\nO300\nG0 X-700\nM99\n"
    found = [(line, message) for rule, line, message in errors(text) if rule == "TG601"]
    assert len(found) == 1 and found[0][0] == 7
    assert "(O300 runs as called by M98 P#1 of line 4" in found[0][1]


def test_the_lines_after_an_o_programs_m99_leave_a_later_program_out(tmp_path) -> None:
    # review 80-lcnc80 R4: TG117 at the stray line after O2000's M99 no longer says that
    # O3000's body, which M98 P3000 runs (rs274 -g: X1, then X-700), is never read
    text = ("G21 G17 G90\nG0 X0 Y0\nM98 P2000\nM98 P3000\nM2\nO2000\nG0 X1.\nM99\nG0 X2.\n"
            "O3000\nG0 X-7.\nM99\n")
    from postproc.check import check_text

    from .test_linuxcnc_later_bodies import profile

    said = [f for f in check_text(text, profile()) if f.rule == "TG117"]
    assert [f.line for f in said] == [9]
    assert "but for the body of an o<name> sub definition or an O number program" in \
        said[0].message
    out = rs274_output(tmp_path, text)
    assert "STRAIGHT_TRAVERSE(-7.0000" in out and "STRAIGHT_TRAVERSE(2.0000" not in out


def g57_profile():
    from formats.profile import builtin_text, profile_from_text

    toml = builtin_text("linuxcnc").replace("[limits]\n",
                                            "[limits]\nX = [-762, 762]\nY = [-406, 406]\n")
    return profile_from_text(toml + "\n[work_offsets]\nG54 = { X = 0.0, Y = 0.0 }\n"
                             "G57 = { X = -300.0, Y = 0.0 }\n")


def g57_overtravels(text: str) -> list[tuple[int, str]]:
    """The TG601 findings (line, message) of `text` on :func:`g57_profile`."""
    from postproc.check import check_text

    return [(f.line, f.message) for f in check_text(text, g57_profile()) if f.rule == "TG601"]


@pytest.mark.parametrize("opened, body, after, said", [
    # review 80-lcnc80 R8: the call inside `o1 if [1]` or an `if` not known, as outside a
    # block (review 78-lcnc78b F7): machine -650 under G54, then 1000 - 300 = 700 under G57,
    # each inside; was "X spans 1650"
    ("o1 if [1]", "G0 X1000.", "", []),
    ("o1 if [#5420 LT 1]", "G0 X1000.", "", []),
    # ... a body beyond under G57 is said as a machine position (1100 - 300 = 800)
    ("o1 if [1]", "G0 X1100.", "", [(9, "X goes to 800 in machine coordinates")]),
    # ... a move of the main program after the block, whose offsets the call lost, joins
    # the span as after a call outside a block (review 79-lcnc79 F2: X1100 with -650, "X
    # spans 1750", kept)
    ("o1 if [1]", "G0 X0", "G0 X1100.\n", [(7, "X spans 1750")]),
])
def test_a_call_in_a_block_keeps_the_spans_set_aside_at_a_selection(opened, body, after,
                                                                     said) -> None:
    text = (f"G21 G17 G90 G54\nG0 X-650.\nG57\n{opened}\nM98 P2000\no1 endif\n{after}M2\n"
            f"O2000\n{body}\nM99\n")
    found = g57_overtravels(text)
    assert len(found) == len(said)
    assert [(line, message[:len(start)]) for (line, message), (_, start)
            in zip(found, said, strict=True)] == said


@pytest.mark.parametrize("block", [
    # the selection inside an `if` known false (#1 is 1): rs274 runs X800 under G54, machine
    # 800, beyond 762; was silent where the `if` line after the call kept the spans set aside
    # (the lead's merge of stop 81)
    "o10 if [#1 NE 1]\nG57\no10 endif\n",
    # ... and inside the `else` of an `if` known true: the same machine 800
    "o10 if [#1 EQ 1]\nG0 Y1.\no10 else\nG57\no10 endif\n",
])
def test_a_selection_in_a_block_after_a_later_call_that_does_not_run(tmp_path, block) -> None:
    text = (f"G21 G17 G90\nG54\n#1=1\nM98 P2000\n{block}G0 X800.\nM30\nO2000\nG0 X-740.\n"
            "M99\n")
    found = g57_overtravels(text)
    assert [message[:len("X spans 1540")] for _, message in found] == ["X spans 1540"], found
    out = rs274_output(tmp_path, text)
    assert "STRAIGHT_TRAVERSE(800.0000" in out and "PROGRAM_END" in out, out
    assert "SET_G5X_OFFSET(4" not in out, out


def test_a_named_label_of_digits_is_the_numbered_one(tmp_path) -> None:
    # rs274 names a numbered label by its value (`%d`): `o<300> sub` answers `o300 call`
    # (rs274 -g with G55 X -100: X-700 at machine -800) and refuses `M98 P300` ("'O.... sub'
    # subroutine must be called with 'O.... call'"); `o<0300>` is another name
    body = "M2\no<300> sub\nG0 X-700.\no<300> endsub\n"
    text = f"G21 G17 G90 G55\nG0 X0 Y0\no300 call\n{body}"
    assert [(r, n) for r, n, _ in errors(text)] == [("TG601", 6)]
    assert "STRAIGHT_TRAVERSE(-700.0000" in rs274_output(tmp_path, text)
    text = f"G21 G17 G90 G55\nG0 X0 Y0\nM98 P300\n{body}"
    assert refusals(text)[0][0] == 5
    assert "'O.... sub' subroutine must be called with 'O.... call'" in rs274_output(tmp_path,
                                                                                   text)
    # the body and its call named as written in the text (review 81-lcnc81 R5), after and
    # before the call
    text = f"G21 G17 G90 G55\nG0 X0 Y0\no<300> call\n{body}"
    assert "(o<300> runs as called by o<300> call of line 3" in errors(text)[0][2]
    text = ("o<300> sub\nG0 X-700.\no<300> endsub\nG21 G17 G90 G55\nG0 X0 Y0\no<300> call\n"
            "M2\n")
    assert "(o<300> runs as called by o<300> call of line 6" in errors(text)[0][2]
    assert "STRAIGHT_TRAVERSE(-700.0000" in rs274_output(tmp_path, text)
    text = f"G21 G17 G90 G55\nG0 X0 Y0\no300 call\n{body.replace('<300>', '<0300>')}"
    assert errors(text) == []
    assert "seeking o-word: o<300>" in rs274_output(tmp_path, text)


@pytest.mark.parametrize("o300", [
    "o1 if [1]\nM99\no1 endif\n",
    "o1 if [#5420 GT 0]\nG0 X1.\nM99\no1 else\nG0 X2.\nM99\no1 endif\n",
])
def test_an_o_program_after_one_whose_m99s_are_in_blocks_is_its_own(tmp_path, o300) -> None:
    # review 81-lcnc81 R2: O300's M99s are all in its blocks, and the O400 line after it
    # starts the program that M98 P400 runs first (rs274 -g with G55 X -100: X-700 at
    # machine -800); the O400 line was read inside O300 and its body never judged
    text = (f"G21 G17 G90 G55\nG0 X0 Y0\nM98 P400\nM98 P300\nM2\nO300\n{o300}O400\n"
            "G0 X-700.\nM99\n")
    line = text.count("\n") - 1
    assert [(r, n) for r, n, _ in errors(text)] == [("TG601", line)]
