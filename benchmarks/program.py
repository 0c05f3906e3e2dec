"""Synthetic milling programs for benchmarks: explicit decimal, metric, the mix a CAM post writes
(mostly linear moves, some arcs, a comment now and then). Deterministic for a given size."""

from __future__ import annotations

import random
import sys
from collections.abc import Iterator

HEADER = ["%", "O1000 (BENCH)", "N1 G21 G17 G90 G94", "N2 T1 M06", "N3 S12000 M03",
          "N4 G00 X0. Y0. Z5."]


def blocks(n: int, seed: int = 1) -> Iterator[str]:
    r = random.Random(seed)
    yield from HEADER
    for i in range(n - len(HEADER) - 2):
        k = r.random()
        number = i + 10
        if k < 0.80:
            yield (f"N{number} G01 X{r.uniform(-200, 200):.3f} Y{r.uniform(-200, 200):.3f} "
                   f"Z-{r.uniform(0, 5):.2f} F{r.randint(100, 3000)}")
        elif k < 0.98:
            yield (f"N{number} G02 X{r.uniform(-200, 200):.3f} Y{r.uniform(-200, 200):.3f} "
                   f"I{r.uniform(-20, 20):.3f} J{r.uniform(-20, 20):.3f}")
        else:
            yield f"N{number} G00 Z5. (RETRACT)"
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
