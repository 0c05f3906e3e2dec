"""Where LinuxCNC's interpreter and the ``linuxcnc`` profile disagree on what reads (issue 32).

    .venv/bin/python benchmarks/rs274_sweep.py [--json] [--only real|variants]
                                               [--samples DIR] [--corpus DIR]

Every LinuxCNC program at hand goes through ``rs274 -g`` (as benchmarks/rs274_compare.py runs
it: batch mode, a tool table of the program's T numbers) and ``tapegate check -p linuxcnc``,
and the two verdicts are set side by side:

- **real**: the ``.ngc`` programs LinuxCNC ships (``/usr/share/linuxcnc/ncfiles``, recursive),
  the corpus programs whose matching profile is ``linuxcnc`` (``MATCHING`` of
  tests/test_dialects.py) and the shops folder's programs of the ``linuxcnc`` family
  (``families.tsv``, corrected by benchmarks/shops.py's ``RELABELLED``);
- **variants**: small programs written here, one form each, that LinuxCNC's reader treats in
  its own way: blanks inserted inside words, numbers and parameter numbers (rs274 drops them
  before it reads a line), the case changed, comments in odd places, numbers written ``1.``,
  ``.5``, ``+1``, ``-.5``, ``1e3``..., text after the program's end.

A program is **refused** by rs274 where it stops with a fault of the program (a stop the
comparison script classes as the configuration's or a library's is left out), by tapegate
where it reports an error. Listed: where one refuses and the other reads, and where both refuse
on different lines. Exit code 0 always (a measurement; tests/test_oracle_rs274.py asserts the
variants' verdicts).
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import sys
import tempfile
from dataclasses import asdict, dataclass
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent


def _load(name: str):
    spec = importlib.util.spec_from_file_location(name, HERE / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # dataclasses look their module up
    spec.loader.exec_module(module)
    return module


compare = _load("rs274_compare")
SHOPS = Path(os.environ.get("TAPEGATE_SHOPS", compare.CORPUS / "shops"))

# -- the variants -------------------------------------------------------------------------------

HEAD = "G21 G90 G17 G94\n"
END = "M2\n"

# name, program: each one form rs274 reads in its own way
VARIANTS: list[tuple[str, str]] = [
    # blanks (rs274 close_and_downcase drops them outside comments)
    ("blank inside a number", HEAD + "G0 X1 0 Y2\n" + END),
    ("blank inside a decimal", HEAD + "G0 X1 . 5\n" + END),
    ("blank after the sign", HEAD + "G0 X - 1\n" + END),
    ("blank inside a G code", HEAD + "G 0 X1\n" + END),
    ("blank inside a G code's digits", HEAD + "G0 X0\nG 0 1 X1 F1 0 0\n" + END),
    ("blank inside an M code", HEAD + "M 3 S1000\nM 5\n" + "M 3 0\n"),
    ("blank inside a line number", "N 1 0 " + HEAD + "N2 0 G0 X1\n" + END),
    ("blank inside a parameter number", HEAD + "#1 2 = 3\nG0 X#12\n" + END),
    ("blank inside a parameter read", HEAD + "#12 = 3\nG0 X#1 2\n" + END),
    ("blank after #", HEAD + "# 1 = 3\nG0 X# 1\n" + END),
    ("blank inside a named parameter", HEAD + "#<a b> = 3\nG0 X#<ab>\n" + END),
    ("blank inside an o-word label", HEAD + "#1 = 1\no1 00 if [#1 GT 0]\nG0 X1\no100 endif\n"
     + END),
    ("blank inside an o-word keyword", HEAD + "#1 = 1\no100 if [#1 GT 0]\nG0 X1\no100 end if\n"
     + END),
    ("blank inside an expression's number", HEAD + "#1 = [1 0 + 2]\nG0 X#1\n" + END),
    ("blank inside a function name", HEAD + "#1 = [S IN[30]]\nG0 X#1\n" + END),
    ("blanks and tabs everywhere", HEAD + "\tG0\t X 1 .5\t Y - 2\n" + END),
    # case
    ("lower case", HEAD.lower() + "g0 x1 y2\n#<Depth> = 1\ng0 z#<depth>\n" + END.lower()),
    ("mixed case", HEAD + "g0 X1 y2\nG1 x2 F100\n" + "m2\n"),
    ("lower-case function", HEAD + "#1 = [sin[30] + abs[-1]]\nG0 X#1\n" + END),
    ("a Fanuc function", HEAD + "#1 = [bcd[1]]\n" + END),
    ("a function as a word's value", HEAD + "G0 Xsin[30] Y-abs[-1]\n" + END),
    ("a sign before a parameter", HEAD + "#1 = 1\nG0 X-#1 Y-[1]\n" + END),
    ("a line number after a word", HEAD + "G0 X1 N10\n" + END),
    # comments
    ("comment between words", HEAD + "G0 (move) X1\n" + END),
    ("comment between letter and number", HEAD + "G0 X(c)1\n" + END),
    ("comment inside a number", HEAD + "G0 X1(c)0\n" + END),
    ("comment before the line number", "(c) N10 G0 X1\n" + END),
    ("semicolon comment", HEAD + "G0 X1 ; move\n" + END),
    ("semicolon inside parentheses", HEAD + "G0 X1 (a;b)\n" + END),
    ("parenthesis after a semicolon", HEAD + "G0 X1 ; a (b\n" + END),
    ("comment with a message", HEAD + "(MSG, hello)\nG0 X1\n" + END),
    ("nested comment", HEAD + "G0 X1 (a (b) c)\n" + END),
    ("unclosed comment", HEAD + "G0 X1 (a\n" + END),
    # numbers
    ("trailing point", HEAD + "G0 X1.\n" + END),
    ("leading point", HEAD + "G0 X.5\n" + END),
    ("plus sign", HEAD + "G0 X+1\n" + END),
    ("minus and leading point", HEAD + "G0 X-.5\n" + END),
    ("exponent", HEAD + "G0 X1e3\n" + END),
    ("two points", HEAD + "G0 X1.2.3\n" + END),
    ("two signs", HEAD + "G0 X--1\n" + END),
    ("sign after sign", HEAD + "G0 X+-1\n" + END),
    ("point alone", HEAD + "G0 X.\n" + END),
    ("leading zeros", HEAD + "G00 X0001.500\n" + END),
    ("decimal G code", HEAD + "G0 X0\nG1.0 X1 F100\n" + END),
    ("decimal M code", HEAD + "M2.0\n"),
    ("decimal line number", "N10.5 " + HEAD + END),
    # the end of the program
    ("text after M30", HEAD + "G0 X1\nM30\nprint[\"Hello World!\"]\n"),
    ("text after M2 and a %", HEAD + "G0 X1\nM2\n%\nhello\n"),
    ("text after the closing %", "%\n" + HEAD + "G0 X1\n%\nhello\n"),
    ("subroutine after M2", HEAD + "o<s> call\nM2\nbad line\no<s> sub\nG90 G0 X2\no<s> endsub\n"),
    ("subroutine after the closing %", "%\n" + HEAD + "o<s> call\nM2\n%\no<s> sub\nG0 X2\n"
     "o<s> endsub\n"),
    ("M2 inside an if", HEAD + "#1 = 1\no1 if [#1 GT 0]\nM2\no1 endif\nG0 X\nM2\n"),
    ("M2 after block delete", HEAD + "/M2\nG0 X\nM2\n"),
    ("M30 with leading zero", HEAD + "G0 X1\nM030\nhello\n"),
]


@dataclass
class Verdict:
    name: str
    source: str  # sample, corpus, shops, variant
    rs274: str  # "ok", or "L<n> message"
    rs274_line: int | None
    kind: str  # program, configuration, library
    tapegate: str  # "ok", or the first error "L<n> TGnnn message"
    tapegate_line: int | None
    verdict: str  # both read, both refuse, rs274 refuses, tapegate refuses, lines differ,
    #                excluded


def verdict(rs_ok: bool, rs_line: int | None, kind: str, errors: list) -> str:
    if kind != "program":
        return "excluded"
    if rs_ok:
        return "both read" if not errors else "tapegate refuses"
    if not errors:
        return "rs274 refuses"
    if rs_line is not None and errors[0].line != rs_line:
        return "lines differ"
    return "both refuse"


def sweep(files: list[tuple[Path, str, str]], workdir: Path) -> list[Verdict]:
    found = compare.run_tapegate([p for p, _, _ in files], "linuxcnc")
    out = []
    for path, source, name in files:
        raw = path.read_bytes().decode("utf-8", "replace")
        rs = compare.run_rs274(path, workdir)
        kind, _ = compare.classify(rs, raw)
        errors = sorted(found.get(str(path), []), key=lambda e: e.line)
        if not rs.ok and rs.message.startswith(compare.LIBRARY_END) and kind == "program":
            # a fragment: rs274 refuses it at its end, tapegate by TG114
            errors = [e for e in errors if e.rule != compare.NO_PROGRAM_END] or errors
            rs.line = errors[0].line if errors else rs.line
        first = errors[0] if errors else None
        out.append(Verdict(
            name=name, source=source,
            rs274="ok" if rs.ok else f"L{rs.line} {rs.message}", rs274_line=rs.line,
            kind=kind,
            tapegate=f"L{first.line} {first.rule} {first.message}" if first else "ok",
            tapegate_line=first.line if first else None,
            verdict=verdict(rs.ok, rs.line, kind, errors)))
    return out


def real_files(samples: Path, corpus: Path, shops: Path) -> list[tuple[Path, str, str]]:
    files = [(p, "sample", str(p.relative_to(samples))) for p in sorted(samples.rglob("*.ngc"))]\
        if samples.is_dir() else []
    if corpus.is_dir():
        files += [(corpus / name, "corpus", name)
                  for name, profile in sorted(compare.matching().items())
                  if profile == "linuxcnc" and (corpus / name).is_file()]
    if (shops / "families.tsv").is_file():
        shops_module = _load("shops")
        files += [(shops / name, "shops", name)
                  for name, family, _ in shops_module.entries(shops)
                  if family == "linuxcnc" and (shops / name).is_file()]
    return files


def variant_files(workdir: Path) -> list[tuple[Path, str, str]]:
    files = []
    for i, (name, text) in enumerate(VARIANTS):
        path = workdir / f"variant{i:02d}.ngc"
        path.write_text(text)
        files.append((path, "variant", name))
    return files


def run(only: set[str], samples: Path, corpus: Path, shops: Path) -> list[Verdict]:
    with tempfile.TemporaryDirectory(prefix="rs274_sweep.") as tmp:
        work = Path(tmp)
        files = (real_files(samples, corpus, shops) if "real" in only else []) + \
                (variant_files(work) if "variants" in only else [])
        return sweep(files, work)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", action="store_true", help="machine-readable output")
    ap.add_argument("--only", choices=["real", "variants"], action="append")
    ap.add_argument("--samples", type=Path, default=compare.NCFILES)
    ap.add_argument("--corpus", type=Path, default=compare.CORPUS)
    ap.add_argument("--shops", type=Path, default=SHOPS)
    args = ap.parse_args(argv)
    if compare.rs274_exe() is None:
        print("rs274 is not installed (Debian package linuxcnc-uspace): nothing to compare",
              file=sys.stderr)
        return 0
    rows = run(set(args.only or ["real", "variants"]), args.samples, args.corpus, args.shops)
    if args.json:
        json.dump([asdict(r) for r in rows], sys.stdout, indent=1)
        print()
        return 0
    counts: dict[str, int] = {}
    for r in rows:
        counts[r.verdict] = counts.get(r.verdict, 0) + 1
        if r.verdict in ("both read", "both refuse", "excluded"):
            continue
        print(f"{r.verdict:16} {r.source:8} {r.name[:48]:48}\n"
              f"{'':25}rs274:    {r.rs274[:90]}\n{'':25}tapegate: {r.tapegate[:90]}")
    print(f"\n{len(rows)} programs: " + ", ".join(f"{k} {n}" for k, n in sorted(counts.items())))
    return 0


if __name__ == "__main__":
    sys.exit(main())
