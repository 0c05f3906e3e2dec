"""The DNC state machines with a fake clock: no ports, no threads, no waiting."""

from __future__ import annotations

import io
from collections import deque
from dataclasses import replace

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dnc.control import Control, Throttle
from dnc.framing import Framer, split_lines
from dnc.link import LinkError, chars_per_second, frame_bits, override
from dnc.receiver import Finished, Receiver, Reply, Text
from dnc.sender import (
    Done,
    Fail,
    FlowSettings,
    Pause,
    Resume,
    Rewind,
    Sender,
    Write,
    bytes_ahead,
    paced_cps,
)
from formats.errors import TapeError
from formats.profile import SerialSettings, load_profile
from formats.tape import EIA_TABLE, decode, encode, iso_byte, parity_bits

ISO = SerialSettings(leader=3, trailer=2, leader_char="nul")
SOFT = replace(ISO, data_bits=8, parity="none", parity_mode="software")
EIA = replace(SOFT, code="eia")


def frames(s: SerialSettings, text: str) -> bytes:
    framer = Framer(s)
    return b"".join(d for _, d in framer.frames(split_lines([text])))


# -- link --------------------------------------------------------------------------------------


def test_wire_time_of_a_character() -> None:
    s = SerialSettings(baud=9600, data_bits=7, parity="even", stop_bits=2)
    assert frame_bits(s) == 11
    assert chars_per_second(s) == pytest.approx(872.7, abs=0.1)
    assert chars_per_second(replace(s, data_bits=8, parity="none", stop_bits=1)) == 960


def test_overrides_switch_the_frame_with_the_parity_mode() -> None:
    s = override(ISO, parity_mode="software")
    assert (s.data_bits, s.parity) == (8, "none")
    assert override(s, parity_mode="uart") == replace(s, parity_mode="uart", data_bits=7,
                                                      parity="even")
    assert override(ISO, code="eia").parity_mode == "software"
    with pytest.raises(LinkError) as info:
        override(ISO, parity_mode="software", data_bits=7)
    assert info.value.code == "link-settings"


# -- framing -----------------------------------------------------------------------------------


def test_iso_uart_frame_is_seven_bit_with_the_profiles_eob() -> None:
    out = frames(replace(ISO, eob="lfcrcr"), "%\nN1 G01\n%\n")
    assert out == b"%\n\r\rN1 G01\n\r\r%"


def test_software_parity_sets_bit_8_per_byte() -> None:
    out = frames(SOFT, "%\nN1 X1\n%\n")
    assert all(parity_bits(b) % 2 == 0 for b in out)
    assert out == bytes(iso_byte(c) for c in "%\nN1 X1\n%")


def test_eia_frame_uses_er_and_eob() -> None:
    out = frames(EIA, "%\nN1 X-1.5\n%\n")
    assert out[0] == 0x0B and out[-1] == 0x0B
    assert out[1] == 0x80
    assert out[2:11] == bytes(EIA_TABLE[c] for c in "N1 X-1.5") + b"\x80"
    assert decode(out, "eia").text == "%\nN1 X-1.5\n%"


def test_tv_check_pads_odd_blocks_only() -> None:
    s = replace(ISO, tv_check=True)
    framer = Framer(s)
    out = b"".join(d for _, d in framer.frames(split_lines(["%\nN1 X1\nN2 X10\n%\n"])))
    assert out == b"%\nN1 X1 \nN2 X10\n%"
    assert framer.stats.padded == 1


def test_missing_percent_signs_are_added_and_trailing_text_reported() -> None:
    framer = Framer(ISO)
    assert b"".join(d for _, d in framer.frames(split_lines(["N1 X1\n"]))) == b"%\nN1 X1\n%"
    assert framer.stats.added_start and framer.stats.added_end
    framer = Framer(ISO)
    list(framer.frames(split_lines(["%\nN1\n%\nN9 junk\n"])))
    assert framer.stats.left_after_end == 1


def test_leader_characters() -> None:
    assert Framer(ISO).leader() == b"\0\0\0"
    assert Framer(replace(SOFT, leader_char="space")).leader() == bytes([iso_byte(" ")]) * 3
    assert Framer(replace(EIA, leader_char="del")).leader() == b"\x7f" * 3
    # blank tape is blank in EIA too (NUL was dropped by the encoder: no leader was sent)
    assert Framer(EIA).leader() == b"\0\0\0"


@pytest.mark.parametrize("s", [ISO, SOFT, EIA], ids=["iso", "software", "eia"])
def test_cr_line_ends_next_to_lf_are_not_sent(s: SerialSettings) -> None:
    """FANUC's punched LF CR CR and CR LF are line ends, as `tape encode` reads them
    (formats.tape.TapeEncoder): CRs next to LF are not sent (no two empty EIA blocks before
    every block, no ISO refusal of 0x0D). Every CR is counted."""
    plain = frames(s, "%\nO1\nG0 X1.\nM30\n%\n")
    for text, by_lf in [("%\n\r\rO1\n\r\rG0 X1.\n\r\rM30\n\r\r%\n", 8),
                        ("%\r\nO1\r\nG0 X1.\r\nM30\r\n%\r\n", 5)]:
        framer = Framer(s)
        assert b"".join(d for _, d in framer.frames(split_lines([text]))) == plain, text
        assert (framer.stats.cr_by_lf, framer.stats.blocks) == (by_lf, 3), text
        if s.code == "eia":  # what the tape encoder writes of the same file, decoded
            assert decode(encode(text, "eia"), "eia").text.rstrip("\n") == decode(
                plain, "eia").text


