"""What the click commands share beside :mod:`tapegate.common`: the profile option and the
usage error a command finds itself (click's own usage errors are told the same way)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar

import click

F = TypeVar("F", bound=Callable[..., Any])


class UsageProblem(click.ClickException):
    """A usage error found by the command itself (click's own are the same): exit 2."""

    exit_code = 2
    code = "usage"


def profile_option() -> Callable[[F], F]:
    """``--profile``/``-p``, optional on every command: without it the program is read with the
    neutral profile, adjusted to what can be detected in the program, and stderr says so."""
    return click.option(
        "--profile", "-p", "profile",
        help="Machine profile: a built-in name (see `tapegate profiles`) or a .toml file "
             "(default: the neutral profile, with the units codes and decimal style detected "
             "in the program).")
