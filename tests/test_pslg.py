"""PSLGs with interior interfaces (issue 4): both sides of every interior constraint refined, junctions,
dangling segments, region conductivities; hand-worked cases, seeded random multi-region PSLGs, and the real
corpus with pinned counts (tests/data/pslg_corpus.json)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import nonobtuse
from nonobtuse import Domain
from nonobtuse.control_volumes import control_volumes
from nonobtuse.errors import InvalidInputError
from nonobtuse.io import load_domain
from nonobtuse.io.triangle import read_poly
from nonobtuse.validate import validate_domain
from refine_helpers import SHARED, obtuse_constraint_sides

PINS = json.loads((Path(__file__).parent / "data" / "pslg_corpus.json").read_text())["files"]


def steiner_points_on_input_segments(domain: Domain, mesh) -> bool:
    """Every Steiner point lies on an input segment (or a convex hull edge when the hull is the boundary), up
    to a few ulps of its coordinates (Steiner points are rounded onto the line, or a few ulps off it, by
    design)."""
    pts, segs = np.asarray(domain.points), np.asarray(domain.segments).reshape(-1, 2)
    if domain.convex_hull:
        from scipy.spatial import ConvexHull

        segs = np.r_[segs, ConvexHull(pts).simplices]
    a, b = pts[segs[:, 0]], pts[segs[:, 1]]
    scale = np.abs(pts).max() + 1.0
    for q in np.asarray(mesh.points)[len(pts) :]:
        d = b - a
        t = np.clip(np.einsum("ij,ij->i", q - a, d) / np.einsum("ij,ij->i", d, d), 0, 1)
        if np.min(np.hypot(*(a + t[:, None] * d - q).T)) > 64 * np.finfo(float).eps * scale:
            return False
    return True


def assert_refined(domain: Domain, res) -> None:
    assert res.status == "converged"
    assert res.stats["obtuse_boundary_sides"] == 0
    assert obtuse_constraint_sides(res.mesh) == 0
    assert nonobtuse.check(res.mesh).ok
    assert steiner_points_on_input_segments(domain, res.mesh)
    assert res.stats["steiner_points"] >= res.stats["lower_bound"]


def polygon(n: int, radius: float, center=(0.0, 0.0)) -> np.ndarray:
    """A regular n-gon (counter-clockwise). Its edges' diametral disks lie near the rim: for n = 16 and radius
    10 each disk has radius 10 sin(11.25 deg) = 1.95 around a point at 10 cos(11.25 deg) = 9.81 from the
    center, so points within 7.8 of the center encroach no boundary edge."""
    a = 2 * np.pi * np.arange(n) / n
    return np.c_[center[0] + radius * np.cos(a), center[1] + radius * np.sin(a)]


def loop(k: int, start: int = 0) -> list[tuple[int, int]]:
    return [(start + i, start + (i + 1) % k) for i in range(k)]


# ---- hand-worked interfaces ----


def test_interface_through_a_rectangle_gets_both_sides_refined():
    # Rectangle [0, 8] x [0, 8] cut by the interface y = 4 (points 4, 5 on the sides); q1 = (2, 4.5) above it
    # and q2 = (6, 3.5) below, both strictly inside its diametral disk (center (4, 4), radius 4; distances
    # 2.06) and inside no boundary disk (the nearest, the top's (4, 8) r 4 and the upper left side's (0, 6) r
    # 2, are at 4.03 and 2.5). One point y on the interface would need q1 outside [0, y] and [y, 8]: y <=
    # 2.125 (2 + 0.25 / 2) and y >= 8 - 36.25 / 6 = 1.958; and q2: y >= 5.875 and y <= 6.04: no such y, so 2
    # points are needed, and the two-sided greedy from either end places 2 (from x = 0: 17/64 * 8 = 2.125 for
    # q1, then for q2 at (3.875, -0.5) from there 2.125 + 15.265625 / 3.875 = 6.0645). Regions 1 (below) and 2
    # (above).
    pts = [(0, 0), (8, 0), (8, 4), (8, 8), (0, 8), (0, 4), (2, 4.5), (6, 3.5)]
    segs = loop(6) + [(5, 2)]
    d = Domain(points=pts, segments=segs, regions=[(1, 1, 1.0), (1, 7, 2.0)])
    res = nonobtuse.refine(d)
    assert_refined(d, res)
    assert res.stats["steiner_points"] == 2 and res.stats["lower_bound"] == 2
    interface = [e for e in res.stats["edges"] if sorted(e["edge"]) == [2, 5]]
    assert len(interface) == 1 and interface[0]["steiner_points"] == 2
    steiner = res.mesh.points[len(pts) :]
    assert np.allclose(steiner[:, 1], 4.0, atol=1e-12)
    xs = np.sort(steiner[:, 0])
    # From (0, 4): 2.125, 6.0645; from (8, 4), by symmetry: 8 - 2.125 = 5.875, then 5.875 - 3.8952 = 1.9355.
    step = 15.265625 / 3.875
    assert np.allclose(xs, [2.125, 2.125 + step]) or np.allclose(xs, [5.875 - step, 5.875])
    # Before refining, the interface is obtuse on both sides; the outer boundary is fine.
    assert obtuse_constraint_sides(nonobtuse.triangulate(d)) == 2
    cv = control_volumes(res.mesh, conductivity={1.0: 1.0, 2.0: 1000.0})
    assert cv.m_matrix


def test_t_junction():
    # Square [0, 4]^2, interface y = 2 across it, and a stem x = 2 from the junction (2, 2) up to the top (2,
    # 4): three regions. q = (3, 1.8) lies in the horizontal interface's right half's disk (center (3, 2), r
    # 1, distance 0.2) and in no other (bottom (3, 0) r 1: 1.8; right side (4, 1) r 1: 1.28; left half (1, 2):
    # 2.01). From (2, 2): t = 1.04 / 2 -> x = 3.04; from (4, 2): x = 4 - 1.04 = 2.96; either point leaves q
    # outside both halves (its foot x = 3 is inside [2.96, 3.04] and q is below), so 1 point, the lower bound.
    pts = [(0, 0), (4, 0), (4, 2), (4, 4), (2, 4), (0, 4), (0, 2), (2, 2), (3, 1.8)]
    segs = loop(7) + [(6, 7), (7, 2), (7, 4)]
    d = Domain(points=pts, segments=segs, regions=[(1, 1, 1.0), (1, 3, 2.0), (3, 3, 3.0)])
    res = nonobtuse.refine(d)
    assert_refined(d, res)
    assert res.stats["steiner_points"] == 1 and res.stats["lower_bound"] == 1
    x, y = res.mesh.points[len(pts)]
    assert y == 2.0 and 2.96 <= x <= 3.04
    assert control_volumes(res.mesh, conductivity={1.0: 1.0, 2.0: 5.0, 3.0: 0.01}).m_matrix


def test_cross_without_violation_needs_nothing():
    # Square [0, 4]^2 cut by x = 2 and y = 2 into four 2 x 2 cells, each split into two right isosceles
    # triangles: the angles opposite the constraints are 45 degrees (the right angle is opposite the
    # diagonal), so nothing is obtuse and nothing is added (lower bound 0).
    pts = [(0, 0), (2, 0), (4, 0), (4, 2), (4, 4), (2, 4), (0, 4), (0, 2), (2, 2)]
    segs = loop(8) + [(8, 1), (8, 3), (8, 5), (8, 7)]
    d = Domain(points=pts, segments=segs)
    res = nonobtuse.refine(d)
    assert_refined(d, res)
    assert res.stats["steiner_points"] == 0 and res.stats["lower_bound"] == 0


def test_cross_with_encroached_arms():
    # The cross above with q = (3, 1.8) and q' = (1.8, 3): q encroaches the right arm (2, 2)-(4, 2) from
    # below, q' the upper arm (2, 2)-(2, 4) from the left (the same computation as the T-junction by symmetry:
    # one point each, at 2.96 .. 3.04 along its arm). They meet at a right angle (not acute: no shells).
    pts = [(0, 0), (2, 0), (4, 0), (4, 2), (4, 4), (2, 4), (0, 4), (0, 2), (2, 2), (3, 1.8), (1.8, 3)]
    segs = loop(8) + [(8, 1), (8, 3), (8, 5), (8, 7)]
    d = Domain(points=pts, segments=segs)
    res = nonobtuse.refine(d)
    assert_refined(d, res)
    assert res.stats["steiner_points"] == 2 and res.stats["lower_bound"] == 2
    s = res.mesh.points[len(pts) :]
    on_right = s[np.isclose(s[:, 1], 2.0)]
    on_up = s[np.isclose(s[:, 0], 2.0)]
    assert len(on_right) == 1 and 2.96 <= on_right[0, 0] <= 3.04
    assert len(on_up) == 1 and 2.96 <= on_up[0, 1] <= 3.04


def test_dangling_well_segment_both_sides():
    # A well (2, 1)-(2, 3), both ends free, inside a 16-gon of radius 10 around (2, 2) (no boundary disk
    # reaches the points below). q1 = (1.8, 2.5) left of it and q2 = (2.3, 1.6) right of it are inside its
    # disk (center (2, 2), r 1; distances 0.54, 0.5). One point y would need y in [2.42, 2.5267] for q1 (from
    # each end: 3 - 0.29 * 2 and 1 + 2.29 / 3 * 2) and in [1.536, 1.75] for q2: disjoint, so 2 points (lower
    # bound 2); the two-sided greedy from (2, 1) places 1.75 (t = 0.45 / 1.2 = 3/8) then 1.75 + 0.6025 /
    # 0.9375 * 1.25 = 2.5533; from (2, 3): 2.42 then 1.490.
    ring = polygon(16, 10.0, center=(2.0, 2.0))
    pts = np.r_[ring, [(2, 1), (2, 3), (1.8, 2.5), (2.3, 1.6)]]
    segs = loop(16) + [(16, 17)]
    d = Domain(points=pts, segments=segs)
    res = nonobtuse.refine(d)
    assert_refined(d, res)
    assert res.stats["steiner_points"] == 2 and res.stats["lower_bound"] == 2
    s = res.mesh.points[len(pts) :]
    assert np.allclose(s[:, 0], 2.0, atol=1e-12)
    ys = np.sort(s[:, 1])
    assert 1.49 <= ys[0] <= 1.75 and 2.42 <= ys[1] <= 2.5534
    # The well borders one region on both sides: each side is checked on its own.
    assert obtuse_constraint_sides(nonobtuse.triangulate(d)) == 2


def test_lower_bound_counts_only_vertices_the_edge_sees():
    # A dangling segment E = (17, 14)-(14, 3) in the box [0, 20]^2: its disk has center (15.5, 8.5) and
    # r^2 = 130 / 4 = 32.5. Inside: q = (10, 8) only (5.5^2 + 0.5^2 = 30.5; every other vertex is farther:
    # (9, 14) 72.5, (20, 0) 92.5). q is hidden from E by the dangling segment (9, 14)-(12, 4): the sight
    # line from q through its end (12, 4) is y = 8 - 2 (x - 10), which meets x = 14 at y = 0, below E's
    # lowest point (14, 3), so every sight line from E to q crosses it. Its free end (12, 4) lies on E's
    # circle (3.5^2 + 4.5^2 = 32.5): not inside, but a walk inside the closed disk wraps around it to q. No
    # subsegment of E sees a vertex inside its disk, so E's bound is 0 (a walk-based count gave 1).
    pts = [(0, 0), (20, 0), (20, 20), (0, 20), (17, 14), (14, 3), (9, 14), (12, 4), (10, 8)]
    d = Domain(points=np.array(pts, dtype=float), segments=loop(4) + [(4, 5), (6, 7)])
    res = nonobtuse.refine(d)
    assert_refined(d, res)
    bound = {tuple(e["edge"]): e["lower_bound"] for e in res.stats["edges"]}
    assert bound[(4, 5)] == 0
    assert all(e["steiner_points"] >= e["lower_bound"] for e in res.stats["edges"])


def test_acute_junction_of_ten_degrees_terminates_with_the_junction_diagnosed():
    # Two interfaces leave v = (0, 0) at 0 and 10 degrees (length 6), inside a 16-gon of radius 10; points in
    # the wedge near v (angles 2.9 .. 7 degrees, radii 1 .. 3) encroach both constraints, so each split on one
    # can encroach the other: the ping-pong that the concentric shells stop. The junction at v must draw the
    # most Steiner points, its angle reported as 10 degrees.
    ring = polygon(16, 10.0)
    c, s = math.cos(math.radians(10)), math.sin(math.radians(10))
    inner = [(0.0, 0.0), (6.0, 0.0), (6 * c, 6 * s), (2.0, 0.1), (3.0, 0.3), (1.0, 0.1), (2.5, 0.25)]
    pts = np.r_[ring, inner]
    v = 16
    d = Domain(points=pts, segments=loop(16) + [(v, v + 1), (v, v + 2)])
    res = nonobtuse.refine(d)
    assert_refined(d, res)
    junction = res.stats["diagnosis"]["junctions"][0]
    assert junction["vertex"] == v and junction["constraints"] == 2
    assert junction["min_angle_degrees"] == pytest.approx(10.0)
    angle = res.stats["diagnosis"]["angles"][0]
    assert angle["vertex"] == v and angle["degrees"] == pytest.approx(10.0)
    # Concentric shells: from v the greedy end on the 0 degree arm is at |q|^2 / (q . d) = 1.01 / 1 for q =
    # (1, 0.1) (the nearest blocker), on the 10 degree arm at 1.01 / (cos 10 + 0.1 sin 10) = 1.0078; the shell
    # rule rounds both down to 2^0 = 1 (then rounded to a double point on the line, within ulps). The Steiner
    # point nearest v on each arm is therefore at distance 1 from v, where the plain greedy would put 1.01 and
    # 1.0078.
    steiner = res.mesh.points[len(pts) :]
    r = np.hypot(*steiner.T)
    on_x_axis = steiner[:, 1] == 0
    assert on_x_axis.any() and (~on_x_axis).any()
    assert np.min(r[on_x_axis]) == pytest.approx(1.0, rel=1e-15)
    assert np.min(r[~on_x_axis]) == pytest.approx(1.0, rel=1e-15)


def test_budget_exhausted_is_a_status_on_an_interface():
    # The rectangle case needs 2 points; with a budget of 1 it stops with the partial mesh.
    pts = [(0, 0), (8, 0), (8, 4), (8, 8), (0, 8), (0, 4), (2, 4.5), (6, 3.5)]
    d = Domain(points=pts, segments=loop(6) + [(5, 2)])
    res = nonobtuse.refine(d, max_steiner=1)
    assert res.status == "budget_exhausted" and res.stats["steiner_points"] == 1
    assert res.stats["obtuse_boundary_sides"] == obtuse_constraint_sides(res.mesh) > 0


def test_propagation_is_diagnosed_along_a_chain():
    # The Figure 6 family (experiments/figure6_propagation.py) with 12 layers: one initial violation (the
    # 120 degree triangle at p under e_1), whose repair must put a Steiner point on every layer (the forced
    # intervals, tests/test_figure6.py), so on at least the 2 input edges e_1 and e_2.
    import sys

    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "experiments"))
    from figure6_propagation import figure6

    d = figure6(12)
    res = nonobtuse.refine(d)
    assert_refined(d, res)
    g = res.stats["diagnosis"]
    assert g["initial_violations"] == 1
    assert g["propagation_depth"] >= 2 and g["propagation_splits"] == res.stats["steiner_points"]


# ---- random multi-region PSLGs ----


@st.composite
def layered_pslgs(draw):
    """A box [0, 100] x [0, 20 L] with L - 1 non-crossing interface polylines (layer k near y = 20 k, vertices
    at random x with y within +-6 of it, integers), isolated integer points, a region seed per layer with
    attribute k, and optionally a dangling segment inside the bottom layer."""
    layers = draw(st.integers(2, 4))
    # Counter-clockwise: along the bottom, up the right side (a vertex per interface), back along the top,
    # down the left side.
    pts = [(0, 0)] + [(100, 20 * k) for k in range(layers + 1)] + [(0, 20 * k) for k in range(layers, 0, -1)]
    n_boundary = len(pts)
    segs = loop(n_boundary)
    index = {p: i for i, p in enumerate(pts)}
    for k in range(1, layers):
        xs = sorted(draw(st.sets(st.integers(5, 95), min_size=0, max_size=4)))
        chain = [index[(0, 20 * k)]]
        for x in xs:
            pts.append((x, 20 * k + draw(st.integers(-6, 6))))
            chain.append(len(pts) - 1)
        chain.append(index[(100, 20 * k)])
        segs += list(zip(chain[:-1], chain[1:]))
    for _ in range(draw(st.integers(0, 6))):
        k = draw(st.integers(0, layers - 1))
        p = (draw(st.integers(3, 97)), 20 * k + draw(st.sampled_from([8, 9, 10, 11, 12])))
        if p not in pts:
            pts.append(p)
    if draw(st.booleans()):
        x = draw(st.integers(10, 80))
        pts += [(x, 9), (x + draw(st.integers(3, 15)), 10 + draw(st.integers(-1, 1)))]
        segs.append((len(pts) - 2, len(pts) - 1))
    regions = [(99, 20 * k + 10, float(k)) for k in range(layers)]
    return Domain(points=np.array(pts, dtype=float), segments=segs, regions=regions)


@settings(derandomize=True, deadline=None, max_examples=40)
@given(layered_pslgs())
def test_random_layered_pslgs_refine_and_verify(domain):
    try:
        d = validate_domain(domain)
    except InvalidInputError:
        return  # a drawn isolated point on an interface or the well: not a valid domain
    res = nonobtuse.refine(d)
    assert_refined(d, res)
    attributes = sorted(set(np.asarray(d.regions)[:, 2].tolist()) | set(np.unique(res.mesh.regions).tolist()))
    k = {a: 10.0 ** (i % 3 - 1) for i, a in enumerate(attributes)}  # 0.1, 1, 10: contrasts across interfaces
    assert control_volumes(res.mesh, conductivity=k).m_matrix


@st.composite
def fans(draw):
    """k = 2..6 interfaces of length 3..7 from the center of a 16-gon of radius 10 at random whole-degree
    angles (acute junctions down to 1 degree), with up to 11 isolated points on a 0.1 grid within 6 of the
    center."""
    k = draw(st.integers(2, 6))
    # Angles on a 1 degree grid, distinct: junction angles of 1 degree and up (near-coincident arms, 1e-6
    # degree apart, make the two arms mirror each other's points at ulp scale; that is a stress test, not a
    # property).
    degrees = sorted(draw(st.sets(st.integers(0, 359), min_size=k, max_size=k)))
    angles = [math.radians(a) for a in degrees]
    lengths = draw(st.lists(st.integers(30, 70).map(lambda i: i / 10), min_size=k, max_size=k))
    # On a 0.1 grid: the refinement works in doubles, so features far below the coordinates' size (a point
    # 1e-200 from a vertex, which hypothesis finds) end as status "stalled", as documented, not as a test
    # case.
    grid = st.integers(-42, 42).map(lambda i: i / 10)
    inner = draw(st.lists(st.tuples(grid, grid), max_size=11))
    arms = [(r * math.cos(a), r * math.sin(a)) for a, r in zip(angles, lengths)]
    pts = np.r_[polygon(16, 10.0), [(0.0, 0.0)], arms, np.reshape(inner, (-1, 2))]
    return Domain(points=pts, segments=loop(16) + [(16, 17 + i) for i in range(k)])


@settings(derandomize=True, deadline=None, max_examples=40)
@given(fans())
def test_random_fans_with_acute_junctions_refine_and_verify(domain):
    try:
        d = validate_domain(domain)
    except InvalidInputError:
        return  # two arms on one ray, a point on an arm, duplicate points: not a valid domain
    res = nonobtuse.refine(d)
    assert_refined(d, res)


# ---- the corpus ----


def corpus_domain(name: str) -> Domain:
    """Read a corpus file the way the pins were recorded (see pslg_corpus.json's _comment)."""
    path = SHARED / name
    how = PINS[name]["load"]
    if how == "convex_hull":
        return load_domain(path, convex_hull=True)
    if how == "drop_degenerate_segments":
        raw = read_poly(path)
        seg = raw.segments[raw.segments[:, 0] != raw.segments[:, 1]]
        seg = np.unique(np.sort(seg, axis=1), axis=0)
        return validate_domain(Domain(points=raw.points, segments=seg, holes=raw.holes, regions=raw.regions))
    return load_domain(path)


@pytest.mark.parametrize("name", sorted(PINS))
def test_corpus_file(name):
    if not (SHARED / name).exists():
        pytest.skip("../shared/data not present")
    d = corpus_domain(name)
    res = nonobtuse.refine(d)
    assert_refined(d, res)
    pin = PINS[name]
    assert (res.stats["steiner_points"], res.stats["lower_bound"]) == (pin["greedy"], pin["lower_bound"])
    attributes = np.unique(res.mesh.regions if res.mesh.regions is not None else [0.0]).tolist()
    k = {a: 1.0 + 9.0 * (i % 2) for i, a in enumerate(attributes)}  # alternating 1 and 10 between regions
    assert control_volumes(res.mesh, conductivity=k).m_matrix


def test_every_input_of_the_2d_corpus_is_pinned():
    folder = SHARED / "2d"
    if not folder.exists():
        pytest.skip("../shared/data not present")
    assert {f"2d/{p.name}" for p in folder.iterdir() if p.suffix in (".poly", ".node")} <= set(PINS)


def test_cgshop_exterior_totals_beat_best_known():
    # Issue 4's target on simple-polygon-exterior(-20): below the best known all-triangle counts of
    # best_known.csv (every triangle nonobtuse there, a stronger requirement than ours, so ours should be
    # lower).
    import csv

    best_file = SHARED / "cgshop25" / "best_known.csv"
    if not best_file.exists():
        pytest.skip("../shared/data not present")
    with best_file.open() as fh:
        best = {r["instance_uid"]: int(r["best_known_steiner"]) for r in csv.DictReader(fh)}
    ours = {n: p["greedy"] for n, p in PINS.items() if "simple-polygon-exterior" in n}
    assert len(ours) == 52
    assert sum(ours.values()) < sum(best[Path(n).name.split(".")[0]] for n in ours)


def test_cgshop_exterior_total_is_at_most_a_quarter_of_triangle_pd():
    # Issue 4's other target on the same 52 instances: at most a quarter of Triangle -pD's Steiner points
    # (Triangle splits every encroached subsegment at its midpoint, on both sides, exterior included).
    triangle = pytest.importorskip("triangle")
    names = [n for n in PINS if "simple-polygon-exterior" in n]
    if not (SHARED / names[0]).exists():
        pytest.skip("../shared/data not present")
    total = 0
    for n in names:
        d = corpus_domain(n)
        out = triangle.triangulate({"vertices": d.points, "segments": d.segments}, "pDQ")
        total += len(out["vertices"]) - len(d.points)
    assert 4 * sum(PINS[n]["greedy"] for n in names) <= total
