"""benchmarks/identity.py, the byte-identity comparison of two builds (issue 31): recorded twice on
one build it finds no difference, and it finds the one a profile edited in a copy of the build
plants, in the entries that profile governs and nowhere else. Two programs of its own, no corpus.
"""

from __future__ import annotations

import hashlib
import importlib.util
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
SCRIPT = ROOT / "benchmarks" / "identity.py"


def _load():
    spec = importlib.util.spec_from_file_location("identity", SCRIPT)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules["identity"] = module  # dataclasses look their module up
    spec.loader.exec_module(module)
    return module


identity = _load()

METRIC = (b"%\nO1000\n(TWO HOLES, METRIC)\nN10 G21 G90 G17 G40\nN20 T1 M06\n"
          b"N30 G00 X10. Y20. S1000 M03\nN40 G01 Z-1. F100.\nN50 X50.5 Y20.\n"
          b"N60 G02 X60.5 Y30. I0 J10.\nN70 G00 Z5.\nN80 M30\n%\n")
INCH = (b"%\nO2000\nN1 G20 G90 (INCH)\nN2 G0 X1.25 Y0.5\nN3 G1 Z-0.1 F10.\nN4 X2.\n"
        b"N5 M30\n%\n")


@pytest.fixture
def corpus(tmp_path: Path) -> Path:
    folder = tmp_path / "programs"
    folder.mkdir()
    (folder / "metric.nc").write_bytes(METRIC)
    (folder / "inch.nc").write_bytes(INCH)
    (folder / "SOURCES.md").write_text("not a program: left out\n")
    return folder


def run(*args: str | Path, build: Path = ROOT, cwd: Path | None = None
        ) -> subprocess.CompletedProcess[str]:
    """The tool as a user runs it: its build chosen by PYTHONPATH."""
    env = {**os.environ, "PYTHONPATH": str(build)}
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], env=env, cwd=cwd,
                          capture_output=True, text=True, timeout=240, check=False)


def entries(record: Path) -> list[dict]:
    lines = [json.loads(line) for line in record.read_text().splitlines()]
    assert "meta" in lines[0]
    return lines[1:]


def copy_of_build(target: Path) -> Path:
    """A second checkout: the four packages (with the built extension), nothing else."""
    for package in ("formats", "postproc", "dnc", "tapegate"):
        shutil.copytree(ROOT / package, target / package,
                        ignore=shutil.ignore_patterns("__pycache__"))
    return target


def test_the_same_build_recorded_twice_compares_equal(corpus, tmp_path):
    a, b = tmp_path / "a.jsonl", tmp_path / "b.jsonl"
    for record in (a, b):
        done = run("record", record, "--corpus", corpus, cwd=tmp_path)
        assert done.returncode == 0, done.stderr
    found = entries(a)
    profiles = sorted(p.stem for p in (ROOT / "formats" / "profiles").glob("*.toml"))
    # every command on every file and profile (neutral too), and nothing from SOURCES.md
    assert {e["file"] for e in found} == {"programs/inch.nc", "programs/metric.nc"}
    assert {e["profile"] for e in found} == {*profiles, "neutral"}
    for prof in [*profiles, "neutral"]:
        keys = {(e["command"], e["target"]) for e in found
                if e["profile"] == prof and e["file"] == "programs/metric.nc"}
        assert {("parse", ""), ("check", ""), ("convert", "units"), ("convert", "decimal"),
                ("convert", "family"), ("diff", "vs units"), ("diff", "vs decimal"),
                ("diff", "vs family"), ("diff", "changed word"),
                ("diff", "changed word json")} <= keys
    # the hashes are of the CLI's bytes: the reprint is the program itself, byte for byte
    reprint = next(e for e in found if e["command"] == "parse" and e["profile"] == "fanuc-mill"
                   and e["file"] == "programs/metric.nc")
    assert reprint["argv"] == ["parse", "programs/metric.nc", "-p", "fanuc-mill", "--reprint"]
    assert reprint["exit"] == 0
    assert reprint["stdout"] == hashlib.sha256(METRIC).hexdigest()
    assert reprint["stderr"] == hashlib.sha256(b"").hexdigest()
    units = next(e for e in found if e["command"] == "convert" and e["target"] == "units"
                 and e["profile"] == "fanuc-mill" and e["file"] == "programs/metric.nc")
    assert units["argv"][-5:] == ["--to", "fanuc-mill", "--units", "inch", "--verify"]
    assert units["exit"] == 0 and units["output"] is not None
    changed = next(e for e in found if e["target"] == "changed word"
                   and e["profile"] == "fanuc-mill" and e["file"] == "programs/metric.nc")
    assert changed["exit"] == 1  # diff: the programs differ
    assert changed["note"] == "line 7 column 9: Z-1. -> Z-2."
    assert not [e for e in found if "exception" in e]
    compared = run("compare", a, b)
    assert compared.returncode == 0, compared.stdout + compared.stderr
    assert f"{len(found)} entries compared" in compared.stdout
    assert "all byte-identical" in compared.stdout
    assert "DIFFERS" not in compared.stdout
    # the two records were made in two scratch folders: their paths are in no entry
    assert "tapegate-identity-" not in a.read_text().split("\n", 1)[1]


