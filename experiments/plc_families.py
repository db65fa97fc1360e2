"""Parametric PLC families with a controlled small input angle ``theta`` (degrees), for termination studies.

Every family returns a ``nonobtuse.mesh3d.PLC`` whose outer surface is closed, edge-manifold and outward
oriented; facets inside a box (the fan) and dangling segments are internal features of the box's volume, and
every edge of every facet is shared by at least two facets. Segments are
the edges where facets meet at a non-flat angle, the free edges of internal facets, and the dangling segments.

    wedge(theta)        a prism over a circular sector: two facets meet at dihedral theta along the apex
                        edge; the sector's arc is split into pieces of at most 30 degrees, so the other
                        dihedrals are >= 75 degrees (90 at the caps). theta in (0, 180).
    wedge_asym(theta)   a prism over the triangle (0, 0), (1, 0), 2 (cos theta, sin theta): the two facets at
                        dihedral theta have widths 1 and 2, so for theta < 60 the narrow facet's far vertices
                        lie inside the diametral spheres of the wide facet's subfacets (the symmetric wedge
                        has none: it is Gabriel as it stands). The dihedral at the third edge,
                        asin(sin theta / sqrt(5 - 4 cos theta)), is smaller than theta. theta in (0, 180).
    spike(theta, k)     a cone of apex half-angle theta (unit generators) over a regular k-gon base;
                        the smallest angle is min(2 asin(sin theta sin(pi/k)) (apex angle of a side
                        triangle), 90 - theta (a generator against the base)). theta in (0, 90).
    segment_facet(theta) a dangling segment standing on the bottom facet of a box at angle theta to it.
                        theta in (0, 90].
    segments(theta)     two dangling segments meeting at angle theta inside a box. theta in (0, 180].
    fan(theta, k)       k internal facets around one edge cut a box into k regions, consecutive facets at
                        dihedral theta; needs k theta <= 360 so that the last gap is at least theta.

Coordinates are O(1) and nothing is symmetric about the box centre (the features sit off centre), so that no
feature point is cospherical with the box corners by construction.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from nonobtuse.mesh3d.plc import PLC

BOX_LO, BOX_HI = -1.0, 1.0


@dataclass(frozen=True)
class Family:
    """A PLC family: ``build(theta_degrees, k)`` and the open/closed range of theta it accepts."""

    name: str
    build: Callable[[float, int], PLC]
    theta_max: float  # theta in (0, theta_max]; theta_max itself excluded when max_exclusive
    max_exclusive: bool
    uses_k: bool
    default_k: int = 0

    def accepts(self, theta: float, k: int | None = None) -> bool:
        """Whether (theta, k) makes a valid member of the family."""
        k = self.default_k if k is None else k
        below = theta < self.theta_max if self.max_exclusive else theta <= self.theta_max
        fan_fits = not (self.name == "fan" and k * theta > 360.0)
        return 0.0 < theta and below and fan_fits and (not self.uses_k or k >= 3)


class _Builder:
    """Accumulates points, facets (as triangles with one facet id per polygon) and segments."""

    def __init__(self) -> None:
        self.points: list[tuple[float, float, float]] = []
        self.triangles: list[tuple[int, int, int]] = []
        self.facet_ids: list[int] = []
        self.segments: list[tuple[int, int]] = []
        self.n_facets = 0

    def point(self, p) -> int:
        self.points.append(tuple(float(c) for c in p))
        return len(self.points) - 1

    def facet(self, triangles: list[tuple[int, int, int]]) -> int:
        """One planar facet, given as its (consistently oriented) triangles."""
        self.triangles.extend(triangles)
        self.facet_ids.extend([self.n_facets] * len(triangles))
        self.n_facets += 1
        return self.n_facets - 1

    def polygon(self, loop: list[int]) -> int:
        """A convex planar polygon facet, fan-triangulated from its first vertex; oriented as the loop."""
        return self.facet([(loop[0], loop[i], loop[i + 1]) for i in range(1, len(loop) - 1)])

    def loop_segments(self, loop: list[int]) -> None:
        self.segments.extend((loop[i], loop[(i + 1) % len(loop)]) for i in range(len(loop)))

    def plc(self, source: str) -> PLC:
        return PLC(points=np.array(self.points, dtype=np.float64),
                   triangles=np.array(self.triangles, dtype=np.int64).reshape(-1, 3),
                   facet_ids=np.array(self.facet_ids, dtype=np.int64),
                   segments=np.array(self.segments, dtype=np.int64).reshape(-1, 2), source=source)


def _prism(b: _Builder, section: list[tuple[float, float]], z0: float, z1: float) -> None:
    """Closed prism over a convex counter-clockwise polygon, outward oriented; all its edges are segments."""
    low = [b.point((x, y, z0)) for x, y in section]
    high = [b.point((x, y, z1)) for x, y in section]
    b.polygon([low[0], *low[:0:-1]])  # bottom faces -z
    b.polygon(high)
    n = len(section)
    for i in range(n):
        j = (i + 1) % n
        b.polygon([low[i], low[j], high[j], high[i]])  # outward: (edge direction) x (+z) leaves the polygon
        b.segments.append((low[i], high[i]))
    b.loop_segments(low)
    b.loop_segments(high)


def _box(b: _Builder, bottom_point: tuple[float, float] | None = None) -> int | None:
    """The box [BOX_LO, BOX_HI]^3 as 6 facets (ids in build order) and 12 segments. With ``bottom_point``
    (x, y), that point is a vertex of the bottom facet (fan-triangulated around it); its index is returned."""
    lo, hi = BOX_LO, BOX_HI
    square = [(lo, lo), (hi, lo), (hi, hi), (lo, hi)]
    if bottom_point is None:
        _prism(b, square, lo, hi)
        return None
    low = [b.point((x, y, lo)) for x, y in square]
    high = [b.point((x, y, hi)) for x, y in square]
    foot = b.point((*bottom_point, lo))
    b.facet([(foot, low[(i + 1) % 4], low[i]) for i in range(4)])  # bottom faces -z
    b.polygon(high)
    for i in range(4):
        j = (i + 1) % 4
        b.polygon([low[i], low[j], high[j], high[i]])
        b.segments.append((low[i], high[i]))
    b.loop_segments(low)
    b.loop_segments(high)
    return foot


def wedge(theta: float, k: int = 0) -> PLC:
    """Prism (height 1) over the unit circular sector of angle theta: dihedral theta at the apex edge."""
    pieces = max(1, math.ceil(theta / 30.0))
    arc = [math.radians(theta) * j / pieces for j in range(pieces + 1)]
    b = _Builder()
    _prism(b, [(0.0, 0.0)] + [(math.cos(a), math.sin(a)) for a in arc], 0.0, 1.0)
    return b.plc(f"wedge(theta={theta:g})")


def wedge_asym(theta: float, k: int = 0) -> PLC:
    """Prism (height 1) over the triangle (0, 0), (1, 0), 2 (cos theta, sin theta)."""
    t = math.radians(theta)
    b = _Builder()
    _prism(b, [(0.0, 0.0), (1.0, 0.0), (2 * math.cos(t), 2 * math.sin(t))], 0.0, 1.0)
    return b.plc(f"wedge_asym(theta={theta:g})")


def spike(theta: float, k: int = 10) -> PLC:
    """Cone with unit generators at half-angle theta from the axis over a regular k-gon (apex on +z)."""
    t = math.radians(theta)
    b = _Builder()
    angles = [2 * math.pi * j / k for j in range(k)]
    base = [b.point((math.sin(t) * math.cos(a), math.sin(t) * math.sin(a), 0.0)) for a in angles]
    apex = b.point((0.0, 0.0, math.cos(t)))
    b.polygon(base[::-1])  # faces -z
    for j in range(k):
        b.facet([(base[j], base[(j + 1) % k], apex)])
        b.segments.append((base[j], apex))
    b.loop_segments(base)
    return b.plc(f"spike(theta={theta:g}, k={k})")


def segment_facet(theta: float, k: int = 0) -> PLC:
    """Box with a dangling segment of length 0.5 standing on its bottom facet at angle theta to the facet."""
    t = math.radians(theta)
    b = _Builder()
    foot_xy = (-0.25, 0.0625)
    foot = _box(b, foot_xy)
    top = b.point((foot_xy[0] + 0.5 * math.cos(t), foot_xy[1], BOX_LO + 0.5 * math.sin(t)))
    b.segments.append((foot, top))
    return b.plc(f"segment_facet(theta={theta:g})")


def segments(theta: float, k: int = 0) -> PLC:
    """Box with two dangling segments of length 0.5 from one interior point, at angle theta."""
    t = math.radians(theta)
    b = _Builder()
    _box(b)
    o = (-0.25, 0.0625, 0.03125)
    centre = b.point(o)
    for d in ((1.0, 0.0, 0.0), (math.cos(t), math.sin(t), 0.0)):
        b.segments.append((centre, b.point(tuple(o[i] + 0.5 * d[i] for i in range(3)))))
    return b.plc(f"segments(theta={theta:g})")


def _square_exit(c: tuple[float, float], angle: float) -> float:
    """Where the ray from c (inside the square [BOX_LO, BOX_HI]^2) at ``angle`` leaves the square, as a
    perimeter position s in [0, 4 * side): counter-clockwise from corner (BOX_LO, BOX_LO)."""
    side = BOX_HI - BOX_LO
    dx, dy = math.cos(angle), math.sin(angle)
    exits = []  # (ray parameter, perimeter position) for the four sides the ray runs towards
    if dy < 0:
        t = (BOX_LO - c[1]) / dy
        exits.append((t, c[0] + t * dx - BOX_LO))
    if dx > 0:
        t = (BOX_HI - c[0]) / dx
        exits.append((t, side + c[1] + t * dy - BOX_LO))
    if dy > 0:
        t = (BOX_HI - c[1]) / dy
        exits.append((t, 2 * side + BOX_HI - (c[0] + t * dx)))
    if dx < 0:
        t = (BOX_LO - c[0]) / dx
        exits.append((t, 3 * side + BOX_HI - (c[1] + t * dy)))
    return min(exits)[1] % (4 * side)


def _perimeter_point(s: float) -> tuple[float, float]:
    side = BOX_HI - BOX_LO
    edge, u = divmod(s, side)
    return [(BOX_LO + u, BOX_LO), (BOX_HI, BOX_LO + u), (BOX_HI - u, BOX_HI), (BOX_LO, BOX_HI - u)][int(edge)]


def fan(theta: float, k: int = 3) -> PLC:
    """The box cut into k regions by k internal facets around a vertical axis edge, consecutive ones at
    dihedral theta. Each internal facet runs from the axis to a box wall, so every facet edge is shared (a
    multi-region PLC, like TetGen's example.poly); the box facets are triangulated to contain the internal
    facets' edges."""
    side = BOX_HI - BOX_LO
    centre = (0.0625, -0.03125)
    walls = [_square_exit(centre, math.radians(i * theta)) for i in range(k)]
    if any(abs(w / side - round(w / side)) < 1e-9 for w in walls):
        raise ValueError(f"fan(theta={theta}, k={k}): an internal facet ends in a box corner")
    # Ring: the square's boundary points in counter-clockwise order, the corners and the facets' wall points.
    ring = sorted([(i * side, None) for i in range(4)] + [(w, i) for i, w in enumerate(walls)])
    b = _Builder()
    low = [b.point((*_perimeter_point(s), BOX_LO)) for s, _ in ring]
    high = [b.point((*_perimeter_point(s), BOX_HI)) for s, _ in ring]
    axis = (b.point((*centre, BOX_LO)), b.point((*centre, BOX_HI)))
    n = len(ring)
    b.facet([(axis[0], low[(j + 1) % n], low[j]) for j in range(n)])  # bottom, -z, fan around the axis foot
    b.facet([(axis[1], high[j], high[(j + 1) % n]) for j in range(n)])
    for wall in range(4):  # one facet per box wall, split at the wall points on it
        on_wall = [j for j in range(n) if wall * side <= ring[j][0] < (wall + 1) * side]
        quads = [(j, (j + 1) % n) for j in on_wall]
        b.facet([t for i, j in quads for t in ((low[i], low[j], high[j]), (low[i], high[j], high[i]))])
    b.loop_segments(low)
    b.loop_segments(high)
    b.segments.append(axis)
    wall_index = {facet: j for j, (_, facet) in enumerate(ring) if facet is not None}
    b.segments.extend(zip(low, high))  # box corner edges and the internal facets' wall edges
    for i in range(k):
        j = wall_index[i]
        b.polygon([axis[0], low[j], high[j], axis[1]])
        b.segments.extend([(axis[0], low[j]), (axis[1], high[j])])
    return b.plc(f"fan(theta={theta:g}, k={k})")


FAMILIES: dict[str, Family] = {
    "wedge": Family("wedge", wedge, 180.0, True, False),
    "wedge_asym": Family("wedge_asym", wedge_asym, 180.0, True, False),
    "spike": Family("spike", spike, 90.0, True, True, default_k=10),
    "segment_facet": Family("segment_facet", segment_facet, 90.0, False, False),
    "segments": Family("segments", segments, 180.0, False, False),
    "fan": Family("fan", fan, 360.0, False, True, default_k=3),
}


def make_plc(family: str, theta: float, k: int | None = None) -> PLC:
    """The member (theta degrees, k) of a family; ValueError when the family does not accept it."""
    fam = FAMILIES[family]
    k = fam.default_k if k is None else k
    if not fam.accepts(theta, k):
        raise ValueError(f"{family} does not accept theta={theta}, k={k}")
    return fam.build(theta, k)
