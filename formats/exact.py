"""A profile's exact numbers kept as their text until a reader asks for them.

A profile's limits, arc tolerances, restart clearances and work offsets are
:class:`decimal.Decimal` values, but a check reads none of them in Python: the core's machine
takes them as text (:func:`formats.machine.machine_spec`). Made at the profile's load, they
imported ``decimal`` (``_decimal``, ``numbers``, and ``collections`` for its ``DecimalTuple``)
before a batch's threads start, 11.1M instructions of the 78M the main thread runs there,
work the threads cannot share (docs/benchmarks.md, "no decimal before the threads").

A field declared :class:`Exact` holds what the profile's reading validated -- the
:class:`Text` of a TOML integer or float (``str(value)``), or a :class:`Texts` table of such
texts -- and makes
the ``Decimal`` (``Decimal(text)``, the value the field held before) the first time the field
is read, keeping it. Whoever reads the field gets a ``Decimal``, as before: ``repr``, ``==``,
the hash, pickling and ``dataclasses`` read the fields through it. :func:`text` gives a
field's value as ``str`` of its ``Decimal`` writes it, without making one where the text is
plain digits (the machine spec's way). Any other value given to the record's ``__init__`` (a
``Decimal``, a plain ``str``) is kept as it is.
"""

from __future__ import annotations

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from typing import Any

__all__ = ["Exact", "Text", "Texts", "exact_fields", "plain_text", "table_keys", "text"]


class Text(str):
    """The text of a validated TOML number in an :class:`Exact` field, not yet read: made
    ``Decimal(text)`` when it is."""

    __slots__ = ()


class Texts(dict):  # type: ignore[type-arg]
    """A table of an :class:`Exact` field not yet read: its values are texts (:class:`Text`), or
    pairs of them, or tables of them, each made a ``Decimal`` (in a plain ``dict``, the pairs
    as tuples) when the field is first read."""

    __slots__ = ()


def _made(value: Any) -> Any:
    """``value`` (a :class:`Text`, a pair or a table of them) with every :class:`Text` made a
    ``Decimal``; anything else as it is."""
    if type(value) is Text:
        from decimal import Decimal

        return Decimal(value)
    if isinstance(value, tuple):
        return tuple(_made(v) for v in value)
    if isinstance(value, dict):
        return {key: _made(v) for key, v in value.items()}
    return value


class Exact:
    """A record's field of exact numbers (a ``Decimal``, a table of pairs of them, a table of
    tables), declared on the class after :func:`formats.records.record` made it (a data
    descriptor: the instance's own entry under the same name is where the value is kept).
    ``default`` is the class's default, as its text (``"5000"``), None, or a factory
    (``dict``) of a field declared with ``field(default_factory=...)``."""

    __slots__ = ("name", "default")

    def __init__(self, name: str, default: Any) -> None:
        self.name, self.default = name, default

    def __set__(self, obj: Any, value: Any) -> None:
        obj.__dict__[self.name] = value

    def __get__(self, obj: Any, owner: type | None = None) -> Any:
        if obj is None:  # the class's default, as dataclasses and readers of the class see it
            default = self.default
            if callable(default):
                import dataclasses

                return dataclasses.field(default_factory=default)
            return _made(Text(default)) if default is not None else None
        held = obj.__dict__
        try:
            value = held[self.name]
        except KeyError:  # (not set yet: as a missing attribute)
            raise AttributeError(self.name) from None
        if type(value) is Text or type(value) is Texts:
            value = held[self.name] = _made(value)
        return value


def exact_fields(cls: type, defaults: dict[str, Any]) -> None:
    """Declare the fields ``defaults`` names (each with its default, as :class:`Exact` takes
    it) of the record class ``cls`` exact: kept as text until read."""
    for name, default in defaults.items():
        setattr(cls, name, Exact(name, default))
    cls.__record_exact__ = tuple(defaults)  # type: ignore[attr-defined]


def plain_text(value: str) -> str | None:
    """``str(Decimal(value))`` for the text of a TOML integer or float written as plain
    digits (``-30``, ``0.0282843``, ``-400.0``): the text itself; None for any other form
    (an exponent, ``inf``), which the ``Decimal`` writes otherwise."""
    body = value[1:] if value[:1] == "-" else value
    whole, point, decimals = body.partition(".")
    if whole.isdigit() and whole.isascii() and (
            not point or (decimals.isdigit() and decimals.isascii())):
        return value
    return None


def _text(value: Any) -> Any:
    if type(value) is Text:
        found = plain_text(value)
        return str(found) if found is not None else str(_made(value))  # (a plain str)
    if isinstance(value, tuple):
        return tuple(_text(v) for v in value)
    if isinstance(value, dict):
        return {key: _text(v) for key, v in value.items()}
    return None if value is None else str(value)


def text(obj: Any, name: str) -> Any:
    """The exact field ``name`` of ``obj`` with each number as ``str`` of its ``Decimal``
    writes it (a pair of texts, a table of them), without making the ``Decimal`` where the
    text is plain digits; None for None."""
    return _text(obj.__dict__[name])


def table_keys(obj: Any, name: str) -> list[Any]:
    """The keys of the exact table field ``name`` of ``obj`` (a limits' axes), without making
    its ``Decimal`` values."""
    return list(obj.__dict__[name])


def shown(value: Text) -> str:
    """``str(Decimal(value))``, without making the ``Decimal`` where the text is plain."""
    return _text(value)  # type: ignore[no-any-return]
