"""The entry point's plain commands (tapegate.launch): a ``check`` or ``convert`` of files read
without click answers byte for byte as click's command does (stdout, stderr, exit code, the
files it writes), reads its options as click does, and does not import click."""

from __future__ import annotations

import array
import fcntl
import json
import os
import shutil
import signal
import subprocess
import sys
import termios
import time
from pathlib import Path

import click
import pytest

from tapegate.check_cli import check
from tapegate.convert_cli import convert
from tapegate.launch import COMMANDS, plain

ROOT = Path(__file__).resolve().parent.parent

# findings of each severity: a word after the motion it modifies, an unknown code, an arc whose
# K is not of its plane, no M30
BAD = "%\nN1 G71\nN2 X10. G01 F100.\nN3 G77 X20.\nN4 G02 X20 Y0 K5 F100\nN5 M03 S99999\n%\n"
GOOD = "%\nN1 G21 G90 G94\nN2 G01 X25.4 Y12.7 F254.\nN3 G02 X30. Y20. I5. J0\nN4 M30\n%\n"
# a comment outside ASCII and one holding an escape sequence (click strips it from a pipe)
ODD = "%\nN1 G21 (Fräser \x1b[31mrot\x1b[0m)\nN2 G01 X1. F100.\nN3 M30\n%\n"
# 12 sequence numbers past haas-mill's N05 (TG208): the text report folds 7 of them
REPEATED = "%\nO1000\n" + "".join(f"N{100000 + 10 * n} G0 X{n}.\n" for n in range(12)) + "M30\n%\n"


@pytest.fixture
def place(tmp_path: Path) -> Path:
    (tmp_path / "bad.nc").write_text(BAD)
    (tmp_path / "good.nc").write_text(GOOD)
    (tmp_path / "odd.nc").write_text(ODD, encoding="utf-8")
    (tmp_path / "repeated.nc").write_text(REPEATED)
    (tmp_path / "binary.nc").write_bytes(b"\x00\xff\xfe\x81" * 64)
    (tmp_path / "many").mkdir()
    for n in range(3):
        (tmp_path / "many" / f"p{n}.nc").write_text(BAD if n % 2 else GOOD)
    (tmp_path / "empty").mkdir()
    (tmp_path / "mill.toml").write_text('base = "iso-mill"\nname = "my-mill"\n')
    (tmp_path / "old.nc").write_text("kept unless --force\n")
    return tmp_path


