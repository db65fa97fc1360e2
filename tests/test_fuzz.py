"""The fuzzer's short mode (experiments/fuzz.py): random valid and near-degenerate 2D domains and small 3D
PLCs, derandomized. Every run ends with a status (or InvalidInputError for an input validation refuses), and
every converged mesh passes the exact re-check (rational oracle in 2D, integer diametral-sphere test in 3D).
The long mode: ``python experiments/fuzz.py --minutes N``."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest
from experiments import fuzz
from experiments.plc_families import make_plc

from mesh3d_shapes import CUBE_POINTS, CUBE_TRIANGLES
from nonobtuse import Domain
from nonobtuse.mesh3d import PLC


def test_fuzz_2d_short():
    outcomes: dict[str, int] = {}
    fuzz.run_2d(examples=80, outcomes=outcomes)
    # the generators mostly make valid inputs, and most of those converge
    assert outcomes.get("converged", 0) > sum(outcomes.values()) / 2, outcomes


def test_fuzz_3d_short():
    outcomes: dict[str, int] = {}
    fuzz.run_3d(examples=8, outcomes=outcomes)
    assert outcomes.get("converged", 0) >= 1, outcomes


def test_fuzz_3d_quality_short():
    outcomes: dict[str, int] = {}
    fuzz.run_quality_3d(examples=6, outcomes=outcomes)
    assert outcomes.get("converged", 0) >= 1, outcomes


def test_the_quality_check_refuses_a_mesh_that_lies(monkeypatch):
    # The unit cube with a volume bound of 0.05: a run made for a bound 100 times larger that claims to meet
    # this one, and a mesh that lost a tet, must both be caught.
    cube = PLC(CUBE_POINTS.copy(), CUBE_TRIANGLES.copy(), np.tile(np.arange(6), 2))  # a quad is two rows
    real = fuzz.refine_quality3d

    def loose(plc, max_volume, **kw):
        return real(plc, max_volume=100 * max_volume, **kw)

    def lost_a_tet(plc, **kw):
        r = real(plc, **kw)
        r.mesh = replace(r.mesh, tets=r.mesh.tets[:-1])
        return r

    for lie, message in ((loose, "over the volume bound"), (lost_a_tet, "another volume")):
        monkeypatch.setattr(fuzz, "refine_quality3d", lie)
        with pytest.raises(AssertionError, match=message):
            fuzz.check_quality_3d(cube, 0.05, None)


def test_the_quality_check_measures_flat_tets_exactly():
    # a rectangle p0, p0 + u, p0 + v, p0 + u + v (u . v = 0) in a tilted plane, its corners rounded off the
    # plane: floating point gets the ratio wrong; the circumcenter is the rectangle's center, so the ratio is
    # sqrt(|u|^2 + |v|^2) / (2 |v|) (|v| < |u|)
    p0, u, v = np.array([0.1, 0.7, 0.3]), np.array([0.1, 0.2, 0.3]), np.array([0.3, 0.0, -0.1])
    corners = np.array([p0, p0 + u, p0 + v, p0 + u + v])
    volumes, ratios = fuzz.tet_volumes_and_ratios(corners, np.array([[0, 1, 2, 3]]))
    assert ratios[0] == pytest.approx(np.sqrt(u @ u + v @ v) / (2 * np.sqrt(v @ v)), rel=1e-9)
    assert volumes[0] < 1e-17
    # fuzz seed 160: spike(theta = 5, k = 5) at 0.2 of the box, R = 2, converges with a sliver between
    # boundary points rounded off a side facet (volume 3.6e-21): floating-point ratio 4.07, exact 0.96
    assert fuzz.check_quality_3d(make_plc("spike", 5.0, 5), 0.2, 2.0) == "converged"


def test_the_enclosed_volume_is_exact_and_only_for_closed_oriented_surfaces():
    # the unit cube scaled by 3 and shifted by 1e6 (exact in doubles): 27; one triangle flipped, or a cube's
    # triangles twice (an edge used four times): no volume
    cube = PLC(3 * CUBE_POINTS + 1e6, CUBE_TRIANGLES.copy(), np.tile(np.arange(6), 2))
    assert fuzz.enclosed_volume(cube) == 27.0
    flipped = CUBE_TRIANGLES.copy()
    flipped[0] = flipped[0, ::-1]
    assert fuzz.enclosed_volume(replace(cube, triangles=flipped)) is None
    twice = np.vstack([CUBE_TRIANGLES, CUBE_TRIANGLES])
    assert fuzz.enclosed_volume(replace(cube, triangles=twice, facet_ids=np.arange(24) % 6)) is None


def test_the_3d_oracle_sees_an_encroached_facet_and_segment():
    # The low tet: the apex (1, 1, 2) is at distance sqrt(6) < 2 sqrt(2) from the circumcentre (2, 2, 0) of
    # the base (0,0,0), (4,0,0), (0,4,0): inside the base's diametral sphere. The base edge (4,0,0)-(0,4,0)
    # has centre (2, 2, 0), radius 2 sqrt(2): the apex is inside that sphere too; the other edges are
    # not encroached ((p - a).(p - b) >= 0 for every vertex p), nor are the side faces.
    pts = np.array([[0, 0, 0], [4, 0, 0], [0, 4, 0], [1, 1, 2]], dtype=np.float64)
    faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    edges = np.array([[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]])
    assert fuzz.gabriel_violations(pts, faces[:1], edges[3:4]) == 2
    assert fuzz.gabriel_violations(pts, faces[1:], edges[[0, 1, 2, 4, 5]]) == 0
    # Raised to (1, 1, 3): |apex - (2,2,0)|^2 = 11 > 8, outside both spheres.
    pts[3, 2] = 3
    assert fuzz.gabriel_violations(pts, faces[:1], edges[3:4]) == 0


@pytest.mark.parametrize("scale, shift", [(1.0, 0.0), (1e-4, 1e3), (1e5, -1e6)])
def test_the_3d_oracle_finds_what_testing_every_point_finds(scale, shift):
    # Random triangles and segments among random points (many encroached, some nearly flat triangles): the
    # candidates of the k-d tree must not miss a point the integer test over every point finds.
    rng = np.random.default_rng(7)
    points = rng.uniform(-1, 1, (80, 3))
    points[70:] = points[60:70] + 1e-9 * rng.uniform(-1, 1, (10, 3))  # near-duplicates: skinny triangles
    points = points * scale + shift
    faces = np.array([rng.choice(80, 3, replace=False) for _ in range(60)] + [[60, 70, 0], [61, 71, 1]])
    segments = np.array([rng.choice(80, 2, replace=False) for _ in range(30)])
    brute = fuzz.gabriel_violations(points, faces, segments, every_point=True)
    assert fuzz.gabriel_violations(points, faces, segments) == brute > 20


def test_the_2d_check_refuses_a_mesh_that_lies(monkeypatch):
    # A refinement that claims convergence on the obtuse triangle (0,0), (4,0), (2,1) (the apex angle is
    # 126.87 degrees) without adding a point: the exact re-check must catch it.
    domain = Domain(np.array([[0, 0], [4, 0], [2, 1]], dtype=np.float64), np.array([[0, 1], [1, 2], [2, 0]]))
    real = fuzz.nonobtuse.refine

    def lying_refine(d, **kw):
        r = real(d, max_steiner=0)
        r.status = "converged"
        r.stats["obtuse_boundary_sides"] = 0
        return r

    monkeypatch.setattr(fuzz.nonobtuse, "refine", lying_refine)
    with pytest.raises(AssertionError, match="obtuse constraint side"):
        fuzz.check_refine_2d(domain, "greedy")
