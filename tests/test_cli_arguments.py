"""Every command, as a new user meets it: a missing, an empty, a binary and a directory argument
where a file is read, a directory and an unwritable path where one is written. Each gets one
clear message, the documented exit code (0 done, 1 the input is bad, 2 usage or a file that
cannot be read or written, 3 the link failed; see README.md) and never a traceback.

The commands are listed from the click group itself (the lazy ones included), and every one
must have its rows below: a command added later fails :func:`test_every_command_is_covered`
until its arguments are tried too. The rows run in-process (click's CliRunner); a few run
``python -m tapegate`` to prove that the real entry point shows no traceback either.
"""

from __future__ import annotations

import importlib.util
import os
import re
import subprocess
import sys
from pathlib import Path

import click
import pytest
from click.testing import CliRunner

from tapegate.cli import main

pytestmark = pytest.mark.timeout(60)

GOOD = "%\nO1\nG01 X1. F100.\nM30\n%\n"

# The argument kinds. Files read: missing, empty, binary, directory. Files written: directory,
# unwritable (a path under a regular file: not writable even by root).
READ = ("missing", "empty", "binary", "directory")
WRITE = ("directory", "unwritable")


def commands(group: click.Group = main, prefix: tuple[str, ...] = ()) -> list[str]:
    """Every command of the group, subcommands as ``tape encode``; a group that runs on its
    own (``profiles``) is a command too."""
    ctx = click.Context(group)
    found: list[str] = []
    for name in group.list_commands(ctx):
        command = group.get_command(ctx, name)
        assert command is not None, name
        path = (*prefix, name)
        if isinstance(command, click.Group):
            if command.invoke_without_command:
                found.append(" ".join(path))
            found += commands(command, path)
        else:
            found.append(" ".join(path))
    return found


# (command, argv with {} for the argument tried, kind, exit code, pattern the output must match)
# A file read
ROWS: list[tuple[str, list[str], str, int, str]] = []


def reads(command: str, argv: list[str], *expected: tuple[str, int, str]) -> None:
    for kind, code, pattern in expected:
        ROWS.append((command, argv, kind, code, pattern))


writes = reads

NOT_FOUND = ("missing", 2, r"cannot read \S*nope\S*: No such file or directory")
IS_DIR = ("directory", 2, r"is a directory")
UNWRITABLE_FOLDER = ("unwritable", 2, r"cannot write \S*afile/out\S*: \S*afile is not a folder")

reads("parse", ["parse", "{}"], NOT_FOUND, ("empty", 0, r"empty\.nc: 0 blocks"),
      ("binary", 1, r"binary\.nc:\d+:\d+: control or binary character 0x01"), IS_DIR)
reads("check", ["check", "{}"], NOT_FOUND,
      ("empty", 1, r"empty\.nc:1:1: error TG114 the program has no M02 or M30"),
      ("binary", 1, r"binary\.nc:\d+:\d+: error TG101"),
      ("directory", 2, r"no file to check in \S*dir$"))  # a folder: every file in it
reads("convert", ["convert", "{}", "-o", "{out}", "--to", "fanuc-mill"],
      ("missing", 2, r"no such file or directory: \S*nope\.nc"),
      ("empty", 0, r"empty\.nc\s+0\s+0\s+0\s+ok"),
      ("binary", 1, r"binary\.nc\s+0\s+0\s+0\s+FAILED"),
      ("directory", 2, r"-o names one output file; use --out-dir for several inputs"))
# convert's documented exit code for a file that failed, whatever the cause, is 1
writes("convert", ["convert", "{good}", "-o", "{}", "--to", "fanuc-mill"], IS_DIR,
       ("unwritable", 1, r"cannot write \S*afile/out\S*: Not a directory"))
writes("convert", ["convert", "{good}", "--out-dir", "{}", "--to", "fanuc-mill"],
       ("directory", 0, r"good\.nc\s+\d+\s+\d+\s+\S+\s+ok"), UNWRITABLE_FOLDER)
