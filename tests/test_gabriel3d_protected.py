"""refine_gabriel's protected strategy: protecting balls at apex vertices end the small-angle cascades.

Every converged case is re-certified here by the exact check of the returned mesh and its tetrahedra are
checked to fill the PLC's volume (the signed volume of its outward triangles).
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from experiments.plc_families import make_plc

from nonobtuse.mesh3d import check_gabriel, load_plc, refine_gabriel
from nonobtuse.mesh3d.plc import PLC

DATA = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "3d"


def enclosed_volume(plc: PLC) -> float:
    """The signed volume bounded by the PLC's consistently oriented triangles (divergence theorem)."""
    p = plc.points[plc.triangles]
    return float(np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0)


def assert_certified(res, plc: PLC) -> None:
    assert res.status == "converged", res.stats["diagnosis"]["stop_reason"]
    again = check_gabriel(res.mesh)  # exact, independent of the refinement's own certificate
    assert again.ok and again.n_faces > 0
    np.testing.assert_array_equal(res.mesh.points[: len(plc.points)], plc.points)
    t = res.mesh.points[res.mesh.tets]
    tet_volume = np.linalg.det(t[:, 1:] - t[:, :1]).sum() / 6.0
    assert tet_volume == pytest.approx(abs(enclosed_volume(plc)), rel=1e-9)


@pytest.mark.parametrize(("family", "theta"), [("segment_facet", 5.0), ("segment_facet", 1.0)])
def test_protected_strategy_converges_on_small_segment_facet_angles(family, theta):
    plc = make_plc(family, theta)
    res = refine_gabriel(plc, split="protected")
    assert_certified(res, plc)
    assert res.stats["strategy"] == "protected"
    assert res.stats["protecting_balls"] == 1  # the foot; the box's edges lie in its facets


@pytest.mark.parametrize(("family", "theta", "strategy"), [("wedge", 1.0, "shells"),
                                                           ("segment_facet", 5.0, "shells+protected")])
def test_default_strategy_converges_on_small_angle_families(family, theta, strategy):
    plc = make_plc(family, theta)
    res = refine_gabriel(plc)
    assert_certified(res, plc)
    assert res.stats["strategy"] == strategy


def test_default_falls_back_to_protection_where_shells_cascade():
    # A segment 5 degrees over the facet it stands on: shells alone run the subsegment at its foot down to
    # min_length; the default then reruns from the input with the foot protected, and converges.
    plc = make_plc("segment_facet", 5.0)
    shells = refine_gabriel(plc, protected_fallback=False)
    assert shells.status == "min_length_reached" and shells.stats["strategy"] == "shells"
    res = refine_gabriel(plc)
    assert_certified(res, plc)
    assert res.stats["strategy"] == "shells+protected"
    assert res.stats["other_attempt"].startswith("shells: min_length_reached")


def test_fallback_leaves_converging_inputs_alone():
    plc = make_plc("segments", 10.0)  # shells converge: no protected pass, no balls
    res = refine_gabriel(plc)
    assert_certified(res, plc)
    assert res.stats["strategy"] == "shells" and res.stats["protecting_balls"] == 0


def test_schonhardt_with_orientation_fixed_reports_both_attempts():
    # Neither strategy converges on the Schönhardt prism yet (its facets meet at 19-22 degree segment-facet
    # angles along shared edges, outside what the balls cover): the status stays consistent with the exact
    # check of the returned mesh, and the stats say what the protected attempt did.
    path = DATA / "schonhardt.off"
    if not path.exists():
        pytest.skip("../shared/data not present")
    plc = load_plc(path)  # load_plc orients it (orientation is never refused)
    res = refine_gabriel(plc, max_steiner=2_000)
    assert (res.status == "converged") == check_gabriel(res.mesh).ok
    if res.status != "converged":
        assert res.stats["strategy"] == "shells"
        assert res.stats["other_attempt"].startswith("protected: ")


CORPUS = Path(__file__).resolve().parent / "data" / "3d"


def test_generated_schonhardt_converges_through_the_fallback():
    # The generated Schönhardt prism (twisted 30 degrees): shells alone run down to min_length at its
    # segment-facet angles; the protected rerun converges with a few dozen points.
    plc = load_plc(CORPUS / "schonhardt.off")
    res = refine_gabriel(plc)
    assert_certified(res, plc)
    assert res.stats["strategy"] == "shells+protected"
    assert res.stats["other_attempt"].startswith("shells: min_length_reached")


def test_the_first_pass_stops_its_cascade_at_a_thousandth_of_the_inputs_scale():
    # Alone, shells on the generated prism split down to min_length (1e-6 of the diagonal), far below
    # the input's own scale (its closest points; its triangles are well shaped). Where the protected rerun
    # follows, the first pass stops once a subsegment is shorter than 1/1000 of that: the whole run (that
    # pass and the rerun) then costs less work than the first pass alone did.
    plc = load_plc(CORPUS / "schonhardt.off")
    alone = refine_gabriel(plc, protected_fallback=False)
    assert alone.status == "min_length_reached"
    assert alone.stats["smallest_subsegment"] < 1e-3 * min(closest_pair(plc.points), smallest_altitude(plc))
    res = refine_gabriel(plc)
    assert_certified(res, plc)
    assert res.stats["strategy"] == "shells+protected"
    assert "cascade floor" in res.stats["other_attempt"]
    assert res.stats["work"] < alone.stats["work"]
    # an explicit min_length is the caller's: no floor
    given = refine_gabriel(plc, min_length=alone.stats["min_length"])
    assert "cascade floor" not in given.stats["other_attempt"]
    assert given.stats["work"] > alone.stats["work"]


