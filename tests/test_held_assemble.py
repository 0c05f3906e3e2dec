"""benchmarks/held_assemble.py: the held-out sets' rows, and a file's bytes taken from its
repository's snapshot as they are (issue 32; docs/benchmarks.md, "Every held-out set re-read
on one main")."""

from __future__ import annotations

import importlib.util
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def assemble_module():
    spec = importlib.util.spec_from_file_location(
        "held_assemble", ROOT / "benchmarks" / "held_assemble.py")
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def test_every_row_names_a_commit_and_a_file_name_no_other_row_uses():
    """--union puts every set's files in one folder: a name used twice would lose a program."""
    module = assemble_module()
    names = []
    # every set's rows; ledger.tsv, beside them, classes programs and is no set
    for tsv in sorted(t for t in module.UNSEEN.glob("*.tsv") if t.name != "ledger.tsv"):
        for row in module.rows(tsv.stem):
            assert len(row) == 6, (tsv.name, row[:2])
            family, file, repository, commit, path, _ = row
            assert family in {"fanuc", "haas", "linuxcnc", "okuma", "sinumerik"}, (tsv.name, file)
            assert re.fullmatch(r"[0-9a-f]{40}", commit), (tsv.name, file)
            assert repository.count("/") == 1 and path, (tsv.name, file)
            names.append(file)
    assert len(names) == len(set(names))
    assert len(names) >= 289 + 67 + 119 + 140  # held..held10, dev, held11, held12


def git(*args: str, cwd: Path) -> str:
    return subprocess.run(["git", *args], cwd=cwd, capture_output=True, text=True,
                          check=True).stdout.strip()


@pytest.fixture
def snapshot(tmp_path):
    """A repository 'shop/progs' with one program of CR LF lines and a byte outside ASCII."""
    repo = tmp_path / "snap" / "shop+progs" / "repo"
    (repo / "nc").mkdir(parents=True)
    git("init", "-q", cwd=repo)
    (repo / "nc" / "O0001.NC").write_bytes(b"%\r\nO0001(T\xe9ST)\r\nG0 X0\r\nM30\r\n%\r\n")
    git("add", ".", cwd=repo)
    git("-c", "user.name=t", "-c", "user.email=t@t", "commit", "-q", "-m", "p", cwd=repo)
    return tmp_path / "snap", git("rev-parse", "HEAD", cwd=repo)


def test_a_file_is_the_snapshot_s_blob_and_a_hand_written_one_is_kept(tmp_path, snapshot,
                                                                      monkeypatch, capsys):
    module = assemble_module()
    snap, commit = snapshot
    unseen = tmp_path / "unseen"
    unseen.mkdir()
    (unseen / "heldx.tsv").write_text(
        "# family\tfile\trepository\tcommit\tpath\tdescription\n"
        f"fanuc\tshop__O0001.NC\tshop/progs\t{commit}\tnc/O0001.NC\ta mill program\n"
        f"haas\tshop__O0002.NC\tshop/progs\t{'0' * 40}\tnc/O0002.NC\ta lathe program\n"
        f"fanuc\tother__O0003.NC\tother/none\t{'1' * 40}\tO0003.NC\tno snapshot\n",
        encoding="utf-8")
    monkeypatch.setattr(module, "UNSEEN", unseen)
    out = tmp_path / "out"
    (out / "heldx").mkdir(parents=True)
    (out / "heldx" / "shop__O0002.NC").write_bytes(b"%\nO0002\nM30\n%\n")  # from the text index
    assert module.main(["--snapshots", str(snap), "--out", str(out), "--union", "heldx"]) == 0

    got = (out / "heldx" / "shop__O0001.NC").read_bytes()
    assert got == (snap / "shop+progs" / "repo" / "nc" / "O0001.NC").read_bytes()
    # a row with neither a snapshot nor a file written by hand is said, not invented
    assert not (out / "heldx" / "other__O0003.NC").exists()
    assert capsys.readouterr().err.splitlines() == [
        f"missing\theldx\tother__O0003.NC\tother/none\t{'1' * 40}\tO0003.NC\tno snapshot"]
    manifest = (out / "manifest.tsv").read_text(encoding="utf-8").splitlines()
    rows = {line.split("\t")[1]: line.split("\t") for line in manifest[1:]}
    assert set(rows) == {"shop__O0001.NC", "shop__O0002.NC"}
    blob = git("rev-parse", f"{commit}:nc/O0001.NC", cwd=snap / "shop+progs" / "repo")
    assert rows["shop__O0001.NC"][2:] == [str(len(got)), "5", blob, "snapshot"]
    assert rows["shop__O0002.NC"][5] == "written by hand (commit not in the snapshot)"
    # families.tsv as shops.py --shops reads it: family, file, description; every row
    families = (out / "heldx" / "families.tsv").read_text(encoding="utf-8").splitlines()
    assert families[0] == "fanuc\tshop__O0001.NC\ta mill program"
    assert len(families) == 3
    # the union holds the files there are, under the rows that name them
    assert sorted(p.name for p in (out / "all").iterdir()) == [
        "families.tsv", "shop__O0001.NC", "shop__O0002.NC"]
    assert len((out / "all" / "families.tsv").read_text(encoding="utf-8").splitlines()) == 2


def test_the_manifest_hash_is_the_raw_blob_s_under_autocrlf(tmp_path, snapshot, monkeypatch):
    """A global core.autocrlf made `git hash-object` hash the CR LF program as LF lines: the
    manifest gave a hash other than the repository's blob (review 10, finding 9). The bytes
    written are the raw blob's too (`git cat-file blob`)."""
    module = assemble_module()
    snap, commit = snapshot
    config = tmp_path / "gitconfig"
    config.write_text("[core]\n\tautocrlf = true\n", encoding="utf-8")
    monkeypatch.setenv("GIT_CONFIG_GLOBAL", str(config))
    unseen = tmp_path / "unseen"
    unseen.mkdir()
    (unseen / "heldy.tsv").write_text(
        f"fanuc\tshop__O0001.NC\tshop/progs\t{commit}\tnc/O0001.NC\ta mill program\n",
        encoding="utf-8")
    monkeypatch.setattr(module, "UNSEEN", unseen)
    out = tmp_path / "out"
    assert module.main(["--snapshots", str(snap), "--out", str(out), "heldy"]) == 0
    repo = snap / "shop+progs" / "repo"
    raw = subprocess.run(["git", "cat-file", "blob", f"{commit}:nc/O0001.NC"], cwd=repo,
                         capture_output=True, check=True).stdout
    assert b"\r\n" in raw and (out / "heldy" / "shop__O0001.NC").read_bytes() == raw
    blob = git("rev-parse", f"{commit}:nc/O0001.NC", cwd=repo)
    filtered = git("hash-object", str(out / "heldy" / "shop__O0001.NC"), cwd=repo)
    assert filtered != blob  # what the filters do, which the manifest must not take
    manifest = (out / "manifest.tsv").read_text(encoding="utf-8").splitlines()
    assert manifest[1].split("\t")[4] == blob
