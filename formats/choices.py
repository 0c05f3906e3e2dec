"""String choices that cost nothing to import: :class:`enum.StrEnum` without ``enum``.

A word format's zero suppression and a conversion's rounding (:class:`formats.wordformat.Zeros`,
:class:`~formats.wordformat.Rounding`) were the only enums a ``tapegate check`` imported:
``import enum`` was 5.7M instructions and the two classes 1.4M more, 7.1M of the 98M that
``check DIR -j 2`` ran before its first thread, the serial part its threads cannot share; 6.0M
less with this module in its place (docs/benchmarks.md, "the serial start-up without enum"). A
class of this module is a ``str`` subclass whose members are its instances, made once when the
class is defined, with what the code and the tests use of a ``StrEnum``: each member equal to
its value and written as it (``str``, ``format``, the core's extraction of a string), ``.value``
and ``.name``, the same ``repr`` (``<Zeros.LEADING: 'leading'>``), the class called with a value
or a member giving the member (a ValueError for anything else, worded as ``enum``'s), iteration
and ``len`` in the order of definition, and a member kept itself through ``copy``, ``deepcopy``
and ``pickle``. Unlike a ``StrEnum``'s, a member's hash is its text's, so a dict keyed by the
text finds it. ``tests/test_choices.py`` holds each class to a ``StrEnum`` of the same members.

A member is declared in the class body as ``NAME = "value"``; the class replaces each such
string by the member (:meth:`_Choices.__init__`)."""

from __future__ import annotations

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from collections.abc import Iterator
    from typing import Any, TypeVar

    C = TypeVar("C", bound="StrChoice")


class _Choices(type):
    """The metaclass: the members made when a class is defined, the class iterable."""

    _members_: dict[str, Any]  # value -> member
    _names_: dict[str, str]  # value -> name

    def __init__(cls, name: str, bases: tuple[type, ...], namespace: dict[str, Any]) -> None:
        super().__init__(name, bases, namespace)
        cls._members_, cls._names_ = {}, {}
        for key, value in namespace.items():
            if key.isupper() and type(value) is str:
                member: Any = str.__new__(cls, value)  # type: ignore[arg-type]
                cls._members_[value] = member
                cls._names_[value] = key
                type.__setattr__(cls, key, member)

    def __iter__(cls: type[C]) -> Iterator[C]:  # type: ignore[misc]
        return iter(cls._members_.values())

    def __len__(cls) -> int:
        return len(cls._members_)

    def __repr__(cls) -> str:
        return f"<enum {cls.__name__!r}>"

    def __setattr__(cls, key: str, value: object) -> None:
        if key in cls.__dict__ and key.isupper():
            raise AttributeError(f"cannot reassign member {key!r}")
        super().__setattr__(key, value)


class StrChoice(str, metaclass=_Choices):
    """A member of a set of string choices (see the module's text)."""

    __slots__ = ()

    def __new__(cls: type[C], value: object) -> C:
        member: C | None = cls._members_.get(value) if isinstance(value, str) else None
        if member is None:
            raise ValueError(f"{value!r} is not a valid {cls.__qualname__}")
        return member

    @property
    def value(self) -> str:
        return str.__str__(self)

    @property
    def name(self) -> str:
        return type(self)._names_[self]

    # written as the text, by str's own methods (a StrEnum's are str's too)
    __str__ = str.__str__
    __format__ = str.__format__

    def __repr__(self) -> str:
        return f"<{type(self).__name__}.{self.name}: {str.__repr__(self)}>"

    def __reduce_ex__(self, protocol: object) -> tuple[type, tuple[str]]:
        return type(self), (str.__str__(self),)

    def __copy__(self: C) -> C:
        return self

    def __deepcopy__(self: C, memo: object) -> C:
        return self
