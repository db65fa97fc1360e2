"""The experiments: PLC families are closed and have the angle they claim; tiny --quick runs write CSV/PNG."""

from __future__ import annotations

import csv
import math
from collections import Counter

import numpy as np
import pytest
from experiments.plc_families import FAMILIES, make_plc

from nonobtuse.mesh3d import validate_plc

BOXED = {"segment_facet", "segments", "fan"}  # facets 0..5 are the box; the rest is inside it


def shell_triangles(family: str, plc) -> np.ndarray:
    return plc.triangles[plc.facet_ids < 6] if family in BOXED else plc.triangles


def directed_edges(triangles: np.ndarray) -> list[tuple[int, int]]:
    return [(int(t[i]), int(t[(i + 1) % 3])) for t in triangles for i in range(3)]


def check_closed_outward(points: np.ndarray, triangles: np.ndarray) -> None:
    """Every directed edge once and its reverse once (closed, edge-manifold, consistently oriented), positive
    enclosed volume (outward orientation)."""
    directed = Counter(directed_edges(triangles))
    assert all(n == 1 and directed[(b, a)] == 1 for (a, b), n in directed.items())
    p = points[triangles]
    volume = np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6
    assert volume > 0


def angle_deg(u, v) -> float:
    u, v = np.asarray(u, float), np.asarray(v, float)
    return math.degrees(math.acos(np.clip(u @ v / np.linalg.norm(u) / np.linalg.norm(v), -1, 1)))


def facet_normal(plc, facet: int) -> np.ndarray:
    a, b, c = plc.points[plc.triangles[plc.facet_ids == facet][0]]
    return np.cross(b - a, c - a)


def dangling(plc) -> list[tuple[int, int]]:
    edges = {frozenset(e) for e in directed_edges(plc.triangles)}
    return [tuple(int(i) for i in s) for s in plc.segments if frozenset(s) not in edges]


CASES = [(f, theta, k) for f, theta, k in
         [("wedge", 1.0, None), ("wedge", 45.0, None), ("wedge", 120.0, None), ("wedge_asym", 3.0, None),
          ("wedge_asym", 100.0, None), ("spike", 1.0, 10),
          ("spike", 60.0, 3), ("segment_facet", 2.5, None), ("segment_facet", 90.0, None),
          ("segments", 1.0, None), ("segments", 120.0, None), ("fan", 30.0, 12), ("fan", 1.0, 3),
          ("fan", 120.0, 3)]]


@pytest.mark.parametrize(("family", "theta", "k"), CASES)
def test_family_is_closed_planar_and_has_its_angle(family, theta, k):
    plc = make_plc(family, theta, k)
    check_closed_outward(plc.points, shell_triangles(family, plc))
    validate_plc(plc)  # exact checks, self-intersections included
    for facet in np.unique(plc.facet_ids):  # each facet planar: all its triangle normals parallel
        ref = facet_normal(plc, facet)
        for tri in plc.triangles[plc.facet_ids == facet]:
            a, b, c = plc.points[tri]
            assert np.linalg.norm(np.cross(np.cross(b - a, c - a), ref)) < 1e-12
    a, b, c = (plc.points[plc.triangles[:, i]] for i in range(3))
    assert np.all(np.linalg.norm(np.cross(b - a, c - a), axis=1) > 1e-6)  # no degenerate facet triangle
    edge_use = Counter(frozenset(e) for e in directed_edges(plc.triangles))
    assert min(edge_use.values()) >= 2  # no facet has a free edge: internal facets end on other facets
    assert len({frozenset(s) for s in plc.segments}) == len(plc.segments)
    assert np.all(plc.segments[:, 0] != plc.segments[:, 1])
    if family in ("wedge", "wedge_asym"):
        # facets 2 and 2 + n - 1 are the sides at the apex edge; interior angle = 180 - the normals' angle
        n_sides = int(plc.facet_ids.max()) - 1
        assert 180 - angle_deg(facet_normal(plc, 2), facet_normal(plc, 1 + n_sides)) == pytest.approx(theta)
    elif family == "spike":  # point k is the apex, on +z; generators at theta from the axis
        apex = plc.points[k]
        assert angle_deg(plc.points[0] - apex, [0, 0, -1]) == pytest.approx(theta)
    elif family == "segment_facet":  # the dangling segment leaves the bottom facet (z = -1) at theta
        (a, b), = dangling(plc)
        foot, top = sorted((plc.points[a], plc.points[b]), key=lambda p: p[2])
        assert foot[2] == -1.0 and 90 - angle_deg(top - foot, [0, 0, 1]) == pytest.approx(theta)
    elif family == "segments":
        (a, b), (c, d) = dangling(plc)
        assert a == c and angle_deg(plc.points[b] - plc.points[a], plc.points[d] - plc.points[c]) \
            == pytest.approx(theta)
    else:  # fan: facets 6.. rotate by theta about the axis, so do their normals (theta <= 180 here)
        assert len(np.unique(plc.facet_ids)) == 6 + k
        for i in range(6, 5 + k):
            assert angle_deg(facet_normal(plc, i), facet_normal(plc, i + 1)) == pytest.approx(theta)


