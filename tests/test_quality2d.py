"""refine(min_angle=, max_area=, size=): interior quality with the boundary still certified. Angles and areas
are recomputed here from the returned mesh; the boundary certificate by the exact rational oracle."""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import nonobtuse
from nonobtuse import Domain, InvalidInputError
from nonobtuse.cli import main
from nonobtuse.io import load_domain
from refine_helpers import obtuse_boundary_sides


def smallest_angles(mesh: nonobtuse.Mesh) -> np.ndarray:
    """(m,) float64: the smallest angle of every triangle, in degrees."""
    p = mesh.points[mesh.triangles]
    out = np.full(len(p), 180.0)
    for i in range(3):
        u, w = p[:, (i + 1) % 3] - p[:, i], p[:, (i + 2) % 3] - p[:, i]
        cross = np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])
        out = np.minimum(out, np.degrees(np.arctan2(cross, np.einsum("ij,ij->i", u, w))))
    return out


def areas(mesh: nonobtuse.Mesh) -> np.ndarray:
    p = mesh.points[mesh.triangles]
    u, w = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    return 0.5 * np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])


def loop(n: int) -> list[tuple[int, int]]:
    return [(i, (i + 1) % n) for i in range(n)]


def cyclic_polygon(seed: int, n: int, n_inner: int) -> Domain:
    """n vertices on a circle of radius 1000, consecutive central angles in [0.7, 1.3] times 2 pi / n (so for
    n >= 6 every interior angle is above 90 degrees: no small input angle), and n_inner interior points at
    radius <= 600."""
    rng = np.random.default_rng(seed)
    gaps = rng.uniform(0.7, 1.3, n)
    a = 2 * np.pi * np.cumsum(gaps) / gaps.sum()
    r, b = 600 * np.sqrt(rng.uniform(0, 1, n_inner)), rng.uniform(0, 2 * np.pi, n_inner)
    pts = np.r_[1000 * np.c_[np.cos(a), np.sin(a)], np.c_[r * np.cos(b), r * np.sin(b)]]
    return Domain(points=pts, segments=loop(n))


def star(seed: int, n: int) -> Domain:
    """A star-shaped polygon, radii in [300, 1000]: small input angles are likely."""
    rng = np.random.default_rng(seed)
    a = 2 * np.pi / n * (np.arange(n) + rng.uniform(0, 0.5, n))
    rad = rng.uniform(300, 1000, n)
    return Domain(points=np.c_[rad * np.cos(a), rad * np.sin(a)], segments=loop(n))


def check_quality(res: nonobtuse.RefineResult, min_angle: float) -> None:
    q = res.stats["quality"]
    assert res.stats["obtuse_boundary_sides"] == 0
    assert obtuse_boundary_sides(res.mesh) == 0  # exact, independent of the C++ certificate
    assert nonobtuse.check(res.mesh).ok
    angles = smallest_angles(res.mesh)
    assert q["triangles"] == len(res.mesh.triangles)
    # every triangle below the bound is one left alone near a small input angle (float tolerance at the bound)
    assert np.count_nonzero(angles < min_angle - 1e-9) <= q["small_angle_triangles"]
    assert q["min_angle_degrees"] == pytest.approx(angles.min(), abs=1e-9)
    n_steiner = len(res.mesh.points) - len(res.mesh.input_points)
    assert n_steiner == res.stats["steiner_points"] + res.stats["interior_points"]


@settings(max_examples=30, deadline=20000, derandomize=True)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(6, 24), n_inner=st.integers(0, 12),
       min_angle=st.sampled_from([20.0, 25.0, 30.0]))
def test_min_angle_on_polygons_without_small_angles(seed: int, n: int, n_inner: int,
                                                    min_angle: float) -> None:
    res = nonobtuse.refine(cyclic_polygon(seed, n, n_inner), min_angle=min_angle)
    assert res.status == "converged"
    check_quality(res, min_angle)
    assert res.stats["quality"]["small_angle_triangles"] == 0
    assert smallest_angles(res.mesh).min() >= min_angle - 1e-9


