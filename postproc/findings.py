"""What the checker reports: :class:`Finding`, one rule broken at one place.

The rules and their messages are the core's (``crates/core/src/check.rs``); a finding reaches
Python as the seven fields of this tuple, made in C by :data:`make_finding`.
"""

from __future__ import annotations

from collections import namedtuple

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
    # the same tuple at run time, without typing (whose NamedTuple also compiled each field's
    # annotation: 10M instructions for these seven)
    _Fields = namedtuple("Finding", "rule severity message file line column clause")


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