reads("plot", ["plot", "{}", "-o", "{out}.svg"], NOT_FOUND, ("empty", 0, r"0 moves"),
      ("binary", 1, r"0 moves, 0 of \d+ findings marked[^\n]*\n.*binary\.nc: nothing to draw"),
      IS_DIR)
writes("plot", ["plot", "{good}", "-o", "{}"], IS_DIR)
writes("plot", ["plot", "{good}", "-o", "{}.svg"], UNWRITABLE_FOLDER)
reads("tape encode", ["tape", "encode", "{}", "-o", "{out}"], NOT_FOUND,
      ("empty", 0, r": 0 bytes, ISO code"),
      ("binary", 1, r"binary\.nc:\d+:\d+: byte 0x[0-9A-F]{2} \(not ASCII or UTF-8 text: an "
                    r"8-bit character set\?\) cannot be carried by ISO 7-bit code"),
      IS_DIR)
writes("tape encode", ["tape", "encode", "{good}", "-o", "{}"], IS_DIR,
       ("unwritable", 2, r"cannot write \S*afile/out\S*: Not a directory"))
reads("tape decode", ["tape", "decode", "{}", "-o", "{out}"], NOT_FOUND,
      ("empty", 0, r"ISO code, 0 characters"),
      ("binary", 1, r"binary\.nc:\d+:\d+: parity error"), IS_DIR)
writes("tape decode", ["tape", "decode", "{good}", "-o", "{}"], IS_DIR,
       ("unwritable", 2, r"cannot write \S*afile/out\S*: Not a directory"))
reads("tape detect", ["tape", "detect", "{}"], NOT_FOUND, ("empty", 0, r"^text$"),
      ("binary", 1, r"^binary\n.*binary\.nc: \d+ of the first \d+ bytes are no character"),
      IS_DIR)
# classify reads no file: its argument is the classification itself
reads("classify", ["classify", "{text}"],
      ("missing", 2, r"Missing argument 'CLASSIFICATION\.\.\.'"),
      ("empty", 1, r"detailed classification: unexpected end of text at column 1"),
      ("binary", 1, r"detailed classification: unexpected character '\\x01' at column 1"),
      ("directory", 1, r"detailed classification: unexpected '\S+' at column"))
reads("profiles", ["profiles"], ("none", 0, r"fanuc-mill"))
# password reads no file: the password is a line on stdin (here none)
reads("password", ["password"], ("none", 2, r"no password on stdin"))
reads("profiles show", ["profiles", "show", "{profile}"],
      ("missing", 2, r"nope\.toml: cannot read profile: No such file or directory"),
      ("empty", 0, r"empty\.toml: an empty profile: every setting at its default"),
      ("binary", 2, r"binary\.toml: cannot read profile: not UTF-8 text"),
      ("directory", 2, r"dir\.toml: cannot read profile: Is a directory"))
reads("journal", ["journal", "{}"], ("missing", 2, r"nope\.nc: no journal here yet"),
      ("empty", 0, r"^start\s+port\s+dir\s+program"),
      ("binary", 1, r"binary\.nc: not a transfer journal: none of its \d+ line\(s\) is a record"),
      IS_DIR)
reads("send", ["send", "{}", "--port", "loop://", "--flow", "none"], NOT_FOUND,
      ("empty", 1, r"not sent: the check found 1 error\(s\)"),
      ("binary", 1, r"not sent: the check found \d+ error\(s\)"), IS_DIR)
writes("send", ["send", "{good}", "--port", "loop://", "--flow", "none", "--journal", "{}"],
       IS_DIR, ("unwritable", 2, r"cannot write the journal \S*afile/out\S*: \S*afile is not "
                                 r"a folder"))
writes("receive", ["receive", "--port", "loop://", "--timeout", "0.2", "-o", "{}"],
       ("directory", 3, r"nothing received \(no data\)"), UNWRITABLE_FOLDER)