@pytest.mark.parametrize("s", [ISO, SOFT, EIA], ids=["iso", "software", "eia"])
def test_blanks_after_a_line_ending_cr_are_no_text(s: SerialSettings) -> None:
    """Review 12: `G0 X1.` CR blank LF was refused as "a CR with text on both sides"; only
    blanks follow the CR, so it is the line end's: not sent, with the blanks, and counted."""
    plain = frames(s, "%\nO1\nG0 X1.\nM30\n%\n")
    framer = Framer(s)
    text = "%\nO1\nG0 X1.\r \t\nM30\r\r \n%\n"
    assert b"".join(d for _, d in framer.frames(split_lines([text]))) == plain
    assert framer.stats.cr_by_lf == 3


@pytest.mark.parametrize("s", [ISO, SOFT, EIA], ids=["iso", "software", "eia"])
@pytest.mark.parametrize(("text", "line", "column"), [
    # a CR inside a comment: the check reads one block with a closed comment; ended there,
    # the control would get an open comment, then ') F50.' (review 11, finding 4)
    ("%\nO1\nG1 Z-5. (A B \r) F50.\nM30\n%\n", 3, 14),
    ("%\nO1\nG1 Z-5.\rF50.\nM30\n%\n", 3, 8),
    ("%\r\nO1\r\n\rG1 Z-5.\rF50.\r\nM30\r\n%\r\n", 3, 9),
    # a file whose lines end in CR alone is one line to the check
    ("%\rO1\rG0 X1.\rM30\r%\r", 1, 2),
])
def test_a_cr_inside_a_line_is_refused_where_it_stands(s: SerialSettings, text: str,
                                                       line: int, column: int) -> None:
    """tapegate's check reads a line across a CR with text on both sides as one block (a
    FANUC's end of block is LF, CR-LF or LF-CR-CR); a sender can only drop the CR or end the
    block there, neither the block checked: refused, located, before a byte is framed."""
    with pytest.raises(TapeError) as info:
        frames(s, text)
    assert (info.value.code, info.value.line, info.value.column) == (
        "tape-character", line, column)
    assert "a CR inside the line" in info.value.message


@pytest.mark.parametrize(("s", "text", "column"), [
    (EIA, "%\nN1 X1=2\n%", 6),
    # EIA's ER, written for '%', is the rewind stop: a reader would stop inside the block
    (EIA, "%\nO1000 (FEED 50%)\n%", 15),
    (ISO, "%\nN1 X\u00b52\n%", 5),
    (ISO, "%\nN1 \x13X2\n%", 4),
])
def test_characters_the_code_cannot_carry_are_located(s: SerialSettings, text: str,
                                                       column: int) -> None:
    with pytest.raises(TapeError) as info:
        frames(s, text)
    assert info.value.code == "tape-character"
    assert (info.value.line, info.value.column) == (2, column)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.text(alphabet=st.sampled_from("NX1.( %\t\x01\x13\x7f\u00b5\r"),
                        min_size=1, max_size=12), min_size=1, max_size=8),
       st.sampled_from([ISO, SOFT, replace(ISO, tv_check=True), replace(SOFT, tv_check=True)]))
def test_every_block_is_framed_as_encode_frames_it(blocks: list[str], s: SerialSettings
                                                   ) -> None:
    """The common block (printable ASCII in ISO code) is encoded in frames() itself: the bytes,
    and the error of a character the code cannot carry, are encode()'s."""
    text = "%\n" + "".join(b + "\n" for b in blocks)
    expected: list[bytes] = []
    error: str | None = None
    framer = Framer(s)
    # CRs at a line's ends are not sent (test_cr_line_ends_next_to_lf_are_not_sent); one
    # inside is refused (test_a_cr_inside_a_line_is_refused_where_it_stands)
    cr_at: tuple[int, int] | None = None
    for line, raw in enumerate(blocks, 2):
        block = raw.strip("\r")
        tail = block.rstrip(" \t\r")
        if "\r" in block[len(tail):]:  # CR then only blanks before the LF: the line end's
            block = tail
        if "\r" in block:
            cr_at = (line, len(raw) - len(raw.lstrip("\r")) + block.index("\r") + 1)
            break
        if block.strip() == "%":
            expected.append(framer.encode("%", line))
            break
        if s.tv_check and len(block) % 2:
            block += " "
        try:
            expected.append(framer.encode(block, line) + framer.eob)
        except TapeError as exc:
            error = (exc.code, str(exc))
            break
    try:
        got = [d for _, d in Framer(s).frames(split_lines([text]))][1:]
    except TapeError as exc:
        if error is None and cr_at is not None:
            assert (exc.code, exc.line, exc.column) == ("tape-character", *cr_at)
        else:
            assert (exc.code, str(exc)) == error
    else:
        assert error is None and cr_at is None
        assert got[:len(expected)] == expected


