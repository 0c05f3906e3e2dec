"""benchmarks/workers.py's real-files batches (issue 35 item 3: `check`/`convert` of "200 real
files", 2 workers against 1): which files a folder gives, on which profile each is read, and
one run of both batches through the command (docs/benchmarks.md, par82)."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
CORPUS = Path(os.environ.get("TAPEGATE_CORPUS", ROOT.parent / "shared" / "corpus"))


def workers_module():
    """benchmarks/workers.py as a module (it puts its folder on ``sys.path`` for its own
    imports: core, real_program, shops)."""
    spec = importlib.util.spec_from_file_location("workers_bench",
                                                  ROOT / "benchmarks" / "workers.py")
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def test_the_first_files_of_a_folder_by_their_paths_below_it(tmp_path: Path):
    """Sorted by the path below the folder (a subfolder's files where its name sorts), hidden
    files and folders, the map named and a folder linked to left out, cut at the count."""
    module = workers_module()
    (tmp_path / "b").mkdir()
    (tmp_path / ".hidden").mkdir()
    elsewhere = tmp_path.parent / f"{tmp_path.name}-elsewhere"
    elsewhere.mkdir()
    (elsewhere / "x.nc").write_text("G0 X1\n")
    (tmp_path / "linked").symlink_to(elsewhere, target_is_directory=True)
    for name in ("c.nc", "a.nc", "b/z.nc", "b/a.nc", ".dot.nc", ".hidden/h.nc", "map.tsv"):
        (tmp_path / name).write_text("G0 X1\n")
    found = module.real_files(tmp_path, 10, tmp_path / "map.tsv")
    assert [p.relative_to(tmp_path).as_posix() for p in found] == [
        "a.nc", "b/a.nc", "b/z.nc", "c.nc"]
    # the count cuts the sorted list; without a map to leave, the map is a file like any
    assert [p.name for p in module.real_files(tmp_path, 2)] == ["a.nc", "a.nc"]
    assert [p.name for p in module.real_files(tmp_path, 10)][-1] == "map.tsv"


def test_each_file_on_its_family_profile_and_the_rest_on_the_one_named(tmp_path: Path):
    """A families.tsv-like map: the family's mill profile, its lathe profile where the
    description says turning, shops.py's corrections; a file of family "?" or not in the
    map on the profile named."""
    module = workers_module()
    rows = ["haas\tmill.nc\tFusion 360 Haas post, metric",
            "fanuc\tlathe.nc\tDoosan Lynx lathe, T0101",
            "?\tunknown.nc\tsome other control",
            # shops.py's RELABELLED: listed fanuc, an Okuma OSP program
            "fanuc\tGCodeProjects__GCodeWorkShop__FLANGE.nc\tOkuma"]
    (tmp_path / "map.tsv").write_text("\n".join(rows) + "\n")
    names = ["mill.nc", "lathe.nc", "unknown.nc", "absent.nc",
             "GCodeProjects__GCodeWorkShop__FLANGE.nc"]
    files = [tmp_path / name for name in names]
    groups = module.real_groups(files, tmp_path, "sinumerik-840d", tmp_path / "map.tsv")
    assert {profile: [p.name for p in paths] for profile, paths in groups.items()} == {
        "haas-mill": ["mill.nc"],
        "fanuc-lathe": ["lathe.nc"],
        "sinumerik-840d": ["unknown.nc", "absent.nc"],
        "okuma-mill": ["GCodeProjects__GCodeWorkShop__FLANGE.nc"],
    }
    # no map: every file on the profile named
    assert list(module.real_groups(files, tmp_path, "linuxcnc", None)) == ["linuxcnc"]


def test_several_commands_measured_as_one():
    """A batch of several profiles is their commands one after the other: each figure summed,
    each worker's summed with the other commands' same worker."""
    module = workers_module()
    assert module.summed([(1.0, 2.0, 3.0, 4.0, 0.5), (10.0, 20.0, 30.0, 40.0, 5.0, 6.0)]) == (
        11.0, 22.0, 33.0, 44.0, 5.5, 6.0)
    assert module.summed([(1, 2), (3, 4)]) == (4, 6)


@pytest.mark.skipif(not (CORPUS / "shops" / "families.tsv").is_file(),
                    reason="needs ../shared/corpus/shops")
def test_the_real_files_batches_run_on_each_family_profile(tmp_path: Path):
    """Twelve shops programs, each checked and converted on its family's profile: one
    command a profile, with 1 and 2 workers, each run to its end (the exit code printed:
    0-2, a check's findings or a conversion's refusals, never a crash)."""
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    done = subprocess.run(
        [sys.executable, str(ROOT / "benchmarks" / "workers.py"), "--real",
         str(CORPUS / "shops"), "--families", str(CORPUS / "shops" / "families.tsv"),
         "--real-count", "12", "--copies", "2", "--only", "real files", "--repeat", "1",
         "--tapegate", f"{sys.executable} -m tapegate"],
        capture_output=True, text=True, env=env, cwd=tmp_path, timeout=600, check=False)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    head = lines[0]
    assert head.startswith("real files: 12 of ") and "fanuc-mill" in head, head
    rows = [line.split() for line in lines if line.startswith(("check 12", "convert 12"))]
    assert [(row[0], row[4]) for row in rows] == [
        ("check", "1"), ("check", "2"), ("convert", "1"), ("convert", "2")]
    assert all(row[-1] in {"0", "1", "2"} for row in rows), rows