# (the arguments after ``tapegate``, read by the entry point itself?)
FORMS: list[tuple[list[str], bool]] = [
    (["check", "bad.nc", "-p", "iso-mill"], True),
    (["check", "bad.nc", "--profile", "iso-mill"], True),
    (["check", "bad.nc", "--profile=iso-mill"], True),
    (["check", "bad.nc", "-piso-mill"], True),
    (["check", "-p", "fanuc-mill", "bad.nc"], True),
    (["check", "bad.nc", "-p", "iso-mill", "-p", "fanuc-mill"], True),
    (["check", "bad.nc"], True),  # the neutral profile, told on stderr
    (["check", "good.nc", "-p", "fanuc-mill"], True),
    (["check", "odd.nc", "-p", "fanuc-mill"], True),
    (["check", "bad.nc", "-p", "mill.toml"], True),
    (["check", "bad.nc", "-p", "iso-mill", "--format", "json"], True),
    (["check", "bad.nc", "-p", "iso-mill", "--format=jsonl"], True),
    (["check", "bad.nc", "-p", "iso-mill", "--format", "sarif"], True),
    (["check", "bad.nc", "-p", "iso-mill", "--fail-on", "warning"], True),
    (["check", "good.nc", "-p", "iso-mill", "--fail-on=warning"], True),
    (["check", "bad.nc", "-p", "iso-mill", "--stats"], True),
    (["check", "bad.nc", "-p", "iso-mill", "--stats", "--format", "json"], True),
    (["check", "bad.nc", "-p", "iso-mill", "--all"], True),
    (["check", "repeated.nc", "-p", "haas-mill"], True),
    (["check", "repeated.nc", "-p", "haas-mill", "--all"], True),
    (["check", "many", "good.nc", "-p", "iso-mill", "--all", "-j", "2"], True),
    (["check", "bad.nc", "-p", "iso-mill", "--select", "TG4", "--ignore=TG401"], True),
    (["check", "bad.nc", "-p", "iso-mill", "--select", "TG1,TG4", "--select", "TG6"], True),
    (["check", "bad.nc", "good.nc", "-p", "iso-mill", "-j", "2"], True),
    (["check", "bad.nc", "good.nc", "odd.nc", "-p", "iso-mill", "-j1"], True),
    (["check", "many", "-p", "iso-mill", "--jobs=2", "--format", "json"], True),
    (["check", "many", "good.nc", "-p", "iso-mill"], True),
    # errors told by the shared body: an unknown profile, a file that is no program, a rule
    # that does not exist and an empty folder (click's usage error, raised by the body)
    (["check", "bad.nc", "-p", "nope"], True),
    (["check", "binary.nc", "-p", "iso-mill"], True),
    (["check", "bad.nc", "-p", "iso-mill", "--select", "TG9999"], True),
    (["check", "empty", "-p", "iso-mill"], True),
    # click's: anything the entry point does not read the way click does
    (["check", "missing.nc", "-p", "iso-mill"], False),
    (["check", "bad.nc", "-p", "iso-mill", "--format", "xml"], False),
    (["check", "bad.nc", "-p", "iso-mill", "-j", "0"], False),
    (["check", "bad.nc", "-p", "iso-mill", "-j", "+2"], False),
    (["check", "bad.nc", "-p", "iso-mill", "--stats=yes"], False),
    (["check", "bad.nc", "-p", "iso-mill", "--all=yes"], False),
    (["check", "bad.nc", "-p", "iso-mill", "--bogus"], False),
    (["check", "bad.nc", "-p"], False),
    (["check", "bad.nc", "-p", "--format", "json"], False),
    (["check", "bad.nc", "--profile="], False),
    (["check", "--", "bad.nc", "-p", "iso-mill"], False),
    (["check", "-h"], False),
    (["check", "bad.nc", "--help"], False),
    (["check"], False),
    (["check", "-p", "iso-mill"], False),
    (["--version"], False),
    (["profiles"], False),
    (["chek", "bad.nc"], False),
    # convert, read by the entry point: the output files are compared too
    (["convert", "good.nc", "-o", "out.nc", "--to", "fanuc-mill"], True),
    (["convert", "good.nc", "--output=out.nc", "--to=fanuc-mill", "--units", "inch"], True),
    (["convert", "good.nc", "-oout.nc", "--to", "fanuc-mill", "--units=inch", "--verify"], True),
    (["convert", "--to", "iso-mill", "good.nc", "-o", "out.nc", "--decimal", "implicit",
      "--zeros", "trailing"], True),
    (["convert", "good.nc", "-o", "out.nc", "--to", "iso-mill", "--from", "fanuc-mill",
      "--from-decimal", "increments", "--from-zeros=leading"], True),
    (["convert", "good.nc", "-o", "out.nc", "--to", "iso-mill", "--eob", "crlf",
      "--spacing", "insert", "--round", "error"], True),
    (["convert", "good.nc", "-o", "out.nc", "--to", "fanuc-mill", "--units", "inch",
      "--round=error"], True),  # a rounding refused: the file fails, exit 1
    (["convert", "good.nc", "-o", "out.nc", "--to", "mill.toml", "--to", "fanuc-mill",
      "--spacing=remove", "--eob=lf", "--round", "half-up"], True),
    (["convert", "many", "--out-dir", "out", "--to", "fanuc-mill", "-j", "2"], True),
    (["convert", "many", "good.nc", "--out-dir=out", "--to", "fanuc-mill", "-j1",
      "--units", "inch", "--jobs=2"], True),
    (["convert", "many", "--dry-run", "--to", "fanuc-mill", "--allow-unconverted"], True),
    (["convert", "many", "--dry-run", "--to", "fanuc-mill", "--units", "inch", "--verify",
      "--format", "json"], True),
    (["convert", "bad.nc", "-o", "out.nc", "--to", "iso-mill", "--format=json"], True),
    (["convert", "bad.nc", "odd.nc", "--out-dir", "out/deeper", "--to", "iso-mill"], True),
    (["convert", "good.nc", "-o", "old.nc", "--to", "fanuc-mill"], True),
    (["convert", "good.nc", "-o", "old.nc", "--to", "fanuc-mill", "--force"], True),
    # errors told by the shared body
    (["convert", "good.nc", "-o", "out.nc", "--to", "nope"], True),
    (["convert", "binary.nc", "-o", "out.nc", "--to", "fanuc-mill"], True),
    (["convert", "many", "-o", "out.nc", "--to", "fanuc-mill"], True),
    (["convert", "good.nc", "--to", "fanuc-mill"], True),
    (["convert", "good.nc", "-o", "o.nc", "--out-dir", "out", "--to", "fanuc-mill"], True),
    (["convert", "good.nc", "-o", "good.nc", "--to", "iso-mill"], True),
    (["convert", "empty", "--out-dir", "out", "--to", "fanuc-mill"], True),
    (["convert", "good.nc", "-o", "nowhere/out.nc", "--to", "fanuc-mill"], True),
    (["convert", "good.nc", "--out-dir", "good.nc/out", "--to", "fanuc-mill"], True),
    # click's
    (["convert", "missing.nc", "-o", "out.nc", "--to", "fanuc-mill"], False),
    (["convert", "*.nc", "--out-dir", "out", "--to", "fanuc-mill"], False),
    (["convert", "-", "-o", "out.nc", "--to", "fanuc-mill"], False),
    (["convert", "good.nc", "-o", "-", "--to", "fanuc-mill"], False),
    (["convert", "good.nc", "-o", "out.nc"], False),
    (["convert", "good.nc", "-o", "many", "--to", "fanuc-mill"], False),
    (["convert", "good.nc", "--out-dir", "bad.nc", "--to", "fanuc-mill"], False),
    (["convert", "good.nc", "-o", "out.nc", "--to", "fanuc-mill", "--units", "mm"], False),
    (["convert", "good.nc", "-o", "out.nc", "--to", "fanuc-mill", "--verify=1"], False),
    (["convert", "good.nc", "-o", "out.nc", "--to", "fanuc-mill", "-j", "0"], False),
    (["convert", "good.nc", "-o", "out.nc", "--to"], False),
    (["convert", "good.nc", "-o", "out.nc", "--to", "fanuc-mill", "-p", "iso-mill"], False),
    (["convert", "good.nc", "-o", "out.nc", "--to", "fanuc-mill", "--"], False),
    (["convert", "-h"], False),
    (["convert", "good.nc", "--help"], False),
    (["convert"], False),
]


