"""Whether LinuxCNC runs an o-word block's lines, and which o-word lines it reads as o-words
(review 49a, F2, F3, F4, F8; review 48, c19). Each program is asserted against ``rs274 -g``
(LinuxCNC's interpreter, the independent oracle) where it is installed, and tapegate's check
against what rs274 does, by rule, line and column:

- F2: a condition of comparisons and logical operators known here decides whether the block
  runs (interp_execute.cc ``execute_binary2``, interp_internal.cc ``precedence``); a repeat's
  count is rounded half to even (``nearbyint``); two values closer than the versions'
  tolerances leave it not known.
- F3: a label written through a parameter (``o#1 if``) is the label of its value.
- F4: a setting the block skip deletes (``/#1=4``) may run or not, as the machine's switch is.
- F8: an o-word only at the start of its line; a closing word of a label no line named.
- c19: a subroutine whose body ends the program ends it at the call.
"""

from __future__ import annotations

import pytest

from formats.profile import builtin_text, profile_from_text
from postproc.check import check_text
from postproc.rules import rule_id

from .conftest import rs274_output

REFUSES = rule_id("LinuxCncRefuses")
NOT_FOLLOWED = rule_id("NotFollowed")
PROFILE = profile_from_text(builtin_text("linuxcnc"))


def errors(text: str) -> list[tuple[str, int, int]]:
    return [(f.rule, f.line, f.column) for f in check_text(text, PROFILE)
            if f.severity == "error"]


def found(text: str) -> list[tuple[str, int, int, str, str]]:
    return [(f.rule, f.line, f.column, f.severity, f.message)
            for f in check_text(text, PROFILE)]


# the block's own line sets the parameter its closing label reads: rs274 refuses the closing
# line (6) where the block's lines ran, and closes the block where they did not
CHANGED = "G21\n#1=2\n#2=3\no#2 if {condition}\n#2=4\no#2 endif\nM2\n"
UNDEFINED = "6: undefined O-word label: 'o#2 endif'"


@pytest.mark.parametrize("condition", [
    "[#1 LT 3]", "[#1 EQ 2]", "[#1 GE 2]", "[#1 le 2]", "[[#1 LT 3] AND [#1 GT 1]]",
    "[#1 LT 3 OR #1 GT 2]", "[#1 GT 3 XOR #1 EQ 2]", "[#1 LT 3 EQ 1]", "[0 AND 1 OR 1]",
    "[#1*2 GT 3]", "[-#1 LT 0]", "[#1 NE 2.5]",
])
def test_a_condition_known_true_runs_its_block(tmp_path, condition):
    text = CHANGED.format(condition=condition)
    assert errors(text) == [(REFUSES, 6, 1)]
    assert UNDEFINED in rs274_output(tmp_path, text)


@pytest.mark.parametrize("condition", [
    "[#1 GT 3]", "[#1 NE 2]", "[#1 LE 1.9]", "[#1 LT 3 AND #1 GT 2]", "[#1 LT 3 EQ 0]",
    "[1 OR 1 AND 0]", "[2 LT 3 LT 1]",
])
def test_a_condition_known_false_skips_its_block(tmp_path, condition):
    text = CHANGED.format(condition=condition)
    assert errors(text) == []
    assert [(r, ln) for r, ln, _, _, m in found(text) if "undefined O-word" in m] == []
    out = rs274_output(tmp_path, text)
    assert "undefined O-word label" not in out and "error" not in out.lower(), out


@pytest.mark.parametrize("condition", [
    # 0.00005 apart: equal to LinuxCNC 2.9 (0.0001), not to later versions (1e-6)
    "[#1 EQ 2.00005]", "[#1 GE 2.0000005]",
    # a function, MOD, a comparison inside a sum, a parameter the checker does not know
    "[abs[-2] EQ #1]", "[#1 MOD 2 EQ 0]", "[1 + [#1 LT 3]]", "[#1 EQ 2 AND #3 EQ 0]",
])
def test_a_condition_not_known_is_said_not_refused(condition):
    text = CHANGED.format(condition=condition)
    assert errors(text) == []
    assert [(r, ln, col) for r, ln, col, _, m in found(text)
            if r == NOT_FOLLOWED and ln == 6] == [(NOT_FOLLOWED, 6, 1)]


@pytest.mark.parametrize("count, runs", [("0.5", False), ("1.5", True), ("2.5", True),
                                         ("0.49", False), ("0.51", True)])
def test_a_repeat_count_is_rounded_half_to_even(tmp_path, count, runs):
    text = f"G21\n#2=3\no#2 repeat [{count}]\n#2=4\no#2 endrepeat\nM2\n"
    assert errors(text) == ([(REFUSES, 5, 1)] if runs else [])
    out = rs274_output(tmp_path, text)
    assert ("5: undefined O-word label: 'o#2 endrepeat'" in out) is runs, out


@pytest.mark.parametrize("close, refused", [("o5 endif", False), ("o#1 endif", False),
                                            ("o6 endif", True)])
def test_a_label_written_through_a_parameter_is_its_value_s(tmp_path, close, refused):
    # F3: rs274 reads `o#1 if` as the label of #1's value; the line after the block runs
    text = f"G21\n#1=5\no#1 if [1]\nG0 X1\n{close}\nG0 X#<nope>\nM2\n"
    out = rs274_output(tmp_path, text)
    if refused:
        assert errors(text) == [(REFUSES, 5, 1)]
        assert f"5: undefined O-word label: '{close}'" in out, out
    else:
        assert errors(text) == [(REFUSES, 6, 4)]
        assert "Named parameter #<nope> not defined" in out, out