def test_families_refuse_angles_outside_their_range():
    for family, theta, k in [("spike", 90.0, 10), ("wedge", 180.0, None), ("fan", 121.0, 3),
                             ("fan", 31.0, 12), ("segment_facet", 91.0, None), ("segments", 0.0, None)]:
        assert not FAMILIES[family].accepts(theta, k)
        with pytest.raises(ValueError, match="does not accept"):
            make_plc(family, theta, k)


def read_csv(path) -> list[dict]:
    with open(path) as f:
        return list(csv.DictReader(f))


def test_termination_map_quick_writes_csv_and_png(tmp_path):
    pytest.importorskip("nonobtuse.mesh3d", reason="needs nonobtuse.mesh3d")
    from nonobtuse import mesh3d

    if not hasattr(mesh3d, "refine_gabriel"):
        pytest.skip("nonobtuse.mesh3d.refine_gabriel (helper gabriel3d) is not merged yet")
    from experiments import termination_map

    assert termination_map.main(["--quick", "--out", str(tmp_path), "--thetas", "60", "--families",
                                 "wedge,segments", "--workers", "2"]) == 0
    rows = read_csv(tmp_path / "termination_map_quick.csv")
    assert list(rows[0]) == termination_map.COLUMNS
    # the deterministic work budget, not a wall time limit
    assert {int(r["max_work"]) for r in rows} == {termination_map.QUICK_MAX_WORK}
    # 2 families x theta 60 x every strategy
    assert sorted((r["family"], r["split"]) for r in rows) == sorted(
        (f, s) for f in ("wedge", "segments")
        for s in ("midpoint", "shells", "protected", "mirrored", "default"))
    frontier = read_csv(tmp_path / "termination_frontier_quick.csv")
    assert list(frontier[0]) == termination_map.FRONTIER_COLUMNS and len(frontier) == 10
    assert (tmp_path / "termination_map_quick.png").stat().st_size > 0


def test_frontier_is_the_smallest_theta_from_which_all_converged():
    from experiments.termination_map import frontier

    statuses = {1.0: "max_steiner", 5.0: "converged", 10.0: "time_limit", 20.0: "converged",
                30.0: "converged"}
    rows = [{"family": "wedge", "k": None, "split": "shells", "theta": t, "status": s}
            for t, s in statuses.items()]
    rows.append({"family": "wedge", "k": None, "split": "midpoint", "theta": 30.0, "status": "killed"})
    by_split = {b["split"]: b for b in frontier(rows)}
    # shells: 20 and 30 converged, 10 did not -> from 20; 2 of 5 not converged. midpoint: the largest failed.
    assert (by_split["shells"]["converges_from_theta"], by_split["shells"]["not_converged"]) == (20.0, 2)
    assert by_split["midpoint"]["converges_from_theta"] is None


def test_fit_exponent_recovers_a_power_law():
    from experiments.steiner_study_2d import fit_exponent

    xs = [1e3, 1e4, 1e5]
    assert fit_exponent(xs, [3 * x**1.5 for x in xs]) == pytest.approx(1.5)  # log y = log 3 + 1.5 log x
    assert math.isnan(fit_exponent([1e3], [5.0]))


