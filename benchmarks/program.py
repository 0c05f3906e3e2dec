"""Synthetic milling programs for benchmarks: explicit decimal, metric, the mix a CAM post writes
(mostly linear moves, some arcs, a comment now and then). Deterministic for a given size."""

from __future__ import annotations

import random
import sys
from collections.abc import Iterator

HEADER = ["%", "O1000 (BENCH)", "N1 G21 G17 G90 G94", "N2 T1 M06", "N3 S12000 M03",
          "N4 G00 X0. Y0. Z5."]


def blocks(n: int, seed: int = 1) -> Iterator[str]:
    """About 27 bytes per block, like the 1,000,000-block / ~27 MB program of the issue:
    80 % linear XY moves, 15 % arcs with I J, 5 % Z moves with a feed, a comment every 1,000."""
    r = random.Random(seed)
    yield from HEADER
    yield "N5 G01 F1200."
    for i in range(n - len(HEADER) - 3):
        k = r.random()
        number = i + 10
        if i % 1000 == 999:
            yield f"N{number} G00 Z5. (RETRACT)"
        elif k < 0.80:
            yield f"N{number} X{r.uniform(-200, 200):.3f} Y{r.uniform(-200, 200):.3f}"
        elif k < 0.95:
            yield (f"N{number} G02 X{r.uniform(-99, 99):.2f} Y{r.uniform(-99, 99):.2f} "
                   f"I{r.uniform(-9, 9):.2f} J{r.uniform(-9, 9):.2f}")
        else:
            yield f"N{number} G01 Z-{r.uniform(0, 5):.2f} F{r.randint(100, 3000)}."
    yield "M30"
    yield "%"


def write(path: str, n: int) -> None:
    with open(path, "w", encoding="ascii", newline="") as f:
        batch: list[str] = []
        for line in blocks(n):
            batch.append(line)
            if len(batch) >= 10000:
                f.write("\n".join(batch) + "\n")
                batch.clear()
        if batch:
            f.write("\n".join(batch) + "\n")


if __name__ == "__main__":
    write(sys.argv[1], int(sys.argv[2]))