@settings(max_examples=60, deadline=None)
@given(st.lists(st.text(alphabet="NGXYZ0123456789.- ()", max_size=30), max_size=20),
       st.sampled_from([ISO, SOFT, EIA]))
def test_framed_program_decodes_back_exactly(blocks: list[str], s: SerialSettings) -> None:
    text = "%\n" + "".join(b + "\n" for b in blocks) + "%"
    data = frames(s, text + "\n")
    if s.parity_mode == "uart":
        assert data.decode("ascii") == text
    else:
        back = decode(data, s.code)  # type: ignore[arg-type]
        assert back.text == text and not back.issues


# -- sender ------------------------------------------------------------------------------------


def writes(actions: list) -> bytes:
    return b"".join(a.data for a in actions if isinstance(a, Write))


def run(sender: Sender, until: float, step: float, start: float = 0.0) -> bytes:
    """Advance the fake clock, accepting every write; returns what was written."""
    out = bytearray()
    t = start
    while t <= until:
        data = writes(sender.time_passed(t))
        sender.bytes_accepted(len(data), t)
        out += data
        t += step
    return bytes(out)


def test_waits_for_dc1_then_paces_at_wire_speed() -> None:
    flow = FlowSettings(cps=1000.0, ahead=2)
    s = Sender(flow, 0.0)
    s.feed(b"x" * 100)
    s.finish()
    assert s.time_passed(0.5) == []  # no DC1 yet
    actions = s.data_received(b"\x11", 0.5)
    assert isinstance(actions[0], Resume) and writes(actions) == b"xx"
    s.bytes_accepted(2, 0.5)
    sent = run(s, 0.55, 0.0001, start=0.5001)
    # 50 ms at 1000 chars/s: 50 characters on the wire, never more than 2 ahead of it
    assert 50 <= len(sent) + 2 <= 53


def test_dc3_stops_at_once_and_dc1_resumes_repeated_dc1_harmless() -> None:
    s = Sender(FlowSettings(cps=1000.0, ahead=2, wait_for_dc1=False), 0.0)
    s.feed(b"y" * 50)
    s.finish()
    run(s, 0.01, 0.001)
    assert isinstance(s.data_received(b"\x93", 0.0105)[0], Pause)  # DC3 with its parity bit
    assert run(s, 0.5, 0.001, start=0.011) == b""
    assert isinstance(s.data_received(b"\x11", 0.6)[0], Resume)
    assert s.data_received(b"\x11\x11", 0.6) == []  # already sending
    rest = run(s, 1.0, 0.001, start=0.6)
    assert s.sent == 50 and len(rest) > 0


def test_never_more_than_ahead_bytes_in_front_of_the_wire() -> None:
    cps = 11520.0
    s = Sender(FlowSettings(cps=cps, wait_for_dc1=False), 0.0)
    s.feed(b"z" * 2000)
    t, wire = 0.0, 0.0
    while s.sent < 2000:
        data = writes(s.time_passed(t))
        s.bytes_accepted(len(data), t)
        wire = max(wire, t) + len(data) / cps
        assert (wire - t) * cps <= s.ahead + 1e-9
        t += 0.00003
    assert s.ahead == bytes_ahead(cps, 10) == 5


def test_bytes_ahead_depends_on_the_baud() -> None:
    assert bytes_ahead(872.7, 10) == 2  # 9600 7E2
    assert bytes_ahead(3490.9, 10) == 2  # 38400 7E2: a DC3 obeyed within 3 characters
    assert bytes_ahead(11520, 10) == 5  # 115200 8N1: half the Fanuc allowance
    assert bytes_ahead(11520, 4) == 2


def test_the_pace_keeps_a_late_dc3_within_the_allowance() -> None:
    cps = 115200 / 11  # 7E2
    assert paced_cps(cps, 10, 5, 0.004) == 1250  # 5 characters in 4 ms, 5 ahead
    assert paced_cps(cps, 10, 5, 0.0) == cps  # no reaction time given: the wire's pace
    assert paced_cps(9600 / 11, 10, 2, 0.004) == 9600 / 11  # the wire is slower anyway
    assert paced_cps(cps, 4, 5, 0.004) == 250  # never stopped outright
    assert Sender(FlowSettings(cps=cps, reaction=0.004), 0.0).cps == 1250
    for flow in ("rtscts", "none"):  # no DC3 to see late: the wire's pace
        assert Sender(FlowSettings(cps=cps, flow=flow, reaction=0.004), 0.0).cps == cps