def test_steiner_study_2d_quick_writes_csv_and_png(tmp_path):
    import nonobtuse

    try:
        from nonobtuse.io import load_domain  # noqa: F401
        from nonobtuse.validate import validate_domain  # noqa: F401
    except ImportError as e:
        pytest.skip(f"needs nonobtuse.io and nonobtuse.validate (helper io2d), not merged yet: {e}")
    if not hasattr(nonobtuse, "refine"):
        pytest.skip("nonobtuse.refine (helper refine2d) is not merged yet")
    from experiments import steiner_study_2d as study

    if not (study.data_root() / "cgshop25").is_dir():
        pytest.skip("../shared/data not present")
    assert study.main(["--quick", "--out", str(tmp_path),
                       "--instances", "^(box|ortho_10_d2723dcc|point_set_100.*)$",
                       "--sizes", "1000,2000", "--workers", "2"]) == 0
    rows = read_csv(tmp_path / "steiner_study_2d_quick.csv")
    assert list(rows[0]) == study.CORPUS_COLUMNS
    assert sorted(r["instance"] for r in rows) == ["box", "ortho_10_d2723dcc", "point_set_100_seed0"]
    ortho = next(r for r in rows if r["instance"] == "ortho_10_d2723dcc")
    assert ortho["cgshop_best_known"] == "3"  # best_known.csv, row ortho_10_d2723dcc
    assert all(int(ortho[c]) >= int(ortho["lower_bound"]) for c in ("greedy", "project_flip", "projection"))
    scaling = read_csv(tmp_path / "steiner_scaling_quick.csv")
    assert list(scaling[0]) == study.SCALING_COLUMNS and len(scaling) == 2 * len(study.METHODS)
    assert list(read_csv(tmp_path / "steiner_scaling_exponents_quick.csv")[0]) == study.EXPONENT_COLUMNS
    for png in ("steiner_study_2d_quick.png", "steiner_scaling_quick.png"):
        assert (tmp_path / png).stat().st_size > 0


def test_bench_scaling_families_are_valid_and_a_tiny_run_writes_its_outputs(tmp_path):
    pytest.importorskip("triangle")
    from experiments import bench_scaling

    from nonobtuse.validate import validate_domain

    for family in bench_scaling.FAMILIES:
        d = validate_domain(bench_scaling.domain_of(family, 400, seed=1), decide_convex_hull=False)
        assert 300 <= len(d.points) <= 400 and d.repairs == []
    assert bench_scaling.main(["--quick", "--out", str(tmp_path), "--sizes", "300,600",
                               "--families", "star,point_set", "--workers", "2"]) == 0
    rows = read_csv(tmp_path / "bench_scaling_quick.csv")
    assert list(rows[0]) == bench_scaling.COLUMNS and len(rows) == 8
    assert all(r["status"] == "ok" and float(r["seconds"]) > 0 and float(r["peak_mb"]) > 0 for r in rows)
    fits = read_csv(tmp_path / "bench_scaling_exponents_quick.csv")
    assert {(f["family"], f["tool"]) for f in fits} == {(f, t) for f in ("star", "point_set")
                                                        for t in bench_scaling.TOOLS}
    assert (tmp_path / "bench_scaling_quick.png").stat().st_size > 0


def test_bench_gabriel3d_keeps_each_methods_least_times_over_repeats(tmp_path, capsys):
    from pathlib import Path

    from experiments.bench_gabriel3d import fastest, main

    runs = [{"input": "a.off", "method": "ours", "points": 9, "seconds": 0.5, "cpu_seconds": 0.3},
            {"input": "a.off", "method": "ours", "points": 9, "seconds": 0.2, "cpu_seconds": 0.4}]
    least = {"input": "a.off", "method": "ours", "points": 9, "seconds": 0.2, "cpu_seconds": 0.3}
    assert fastest(runs) == least
    assert capsys.readouterr().err == ""
    fastest([runs[0], {**runs[1], "points": 10}])
    assert "a.off ours: the repeated runs' results differ" in capsys.readouterr().err
    cube = Path(__file__).parent / "data" / "3d" / "cubes_edge.off"
    assert main(["--methods", "tetgen-pq", "ours", "--repeat", "2", "--out", str(tmp_path), str(cube)]) == 0
    with open(tmp_path / "bench_gabriel3d.csv") as f:
        rows = list(csv.DictReader(f))
    assert [r["method"] for r in rows] == ["tetgen-pq", "ours"]
    assert rows[1]["status"] == "converged" and rows[1]["encroached_facets"] == "0"
    with pytest.raises(SystemExit):
        main(["--repeat", "0", str(cube)])
