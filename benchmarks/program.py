"""Synthetic milling programs for benchmarks: explicit decimal, metric, the mix a CAM post writes
(mostly linear moves, some arcs, a comment now and then). Deterministic for a given size."""

from __future__ import annotations

import math
import random
import sys
from collections.abc import Iterator

HEADER = ["%", "O1000 (BENCH)", "N1 G21 G17 G90 G94", "N2 T1 M06", "N3 S12000 M03",
          "N4 G00 X0. Y0. Z5."]


def blocks(n: int, seed: int = 1, clean: bool = False) -> Iterator[str]:
    """About 27 bytes per block, like the 1,000,000-block / ~27 MB program of the issue:
    80 % linear XY moves, 15 % arcs with I J, 5 % Z moves with a feed, a comment every 1,000.

    The default program is a stress test for the checker: its arcs have random centres, the
    linear moves after an arc inherit G02 (arcs without I J), and sequence numbers pass N99999,
    so it has about two findings per block. ``clean`` writes what a CAM post would: arcs on
    their circle from the current point, G01 on the first linear move after an arc, sequence
    numbers wrapping at N99999 -- the findings left are the TV check's odd block lengths."""
    r = random.Random(seed)
    yield from HEADER
    yield "N5 G01 F1200."
    x = y = 0.0
    motion = 1
    for i in range(n - len(HEADER) - 3):
        k = r.random()
        number = (i + 10) % 100000 if clean else i + 10
        if i % 1000 == 999:
            yield f"N{number} G00 Z5. (RETRACT)"
            motion = 0
        elif k < 0.80:
            x, y = round(r.uniform(-200, 200), 3), round(r.uniform(-200, 200), 3)
            g = "G01 " if clean and motion != 1 else ""
            motion = 1 if clean else motion
            yield f"N{number} {g}X{x:.3f} Y{y:.3f}"
        elif k < 0.95:
            if not clean:
                yield (f"N{number} G02 X{r.uniform(-99, 99):.2f} Y{r.uniform(-99, 99):.2f} "
                       f"I{r.uniform(-9, 9):.2f} J{r.uniform(-9, 9):.2f}")
                continue
            ci, cj = round(r.uniform(-9, 9), 2), round(r.uniform(-9, 9), 2)
            if abs(x + 2 * ci) > 200 or abs(y + 2 * cj) > 200:  # turn back towards the middle
                ci, cj = -ci, -cj
            angle = r.uniform(0, 2 * math.pi)
            radius = math.hypot(ci, cj)
            x = round(x + ci + radius * math.cos(angle), 3)
            y = round(y + cj + radius * math.sin(angle), 3)
            motion = 2
            yield f"N{number} G02 X{x:.3f} Y{y:.3f} I{ci:.2f} J{cj:.2f}"
        else:
            motion = 1
            yield f"N{number} G01 Z-{r.uniform(0, 5):.2f} F{r.randint(100, 3000)}."
    yield "M30"
    yield "%"


def write(path: str, n: int, clean: bool = False) -> None:
    with open(path, "w", encoding="ascii", newline="") as f:
        batch: list[str] = []
        for line in blocks(n, clean=clean):
            batch.append(line)
            if len(batch) >= 10000:
                f.write("\n".join(batch) + "\n")
                batch.clear()
        if batch:
            f.write("\n".join(batch) + "\n")


if __name__ == "__main__":
    write(sys.argv[1], int(sys.argv[2]), clean="--clean" in sys.argv[3:])
