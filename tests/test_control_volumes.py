"""nonobtuse.control_volumes: the control-volume matrix, Voronoi areas, exact coefficient signs."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from nonobtuse import Domain, InvalidInputError, Mesh, control_volumes, triangulate
from nonobtuse.certificate import ANGLES, KINDS, classify_edges
from nonobtuse.demo import CONDUCTIVITY, CURVES, cross_section
from nonobtuse.io import load_domain
from point_sets import point_set_mesh

SHARED = Path(__file__).resolve().parents[1] / ".." / "shared" / "data"
CORPUS_SUFFIXES = {".poly", ".node", ".json"}
# open boundaries (an outer one that does not close, constraints enclosing nothing): Triangle -c
CLOSED_BY_HULL = {"box.poly", "cdt_Constrained_Sweden.poly", "cdt_points_on_constraint_edge.poly"}
INVALID = {"cdt_cdt.poly"}  # zero-length segments
OBTUSE = ANGLES.index("obtuse")


def one_triangle(points) -> Mesh:
    points = np.asarray(points, dtype=float)
    return Mesh(points=points, triangles=np.array([[0, 1, 2]]), segments=np.array([[0, 1], [1, 2], [0, 2]]),
                input_points=points, input_segments=np.zeros((0, 2), np.int64))


def polygon_area(points: np.ndarray) -> float:
    x, y = points[:, 0], points[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def test_unit_right_triangle_by_hand():
    # (0,0), (1,0), (0,1): cot at (0,0) = cot 90 = 0, at (1,0) and (0,1) = cot 45 = 1. T_e = cot(opposite)/2:
    # edge (0,1) faces (0,1): 1/2; edge (0,2) faces (1,0): 1/2; edge (1,2) faces (0,0): 0.
    cv = control_volumes(one_triangle([(0, 0), (1, 0), (0, 1)]))
    expected = np.array([[1.0, -0.5, -0.5], [-0.5, 0.5, 0.0], [-0.5, 0.0, 0.5]])
    np.testing.assert_allclose(cv.matrix.toarray(), expected, atol=1e-15)
    np.testing.assert_array_equal(cv.edges, [[0, 1], [0, 2], [1, 2]])
    np.testing.assert_array_equal(cv.signs, [1, 1, 0])  # the right angle gives an exact zero
    assert cv.m_matrix
    # Circumcenter = midpoint of the hypotenuse (1/2, 1/2): the right corner gets the square [0, 1/2]^2 = 1/4,
    # each other corner the triangle (corner, (1/2,1/2), mid of its leg) = 1/8.
    np.testing.assert_allclose(cv.areas, [0.25, 0.125, 0.125])


def test_obtuse_triangle_by_hand():
    # (0,0), (4,0), (2,1): cot at (2,1) = dot/cross = -3/4; at (0,0): u=(4,0), v=(2,1), 8/4 = 2; at (4,0) 2.
    cv = control_volumes(one_triangle([(0, 0), (4, 0), (2, 1)]))
    np.testing.assert_allclose(cv.coefficients, [-3 / 8, 1.0, 1.0])
    np.testing.assert_array_equal(cv.wrong_sign, [0])
    assert not cv.m_matrix
    # Clipped areas: (0,0) gets |ac|^2 tan A / 8 = 5 * (1/2) / 8 = 5/16, same for (4,0); (2,1) the rest of 2.
    np.testing.assert_allclose(cv.areas, [5 / 16, 5 / 16, 2 - 10 / 16])


def kite() -> Mesh:
    # Interface (0,0)-(4,0) between region 1 above (apex (2,1), cot -3/4) and region 2 below (apex (2,-4),
    # cot +3/4: u=(2,4), v=(-2,4), dot 12, cross 16). T = (k1 (-3/4) + k2 (3/4)) / 2.
    return triangulate(Domain(points=[(0, 0), (2, -4), (4, 0), (2, 1)],
                              segments=[(0, 1), (1, 2), (2, 3), (3, 0), (0, 2)],
                              regions=[(2, 0.5, 1.0), (2, -1, 2.0)]))


def kite_with_interface(conductivity):
    cv = control_volumes(kite(), conductivity)
    return cv, int(np.flatnonzero((cv.edges == [0, 2]).all(axis=1))[0])


@pytest.mark.parametrize(("k", "sign", "value"), [
    ({1.0: 1.0, 2.0: 1.0}, 0, 0.0),  # -3/4 + 3/4: cocircular, exactly zero
    ({1.0: 1.0, 2.0: 2.0}, 1, 0.375),  # (-3/4 + 3/2) / 2
    ({1.0: 2.0, 2.0: 1.0}, -1, -0.375),  # (-3/2 + 3/4) / 2
])
def test_interface_coefficient_is_weighted_per_side(k, sign, value):
    cv, e = kite_with_interface(k)
    assert cv.signs[e] == sign
    assert cv.coefficients[e] == pytest.approx(value, abs=1e-15)
    assert cv.m_matrix == (sign >= 0)  # every other edge faces an acute angle


def test_conductivity_per_triangle_and_errors():
    mesh = kite()
    by_region = control_volumes(mesh, {1.0: 3.0, 2.0: 5.0})
    per_triangle = control_volumes(mesh, np.where(mesh.regions == 1.0, 3.0, 5.0))
    np.testing.assert_array_equal(by_region.coefficients, per_triangle.coefficients)
    with pytest.raises(InvalidInputError, match="region"):
        control_volumes(mesh, {1.0: 3.0})
    with pytest.raises(InvalidInputError, match="finite and > 0"):
        control_volumes(mesh, np.array([1.0, 0.0]))
    with pytest.raises(InvalidInputError, match="one value per triangle"):
        control_volumes(mesh, np.ones(3))


def assert_consistent(mesh: Mesh, domain_area: float, conductivity=None) -> None:
    """Rows sum to zero, symmetry, positive areas summing to the domain area, exact signs agree with the
    checker: a boundary coefficient is negative exactly when its angle is obtuse; an interface coefficient can
    be negative only when one of its sides is obtuse; with a CDT, interior coefficients are >= 0."""
    cv = control_volumes(mesh, conductivity)
    scale = abs(cv.matrix).max()
    assert abs(cv.matrix.sum(axis=1)).max() <= 1e-12 * scale
    assert abs(cv.matrix - cv.matrix.T).max() == 0
    used = np.unique(mesh.triangles)
    assert (cv.areas[used] > 0).all()
    assert cv.areas.sum() == pytest.approx(domain_area, rel=1e-10)
    edges = classify_edges(mesh)
    np.testing.assert_array_equal(edges["edges"], cv.edges)
    obtuse = (edges["triangle"] >= 0) & (edges["angle"] == OBTUSE)
    boundary = edges["kind"] == KINDS.index("boundary")
    np.testing.assert_array_equal(cv.signs[boundary] < 0, obtuse[boundary].any(axis=1))
    interface = edges["kind"] == KINDS.index("interface")
    assert not (interface & (cv.signs < 0) & ~obtuse.any(axis=1)).any()
    assert (cv.signs[edges["kind"] == KINDS.index("interior")] >= 0).all()


def test_demo_cross_section_is_consistent():
    domain = cross_section()
    # Bounded by the base y = 0, two vertical sides and the topography (the last curve): its area is the
    # integral of the topography polyline, a sum of trapezoids.
    top = domain.points[-CURVES[-1][4]:]
    area = float(np.sum(np.diff(top[:, 0]) * (top[1:, 1] + top[:-1, 1]) / 2))
    assert_consistent(triangulate(domain), area, CONDUCTIVITY)


@settings(derandomize=True, deadline=None, max_examples=30)
@given(st.lists(st.tuples(st.integers(0, 50), st.integers(0, 50)), min_size=4, max_size=40, unique=True))
def test_random_point_sets_are_consistent(coords):
    mesh = point_set_mesh(coords)
    assume(mesh is not None)
    hull = mesh.points[np.unique(mesh.segments)]
    centre = hull.mean(axis=0)
    ordered = hull[np.argsort(np.arctan2(hull[:, 1] - centre[1], hull[:, 0] - centre[0]))]
    assert_consistent(mesh, polygon_area(ordered))


def corpus() -> list[Path]:
    files = (p for d in ("2d", "cgshop25") for p in sorted((SHARED / d).glob("*")))
    return [p for p in files if p.suffix in CORPUS_SUFFIXES]


@pytest.mark.parametrize("path", corpus() or [None], ids=lambda p: p.name if p else "absent")
def test_corpus_signs_agree_with_the_checker(path):
    if path is None:
        pytest.skip("../shared/data not present")
    if path.name in INVALID:
        pytest.skip(f"{path.name} is invalid input (see test_io2d)")
    mesh = triangulate(load_domain(path, convex_hull=True if path.name in CLOSED_BY_HULL else None))
    # The reference area: the triangles' own areas (that they cover the domain is triangulate's guarantee).
    u, v = (mesh.points[mesh.triangles[:, k]] - mesh.points[mesh.triangles[:, 0]] for k in (1, 2))
    area = float(np.sum(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]) / 2)
    attributes = np.unique(mesh.regions)
    assert_consistent(mesh, area)
    # One conductivity per region (1, 2, 3, ... in attribute order): interior edges keep one region.
    assert_consistent(mesh, area, {a: float(i + 1) for i, a in enumerate(attributes.tolist())})
