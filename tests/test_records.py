"""The value classes written as records (formats.records) behave as the dataclasses they were:
each is held to a real dataclass of the same fields, built here, on real instances."""

import copy
import dataclasses
import inspect
import pickle
import sys
from decimal import Decimal
from typing import ClassVar

import pytest

from formats.classification import DetailedClassification, GeneralClassification
from formats.codes import TABLES, Code, CodeTable
from formats.conversion import ConvertOptions, ConvertStats
from formats.exact import Text
from formats.model import Word
from formats.parser import PERMISSIVE, Dialect
from formats.profile import (
    CheckSettings,
    Limits,
    NumberReading,
    Profile,
    RestartSettings,
    SerialSettings,
    load_profile,
)
from formats.records import NEW, FrozenRecord, Record, field, init_fields, new, record
from formats.source import Source
from formats.tape import Decoded, TapeIssue
from formats.wordformat import WordFormat, Zeros
from postproc.check import Checker, CheckStats, Drawn, Segment
from postproc.rules import RULES, Rule

FANUC = load_profile("fanuc-mill")


def instances() -> list[object]:
    checker = Checker(FANUC, "p.nc")
    list(checker.run_stream(["%\nO1\nN1 G21 G90 G17\nN2 G0 X10. Y5.\nN3 G2 X20. Y5. R5. F100\n"
                             "N4 M30\n%\n"], FANUC.dialect))
    stats = checker.stats
    return [
        FANUC, FANUC.general, FANUC.detailed, FANUC.table, FANUC.code("G", 2),
        FANUC.word_format("X"), FANUC.dialect, FANUC.numbers, FANUC.limits, FANUC.checks,
        FANUC.serial, FANUC.restart, PERMISSIVE,
        Word("X", "", "-", "12.5", "", 4, "X-12.5"),
        TapeIssue("parity", 7, 2, 3, 0xB1, "1"), Decoded("N1 X1\n", "iso", fill=3),
        Source("program.nc"), RULES["TG101"],
        Segment("arc", (0.0, 0.0, 0.0), (1.0, 1.0, 0.0), 3, (1.0, 0.0, 0.0), True),
        Drawn({"metric"}, {3: {0, 1}}, {2}), stats,
        Limits(axes={"X": (Decimal(-1), Decimal(1))}, feed_max=Decimal(5000)),
        RestartSettings(clearance=Decimal(50)), GeneralClassification("C", "M", 3, 2, 1),
        ConvertOptions(FANUC, source=FANUC, units="inch", from_zeros=Zeros.TRAILING),
        converted_stats(),
    ]


def converted_stats() -> ConvertStats:
    """A conversion's statistics with its notes said, among them one Python made (kept in
    ``_noted``, a field that neither repr nor == reads)."""
    stats = ConvertStats(file="p.nc", output="out/p.nc", blocks=3, words=7, changed=2)
    stats.note("source: detected as fanuc-mill")
    stats.said(["N2: X rounded"])
    stats.body_units.append(("o100", "inch"))
    return stats


CLASSES = (Profile, GeneralClassification, DetailedClassification, CodeTable, Code, WordFormat,
           Dialect, NumberReading, Limits, CheckSettings, SerialSettings, RestartSettings, Word,
           TapeIssue, Decoded, Source, Rule, Segment, Drawn, CheckStats, ConvertOptions,
           ConvertStats)


def twin(cls: type) -> type:
    """A real dataclass of ``cls``'s fields, frozen as ``cls`` is."""
    made = dataclasses.make_dataclass(
        cls.__name__, [(f.name, object, dataclasses.field(repr=f.repr, compare=f.compare))
                       for f in dataclasses.fields(cls)],
        frozen=issubclass(cls, FrozenRecord))
    made.__qualname__ = cls.__qualname__
    return made


def test_every_instance_is_of_a_record_class_and_each_class_has_one():
    assert {type(x) for x in instances()} == set(CLASSES)
    assert all(issubclass(c, Record) for c in CLASSES)


@pytest.mark.parametrize("value", instances(), ids=lambda x: type(x).__name__)
def test_repr_eq_and_hash_as_a_dataclass_of_the_same_fields(value):
    cls = type(value)
    names = [f.name for f in dataclasses.fields(cls)]
    values = [getattr(value, name) for name in names]
    reference = twin(cls)(*values)
    assert repr(value) == repr(reference)
    again = cls(*values)  # __init__ takes the fields in their order, by name as well
    by_name = cls(**dict(zip(names, values, strict=True)))
    assert [getattr(by_name, name) for name in names] == values
    assert again == value and (again != value) is False
    assert value.__eq__(reference) is NotImplemented and value != reference
    if isinstance(value, FrozenRecord):
        try:
            expected = hash(reference)
        except TypeError:  # a dict field: unhashable, as the dataclass was
            with pytest.raises(TypeError):
                hash(value)
        else:
            assert hash(value) == expected == hash(again)
    else:
        with pytest.raises(TypeError, match="unhashable"):
            hash(value)
    # (a conversion's target must be a profile: its __init__ reads it)
    at = names.index("spacing") if cls is ConvertOptions else 0
    other = dataclasses.replace(value, **{names[at]: "changed" if values[at] != "changed"
                                          else "x"})
    assert other != value and type(other) is cls
    assert [getattr(other, n) for n in names if n != names[at]] == values[:at] + values[at + 1:]