def test_a_profile_edited_in_a_second_build_is_found(corpus, tmp_path):
    other = copy_of_build(tmp_path / "other")
    profile = other / "formats" / "profiles" / "fanuc-mill.toml"
    text = profile.read_text()
    assert "feed_max = 10000" in text
    profile.write_text(text.replace("feed_max = 10000", "feed_max = 50"))  # F100. too fast
    a, b = tmp_path / "a.jsonl", tmp_path / "b.jsonl"
    assert run("record", a, "--corpus", corpus, cwd=tmp_path).returncode == 0
    done = run("record", b, "--corpus", corpus, build=other, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert f"tapegate from {other}" in done.stderr  # the copy's packages, not this checkout's
    compared = run("compare", a, b)
    assert compared.returncode == 1, compared.stdout + compared.stderr
    lines = compared.stdout.splitlines()
    differs = [line for line in lines if line.startswith("DIFFERS")]
    # the check on fanuc-mill of both programs finds the feed too fast (TG605, a warning: a
    # FANUC clamps it, so the exit code stays 0); how to reproduce it
    for name in ("metric", "inch"):
        line = f"DIFFERS check programs/{name}.nc [fanuc-mill]: stdout"
        assert line in differs, compared.stdout
        at = lines.index(line)
        assert lines[at + 1].strip() == (f"tapegate check programs/{name}.nc -p fanuc-mill "
                                         "--format json")
        assert lines[at + 2].strip().startswith("replay: PYTHONPATH=CHECKOUT python "
                                                "benchmarks/identity.py replay DIR --file "
                                                f"programs/{name}.nc --profile fanuc-mill")
    # nothing else: not the conversions (feed_max is no part of them), nor the other profiles
    # (the other checkout's path is normalised away)
    assert len(differs) == 2
    assert lines[-3:-1] == ["differing entries by command: check 2",
                            "differing entries by profile: fanuc-mill 2"]
    total = len(entries(a))
    assert lines[-1] == (f"{total} entries compared ({total} in {a}, {total} in {b}): "
                         f"{len(differs)} differ")
    b_entries = {(e["command"], e["file"], e["profile"], e["target"]): e for e in entries(b)}
    for line in differs:
        key = next(k for k in b_entries
                   if line.startswith(f"DIFFERS {k[0]} {k[1]} [{k[2]}] {k[3]}".rstrip() + ":"))
        assert "fanuc-mill" in b_entries[key]["argv"], line


def test_replay_keeps_each_entry_output(corpus, tmp_path):
    keep = tmp_path / "replay"
    done = run("replay", keep, "--file", "programs/metric.nc", "--profile", "fanuc-mill",
               "--corpus", corpus)
    assert done.returncode == 0, done.stderr
    results = keep / "results"
    [reprint] = results.glob("*-parse.stdout")
    assert reprint.read_bytes() == METRIC
    [command] = results.glob("*-parse.cmd")
    assert command.read_text() == "tapegate parse programs/metric.nc -p fanuc-mill --reprint\n"
    [check] = results.glob("*-check.exit")
    assert check.read_text() in ("0\n", "1\n")
    assert (keep / "out" / "fanuc-mill" / "units" / "programs" / "metric.nc").is_file()
    again = run("replay", keep, "--file", "programs/metric.nc", "--corpus", corpus)
    assert again.returncode == 2
    assert again.stderr == f"identity: {keep}: not empty; replay into a new folder\n"


def test_bad_records_and_folders_are_named_with_exit_2(corpus, tmp_path):
    missing = run("compare", tmp_path / "none.jsonl", tmp_path / "none.jsonl")
    assert (missing.returncode, missing.stderr) == (
        2, f"identity: {tmp_path / 'none.jsonl'}: cannot read: No such file or directory\n")
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"meta": {}}\n{"command": "parse"}\n')
    broken = run("compare", bad, bad)
    assert broken.returncode == 2
    assert broken.stderr.startswith(f"identity: {bad}:2: not an entry of identity.py record")
    no_meta = tmp_path / "plain.jsonl"
    no_meta.write_text("\n")
    assert run("compare", no_meta, no_meta).stderr == (
        f"identity: {no_meta}: no meta line: not written by identity.py record\n")
    gone = run("record", tmp_path / "r.jsonl", "--corpus", tmp_path / "nowhere")
    assert (gone.returncode, gone.stderr) == (
        2, f"identity: {tmp_path / 'nowhere'}: no such folder (give the corpus with "
           "--corpus DIR)\n")
    wrong = run("record", tmp_path / "r.jsonl", "--corpus", corpus, "--profile", "nope")
    assert wrong.returncode == 2 and "no profile 'nope'" in wrong.stderr
    assert not (tmp_path / "r.jsonl").exists()  # no half record is left
    nowhere = run("record", tmp_path / "no" / "r.jsonl", "--corpus", corpus)
    assert (nowhere.returncode, nowhere.stderr) == (
        2, f"identity: cannot write {tmp_path / 'no' / 'r.jsonl'}: No such file or directory\n")