def smallest_altitude(plc) -> float:
    a, b, c = (plc.points[plc.triangles[:, k]] for k in range(3))
    longest = np.linalg.norm(np.stack([b - a, c - b, a - c]), axis=2).max(0)
    return float((np.linalg.norm(np.cross(b - a, c - a), axis=1) / longest).min())


def closest_pair(points: np.ndarray) -> float:
    from scipy.spatial import cKDTree

    d, _ = cKDTree(points).query(points, k=2)
    return float(d[:, 1].min())


@pytest.mark.slow
def test_gyroid_converges_past_cospherical_circumcenters():
    # Marching cubes of a gyroid: the repair of the Delaunay mesh meets the second face of a cospherical
    # pair whose circumcenter (already inserted) is 2e-16 from it. That circumcenter is refused instead of
    # ending the run at min_length; the mesh converges and keeps no edge of rounding length.
    plc = load_plc(CORPUS / "mc_gyroid.off")
    res = refine_gabriel(plc, split="protected")
    assert_certified(res, plc)
    assert closest_pair(res.mesh.points) >= res.stats["min_length"]


def test_protecting_ball_below_min_length_is_a_diagnosed_stop():
    # min_length above every protecting radius (<= lfs / 4 < the box's extent / 4): the first point where a
    # segment leaves a ball would make an edge shorter than min_length; the run says so and places nothing.
    plc = make_plc("segment_facet", 5.0)
    extent = float(np.linalg.norm(plc.points.max(axis=0) - plc.points.min(axis=0)))
    res = refine_gabriel(plc, split="protected", min_length=extent / 4)
    assert res.status == "min_length_reached"
    assert res.stats["protecting_balls"] > 0 and res.stats["steiner_points"] == 0
    assert "leaves a protecting ball" in res.stats["diagnosis"]["stop_reason"]


def shared_plc(name: str) -> PLC:
    """The file of ../shared/data/3d, loaded; skips the test when the shared data is absent."""
    if not (DATA / name).exists():
        pytest.skip("../shared/data not present")
    return load_plc(DATA / name)


def diagonal(plc: PLC) -> float:
    return float(np.linalg.norm(plc.points.max(axis=0) - plc.points.min(axis=0)))


def test_step_off_names_the_protecting_ball_below_min_length():
    # step.off's near-duplicate vertices (6e-4 apart, 2e-7 of its diagonal) give balls of radius 1.2e-4, below
    # the first pass's min_length (1e-6 of the diagonal, 3e-3).
    plc = shared_plc("step.off")
    res = refine_gabriel(plc, split="protected", min_length=1e-6 * diagonal(plc))
    assert res.status == "min_length_reached"
    assert "leaves a protecting ball" in res.stats["diagnosis"]["stop_reason"]


def test_protected_rerun_has_limits_of_its_own_unless_given():
    # Left to the defaults, the fallback's protected rerun gets 4 times the Steiner budget (10 n + 10,000)
    # and 1/1000 of the min_length (1e-6 of the bounding box diagonal); explicit limits are kept as given, and
    # split="protected" alone keeps the shared defaults.
    plc = make_plc("segment_facet", 5.0)  # shells end at min_length, the protected rerun converges
    n, diag = len(plc.points), diagonal(plc)
    res = refine_gabriel(plc)
    assert res.stats["strategy"] == "shells+protected"
    assert res.stats["max_steiner"] == 4 * (10 * n + 10_000)
    assert res.stats["min_length"] == pytest.approx(1e-9 * diag, rel=1e-12)
    given = refine_gabriel(plc, max_steiner=5_000, min_length=1e-5 * diag)
    assert given.stats["strategy"] == "shells+protected"
    assert given.stats["max_steiner"] == 5_000 and given.stats["min_length"] == 1e-5 * diag
    alone = refine_gabriel(plc, split="protected")
    assert alone.stats["max_steiner"] == 10 * n + 10_000
    assert alone.stats["min_length"] == pytest.approx(1e-6 * diag, rel=1e-12)
    shared = refine_gabriel(plc, fallback_own_limits=False)  # the 3D quality pass's repairs
    assert shared.stats["strategy"] == "shells+protected"
    assert shared.stats["max_steiner"] == 10 * n + 10_000
    assert shared.stats["min_length"] == pytest.approx(1e-6 * diag, rel=1e-12)


