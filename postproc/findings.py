"""What the checker reports: :class:`Finding`, one rule broken at one place.

The rules and their messages are the core's (``crates/core/src/check.rs``); a finding reaches
Python as the seven fields of this tuple, made in C by :data:`make_finding`.
"""

# (no ``from __future__ import annotations``: NamedTuple checks each field's annotation, and a
# string annotation is compiled into a ForwardRef first -- 10M instructions for these seven, a
# sixteenth of a one-file check)
from functools import partial
from typing import NamedTuple

from formats import _core
from postproc.rules import Severity


class Finding(NamedTuple):
    """One rule broken at one place (a tuple: millions of them are cheap to make)."""

    rule: str
    severity: Severity
    message: str
    file: str
    line: int
    column: int
    clause: str

    def __str__(self) -> str:
        """``file:line:column: severity rule message [clause]``: the text report's line, as
        the core writes it (``crates/core/src/report.rs``)."""
        return _core.render_findings("text", (self,))[:-1]


make_finding = partial(tuple.__new__, Finding)
"""A Finding from its 7 fields in one tuple, without a call to ``Finding`` (the core makes
millions)."""