def feed_late(reaction: float, late: float, *, share: float = 0.05,
              seconds: float = 1.0) -> Control:
    """A sender at 115200 baud feeding a control with a 128-character buffer that machines at
    ``share`` of the line speed, on a host that sees every DC1 and DC3 ``late`` seconds after
    the control sent it (a fake clock in 50 us steps). Returns the control."""
    cps = 115200 / 11
    control = Control(cps=cps, buffer=128, rate=cps * share, allowance=10, keep_text=False)
    sender = Sender(FlowSettings(cps=cps, reaction=reaction), 0.0)
    sender.feed(b"%\n" + b"X1\n" * 5000)
    sender.finish()
    inbox: deque[tuple[float, bytes]] = deque()  # (when the sender sees it, what)

    def post(data: bytes, now: float) -> None:
        if data:
            inbox.append((now + late, data))

    post(control.time_passed(0.0), 0.0)
    t = 0.0
    while t < seconds:
        actions = []
        while inbox and inbox[0][0] <= t:
            actions += sender.data_received(inbox.popleft()[1], t)
        actions += sender.time_passed(t)
        for action in actions:
            if isinstance(action, Write):
                sender.bytes_accepted(len(action.data), t)
                post(control.data_received(action.data, t), t)
        post(control.time_passed(t), t)
        t += 50e-6
    return control


def test_a_dc3_seen_late_is_overrun_without_the_pace_and_not_with_it() -> None:
    """At 115200 baud the allowance of 10 characters lasts under 1 ms of wire; a host that
    sees the DC3 4 ms late overruns it at the wire's pace, not at the pace for 4 ms."""
    wire = feed_late(0.0, 0.004)
    assert wire.stats.alarms_087 > 0 and wire.stats.most_after_dc3 > 30
    paced = feed_late(0.004, 0.004)
    assert paced.stats.dc3 >= 5  # it throttled all along
    assert paced.stats.alarms_087 == 0 and paced.stats.most_after_dc3 <= 10
    assert feed_late(0.0, 0.0).stats.alarms_087 == 0  # a DC3 seen at once needs no pace


@given(st.floats(0.0, 0.004), st.floats(0.01, 0.9))
@settings(max_examples=20, deadline=None)
def test_no_dc3_seen_within_the_reaction_time_is_overrun(late: float, share: float) -> None:
    control = feed_late(0.004, late, share=share, seconds=0.5)
    assert control.stats.alarms_087 == 0 and control.stats.most_after_dc3 <= 10


def test_xon_timeout_fails_with_a_message() -> None:
    s = Sender(FlowSettings(cps=1000.0, xon_timeout=2.0), 0.0)
    s.feed(b"abc")
    assert s.deadline == 2.0
    fail = s.time_passed(2.0)
    assert isinstance(fail[0], Fail) and "no DC1 to start within 2 s" in fail[0].message
    s = Sender(FlowSettings(cps=1000.0, xon_timeout=1.0, wait_for_dc1=False), 0.0)
    s.feed(b"abc")
    s.data_received(b"\x13", 0.0)
    assert "to resume after DC3" in s.time_passed(1.5)[0].message  # type: ignore[union-attr]


def test_control_alarm_fails_the_transfer() -> None:
    s = Sender(FlowSettings(cps=1000.0, wait_for_dc1=False), 0.0)
    s.feed(b"abc")
    assert "alarm (NAK)" in s.data_received(b"\x15", 0.0)[0].message  # type: ignore[union-attr]
    assert s.data_received(b"\x11", 0.1) == [] and s.state == "failed"


@pytest.mark.parametrize("reset", [b"\x93\x96", b"\x16"])  # with and without its parity bit
def test_a_reset_and_rewind_ends_the_pass_with_rewind(reset: bytes) -> None:
    s = Sender(FlowSettings(cps=1000.0, wait_for_dc1=False), 0.0)
    s.feed(b"%\nX1\n" * 10)
    s.finish()
    run(s, 0.005, 0.001)
    assert s.data_received(reset, 0.006) == [Rewind()]
    assert s.state == "rewound" and s.deadline is None
    assert s.data_received(b"\x11", 0.01) == [] and s.time_passed(0.02) == []  # nothing more


def test_dc3_after_the_program_ends_the_pass_without_trailer() -> None:
    s = Sender(FlowSettings(cps=1000.0, wait_for_dc1=False), 0.0)
    s.feed(b"%\nX1\n%")
    s.mark_end()
    s.feed(b"\0" * 50)
    s.finish()
    run(s, 0.007, 0.001)
    assert s.sent >= 6
    assert s.data_received(b"\x93", 0.008) == [Done()]


def test_partial_writes_are_sent_again() -> None:
    s = Sender(FlowSettings(cps=1000.0, ahead=4, wait_for_dc1=False), 0.0)
    s.feed(b"abcdef")
    s.finish()
    assert writes(s.time_passed(0.0)) == b"abcd"
    s.bytes_accepted(1, 0.0)
    assert writes(s.time_passed(0.01)) == b"bcde"