writes("receive", ["receive", "--port", "loop://", "--timeout", "0.2", "-o", "{tmp}/in/",
                   "--journal", "{}"], IS_DIR,
       ("unwritable", 2, r"cannot write the journal \S*afile/out\S*: \S*afile is not a folder"))
reads("emulate", ["emulate", "--punch", "{}"],
      ("missing", 2, r"Invalid value for '--punch': File '\S*nope\.nc' does not exist"),
      ("empty", 1, r"empty\.nc: nothing to punch: the program has no blocks"),
      ("binary", 1, r"binary\.nc:1:1: control character 0x00 is not an Annex A character"),
      IS_DIR)
writes("emulate", ["emulate", "--save", "{}"], IS_DIR, UNWRITABLE_FOLDER)
reads("serve", ["serve", "--config", "{}"],
      ("missing", 2, r"nope\.nc: cannot read the configuration: No such file or directory"),
      ("empty", 2, r"empty\.nc: no ports: add a \[\[port\]\] table"),
      ("binary", 2, r"binary\.nc: cannot read the configuration: not UTF-8 text"), IS_DIR)
# nobody listens on loopback port 9 (discard): an empty password gets as far as the broker
reads("fleet", ["fleet", "--broker", "mqtt://127.0.0.1:9", "--user", "u", "--password-file", "{}"],
      ("missing", 2, r"Invalid value for '--password-file': File '\S*nope\.nc' does not exist"),
      ("empty", 3, r"cannot reach the broker mqtt://127\.0\.0\.1:9: Connection refused"),
      ("binary", 2, r"binary\.nc: cannot read the password: 'utf-8' codec can't decode"),
      ("directory", 2, r"Invalid value for '--password-file': File '\S*dir' is a directory"))
for slot in (["diff", "{}", "{good}"], ["diff", "{good}", "{}"]):
    reads("diff", slot, NOT_FOUND, ("empty", 1, r"differ: 5 only in \S*good\.nc"),
          ("binary", 2, r"binary\.nc:1:2: control or binary character 0x01"), IS_DIR)
# the profile, wherever a command takes one (a file when it is not a built-in name)
for command, argv in (("parse", ["parse", "{good}"]), ("check", ["check", "{good}"]),
                      ("convert", ["convert", "{good}", "-o", "{out}", "--to", "fanuc-mill"]),
                      ("plot", ["plot", "{good}", "-o", "{out}.svg"]),
                      ("send", ["send", "{good}", "--port", "loop://"]),
                      ("receive", ["receive", "--port", "loop://", "-o", "{tmp}/in/"]),
                      ("emulate", ["emulate"]), ("diff", ["diff", "{good}", "{good}"])):
    option = "--to" if command == "convert" else "-p"
    if option == "--to":
        argv = argv[:-2]
    reads(command, [*argv, option, "{profile}"],
          ("missing", 2, r"nope\.toml: cannot read profile: No such file or directory"),
          ("binary", 2, r"binary\.toml: cannot read profile: not UTF-8 text"),
          ("directory", 2, r"dir\.toml: cannot read profile: Is a directory"))


@pytest.fixture
def place(tmp_path: Path) -> dict[str, str]:
    (tmp_path / "good.nc").write_text(GOOD)
    (tmp_path / "empty.nc").write_bytes(b"")
    (tmp_path / "binary.nc").write_bytes(bytes(range(256)) * 8)
    (tmp_path / "binary.toml").write_bytes(bytes(range(256)) * 8)
    (tmp_path / "empty.toml").write_bytes(b"")
    (tmp_path / "dir").mkdir()
    (tmp_path / "dir.toml").mkdir()
    (tmp_path / "afile").write_text("a file, not a folder\n")
    return {"tmp": str(tmp_path), "good": str(tmp_path / "good.nc"),
            "out": str(tmp_path / "out.nc")}


