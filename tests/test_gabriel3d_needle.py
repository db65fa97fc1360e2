"""Needle facets (two segments of a facet at a corner of a few thousandths of a degree, as marching cubes
leaves): the paired points of gabriel3d_needle_pairs.cpp let the first pass converge where shells cascaded."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from mesh3d_shapes import write_off
from nonobtuse.mesh3d.gabriel import check_gabriel, refine_gabriel
from nonobtuse.mesh3d.load import load_plc

DATA = Path(__file__).parent / "data" / "3d"


def needle_box(tmp_path: Path) -> Path:
    """A box whose top is triangulated around the needle (v, q, p): v = (0.2, 0.5, 0), q = (0.8, 0.5, 0) and p
    near the segment vq, 2e-5 off it in y and z, so the needle has corners of 0.003 degrees at v and 0.03 at q
    (p's triangles are not coplanar with the rest of the top, whose triangles merge into one facet)."""
    points = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, -1], [1, 0, -1], [1, 1, -1],
                       [0, 1, -1], [0.2, 0.5, 0], [0.75, 0.5 + 2e-5, 2e-5], [0.8, 0.5, 0]], dtype=np.float64)
    a, b, c, d, a1, b1, c1, d1, v, p, q = range(11)
    faces = [[v, q, p], [v, p, d], [p, c, d], [p, q, c], [q, b, c], [a, b, q], [a, q, v], [a, v, d],
             [a1, d1, c1, b1], [a, a1, b1, b], [b, b1, c1, c], [c, c1, d1, d], [d, d1, a1, a]]
    return write_off(tmp_path / "needle_box.off", points, faces)


def assert_certified(res) -> None:
    assert res.status == "converged", res.stats["diagnosis"]["stop_reason"]
    again = check_gabriel(res.mesh)  # exact, independent of the refinement's own certificate
    assert again.ok and again.n_faces > 0 and len(res.mesh.tets) > 0


def points_on(points: np.ndarray, a: int, b: int) -> np.ndarray:
    """Distances from point a of the points on segment ab (within rounding of its line), ascending."""
    d = points[b] - points[a]
    length = np.linalg.norm(d)
    w = points - points[a]
    along = w @ d / length
    off = np.linalg.norm(w - np.outer(along, d / length), axis=1)
    return np.sort(along[(off < 1e-12) & (along > 0) & (along < length)])


def test_needle_box_converges_in_the_first_pass_with_paired_points(tmp_path):
    plc = load_plc(needle_box(tmp_path))
    angles = [a for a in refine_gabriel(plc, max_steiner=0).stats["diagnosis"]["smallest_angles"]
              if a["kind"] == "segment-segment"]
    assert angles[0]["vertices"] == [8, 9, 10] and angles[0]["degrees"] < 0.004
    res = refine_gabriel(plc)
    assert_certified(res)
    # Without the pairs shells ended at their Steiner budget (10,110) and the protected rerun needed 38,291.
    assert res.stats["strategy"] == "shells" and res.stats["steiner_points"] < 1000
    pts = res.mesh.points
    on_vp, on_vq = points_on(pts, 8, 9), points_on(pts, 8, 10)
    assert len(on_vp) > 0
    e, f = pts[9] - pts[8], pts[10] - pts[8]
    theta = np.arctan2(np.linalg.norm(np.cross(e, f)), np.dot(e, f))
    # A Steiner point of v-p has its partner on v-q at cos(theta / 2) r, or r / cos(theta / 2), unless it and
    # the subsegment of v-q its partner would split did not encroach each other (no partner needed).
    def paired(r: float) -> bool:
        ratio = on_vq[np.argmin(np.abs(on_vq - r))] / r
        return min(abs(ratio - np.cos(theta / 2)), abs(ratio - 1 / np.cos(theta / 2))) < 1e-12

    assert sum(paired(r) for r in on_vp) >= len(on_vp) // 2  # measured: 11 of 12


def test_mc_torus_converges_with_defaults():
    # Needles of 0.0022 and 0.0029 degrees (vertices 496 and 865); before the pairs: budget_exhausted.
    res = refine_gabriel(load_plc(DATA / "mc_torus.off"))
    assert_certified(res)
    assert res.stats["strategy"] == "shells"