def test_u_off_converges_through_the_protected_rerun():
    # The shared u.off has needle facets: segment-facet angles of 0.067 degrees at 4 apices, balls of radius
    # 2^-8, so segment and facet are r sin(theta) = 4.6e-6 apart outside the balls. The protected rerun
    # converges with about 22,300 points (2x the first Steiner budget; closest points 2e-7 apart, 1.7e-7
    # of the diagonal, below the first pass's min_length); shells alone do not converge (their Steiner budget,
    # or min_length since needle corners get paired points).
    plc = shared_plc("u.off")
    res = refine_gabriel(plc)
    assert_certified(res, plc)
    assert res.stats["strategy"] == "shells+protected"
    assert res.stats["other_attempt"].startswith(("shells: budget_exhausted", "shells: min_length_reached"))
    assert res.stats["steiner_points"] > 10 * len(plc.points) + 10_000  # more than the first pass's budget


def test_part_off_converges_through_the_protected_rerun():
    # The shared part.off has a 6.4 degree corner at vertex 20 (facet 223), where the shells rule leaves
    # exactly cocircular trapezoids on the protecting ball's sphere; the rerun's arc split of one subfacet
    # lands next to its twin's arc point. That point is refused (split_subfacet), not a min_length stop, so
    # the protected rerun converges and the mirrored third pass is not needed.
    plc = shared_plc("part.off")
    res = refine_gabriel(plc)
    assert_certified(res, plc)
    assert res.stats["strategy"] == "shells+protected"
    assert res.stats["other_attempt"].startswith("shells: ")


@pytest.mark.parametrize("split", ["protected", "mirrored"])
def test_split_points_stay_on_their_facets_plane_on_a_sliver_far_from_the_origin(split):
    # fuzz seed 206: a tet 1.4e-6 across and 7e-9 thick at 1000 (a unit in the last place: 1.1e-13). The
    # collar rule moved a subfacet's circumcenter half a unit in the last place from a subsegment's midpoint
    # along that noise onto the subsegment's sphere: boundary points 1.5e-8 (mirrored) and 5.3e-8 (protected)
    # off their facet's plane, and a "converged" mesh enclosing 0.09% more than the input. Now within 1e-11
    # (exact distances).
    points = np.array([[999.9999998151209, 999.9999998556286, 1000.0],
                       [1000.0000005918604, 1000.0, 1000.0000000001],
                       [999.9999991640155, 999.9999990468925, 999.9999994687439],
                       [999.9999999576048, 1000.0, 1000.0000000163817]])
    triangles = np.array([[3, 1, 2], [2, 1, 0], [0, 3, 2], [1, 3, 0]])
    segments = np.array([[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]])
    r = refine_gabriel(PLC(points, triangles, np.arange(4), segments), split=split, max_steiner=3000)
    assert squared_plane_distances(r.mesh, triangles).max() <= Fraction(1, 10**22), split


def squared_plane_distances(mesh, triangles: np.ndarray) -> np.ndarray:
    """For every boundary point of mesh, its squared distance (exact, a Fraction) to the plane of the input
    triangle whose facet it lies on (face_facets numbering the input triangles: one facet each)."""
    q = [[Fraction(x) for x in row] for row in mesh.points.tolist()]
    faces, facets = np.asarray(mesh.boundary_faces), np.asarray(mesh.face_facets)
    out = []
    for f, (a, b, c) in enumerate(triangles.tolist()):
        u, v = ([q[k][i] - q[a][i] for i in range(3)] for k in (b, c))
        n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        norm2 = sum(x * x for x in n)
        for i in np.unique(faces[facets == f]).tolist():
            height = sum((q[i][k] - q[a][k]) * n[k] for k in range(3))
            out.append(height * height / norm2)
    return np.array(out, dtype=object)


def test_collar_points_stay_on_their_facets_plane_far_from_the_origin():
    # fuzz seed 359: a tet 1.6e4 across at 1e6 (a unit in the last place: 1.2e-10). The collar rule moved a
    # subfacet's circumcenter, rounded about a unit in the last place off its facet, along the ray from a
    # subsegment's midpoint onto its sphere, which multiplied that by up to 1e7: a point 0.032 off its
    # facet, and refine_gabriel returned "converged" for a mesh enclosing 3e-8 less than the input. The ray
    # now lies in the facet's plane: every boundary point within a unit in the last place of it, the volume
    # the input's.
    points = np.array([[1000000.0, 1006250.0, 997500.0], [1000000.0, 990934.0620086221, 991621.8887856705],
                       [1006797.30139335, 995644.53125, 1009555.6977237413],
                       [1002298.4992539875, 997229.0176661927, 992312.9704441539],
                       [998203.125, 1004976.404580596, 1004765.625]])
    triangles = np.array([[1, 2, 4], [4, 2, 0], [0, 1, 4], [2, 1, 3], [3, 0, 2], [1, 0, 3]])
    segments = np.array([[0, 1], [0, 2], [0, 3], [0, 4], [1, 2], [1, 3], [1, 4], [2, 3], [2, 4]])
    plc = PLC(points, triangles, np.arange(6), segments)
    r = refine_gabriel(plc)
    assert_certified(r, plc)
    assert r.stats["strategy"] == "shells+protected"
    assert squared_plane_distances(r.mesh, triangles).max() <= Fraction(float(np.spacing(1.1e6))) ** 2
