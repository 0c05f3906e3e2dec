"""`make demo`: the main job on a built-in sample program, no hardware needed."""

from __future__ import annotations

from importlib import resources

import click

from formats.classification import DetailedClassification
from formats.convert import ConvertOptions, convert_text
from formats.parser import parse_text
from formats.printer import program_text
from formats.profile import load_profile
from formats.tape import decode, encode
from postproc.check import check_text


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
    letter, worst = stats.largest_rounding()
    for before, after in list(zip(sample.splitlines(), inch.splitlines(), strict=True))[4:7]:
        click.echo(f"   {before:34} -> {after}")
    click.echo(f"   {stats.changed} words changed, largest rounding {letter} {worst} in")
    click.secho("\n5. Encode as tape and decode again", bold=True)
    for code in ("iso", "eia"):
        data = encode(sample, code, leader=10, trailer=10)  # type: ignore[arg-type]
        back = decode(data)
        click.echo(f"   {code.upper()}: {len(data)} bytes, first block "
                   f"{data[10:16].hex(' ')}, detected {back.code.upper()}, "
                   f"round trip exact: {back.text == sample}, errors: {len(back.issues)}")


if __name__ == "__main__":
    main()
