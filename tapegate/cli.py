"""The ``tapegate`` command line: options in, library calls, results out -- no work of its own.

The group is assembled here from one module per command group: ``parse_cli``, ``convert_cli``,
``check_cli`` (check, plot), ``diff_cli``, ``tape_cli``, ``profiles_cli`` (classify, profiles),
``serial_cli`` (send, receive, journal, emulate) and ``serve_cli``. What they share -- file
arguments, the profile option, and the one mapping of errors to messages and exit codes -- is
in :mod:`tapegate.common`. Exit codes: 0 done, 1 the input is bad (parse, tape, conversion or
check findings), 2 usage error or unreadable file, 3 the link failed.
"""

from __future__ import annotations

import click

from tapegate.check_cli import check, plot
from tapegate.convert_cli import convert
from tapegate.diff_cli import diff
from tapegate.parse_cli import parse
from tapegate.profiles_cli import classify, profiles
from tapegate.tape_cli import tape


class LazyGroup(click.Group):
    """A group whose serial and gateway commands are imported when they are used (click's
    documented pattern for lazy subcommands), so ``parse``, ``check`` and ``convert`` do not load
    pyserial, pymodbus and the DNC layer."""

    LAZY = {
        "send": "tapegate.serial_cli:send",
        "receive": "tapegate.serial_cli:receive",
        "journal": "tapegate.serial_cli:journal_command",
        "emulate": "tapegate.serial_cli:emulate",
        "serve": "tapegate.serve_cli:serve",
        "password": "tapegate.serve_cli:password",
        "fleet": "tapegate.fleet_cli:fleet",
    }

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted([*super().list_commands(ctx), *self.LAZY])

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        target = self.LAZY.get(cmd_name)
        if target is None:
            return super().get_command(ctx, cmd_name)
        import importlib

        module, name = target.split(":")
        command = getattr(importlib.import_module(module), name)
        assert isinstance(command, click.Command)
        return command


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="tapegate")
def main() -> None:
    """tapegate: convert, check and drip-feed ISO 6983-1 NC programs."""


for command in (parse, convert, check, plot, tape, classify, profiles, diff):
    main.add_command(command)
