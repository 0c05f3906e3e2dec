"""Backplot: the tool path drawn with matplotlib -- rapids dashed, feeds solid, arcs as arcs (by
I J K, by R and by Sinumerik ``CR=``), the findings as markers with a short legend. SVG or PNG
by the file name.

The path is the checker's (:attr:`postproc.check.Checker.path`, the core's modal state: the
walk that finds the findings records the moves, every arc with its centre, by I J K, R or CR=
alike -- the centre the checker's own TG410 is decided by). What the path does not say -- where
the position is not known, the units -- the same pass gathers too
(:attr:`postproc.check.Checker.drawn`): a program is read once, by the core. The whole path is
two line collections (rapid, feed), and the findings one marker set per rule, so a program of
any size is a handful of matplotlib artists.

A lathe (profile ``control_type = "lathe"``) is drawn as its programmer reads it: Z across and
X up, and where X is programmed as a diameter (the Fanuc and Haas lathes) X/2, the radius. Only
X Y Z are drawn; a program that moves U V W or a rotary axis (A B C, in degrees) says so on the
picture.
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

from formats.machine import machine  # noqa: E402
from formats.profile import Profile  # noqa: E402
from postproc.check import Checker, Finding, Segment, check_file  # noqa: E402
from postproc.geometry import arc_points  # noqa: E402

__all__ = ["LEGEND_RULES", "VIEWS", "VIEW_AXES", "Backplot", "Move", "backplot", "backplot_file",
           "default_view", "is_diameter", "legend_groups", "moves", "plot", "transforms_note"]

VIEWS = ("xy", "xz", "yz", "iso")
LEGEND_RULES = 8  # rules named in the legend; the others are one group
_AXES = {"xy": (0, 1), "xz": (0, 2), "yz": (1, 2)}
# the axes each view shows (0 X, 1 Y, 2 Z)
VIEW_AXES = {"xy": frozenset({0, 1}), "xz": frozenset({0, 2}), "yz": frozenset({1, 2}),
             "iso": frozenset({0, 1, 2})}
_ISO = np.array([(math.cos(math.radians(30)), -math.cos(math.radians(30)), 0.0),
                 (math.sin(math.radians(30)), math.sin(math.radians(30)), 1.0)]).T
_SEVERITY = {"error": 0, "warning": 1, "info": 2}
_MARKER = {"error": "X", "warning": "^"}  # a note or info: a dot
_SIZE = {"error": 8, "warning": 7}
_COLOURS = ("black", "tab:orange", "tab:purple", "tab:brown", "tab:pink", "tab:olive",
            "tab:cyan", "tab:green")  # not the rapids' red nor the feeds' blue


@dataclass
class Move:
    """One move as drawn: its points (X Y Z in the drawn space: a lathe's diameter X halved)."""

    kind: str  # rapid | feed
    points: list[tuple[float, float, float]]
    line: int
    arc: bool = False
    impossible: bool = False  # an R arc shorter than half its chord: the chord is drawn
    lost: bool = False  # it starts where the position is unknown: only its end point is kept
    # axes (0 X, 1 Y, 2 Z) it runs at where the program lost them (a shift, a skip, a call):
    # a view showing one of them does not draw it
    adrift: frozenset[int] = frozenset()


@dataclass
class Backplot:
    """What a picture is drawn from: the moves, the findings, and how to read the axes."""

    moves: list[Move]
    findings: list[Finding]
    lathe: bool = False
    diameter: bool = False  # X is programmed as a diameter; the moves hold X/2
    units: str = "metric"  # metric | inch | mixed (the program switches)
    not_drawn: list[str] = field(default_factory=list)  # axes moved but not drawn (A, B, U...)
    # blocks that shift, rotate, scale or mirror the coordinates, not applied in the picture:
    # the first few (line, code) and how many there are
    transforms: list[tuple[int, str]] = field(default_factory=list)
    transform_count: int = 0
    # from which line the moves are not known and why (a G code the family's list lacks):
    # those moves are not drawn
    moves_not_known: list[str] = field(default_factory=list)


def is_diameter(profile: Profile) -> bool:
    """X is a diameter: the Fanuc and Haas lathes (the core's reading of the machine)."""
    return machine(profile).diameter


def default_view(profile: Profile) -> str:
    """Z across and X up on a lathe; X-Y otherwise."""
    return "xz" if profile.control_type == "lathe" else "xy"


# -- the path ------------------------------------------------------------------------------------


def moves(path: Sequence[Segment], *, diameter: bool = False,
          unknown: dict[int, set[int]] | None = None,
          machine: set[int] | None = None,
          adrift: dict[int, set[int]] | None = None) -> list[Move]:
    """The checker's moves as drawn: its arcs (by I J K, R or CR=, with the core's centres)
    sampled, an R arc that cannot exist (kind "chord") as the chord, marked; a diameter X, the
    centre's too, halved.

    A move from a position nobody knows is not drawn (an unknown axis reads 0 in the path),
    and the path goes on from its end point: one that does not start where the one before it
    ended (after a subprogram call or a jump the checker does not follow, TG140), and one that
    moves an axis ``unknown`` names for its line (the first moves of a program, before it has
    set X, Y and Z, and those after a reference return: the tool is where the machine left it).
    A move on a ``machine`` line (G28 G30 G53: to or through the reference point, in machine
    coordinates) is not drawn either: it keeps only its start point. A move on an ``adrift``
    line runs at axes the program had set and lost since (after a shift, a skip, a call):
    :func:`plot` does not draw it in a view that shows one of them."""
    unknown = unknown or {}
    machine = machine or set()
    adrift = adrift or {}
    out: list[Move] = []
    last: tuple[float, float, float] | None = None

    def drawn(p: tuple[float, float, float]) -> tuple[float, float, float]:
        return (p[0] / 2, p[1], p[2]) if diameter else p

    for seg in path:
        s, e = seg.start, seg.end
        lost = (last is not None and s != last) or any(
            s[n] != e[n] for n in unknown.get(seg.line, ()))
        last = e
        s, e = drawn(s), drawn(e)
        kind = "rapid" if seg.kind == "rapid" else "feed"
        off = frozenset(adrift.get(seg.line, ()))
        if seg.line in machine:  # its end is no work position
            out.append(Move(kind, [s], seg.line, lost=True))
        elif lost:  # nothing to draw from
            out.append(Move(kind, [e], seg.line, lost=True))
        elif seg.kind == "chord":
            out.append(Move(kind, [s, e], seg.line, arc=True, impossible=True, adrift=off))
        elif seg.kind == "arc" and seg.centre is not None:
            out.append(Move(kind, arc_points(s, e, drawn(seg.centre), seg.plane, seg.clockwise),
                            seg.line, arc=True, adrift=off))
        else:
            out.append(Move(kind, [s, e], seg.line, adrift=off))
    return out


def _backplot(checker: Checker, findings: list[Finding], profile: Profile) -> Backplot:
    diameter = is_diameter(profile)
    walk = checker.drawn
    assert walk is not None, "the checker records the path for the backplot"
    drawn = moves(checker.path or [], diameter=diameter, unknown=walk.unknown,
                  machine=walk.machine, adrift=walk.adrift)
    units = walk.units or {profile.default_units}
    return Backplot(drawn, findings, lathe=profile.control_type == "lathe", diameter=diameter,
                    units=units.pop() if len(units) == 1 else "mixed",
                    not_drawn=[a for a in "UVWABC" if a in checker.stats.low],
                    transforms=walk.transforms, transform_count=walk.transform_count,
                    moves_not_known=checker.stats.moves_not_known)


def transforms_note(bp: Backplot) -> str:
    """What the picture says of the coordinate transforms it does not apply ("" for none):
    its moves are the program's coordinates, not where the machine goes under a shift (G52,
    G92, G10), a rotation (G68), a scaling (G51) or a mirror (G51.1, Haas G101)."""
    if not bp.transform_count:
        return ""
    named = ", ".join(f"{code} (line {line})" for line, code in bp.transforms)
    more = bp.transform_count - len(bp.transforms)
    if more > 0:
        named += f" and {more} more"
    return (f"not applied: {named}: the moves after them are drawn in the program's "
            "coordinates, not where the machine goes")


def backplot(text: str, profile: Profile, *, file: str = "<input>") -> Backplot:
    """The backplot of a program held in memory."""
    checker = Checker(profile, file, record_path=True)
    findings = list(checker.run_stream([text], profile.dialect))
    return _backplot(checker, findings, profile)


def backplot_file(path: str, profile: Profile, *, display: str | None = None) -> Backplot:
    """The backplot of a file (text or tape image)."""
    checker, findings = check_file(path, profile, display=display, record_path=True)
    return _backplot(checker, findings, profile)


# -- the picture ---------------------------------------------------------------------------------


def _project(points: np.ndarray, view: str, lathe: bool) -> np.ndarray:
    if view == "iso":
        projected: np.ndarray = points @ _ISO
        return projected
    i, j = _AXES[view]
    if lathe and view == "xz":
        i, j = j, i  # Z across, X up
    return points[:, [i, j]]


def _labels(view: str, bp: Backplot) -> tuple[str, str]:
    unit = {"inch": "in", "metric": "mm"}.get(bp.units, "mm and in as programmed")
    x = f"X/2 ({unit}, radius: X is programmed as a diameter)" if bp.diameter else f"X ({unit})"
    if view == "iso":
        return f"isometric X Y Z ({unit})", ""
    names = {"xy": (x, f"Y ({unit})"), "xz": (x, f"Z ({unit})"), "yz": (f"Y ({unit})",
                                                                      f"Z ({unit})")}[view]
    if bp.lathe and view == "xz":
        return f"Z ({unit})", x
    return names


def legend_groups(findings: Sequence[Finding], cap: int = LEGEND_RULES
                  ) -> list[tuple[str, str, int, list[Finding]]]:
    """The findings grouped by rule for the legend: (label, severity, count, findings), the
    most severe and most frequent rules first, at most ``cap`` of them; the rest are one last
    group ("N more rules")."""
    by_rule: dict[str, list[Finding]] = {}
    for f in findings:
        by_rule.setdefault(f.rule, []).append(f)
    order = sorted(by_rule, key=lambda r: (_SEVERITY.get(by_rule[r][0].severity, 2),
                                           -len(by_rule[r]), r))
    groups: list[tuple[str, str, int, list[Finding]]] = []
    for r in order[:cap]:
        severity = by_rule[r][0].severity
        groups.append((f"{r} {severity} \u00d7{len(by_rule[r])}", severity, len(by_rule[r]),
                       by_rule[r]))
    rest = order[cap:]
    if rest:
        others = [f for r in rest for f in by_rule[r]]
        worst = min((f.severity for f in others), key=lambda s: _SEVERITY.get(s, 2))
        groups.append((f"{len(rest)} more rules \u00d7{len(others)}", worst, len(others),
                       others))
    return groups


def plot(bp: Backplot, output: str, *, view: str = "xy", title: str = "",
         findings: bool = True) -> int:
    """Draw ``bp`` into ``output`` (.svg or .png); returns how many findings are marked."""
    fig, ax = plt.subplots(figsize=(10, 6))
    # one array of every point, projected at once, then cut into the moves' polylines
    counts = [len(m.points) for m in bp.moves]
    every = np.array([p for m in bp.moves for p in m.points], dtype=float).reshape(-1, 3)
    flat = _project(every, view, bp.lathe)
    lines = np.split(flat, np.cumsum(counts)[:-1]) if counts else []
    styles = {"rapid": dict(colors="tab:red", linestyles="--", linewidths=0.8,
                            label="rapid (G00)"),
              "feed": dict(colors="tab:blue", linestyles="-", linewidths=1.1,
                           label="feed (G01, arcs G02/G03)")}
    shown = VIEW_AXES[view]
    for kind, style in styles.items():
        chosen = _chains([pts for m, pts in zip(bp.moves, lines, strict=True)
                          if m.kind == kind and not m.impossible and len(pts) > 1
                          and not m.adrift & shown])
        if chosen:
            ax.add_collection(LineCollection(chosen, **style))  # type: ignore[arg-type]
    bad = [pts for m, pts in zip(bp.moves, lines, strict=True)
           if m.impossible and not m.adrift & shown]
    if bad:
        ax.add_collection(LineCollection(bad, colors="magenta", linestyles=":", linewidths=2.5,
                                         label=f"R arc that cannot exist, chord drawn "
                                               f"\u00d7{len(bad)}"))
    marked = _mark(ax, bp, lines) if findings else 0
    if len(flat):
        ax.update_datalim(flat)
    ax.autoscale_view()
    across, up = _labels(view, bp)
    ax.set_xlabel(across)
    ax.set_ylabel(up)
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, linewidth=0.3)
    ax.set_title(title or f"backplot ({view})")
    notes = []
    if bp.not_drawn:
        axes = " ".join(bp.not_drawn)
        notes.append(f"not drawn: {axes} (the picture is the X Y Z path only"
                     + ("; A B C are rotary, in degrees)" if set(bp.not_drawn) & set("ABC")
                        else ")"))
    if bp.transform_count:
        notes.append(transforms_note(bp))
    notes.extend(f"moves not known {why}" for why in bp.moves_not_known)
    if notes:
        ax.text(0.0, -0.12, "\n".join(notes), transform=ax.transAxes, fontsize=8, va="top",
                wrap=True)
    if ax.collections or ax.lines:
        # outside the axes: "best" would test every point of the path for overlap
        ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=8, borderaxespad=0)
    fig.tight_layout()
    fig.savefig(output)
    plt.close(fig)
    return marked


