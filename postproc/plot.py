"""Backplot: the tool path drawn with matplotlib -- rapids dashed, feeds solid, true arcs, the
findings marked where they are, and a legend. SVG or PNG by the file name."""

from __future__ import annotations

import math
from collections.abc import Sequence

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from postproc.check import Finding, Segment  # noqa: E402

VIEWS = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}
_ISO = ((math.cos(math.radians(30)), -math.cos(math.radians(30)), 0.0),
        (math.sin(math.radians(30)), math.sin(math.radians(30)), 1.0))


def _project(p: Sequence[float], view: str) -> tuple[float, float]:
    if view == "iso":
        return (sum(a * b for a, b in zip(_ISO[0], p, strict=True)),
                sum(a * b for a, b in zip(_ISO[1], p, strict=True)))
    i, j = VIEWS[view]
    return p[i], p[j]


def _arc_points(seg: Segment, steps: int = 48) -> list[tuple[float, float, float]]:
    assert seg.centre is not None
    i, j = {17: (0, 1), 18: (2, 0), 19: (1, 2)}[seg.plane]
    k = 3 - i - j
    s, e, c = seg.start, seg.end, seg.centre
    a0 = math.atan2(s[j] - c[j], s[i] - c[i])
    a1 = math.atan2(e[j] - c[j], e[i] - c[i])
    sweep = (a0 - a1) if seg.clockwise else (a1 - a0)
    sweep %= 2 * math.pi
    if sweep == 0:
        sweep = 2 * math.pi
    r = math.hypot(s[i] - c[i], s[j] - c[j])
    points = []
    for n in range(steps + 1):
        t = n / steps
        angle = a0 - sweep * t if seg.clockwise else a0 + sweep * t
        p = [0.0, 0.0, 0.0]
        p[i] = c[i] + r * math.cos(angle)
        p[j] = c[j] + r * math.sin(angle)
        p[k] = s[k] + (e[k] - s[k]) * t
        points.append((p[0], p[1], p[2]))
    return points


def plot(path: Sequence[Segment], findings: Sequence[Finding], output: str, *,
         view: str = "xy", title: str = "") -> None:
    fig, ax = plt.subplots(figsize=(8, 6))
    by_line: dict[int, tuple[float, float]] = {}
    drawn = {"rapid": False, "feed": False, "arc": False}
    for seg in path:
        points = _arc_points(seg) if seg.kind == "arc" and seg.centre else [seg.start, seg.end]
        xs, ys = zip(*(_project(p, view) for p in points), strict=True)
        style = {"rapid": dict(color="tab:red", linestyle="--", linewidth=0.8),
                 "feed": dict(color="tab:blue", linestyle="-", linewidth=1.2),
                 "arc": dict(color="tab:green", linestyle="-", linewidth=1.2)}[seg.kind]
        label = {"rapid": "rapid (G00)", "feed": "feed (G01)", "arc": "arc (G02/G03)"}[seg.kind]
        ax.plot(xs, ys, label=None if drawn[seg.kind] else label, **style)  # type: ignore[arg-type]
        drawn[seg.kind] = True
        by_line[seg.line] = (xs[-1], ys[-1])
    marked = False
    for f in findings:
        if f.line in by_line:
            x, y = by_line[f.line]
            color = "black" if f.severity == "error" else "orange"
            ax.plot([x], [y], marker="x", color=color, markersize=9, linestyle="none",
                    label=None if marked else "finding")
            ax.annotate(f.rule, (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7)
            marked = True
    names = {"xy": ("X", "Y"), "xz": ("X", "Z"), "yz": ("Y", "Z"), "iso": ("", "")}[view]
    ax.set_xlabel(names[0])
    ax.set_ylabel(names[1])
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, linewidth=0.3)
    ax.set_title(title or f"backplot ({view})")
    if any(drawn.values()) or marked:
        ax.legend(loc="best", fontsize=8)
    fig.tight_layout()
    fig.savefig(output)
    plt.close(fig)
