"""The value classes written as records (formats.records) behave as the dataclasses they were:
each is held to a real dataclass of the same fields, built here, on real instances."""

import copy
import dataclasses
import inspect
import pickle
from decimal import Decimal

import pytest

from formats.classification import DetailedClassification, GeneralClassification
from formats.codes import TABLES, Code, CodeTable
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
from formats.records import NEW, FrozenRecord, Record, new
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
        FANUC, FANUC.general, FANUC.detailed, FANUC.table, FANUC.table.lookup("G", 2),
        FANUC.word_format("X"), FANUC.dialect, FANUC.numbers, FANUC.limits, FANUC.checks,
        FANUC.serial, FANUC.restart, PERMISSIVE,
        Word("X", "", "-", "12.5", "", 4, "X-12.5"),
        TapeIssue("parity", 7, 2, 3, 0xB1, "1"), Decoded("N1 X1\n", "iso", fill=3),
        Source("program.nc"), RULES["TG101"],
        Segment("arc", (0.0, 0.0, 0.0), (1.0, 1.0, 0.0), 3, (1.0, 0.0, 0.0), True),
        Drawn({"metric"}, {3: {0, 1}}, {2}), stats,
        Limits(axes={"X": (Decimal(-1), Decimal(1))}, feed_max=Decimal(5000)),
        RestartSettings(clearance=Decimal(50)), GeneralClassification("C", "M", 3, 2, 1),
    ]


CLASSES = (Profile, GeneralClassification, DetailedClassification, CodeTable, Code, WordFormat,
           Dialect, NumberReading, Limits, CheckSettings, SerialSettings, RestartSettings, Word,
           TapeIssue, Decoded, Source, Rule, Segment, Drawn, CheckStats)


def twin(cls: type) -> type:
    """A real dataclass of ``cls``'s fields, frozen as ``cls`` is."""
    made = dataclasses.make_dataclass(cls.__name__, [f.name for f in dataclasses.fields(cls)],
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
    first = names[0]
    other = dataclasses.replace(value, **{first: "changed" if values[0] != "changed" else "x"})
    assert other != value and type(other) is cls
    assert [getattr(other, n) for n in names[1:]] == values[1:]


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
