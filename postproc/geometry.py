"""Arc geometry for the backplot: the points of an arc to draw.

Where an arc runs -- its centre, by I J K, by its radius (``G02 X Y R``, Sinumerik ``CR=``) --
is the core's (``crates/core/src/geometry.rs``, the checker's path, the same centre its TG410
and its statistics use); this module only samples the arc it gives into points.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

__all__ = ["PLANE_AXES", "arc_points", "sweep"]

# The indexes (into X Y Z) of a plane's first and second axis: the first is drawn across, the
# second up, and G02 is clockwise seen that way (G17 X-Y, G18 Z-X, G19 Y-Z; ISO 6983-1 7.3).
PLANE_AXES = {17: (0, 1), 18: (2, 0), 19: (1, 2)}

Point = tuple[float, float, float]


def sweep(start: Sequence[float], end: Sequence[float], centre: Sequence[float], plane: int,
          clockwise: bool) -> float:
    """The angle in radians (0 < sweep <= 2 pi) the arc turns through; the same start and end
    point is a full circle, as on the control."""
    i, j = PLANE_AXES[plane]
    a0 = math.atan2(start[j] - centre[j], start[i] - centre[i])
    a1 = math.atan2(end[j] - centre[j], end[i] - centre[i])
    turn = ((a0 - a1) if clockwise else (a1 - a0)) % (2 * math.pi)
    return turn if turn > 1e-12 else 2 * math.pi


def arc_points(start: Sequence[float], end: Sequence[float], centre: Sequence[float],
               plane: int, clockwise: bool, per_turn: int = 96) -> list[Point]:
    """Points along the arc, ``per_turn`` to a full circle (at least 4): from the start point
    exactly to the end point. The radius goes over from the start's to the end's (the two
    differ within the checker's tolerance) and the third axis linearly (a helix)."""
    i, j = PLANE_AXES[plane]
    k = 3 - i - j
    turn = sweep(start, end, centre, plane, clockwise)
    a0 = math.atan2(start[j] - centre[j], start[i] - centre[i])
    r0 = math.hypot(start[i] - centre[i], start[j] - centre[j])
    r1 = math.hypot(end[i] - centre[i], end[j] - centre[j])
    steps = max(4, math.ceil(per_turn * turn / (2 * math.pi)))
    direction = -1.0 if clockwise else 1.0
    points: list[Point] = [(start[0], start[1], start[2])]
    for n in range(1, steps):
        t = n / steps
        angle = a0 + direction * turn * t
        r = r0 + (r1 - r0) * t
        p = [0.0, 0.0, 0.0]
        p[i] = centre[i] + r * math.cos(angle)
        p[j] = centre[j] + r * math.sin(angle)
        p[k] = start[k] + (end[k] - start[k]) * t
        points.append((p[0], p[1], p[2]))
    points.append((end[0], end[1], end[2]))
    return points
