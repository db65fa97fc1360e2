"""nonobtuse.triangulate: the constrained Delaunay triangulation of a validated domain."""

from __future__ import annotations

import numpy as np
import pytest

from nonobtuse import Domain, InvalidInputError, triangulate


def twice_signed_areas(points: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    a, b, c = (points[triangles[:, k]] for k in range(3))
    return (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])


def test_square_with_hole_keeps_the_ring_and_the_input():
    points = [(0, 0), (4, 0), (4, 4), (0, 4), (1, 1), (3, 1), (3, 3), (1, 3)]
    segments = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4)]
    mesh = triangulate(Domain(points=points, segments=segments, holes=[(2, 2)]))
    # A ring between two squares, 8 vertices and no Steiner point: 8 triangles (n + 2 * holes - 2 = 8).
    assert len(mesh.triangles) == 8
    assert mesh.steiner_points == 0
    np.testing.assert_array_equal(mesh.points, np.asarray(points, dtype=float))
    np.testing.assert_array_equal(mesh.input_segments, segments)
    assert (twice_signed_areas(mesh.points, mesh.triangles) > 0).all()
    # Area of the ring: 16 - 4 = 12.
    assert twice_signed_areas(mesh.points, mesh.triangles).sum() / 2 == 12.0
    assert len(mesh.segments) == 8


def test_regions_are_carried_per_triangle():
    # Two unit squares side by side, split by the interface x = 1: two triangles each.
    points = [(0, 0), (1, 0), (2, 0), (2, 1), (1, 1), (0, 1)]
    segments = [(0, 1), (1, 2), (2, 3), (3, 4), (4, 5), (5, 0), (1, 4)]
    mesh = triangulate(Domain(points=points, segments=segments, regions=[(0.5, 0.5, 7.0), (1.5, 0.5, 9.0)]))
    assert sorted(mesh.regions.tolist()) == [7.0, 7.0, 9.0, 9.0]
    centroid_x = mesh.points[mesh.triangles].mean(axis=1)[:, 0]
    assert ((centroid_x < 1) == (mesh.regions == 7.0)).all()


def test_point_set_uses_the_convex_hull():
    # 4 hull corners and 1 interior point: 2n - h - 2 = 10 - 4 - 2 = 4 triangles.
    mesh = triangulate(Domain(points=[(0, 0), (2, 0), (2, 2), (0, 2), (1, 0.5)], convex_hull=True))
    assert len(mesh.triangles) == 4
    assert len(mesh.segments) == 4


def test_crossing_segments_are_invalid_input():
    domain = Domain(points=[(0, 0), (1, 1), (0, 1), (1, 0)], segments=[(0, 1), (2, 3)], convex_hull=True)
    with pytest.raises(InvalidInputError):
        triangulate(domain)


def test_the_domain_is_validated_and_repaired_first():
    # (1, 0) lies inside the segment (0,0)-(2,0): validation splits it there, so the mesh has 4 subsegments.
    domain = Domain(points=[(0, 0), (2, 0), (2, 2), (1, 0)], segments=[(0, 1), (1, 2), (2, 0)])
    mesh = triangulate(domain)
    assert len(mesh.input_segments) == 4
    assert len(mesh.stats["repairs"]) == 1
    assert sorted(map(tuple, mesh.segments.tolist())) == [(0, 2), (0, 3), (1, 2), (1, 3)]
    # An open chain encloses nothing.
    with pytest.raises(InvalidInputError):
        triangulate(Domain(points=[(0, 0), (2, 0), (2, 2)], segments=[(0, 1), (1, 2)]))
