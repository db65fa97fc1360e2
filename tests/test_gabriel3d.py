"""check_gabriel / refine_gabriel: exact 3D Gabriel certificate and the Ruppert-like repair of PLCs."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from experiments.plc_families import make_plc
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial import cKDTree

import nonobtuse
from nonobtuse.errors import InvalidInputError
from nonobtuse.io.tetmesh import write_tetmesh
from nonobtuse.mesh3d import check_gabriel, load_plc, refine_gabriel
from nonobtuse.mesh3d.control_volumes3d import control_volumes3d
from nonobtuse.mesh3d.plc import PLC, TetMesh

DATA = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "3d"
STATUSES = {"converged", "budget_exhausted", "min_length_reached", "stalled"}


def quad(a: int, b: int, c: int, d: int) -> list[list[int]]:
    return [[a, b, c], [a, c, d]]


def plc_of(points, facets: list[list[list[int]]]) -> PLC:
    tris = [t for f in facets for t in f]
    ids = [i for i, f in enumerate(facets) for _ in f]
    return PLC(points=np.asarray(points, dtype=float), triangles=np.array(tris), facet_ids=np.array(ids))


def cube() -> PLC:
    pts = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
    return plc_of(
        pts,
        [
            quad(0, 3, 2, 1),
            quad(4, 5, 6, 7),
            quad(0, 1, 5, 4),
            quad(1, 2, 6, 5),
            quad(2, 3, 7, 6),
            quad(3, 0, 4, 7),
        ],
    )


def wedge(theta: float) -> PLC:
    """Two unit-square facets meeting at segment (0, 1) at dihedral angle theta (degrees), closed by three
    facets."""
    h = np.tan(np.radians(theta))
    pts = [[0, 0, 0], [0, 1, 0], [1, 0, 0], [1, 1, 0], [1, 0, h], [1, 1, h]]
    return plc_of(pts, [quad(0, 1, 3, 2), quad(0, 4, 5, 1), [[0, 2, 4]], [[1, 5, 3]], quad(2, 3, 5, 4)])


def spike(theta: float, n: int = 10) -> PLC:
    """A cone of height 1 over a regular n-gon, apex (index n) half-angle theta (degrees)."""
    r = np.tan(np.radians(theta))
    ang = 2 * np.pi * np.arange(n) / n
    pts = np.vstack([np.c_[r * np.cos(ang), r * np.sin(ang), np.zeros(n)], [[0, 0, 1]]])
    sides = [[[i, (i + 1) % n, n]] for i in range(n)]
    base = [[[0, i + 1, i] for i in range(1, n - 1)]]
    return plc_of(pts, sides + base)


def volume(mesh: TetMesh) -> float:
    p = mesh.points[mesh.tets]
    return float(np.sum(np.linalg.det(p[:, 1:] - p[:, :1])) / 6.0)


def assert_result_consistent(res, plc: PLC) -> None:
    mesh = res.mesh
    assert res.status in STATUSES
    np.testing.assert_array_equal(mesh.points[: len(plc.points)], plc.points)  # input points first, unchanged
    assert res.stats["steiner_points"] == len(mesh.points) - len(plc.points)
    again = check_gabriel(mesh)  # the certificate is recomputed independently of the refinement
    assert (res.status == "converged") == again.ok
    if res.stats["unchecked_faces"] or res.stats["unchecked_segments"]:  # time_limit cut the check short
        assert res.status == "budget_exhausted"
        assert res.stats["encroached_facets"] <= len(again.faces)
        assert res.stats["encroached_segments"] <= len(again.segments)
    else:
        assert res.stats["encroached_facets"] == len(again.faces)
        assert res.stats["encroached_segments"] == len(again.segments)


# ---- check_gabriel
# ----------------------------------------------------------------------------------------------


def test_check_flat_sliver_face_is_encroached():
    # Base: equilateral triangle with circumcenter (0,0,0), radius 1; apex 0.1 above: depth 1 - 0.1 = 0.9.
    s = np.sqrt(3) / 2
    pts = np.array([[1, 0, 0], [-0.5, s, 0], [-0.5, -s, 0], [0, 0, 0.1]])
    mesh = TetMesh(
        points=pts,
        tets=np.zeros((0, 4), np.int64),
        boundary_faces=np.array([[0, 2, 1], [0, 1, 3]]),
        face_markers=np.zeros(2, np.int64),
    )
    rep = check_gabriel(mesh)
    # Only face 0 is asserted: the apex lies on face (0, 1, 3) itself and cannot encroach it.
    assert 0 in rep.faces.tolist()
    i = rep.faces.tolist().index(0)
    assert rep.face_vertices[i] == 3
    assert rep.face_depths[i] == pytest.approx(0.9)


def test_check_right_angle_is_not_encroached():
    # (0, 1, 0) sees the segment (-1,0,0)-(1,0,0) at exactly 90 degrees (Thales): on the sphere, not inside.
    pts = np.array([[-1, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=float)
    mesh = TetMesh(
        points=pts,
        tets=np.zeros((0, 4), np.int64),
        boundary_faces=np.zeros((0, 3), np.int64),
        face_markers=np.zeros(0, np.int64),
        segments=np.array([[0, 1]]),
    )
    assert check_gabriel(mesh).ok
    mesh.points = np.vstack([pts, [[0, 0.99, 0]]])
    rep = check_gabriel(mesh)
    assert rep.segments.tolist() == [0] and rep.segment_vertices.tolist() == [3]


def test_check_rejects_bad_faces():
    pts = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0]], dtype=float)
    mesh = TetMesh(
        points=pts,
        tets=np.zeros((0, 4), np.int64),
        boundary_faces=np.array([[0, 1, 2]]),
        face_markers=np.zeros(1, np.int64),
    )
    with pytest.raises(InvalidInputError, match="collinear"):
        check_gabriel(mesh)
    mesh.boundary_faces = np.array([[0, 1, 7]])
    with pytest.raises(InvalidInputError, match="point 7"):
        check_gabriel(mesh)


@settings(derandomize=True, deadline=None, max_examples=30)
@given(st.lists(st.tuples(*[st.integers(-8, 8)] * 3), min_size=4, max_size=12, unique=True))
def test_check_agrees_with_brute_force_on_integer_points(coords):
    # Integer coordinates: squared distances are exact in float64, so a brute-force test is exact too.
    pts = np.array(coords, dtype=float)
    n = len(pts)
    faces = [
        (a, b, c)
        for a in range(n)
        for b in range(a + 1, n)
        for c in range(b + 1, n)
        if np.linalg.norm(np.cross(pts[b] - pts[a], pts[c] - pts[a])) > 0
    ][:40]
    segs = [(a, b) for a in range(n) for b in range(a + 1, n)]
    mesh = TetMesh(
        points=pts,
        tets=np.zeros((0, 4), np.int64),
        boundary_faces=np.array(faces).reshape(-1, 3),
        face_markers=np.zeros(len(faces), np.int64),
        segments=np.array(segs),
    )
    rep = check_gabriel(mesh)
    # Segment (a, b): p is strictly inside its diametral sphere iff (a - p).(b - p) < 0 (exact on integers).
    expect = [
        k
        for k, (a, b) in enumerate(segs)
        if any(np.dot(pts[a] - pts[p], pts[b] - pts[p]) < 0 for p in range(n) if p not in (a, b))
    ]
    assert rep.segments.tolist() == expect


# ---- refine_gabriel
# ---------------------------------------------------------------------------------------------


def test_cube_converges_without_steiner_points():
    # Square faces: the fourth corner lies on each triangle's diametral sphere (not inside), the other corners
    # outside; an edge is seen from every other corner at an angle of at most 90 degrees. Nothing to do.
    plc = cube()
    res = refine_gabriel(plc, max_steiner=50)
    assert res.status == "converged", res.stats["diagnosis"]["stop_reason"]
    assert res.stats["steiner_points"] == 0
    assert volume(res.mesh) == pytest.approx(1.0, abs=1e-12)
    assert sorted(set(res.mesh.face_facets.tolist())) == [0, 1, 2, 3, 4, 5]
    assert_result_consistent(res, plc)


def test_control_volumes_false_skips_the_summary_only():
    plc = spike(20.0)
    full, bare = refine_gabriel(plc), refine_gabriel(plc, control_volumes=False)
    assert bare.stats["negative_couplings"] is None
    assert full.stats["negative_couplings"] == control_volumes3d(full.mesh).negative_couplings
    assert np.array_equal(full.mesh.points, bare.mesh.points) and full.status == bare.status


@pytest.mark.parametrize("theta", range(1, 11))
def test_wedge_ends_with_status_and_names_the_dihedral(theta):
    plc = wedge(theta)
    res = refine_gabriel(plc, max_steiner=200, time_limit=5)
    assert_result_consistent(res, plc)
    angles = res.stats["diagnosis"]["smallest_angles"]
    # The dihedral angle between the bottom (z = 0) and the top (z = x tan theta) facets along segment (0, 1).
    dihedral = [a for a in angles if a["kind"] == "dihedral" and sorted(a["vertices"]) == [0, 1]]
    assert dihedral and dihedral[0]["degrees"] == pytest.approx(theta, abs=1e-9)
    assert angles[0]["degrees"] == pytest.approx(theta, abs=1e-9)  # nothing smaller in this PLC
    # The wedge's vertices sit at the corners of unit squares: every diametral sphere of the input is empty.
    assert res.status == "converged"


@pytest.mark.parametrize("theta", range(1, 11))
def test_spike_ends_within_budget_and_names_the_apex(theta):
    plc = spike(theta)
    res = refine_gabriel(plc, max_steiner=150, time_limit=5)
    assert_result_consistent(res, plc)
    assert res.stats["steiner_points"] <= 150
    smallest = res.stats["diagnosis"]["smallest_angles"][0]
    # At the apex (index 10) neighbouring generators make 2 asin(sin(theta) sin(18 deg)) < theta degrees.
    generators = 2 * np.degrees(np.arcsin(np.sin(np.radians(theta)) * np.sin(np.radians(18))))
    assert 10 in smallest["vertices"]
    assert smallest["degrees"] <= generators + 1e-9


def flat_tetrahedron() -> PLC:
    """Apex 0.1 above the center of an equilateral base of circumradius 1: the apex encroaches the base facet
    (depth 0.9), and its edges make 5.7 degrees with the base: refinement runs until a budget stops it."""
    s = np.sqrt(3) / 2
    pts = [[1, 0, 0], [-0.5, s, 0], [-0.5, -s, 0], [0, 0, 0.1]]
    return plc_of(pts, [[[0, 2, 1]], [[0, 1, 3]], [[1, 2, 3]], [[2, 0, 3]]])


def test_budget_and_min_length_are_statuses():
    plc = flat_tetrahedron()
    res = refine_gabriel(plc, max_steiner=3)
    assert res.status == "budget_exhausted" and res.stats["steiner_points"] == 3
    assert_result_consistent(res, plc)
    # The apex is 0.51 from the midpoint of base edge (0, 1), inside its diametral sphere (radius 0.866): the
    # first split halves it into pieces of 0.866 < 0.9.
    res = refine_gabriel(plc, max_steiner=1000, min_length=0.9)
    assert res.status == "min_length_reached" and res.stats["steiner_points"] == 0
    assert "min_length" in res.stats["diagnosis"]["stop_reason"]
    # No time at all: stops before the first insertion; the input is not Gabriel.
    res = refine_gabriel(plc, max_steiner=10**6, time_limit=0.0)
    assert res.status == "budget_exhausted" and res.stats["steiner_points"] == 0
    assert "time_limit" in res.stats["diagnosis"]["stop_reason"]
    smallest = res.stats["diagnosis"]["smallest_angles"][0]
    # Edge (apex, base vertex) against the base plane: atan(0.1 / 1) = 5.71 degrees.
    assert smallest["kind"] == "segment-facet"
    assert smallest["degrees"] == pytest.approx(np.degrees(np.arctan(0.1)))


def test_time_limit_bounds_refinement_and_check():
    # fan k=12 at 3 degrees, midpoint split: the refinement stalls with ~9,700 Steiner points crowded at the
    # axis (0.3 s in, on a quiet machine, since the incremental encroachment set; 3,765 points at 0.1 s); the
    # exact check of that state alone took 44 s before time_limit covered it.
    plc = make_plc("fan", 3.0, 12)
    start = time.perf_counter()
    res = refine_gabriel(plc, split="midpoint", time_limit=0.1, min_length=0.0)  # no other stop than time
    elapsed = time.perf_counter() - start
    assert elapsed < 0.1 + 5.0  # slack: building the final Delaunay mesh (not time-limited) on a busy machine
    assert res.status == "budget_exhausted"
    assert "time_limit" in res.stats["diagnosis"]["stop_reason"]
    assert_result_consistent(res, plc)


def area_vectors(points: np.ndarray, triangles: np.ndarray, ids: np.ndarray) -> dict[int, np.ndarray]:
    """Sum of the area vectors (half cross products) of the triangles of each facet id."""
    p = points[triangles]
    a = 0.5 * np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    return {int(i): a[ids == i].sum(axis=0) for i in np.unique(ids)}


def test_budget_exhausted_result_keeps_the_subfacets():
    # fan k=3 at 5 degrees stopped after 5 Steiner points: the Delaunay tetrahedralization crosses an
    # encroached subfacet, the flood fill from outside leaks into every region and no tet is left. The result
    # used to carry no boundary face at all (so "0 encroached facets" certified nothing).
    plc = make_plc("fan", 5.0, 3)
    res = refine_gabriel(plc, max_steiner=5)
    assert res.status == "budget_exhausted"
    assert res.stats["volume_mesh"].startswith("not built")
    assert len(res.mesh.tets) == 0
    # The subfacets tile each facet with the input's orientation: per facet, the same summed area vector as
    # the input triangles (a planar facet's area vector is additive over any tiling).
    got = area_vectors(res.mesh.points, res.mesh.boundary_faces, res.mesh.face_facets)
    want = area_vectors(plc.points, plc.triangles, plc.facet_ids)
    assert got.keys() == want.keys()
    for f in want:
        np.testing.assert_allclose(got[f], want[f], rtol=1e-9, atol=1e-12)
    # A subfacet that is no Delaunay face has a vertex inside its diametral sphere: some must be encroached.
    assert res.stats["encroached_facets"] > 0
    assert_result_consistent(res, plc)


def test_result_without_tets_can_be_written(tmp_path):
    # The result of the test above (subfacets, no tets): meshio's VTU writer failed on the empty tetra block.
    import meshio

    res = refine_gabriel(make_plc("fan", 5.0, 3), max_steiner=5)
    assert len(res.mesh.tets) == 0
    for suffix in (".vtu", ".msh"):
        write_tetmesh(res.mesh, tmp_path / f"out{suffix}")
        back = meshio.read(tmp_path / f"out{suffix}")
        assert [(c.type, len(c.data)) for c in back.cells] == [("triangle", len(res.mesh.boundary_faces))]


@pytest.mark.parametrize("theta", [14.0, 16.0, 22.0])
def test_fan_midpoint_does_not_crash(theta):
    # Killed the process with SIGFPE on main 1a747d5: a needle subfacet's floating-point circumcenter was NaN
    # and GMP raises SIGFPE when the facet's exact triangulation reads a NaN. In a subprocess so that a crash
    # fails this test instead of killing pytest; a small budget keeps it short.
    code = (
        "from experiments.plc_families import make_plc\n"
        "from nonobtuse.mesh3d import refine_gabriel\n"
        f"r = refine_gabriel(make_plc('fan', {theta}, 3), split='midpoint', time_limit=10, "
        "max_steiner=2000)\n"
        "print(r.status)\n"
    )
    root = Path(__file__).resolve().parents[1]
    package_parent = Path(nonobtuse.__file__).resolve().parents[1]  # the nonobtuse this test imported
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(package_parent), str(root)])}
    done = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() in STATUSES


def test_split_rules_are_deterministic():
    plc = flat_tetrahedron()
    for split in ("shells", "midpoint"):
        a = refine_gabriel(plc, max_steiner=60, split=split, min_length=0.0)  # spins: min_length would end it
        b = refine_gabriel(plc, max_steiner=60, split=split, min_length=0.0)
        assert a.stats["steiner_points"] == 60
        np.testing.assert_array_equal(a.mesh.points, b.mesh.points)
        np.testing.assert_array_equal(a.mesh.tets, b.mesh.tets)


def test_progress_callback_is_called():
    calls = []
    res = refine_gabriel(flat_tetrahedron(), max_steiner=40, progress=lambda *a: calls.append(a),
                         progress_every=10, protected_fallback=False)  # one pass (the fallback reports too)
    # Every 10 insertions up to the budget, then once per exact check of the Delaunay mesh (one here: the
    # budget stops the run before any repair round), with that check's counts.
    assert [c[0] for c in calls] == [10, 20, 30, 40, 40]
    assert calls[-1][1:3] == (res.stats["encroached_segments"], res.stats["encroached_facets"])


def test_invalid_plc_is_reported():
    plc = cube()
    plc.points[7] = plc.points[0]
    with pytest.raises(InvalidInputError, match="duplicate points"):
        refine_gabriel(plc)
    plc = cube()
    plc.triangles[0] = [0, 1, 99]
    with pytest.raises(InvalidInputError, match="point 99"):
        refine_gabriel(plc)


def schonhardt() -> PLC:
    """The Schönhardt prism: top triangle twisted by 30 degrees; side quads split along their reflex
    diagonals."""
    path = DATA / "schonhardt.off"
    if not path.exists():
        pytest.skip("../shared/data not present")
    lines = [ln for ln in path.read_text().split("\n")[1:] if ln.strip()]
    n, m = map(int, lines[0].split()[:2])
    pts = np.array([[float(v) for v in ln.split()] for ln in lines[1 : 1 + n]])
    tris = np.array([[int(v) for v in ln.split()[1:4]] for ln in lines[1 + n : 1 + n + m]])
    return PLC(points=pts, triangles=tris, facet_ids=np.arange(len(tris)))


def test_schonhardt_prism():
    plc = schonhardt()
    # SOURCES.md: 4 of its 8 triangles are not Gabriel, so Steiner points are needed.
    res = refine_gabriel(plc, max_steiner=500, time_limit=10)
    assert_result_consistent(res, plc)
    assert res.stats["steiner_points"] > 0
    if res.status == "converged":
        assert volume(res.mesh) > 0


def test_cospherical_repair_faces_get_one_circumcenter():
    # gc_spot.ply (a smooth closed surface): the repair rounds split Delaunay faces that are not subfacets.
    # Two such faces on one facet with the same circumcircle (four cocircular points) both used to be split,
    # the second rounded circumcenter landing 1 or 2 ulps from the first: 19 point pairs 1e-17 of the bounding
    # box diagonal apart in the converged mesh. Points that close are never needed: the smallest input feature
    # (subsegment, vertex distance) of this surface is ~1e-3 of the diagonal.
    path = DATA / "gc_spot.ply"
    if not path.exists():
        pytest.skip("../shared/data not present")
    plc = load_plc(path)
    res = refine_gabriel(plc)
    assert res.status == "converged"
    p = res.mesh.points
    diag = np.linalg.norm(p.max(axis=0) - p.min(axis=0))
    closest = cKDTree(p).query(p, k=2)[0][:, 1].min()
    assert closest > 1e-9 * diag


def test_default_min_length_ends_a_small_angle_cascade():
    # A segment at 1 degree to a facet it ends on: concentric shells alone do not terminate there (the
    # protected fallback does; test_gabriel3d_protected.py). With min_length=0 the shells pass splits down
    # to subsegments of ~1e-17 of the bounding box diagonal and stalls on rounding (measured: ~4,700 points,
    # 2 s); the default, 1e-6 of the diagonal (here sqrt(12) * 1e-6: the box is [-1, 1]^3), stops the cascade
    # there.
    plc = make_plc("segment_facet", 1.0)
    diag = np.linalg.norm(plc.points.max(axis=0) - plc.points.min(axis=0))
    res = refine_gabriel(plc, max_steiner=20_000, protected_fallback=False)
    assert res.stats["min_length"] == 1e-6 * diag
    assert res.status == "min_length_reached"
    assert res.stats["smallest_subsegment"] >= 1e-6 * diag
    assert_result_consistent(res, plc)
    off = refine_gabriel(plc, max_steiner=2_000, min_length=0.0, protected_fallback=False)  # far below 1e-6
    assert off.status != "min_length_reached" and off.stats["min_length"] == 0.0