def test_no_flow_control_waits_the_character_and_line_delays() -> None:
    flow = FlowSettings(cps=1000.0, flow="none", char_delay=0.01, line_delay=0.1)
    s = Sender(flow, 0.0)
    s.feed(b"a\nb")
    s.finish()
    assert writes(s.time_passed(0.0)) == b"a"
    s.bytes_accepted(1, 0.0)
    assert s.time_passed(0.005) == []
    assert writes(s.time_passed(0.011)) == b"\n"
    s.bytes_accepted(1, 0.011)
    assert s.time_passed(0.05) == []  # the line delay
    assert writes(s.time_passed(0.122)) == b"b"


def test_rtscts_uses_the_drivers_queue() -> None:
    s = Sender(FlowSettings(cps=1000.0, flow="rtscts", ahead=2), 0.0)
    s.feed(b"abcdef")
    assert s.time_passed(0.0, queued=5) == []  # CTS low: the driver still holds 5 bytes
    assert writes(s.time_passed(0.0, queued=0)) == b"ab"


# -- receiver ----------------------------------------------------------------------------------


def collect(actions: list) -> tuple[str, list]:
    return "".join(a.text for a in actions if isinstance(a, Text)), actions


def test_receiver_answers_dc2_strips_leader_and_ends_at_dc4() -> None:
    r = Receiver()
    data = b"\x12" + b"\0" * 5 + bytes(iso_byte(c) for c in "%\nO12\nX1\n%") + b"\0\0\x14"
    text, actions = collect(r.data_received(data, 0.0))
    assert actions[0] == Reply(b"\x11")
    assert text == "%\nO12\nX1\n%"
    assert actions[-1] == Finished("closing %")
    assert r.code == "iso" and not r.issues


def test_receiver_detects_eia_and_keeps_the_digit_3() -> None:
    r = Receiver()
    body = "%\nN3 X33\n%"
    data = b"\x12\0\0" + bytes(EIA_TABLE[c] for c in body) + b"\x14"
    text, actions = collect(r.data_received(data, 0.0))
    assert r.code == "eia" and text == body


def test_parity_errors_are_located_and_kept() -> None:
    r = Receiver()
    good = bytes(iso_byte(c) for c in "%\nN1 X12\n%")
    bad = bytearray(good)
    bad[7] ^= 0x80  # the "1" of X12 on line 2
    text, _ = collect(r.data_received(bytes(bad), 0.0))
    assert text == "%\nN1 X12\n%"
    (issue,) = r.issues
    assert (issue.kind, issue.line, issue.column) == ("parity", 2, 6)


def test_uart_parity_marks_are_read() -> None:
    r = Receiver(uart_parity=True, parity_marks=True)
    data = b"%\nN1 X\xff\x002\n%"
    text, _ = collect(r.data_received(data, 0.0))
    assert text == "%\nN1 X2\n%"
    assert [(i.kind, i.line, i.column) for i in r.issues] == [("parity", 2, 5)]


def test_idle_timeout_ends_and_no_data_is_reported() -> None:
    r = Receiver(idle_timeout=1.0)
    collect(r.data_received(b"%\nN1\n", 0.0))
    assert r.time_passed(0.5) == []
    text, actions = collect(r.time_passed(1.0))
    assert actions[-1] == Finished("idle")
    r = Receiver(start_timeout=2.0)
    assert r.time_passed(2.0) == [Finished("no data")]


# -- control -----------------------------------------------------------------------------------


def feed(control: Control, data: bytes, start: float, cps: float) -> bytes:
    """The host writes one byte per wire character time; returns the control's replies."""
    out = bytearray()
    t = start
    for byte in data:
        out += control.data_received(bytes([byte]), t)
        t += 1 / cps
    return bytes(out)


def test_control_throttles_at_its_watermarks() -> None:
    c = Control(cps=1000.0, buffer=64, rate=100.0, allowance=10, sink=io.BytesIO())
    assert c.time_passed(0.0) == b"\x11"
    replies = feed(c, b"%\n" + b"X1\n" * 20, 0.0, 1000.0)
    assert replies == b"\x93"  # DC3 when 54 characters are in the buffer
    assert c.stats.dc3 == 1
    assert c.deadline is not None and c.time_passed(c.deadline + 1e-6) == b"\x11"
    assert c.stats.most_after_dc3 == 2 and c.stats.after_dc3 == {2: 1}  # fed after it


def test_overrun_raises_alarm_087() -> None:
    c = Control(cps=1000.0, buffer=32, rate=1.0, allowance=10)
    feed(c, b"%\n" + b"X12345\n" * 10, 0.0, 1000.0)  # a host that ignores DC3
    assert c.stats.alarms_087 == 1
    assert c.stats.most_after_dc3 > 10
    assert any(e.kind == "087" for e in c.stats.errors)


def test_bytes_ahead_of_the_wire_count_after_dc3() -> None:
    c = Control(cps=1000.0, buffer=32, rate=1.0, allowance=10)
    c.data_received(b"%\n" + b"X" * 40, 0.0)  # a burst: the wire needs 42 ms for it
    assert c.stats.most_after_dc3 > 10 and c.stats.alarms_087 == 1


