"""The one send workflow (dnc.workflow) on its own: preparing, the passes and their journal
records, the events, and the pure pieces (how a pass waits, the closing line)."""

from __future__ import annotations

import os
from dataclasses import replace
from pathlib import Path

import pytest

from dnc import workflow
from dnc.journal import Transfer
from dnc.link import open_port
from dnc.session import SendProgress
from formats.errors import TapegateError
from formats.profile import load_profile
from tests.test_dnc_serial import program

pytestmark = pytest.mark.timeout(30)

FANUC = load_profile("fanuc-mill")
LOOP = replace(FANUC.serial, baud=115200, flow="none")  # loop:// has no control to answer


def test_summary_is_exact_and_readable() -> None:
    s = replace(FANUC.serial, baud=9600)  # 7E2: 872.7 chars/s
    p = SendProgress(sent=737, lines=49, elapsed=1.48, paused_time=0.46, pauses=8, waited=0.10)
    assert workflow.summary(p, s) == (
        "sent 737 bytes (49 lines) in 1.48 s: 723 chars/s while sending, 83% of the line's "
        "873 chars/s; waited 0.10 s for the first DC1; paused by the control 8 times for 0.36 s")
    # the link took the last bytes before the wire carried them: never above the line
    quick = SendProgress(sent=876, lines=1, elapsed=1.0)
    assert workflow.summary(quick, s) == (
        "sent 876 bytes (1 line) in 1.00 s: 873 chars/s while sending, the line's full rate; "
        "never paused by the control")


def test_a_pass_after_the_first_waits_for_dc1_and_with_repeat_for_as_long_as_it_takes() -> None:
    s = replace(FANUC.serial, wait_for_dc1=False, xon_timeout=30.0)
    passes = workflow.Passes(xon_timeout=5.0, start_timeout=60.0)
    first = workflow.pass_flow(s, passes, again=False)
    assert (first.wait_for_dc1, first.xon_timeout, first.start_timeout) == (False, 5.0, 60.0)
    again = workflow.pass_flow(s, passes, again=True)
    assert (again.wait_for_dc1, again.xon_timeout) == (True, 5.0)
    production = workflow.pass_flow(s, replace(passes, repeat=True), again=True)
    assert production.xon_timeout == float("inf")


def test_passes_are_journalled_and_reported(tmp_path: Path) -> None:
    src = tmp_path / "p.nc"
    src.write_text(program(5))
    records: list[Transfer] = []
    events: list[workflow.Event] = []
    with workflow.prepare(str(src), FANUC, LOOP, name="p.nc") as prog:
        port = open_port("loop://", LOOP)
        try:
            outcome = workflow.run(port, prog, workflow.Passes(repeat=True, passes=2),
                                   port_name="loop", record=records.append,
                                   on_event=events.append)
        finally:
            port.close()
    assert (outcome.result, outcome.passes) == ("ok", 2)
    assert [(t.port, t.program, t.result) for t in records] == [("loop", "p.nc", "ok")] * 2
    assert all(t.bytes == prog.total and t.sha256 == prog.digest for t in records)
    assert prog.through_end == prog.total - LOOP.trailer  # the bar's 100 %: no trailer
    shown = [(type(e).__name__, e.number) for e in events
             if isinstance(e, workflow.Waiting | workflow.PassDone)]
    assert shown == [("Waiting", 1), ("PassDone", 1), ("Waiting", 2), ("PassDone", 2)]
    assert [e.again for e in events if isinstance(e, workflow.Waiting)] == [False, True]


def test_a_stop_ends_the_pass_and_is_journalled_with_its_word(tmp_path: Path) -> None:
    src = tmp_path / "p.nc"
    src.write_text(program(400))
    records: list[Transfer] = []
    with workflow.prepare(str(src), FANUC, replace(LOOP, baud=1200), name="p.nc") as prog:
        port = open_port("loop://", prog.settings)
        seen: list[int] = []

        def stop() -> str | None:
            return "aborted" if seen and seen[-1] > 50 else None

        def progress(event: workflow.Event) -> None:
            if isinstance(event, workflow.Progress):
                seen.append(event.progress.sent)

        try:
            outcome = workflow.run(port, prog, port_name="loop", record=records.append,
                                   on_event=progress, stop=stop)
        finally:
            port.close()
    assert outcome.result == "aborted" and 50 < outcome.progress.sent < prog.total
    (record,) = records
    assert record.result == "aborted" and record.bytes == outcome.progress.sent
    assert record.errors == [f"aborted at line {outcome.progress.line}"]


def test_prepare_refuses_errors_unless_forced_and_cleans_up_a_conversion(
        tmp_path: Path, sample_program: str) -> None:
    bad = tmp_path / "bad.nc"
    bad.write_text("%\nN1 G01 X10. X20.\n%\n")
    events: list[workflow.Event] = []
    with pytest.raises(workflow.Refused) as refused:
        workflow.prepare(str(bad), FANUC, LOOP, name="bad.nc", on_event=events.append)
    assert refused.value.code == "check-refused"
    assert refused.value.message.startswith("the check found ")  # what `send` prints
    assert events == [workflow.CheckErrors(refused.value.findings, False)]
    with workflow.prepare(str(bad), FANUC, LOOP, name="bad.nc", force=True) as forced:
        assert forced.frame.blocks == 1
    src = tmp_path / "bracket.nc"
    src.write_text(sample_program)
    events.clear()
    with workflow.prepare(str(src), FANUC, LOOP, name="bracket.nc", convert=True,
                          source=load_profile("iso-mill"), on_event=events.append) as prog:
        temporary = prog.temporary
        assert temporary is not None and os.path.exists(temporary)
        assert "G21" in "".join(text for _, text in prog.source())
    assert not os.path.exists(temporary)
    assert isinstance(events[0], workflow.Converted) and events[0].profile == "fanuc-mill"
    with pytest.raises(TapegateError) as info:
        workflow.prepare(str(src), FANUC, LOOP, name="bracket.nc", restart_at="N999")
    assert (info.value.code, info.value.file) == ("restart-no-block", "bracket.nc")


def test_prepare_says_the_warnings_of_what_is_sent_before_anything_goes(tmp_path: Path) -> None:
    """A '(' inside a Fanuc comment read once (TG136) and a mid-block '/' (TG128) do not stop
    a send, but the control may read them otherwise than tapegate did: they come as one
    CheckWarnings event, before the program is framed; other warnings do not."""
    src = tmp_path / "p.nc"
    src.write_text("%\nO1000\nG21 G90 G17\nG0 X0. Y0. Z50. (VNMG 332(1))\n"
                   "G1 X5. F200. /M08\nM30\n%\n")
    events: list[workflow.Event] = []
    with workflow.prepare(str(src), FANUC, LOOP, name="p.nc", on_event=events.append) as prog:
        assert prog.frame.blocks == 5  # sent all the same
    assert len(events) == 1 and isinstance(events[0], workflow.CheckWarnings)
    assert [(f.rule, f.line) for f in events[0].findings] == [("TG136", 4), ("TG128", 5)]
    plain = tmp_path / "plain.nc"
    plain.write_text("%\nO1000\nG21 G90 G17\nG0 X0. Y0. Z50. (VNMG 332-1)\nM30\n%\n")
    events.clear()
    with workflow.prepare(str(plain), FANUC, LOOP, name="plain.nc", on_event=events.append):
        pass
    assert events == []
