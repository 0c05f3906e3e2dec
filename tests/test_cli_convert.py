"""`tapegate convert`: batches, layout, refusals, exit codes."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from tapegate.cli import main

METRIC = "%\nN1 G21 G90 G94\nN2 G01 X25.4 Y12.7 F254.\nM30\n%\n"


def run(*args):
    return CliRunner().invoke(main, list(args), catch_exceptions=False)


def test_directory_batch_keeps_layout_and_reports(tmp_path):
    src = tmp_path / "cam"
    (src / "op1").mkdir(parents=True)
    (src / "a.nc").write_text(METRIC)
    (src / "op1" / "b.nc").write_text(METRIC.replace("X25.4", "X50.8"))
    (src / ".hidden").write_text("not a program")
    out = tmp_path / "out"
    result = run("convert", str(src), "--out-dir", str(out), "--to", "fanuc-mill",
                 "--units", "inch", "--verify", "--jobs", "2")
    assert result.exit_code == 0, result.output
    assert (out / "a.nc").read_text() == "%\nN1 G20 G90 G94\nN2 G01 X1. Y0.5 F10.\nM30\n%\n"
    assert "X2." in (out / "op1" / "b.nc").read_text()
    assert not (out / ".hidden").exists()
    assert "verified" in result.output and "total: 2 files" in result.output
    assert "units codes G20/G21 (G21 found)" in result.output  # what was assumed is said


def test_existing_output_needs_force(tmp_path):
    (tmp_path / "a.nc").write_text(METRIC)
    out = tmp_path / "o.nc"
    out.write_text("keep me")
    result = run("convert", str(tmp_path / "a.nc"), "-o", str(out), "--to", "iso-mill")
    assert result.exit_code == 1 and "use --force" in result.output
    assert out.read_text() == "keep me"
    assert run("convert", str(tmp_path / "a.nc"), "-o", str(out), "--to", "iso-mill",
               "--force").exit_code == 0
    assert "G71" in out.read_text()


def test_failed_file_exit_code_and_no_partial_output(tmp_path):
    (tmp_path / "in").mkdir()
    (tmp_path / "in" / "good.nc").write_text(METRIC)
    (tmp_path / "in" / "big.nc").write_text("N1 X1.\nN2 X12345678.\n")
    result = run("convert", str(tmp_path / "in"), "--out-dir", str(tmp_path / "out"),
                 "--to", "iso-mill")
    assert result.exit_code == 1
    assert "big.nc:2:4: X12345678. is 12345678 in the target format X+053" in result.output
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["good.nc"]


def test_usage_errors(tmp_path):
    (tmp_path / "a.nc").write_text(METRIC)
    (tmp_path / "b.nc").write_text(METRIC)
    r = run("convert", str(tmp_path / "a.nc"), str(tmp_path / "b.nc"), "-o", "x", "--to",
            "iso-mill")
    assert r.exit_code == 2 and "--out-dir" in r.output
    r = run("convert", str(tmp_path / "a.nc"), "--to", "iso-mill")
    assert r.exit_code == 2 and "--dry-run" in r.output
    r = run("convert", str(tmp_path / "none*.nc"), "--dry-run", "--to", "iso-mill")
    assert r.exit_code == 2 and "no such file" in r.output
    r = run("convert", str(tmp_path / "a.nc"), "--dry-run", "--to", "no-such-profile")
    assert r.exit_code == 2 and "no profile named" in r.output


def test_glob_and_dry_run_write_nothing(tmp_path):
    (tmp_path / "a.nc").write_text(METRIC)
    (tmp_path / "b.nc").write_text(METRIC)
    before = sorted(tmp_path.iterdir())
    r = run("convert", str(tmp_path / "*.nc"), "--dry-run", "--to", "iso-mill", "--decimal",
            "implicit", "--zeros", "trailing", "--eob", "crlf")
    assert r.exit_code == 0 and "dry run: nothing written" in r.output
    assert sorted(tmp_path.iterdir()) == before


SUBPROGRAM = ("%\nO1000\nG21 G90\nG0 X10. Y10.\nM98 P2000\nM30\nO2000\nG01 X1. Y1. F100.\n"
              "M99\n%\n")


def test_a_subprogram_that_inherits_its_distance_mode_is_refused_under_a_change_of_units(
        tmp_path):
    """O2000 ends with M99: it runs in the caller's G90 or G91, which its text does not show,
    so its X1. cannot be converted safely (by positions in G91, word by word in G90)."""
    src, out = tmp_path / "p.nc", tmp_path / "o.nc"
    src.write_text(SUBPROGRAM)
    args = ["convert", str(src), "-o", str(out), "--from", "fanuc-mill", "--to", "fanuc-mill"]
    result = run(*args, "--units", "inch", "--verify")
    assert result.exit_code == 1 and not out.exists()
    assert "p.nc:8:5: X1.: an axis word of a subprogram (it ends with M99 at line 9)" \
        in result.output and "write G90 or G91 in the subprogram" in result.output
    assert "Traceback" not in result.output
    # the subprogram that selects its distance mode converts, and verifies
    src.write_text(SUBPROGRAM.replace("O2000\nG01", "O2000\nG91 G01"))
    result = run(*args, "--units", "inch", "--verify")
    assert result.exit_code == 0, result.output
    assert "G91 G01 X0.0394 Y0.0394 F3.937\n" in out.read_text()  # its own path, afresh
    # and without a change of units nothing is converted, so nothing is refused
    src.write_text(SUBPROGRAM)
    assert run(*args, "--force", "--verify").exit_code == 0


@pytest.mark.parametrize("profile, text, end", [
    ("sinumerik-840d", "G1 X10 Y10 F100\nG91 X1\nM17\n", "M17 at line 3"),
    ("sinumerik-840d", "G1 X10 Y10 F100\nRET\n", "RET at line 2"),
    ("linuxcnc", "o100 sub\nG1 X10 Y10 F100\no100 endsub\nG21 G90\no100 call\nM2\n",
     "o100 endsub at line 3"),
])
def test_the_subprograms_of_other_dialects_are_refused_alike(tmp_path, profile, text, end):
    """Sinumerik's M17 and RET end a subprogram, LinuxCNC's o100 sub ... endsub is one: their
    first move ran in the caller's distance mode, converted as G90 without a word (the review
    found all three)."""
    src = tmp_path / "p.nc"
    src.write_text(text)
    args = ["convert", str(src), "-o", "-", "--from", profile, "--to", profile,
            "--units", "inch"]
    result = run(*args)
    assert result.exit_code == 1 and f"an axis word of a subprogram (it ends with {end})" in \
        result.output, result.output
    # selecting G90 first converts; a `return` inside a LinuxCNC sub is no end of it
    fixed = text.replace("G1 X10", "G90 G1 X10").replace("o100 sub\n", "o100 sub\nG90\n")
    fixed = fixed.replace("o100 endsub", "o100 return\nX20\no100 endsub")
    src.write_text(fixed)
    ok = run(*args)
    assert ok.exit_code == 0, ok.output