def _run(argv: list[str], cwd: Path, *, through_click: bool) -> tuple[bytes, bytes, int]:
    code = ("from tapegate.cli import main; main(prog_name='tapegate')" if through_click
            else "from tapegate.launch import main; main(prog_name='tapegate')")
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    env.pop("_TAPEGATE_COMPLETE", None)
    done = subprocess.run([sys.executable, "-c", code, *argv], cwd=cwd, env=env,
                          capture_output=True, stdin=subprocess.DEVNULL, timeout=120,
                          check=False)
    return done.stdout, done.stderr, done.returncode


def _files(folder: Path) -> dict[str, bytes]:
    """Every file below ``folder`` and its bytes."""
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file()}


@pytest.mark.parametrize(("argv", "read_here"), FORMS, ids=[" ".join(a) for a, _ in FORMS])
def test_the_entry_point_answers_as_click_does(place: Path,
                                               tmp_path_factory: pytest.TempPathFactory,
                                               argv: list[str], read_here: bool) -> None:
    cwd = os.getcwd()
    os.chdir(place)
    try:
        assert (plain(argv) is not None) == read_here
    finally:
        os.chdir(cwd)
    # each way in its own copy of the folder: what one writes is compared with the other's
    answers = []
    for through_click in (False, True):
        here = tmp_path_factory.mktemp("copy") / "place"
        shutil.copytree(place, here)
        answers.append((*_run(argv, here, through_click=through_click), _files(here)))
    fast, slow = answers
    assert fast == slow
    assert b"Traceback" not in fast[1]


def test_the_answers_compared_are_the_real_ones(place: Path) -> None:
    """The comparison above compares what it should: findings on stdout, the summary on
    stderr, the exit codes of findings and of usage errors."""
    out, err, code = _run(["check", "bad.nc", "-p", "iso-mill"], place, through_click=False)
    assert code == 1
    assert b"bad.nc:3:" in out and b"TG" in out
    assert err.startswith(b"1 file checked: ") and b"error" in err
    out, err, code = _run(["check", "bad.nc", "-p", "iso-mill", "--select", "TG9999"], place,
                          through_click=False)
    assert (out, err, code) == (b"", b"Error: no rule TG9999; see docs/rules.md\n", 2)
    out, err, code = _run(["check", "empty", "-p", "iso-mill"], place, through_click=False)
    assert (err, code) == (b"Error: no file to check in empty\n", 2)
    out, err, code = _run(["check", "odd.nc", "-p", "fanuc-mill"], place, through_click=False)
    assert b"\x1b" not in out + err  # stripped from a pipe, as click strips it


