"""Which codes do two built-in profiles both list without saying they are one function?

    .venv/bin/python benchmarks/code_meanings.py [--all] [--missing] [--profiles A,B,...]

For every pair of built-in profiles of two control families (the profile's ``dialect``; the
ISO 6983-1 profiles, whose codes are the standard's table, with ``--all``), every G or M code
number both list in their own ``[codes]`` where at least one of them gives it no ``meaning``
key (docs/profiles.md, "Code meanings"): the code, each side's function as its profile words it
and its key. ``convert`` between two families refuses such a code unless both functions are one
text (``machine::meaning_differences``): a row here is either a code to key from the controls'
documentation, or a refusal the converter makes on purpose. With ``--missing``, codes one side
lists and the other does not are listed too (``-`` for the side without): the converter refuses
them between families (the target alarms on the code or reads it as another), but for the
source's units code, which the converter replaces by the target's own. The last line counts
the rows.

Exit code 0 always (a listing).
"""

from __future__ import annotations

import argparse
import sys
from itertools import combinations
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))

from formats.codes import Code  # noqa: E402
from formats.profile import Profile, builtin_names, load_profile  # noqa: E402


def own_codes(profile: Profile) -> dict[str, Code]:
    """The codes a profile lists itself, by the name the core gives them (``G5``, ``G43.1``,
    ``M8``), without those it marks unassigned."""
    out = {}
    for key, code in profile.extra_codes.items():
        if code.status == "unassigned":
            continue
        number, dot, rest = key[1:].partition(".")
        out[f"{key[0]}{int(number)}{dot}{rest}"] = code
    return out


def one_function(a: str, b: str) -> bool:
    """The converter's test (``machine::one_function``): the same words, case and blanks
    aside."""
    return " ".join(a.lower().split()) == " ".join(b.lower().split())


def rows(a: Profile, b: Profile, missing: bool) -> list[tuple[str, str, str]]:
    ca, cb = own_codes(a), own_codes(b)
    out = []
    for name in sorted(set(ca) | set(cb), key=lambda n: (n[0], float(n[1:]))):
        x, y = ca.get(name), cb.get(name)
        if x is None or y is None:
            if missing:
                out.append((name, _side(x), _side(y)))
            continue
        if x.meaning and y.meaning:
            continue
        if one_function(x.function, y.function):
            continue
        out.append((name, _side(x), _side(y)))
    return out


def _side(code: Code | None) -> str:
    if code is None:
        return "-"
    return f"{code.function} [{code.meaning or 'no key'}]"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--all", action="store_true",
                        help="the ISO 6983-1 profiles too (their codes are the standard's)")
    parser.add_argument("--profiles", help="only these profiles, by name, comma separated")
    parser.add_argument("--missing", action="store_true",
                        help="codes one profile lists and the other does not, too")
    args = parser.parse_args(argv)
    names = args.profiles.split(",") if args.profiles else builtin_names()
    profiles = [load_profile(n) for n in names]
    if not args.all:
        profiles = [p for p in profiles if p.dialect.family != "iso"]
    count = 0
    for a, b in combinations(profiles, 2):
        if a.dialect.family == b.dialect.family:
            continue
        found = rows(a, b, args.missing)
        if not found:
            continue
        print(f"## {a.name} / {b.name}")
        for code, x, y in found:
            print(f"{code}\t{x}\t{y}")
        count += len(found)
    print(f"{count} codes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