@pytest.mark.parametrize("text, skipped", [
    ("G21\n#1=5\no#1 if [0]\nG0 X1\no6 endif\nM2\n", True),
    ("G21\no5 repeat [0]\nG0 X1\nM2\n", True),
    ("G21\no5 while [#1 GT 1]\nG0 X1\no6 endwhile\nM2\n", False),
    ("G21\no5 if [0]\nG0 X1\no5 else\nG0 X2\no5 endif\nM2\n", False),
    ("G21\no5 while [0]\nG0 X1\no6 endwhile\no5 endwhile\nM2\n", False),
])
def test_a_block_not_run_skips_to_its_label(tmp_path, text, skipped):
    # F3: rs274 reads only o-word lines while it skips, to one of the block's label; a file
    # without one ends in the skip (#1 is 0 to rs274, not known to the checker: no claim)
    last = text.count("\n")
    assert errors(text) == ([(rule_id("NoProgramEnd"), last, 1)] if skipped else [])
    out = rs274_output(tmp_path, text)
    assert ("File ended with no percent sign or program end" in out) is (
        skipped or "#1" in text), out


def test_a_setting_the_block_skip_deletes_is_not_known(tmp_path):
    # F4: rs274 -g runs /#1=4 (the switch off) and refuses the endif of label 4; with the
    # switch on (-b) it closes o3; tapegate knows no machine's switch: said, not refused
    text = "G21\n#1=3\no#1 if [1]\n/#1=4\no#1 endif\nM2\n"
    assert errors(text) == []
    # (the note of the label, not the file's first unfollowed line: `o#1 if [1]` is known to
    # run, no jump, so that note stands at the endif too)
    notes = [(ln, col) for r, ln, col, _, m in found(text)
             if r == NOT_FOLLOWED and ln == 5 and "worked out as the line runs" in m]
    assert notes == [(5, 1)]
    assert "5: undefined O-word label: 'o#1 endif'" in rs274_output(tmp_path, text)
    out = rs274_output(tmp_path, text, ("-b",))
    assert "undefined O-word label" not in out, out


@pytest.mark.parametrize("setting", ["/#1=0", "/#1=1"])
def test_a_divisor_a_deleted_setting_gives_is_not_known(tmp_path, setting):
    old = "1" if setting.endswith("0") else "0"
    text = f"G21\n#1={old}\n{setting}\nG0 X[1/#1]\nM2\n"
    assert errors(text) == []
    off = "Attempt to divide by zero" in rs274_output(tmp_path, text)
    on = "Attempt to divide by zero" in rs274_output(tmp_path, text, ("-b",))
    assert off != on


@pytest.mark.parametrize("line, column, said", [
    ("(c) o5 if [1]", 5, "Bad character 'o' used (rs274ngc)"),
    ("G0 X1 o5 if [1]", 7, "Bad character 'o' used (rs274ngc)"),
    ("#1=1 o5 if [1]", 6, "Bad character 'o' used (rs274ngc)"),
    ("o5 if [1] G0 X1", 11, "Unexpected character after O-word (rs274ngc)"),
])
def test_an_o_word_stands_alone_at_the_start_of_its_line(tmp_path, line, column, said):
    # F8: rs274 reads an o-word only after a block delete and a line number (read_items)
    text = f"G21\n{line}\nG0 X1\no5 endif\nM2\n"
    first = [(r, ln, col, m) for r, ln, col, sev, m in found(text) if sev == "error"][0]
    assert first[:3] == (REFUSES, 2, column)
    assert first[3].startswith(said), first
    assert said.removesuffix(" (rs274ngc)") in rs274_output(tmp_path, text)


@pytest.mark.parametrize("text", [
    "G21\nN10 o5 if [1]\nG0 X1\no5 endif\nM2\n",
    "G21\no5 if [1] (a comment)\nG0 X1\no5 endif\nM2\n",
    "G21\no1 if [0]\n(c) o5 if [1]\no1 endif\nM2\n",
    "G21\no2 if [1]\no2 endif\no2 endif\nM2\n",
])
def test_o_words_rs274_reads_or_passes_over(tmp_path, text):
    assert errors(text) == []
    out = rs274_output(tmp_path, text)
    assert "rror" not in out and "used" not in out and "undefined" not in out, out


def test_an_endif_with_no_if_is_an_undefined_label(tmp_path):
    text = "G21\no2 endif\nG0 X1\nM2\n"
    first = [(r, ln, col, m) for r, ln, col, sev, m in found(text) if sev == "error"]
    assert [f[:3] for f in first] == [(REFUSES, 2, 1)]
    assert "\"2: undefined O-word label: 'o2 endif'\"" in first[0][3]
    assert "2: undefined O-word label: 'o2 endif'" in rs274_output(tmp_path, text)


@pytest.mark.parametrize("body, judged", [
    ("G0 X1\nM2", False),
    ("G0 X1\nM30", False),
    ("o1 if [#2 EQ 0]\nM2\no1 endif", True),
    ("/M2", True),
])
def test_a_call_of_a_body_that_ends_the_program_ends_it(tmp_path, body, judged):
    # c19: rs274 -g runs the body's M2 and reads no line after the call
    text = f"G21\no<s> sub\n{body}\no<s> endsub\no<s> call\nG0 X#<nope>\nM2\n"
    call = text.split("\n").index("o<s> call") + 1
    assert errors(text) == ([(REFUSES, call + 1, 4)] if judged else [])
    if not judged:
        out = rs274_output(tmp_path, text)
        assert "Named parameter" not in out, out