def test_the_answers_of_a_conversion_compared_are_the_real_ones(place: Path) -> None:
    """The same for ``convert``: the table on stdout, the converted file written, the errors
    of a conversion and of usage."""
    out, err, code = _run(["convert", "good.nc", "-o", "out.nc", "--to", "fanuc-mill",
                           "--units", "inch"], place, through_click=False)
    assert code == 0 and err.count(b"good.nc: source: ") == 2
    assert out.splitlines()[0].split() == [b"file", b"blocks", b"words", b"changed",
                                           b"largest", b"rounding", b"result"]
    assert b"X1. Y0.5 F10." in (place / "out.nc").read_bytes()
    out, err, code = _run(["convert", "good.nc", "-o", "old.nc", "--to", "fanuc-mill"], place,
                          through_click=False)
    assert code == 1 and b"FAILED" in out and b"old.nc" in err
    assert (place / "old.nc").read_text() == "kept unless --force\n"
    out, err, code = _run(["convert", "many", "-o", "out.nc", "--to", "fanuc-mill"], place,
                          through_click=False)
    assert (out, err, code) == (
        b"", b"Error: -o names one output file; use --out-dir for several inputs\n", 2)


def _click_option(command: click.Command, name: str) -> click.Option:
    found = [p for p in command.params if isinstance(p, click.Option)
             and name in (*p.opts, *p.secondary_opts)]
    assert len(found) == 1, f"{command.name} has no option {name}"
    return found[0]


@pytest.mark.parametrize(("command", "argument"), [(check, "bad.nc"), (convert, "good.nc")],
                         ids=["check", "convert"])
def test_every_option_read_without_click_is_clicks_own(command: click.Command,
                                                       argument: str) -> None:
    """Each option of the entry point's table is one of click's options of the command: the
    same names, the same parameter, the same kind of value, choices and default -- so the two
    cannot drift apart; the options click requires are those the entry point requires."""
    assert command.name is not None
    options, defaults, positional, required, _ = COMMANDS[command.name]
    for name, (key, how) in options.items():
        option = _click_option(command, name)
        assert option.name == key
        assert set(option.opts) == {n for n, (k, _) in options.items() if k == key}
        assert option.is_flag == (how == "flag")
        assert option.multiple == (how == "many")
        if isinstance(how, tuple):
            assert isinstance(option.type, click.Choice)
            assert tuple(option.type.choices) == how
        elif how == "positive":
            assert isinstance(option.type, click.IntRange)
            assert (option.type.min, option.type.max, option.type.min_open) == (1, None, False)
        elif how in ("file", "folder"):
            assert isinstance(option.type, click.Path)
            kind = option.type
            assert (kind.exists, kind.readable, kind.writable, kind.executable,
                    kind.resolve_path, kind.file_okay, kind.dir_okay) == (
                False, True, False, False, False, how == "file", how == "folder")
        elif how in ("value", "many"):
            assert option.type is click.STRING
    assert {p.name for p in command.params if isinstance(p, click.Option)
            and p.name != "help"} == {key for key, _ in options.values()}
    assert tuple(p.name for p in command.params if p.required
                 and isinstance(p, click.Option)) == required
    # the defaults: what click passes when no option is given (a required one: its value)
    given = [f"--{k.split('_')[0]}=x" for k in required]
    clicks = command.make_context(command.name, [argument, *given]).params
    assert clicks.pop(positional) == (argument,)
    assert clicks == {**defaults, **dict.fromkeys(required, "x")}


@pytest.mark.parametrize(("command", "options"), [
    *((check, o) for o in [
        [], ["-p", "x"], ["-px"], ["--profile", "x"], ["--profile=x"],
        ["-p", "a", "--profile", "b"], ["--format", "sarif"], ["--format=jsonl"],
        ["--select", "TG1", "--select=TG2,TG3"], ["--ignore", "TG4"], ["--fail-on", "warning"],
        ["--stats"], ["--all"], ["-j", "3"], ["-j3"], ["--jobs", "12"], ["--jobs=1"],
        ["--stats", "--format", "json", "-p", "q", "-j2"], ["--all", "--stats", "-j1"]]),
    *((convert, ["--to", "t", *o]) for o in [
        [], ["--to=u"], ["-o", "x.nc"], ["-ox.nc"], ["--output", "x.nc"], ["--output=x.nc"],
        ["-o", "good.nc"], ["--out-dir", "out"], ["--out-dir=many"], ["--from", "f"],
        ["--from-decimal", "increments"], ["--from-zeros=none"], ["--decimal", "implicit"],
        ["--zeros", "leading"], ["--units", "inch"], ["--units=metric"], ["--eob", "crlf"],
        ["--spacing", "remove"], ["--round", "error"], ["--round=half-up"],
        ["--allow-unconverted"], ["--verify"], ["--dry-run"], ["--force"], ["-j2"],
        ["--jobs", "4"], ["--dry-run", "--verify", "-j", "1", "--units", "inch", "--force"]]),
], ids=lambda v: " ".join(v) if isinstance(v, list) else v.name)
def test_the_options_are_read_as_click_reads_them(place: Path, command: click.Command,
                                                  options: list[str]) -> None:
    """What the entry point passes the command's body is what click passes: the options in
    every place among the files, repeated ones the last (or, for ``many``, all)."""
    assert command.name is not None
    cwd = os.getcwd()
    os.chdir(place)
    try:
        for argv in ([*options, "bad.nc"], ["bad.nc", *options], ["good.nc", *options, "many"]):
            ours = plain([command.name, *argv])
            assert ours is not None
            body, params = ours
            assert body == COMMANDS[command.name][4]
            assert params == command.make_context(command.name, list(argv)).params
    finally:
        os.chdir(cwd)