def test_an_entry_in_one_record_only_is_a_difference(corpus, tmp_path):
    a, b = tmp_path / "a.jsonl", tmp_path / "b.jsonl"
    assert run("record", a, "--corpus", corpus, "--profile", "iso-mill").returncode == 0
    lines = a.read_text().splitlines()
    b.write_text("\n".join(lines[:-1]) + "\n")  # the last entry left out
    last = json.loads(lines[-1])
    compared = run("compare", a, b)
    assert compared.returncode == 1
    assert (f"DIFFERS {last['command']} {last['file']} [iso-mill] {last['target']}: "
            f"only in {a}") in compared.stdout
    assert compared.stdout.splitlines()[-1] == (
        f"{len(lines) - 1} entries compared ({len(lines) - 1} in {a}, {len(lines) - 2} in {b}): "
        "1 differ")


@pytest.mark.parametrize(("program", "expected", "what"), [
    (b"N1 G0 X1.5\nN2 (X9) Y2.25 ; Z3\nN3 M30\n", b"N1 G0 X1.5\nN2 (X9) Y2.26 ; Z3\nN3 M30\n",
     "line 2 column 9: Y2.25 -> Y2.26"),
    (b"N1 X19\nN2 G1 Z-0.9\n", b"N1 X19\nN2 G1 Z-0.0\n", "line 2 column 7: Z-0.9 -> Z-0.0"),
    (b"N1G0X1.\nN2G1X120.Z7.5F.1\n", b"N1G0X1.\nN2G1X121.Z7.5F.1\n",
     "line 2 column 5: X120. -> X121."),  # no spaces: a word after a digit
    (b"N1 _X_HOME=5 AX1 #X2 (X1)\nN2 G4 P9\n", b"N1 _X_HOME=5 AX1 #X2 (X1)\nN2 G4 P0\n",
     "line 2 column 7: P9 -> P0"),  # not in a name, a variable or a comment
    (b"(ONLY Y9 IN COMMENTS)\nN1 G4 P9\n", b"(ONLY Y9 IN COMMENTS)\nN1 G4 P0\n",
     "line 2 column 7: P9 -> P0"),  # no X Y Z word: any letter's
])
def test_one_word_changed_outside_comments(program, expected, what):
    assert identity.changed_word(program) == (expected, what)


def test_a_program_without_words_has_none_to_change():
    assert identity.changed_word(b"%\n(NOTHING)\n%\n") is None