@settings(max_examples=25, deadline=30000, derandomize=True)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(8, 30))
def test_star_polygons_terminate_certified(seed: int, n: int) -> None:
    res = nonobtuse.refine(star(seed, n), min_angle=25.0, max_steiner=20000, max_interior=20000)
    assert res.status in ("converged", "budget_exhausted", "stalled")
    check_quality(res, 25.0)
    if res.status == "converged":
        assert res.stats["quality"]["bad_triangles"] == 0
        assert res.stats["quality"]["min_angle_outside_small_angles_degrees"] >= 25.0 - 1e-9


def test_max_area_and_region_sizes() -> None:
    d = Domain(points=[[0, 0], [10, 0], [10, 4], [4, 4], [4, 10], [0, 10]],
               segments=[[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [3, 0]],
               regions=[[1, 6, 1.0], [6, 1, 2.0]])
    res = nonobtuse.refine(d, max_area=2.0, size={2.0: 0.25})
    assert res.converged and obtuse_boundary_sides(res.mesh) == 0
    a, region = areas(res.mesh), np.asarray(res.mesh.regions)
    assert np.all(a[region == 2.0] <= 0.25) and np.all(a <= 2.0)
    assert a[region == 2.0].sum() == pytest.approx(32.0) and a[region == 1.0].max() > 0.25
    assert res.stats["quality"]["max_area"] == pytest.approx(a.max())


def test_size_function_and_its_errors() -> None:
    d = Domain(points=[[0, 0], [4, 0], [4, 4], [0, 4]], segments=[[0, 1], [1, 2], [2, 3], [3, 0]])
    res = nonobtuse.refine(d, size=lambda x, y: 0.02 + 0.1 * x)
    assert res.converged
    centroid_x = res.mesh.points[res.mesh.triangles][:, :, 0].mean(axis=1)
    assert np.all(areas(res.mesh) <= 0.02 + 0.1 * centroid_x + 1e-12)
    assert areas(res.mesh)[centroid_x > 3].max() > 0.05  # coarser where allowed
    with pytest.raises(InvalidInputError, match=r"size\(.*\) returned -1"):
        nonobtuse.refine(d, size=lambda x, y: -1.0)
    for bad in ({"min_angle": 50}, {"min_angle": float("nan")}, {"max_area": 0}, {"size": 3.0},
                {"size": {1.0: -2}}, {"max_interior": -1}):
        with pytest.raises(InvalidInputError):
            nonobtuse.refine(d, **bad)


def test_small_input_angle_is_left_alone_and_counted() -> None:
    a = np.radians(np.linspace(0, 8, 5))
    d = Domain(points=np.r_[[[0, 0]], 10 * np.c_[np.cos(a), np.sin(a)]], segments=loop(6))
    res = nonobtuse.refine(d, min_angle=30.0)
    assert res.converged
    check_quality(res, 30.0)
    q = res.stats["quality"]
    assert q["small_angle_triangles"] > 0 and q["min_angle_degrees"] < 30
    assert q["min_angle_outside_small_angles_degrees"] >= 30 - 1e-9


def test_off_by_default_and_the_triangle_dict() -> None:
    d = {"vertices": [[0, 0], [3, 0], [3, 1], [0, 1]], "segments": [[0, 1], [1, 2], [2, 3], [3, 0]]}
    plain = nonobtuse.refine(d)
    assert plain["stats"]["quality"] is None and plain["stats"]["interior_points"] == 0
    quality = nonobtuse.refine(d, min_angle=30)
    assert len(quality["triangles"]) > len(plain["triangles"])
    assert quality["stats"]["quality"]["min_angle_degrees"] >= 30


def test_points_outside_the_domain_are_refused_by_the_api() -> None:
    d = Domain(points=[[0, 0], [1, 0], [1, 1], [0, 1], [5, 5]], segments=[[0, 1], [1, 2], [2, 3], [3, 0]])
    for f in (nonobtuse.refine, nonobtuse.triangulate):
        with pytest.raises(InvalidInputError, match=r"point 4 .*outside the domain"):
            f(d)


def test_cli_min_angle_max_area(tmp_path, capsys) -> None:
    src = tmp_path / "sq.poly"
    src.write_text("4 2 0 0\n1 0 0\n2 3 0\n3 3 2\n4 0 2\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n")
    out = tmp_path / "sq.json"
    assert main(["refine", str(src), "-o", str(out), "--min-angle", "30", "--max-area", "0.1", "--json"]) == 0
    s = json.loads(capsys.readouterr().out)
    assert s["status"] == "converged" and s["quality"]["max_area"] <= 0.1 and s["interior_points"] > 0
    assert s["quality"]["min_angle_degrees"] >= 30 - 1e-9
    reason = "every boundary side has a nonobtuse apex and every triangle meets the quality bounds outside"
    assert s["diagnosis"] == {"stop_reason": reason + " small input angles"} and "edges" not in s
    assert main(["refine", str(src), "-o", str(out), "--max-area", "0.1", "--max-interior", "2"]) == 3
    assert "budget_exhausted (max_interior (2) reached)" in capsys.readouterr().out  # the summary line
    assert main(["refine", str(src), "-o", str(out), "--min-angle", "30", "--quality-boundary", "minimal",
                 "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["quality"]["boundary"] == "minimal"
    with pytest.raises(SystemExit) as exit_info:  # argparse refuses it
        main(["refine", str(src), "-o", str(out), "--region-area", "x=1"])
    assert exit_info.value.code == 2
    assert main(["refine", str(src), "-o", str(out), "--min-angle", "45"]) == 2
    assert "min_angle must be at most 40" in capsys.readouterr().err


def test_region_areas_from_the_poly_region_list(tmp_path, capsys) -> None:
    """Triangle's -a without a number: each region's fourth number bounds its triangles' area."""
    src = tmp_path / "two.poly"
    src.write_text("6 2 0 0\n1 0 0\n2 2 0\n3 4 0\n4 4 2\n5 2 2\n6 0 2\n"
                   "7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n7 2 5\n0\n"
                   "2\n1 1 1 10 0.05\n2 3 1 20\n")
    d = load_domain(src)
    assert d.region_max_areas is not None
    assert d.region_max_areas[0] == 0.05 and np.isnan(d.region_max_areas[1])
    res = nonobtuse.refine(d, size="regions")
    a, region = areas(res.mesh), np.asarray(res.mesh.regions)
    assert res.converged and np.all(a[region == 10] <= 0.05) and a[region == 20].max() > 0.05
    out = tmp_path / "two.json"
    assert main(["refine", str(src), "-o", str(out), "--region-areas", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["interior_points"] == res.stats["interior_points"]
    plain = Domain(points=d.points, segments=d.segments, regions=d.regions)
    with pytest.raises(InvalidInputError, match="no region of the domain gives a maximum area"):
        nonobtuse.refine(plain, size="regions")


def square_with_sharp_hole(seed: int, tip_degrees: float) -> Domain:
    """A 100 x 100 square with a triangular hole whose tip angle is tip_degrees (the other two corners share
    the rest), of size 15-30, rotated and placed at random inside: every angle of the domain is 90 degrees or
    reflex, the hole's small corner lies outside the domain."""
    rng = np.random.default_rng(seed)
    size, turn = rng.uniform(15, 30), rng.uniform(0, 2 * np.pi)
    half = np.radians(tip_degrees) / 2
    local = np.array([[0, 0], [size * np.cos(half), size * np.sin(half)],
                      [size * np.cos(half), -size * np.sin(half)]])
    rot = np.array([[np.cos(turn), -np.sin(turn)], [np.sin(turn), np.cos(turn)]])
    hole = local @ rot.T + rng.uniform(35, 65, 2)
    pts = np.r_[[[0, 0], [100, 0], [100, 100], [0, 100]], hole]
    return Domain(points=pts, segments=loop(4) + [(4, 5), (5, 6), (6, 4)], holes=[hole.mean(axis=0)])


@settings(max_examples=12, deadline=30000, derandomize=True)
@given(seed=st.integers(0, 2**32 - 1), tip=st.floats(10.0, 55.0), min_angle=st.sampled_from([25.0, 30.0]))
def test_a_hole_corner_is_no_small_input_angle(seed: int, tip: float, min_angle: float) -> None:
    """Only angles with the domain inside are small input angles: beside a sharp hole every triangle reaches
    the bound and none is left alone."""
    res = nonobtuse.refine(square_with_sharp_hole(seed, tip), min_angle=min_angle)
    assert res.status == "converged"
    check_quality(res, min_angle)
    assert res.stats["quality"]["small_angle_triangles"] == 0
    assert smallest_angles(res.mesh).min() >= min_angle - 1e-9