def test_a_field_left_out_of_repr_and_eq_as_a_dataclass_leaves_it():
    """``field(repr=False, compare=False)``: a conversion's own bookkeeping (the notes said,
    where they spill) is no part of what it did."""
    stats, again = converted_stats(), converted_stats()
    again._noted.add("another note said")
    again.spill_to("somewhere")
    assert stats == again
    assert repr(stats).endswith(", notes_spill=None)") and "_noted=" not in repr(stats)
    assert repr(stats) == repr(again)
    again.changed += 1
    assert stats != again
    for registered_first in (False, True):  # (registering replaces the fields' declarations)

        @record
        class Kept(Record):
            a: int
            b: list[int] = field(default_factory=list, repr=False, compare=False)

            def __init__(self, a: int, b: list[int] = NEW) -> None:
                init_fields(self, a, new(b, list))

        if registered_first:
            assert [f.repr for f in dataclasses.fields(Kept)] == [True, False]
        assert repr(Kept(1, [2])) == "test_a_field_left_out_of_repr_and_eq_as_a_dataclass_" \
            "leaves_it.<locals>.Kept(a=1)"
        assert Kept(1, [2]) == Kept(1, [3]) != Kept(2, [2])

        @record
        class Plain(Kept):  # (a record's fields are its own annotations: none left out)
            c: int

            def __init__(self, c: int) -> None:
                init_fields(self, c)

        assert repr(Plain(3)).endswith(".Plain(c=3)") and Plain(3) != Plain(4)


@pytest.mark.parametrize("value", instances(), ids=lambda x: type(x).__name__)
def test_frozen_records_refuse_assignment_and_every_record_pickles_and_copies(value):
    name = dataclasses.fields(value)[0].name
    if isinstance(value, FrozenRecord):
        with pytest.raises(dataclasses.FrozenInstanceError, match=repr(name)):
            setattr(value, name, 1)
        with pytest.raises(dataclasses.FrozenInstanceError):
            delattr(value, name)
    else:
        copied = copy.copy(value)
        setattr(copied, name, "set")
        assert getattr(copied, name) == "set"
    assert pickle.loads(pickle.dumps(value)) == value
    assert copy.deepcopy(value) == value


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_init_takes_the_fields_with_their_declared_defaults(cls):
    """The hand-written __init__ names the fields in their order, and where the class declares a
    default (as a dataclass did) the same one; a default_factory field makes a new value per
    instance."""
    params = list(inspect.signature(cls.__init__).parameters.values())[1:]
    fields = dataclasses.fields(cls)
    assert [p.name for p in params] == [f.name for f in fields]
    for param, f in zip(params, fields, strict=True):
        if f.default_factory is not dataclasses.MISSING:
            assert param.default is NEW
        elif f.name in cls.__dict__.get("__record_exact__", ()) and f.default is not None:
            # an exact field (formats.exact): the default is the text of the field's Decimal,
            # made that Decimal when the field is read
            assert type(param.default) is Text and Decimal(param.default) == f.default
            assert repr(cls(**{f.name: param.default}).__getattribute__(f.name)) == repr(
                f.default)
        elif f.default is not dataclasses.MISSING:
            assert param.default == f.default and type(param.default) is type(f.default)
        elif "__slots__" not in cls.__dict__:  # a slot class declares its defaults in __init__
            assert param.default is inspect.Parameter.empty, param.name


def test_a_default_factory_gives_each_instance_its_own_value():
    a, b = Source("a.nc"), Source("b.nc")
    a.issues.append(TapeIssue("illegal", 0, 1, 1, 0xFF, "?"))
    assert b.issues == [] and a.issues is not b.issues
    assert Limits().axes == {} and Limits().axes is not Limits().axes
    assert CheckSettings().pqr == {"P": "parameter", "Q": "parameter", "R": "parameter"}
    assert Dialect().extra == frozenset()
    given: dict[str, str] = {}
    assert CheckSettings(pqr=given).pqr is given
    assert new(NEW, list) == [] and new(None, list) is None


def test_the_slot_classes_keep_their_slots_and_defaults():
    assert WordFormat("X", 5) == WordFormat("X", 5, 0, False, Zeros.LEADING, True)
    assert Code("G", 1, "f", "a") == Code("G", 1, "f", "a", "assigned", "")
    for value in (WordFormat("X", 5), Code("G", 1, "f", "a"), Word("X", "", "", "1", "", 1, "X1")):
        assert not hasattr(value, "__dict__")


def test_the_code_tables_and_a_profile_are_unchanged_by_a_round_trip():
    for table in TABLES.values():
        assert pickle.loads(pickle.dumps(table)) == table
    assert pickle.loads(pickle.dumps(FANUC)) == FANUC
    assert dataclasses.asdict(FANUC.serial)["baud"] == FANUC.serial.baud


