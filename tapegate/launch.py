"""The ``tapegate`` command's entry point: a plain ``check`` of files is run without click.

Importing click is most of a one-file check's start-up: about 130M instructions of the 260M
of ``tapegate check FILE -p fanuc-mill``, more than LinuxCNC's ``rs274`` takes for the whole
program. A CAM programmer's CI runs that command once per file, so :func:`main` looks at the
arguments first: when they are ``check``, existing files or folders, and only the options of
:data:`CHECK_OPTIONS` in the forms click reads the same way, it reads them itself and calls
the command's body, :func:`tapegate.checking.run_check`, with the values click would pass.
Anything else -- another command, ``--help``, an option not in the table, ``--``, a missing
file or standard input (``-``), a value click would read otherwise (one starting with ``-``,
a choice not offered) -- goes to click's group (:data:`tapegate.cli.main`) unchanged, so
that click stays the one place that reads the rest and explains every usage error.

tests/test_launch.py holds the two together: every option of the table is one of click's
``check`` options with the same names, kind, choices and default, and a table of argument
forms (errors among them) answers the same, byte for byte, both ways.
"""

from __future__ import annotations

import os
import sys
from typing import Any

# check's options read here: each name -> (the parameter of ``run_check``, how its value is
# read): "value" (the next argument, or after "=" or, for a short name, attached), "many" (the
# same, repeatable: a tuple in order), "flag" (no value), "positive" (an integer >= 1), or a
# tuple of the choices. The defaults are click's (tests/test_launch.py compares both).
CHECK_OPTIONS: dict[str, tuple[str, str | tuple[str, ...]]] = {
    "-p": ("profile", "value"),
    "--profile": ("profile", "value"),
    "--format": ("fmt", ("text", "json", "jsonl", "sarif")),
    "--select": ("select", "many"),
    "--ignore": ("ignore", "many"),
    "--fail-on": ("fail_on", ("error", "warning")),
    "--stats": ("show_stats", "flag"),
    "-j": ("jobs", "positive"),
    "--jobs": ("jobs", "positive"),
}
CHECK_DEFAULTS: dict[str, Any] = {
    "profile": None, "fmt": "text", "select": (), "ignore": (), "fail_on": "error",
    "show_stats": False, "jobs": None,
}


def plain_check(args: list[str]) -> dict[str, Any] | None:
    """The keyword arguments of ``run_check`` for ``args`` (the command line after the
    program's name), or None when click is to read them."""
    if not args or args[0] != "check":
        return None
    params: dict[str, Any] = dict(CHECK_DEFAULTS)
    files: list[str] = []
    rest = iter(args[1:])
    for arg in rest:
        if not arg.startswith("-"):
            if not os.path.exists(arg):
                return None
            files.append(arg)
            continue
        name: str = arg
        attached: str | None = None  # a value given in the same argument
        if arg.startswith("--"):
            name, eq, given = arg.partition("=")
            attached = given if eq else None
        elif len(arg) > 2:  # -pNAME: a short option's value attached
            name, attached = arg[:2], arg[2:]
        found = CHECK_OPTIONS.get(name)
        if found is None:  # --help, --, -, another option: click's
            return None
        key, how = found
        if how == "flag":
            if attached is not None:
                return None
            params[key] = True
            continue
        value = attached if attached is not None else next(rest, None)
        if not value or value.startswith(("-", "=")):
            return None
        if how == "many":
            params[key] = (*params[key], value)
        elif how == "positive":
            if not (value.isascii() and value.isdigit()) or int(value) < 1:
                return None
            params[key] = int(value)
        elif isinstance(how, tuple) and value not in how:
            return None
        else:
            params[key] = value
    if not files:
        return None
    params["files"] = tuple(files)
    return params


def main(prog_name: str | None = None) -> None:
    """``tapegate``: a plain check (:func:`plain_check`) run here, anything else by click."""
    params = None if "_TAPEGATE_COMPLETE" in os.environ else plain_check(sys.argv[1:])
    if params is None:
        from tapegate.cli import main as group

        group(prog_name=prog_name)
        return
    from tapegate.checking import run_check
    from tapegate.common import prepare_streams

    prepare_streams()
    try:
        run_check(**params)
    except KeyboardInterrupt:  # as click's main tells it
        sys.stderr.write("\nAborted!\n")
        sys.exit(1)
    except Exception as exc:
        # a usage problem the check finds itself (a rule --select names that does not exist)
        # is click's exception: told as click's main tells it
        click = sys.modules.get("click")
        if click is None or not isinstance(exc, click.ClickException):
            raise
        exc.show()
        sys.exit(exc.exit_code)
