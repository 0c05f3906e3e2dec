"""The core's objects may be freed on any thread: the gateway runs ports, Modbus and the status
page on threads of their own, and Python's cycle collector frees garbage on whichever thread it
happens to run. An object the binding tied to its thread was then never freed, and the collector
reported an error on the thread that found it."""

from __future__ import annotations

import gc
import sys
import threading
from typing import Any

from formats.convert import Converter, ConvertOptions
from formats.diff import Differ, DiffOptions, ProgramReader
from formats.parser import parse_text
from formats.profile import load_profile
from postproc.check import Checker
from postproc.restart import RestartWalk
from postproc.state import ModalMachine

PROFILE = load_profile("fanuc-mill")
PROGRAM = "%\nO1000\nN10 G21 G90 G01 X1. F100.\nN20 X2.\nN30 M30\n%\n"


def core_objects() -> list[Any]:
    """One of each object that holds a core object, each after some use."""
    checker = Checker(PROFILE)
    list(checker.run_stream([PROGRAM], PROFILE.dialect))
    reader = ProgramReader(PROFILE, file="a.nc", options=DiffOptions())
    blocks = list(reader.read_text([PROGRAM]))
    differ = Differ(DiffOptions(), PROFILE)
    list(differ.run(iter(blocks), iter(list(ProgramReader(
        PROFILE, file="b.nc", options=DiffOptions()).read_text([PROGRAM])))))
    converter = Converter(ConvertOptions(target=PROFILE, units="inch"), PROFILE, file="a.nc")
    walk = RestartWalk(PROFILE, "a.nc")
    machine = ModalMachine(PROFILE)
    for block in parse_text(PROGRAM, PROFILE.dialect):
        walk.step(block)
        machine.apply(block)
    return [checker, reader, blocks, differ, converter, walk, machine]


def test_core_objects_in_a_cycle_are_freed_by_a_collection_on_another_thread() -> None:
    raised: list[BaseException | None] = []
    hook = sys.unraisablehook
    sys.unraisablehook = lambda report: raised.append(report.exc_value)
    gc.disable()
    try:
        cycle: list[Any] = core_objects()
        cycle.append(cycle)  # only the cycle collector can free it
        del cycle
        collector = threading.Thread(target=gc.collect)
        collector.start()
        collector.join(timeout=30)
        assert not collector.is_alive()
    finally:
        gc.enable()
        sys.unraisablehook = hook
    assert raised == []
