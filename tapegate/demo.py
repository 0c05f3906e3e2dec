"""`make demo`: the main job on a built-in sample program, no hardware needed."""

from __future__ import annotations

import os
import sys
import tempfile
from importlib import resources
from pathlib import Path

import click

from dnc.control import Control
from dnc.emulator import Emulator
from dnc.link import chars_per_second
from formats.classification import DetailedClassification
from formats.convert import ConvertOptions, convert_text
from formats.parser import parse_text
from formats.printer import program_text
from formats.profile import load_profile
from formats.tape import decode, encode
from postproc.check import check_text
from tapegate import cli
from tapegate.serial_cli import stats_text


def main() -> None:
    sample = (resources.files("tapegate") / "examples" / "bracket.nc").read_text("ascii")
    profile = load_profile("iso-mill")
    click.secho("1. The machine: profile iso-mill", bold=True)
    click.echo(f"   Annex B {profile.general}   Annex C {profile.detailed}")
    for row in DetailedClassification.parse(str(profile.detailed)).explain()[4:8]:
        click.echo(f"   {row[0]:6} {row[2]}")
    click.secho("\n2. Parse the sample program (lossless)", bold=True)
    blocks = parse_text(sample, profile.dialect, file="bracket.nc")
    words = sum(len(b.words) for b in blocks)
    same = program_text(blocks) == sample
    click.echo(f"   {len(blocks)} blocks, {words} words; reprint byte-identical: {same}")
    x = next(b for b in blocks if "X90." in b.words)
    click.echo(f"   line {x.line}: {x.text!r} -> X = {profile.value('X90.')} mm")
    click.secho("\n3. Check it against the machine", bold=True)
    findings = check_text(sample, profile, file="bracket.nc")
    for f in findings:
        click.echo(f"   {f}")
    click.echo(f"   {len(findings)} finding(s), "
               f"{sum(f.severity == 'error' for f in findings)} error(s)")
    click.secho("\n4. Convert it for an inch Fanuc-style control", bold=True)
    inch, stats = convert_text(sample, ConvertOptions(load_profile("fanuc-mill"), profile,
                                                      units="inch"))
    letter, worst = stats.largest_rounding_text()
    for before, after in list(zip(sample.splitlines(), inch.splitlines(), strict=True))[4:7]:
        click.echo(f"   {before:34} -> {after}")
    click.echo(f"   {stats.changed} words changed, largest rounding {letter} {worst} in")
    click.secho("\n5. Encode as tape and decode again", bold=True)
    for code in ("iso", "eia"):
        data = encode(sample, code, leader=10, trailer=10)
        back = decode(data)
        click.echo(f"   {code.upper()}: {len(data)} bytes, first block "
                   f"{data[10:16].hex(' ')}, detected {back.code.upper()}, "
                   f"round trip exact: {back.text == sample}, errors: {len(back.issues)}")
    drip_feed(inch)


def drip_feed(program: str) -> None:
    """Step 6: the converted program drip-fed to an emulated Fanuc on a pseudo-terminal."""
    fanuc = load_profile("fanuc-mill")
    s = fanuc.serial
    cps = chars_per_second(s)
    click.secho("\n6. Drip-feed it to an emulated Fanuc control (no hardware)", bold=True)
    control = Control(cps=cps, buffer=64, rate=cps / 3, allowance=s.overrun_allowance,
                      tv_check=s.tv_check, dc1_every=0.1, dialect=fanuc.dialect)
    emulator = Emulator(control)
    click.echo(f"   control on {emulator.path}: buffer 64 characters, machining at "
               f"{cps / 3:.0f} chars/s, so it must pause the sender with DC3")
    here = os.getcwd()
    with tempfile.TemporaryDirectory() as folder:
        os.chdir(folder)
        Path("O1001.nc").write_text(program)
        args = ["send", "O1001.nc", "--port", emulator.path, "--profile", "fanuc-mill",
                "--xon-timeout", "10"] + (["--progress"] if sys.stderr.isatty() else [])
        try:
            cli.main(args, standalone_mode=False)
        finally:
            os.chdir(here)
            emulator.wait(3)
            emulator.stop()
    click.echo("   the control's statistics:")
    for line in stats_text(control.stats, cps).splitlines():
        click.echo(f"   {line}")


if __name__ == "__main__":
    main()
