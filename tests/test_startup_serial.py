"""What a check of a folder with two workers has done when it starts its first thread: the
serial part of ``check -j`` that its threads cannot share (docs/benchmarks.md, "the serial
start-up without enum"). Neither ``enum`` (formats.choices) nor the rules' records
(postproc.rules.RULES, made when first asked for) nor ``threading`` (the workers run on
``_thread``) nor ``functools`` are among it; the output is the same."""

from __future__ import annotations

import ast
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PROGRAM = "%\nN1 G21 G90\nN2 G00 X1.\nN3 M30\n%\n"

# Run as the tapegate command with the given arguments; at its first thread's start (the
# workers' threads are _thread's: tapegate.workers), print the modules loaded and whether
# postproc.rules has made its RULES yet, and end (printed by repr: json would import re, and
# re enum).
PROBE = """\
import _thread, os, sys
def stop(*args):
    rules = sys.modules.get("postproc.rules")
    made = rules is not None and "RULES" in vars(rules)
    print(repr({"modules": sorted(sys.modules), "rules_made": made}), flush=True)
    os._exit(0)
_thread.start_new_thread = stop
sys.argv = ["tapegate", *sys.argv[1:]]
from tapegate.launch import main
main()
"""


def _at_first_thread(*args: str) -> dict[str, object]:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    for _ in range(2):  # the first may parse the profile's TOML (tomllib imports re and enum)
        done = subprocess.run([sys.executable, "-P", "-c", PROBE, *args], env=env,
                              capture_output=True, text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    found: dict[str, object] = ast.literal_eval(done.stdout)
    return found


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    for n in range(3):
        (tmp_path / f"p{n}.nc").write_text(PROGRAM)
    return tmp_path


@pytest.mark.parametrize("fmt", ["json", "text", "jsonl"])
def test_a_check_starts_its_threads_without_enum_or_the_rules_records(folder, fmt):
    found = _at_first_thread("check", str(folder), "-p", "fanuc-mill", "-j", "2", "--format", fmt)
    modules = found["modules"]
    assert isinstance(modules, list)
    # the probe stopped where the threads start, after the check's own modules
    assert "tapegate.workers" in modules and "formats.profile_cache" in modules
    # the built-in profile read back as the cache keeps it for a check (its second run): its
    # machine spec and dialect flags, without the profile's modules (jobs62)
    for module in ("formats.profile", "formats.classification", "formats.codes",
                   "formats.parser", "formats.wordformat", "formats.machine", "formats.exact",
                   "zlib"):
        assert module not in modules
    assert "postproc.rules" in modules
    assert "enum" not in modules
    assert "threading" not in modules  # the workers on _thread's locks and threads
    assert "functools" not in modules and "types" not in modules
    assert "decimal" not in modules  # the profile's numbers kept as texts (formats.exact)
    # nor collections (postproc.findings' tuple written out, collections.abc's names taken
    # from _collections_abc, loaded with os)
    assert "collections" not in modules and "collections.abc" not in modules
    assert found["rules_made"] is False


def test_select_makes_the_rules_records_before_the_threads(folder):
    """--select names rules: the records are made to read it (and a wrong one is refused)."""
    found = _at_first_thread("check", str(folder), "-p", "fanuc-mill", "-j", "2",
                             "--select", "TG1")
    assert found["rules_made"] is True
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, "-P", "-m", "tapegate", "check", str(folder), "-p",
                           "fanuc-mill", "-j", "2", "--select", "TG999"], env=env,
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 2 and "no rule TG999" in done.stderr


def test_the_rules_records_are_made_once_at_the_first_ask():
    """In a fresh interpreter: postproc.rules imported makes no record; the first ask makes
    RULES and READING_RULES, kept as the module's; the catalogue reads the same."""
    code = """\
import postproc.rules as r
assert "RULES" not in vars(r) and "READING_RULES" not in vars(r)
rules = r.RULES
assert vars(r)["RULES"] is rules and r.RULES is rules
assert r.READING_RULES == frozenset(x.id for x in rules.values() if x.reading)
assert [x[1] for x in r.CORE_RULES] == list(rules)
assert r.markdown().count("\\n## TG") == len(rules)
try:
    r.NOT_THERE
except AttributeError as exc:
    assert "NOT_THERE" in str(exc)
else:
    raise AssertionError("no AttributeError")
print("ok")
"""
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, "-P", "-c", code], env=env, capture_output=True,
                          text=True, timeout=60)
    assert done.returncode == 0, done.stderr
    assert done.stdout == "ok\n"


def test_a_commands_wrapper_reads_as_functools_wraps_leaves_it():
    """tapegate.common's error wrapper (without functools): the command's name, docstring,
    annotations, module, the attributes click set on it, and __wrapped__, as wraps gives."""
    import functools

    import click

    from tapegate.common import user_errors

    @click.option("--n", type=int, default=1)
    def command(n: int) -> int:
        """What it does."""
        return n

    ours = user_errors(command)

    def theirs() -> None:
        pass

    functools.update_wrapper(theirs, command)
    for name in ("__module__", "__name__", "__qualname__", "__doc__", "__annotations__",
                 "__wrapped__"):
        assert getattr(ours, name) == getattr(theirs, name), name
    assert ours.__dict__ == theirs.__dict__ and "__click_params__" in ours.__dict__
    assert ours(n=3) == 3
    assert click.command()(ours).params[0].name == "n"