def throttled(control: Control, cps: float) -> float:
    """Feed a paced program until the control sends DC3; the time it decided to."""
    control.time_passed(0.0)
    t = 0.0
    for byte in b"%\n" + b"X1\n" * 100:
        t += 1 / cps
        if control.data_received(bytes([byte]), t) == b"\x93":
            return t
    raise AssertionError("the control never throttled")


def test_dc3_counts_from_the_moment_it_is_on_the_line() -> None:
    """The emulator decided on DC3 but lost its core for 20 ms before writing it: the 20
    characters the host sent meanwhile are not after the DC3; the 3 after it are."""
    c = Control(cps=1000.0, buffer=32, rate=1.0, allowance=10)
    decided = throttled(c, 1000.0)
    c.sent(decided + 0.0205)
    feed(c, b"Y" * 20, decided + 0.0005, 1000.0)
    assert c.stats.most_after_dc3 == 0
    feed(c, b"Z" * 3, decided + 0.021, 1000.0)
    assert c.stats.most_after_dc3 == 3 and c.stats.alarms_087 == 0
    assert c.time_passed(decided + 60.0) == b"\x11"  # drained to half at 1 char/s
    assert c.stats.after_dc3 == {3: 1}  # the 3 are this DC3's count
    assert c.stats.throttles == [Throttle(decided + 0.0205, 3)]  # and its moment on the line


def test_bytes_waiting_when_the_dc3_went_out_count_before_it() -> None:
    """The emulator decided on DC3, lost its core for 9 ms, found 9 bytes waiting and wrote the
    DC3; it then reads those 9 and 2 more at once. Dated back to back up to the read, all 11
    would be after the DC3; the 9 were on the line before it, so only 2 count."""
    c = Control(cps=100000.0, buffer=32, rate=1.0, allowance=10)
    decided = throttled(c, 100000.0)
    c.sent(decided + 0.009, waiting=9)
    c.data_received(b"Y" * 11, decided + 0.0095)
    assert c.stats.most_after_dc3 == 2 and c.stats.alarms_087 == 0
    c.data_received(b"Z" * 3, decided + 0.012)  # the next read: all after it
    assert c.stats.most_after_dc3 == 5


def test_a_dc3_never_reported_sent_counts_from_its_decision() -> None:
    c = Control(cps=1000.0, buffer=32, rate=1.0, allowance=10)
    decided = throttled(c, 1000.0)
    feed(c, b"Y" * 20, decided + 0.001, 1000.0)
    assert c.stats.most_after_dc3 == 20 and c.stats.alarms_087 == 1


def test_a_late_first_read_is_dated_back_to_back_before_it() -> None:
    """The control was switched on at 0 and first read at 1 s: 40 characters paced on the
    wire had all arrived by then, none is ahead of the wire."""
    c = Control(cps=1000.0, buffer=32, rate=1.0, allowance=10)
    c.time_passed(0.0)
    assert c.data_received(b"%\n" + b"X" * 38, 1.0) == b"\x93"
    assert c.stats.most_after_dc3 == 0 and c.stats.first == pytest.approx(0.961)


def test_th_and_tv_checks() -> None:
    c = Control(cps=1000.0, software_parity=True, tv_check=True)
    data = bytearray(iso_byte(ch) for ch in "%\nN1 X1\nN2 x2 \n%")
    data[3] ^= 0x80  # parity error on "N" of line 2
    c.data_received(bytes(data), 0.0)
    kinds = [(e.kind, e.line) for e in c.stats.errors]
    assert ("TH parity", 2) in kinds
    assert ("TV", 2) in kinds  # "N1 X1": 5 characters
    assert ("TH illegal", 3) in kinds  # lower case
    assert c.programs == ["%\nN1 X1\nN2 x2 \n%"] and c.done


def test_control_reads_eia_from_er_to_er() -> None:
    c = Control(cps=1000.0, code="eia", programs=2)
    program = "%\nN1 X3\n%"
    data = b"\0\0" + bytes(EIA_TABLE[ch] for ch in program)
    assert data[2] == data[-1] == 0x0B  # ER, the rewind stop, where ISO has %
    c.data_received(data, 0.0)
    assert c.programs == [program] and not c.done
    assert c.rewind(1.0) == b"\x11"  # between programs: cycle start asks at once
    c.data_received(data, 2.0)
    assert c.done and c.stats.programs == 2 and c.stats.blocks == 2 and c.stats.rewinds == 0


@pytest.mark.parametrize("code", ["iso", "eia"])
def test_label_skip_ignores_what_stands_before_the_first_end_of_block(code: str) -> None:
    """As a Fanuc does: no TH or TV check between % and the first end of block, and the
    identification is kept with the program as read."""
    c = Control(cps=1000.0, code=code, software_parity=True, tv_check=True)
    label = "%(PART 7 REV B)" if code == "eia" else "%(part 7; rev b$)"
    program = label + "\nN1 X35\nN2 Y4.25\n%"  # even blocks: TV check passes
    if code == "eia":
        data = bytes(EIA_TABLE[ch] for ch in program)
    else:
        data = bytes(iso_byte(ch) for ch in program)
    c.data_received(b"\0" * 4 + data, 0.0)
    assert c.stats.errors == [] and c.done
    assert c.programs == [program] and c.stats.blocks == 2


