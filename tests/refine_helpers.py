"""Shared by the refinement tests: CG:SHOP instances as domains, an exact check of a mesh in rationals, and
random star polygons."""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import numpy as np

from nonobtuse import Domain

SHARED = Path(__file__).resolve().parents[1] / ".." / "shared" / "data"


def cgshop_domain(path: Path) -> Domain:
    """A CG:SHOP 2025 instance: the region_boundary polygon (closed), additional constraints, interior
    points."""
    d = json.loads(path.read_text())
    pts = np.c_[d["points_x"], d["points_y"]].astype(np.float64)
    rb = d["region_boundary"]
    seg = [(rb[i], rb[(i + 1) % len(rb)]) for i in range(len(rb))] + [
        tuple(c) for c in d["additional_constraints"]
    ]
    return Domain(points=pts, segments=np.array(seg, dtype=np.int64), source=str(path))


def obtuse_constraint_sides(mesh, *, boundary_only: bool = False) -> int:
    """Sides of constrained segments (one per incident triangle: two for an interface or dangling segment;
    only segments with exactly one triangle when boundary_only) whose angle opposite the segment is obtuse,
    decided in exact rationals on the stored doubles, independently of the C++ certificate."""
    apex: dict[tuple[int, int], list[int]] = {tuple(sorted(map(int, s))): [] for s in mesh.segments}
    for t in np.asarray(mesh.triangles):
        for i in range(3):
            k = tuple(sorted((int(t[(i + 1) % 3]), int(t[(i + 2) % 3]))))
            if k in apex:
                apex[k].append(int(t[i]))
    p = [(Fraction(x), Fraction(y)) for x, y in np.asarray(mesh.points)]
    bad = 0
    for (a, b), cs in apex.items():
        if boundary_only and len(cs) != 1:
            continue
        for c in cs:
            (ax, ay), (bx, by), (cx, cy) = p[a], p[b], p[c]
            bad += (ax - cx) * (bx - cx) + (ay - cy) * (by - cy) < 0
    return bad


def obtuse_boundary_sides(mesh) -> int:
    """Boundary segments (exactly one incident triangle) whose triangle is obtuse at the apex (exact)."""
    return obtuse_constraint_sides(mesh, boundary_only=True)


def non_delaunay_edges(mesh) -> int:
    """Unconstrained interior edges that are not locally Delaunay (the opposite vertex strictly inside the
    other triangle's circumcircle), decided exactly in rationals. 0 for a constrained Delaunay
    triangulation."""
    p = [(Fraction(x), Fraction(y)) for x, y in np.asarray(mesh.points)]
    constrained = {tuple(sorted(map(int, s))) for s in mesh.segments}
    opposite: dict[tuple[int, int], list[tuple[int, tuple[int, int, int]]]] = {}
    for t in np.asarray(mesh.triangles).tolist():
        for i in range(3):
            opposite.setdefault(tuple(sorted((t[(i + 1) % 3], t[(i + 2) % 3]))), []).append((t[i], tuple(t)))

    def incircle(a, b, c, d):  # > 0: d strictly inside the circle through a, b, c (counter-clockwise)
        rows = [(x - d[0], y - d[1]) for x, y in (a, b, c)]
        m = [(dx, dy, dx * dx + dy * dy) for dx, dy in rows]
        return (
            m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
        )

    bad = 0
    for edge, sides in opposite.items():
        if len(sides) == 2 and edge not in constrained:
            (_, t), (d, _) = sides
            bad += incircle(p[t[0]], p[t[1]], p[t[2]], p[d]) > 0
    return bad


def star(seed: int, n: int) -> Domain:
    """A star-shaped polygon, radii in [100, 1000] (small input angles likely; star(5, 14) needs 3 Steiner
    points)."""
    rng = np.random.default_rng(seed)
    a = 2 * np.pi / n * (np.arange(n) + rng.uniform(0, 0.5, n))
    rad = rng.uniform(100, 1000, n)
    segments = [(i, (i + 1) % n) for i in range(n)]
    return Domain(points=np.c_[rad * np.cos(a), rad * np.sin(a)], segments=segments)
