"""formats.choices: each class held to an enum.StrEnum of the same members, in everything the
code and the tests use of one (a check's start-up without enum: tests/test_startup_serial.py)."""

from __future__ import annotations

import copy
import enum
import pickle

import pytest

from formats.choices import StrChoice
from formats.wordformat import Rounding, Zeros


def _twin(cls: type) -> type[enum.StrEnum]:
    """The StrEnum the class stood for: the same name and members, in order."""
    twin = enum.StrEnum(cls.__name__, [(m.name, m.value) for m in cls])  # type: ignore[attr-defined]
    return twin


@pytest.mark.parametrize("cls", [Zeros, Rounding])
def test_a_choice_behaves_as_its_str_enum(cls):
    twin = _twin(cls)
    members, twins = list(cls), list(twin)
    assert len(cls) == len(twin) == len(members)
    assert [m.name for m in members] == [t.name for t in twins]
    assert [m.value for m in members] == [t.value for t in twins]
    for member, other in zip(members, twins, strict=True):
        assert type(member.value) is str and type(member.name) is str
        assert repr(member) == repr(other)
        assert str(member) == str(other) and type(str(member)) is str
        assert f"{member}" == f"{other}" and f"{member:>12}" == f"{other:>12}"
        assert type(f"{member}") is str
        for spec in ("", "<9", ">12", "^3"):  # a member where the spec changes nothing, as theirs
            assert format(member, spec) == format(other, spec)
            assert isinstance(format(member, spec), cls) == isinstance(format(other, spec), twin)
        assert "{}".format(member) == "{}".format(other)  # noqa: UP032
        assert member == other.value and member == str(other)
        assert cls(member.value) is member and cls(member) is member
        assert getattr(cls, member.name) is member
        assert isinstance(member, str) and isinstance(member, cls)
        assert member.upper() == other.upper()
        assert {member.value: 1}[member] == 1  # looked up by its text, as a StrEnum's is not
        assert copy.copy(member) is member and copy.deepcopy(member) is member
        assert copy.deepcopy({"k": [member]})["k"][0] is member
        for protocol in range(pickle.HIGHEST_PROTOCOL + 1):
            assert pickle.loads(pickle.dumps(member, protocol)) is member
    for wrong in ("", "LEADING", members[0].value.upper(), 1, None, members[0].value + " "):
        with pytest.raises(ValueError) as ours:
            cls(wrong)
        with pytest.raises(ValueError) as theirs:
            twin(wrong)
        assert str(ours.value) == str(theirs.value)
    # another class's member of the same text is its own class's member
    assert cls(str(members[-1])) is members[-1]


def test_members_cannot_be_reassigned_and_are_not_shared():
    with pytest.raises(AttributeError):
        Zeros.LEADING = "other"
    assert Zeros.LEADING is Zeros("leading")
    assert Zeros.NONE is not Rounding.ERROR and Zeros("none") is Zeros.NONE
    with pytest.raises(ValueError):
        Zeros("error")  # Rounding's value
    assert list(StrChoice) == []


def test_the_core_takes_a_member_as_its_text():
    from formats.wordformat import WordFormat

    fmt = WordFormat("X", 5, 3, True, Zeros.TRAILING)
    assert fmt.entry == ("X", 5, 3, True, "trailing", True)
    assert type(fmt.entry[4]) is str