def test_reset_and_rewind_mid_program_abandons_it_and_asks_again_from_percent() -> None:
    c = Control(cps=1000.0, dc1_every=0.5, programs=1)
    assert c.time_passed(0.0) == b"\x11"
    c.data_received(b"%\nN1 X1\nN2 X2\nN3 X", 0.1)
    assert c.rewind(0.2) == b"\x93\x96"  # DC3 SYN: the reading is abandoned
    assert c.stats.rewinds == 1 and c.programs == [] and not c.done
    c.data_received(b"3\nN4 X4\n%\0\0", 0.21)  # still on the line: thrown away
    assert c.programs == [] and c.stats.errors == []
    assert c.deadline == pytest.approx(0.7)
    assert c.time_passed(0.69) == b""
    assert c.time_passed(0.71) == b"\x11"  # cycle start: read from % again
    c.data_received(b"%\nN1 X1\nN2 X2\nN3 X3\n%", 0.8)
    assert c.done and c.programs == ["%\nN1 X1\nN2 X2\nN3 X3\n%"]
    assert c.stats.programs == 1 and c.stats.rewinds == 1


def test_builtin_profiles_have_working_links() -> None:
    for name in ("fanuc-mill", "pm322-eia", "sinumerik-7e2"):
        s = load_profile(name).serial
        assert Framer(s).eob


class _LatePort:
    """A port whose control sends DC3 while the sending loop is between its look at the line
    and its write (the loop's thread was waiting for a core or the interpreter): after the
    ``at``-th write, the next wait still says "nothing", and the DC3 is there just after. Once
    the DC3 has been read, the next wait that would block brings a DC1."""

    def __init__(self, at: int, clock: list[float]) -> None:
        self.at, self.clock = at, clock
        self.inbox = bytearray(b"\x11")  # DC1: go
        self.late = b""
        self.held = False  # the DC3 was read; a DC1 is due
        self.written = bytearray()
        self.writes = self.writes_after_dc3 = 0

    def wait(self, timeout: float | None) -> bool:
        if self.late:  # the DC3 lands now: too late for this look, in time for the next
            self.inbox += self.late
            self.late = b""
            return False
        if not self.inbox and timeout:
            self.clock[0] += timeout
            if self.held:
                self.inbox += b"\x11"
                self.held = False
        return bool(self.inbox)

    def read(self) -> bytes:
        data, self.inbox = bytes(self.inbox), bytearray()
        self.held = self.held or b"\x13" in data
        return data

    def write(self, data: bytes) -> int:
        self.writes_after_dc3 += b"\x13" in self.inbox
        self.writes += 1
        if self.writes == self.at:
            self.late = b"\x13"
        self.written += data
        self.clock[0] += len(data) / 1000
        return len(data)

    def queued(self) -> None:
        return None

    def hold_output(self, hold: bool) -> None:
        pass

    def discard_output(self) -> None:
        pass


def test_a_dc3_that_lands_between_the_look_and_the_write_stops_the_write() -> None:
    """The loop looks at the line once more just before it writes: a DC3 that came in since
    its last wait goes first, and the bytes it had decided on are sent after the DC1."""
    from dnc.session import send_frames

    text = "%\nN1 G01 X1. Y2. F100.\nN2 X3.\nN3 X4.\nM30\n%\n"
    expected = frames(ISO, text)
    clock = [0.0]
    port = _LatePort(at=3, clock=clock)
    result = send_frames(port, Framer(ISO).frames(split_lines([text])),  # type: ignore[arg-type]
                         FlowSettings(cps=1000.0, xon_timeout=5), clock=lambda: clock[0])
    assert port.writes_after_dc3 == 0
    assert result.pauses == 1
    assert bytes(port.written) == expected


def test_a_pass_stopped_midway_reports_every_byte_it_sent() -> None:
    """The gateway journals an interrupted send from the last progress report: the loop makes
    one as it stops, so the count is the bytes written, not those of the report before."""
    from dnc.link import Aborted
    from dnc.session import send_frames

    text = "%\n" + "".join(f"N{i} X{i}.5\n" for i in range(1, 200)) + "M30\n%\n"
    clock = [0.0]
    port = _LatePort(at=0, clock=clock)
    seen: list[int] = []
    with pytest.raises(Aborted):
        send_frames(port, Framer(ISO).frames(split_lines([text])),  # type: ignore[arg-type]
                    FlowSettings(cps=1000.0, xon_timeout=5), clock=lambda: clock[0],
                    progress=lambda p: seen.append(p.sent), every=10.0,
                    stop=lambda: len(port.written) > 300)
    assert seen[-1] == len(port.written) > 300


