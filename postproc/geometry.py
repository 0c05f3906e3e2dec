"""Arc geometry for the backplot: the centre of an arc given by its radius, and the points of an
arc to draw.

The centre of an arc given by I J K is the core's (``crates/core/src/check.rs``, the checker's
own arc check and path); this module adds what the core's path leaves as a straight move, the
arc given by its radius (``G02 X Y R``, Sinumerik ``CR=``), and samples arcs into points.

Why the radius arc starts from exact decimals: its centre lies on the chord's perpendicular
bisector at the distance ``sqrt(R**2 - (chord/2)**2)`` from the chord's middle. For the common
half circle (R is half the chord) and near it, that difference of two nearly equal squares is
where floats lose every digit: ``G02 X10.001 Y0 R5.0005`` is an exact half circle that floats
can turn into "no such arc" or into a centre off the chord. Computed from the written decimals,
the squares are exact, the comparison with the chord is exact, and only the square root is
rounded (to 28 digits) before the result becomes a float for drawing.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from decimal import Decimal, localcontext

__all__ = ["PLANE_AXES", "arc_points", "radius_centre", "sweep"]

# The indexes (into X Y Z) of a plane's first and second axis: the first is drawn across, the
# second up, and G02 is clockwise seen that way (G17 X-Y, G18 Z-X, G19 Y-Z; ISO 6983-1 7.3).
PLANE_AXES = {17: (0, 1), 18: (2, 0), 19: (1, 2)}

Point = tuple[float, float, float]


def radius_centre(start: tuple[Decimal, Decimal], end: tuple[Decimal, Decimal],
                  radius: Decimal, clockwise: bool,
                  tolerance: Decimal = Decimal(0)) -> tuple[float, float] | None:
    """The centre of the arc from ``start`` to ``end`` (in the plane's first and second axis)
    of the signed ``radius``: positive for the arc of at most 180 degrees, negative for the
    arc over 180 degrees (the Fanuc, Haas, LinuxCNC and Sinumerik reading of R and CR).

    None when no arc of that radius joins the two points: the radius is shorter than half the
    chord by more than ``tolerance`` (the checker's TG410), or it is zero, or the points are
    one point (a full circle cannot be given by a radius). A radius short by at most
    ``tolerance`` gives the half circle about the chord's middle.
    """
    with localcontext() as ctx:
        ctx.prec = 28
        dx, dy = end[0] - start[0], end[1] - start[1]
        chord2 = dx * dx + dy * dy
        r = abs(radius)
        if r == 0 or chord2 == 0:
            return None
        half2 = chord2 / 4
        if r * r < half2:
            if (r + abs(tolerance)) ** 2 < half2:
                return None
            height = Decimal(0)
        else:
            height = (r * r - half2).sqrt()
        chord = chord2.sqrt()
        # the centre is right of the way from start to end for a clockwise arc of at most 180
        # degrees, left for a counter-clockwise one; a negative radius takes the other side
        side = 1 if clockwise == (radius > 0) else -1
        mx, my = (start[0] + end[0]) / 2, (start[1] + end[1]) / 2
        cx = mx + side * height * dy / chord
        cy = my - side * height * dx / chord
        return float(cx), float(cy)


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
