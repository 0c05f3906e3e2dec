"""Value classes that cost nothing to define: dataclasses without generated code.

``@dataclass`` writes each class's ``__init__``, ``__repr__``, ``__eq__``, ``__hash__`` and, when
frozen, ``__setattr__``/``__delattr__`` as source text and compiles it when the module is
imported: about 3.8M instructions a class, and the twenty classes a one-file ``tapegate check``
imports were about a sixth of its start-up (docs/benchmarks.md, "Start-up, second pass"). A class of
this module writes its ``__init__`` in its own body (compiled once, into the ``.pyc``) and takes
the rest from a base class that reads the fields (its annotations, in order); the fields are
registered with ``dataclass(init=False, repr=False, eq=False)``, which compiles nothing, when
first asked for, so :func:`dataclasses.fields`, :func:`dataclasses.replace` and
:func:`dataclasses.asdict` work as before. What a dataclass did, these do alike: the same
``repr`` (``Name(a=1, b='x')``), equality of two instances of the same class field by field
(else ``NotImplemented``), the hash of the fields' tuple for a frozen class and none for a
mutable one, a field declared ``field(repr=False)`` or ``field(compare=False)`` left out of
``repr`` or of ``==`` and the hash, and
:class:`dataclasses.FrozenInstanceError` on assignment to a frozen one
(``tests/test_records.py`` holds each class to a dataclass of the same fields).

A class's ``__init__`` gives its arguments to :func:`init_fields` in the order of the fields; a
field with a ``default_factory`` takes :data:`NEW` as its default and :func:`new` makes the value.
Such a field is declared with this module's :func:`field`, which notes its arguments for
``dataclasses.field`` at the registration: importing ``dataclasses`` imports ``inspect`` (with
``ast``, ``dis`` and ``tokenize``), 42M instructions, a sixth of a one-file check's, so it is
imported only when a record's fields are first asked for, or one is assigned to.
"""

from __future__ import annotations

import _thread
import sys

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    import dataclasses
    from collections.abc import Callable
    from typing import Any, ClassVar, TypeVar

    C = TypeVar("C", bound=type)
    T = TypeVar("T")

__all__ = ["NEW", "FrozenRecord", "Record", "field", "init_fields", "new", "record"]

NEW: Any = type("_New", (), {"__repr__": lambda self: "NEW", "__slots__": ()})()


def new(value: T, factory: Callable[[], T]) -> T:
    """``value``, or a new ``factory()`` where ``value`` is :data:`NEW` (the argument was not
    given): a dataclass's ``default_factory``."""
    return factory() if value is NEW else value


class _Field:
    """What :func:`field` declares: ``dataclasses.field``'s arguments, given to it when the
    class is registered (:class:`_Registered`)."""

    __slots__ = ("arguments",)

    def __init__(self, arguments: dict[str, Any]) -> None:
        self.arguments = arguments


# The fields declared with repr=False or compare=False whose class record() has not yet made:
# a class body declares its fields just before record() makes the class, so only a class that
# declares one pays for finding which (not every record class at import: 0.8M instructions of
# a check's start-up when each class looked at each of its fields).
_FLAGGED: list[_Field] = []


def field(**arguments: Any) -> Any:
    """A record's field with ``dataclasses.field``'s arguments (``default_factory``,
    ``repr``, ``compare``...), as ``dataclasses.field`` declares it in a dataclass."""
    declared = _Field(arguments)
    if arguments.get("repr") is False or arguments.get("compare") is False:
        _FLAGGED.append(declared)
    return declared


def init_fields(obj: Record, *values: object) -> None:
    """Set ``obj``'s fields to ``values``, in the order the class declares them (its
    ``__init__``'s arguments): as a frozen dataclass's ``__init__`` does, past its
    ``__setattr__``."""
    for name, value in zip(obj.__record_fields__, values, strict=True):
        object.__setattr__(obj, name, value)


def record(cls: C) -> C:
    """Make ``cls`` a record: its fields are its own annotations, in order (a ``ClassVar`` is
    none). They are registered with ``dataclasses`` (``dataclass(init=False, repr=False,
    eq=False)``, which generates no method) when something first asks for them --
    ``fields()``, ``replace()``, ``asdict()``, ``is_dataclass()`` -- not at import: the
    registration reads every annotation, 0.4M instructions a class."""
    annotations = cls.__dict__.get("__annotations__", {})
    names = tuple(name for name, kind in annotations.items() if not _classvar(kind))
    cls.__record_fields__ = names  # type: ignore[attr-defined]
    if _FLAGGED:  # the fields repr shows, and those == and hash compare: a field(repr=False)
        # or field(compare=False) of this class left out, as a dataclass leaves it out
        declared = {name: cls.__dict__.get(name) for name in names}
        flagged = {name: value.arguments for name, value in declared.items()
                   if isinstance(value, _Field) and value in _FLAGGED}
        _FLAGGED.clear()
        cls.__record_shown__ = tuple(  # type: ignore[attr-defined]
            n for n in names if flagged.get(n, {}).get("repr") is not False)
        cls.__record_compared__ = tuple(  # type: ignore[attr-defined]
            n for n in names if flagged.get(n, {}).get("compare") is not False)
    elif getattr(cls, "__record_shown__", None) is not None:  # a base's, of other fields
        cls.__record_shown__ = cls.__record_compared__ = None  # type: ignore[attr-defined]
    # positional patterns (`case WordFormat(letter, before, after)`), as a dataclass has them
    cls.__match_args__ = cls.__record_fields__  # type: ignore[attr-defined,misc]
    return cls


