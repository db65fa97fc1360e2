"""Shared by the refinement tests: CG:SHOP instances as domains, and an exact check of a mesh in rationals."""

from __future__ import annotations

import json
from fractions import Fraction
from pathlib import Path

import numpy as np

from nonobtuse import Domain

SHARED = Path(__file__).resolve().parents[1] / ".." / "shared" / "data"


def cgshop_domain(path: Path) -> Domain:
    """A CG:SHOP 2025 instance: the region_boundary polygon (closed), additional constraints, interior points."""
    d = json.loads(path.read_text())
    pts = np.c_[d["points_x"], d["points_y"]].astype(np.float64)
    rb = d["region_boundary"]
    seg = [(rb[i], rb[(i + 1) % len(rb)]) for i in range(len(rb))] + [
        tuple(c) for c in d["additional_constraints"]
    ]
    return Domain(points=pts, segments=np.array(seg, dtype=np.int64), source=str(path))


def obtuse_boundary_sides(mesh) -> int:
    """Boundary segments (exactly one incident triangle) whose triangle is obtuse at the apex, decided in exact
    rational arithmetic on the stored doubles, independently of the C++ certificate."""
    apex: dict[tuple[int, int], list[int]] = {tuple(sorted(map(int, s))): [] for s in mesh.segments}
    for t in np.asarray(mesh.triangles):
        for i in range(3):
            k = tuple(sorted((int(t[(i + 1) % 3]), int(t[(i + 2) % 3]))))
            if k in apex:
                apex[k].append(int(t[i]))
    p = [(Fraction(x), Fraction(y)) for x, y in np.asarray(mesh.points)]
    bad = 0
    for (a, b), c in apex.items():
        if len(c) == 1:
            (ax, ay), (bx, by), (cx, cy) = p[a], p[b], p[c[0]]
            bad += (ax - cx) * (bx - cx) + (ay - cy) * (by - cy) < 0
    return bad