def test_a_byte_order_mark_and_a_dos_end_of_file_are_never_sent():
    from dnc.framing import Framer
    from formats.profile import SerialSettings

    framer = Framer(SerialSettings())
    lines = [(1, "\ufeff%"), (2, "N1 X1."), (3, "M30"), (4, "%"), (5, "\x1a")]
    sent = b"".join(data for _, data in framer.frames(iter(lines)))
    assert sent == b"%\nN1 X1.\nM30\n%"
    assert framer.stats.left_after_end == 0


@pytest.mark.parametrize("code", ["iso", "eia"])
def test_a_dos_end_of_file_ends_the_program_or_is_refused_in_both_codes(code) -> None:
    """Review 16a: under EIA a Ctrl-Z inside the program was dropped unsaid, and under ISO a
    file ending in a Ctrl-Z with no closing % was refused. The check reads a Ctrl-Z as the end
    of the file where only blanks follow it: the text before it is the last line sent, the
    rest stays behind; with text after it, it is refused at the Ctrl-Z in either code."""
    from dnc.framing import Framer
    from formats.errors import TapeError
    from formats.profile import SerialSettings

    def sent(lines):
        framer = Framer(SerialSettings(code=code))
        return b"".join(data for _, data in framer.frames(iter(enumerate(lines, 1)))), framer

    plain, _ = sent(["%", "N1 X1.", "M30", "%"])
    for ending in (["M30\x1a"], ["M30", "\x1a"], ["M30", "%\x1a", " "], ["M30", "%\x1a \r"]):
        data, framer = sent(["%", "N1 X1.", *ending])
        assert data == plain, ending
        assert framer.stats.left_after_end == 0
    for lines, place in ((["%", "N1 X1.\x1a", "M30", "%"], (2, 7)),
                         (["%", "N1 X1.", "\x1aM30", "%"], (3, 1)),
                         (["%", "N1 X1.", "M30\x1a", "", "X"], (3, 4))):
        with pytest.raises(TapeError) as info:
            sent(lines)
        assert (info.value.line, info.value.column) == place, lines
        assert "text after a DOS end of file" in info.value.message


def test_a_cr_only_file_is_refused_by_send_with_its_own_reason(tmp_path) -> None:
    """Review 12: a file whose lines end in CR alone was stopped by the check as TG114 'no M02
    or M30' (the whole file one block): send now says what it is, at line 1, before checking."""
    from click.testing import CliRunner

    from tapegate.cli import main
    path = tmp_path / "cr.nc"
    path.write_bytes(b"%\rO01000\rG90 G00 X0 Y0\rM30\r%\r")
    run = CliRunner().invoke(main, ["send", "--port", "loop://", "--flow", "none", "-p",
                                    "fanuc-mill", "-y", str(path)])
    assert run.exit_code != 0
    assert "cr.nc:1:2: the file's lines end in CR alone (CR-only line ends)" in run.output
    assert "TG114" not in run.output
    # CR-LF line ends are no CR-only file
    path.write_bytes(b"%\r\nO01000\r\nG90 G00 X0 Y0\r\nM30\r\n%\r\n")
    run = CliRunner().invoke(main, ["send", "--port", "loop://", "--flow", "none", "-p",
                                    "fanuc-mill", "-y", str(path)])
    assert "CR alone" not in run.output and run.exit_code == 0, run.output


def test_a_cr_only_iso_tape_image_is_refused_by_send_with_its_own_reason(tmp_path) -> None:
    """Review 13, 7: an ISO tape image's CR is 0x8D (its parity bit set), so the CR-only test on
    the raw bytes missed it and the check said "no M02 or M30" with a --force hint. The
    image is tested as it is decoded: refused at line 1 with its own reason."""
    from click.testing import CliRunner

    from tapegate.cli import main
    path = tmp_path / "cr.iso"
    text = "%\rO1234\rG20 G90 G00 X1.5 Y2.25\rG01 Z-0.5 F10.\rM30\r%\r"
    path.write_bytes(bytes(iso_byte(c) for c in text))
    assert b"\r" not in path.read_bytes()  # the CR is on tape as 0x8D
    run = CliRunner().invoke(main, ["send", "--port", "loop://", "--flow", "none", "-p",
                                    "fanuc-mill", "-y", str(path)])
    assert run.exit_code != 0
    assert ("cr.iso:1:2: the ISO tape image's lines end in CR alone (0x8D, CR with its parity "
            "bit, and no LF") in run.output, run.output
    assert "TG114" not in run.output and "--force" not in run.output
    # the same image with LF line ends is sent
    path.write_bytes(bytes(iso_byte(c) for c in text.replace("\r", "\n")))
    run = CliRunner().invoke(main, ["send", "--port", "loop://", "--flow", "none", "-p",
                                    "fanuc-mill", "--baud", "115200", "--no-progress", "-y",
                                    str(path)])
    assert "CR alone" not in run.output and run.exit_code == 0, run.output