@pytest.mark.parametrize(("argv", "unused", "shown"), [
    (["check", "bad.nc", "-p", "iso-mill", "--format", "json"],
     ("click", "dataclasses", "inspect"), '"rule": "TG'),
    (["convert", "good.nc", "-o", "out.nc", "--to", "fanuc-mill", "--units", "inch"],
     ("click",), "total: 1 file "),
    # a batch to a profile file: no pathlib (with urllib.parse and ipaddress) and no
    # threading, 22M instructions of its start-up (docs/benchmarks.md, "the commits without
    # the GIL")
    (["convert", "many", "--out-dir", "out", "--force", "--to", "target.toml", "-j", "2"],
     ("click", "pathlib", "threading", "urllib", "ipaddress"), "total: 3 files "),
    # a batch with a change of units, so with roundings, its source's format given: no
    # fractions and no decimal (with numbers), no re (with enum, collections, functools),
    # whose imports were most of what was left of its serial start-up; the largest rounding
    # is written from the exact integers, a tape's patterns compiled when a tape is read
    # (docs/benchmarks.md, perf40)
    (["convert", "many", "--out-dir", "out", "--force", "--from", "fanuc-mill", "--to",
      "target.toml", "--units", "inch", "-j", "2"],
     ("click", "pathlib", "threading", "fractions", "decimal", "_decimal", "numbers", "re",
      "enum", "collections", "functools"),
     "I 0.0000497"),
], ids=["check", "convert", "convert-batch", "convert-batch-units"])
def test_a_plain_command_does_not_import_click(place: Path, argv: list[str],
                                               unused: tuple[str, ...], shown: str) -> None:
    """The point of the entry point's own reading: click's import is half the start-up of a
    one-file check or conversion; for the check, ``dataclasses`` (with ``inspect``) waits
    until a record's fields are asked for (formats.records; the converter's own classes are
    dataclasses)."""
    (place / "target.toml").write_text('base = "fanuc-mill"\nname = "target"\n')
    code = ("import sys\nfrom tapegate.launch import main\n"
            f"sys.argv = ['tapegate', *{argv!r}]\n"
            "try:\n    main(clean_exit=True)\nexcept SystemExit as exc:\n    code = exc.code\n"
            "else:\n    code = 0\n"
            "print('MODULES', code, sorted(m for m in sys.modules if m.split('.')[0] in "
            f"{unused!r}))\n")
    done = subprocess.run([sys.executable, "-c", code], cwd=place, capture_output=True,
                          text=True, env={**os.environ, "PYTHONPATH": str(ROOT)}, check=False,
                          timeout=120)
    assert done.stdout.splitlines()[-1] == f"MODULES {1 if argv[0] == 'check' else 0} []"
    assert shown in done.stdout


# A caller that marks the interpreter's finalization (a module object's __del__), then runs the
# command as the console script does: main() as the script's last statement.
FINALIZED = """
import atexit, os, sys
class Mark:
    def __del__(self, os=os):  # (os bound: the module's globals may be gone by then)
        os.close(os.open({marker!r}, os.O_WRONLY | os.O_CREAT, 0o600))
mark = Mark()
{register}
sys.argv = ["tapegate", *{argv!r}]
from tapegate.launch import main
main(clean_exit={clean!r})
"""