def _chains(polylines: list[np.ndarray]) -> list[np.ndarray]:
    """Polylines joined where one starts at the end of the one before (a run of feed moves
    is one path: a smaller SVG, and a dash pattern that runs on)."""
    out: list[list[np.ndarray]] = []
    for pts in polylines:
        if out and np.array_equal(out[-1][-1][-1], pts[0]):
            out[-1].append(pts[1:])
        else:
            out.append([pts])
    return [np.concatenate(run) for run in out]


def _mark(ax: plt.Axes, bp: Backplot, lines: list[np.ndarray]) -> int:
    """The findings as markers at the end point of their block (or where the tool is when the
    block runs), one marker set per legend group."""
    if not bp.moves:
        return 0
    move_lines = [m.line for m in bp.moves]
    ends = [pts[-1] for pts in lines]
    first = lines[0][0]
    marked = 0
    groups = legend_groups([f for f in bp.findings if f.line > 0])
    for n, (label, severity, _count, group) in enumerate(groups):
        where = []
        for f in group:
            k = bisect.bisect_right(move_lines, f.line) - 1
            where.append(ends[k] if k >= 0 else first)
        xy = np.array(where).reshape(-1, 2)
        last = n == LEGEND_RULES
        size = 4 if last else _SIZE.get(severity, 4)
        # a rule found on every other block would hide the path: the more, the smaller
        size = max(2.5, size * min(1.0, (100 / len(where)) ** 0.25))
        ax.plot(xy[:, 0], xy[:, 1], linestyle="none", marker=_MARKER.get(severity, "o"),
                markersize=size, color="tab:gray" if last else _COLOURS[n % 8],
                markeredgewidth=0.5, alpha=0.8, label=label)
        marked += len(where)
    return marked

