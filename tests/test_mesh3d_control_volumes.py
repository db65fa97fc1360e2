"""Voronoi control volumes of tet meshes, against values worked out by hand."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from mesh3d_shapes import CUBE_POINTS
from nonobtuse import _core
from nonobtuse.mesh3d import TetMesh, control_volumes3d
from nonobtuse.mesh3d.control_volumes3d import (
    dual_area_pieces,
    exact_circumspheres,
    signed_tet_volumes,
    tet_circumcenters,
    tet_voronoi_shares,
    triangle_circumcenters,
)
from nonobtuse.mesh3d.gabriel import negative_couplings

NO_FACES = np.zeros((0, 3), dtype=np.int64)


def tetmesh(points, tets) -> TetMesh:
    return TetMesh(np.asarray(points, dtype=float), np.asarray(tets), NO_FACES, np.zeros(0, dtype=np.int64))


def test_regular_tet():
    # corners (1,1,1), (1,-1,-1), (-1,-1,1), (-1,1,-1): edge 2*sqrt(2), circumcenter 0, volume 8/3
    # (det[(0,-2,-2), (-2,-2,0), (-2,0,-2)] = +16 > 0). For edge (0, 1) the piece is the kite with corners
    # M = (1,0,0), the two face circumcenters (= centroids) (1/3, 1/3, -1/3), (1/3, -1/3, 1/3), and 0: twice
    # the triangle (0, M, (1/3,1/3,-1/3)) of area |(0, 1/3, 1/3)| / 2 = sqrt(2)/6, so sqrt(2)/3, and the
    # coupling (sqrt(2)/3) / (2 sqrt(2)) = 1/6. By symmetry every vertex gets a quarter of the volume: 2/3.
    p = [[1, 1, 1], [1, -1, -1], [-1, -1, 1], [-1, 1, -1]]
    cv = control_volumes3d(tetmesh(p, [[0, 1, 2, 3]]))
    assert len(cv.edges) == 6
    np.testing.assert_allclose(cv.dual_areas, np.sqrt(2) / 3, rtol=1e-14)
    np.testing.assert_allclose(cv.couplings, 1 / 6, rtol=1e-14)
    np.testing.assert_allclose(cv.volumes, 2 / 3, rtol=1e-14)
    assert cv.negative_couplings == 0


def test_obtuse_tet_has_a_negative_coupling():
    # a flat-ish tet: apex (0.5, 0.5, 0.05) over the right triangle (0,0,0), (1,0,0), (0,1,0) sits nearly on
    # the hypotenuse's side, so the circumcenter (x, y, z) is far below the base: solving |c-p|^2 equal for
    # all four gives x = y = 0.5, z = (0.05^2 - 0.5) / (2 * 0.05) = -4.975 < 0: outside the tet, beyond the
    # base face. The base edges' pieces then point the wrong way; the volume still sums to 1/6 * 0.05 = 1/120.
    p = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.5, 0.5, 0.05]]
    cv = control_volumes3d(tetmesh(p, [[0, 1, 2, 3]]))
    assert tet_circumcenters(*[np.array([q], dtype=float) for q in p])[0] == pytest.approx([0.5, 0.5, -4.975])
    assert cv.negative_couplings > 0
    assert negative_couplings(tetmesh(p, [[0, 1, 2, 3]])) == cv.negative_couplings
    assert cv.volumes.sum() == pytest.approx(1 / 120, rel=1e-12)


def test_triangle_circumcenter_of_a_right_triangle_is_the_hypotenuse_midpoint():
    a, b, c = (np.array([v], dtype=float) for v in ([0, 0, 0], [2, 0, 0], [0, 2, 2]))
    # angle at a: (b-a).(c-a) = 0, right angle: circumcenter = midpoint of bc = (1, 1, 1)
    np.testing.assert_allclose(triangle_circumcenters(a, b, c)[0], [1, 1, 1], atol=1e-15)


# A unit cube (vertex i = (i&1, (i>>1)&1, (i>>2)&1)) split into 6 tets around the diagonal 0-7 (Kuhn), or into
# 5 tets (the regular tet 1, 2, 4, 7 and four corner tets); orientations made positive by hand (checked
# below).
KUHN = [[0, 1, 3, 7], [0, 3, 2, 7], [0, 2, 6, 7], [0, 6, 4, 7], [0, 4, 5, 7], [0, 5, 1, 7]]
FIVE = [[1, 2, 4, 7], [0, 1, 2, 4], [3, 2, 1, 7], [5, 1, 4, 7], [6, 4, 2, 7]]


@pytest.mark.parametrize("tets", [KUHN, FIVE], ids=["six", "five"])
def test_cube_split_into_tets(tets):
    # All 8 corners lie on one sphere centred at (1/2, 1/2, 1/2), the circumcenter of every tet, so the
    # clipped Voronoi cell of each corner is its octant: volume 1/8. The Voronoi face of a cube edge (length
    # 1) inside the cube is a quarter of the bisector square: 1/2 x 1/2 = 1/4, coupling 1/4. Face and space
    # diagonals join corners whose octants meet in an edge or a point only: dual area 0.
    mesh = tetmesh(CUBE_POINTS, tets)
    assert (signed_tet_volumes(CUBE_POINTS, np.array(tets)) > 0).all()
    cv = control_volumes3d(mesh)
    np.testing.assert_allclose(cv.volumes, 1 / 8, rtol=1e-13)
    axis = cv.lengths == 1.0
    assert axis.sum() == 12
    np.testing.assert_allclose(cv.couplings[axis], 1 / 4, rtol=1e-13)
    # Exact signs: the diagonals' areas are exactly zero, not rounding noise of either sign.
    assert (cv.signs[~axis] == 0).all() and (cv.dual_areas[~axis] == 0.0).all()
    assert (cv.signs[axis] == 1).all() and cv.negative_couplings == 0
    assert cv.to_dict()["zero_couplings"] == len(cv.edges) - 12  # the diagonals (6 faces, +1 long in six)


def test_volumes_sum_to_the_mesh_volume_on_a_delaunay_mesh():
    pytest.importorskip("tetgen")
    from mesh3d_shapes import CUBE_TRIANGLES
    from nonobtuse.mesh3d import PLC, tetrahedralize

    plc = PLC(CUBE_POINTS * [3.0, 2.0, 1.0], CUBE_TRIANGLES, np.arange(12))  # a 3 x 2 x 1 box
    mesh = tetrahedralize(plc, "tetgen", switches="pq1.2a0.05AQ")
    cv = control_volumes3d(mesh)
    assert cv.volumes.sum() == pytest.approx(6.0, rel=1e-12)
    assert len(mesh.tets) > 100  # volume 6 in tets of at most 0.05


def delaunay_control_volumes(coords):
    """Points, Delaunay tets and control volumes of integer coordinates (hypothesis: assume some tet)."""
    points = np.array(coords, dtype=float)
    tets = np.asarray(_core.delaunay_tetrahedra(points))
    assume(len(tets) > 0)
    return points, tets, control_volumes3d(tetmesh(points, tets))


@settings(derandomize=True, deadline=None, max_examples=30)
@given(st.lists(st.tuples(*[st.integers(-50, 50)] * 3), min_size=5, max_size=40, unique=True))
def test_cell_volumes_sum_to_the_hull_volume(coords):
    # On the Delaunay tetrahedralization of any point set (integer coordinates, so volumes are exact in
    # floating point up to rounding of the circumcenters), the pyramids over the dual pieces tile each tet:
    # the cell volumes sum to the volume of the convex hull, whatever the signs of the pieces.
    points, tets, cv = delaunay_control_volumes(coords)
    total = signed_tet_volumes(points, tets).sum()
    assert cv.volumes.sum() == pytest.approx(total, rel=1e-9)


@settings(derandomize=True, deadline=None, max_examples=30)
@given(st.lists(st.tuples(*[st.integers(-5, 5)] * 3), min_size=5, max_size=40, unique=True))
def test_exact_signs_agree_with_clear_float_values(coords):
    # Small integer grids are full of cospherical points: many dual areas are exactly 0. Where the float
    # value is far from 0 the exact sign must be its sign; an exactly zero area is 0.0.
    points, tets, cv = delaunay_control_volumes(coords)
    _, pieces = dual_area_pieces(points, tets)
    scale = np.abs(pieces).max()
    clear = np.abs(cv.dual_areas) > 1e-9 * scale
    assert (np.sign(cv.dual_areas[clear]) == cv.signs[clear]).all()
    assert (cv.dual_areas[cv.signs == 0] == 0.0).all()
    assert cv.negative_couplings == int((cv.signs < 0).sum())
    assert negative_couplings(tetmesh(points, tets)) == cv.negative_couplings  # (zeros are not negative)


def test_on_a_grid_only_the_axis_edges_have_dual_areas():
    # The Voronoi cells of a cubic grid are unit cubes: the dual face of an axis edge is a unit square (a part
    # of one on the hull), that of a diagonal (length sqrt 2 or sqrt 3) is a point, and its area exactly 0.
    # 40,014 tets: the core's interval filter works in blocks of 32,768 tets, so both blocks are checked.
    g = np.stack(np.meshgrid(np.arange(40), np.arange(20), np.arange(10), indexing="ij"), -1)
    points = g.reshape(-1, 3).astype(float)
    tets = np.asarray(_core.delaunay_tetrahedra(points))
    assert len(tets) > 2**15
    cv = control_volumes3d(tetmesh(points, tets))
    length2 = ((points[cv.edges[:, 1]] - points[cv.edges[:, 0]]) ** 2).sum(axis=1)
    np.testing.assert_array_equal(cv.signs, (length2 == 1).astype(cv.signs.dtype))
    assert cv.exact_evaluations >= int((length2 > 1).sum())


def test_tets_flat_in_floating_point_get_exact_circumcenters_in_the_core_and_numpy():
    # The points of a UV sphere 30 x 40 (poles and 29 rings of 40): their Delaunay tetrahedralization has tets
    # of positive exact volume whose triple product is 0 in doubles (cocircular ring points). Their
    # circumcenters are computed exactly, the same in C++ and numpy: every piece finite, the floats equal.
    t = np.pi * np.arange(1, 30) / 30
    f = 2 * np.pi * np.arange(40) / 40
    rings = np.stack([np.outer(np.sin(t), np.cos(f)), np.outer(np.sin(t), np.sin(f)),
                      np.repeat(np.cos(t)[:, None], 40, axis=1)], axis=2).reshape(-1, 3)
    points = np.vstack([[0.0, 0.0, 1.0], rings, [0.0, 0.0, -1.0]])
    tets = np.asarray(_core.delaunay_tetrahedra(points))
    cv = control_volumes3d(tetmesh(points, tets))
    assert cv.flat_in_floating_point > 0
    assert np.isfinite(cv.dual_areas).all() and np.isfinite(cv.volumes).all()
    shares = tet_voronoi_shares(points, tets)
    np.testing.assert_array_equal(cv.volumes, np.bincount(tets.ravel(), weights=shares.ravel(),
                                                          minlength=len(points)))
    assert cv.volumes.sum() == pytest.approx(signed_tet_volumes(points, tets).sum(), rel=1e-13)


@settings(derandomize=True, deadline=None, max_examples=20)
@given(st.integers(0, 2**32 - 1), st.integers(5, 400))
def test_core_magnitudes_are_the_numpy_formulas_bit_for_bit(seed, n):
    # control_volumes3d computes in C++ what dual_area_pieces and tet_voronoi_shares compute in numpy, summed
    # in the same (tet) order: the floats must be equal, not close, on random Delaunay meshes (which have
    # slivers near the hull, where rounding differences would show).
    points = np.random.default_rng(seed).uniform(-1, 1, (n, 3))
    tets = np.asarray(_core.delaunay_tetrahedra(points))
    cv = control_volumes3d(tetmesh(points, tets))
    pairs, pieces = dual_area_pieces(points, tets)
    edges, inv = np.unique(np.sort(pairs.reshape(-1, 2), axis=1), axis=0, return_inverse=True)
    np.testing.assert_array_equal(cv.edges, edges)
    summed = np.bincount(inv.ravel(), weights=pieces.ravel(), minlength=len(edges))
    np.testing.assert_array_equal(cv.dual_areas, cv.signs * np.abs(summed))
    lengths = np.linalg.norm(points[edges[:, 1]] - points[edges[:, 0]], axis=1)
    np.testing.assert_array_equal(cv.lengths, lengths)
    volumes = np.bincount(tets.ravel(), weights=tet_voronoi_shares(points, tets).ravel(), minlength=n)
    np.testing.assert_array_equal(cv.volumes, volumes)


@settings(derandomize=True, deadline=None, max_examples=20)
@given(st.integers(0, 2**32 - 1), st.integers(5, 400), st.integers(-40, 40))
def test_the_signs_alone_are_those_of_the_whole_pass(seed, n, exponent):
    # _core.dual_area_signs skips the floating-point magnitudes; negative_couplings scales the points by a
    # power of two first (exactly, so no sign moves). Random Delaunay meshes have obtuse tets at the hull.
    points = np.ldexp(np.random.default_rng(seed).uniform(-1, 1, (n, 3)), exponent)
    tets = np.asarray(_core.delaunay_tetrahedra(points))
    cv = control_volumes3d(tetmesh(points, tets))
    alone = _core.dual_area_signs(points, tets)
    np.testing.assert_array_equal(alone["edges"], cv.edges)
    np.testing.assert_array_equal(alone["sign"], cv.signs)
    assert alone["exact_evaluations"] == cv.exact_evaluations
    assert negative_couplings(tetmesh(points, tets)) == cv.negative_couplings


EDGE_FRAMES = [(0, 1, 2, 3), (0, 2, 3, 1), (0, 3, 1, 2), (1, 2, 0, 3), (1, 3, 2, 0), (2, 3, 0, 1)]


def exact_dual_area_signs(points: np.ndarray, tets: np.ndarray) -> dict[tuple[int, int], int]:
    """Per edge (a, b), a < b, the sign of its dual area from the definition in rationals: the sum over its
    tets of the area of (M, C(ijk), C_T, C(ijl)) along i -> j (the module docstring), no identity used."""
    q = [[Fraction(float(x)) for x in row] for row in points]

    def sub(x, y):
        return [x[0] - y[0], x[1] - y[1], x[2] - y[2]]

    def add(x, y):
        return [x[0] + y[0], x[1] + y[1], x[2] + y[2]]

    def times(s, x):
        return [s * x[0], s * x[1], s * x[2]]

    def cross(x, y):
        return [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]]

    def dot(x, y):
        return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]

    def triangle_center(a, b, c):
        u, v = sub(b, a), sub(c, a)
        w = cross(u, v)
        num = add(times(dot(u, u), cross(v, w)), times(dot(v, v), cross(w, u)))
        return add(a, times(1 / (2 * dot(w, w)), num))

    sums: dict[tuple[int, int], Fraction] = {}
    for t in tets.tolist():
        a = q[t[0]]
        u, v, w = sub(q[t[1]], a), sub(q[t[2]], a), sub(q[t[3]], a)
        num = add(times(dot(u, u), cross(v, w)), times(dot(v, v), cross(w, u)))
        num = add(num, times(dot(w, w), cross(u, v)))
        ct = add(a, times(1 / (2 * dot(u, cross(v, w))), num))
        for i, j, k, m in EDGE_FRAMES:
            pi, pj = q[t[i]], q[t[j]]
            mid = times(Fraction(1, 2), add(pi, pj))
            c1, c2 = triangle_center(pi, pj, q[t[k]]), triangle_center(pi, pj, q[t[m]])
            area = add(cross(sub(c1, mid), sub(ct, mid)), cross(sub(ct, mid), sub(c2, mid)))
            key = (min(t[i], t[j]), max(t[i], t[j]))
            sums[key] = sums.get(key, Fraction(0)) + dot(area, sub(pj, pi))  # the same for (j, i, m, k)
    return {e: (s > 0) - (s < 0) for e, s in sums.items()}


@settings(derandomize=True, deadline=None, max_examples=10)
@given(st.lists(st.tuples(*[st.integers(-2, 2)] * 3), min_size=12, max_size=24, unique=True))
def test_exact_signs_are_those_of_the_definition_in_rationals(coords):
    # Small integer grids: many dual areas are exactly 0, so the interval filter leaves them to the exact
    # stage (a few edges per example), interior edges (tets all around) and edges on the hull alike.
    points, tets, cv = delaunay_control_volumes(coords)
    want = exact_dual_area_signs(points, tets)
    assert {tuple(e): int(s) for e, s in zip(cv.edges.tolist(), cv.signs)} == want


def _rounded(x: Fraction) -> float:
    """The double nearest to x, inf beyond the range (Python's float(Fraction) raises there)."""
    try:
        return float(x)
    except OverflowError:
        return float("inf") if x > 0 else float("-inf")


@settings(derandomize=True, deadline=None, max_examples=100)
@given(st.lists(st.floats(-1, 1), min_size=9, max_size=9), st.floats(0, 1), st.floats(0, 1),
       st.one_of(st.integers(0, 320), st.integers(300, 340)), st.booleans(), st.integers(-30, 30),
       st.sampled_from([0.0, 0.0, 0.1, 1e3]))
def test_exact_circumspheres_round_the_rational_values_to_nearest(base, s, t, flat, level, scale, shift):
    # a base triangle scaled by 10^scale, the apex above a point of its plane by 10^-flat of that (coplanar
    # once rounded for many), or with `level` the base in the plane z = 0 and the apex at that height
    # (circumradii up to 1e340 of the scale: beyond the double range), then shifted: center, radius^2 and
    # volume must be the rationals' values rounded to nearest, inf beyond the range
    a, b, c = (np.array(base[i:i + 3]) * 10.0**scale for i in range(0, 9, 3))
    if level:
        a[2] = b[2] = c[2] = 0.0
    normal = np.cross(b - a, c - a)
    assume(np.linalg.norm(normal) > 1e-3 * 10.0 ** (2 * scale))
    foot = a + s * (b - a) + t * (c - a)
    up = np.array([0, 0, 1.0]) if level else normal / np.linalg.norm(normal)
    apex = (np.array([*foot[:2], 0.0]) if level else foot) + 10.0 ** (scale - flat) * up
    points = np.array([a, b, c, apex]) + shift
    centers, radius, volume = exact_circumspheres(points, np.array([[0, 1, 2, 3]]))
    q = [[Fraction(float(x)) for x in row] for row in points]
    u, v, w = ([q[k][i] - q[0][i] for i in range(3)] for k in (1, 2, 3))

    def cross(x, y):
        return [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]]

    def dot(x, y):
        return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]

    det = dot(u, cross(v, w))
    if det == 0:
        assert np.isinf(centers[0]).all() and radius[0] == np.inf and volume[0] == 0
        return
    vw, wu, uv = cross(v, w), cross(w, u), cross(u, v)
    offset = [(dot(u, u) * vw[i] + dot(v, v) * wu[i] + dot(w, w) * uv[i]) / (2 * det) for i in range(3)]
    assert centers[0].tolist() == [_rounded(q[0][i] + offset[i]) for i in range(3)]
    assert radius[0] == np.sqrt(_rounded(dot(offset, offset)))
    assert volume[0] == _rounded(det / 6)