@pytest.mark.parametrize(("argv", "code"), [
    (["check", "many", "-p", "iso-mill", "--format", "json", "-j", "2"], 1),
    (["check", "good.nc", "-p", "fanuc-mill", "--format", "json"], 1),
    (["convert", "many", "--out-dir", "out", "--force", "--to", "fanuc-mill", "-j", "2"], 0),
], ids=["check-j2", "check-one", "convert-j2"])
def test_a_plain_command_ends_without_the_interpreters_finalization(
        place: Path, argv: list[str], code: int) -> None:
    """The command's exit code and its whole output, flushed, and no finalization after it
    (tapegate.launch.leave: freeing every module's objects is the last serial step of a
    batch); with ``clean_exit`` or a function registered with ``atexit`` (coverage, a probe),
    the interpreter's own exit, finalization and all, with the same answer."""
    (place / "out").mkdir()
    answers = []
    for clean, register in ((False, ""), (True, ""),
                            (False, "atexit.register(lambda: print('at exit'))")):
        marker = place / "finalized.txt"
        marker.unlink(missing_ok=True)
        script = FINALIZED.format(marker=str(marker), register=register, argv=argv,
                                  clean=clean)
        done = subprocess.run([sys.executable, "-c", script], cwd=place, capture_output=True,
                              text=True, env={**os.environ, "PYTHONPATH": str(ROOT)},
                              check=False, timeout=120)
        assert done.returncode == code, done.stderr
        assert marker.exists() == (clean or bool(register))
        stdout = done.stdout.removesuffix("at exit\n") if register else done.stdout
        assert not register or done.stdout.endswith("at exit\n")
        if "--format" in argv:
            assert json.loads(stdout)["findings"] is not None  # the report, whole
        answers.append((stdout, done.stderr))
    assert answers[0] == answers[1] == answers[2]
    if argv[0] == "convert":
        assert sorted(p.name for p in (place / "out").iterdir()) == ["p0.nc", "p1.nc", "p2.nc"]


@pytest.mark.parametrize(("argv", "code"), [
    (["check", "many", "-p", "iso-mill", "--format", "json", "-j", "2"], 1),
    (["convert", "many", "--out-dir", "out", "--force", "--to", "fanuc-mill", "-j", "2"], 0),
], ids=["check-j2", "convert-j2"])
def test_a_thread_not_a_daemon_still_running_gets_the_interpreters_exit(
        place: Path, argv: list[str], code: int) -> None:
    """A caller's thread that is no daemon, still running when the command is done: the
    interpreter's own exit, which waits for it (its output is there, after the command's) and
    finalizes, with the command's exit code (tapegate.launch.leave returns)."""
    (place / "out").mkdir()
    marker = place / "finalized.txt"
    register = ("import threading, time\n"
                "threading.Thread(target=lambda: (time.sleep(1), print('thread done')),"
                " daemon=False).start()")
    script = FINALIZED.format(marker=str(marker), register=register, argv=argv, clean=False)
    done = subprocess.run([sys.executable, "-c", script], cwd=place, capture_output=True,
                          text=True, env={**os.environ, "PYTHONPATH": str(ROOT)},
                          check=False, timeout=120)
    assert done.returncode == code, done.stderr
    assert done.stdout.endswith("thread done\n") and marker.exists()
    if "--format" in argv:
        assert json.loads(done.stdout.removesuffix("thread done\n"))["findings"]


def test_a_closed_pipe_ends_as_the_interpreter_ends_it(place: Path) -> None:
    """A flush that fails at the end (the reader gone) is left to the interpreter's exit, which
    tells it as before (tapegate.launch.leave returns): the same exit code and message as with
    ``clean_exit``."""
    (place / "big").mkdir()
    for n in range(40):
        (place / "big" / f"p{n}.nc").write_text(BAD * 200)
    answers = []
    for clean in (False, True):
        script = ("import sys\nfrom tapegate.launch import main\n"
                  "sys.argv = ['tapegate', 'check', 'big', '-p', 'iso-mill', '-j', '2']\n"
                  f"main(clean_exit={clean!r})\n")
        reader = subprocess.Popen([sys.executable, "-c", script], cwd=place,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                  env={**os.environ, "PYTHONPATH": str(ROOT)})
        assert reader.stdout is not None and reader.stderr is not None
        reader.stdout.read(100)
        reader.stdout.close()
        stderr = reader.stderr.read()
        answers.append((reader.wait(timeout=120), stderr))
    assert answers[0] == answers[1]


def test_the_collector_is_off_for_the_start_up_only() -> None:
    """tapegate.launch.pause_collector turns the cyclic collector off for a plain command's
    start-up, resume_collector turns it back on with what the start-up made frozen out of
    its reach, and thaw gives that back to it (before the interpreter's own exit); a collector
    already off (a caller's choice) is left off."""
    import gc

    from tapegate.launch import pause_collector, resume_collector, thaw

    assert gc.isenabled()
    frozen = gc.get_freeze_count()
    try:
        pause_collector()
        assert not gc.isenabled()
        made = [[n] for n in range(1000)]  # objects the collector tracks
        resume_collector()
        assert gc.isenabled()
        assert gc.get_freeze_count() >= frozen + len(made)  # out of its reach
        thaw()
        assert gc.get_freeze_count() == 0
        pause_collector()  # a body that ends before it turns the collector on
        thaw()
        assert gc.isenabled()
        gc.disable()
        resume_collector()  # once only: the collector the caller turned off stays off
        assert not gc.isenabled()
        pause_collector()
        resume_collector()
        assert not gc.isenabled()
    finally:
        gc.unfreeze()
        gc.enable()