def _classvar(annotation: object) -> bool:
    if isinstance(annotation, str):  # from __future__ import annotations
        return annotation.startswith(("ClassVar", "typing.ClassVar"))
    typing = sys.modules.get("typing")  # (an annotation that is a ClassVar needed it)
    return typing is not None and (annotation is typing.ClassVar
                                   or getattr(annotation, "__origin__", None) is typing.ClassVar)


# One registration at a time: `convert DIR -j 2` asks two threads for a class's fields at once
# (`dataclasses.replace` of a profile in each), and a thread that came while another was halfway
# through the registration was told the record is no dataclass.
_REGISTERING = _thread.RLock()


class _Registered:
    """``__dataclass_fields__`` of a record class: registered with ``dataclasses`` on first use
    (the registration stores the class's own, which hides this one from then on). The record
    bases themselves have none."""

    def __get__(self, obj: object, owner: type) -> dict[str, dataclasses.Field[Any]]:
        if owner in (Record, FrozenRecord):
            raise AttributeError("__dataclass_fields__")
        with _REGISTERING:
            registered = owner.__dict__.get("__dataclass_fields__")
            if registered is not None and not isinstance(registered, _Registered):
                return registered  # type: ignore[no-any-return]  # another thread's
            return self._register(owner)

    @staticmethod
    def _register(owner: type) -> dict[str, dataclasses.Field[Any]]:
        import dataclasses

        for name, value in list(owner.__dict__.items()):
            if isinstance(value, _Field):
                setattr(owner, name, dataclasses.field(**value.arguments))
        # a field kept as text until read (formats.exact): its descriptor, which dataclass
        # takes away where the default is a factory, put back
        exact = {name: owner.__dict__[name] for name in owner.__dict__.get("__record_exact__", ())}
        dataclasses.dataclass(init=False, repr=False, eq=False)(owner)
        for name, declared in exact.items():
            setattr(owner, name, declared)
        names = tuple(f.name for f in dataclasses.fields(owner))
        if names != owner.__record_fields__:  # type: ignore[attr-defined]
            raise TypeError(f"{owner.__qualname__}: fields {names} are not its annotations")
        return owner.__dict__["__dataclass_fields__"]  # type: ignore[no-any-return]


class Record:
    """A mutable record: ``repr`` and ``==`` over the fields, no hash (as ``@dataclass``)."""

    __slots__ = ()
    __record_fields__: ClassVar[tuple[str, ...]] = ()
    # (record(): repr's fields, and =='s and hash's, where a field(repr=False) or
    # field(compare=False) leaves one out; None: every field)
    __record_shown__: ClassVar[tuple[str, ...] | None] = None
    __record_compared__: ClassVar[tuple[str, ...] | None] = None
    # what dataclasses.replace(), fields() and asdict() read: registered on first use
    __dataclass_fields__: ClassVar[dict[str, dataclasses.Field[Any]]] = _Registered()  # type: ignore[assignment]

    def _values(self) -> tuple[Any, ...]:
        return tuple([getattr(self, name) for name in self.__record_fields__])

    def _compared(self) -> tuple[Any, ...]:
        names = self.__record_compared__
        return tuple([getattr(self, name) for name in
                      (self.__record_fields__ if names is None else names)])

    def __repr__(self) -> str:
        names = self.__record_shown__
        return (f"{type(self).__qualname__}("
                + ", ".join(f"{name}={getattr(self, name)!r}" for name in
                            (self.__record_fields__ if names is None else names))
                + ")")

    def __eq__(self, other: object) -> bool:
        if other.__class__ is self.__class__:
            return self._compared() == other._compared()
        return NotImplemented

    __hash__: ClassVar[None] = None  # type: ignore[assignment]


class FrozenRecord(Record):
    """A frozen record: as :class:`Record`, hashed by its fields, and assigning or deleting an
    attribute raises :class:`dataclasses.FrozenInstanceError`. Its ``__init__`` sets the fields
    with ``object.__setattr__``; pickled (and copied) as the list of its fields' values, as a
    frozen dataclass with slots is."""

    __slots__ = ()

    def __hash__(self) -> int:  # type: ignore[override]
        return hash(self._compared())

    def __setattr__(self, name: str, value: object) -> None:
        from dataclasses import FrozenInstanceError

        raise FrozenInstanceError(f"cannot assign to field {name!r}")

    def __delattr__(self, name: str) -> None:
        from dataclasses import FrozenInstanceError

        raise FrozenInstanceError(f"cannot delete field {name!r}")

    def __getstate__(self) -> object:
        return [getattr(self, name) for name in self.__record_fields__]

    def __setstate__(self, state: Any) -> None:
        for name, value in zip(self.__record_fields__, state, strict=True):
            object.__setattr__(self, name, value)
