"""nonobtuse.check: the exact nonobtuse-boundary certificate."""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from nonobtuse import Domain, InvalidInputError, Mesh, check
from nonobtuse.certificate import ANGLES, KINDS, classify_edges
from point_sets import point_set_mesh


def closed_polygon(points, extra_segments=(), **kwargs) -> Domain:
    n = len(points)
    loop = [(i, (i + 1) % n) for i in range(n)]
    return Domain(points=points, segments=loop + list(extra_segments), **kwargs)


def mesh_of(points, triangles, segments=()) -> Mesh:
    points = np.asarray(points, dtype=float)
    segments = np.asarray(segments, dtype=np.int64).reshape(-1, 2)
    return Mesh(points=points, triangles=np.asarray(triangles, dtype=np.int64), segments=segments,
                input_points=points, input_segments=segments)


def test_exact_right_angle_is_right_not_obtuse():
    # At (1,1) the edge (0,0)-(2,0) is seen under vectors (-1,-1), (1,-1): dot = 0, exactly 90 degrees.
    report = check(closed_polygon([(0, 0), (2, 0), (1, 1)]))
    assert report.ok
    assert report.angles["boundary"] == {"acute": 2, "right": 1, "obtuse": 0}
    assert report.largest_obtuse is None


def test_obtuse_boundary_triangle_is_found():
    # At (2,1) the edge (0,0)-(4,0) is seen under (-2,-1), (2,-1): dot -3, |cross| 4, angle atan2(4, -3).
    report = check(closed_polygon([(0, 0), (4, 0), (2, 1)]))
    assert not report.ok
    (worst,) = report.offenders
    assert (worst.edge, worst.apex, worst.kind) == ((0, 1), 2, "boundary")
    assert worst.points == ((0.0, 0.0), (4.0, 0.0), (2.0, 1.0))
    assert worst.degrees == pytest.approx(np.degrees(np.arctan2(4, -3)))  # 126.87
    assert "NOT OK" in report.summary()
    assert json.loads(json.dumps(report.to_dict()))["largest_obtuse_degrees"] == pytest.approx(126.8698976)


def test_square_with_its_center_passes():
    # Each side faces the center at exactly 90 degrees; each diagonal half faces two 45-degree corners.
    report = check(Domain(points=[(0, 0), (2, 0), (2, 2), (0, 2), (1, 1)],
                          segments=[(0, 1), (1, 2), (2, 3), (3, 0)]))
    assert report.ok
    assert report.edges == {"boundary": 4, "interface": 0, "interior": 4}
    assert report.angles["boundary"] == {"acute": 0, "right": 4, "obtuse": 0}
    assert report.angles["interior"] == {"acute": 8, "right": 0, "obtuse": 0}
    assert report.not_locally_delaunay == []


@pytest.mark.parametrize("obtuse_above", [True, False])
def test_interface_edges_check_both_sides(obtuse_above):
    # Interface (0,0)-(4,0); the apex at distance 1 sees it at 126.87 degrees (dot -3), the one at distance 4
    # at 53.13 (dot 12). Whichever side is obtuse, the interface is reported.
    near, far = ((2, 1), (2, -4)) if obtuse_above else ((2, -1), (2, 4))
    domain = Domain(points=[(0, 0), near, (4, 0), far], segments=[(0, 1), (1, 2), (2, 3), (3, 0), (0, 2)])
    report = check(domain)
    assert report.edges["interface"] == 1
    assert report.angles["interface"] == {"acute": 1, "right": 0, "obtuse": 1}
    (o,) = report.offenders
    assert (o.edge, o.apex, o.kind) == ((0, 2), 1, "interface")


def test_a_mesh_is_checked_as_given_and_local_delaunay_is_exact():
    # Rhombus (0,0), (4,0), (2,1), (2,-1) cut along the long diagonal (0,1): both angles opposite it are
    # 126.87 degrees, so it is not locally Delaunay; the sides face acute angles (at (0,0): 26.57 degrees).
    mesh = mesh_of([(0, 0), (4, 0), (2, 1), (2, -1)], [(0, 1, 2), (1, 0, 3)])
    report = check(mesh)
    assert report.ok
    assert report.not_locally_delaunay == [(0, 1)]
    assert report.angles["interior"]["obtuse"] == 2
    # Constrained, the edge is an interface (a constrained Delaunay triangulation may keep it): not listed.
    constrained = check(mesh_of(mesh.points, mesh.triangles, [(0, 1)]))
    assert constrained.not_locally_delaunay == []
    assert len(constrained.offenders) == 2


def test_malformed_mesh_is_invalid_input():
    with pytest.raises(InvalidInputError, match="clockwise"):
        check(mesh_of([(0, 0), (1, 0), (0, 1)], [(0, 2, 1)]))


def float_classes(mesh: Mesh, edges: dict) -> tuple[np.ndarray, np.ndarray]:
    """Per edge side: the float cosine dot / (|u| |v|) of the angle opposite, and whether the side exists."""
    present = edges["triangle"] >= 0
    margin = np.zeros(present.shape)
    for side in (0, 1):
        apex = np.where(present[:, side], edges["apex"][:, side], 0)
        u = mesh.points[edges["edges"][:, 0]] - mesh.points[apex]
        v = mesh.points[edges["edges"][:, 1]] - mesh.points[apex]
        norms = np.linalg.norm(u, axis=1) * np.linalg.norm(v, axis=1)
        np.divide(np.einsum("ij,ij->i", u, v), norms, out=margin[:, side], where=present[:, side])
    return margin, present


# Floats with up to 6 decimals: no subnormal differences that would underflow the float reference.
COORDINATE = st.floats(-1e3, 1e3).map(lambda x: round(x, 6))


@settings(derandomize=True, deadline=None, max_examples=40)
@given(st.lists(st.tuples(COORDINATE, COORDINATE), min_size=3, max_size=40, unique=True))
def test_exact_classes_agree_with_floats_where_the_margin_is_large(coords):
    mesh = point_set_mesh(coords)
    assume(mesh is not None)
    edges = classify_edges(mesh)
    margin, present = float_classes(mesh, edges)
    clear = present & (np.abs(margin) > 1e-9)
    expected = np.where(margin > 0, ANGLES.index("acute"), ANGLES.index("obtuse"))
    np.testing.assert_array_equal(edges["angle"][clear], expected[clear])


@settings(derandomize=True, deadline=None, max_examples=40)
@given(st.lists(st.tuples(st.integers(0, 6), st.integers(0, 6)), min_size=3, max_size=30, unique=True))
def test_on_a_small_grid_right_angles_are_found_exactly(coords):
    # Small integer coordinates: the float dot product is exact, so its sign is the exact class, RIGHT too.
    mesh = point_set_mesh(coords)
    assume(mesh is not None)
    edges = classify_edges(mesh)
    margin, present = float_classes(mesh, edges)
    expected = np.select([margin > 0, margin == 0], [0, 1], 2)
    np.testing.assert_array_equal(edges["angle"][present], expected[present])
    report = check(mesh)
    boundary_obtuse = (edges["kind"] == KINDS.index("boundary"))[:, None] & present & (expected == 2)
    assert len(report.offenders) == int(boundary_obtuse.sum())