def test_the_fields_are_registered_with_dataclasses_when_first_asked_for():
    """A record's fields are its annotations at once; dataclasses learns them on first use
    (fields(), replace(), asdict(), is_dataclass()), the same names in the same order."""
    code = r'''
import dataclasses, sys
from tapegate.cli import main
sys.argv = ["tapegate", "check", sys.argv[1], "-p", "fanuc-mill"]
try:
    main()
except SystemExit:
    pass
from formats.profile import Profile, SerialSettings
from formats.wordformat import WordFormat
print(sorted(c.__name__ for c in (Profile, SerialSettings, WordFormat)
             if "__dataclass_fields__" in c.__dict__))
print(dataclasses.is_dataclass(Profile), "__dataclass_fields__" in Profile.__dict__)
print([f.name for f in dataclasses.fields(WordFormat)] == list(WordFormat.__record_fields__))
'''
    import os
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    program = root / "tapegate" / "examples" / "bracket.nc"
    done = subprocess.run([sys.executable, "-c", code, str(program)], capture_output=True,
                          text=True, timeout=60, check=False,
                          env={**os.environ, "PYTHONPATH": str(root)})
    assert done.stdout.splitlines()[-3:] == ["[]", "True True", "True"], done.stderr


def test_a_classvar_is_no_field_and_fields_that_differ_are_refused_when_registered():
    from formats.records import record

    @record
    class Pair(FrozenRecord):
        """Fields a, b; a ClassVar is none."""

        a: int
        b: int
        c: ClassVar[int] = 3

        def __init__(self, a: int, b: int) -> None:
            init_fields(self, a, b)

    assert Pair.__record_fields__ == ("a", "b")
    assert [f.name for f in dataclasses.fields(Pair)] == ["a", "b"]
    assert repr(Pair(1, 2)).endswith("<locals>.Pair(a=1, b=2)")  # qualified, as a dataclass
    assert Pair(1, 2) == Pair(1, 2) != Pair(2, 1)

    @record
    class Swapped(FrozenRecord):
        """Its record fields set otherwise than its annotations: refused, not misread."""

        a: int
        b: int

    Swapped.__record_fields__ = ("b", "a")
    with pytest.raises(TypeError, match="not its annotations"):
        dataclasses.fields(Swapped)


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_positional_patterns_match_as_a_dataclass_s(cls):
    """``__match_args__`` is set with the fields, before anything registers them with
    dataclasses (a record class matched positionally in a fresh process)."""
    script = (f"from {cls.__module__} import {cls.__name__} as C\n"
              "print(C.__match_args__)\n")
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                         check=True, timeout=60).stdout
    assert out.strip() == repr(tuple(f.name for f in dataclasses.fields(cls)))


def test_a_record_s_fields_are_registered_once_when_threads_ask_at_once() -> None:
    """``convert DIR -j 2``: two threads ``dataclasses.replace`` a profile at the same moment,
    each the first to ask for its class's fields; each must be given them (a fresh clone's suite,
    run under load, once saw a thread told that a profile is no dataclass)."""
    switching = sys.getswitchinterval()
    sys.setswitchinterval(1e-6)  # a thread switch every few bytecodes: the registration's window
    try:
        for _ in range(40):
            _replace_at_once(threads=6)
    finally:
        sys.setswitchinterval(switching)


def _replace_at_once(threads: int) -> None:
    """A new record class, replaced by ``threads`` threads released together."""
    import threading

    from formats.records import FrozenRecord, field, init_fields, record

    @record
    class Point(FrozenRecord):  # as a profile: fields with a default factory, no slots
        x: int
        y: int
        notes: list[str] = field(default_factory=list)
        more: dict[str, int] = field(default_factory=dict)

        def __init__(self, x: int, y: int, notes: list[str] | None = None,
                     more: dict[str, int] | None = None) -> None:
            init_fields(self, x, y, notes or [], more or {})

    point = Point(1, 2)
    start = threading.Barrier(threads)
    failures: list[BaseException] = []
    results: list[object] = []

    def ask() -> None:
        start.wait(timeout=10)
        try:
            results.append(dataclasses.replace(point, y=3))
        except BaseException as e:  # noqa: BLE001 -- the failure under test, kept to assert
            failures.append(e)

    started = [threading.Thread(target=ask) for _ in range(threads)]
    for t in started:
        t.start()
    for t in started:
        t.join(timeout=10)
    assert failures == []
    assert results == [Point(1, 3)] * threads


def test_a_code_sets_each_argument_to_its_own_field():
    """Code's __init__ sets its fields itself (without init_fields' loop): each argument,
    given by position and by name, lands in the field of its name."""
    names = Code.__record_fields__
    values = [f"value of {name}" for name in names]
    by_position = Code(*values)
    by_name = Code(**dict(zip(names, values, strict=True)))
    for name, value in zip(names, values, strict=True):
        assert getattr(by_position, name) == value
        assert getattr(by_name, name) == value
    assert [f.name for f in dataclasses.fields(Code)] == list(names)
    default = Code("G", 1, "f", "a")
    assert (default.status, default.timing, default.words, default.meaning) == (
        "assigned", "", (), "")
