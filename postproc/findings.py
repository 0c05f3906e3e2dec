"""What the checker reports: :class:`Finding`, one rule broken at one place.

The rules and their messages are the core's (``crates/core/src/check.rs``); a finding reaches
Python as the seven fields of this tuple, made in C by :data:`make_finding`.
"""

from __future__ import annotations

from _operator import itemgetter

from formats import _core

TYPE_CHECKING = False  # typing's, without importing typing (docs/architecture.md, start-up)
if TYPE_CHECKING:
    from typing import Any, NamedTuple

    from postproc.rules import Severity

    class _Fields(NamedTuple):
        rule: str
        severity: Severity
        message: str
        file: str
        line: int
        column: int
        clause: str
else:
    class _Fields(tuple):
        """``collections.namedtuple("Finding", "rule severity message file line column
        clause")``, written out: the same class without typing's ``NamedTuple`` (which also
        compiled each field's annotation: 10M instructions for these seven) nor the
        ``collections`` module (5.7M instructions before a check's threads, now that
        ``decimal`` does not import it; docs/benchmarks.md, "no decimal before the threads").
        tests/test_findings_tuple.py holds it to the namedtuple."""

        __slots__ = ()
        _fields = ("rule", "severity", "message", "file", "line", "column", "clause")
        _field_defaults: dict[str, Any] = {}
        __match_args__ = _fields

        def __new__(_cls, rule, severity, message, file, line, column, clause):  # noqa: N804
            """Create new instance of Finding(rule, severity, message, file, line, column,
            clause)"""
            return tuple.__new__(_cls, (rule, severity, message, file, line, column, clause))

        @classmethod
        def _make(cls, iterable):
            """Make a new Finding object from a sequence or iterable"""
            result = tuple.__new__(cls, iterable)
            if len(result) != 7:
                raise TypeError(f"Expected 7 arguments, got {len(result)}")
            return result

        def _replace(self, /, **kwds):
            """Return a new Finding object replacing specified fields with new values"""
            result = self._make(map(kwds.pop, self._fields, self))
            if kwds:
                raise ValueError(f"Got unexpected field names: {list(kwds)!r}")
            return result

        def __repr__(self):
            """Return a nicely formatted representation string"""
            return self.__class__.__name__ + (  # (namedtuple's own way)
                "(rule=%r, severity=%r, message=%r, file=%r, line=%r, column=%r, clause=%r)"  # noqa: UP031
                % self)

        def _asdict(self):
            """Return a new dict which maps field names to their values."""
            return dict(zip(self._fields, self, strict=True))

        def __getnewargs__(self):
            """Return self as a plain tuple.  Used by copy and pickle."""
            return tuple(self)

        rule = property(itemgetter(0), doc="Alias for field number 0")
        severity = property(itemgetter(1), doc="Alias for field number 1")
        message = property(itemgetter(2), doc="Alias for field number 2")
        file = property(itemgetter(3), doc="Alias for field number 3")
        line = property(itemgetter(4), doc="Alias for field number 4")
        column = property(itemgetter(5), doc="Alias for field number 5")
        clause = property(itemgetter(6), doc="Alias for field number 6")

    _Fields.__name__ = _Fields.__qualname__ = "Finding"


class Finding(_Fields):
    """One rule broken at one place (a tuple: millions of them are cheap to make)."""

    __slots__ = ()

    def __str__(self) -> str:
        """``file:line:column: severity rule message [clause]``: the text report's line, as
        the core writes it (``crates/core/src/report.rs``)."""
        return _core.render_findings("text", (self,))[:-1]


class _Bound:
    def method(self) -> None:
        """(a function bound to an object: its type, as ``types.MethodType`` takes it)"""


_METHOD: Any = type(_Bound().method)
make_finding = _METHOD(tuple.__new__, Finding)
"""A Finding from its 7 fields in one tuple, without a call to ``Finding`` (the core makes
millions): ``tuple.__new__`` bound to the class, ``tuple.__new__(Finding, fields)``, called in
C as ``functools.partial(tuple.__new__, Finding)`` was, without importing functools (and
``types``) before a check's threads (docs/benchmarks.md, "functools")."""
