"""The entry point's plain check (tapegate.launch): a ``check`` of files read without click
answers byte for byte as click's command does, reads its options as click does, and imports
neither click nor dataclasses."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import click
import pytest

from tapegate.check_cli import check
from tapegate.launch import CHECK_DEFAULTS, CHECK_OPTIONS, plain_check

ROOT = Path(__file__).resolve().parent.parent

# findings of each severity: a word after the motion it modifies, an unknown code, an arc whose
# K is not of its plane, no M30
BAD = "%\nN1 G71\nN2 X10. G01 F100.\nN3 G77 X20.\nN4 G02 X20 Y0 K5 F100\nN5 M03 S99999\n%\n"
GOOD = "%\nN1 G21 G90 G94\nN2 G01 X25.4 Y12.7 F254.\nN3 G02 X30. Y20. I5. J0\nN4 M30\n%\n"
# a comment outside ASCII and one holding an escape sequence (click strips it from a pipe)
ODD = "%\nN1 G21 (Fräser \x1b[31mrot\x1b[0m)\nN2 G01 X1. F100.\nN3 M30\n%\n"


@pytest.fixture
def place(tmp_path: Path) -> Path:
    (tmp_path / "bad.nc").write_text(BAD)
    (tmp_path / "good.nc").write_text(GOOD)
    (tmp_path / "odd.nc").write_text(ODD, encoding="utf-8")
    (tmp_path / "binary.nc").write_bytes(b"\x00\xff\xfe\x81" * 64)
    (tmp_path / "many").mkdir()
    for n in range(3):
        (tmp_path / "many" / f"p{n}.nc").write_text(BAD if n % 2 else GOOD)
    (tmp_path / "empty").mkdir()
    (tmp_path / "mill.toml").write_text('base = "iso-mill"\nname = "my-mill"\n')
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


@pytest.mark.parametrize(("argv", "plain"), FORMS, ids=[" ".join(a) for a, _ in FORMS])
def test_the_entry_point_answers_as_click_does(place: Path, argv: list[str],
                                               plain: bool) -> None:
    cwd = os.getcwd()
    os.chdir(place)
    try:
        assert (plain_check(argv) is not None) == plain
    finally:
        os.chdir(cwd)
    fast = _run(argv, place, through_click=False)
    slow = _run(argv, place, through_click=True)
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


def _click_option(name: str) -> click.Option:
    found = [p for p in check.params if isinstance(p, click.Option)
             and name in (*p.opts, *p.secondary_opts)]
    assert len(found) == 1, f"check has no option {name}"
    return found[0]


def test_every_option_read_without_click_is_clicks_own() -> None:
    """Each option of the entry point's table is one of click's ``check`` options: the same
    names, the same parameter, the same kind of value, choices and default -- so the two
    cannot drift apart."""
    for name, (key, how) in CHECK_OPTIONS.items():
        option = _click_option(name)
        assert option.name == key
        assert set(option.opts) == {n for n, (k, _) in CHECK_OPTIONS.items() if k == key}
        assert option.is_flag == (how == "flag")
        assert option.multiple == (how == "many")
        if isinstance(how, tuple):
            assert isinstance(option.type, click.Choice)
            assert tuple(option.type.choices) == how
        elif how == "positive":
            assert isinstance(option.type, click.IntRange)
            assert (option.type.min, option.type.max, option.type.min_open) == (1, None, False)
        elif how in ("value", "many"):
            assert option.type is click.STRING
    # the defaults: what click passes when no option is given
    clicks = check.make_context("check", ["bad.nc"]).params
    assert clicks.pop("files") == ("bad.nc",)
    assert clicks == CHECK_DEFAULTS


@pytest.mark.parametrize("options", [
    [], ["-p", "x"], ["-px"], ["--profile", "x"], ["--profile=x"], ["-p", "a", "--profile", "b"],
    ["--format", "sarif"], ["--format=jsonl"], ["--select", "TG1", "--select=TG2,TG3"],
    ["--ignore", "TG4"], ["--fail-on", "warning"], ["--stats"], ["-j", "3"], ["-j3"],
    ["--jobs", "12"], ["--jobs=1"], ["--stats", "--format", "json", "-p", "q", "-j2"],
])
def test_the_options_are_read_as_click_reads_them(place: Path, options: list[str]) -> None:
    cwd = os.getcwd()
    os.chdir(place)
    try:
        for argv in ([*options, "bad.nc"], ["bad.nc", *options], ["good.nc", *options, "many"]):
            ours = plain_check(["check", *argv])
            assert ours is not None
            assert ours == check.make_context("check", list(argv)).params
    finally:
        os.chdir(cwd)


def test_a_one_file_check_imports_neither_click_nor_dataclasses(place: Path) -> None:
    """The point of the entry point's own reading: click's import is half the start-up of a
    one-file check; ``dataclasses`` (with ``inspect``) waits until a record's fields are asked
    for (formats.records)."""
    code = ("import sys\nfrom tapegate.launch import main\n"
            "sys.argv = ['tapegate', 'check', 'bad.nc', '-p', 'iso-mill', '--format', 'json']\n"
            "try:\n    main()\nexcept SystemExit as exc:\n    code = exc.code\n"
            "print('MODULES', code, sorted(m for m in sys.modules if m.split('.')[0] in "
            "('click', 'dataclasses', 'inspect')))\n")
    done = subprocess.run([sys.executable, "-c", code], cwd=place, capture_output=True,
                          text=True, env={**os.environ, "PYTHONPATH": str(ROOT)}, check=False,
                          timeout=120)
    assert done.stdout.splitlines()[-1] == "MODULES 1 []"
    assert '"rule": "TG' in done.stdout