def argument(kind: str, role: str, tmp: Path) -> str | None:
    """The argument of that kind; ``None``: leave it out (a missing argument where the
    command's argument is no file)."""
    if role == "text":
        return {"missing": None, "empty": "", "binary": "\x01\x02\xff",
                "directory": str(tmp / "dir")}[kind]
    suffix = ".toml" if role == "profile" else ".nc"
    return {"missing": str(tmp / f"nope{suffix}"), "empty": str(tmp / f"empty{suffix}"),
            "binary": str(tmp / f"binary{suffix}"),
            "directory": str(tmp / ("dir.toml" if role == "profile" else "dir")),
            "unwritable": str(tmp / "afile" / "out.nc")}[kind]


def build(argv: list[str], kind: str, place: dict[str, str]) -> list[str]:
    tmp = Path(place["tmp"])
    out: list[str] = []
    for item in argv:
        for role in ("{}", "{text}", "{profile}"):
            if role in item:
                value = argument(kind, role.strip("{}") or "file", tmp)
                if value is None:
                    break
                out.append(item.replace(role, value))
                break
        else:
            out.append(item.format(**place))
    return out


def test_every_command_is_covered() -> None:
    listed = set(commands())
    assert {"send", "receive", "emulate", "serve", "journal", "tape encode", "tape decode",
            "tape detect", "plot", "classify", "profiles", "profiles show", "parse", "check",
            "convert", "diff"} <= listed
    covered = {row[0] for row in ROWS}
    assert listed - covered == set(), "commands whose arguments are not tried here"


HAS_PLOT = importlib.util.find_spec("matplotlib") is not None


@pytest.mark.parametrize(("command", "argv", "kind", "code", "pattern"), ROWS,
                         ids=[f"{' '.join(r[1][:3])}-{r[2]}" for r in ROWS])
def test_a_bad_argument_gets_a_clear_message_and_the_documented_exit_code(
        place: dict[str, str], command: str, argv: list[str], kind: str, code: int,
        pattern: str) -> None:
    if command == "plot" and not HAS_PLOT and code == 0:
        code, pattern = 2, r"plot needs matplotlib"
    args = build(argv, kind, place)
    result = CliRunner().invoke(main, args)
    assert "Traceback" not in result.output
    assert result.exception is None or isinstance(result.exception, SystemExit), (
        f"{args}: {result.exception!r}\n{result.output}")
    assert result.exit_code == code, f"{args}:\n{result.output}"
    assert re.search(pattern, result.output, re.M), f"{args}:\n{result.output}"
    assert not list(Path(place["tmp"]).glob("**/.*.part"))  # no temporary file left behind
    if command == "receive" and kind == "directory":
        assert list((Path(place["tmp"]) / "dir").iterdir()) == []


@pytest.mark.parametrize(("argv", "code", "pattern"), [
    (["parse", "{tmp}/nope.nc"], 2, r"cannot read \S*nope\.nc: No such file or directory"),
    (["serve", "--config", "{tmp}/binary.nc"], 2, r"not UTF-8 text"),
    (["profiles", "show", "{tmp}/binary.toml"], 2, r"not UTF-8 text"),
    (["receive", "--port", "loop://", "-o", "{tmp}/in/", "--journal", "{tmp}/afile/j.jsonl"],
     2, r"cannot write the journal"),
    (["send", "{tmp}/good.nc", "--port", "{tmp}/no-such-port"], 3, r"cannot open port"),
])
def test_the_real_entry_point_shows_no_traceback(place: dict[str, str], argv: list[str],
                                                 code: int, pattern: str) -> None:
    env = dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parents[1]))
    run = subprocess.run([sys.executable, "-m", "tapegate", *(a.format(**place) for a in argv)],
                         capture_output=True, text=True, timeout=30, env=env)
    assert "Traceback" not in run.stderr, run.stderr
    assert run.returncode == code, run.stderr
    assert re.search(pattern, run.stderr), run.stderr
