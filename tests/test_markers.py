"""Boundary markers and region attributes through validation, triangulation and refinement, checked against
an exact geometric oracle (which input segment holds each subsegment) and against the ``triangle`` package's
own output on the same input."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import nonobtuse
from nonobtuse import Domain
from nonobtuse.errors import InvalidInputError
from nonobtuse.io import load_domain
from nonobtuse.markers import segment_parents

SHARED = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "2d"


def shared(name: str) -> Path:
    path = SHARED / name
    if not path.is_file():
        pytest.skip(f"{path} not present (../shared/data is the shared corpus)")
    return path


def distance_to_segments(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distances (k,) from the point p (2,) to the segments a-b (k, 2 each)."""
    d = b - a
    t = np.clip(np.einsum("ij,ij->i", p - a, d) / np.einsum("ij,ij->i", d, d), 0, 1)
    return np.linalg.norm(a + t[:, None] * d - p, axis=1)


def oracle_parents(mesh) -> list[int]:
    """For every output segment, the input segment holding both its ends: a Steiner point is on its input
    segment up to a few ulps (see nonobtuse.refine), so this is a float test with a margin of 1e-12 of the
    domain's size, which is far below the distance to any other input segment. -1 for none."""
    a, b = mesh.input_points[mesh.input_segments[:, 0]], mesh.input_points[mesh.input_segments[:, 1]]
    scale = float(np.ptp(mesh.input_points, axis=0).max())
    out = []
    for u, v in mesh.segments:
        far = np.maximum(*(distance_to_segments(mesh.points[w], a, b) for w in (u, v)))
        holders = np.flatnonzero(far <= 1e-12 * scale)
        assert len(holders) <= 1
        out.append(int(holders[0]) if len(holders) else -1)
    return out


def boundary_edges(mesh) -> set[tuple[int, int]]:
    count: dict[tuple[int, int], int] = {}
    for t in mesh.triangles.tolist():
        for i in range(3):
            e = tuple(sorted((t[i], t[(i + 1) % 3])))
            count[e] = count.get(e, 0) + 1
    return {e for e, c in count.items() if c == 1}


def expected_segment_markers(mesh, input_markers) -> list[int]:
    """Triangle's rule, from the oracle: the parent's nonzero marker, else 1 on the boundary, else 0."""
    boundary = boundary_edges(mesh)
    out = []
    for (a, b), s in zip(mesh.segments.tolist(), oracle_parents(mesh)):
        inherited = int(input_markers[s]) if s >= 0 else 0
        out.append(inherited if inherited else int(tuple(sorted((a, b))) in boundary))
    return out


def test_la_markers_survive_refinement():
    domain = load_domain(shared("la.poly"))
    assert {101, 102, 103} <= set(domain.segment_markers.tolist())
    result = nonobtuse.refine(domain)
    mesh = result.mesh
    assert result.converged and mesh.steiner_points > 0
    assert mesh.segment_markers.tolist() == expected_segment_markers(mesh, domain.segment_markers)
    assert {101, 102, 103} <= set(mesh.segment_markers.tolist())
    # A Steiner point takes the marker of the input segment it lies on (all of la.poly's are nonzero there).
    parents = oracle_parents(mesh)
    n0 = len(mesh.input_points)
    for (a, b), s in zip(mesh.segments.tolist(), parents):
        for v in (a, b):
            if v >= n0:
                assert mesh.point_markers[v] == (domain.segment_markers[s] or 1)
    # Input points keep their own nonzero markers.
    own = np.flatnonzero(domain.point_markers)
    assert np.array_equal(mesh.point_markers[own], domain.point_markers[own])


def triangle_input(domain: Domain) -> dict:
    d = {"vertices": domain.points}
    if len(domain.segments):
        d["segments"] = domain.segments
    if domain.point_markers is not None:
        d["vertex_markers"] = domain.point_markers.reshape(-1, 1)
    if domain.segment_markers is not None:
        d["segment_markers"] = domain.segment_markers.reshape(-1, 1)
    if len(domain.holes):
        d["holes"] = domain.holes
    if len(domain.regions):
        d["regions"] = np.column_stack([domain.regions, np.zeros(len(domain.regions))])
    return d


def segment_table(d: dict) -> dict[tuple[int, int], int]:
    return {tuple(sorted(s)): int(m) for s, m in zip(d["segments"].tolist(), d["segment_markers"].ravel())}


@pytest.mark.parametrize("name", ["la.poly", "face.poly", "spiral.node", "clusters.poly", "A.poly"])
def test_triangulate_dict_matches_the_triangle_package(name):
    triangle = pytest.importorskip("triangle")
    domain = load_domain(shared(name))
    given_dict = triangle_input(domain)
    ours = nonobtuse.triangulate(given_dict)
    switches = "pc" if domain.convex_hull else "p" + "A" * bool(len(domain.regions))
    theirs = triangle.triangulate(given_dict, switches)
    assert set(ours) == set(theirs)
    for key in ours:
        assert ours[key].dtype == theirs[key].dtype and ours[key].shape == theirs[key].shape, key
    assert np.array_equal(ours["vertices"], theirs["vertices"])
    assert np.array_equal(ours["vertex_markers"], theirs["vertex_markers"])
    assert segment_table(ours) == segment_table(theirs)
    if "triangle_attributes" in theirs:  # the same attribute on the triangle with the same corners
        assert attributes_by_corners(ours) == attributes_by_corners(theirs)


