"""What the click commands share beside :mod:`tapegate.common`: the profile option and the
usage error a command finds itself (click's own usage errors are told the same way)."""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, TypeVar

import click

if TYPE_CHECKING:
    from decimal import Decimal

F = TypeVar("F", bound=Callable[..., Any])


class UsageProblem(click.ClickException):
    """A usage error found by the command itself (click's own are the same): exit 2."""

    exit_code = 2
    code = "usage"


class FiniteRange(click.FloatRange):
    """click's ``FloatRange`` for a number of seconds or characters, refusing NaN and the
    infinities, which it lets through (NaN compares false with both ends of the range, an
    infinity passes a range with no upper end) and which no wait or pace can use."""

    def convert(self, value: Any, param: click.Parameter | None,
                ctx: click.Context | None) -> Any:
        number = super().convert(value, param, ctx)
        if not math.isfinite(number):
            self.fail(f"{value!r} is not a finite number", param, ctx)
        return number


_PLAIN_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")


class Height(click.ParamType):  # type: ignore[type-arg]  # (generic in recent click, not 8.1)
    """A length the operator gives for the machine to move to, read exactly as a
    :class:`~decimal.Decimal` (``50.1`` stays 50.1, not the float nearest it): a finite
    number in the digits 0-9 (no ``1_0``, no other script's digits). Whether its digits fit
    the word format is for the command to say, with the profile in hand."""

    name = "height"

    def convert(self, value: Any, param: click.Parameter | None,
                ctx: click.Context | None) -> Decimal:
        from decimal import Decimal, InvalidOperation  # (a conversion's start-up does without)

        if isinstance(value, Decimal):
            number = value
        else:
            try:
                number = Decimal(str(value).strip())
            except InvalidOperation:
                self.fail(f"{value!r} is not a number", param, ctx)
        if not number.is_finite():
            self.fail(f"{value!r} is not a finite number", param, ctx)
        # Decimal also reads `1_0` and other scripts' digits (`５0`): a height is written as
        # the program would write it, in ASCII digits (review 15, finding 7)
        if not isinstance(value, Decimal) and not _PLAIN_NUMBER.fullmatch(str(value).strip()):
            self.fail(f"{value!r} is not a number written in the digits 0-9", param, ctx)
        return number


def profile_option() -> Callable[[F], F]:
    """``--profile``/``-p``, optional on every command: without it the program is read with the
    neutral profile, adjusted to what can be detected in the program, and stderr says so."""
    return click.option(
        "--profile", "-p", "profile",
        help="Machine profile: a built-in name (see `tapegate profiles`) or a .toml file "
             "(default: the neutral profile, with the units codes and decimal style detected "
             "in the program).")
