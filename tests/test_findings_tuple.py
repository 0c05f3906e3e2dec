"""postproc.findings' tuple class, written out without ``collections``, is the namedtuple it
stands for: the same fields, methods, errors, ``repr`` and pickling."""

from __future__ import annotations

import copy
import pickle
from collections import namedtuple

import pytest

from postproc.findings import Finding, make_finding

FIELDS = "rule severity message file line column clause"
Reference = namedtuple("Finding", FIELDS)  # noqa: PYI024
VALUES = ("TG201", "error", "a message with 'quotes'", "dir/a.nc", 12, 3, "6.1")


class Twin(Reference):
    __slots__ = ()


Twin.__name__ = "Finding"  # (repr writes the class's name)


def test_the_fields_and_their_reading():
    found, reference = Finding(*VALUES), Twin(*VALUES)
    base = Finding.__bases__[0]
    assert base.__name__ == base.__qualname__ == "Finding" == Reference.__name__
    assert base._fields == Reference._fields and base._field_defaults == {}
    assert base.__match_args__ == Reference.__match_args__
    assert base.__slots__ == () and Finding.__slots__ == ()
    assert tuple(found) == VALUES and found == reference and hash(found) == hash(reference)
    for index, name in enumerate(Reference._fields):
        assert getattr(found, name) == VALUES[index]
        assert getattr(base, name).__doc__ == getattr(Reference, name).__doc__
    assert repr(found) == repr(reference)
    assert found._asdict() == reference._asdict()
    assert found._replace(line=99, clause="x") == reference._replace(line=99, clause="x")
    assert type(found._replace(line=1)) is Finding
    assert Finding._make(VALUES) == found and type(Finding._make(iter(VALUES))) is Finding
    assert Finding(**dict(zip(Reference._fields, VALUES, strict=True))) == found
    assert make_finding(VALUES) == found and type(make_finding(VALUES)) is Finding
    match found:
        case Finding(rule, severity):
            assert (rule, severity) == VALUES[:2]


def test_the_errors_are_the_namedtuples():
    for call in (lambda cls: cls(*VALUES[:6]), lambda cls: cls(*VALUES, "extra"),
                 lambda cls: cls(*VALUES[:6], claus="x")):
        with pytest.raises(TypeError):
            call(Twin)
        with pytest.raises(TypeError):
            call(Finding)
    with pytest.raises(TypeError, match="Expected 7 arguments, got 6"):
        Reference._make(VALUES[:6])
    with pytest.raises(TypeError, match="Expected 7 arguments, got 6"):
        Finding._make(VALUES[:6])
    with pytest.raises(ValueError, match=r"Got unexpected field names: \['rules'\]"):
        Twin(*VALUES)._replace(rules="x")
    with pytest.raises(ValueError, match=r"Got unexpected field names: \['rules'\]"):
        Finding(*VALUES)._replace(rules="x")
    with pytest.raises(AttributeError):
        Finding(*VALUES).rule = "x"  # type: ignore[misc]
    with pytest.raises(AttributeError):
        Finding(*VALUES).other = 1  # type: ignore[attr-defined]


def test_pickled_and_copied():
    found = Finding(*VALUES)
    for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
        again = pickle.loads(pickle.dumps(found, protocol))
        assert again == found and type(again) is Finding
    assert copy.copy(found) == found and type(copy.deepcopy(found)) is Finding
    assert found.__getnewargs__() == VALUES