def attributes_by_corners(d: dict) -> list:
    return sorted(zip(map(tuple, np.sort(d["triangles"], axis=1).tolist()), d["triangle_attributes"].ravel()))


def test_refine_dict_returns_the_triangle_convention_and_check_reads_it():
    triangle = pytest.importorskip("triangle")
    domain = load_domain(shared("la.poly"))
    given_dict = triangle_input(domain)
    out = nonobtuse.refine(given_dict)
    assert out["stats"]["status"] == "converged"
    assert nonobtuse.check(out).ok
    assert not nonobtuse.check(triangle.triangulate(given_dict, "pA")).ok  # the plain CDT is not
    assert not nonobtuse.check(given_dict).ok  # a domain dict: its CDT is checked
    assert out["segment_markers"].dtype == np.int32 and out["triangle_attributes"].shape == (
        len(out["triangles"]), 1)  # fmt: skip
    n0 = len(domain.points)
    assert np.array_equal(out["vertices"][:n0], domain.points)


def test_dict_errors_name_the_key():
    with pytest.raises(InvalidInputError, match="'vertices' is missing"):
        nonobtuse.triangulate({"segments": [[0, 1]]})
    with pytest.raises(InvalidInputError, match=r"unknown key\(s\) \['segment'\]"):
        nonobtuse.refine({"vertices": [[0, 0], [1, 0], [0, 1]], "segment": [[0, 1]]})
    with pytest.raises(InvalidInputError, match="segment_markers must be 2 integers"):
        nonobtuse.triangulate({"vertices": [[0, 0], [1, 0], [0, 1]], "segments": [[0, 1], [1, 2]],
                               "segment_markers": [[1]]})  # fmt: skip
    with pytest.raises(InvalidInputError, match="'triangles' refers to a vertex"):
        nonobtuse.check({"vertices": [[0, 0], [1, 0], [0, 1]], "triangles": [[0, 1, 3]]})


def test_validation_splits_keep_the_marker():
    # Point 4 lies inside segment 0 (marker 7): both pieces keep 7; point 4 gets 7 too.
    d = Domain([[0, 0], [2, 0], [2, 2], [0, 2], [1, 0]], [[0, 1], [1, 2], [2, 3], [3, 0]],
               segment_markers=[7, 0, 5, 0])  # fmt: skip
    mesh = nonobtuse.triangulate(d)
    table = dict(zip(map(tuple, np.sort(mesh.segments, axis=1).tolist()), mesh.segment_markers.tolist()))
    assert table[(0, 4)] == table[(1, 4)] == 7 and table[(2, 3)] == 5 and table[(1, 2)] == table[(0, 3)] == 1
    assert mesh.point_markers.tolist() == [7, 7, 5, 5, 7]


def test_an_interface_without_marker_is_0_and_the_hull_of_a_point_set_is_1():
    # Two squares sharing the interface 1-4; no markers given.
    d = Domain([[0, 0], [1, 0], [2, 0], [2, 1], [1, 1], [0, 1], [0.5, 0.5]],
               [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [1, 4]])  # fmt: skip
    mesh = nonobtuse.triangulate(d)
    table = dict(zip(map(tuple, np.sort(mesh.segments, axis=1).tolist()), mesh.segment_markers.tolist()))
    assert table.pop((1, 4)) == 0 and set(table.values()) == {1}
    assert mesh.point_markers.tolist() == [1, 1, 1, 1, 1, 1, 0]
    hull = nonobtuse.triangulate({"vertices": [[0, 0], [1, 0], [0, 1], [0.25, 0.25]]})
    assert hull["segment_markers"].ravel().tolist() == [1, 1, 1]
    assert hull["vertex_markers"].ravel().tolist() == [1, 1, 1, 0]


def test_segment_parents_refuses_a_steiner_point_on_one_subsegment():
    with pytest.raises(nonobtuse.InternalError, match="not on exactly two subsegments"):
        segment_parents(np.array([[0, 2], [2, 1], [1, 3]]), 2, np.array([[0, 1]]))


@settings(max_examples=25, deadline=10_000, derandomize=True)
@given(
    n=st.integers(min_value=3, max_value=12),
    markers=st.lists(st.integers(min_value=-3, max_value=3), min_size=12, max_size=12),
    strategy=st.sampled_from(["greedy", "project-flip"]),
)
def test_refined_markers_follow_the_oracle_on_star_polygons(n, markers, strategy):
    # A star-shaped polygon with alternate radii has obtuse boundary angles, so refinement adds points.
    k = np.arange(2 * n)
    r = np.where(k % 2 == 0, 1.0, 0.45)
    points = np.column_stack([r * np.cos(np.pi * k / n), r * np.sin(np.pi * k / n)])
    segments = np.column_stack([k, (k + 1) % (2 * n)])
    seg_markers = np.array((markers * 2)[: 2 * n])
    domain = load_domain_like(points, segments, seg_markers)
    mesh = nonobtuse.refine(domain, strategy=strategy).mesh
    assert mesh.segment_markers.tolist() == expected_segment_markers(mesh, seg_markers)


def load_domain_like(points, segments, segment_markers) -> Domain:
    from nonobtuse.validate import validate_domain

    return validate_domain(Domain(points, segments, segment_markers=segment_markers))
