"""The selection-disk rule of refine(min_angle=) by hand: when the new vertex of the skinniest triangle lies
in a subsegment's closed diametral disk, the point of Chernikov and Chrisochoides' selection disk (centered at
the circumcenter c, radius R - l / (2 sin bound)) farthest from that subsegment, c + radius (c - m) / |c - m|
for its midpoint m, goes in instead when it lies in no such disk; otherwise the subsegment is split at its
midpoint.

The domain is a 4 x 2 rectangle with boundary vertices one apart (subsegment disks of radius 1/2) and one or
two interior points: its constrained Delaunay triangulation has no obtuse boundary side, so the first boundary
pass adds nothing and the first decision is the skinniest triangle's. Every expected point is computed here
from the input triangulation."""

from __future__ import annotations

import numpy as np

import nonobtuse
from nonobtuse import Domain

BOUND = 25.0
FRAME = np.array([(x, 0) for x in range(5)] + [(4, 1)] + [(x, 2) for x in range(4, -1, -1)] + [(0, 1)], float)
SEGMENTS = [[i, (i + 1) % len(FRAME)] for i in range(len(FRAME))]


def frame_with(inner: list[list[float]]) -> Domain:
    return Domain(points=np.r_[FRAME, inner], segments=SEGMENTS)


def circumcenter(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]))
    return np.array([(a @ a) * (b[1] - c[1]) + (b @ b) * (c[1] - a[1]) + (c @ c) * (a[1] - b[1]),
                     (a @ a) * (c[0] - b[0]) + (b @ b) * (a[0] - c[0]) + (c @ c) * (b[0] - a[0])]) / d


def smallest_angle(p: np.ndarray) -> float:
    """The smallest angle (degrees) of the triangle p (3, 2)."""
    out = 180.0
    for i in range(3):
        u, w = p[(i + 1) % 3] - p[i], p[(i + 2) % 3] - p[i]
        out = min(out, np.degrees(np.arctan2(abs(u[0] * w[1] - u[1] * w[0]), u @ w)))
    return out


def in_closed_disk(x: np.ndarray, segment: list[int]) -> bool:
    s, e = FRAME[segment[0]], FRAME[segment[1]]
    return bool(np.linalg.norm(x - (s + e) / 2) <= np.linalg.norm(e - s) / 2)


def selection_disk_point(d: Domain) -> tuple[np.ndarray, list[int], np.ndarray]:
    """The skinniest triangle's circumcenter c, the one subsegment whose closed disk holds c, and the
    selection-disk point farthest from it."""
    tri = nonobtuse.triangulate(d).triangles
    p = d.points[min(tri, key=lambda t: smallest_angle(d.points[t]))]
    assert smallest_angle(p) < BOUND
    c = circumcenter(*p)
    shortest = min(np.linalg.norm(p[i] - p[(i + 1) % 3]) for i in range(3))
    radius = np.linalg.norm(c - p[0]) - shortest / (2 * np.sin(np.radians(BOUND)))
    assert radius > 0
    encroached = [s for s in SEGMENTS if in_closed_disk(c, s)]
    assert len(encroached) == 1
    m = FRAME[encroached[0]].mean(axis=0)
    return c, encroached[0], c + radius * (c - m) / np.linalg.norm(c - m)


def test_the_selection_disk_point_goes_in_when_it_encroaches_nothing() -> None:
    # The skinniest triangle (4, 0), (4, 1), (3.61, 1.15): 18.7 degrees, c = (3.584, 0.5) in the disk of
    # the subsegment x = 4 (0.42 from its midpoint); radius 0.156, so the point (3.428, 0.5) is 0.57 away:
    # outside.
    d = frame_with([[3.61, 1.15], [2.9, 0.8]])
    c, segment, point = selection_disk_point(d)
    assert not any(in_closed_disk(point, s) for s in SEGMENTS)
    r = nonobtuse.refine(d, min_angle=BOUND, max_interior=1)
    assert r.stats["steiner_points"] == 0 and r.stats["interior_points"] == 1
    added = r.mesh.points[len(d.points):]
    np.testing.assert_allclose(added[0], point, rtol=0, atol=1e-12)
    assert np.linalg.norm(added[0] - c) > 0.1  # not the circumcenter


def test_a_selection_disk_point_in_a_disk_is_refused_and_the_subsegment_split() -> None:
    # The skinniest triangle (1, 2), (0, 2), (1.07, 1.71): 15.2 degrees, c = (0.5, 1.726) in the disk of the
    # top subsegment (0, 2)-(1, 2); radius 0.217 moves it to (0.5, 1.509), still 0.49 < 0.5 from (0.5, 2):
    # refused, and that subsegment is split at its midpoint instead.
    d = frame_with([[1.07, 1.71]])
    assert nonobtuse.refine(d).stats["steiner_points"] == 0  # no obtuse boundary side to begin with
    c, segment, point = selection_disk_point(d)
    assert in_closed_disk(point, segment)
    r = nonobtuse.refine(d, min_angle=BOUND, max_steiner=1)
    assert r.stats["steiner_points"] == 1 and r.stats["interior_points"] == 0
    np.testing.assert_allclose(r.mesh.points[len(d.points)], FRAME[segment].mean(axis=0), rtol=0, atol=0)