COLLECTOR_PROBE = """
import gc, sys
from postproc.check import Checker
seen = []
report_file = Checker.report_file
def probe(self, path, write, *rest):
    seen.append(gc.isenabled())
    return report_file(self, path, write, *rest)
Checker.report_file = probe
sys.argv = ["tapegate", *{argv!r}]
from tapegate.launch import main
try:
    main(clean_exit=True)
finally:
    print("COLLECTOR", seen, file=sys.stderr)
"""


@pytest.mark.parametrize("argv", [
    ["check", "many", "-p", "iso-mill", "-j", "2"],
    ["check", "good.nc", "-p", "iso-mill"],
])
def test_the_files_are_checked_with_the_collector_on(place: Path, argv: list[str]) -> None:
    """The collector is on again for every file's work, in the threads and in one: cycles a
    file's work leaves are freed, and memory stays flat."""
    done = subprocess.run([sys.executable, "-c", COLLECTOR_PROBE.format(argv=argv)], cwd=place,
                          capture_output=True, text=True,
                          env={**os.environ, "PYTHONPATH": str(ROOT)}, check=False, timeout=120)
    files = 3 if "many" in argv else 1
    assert done.stderr.splitlines()[-1] == f"COLLECTOR {[True] * files}", done.stderr


def test_a_body_that_fails_before_its_files_leaves_the_collector_on(place: Path) -> None:
    """A plain command whose body stops before the collector is turned back on (a rule that
    does not exist, a profile that cannot be read) hands a caller that goes on
    (``clean_exit``) the collector as it found it: on."""
    script = ("import gc, sys\nfrom tapegate.launch import main\n"
              "sys.argv = ['tapegate', *sys.argv[1:]]\n"
              "try:\n    main(clean_exit=True)\nexcept SystemExit as exc:\n"
              "    print('EXIT', exc.code, gc.isenabled(), gc.get_freeze_count())\n")
    for argv in (["check", "bad.nc", "-p", "no-such-profile"],
                 ["check", "bad.nc", "-p", "iso-mill", "--select", "TG999"],
                 ["check", "bad.nc", "-p", "iso-mill"]):
        done = subprocess.run([sys.executable, "-c", script, *argv], cwd=place,
                              capture_output=True, text=True, check=False, timeout=120,
                              env={**os.environ, "PYTHONPATH": str(ROOT)})
        last = done.stdout.splitlines()[-1].split()
        assert last[0] == "EXIT" and last[1] in ("1", "2"), done.stdout + done.stderr
        assert last[2:] == ["True", "0"], (argv, done.stdout)


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM])
def test_a_command_stopped_while_its_reader_does_not_read_ends(place: Path, signum: int) -> None:
    """^C or SIGTERM to a check whose report waits on a pipe nobody reads (a pager left open,
    a job runner's pipe): the command ends with ^C's 1 or SIGTERM's 143, the rest of the
    report unwritten (tapegate.launch.leave, ``stopped``). Before, the exit's flush waited on
    the full pipe for ever and the stop was not obeyed (CI: a `convert -o -` stopped so hung
    past its timeout)."""
    code = _stopped_on_a_full_pipe(place, ["check", "big", "-p", "iso-mill", "-j", "2"], signum,
                                   subprocess.DEVNULL, 60)
    assert code == (1 if signum == signal.SIGINT else 128 + signal.SIGTERM)


def _big(place: Path) -> None:
    """``place/big``: 40 programs whose report fills a pipe many times."""
    (place / "big").mkdir()
    for n in range(40):
        (place / "big" / f"p{n}.nc").write_text(BAD * 400)


