"""The ``tapegate`` command line: options in, library calls, results out -- no work of its own.

The group is assembled here from one module per command group: ``parse_cli``, ``convert_cli``,
``check_cli`` (check, plot), ``diff_cli``, ``tape_cli``, ``profiles_cli`` (classify, profiles),
``serial_cli`` (send, receive, journal, emulate) and ``serve_cli``. What they share -- file
arguments, the profile, and the one mapping of errors to messages and exit codes -- is in
:mod:`tapegate.common` (click's parts, the profile option and the usage error, in
:mod:`tapegate.options`). The installed command enters through :mod:`tapegate.launch`, which
runs a plain ``check`` of files without importing click and hands everything else to this
group. Exit codes: 0 done, 1 the input is bad (parse, tape, conversion or
check findings), 2 usage error or unreadable file, 3 the link failed.
"""

from __future__ import annotations

import click


class LazyGroup(click.Group):
    """A group whose commands are imported when they are used (click's documented pattern for
    lazy subcommands): ``check`` loads its own module and what it uses, not the converter's,
    the diff's (json), pyserial, pymodbus or the DNC layer. ``--help`` imports them all."""

    LAZY = {
        "parse": "tapegate.parse_cli:parse",
        "convert": "tapegate.convert_cli:convert",
        "check": "tapegate.check_cli:check",
        "plot": "tapegate.check_cli:plot",
        "tape": "tapegate.tape_cli:tape",
        "classify": "tapegate.profiles_cli:classify",
        "profiles": "tapegate.profiles_cli:profiles",
        "diff": "tapegate.diff_cli:diff",
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
    from tapegate.common import prepare_streams

    prepare_streams()