def _stopped_on_a_full_pipe(place: Path, argv: list[str], signum: int, stderr: int,
                            timeout: float) -> int:
    """The exit code of ``tapegate ARGV`` (run in ``place`` on :func:`_big`'s folder, SIGTERM
    made an exit as the command makes it) given ``signum`` once its report has filled its
    standard output, a pipe nobody reads, so that it waits in its write; ``stderr`` its
    standard error (``subprocess.STDOUT``: the same full pipe). Killed past ``timeout``
    seconds (TimeoutExpired raised), its pipe closed either way."""
    from tests.test_convert_interrupt import ended

    _big(place)
    script = ("import sys\nfrom tapegate.launch import main\n"
              "from formats.files import exit_on_termination\nexit_on_termination()\n"
              f"sys.argv = ['tapegate', *{argv!r}]\nmain()\n")
    proc = subprocess.Popen([sys.executable, "-c", script], cwd=place, stdout=subprocess.PIPE,
                            stderr=stderr, env={**os.environ, "PYTHONPATH": str(ROOT)},
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    assert proc.stdout is not None
    try:
        deadline = time.monotonic() + 60
        while not _full(proc.stdout.fileno()):
            assert proc.poll() is None, "the report ended before it filled the pipe"
            assert time.monotonic() < deadline, "the command never filled the pipe"
            time.sleep(0.01)
        proc.send_signal(signum)
    except BaseException:
        proc.kill()
        ended(proc, 60)
        raise
    return ended(proc, timeout)[0]


def _full(fd: int) -> bool:
    """Whether the pipe read by ``fd`` holds all it can (Linux: its size, F_GETPIPE_SZ)."""
    waiting = array.array("i", [0])
    fcntl.ioctl(fd, termios.FIONREAD, waiting)
    return waiting[0] >= fcntl.fcntl(fd, fcntl.F_GETPIPE_SZ)


@pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="needs Linux's /proc")
@pytest.mark.parametrize(("argv", "signum"), [
    (["check", "big", "-p", "iso-mill", "-j", "1"], signal.SIGINT),
    (["check", "big", "-p", "iso-mill", "--format", "jsonl"], signal.SIGTERM),
    (["check", "big", "-p", "iso-mill", "--format", "jsonl"], signal.SIGINT)],
    ids=["plain-int", "click-term", "click-int"])
def test_a_check_whose_report_waits_on_a_full_pipe_ends_at_a_signal_that_interrupts_nothing(
        place: Path, argv: list[str], signum: int) -> None:
    """The lost wake-up of a report written into a pipe nobody reads: a SIGTERM whose C
    handler runs just before the write's system call (here: handed to another thread of the
    command, tests/test_convert_interrupt.py, AIMED) left the write blocked for ever (a plain
    check with one job leaves SIGTERM's default action, which ends it anyway). Standard
    output, a pipe, is written by way of a poll that the signal's wakeup fd ends
    (formats.stops.guard_stdout), by a plain check and by one click reads alike."""
    from tests.test_convert_interrupt import AIMED, ended

    _big(place)
    script = AIMED.format(signum=int(signum), argv=argv)
    proc = subprocess.Popen([sys.executable, "-c", script], cwd=place, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, env={**os.environ, "PYTHONPATH": str(ROOT)},
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    code, err = ended(proc, 30)
    assert err.startswith(b"aimed\n"), err
    assert code == (1 if signum == signal.SIGINT else 128 + signum), err


@pytest.mark.parametrize("argv", [
    ["check", "-p", "iso-mill", "-j", "2", "--", "big"],
    ["check", "-p", "iso-mill", "--format", "jsonl", "--", "big"]], ids=["text", "jsonl"])
def test_a_command_click_reads_stopped_with_stderr_in_its_full_pipe_ends(
        place: Path, argv: list[str]) -> None:
    """^C to a command click parses (``--`` before the files) whose stdout and stderr are one
    pipe nobody reads (``2>&1 | less`` left open): it ends with ^C's 1, "Aborted!" written
    only if stderr takes it at once, as on the plain path. Before, click's own write of it
    waited on the full pipe for ever (review 62c F3)."""
    code = _stopped_on_a_full_pipe(place, argv, signal.SIGINT, subprocess.STDOUT, 30)
    assert code == 1


@pytest.mark.parametrize("argv", [
    ["check", "good.nc", "-p", "iso-mill"],  # the plain path
    ["check", "good.nc", "-p", "iso-mill", "--format", "sarif"],
    ["convert", "good.nc", "-p", "iso-mill", "-o", "out.nc"],  # writes no stdout: refused too
    ["--version"],  # click's path
])
def test_a_closed_standard_output_is_refused_with_a_reason(place: Path, argv: list[str]) -> None:
    """``>&-`` leaves Python no stdout: every command stops before any work, exit 2, with the
    reason on stderr and no traceback (main wrote a traceback, or nothing, exit 1)."""
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run([sys.executable, "-m", "tapegate", *argv], cwd=place, env=env,
                          stdin=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=60,
                          preexec_fn=lambda: os.close(1))
    assert done.returncode == 2
    assert done.stderr == (b"tapegate: error: standard output is closed:"
                           b" give it a file or /dev/null\n")
    assert not (place / "out.nc").exists()
