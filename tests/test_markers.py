"""Boundary markers and region attributes through validation, triangulation and refinement, checked against
an exact geometric oracle (which input segment holds each subsegment) and against the ``triangle`` package's
own output on the same input."""

from __future__ import annotations

import functools
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
    # A duplicate of a piece (4-1, marker 9) is dropped: the first segment's marker stays.
    d = Domain(d.points, np.r_[d.segments, [[4, 1]]], segment_markers=[7, 0, 5, 0, 9])
    mesh = nonobtuse.triangulate(d)
    table = dict(zip(map(tuple, np.sort(mesh.segments, axis=1).tolist()), mesh.segment_markers.tolist()))
    assert len(mesh.segments) == 5 and table[(1, 4)] == 7


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


# ---- every format, with markers and regions -----------------------------------------------------------


@functools.lru_cache(maxsize=2)
def marked_mesh(float_regions: bool):
    """A refined mesh of a small domain with an interface, two regions, vertex and segment markers (shared:
    the tests only read it)."""
    d = Domain(
        [[0, 0], [3, 0], [3, 1], [0, 1], [1.5, 0], [1.5, 1], [0.1, 0.9]],
        [[0, 4], [4, 1], [1, 2], [2, 5], [5, 3], [3, 0], [4, 5]],
        regions=[[0.5, 0.5, 0.25 if float_regions else 2], [2.5, 0.5, 1 / 3 if float_regions else 7]],
        point_markers=[0, 0, 0, 0, 0, 0, 9],
        segment_markers=[11, 12, 13, 14, 15, 16, 0],
    )
    from nonobtuse.validate import validate_domain

    mesh = nonobtuse.refine(validate_domain(d)).mesh
    assert mesh.steiner_points > 0 and 0 in mesh.segment_markers and 9 in mesh.point_markers
    return mesh


def assert_same_markers(back, mesh) -> None:
    assert np.array_equal(back.points, mesh.points)
    assert np.array_equal(back.triangles, mesh.triangles) and np.array_equal(back.segments, mesh.segments)
    assert np.array_equal(back.regions, mesh.regions) and back.regions.dtype == np.float64
    assert np.array_equal(back.segment_markers, mesh.segment_markers)
    assert np.array_equal(back.point_markers, mesh.point_markers)
    assert back.segment_markers.dtype == back.point_markers.dtype == np.int64


@pytest.mark.parametrize("suffix", [".json", ".node", ".ele", ".poly", ".vtu", ".msh"])
@pytest.mark.parametrize("float_regions", [False, True])
def test_every_format_round_trips_markers_and_regions(tmp_path, suffix, float_regions):
    from nonobtuse.io import is_mesh_file, read_mesh, write_mesh

    mesh = marked_mesh(float_regions)
    path = tmp_path / f"m{suffix}"
    written = write_mesh(mesh, path)
    assert sorted(tmp_path.iterdir()) == sorted(written)
    assert is_mesh_file(path)
    assert_same_markers(read_mesh(path), mesh)


def test_msh_maps_float_regions_to_tags_and_writes_the_map(tmp_path):
    import json

    import meshio

    from nonobtuse.io import write_mesh

    mesh = marked_mesh(float_regions=True)
    written = write_mesh(mesh, tmp_path / "m.msh")
    assert [p.name for p in written] == ["m.msh", "m.msh.regions.json"]
    table = json.loads(written[1].read_text())["tag_to_region"]
    assert table == {"1": 0.25, "2": 1 / 3}
    raw = meshio.read(written[0])
    tags = raw.cell_data["gmsh:physical"]
    assert sorted(set(tags[0].tolist())) == [1, 2]  # triangles: region tags
    assert np.array_equal(tags[1], mesh.segment_markers)  # lines: segment markers
    back = nonobtuse.io.read_mesh(written[0])
    written[1].unlink()  # without the map the tags are the regions
    assert np.array_equal(nonobtuse.io.read_mesh(written[0]).regions, tags[0])
    assert set(back.regions.tolist()) == {0.25, 1 / 3}


def test_meshio_objects_round_trip():
    mesh = marked_mesh(float_regions=True)
    m = mesh.to_meshio()
    assert m.cells[0].type == "triangle" and m.cells[1].type == "line"
    assert np.array_equal(m.point_data["point_marker"], mesh.point_markers)
    assert_same_markers(nonobtuse.Mesh.from_meshio(m), mesh)


def test_from_meshio_reads_gmsh_physical_tags():
    import meshio

    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]])
    physical = [np.array([4]), np.array([8, 9])]
    m = meshio.Mesh(points, [("triangle", [[0, 1, 2]]), ("line", [[0, 1], [1, 2]])],
                    cell_data={"gmsh:physical": physical})  # fmt: skip
    mesh = nonobtuse.Mesh.from_meshio(m)
    assert mesh.regions.tolist() == [4.0] and mesh.segment_markers.tolist() == [8, 9]
    assert mesh.point_markers is None
    with pytest.raises(InvalidInputError, match="not planar"):
        nonobtuse.Mesh.from_meshio(meshio.Mesh(points + [0, 0, 1], [("triangle", [[0, 1, 2]])]))


# Triangle's own output for a unit square split by its diagonal, 0-based ids as `triangle -pz` writes them,
# with comments and an attribute column.
NODE = "# square\n4 2 0 1\n0 0 0 1\n1 1 0 2\n2 1 1 1\n3 0 1 0\n"
ELE = "2 3 1\n0 0 1 2 5.5\n1 0 2 3 -1  # second\n"
POLY = "0 2 0 1\n4 1\n0 0 1 7\n1 1 2 8\n2 2 3 9\n3 3 0 9\n0\n"


def test_triangle_output_is_read_as_a_mesh_not_retriangulated(tmp_path):
    from nonobtuse.io import is_mesh_file, load_domain, read_mesh

    (tmp_path / "sq.1.node").write_text(NODE)
    (tmp_path / "sq.1.ele").write_text(ELE)
    for name in ("sq.1.ele", "sq.1.node"):
        assert is_mesh_file(tmp_path / name)
        mesh = read_mesh(tmp_path / name)
        assert mesh.triangles.tolist() == [[0, 1, 2], [0, 2, 3]] and mesh.regions.tolist() == [5.5, -1.0]
        assert mesh.point_markers.tolist() == [1, 2, 1, 0]
        # no .poly: the segments are the edges with one triangle, without markers
        assert mesh.segments.tolist() == [[0, 1], [0, 3], [1, 2], [2, 3]] and mesh.segment_markers is None
    (tmp_path / "sq.1.poly").write_text(POLY)
    mesh = read_mesh(tmp_path / "sq.1.poly")
    assert mesh.segments.tolist() == [[0, 1], [1, 2], [2, 3], [3, 0]]
    assert mesh.segment_markers.tolist() == [7, 8, 9, 9]
    assert len(load_domain(tmp_path / "sq.1.node").points) == 4  # asked for a domain: the point set
    (tmp_path / "lone.node").write_text(NODE)
    assert not is_mesh_file(tmp_path / "lone.node")
    with pytest.raises(InvalidInputError, match="needs lone.ele beside it"):
        read_mesh(tmp_path / "lone.node")


@pytest.mark.parametrize(
    ("ele", "message"),
    [
        ("2 6 0\n", "only 3-node triangles"),
        ("1 3 0\n0 0 1 4\n", "triangle corner 4 does not exist"),
        ("1 3 1\n0 0 1 2 x\n", "the triangle attribute must be a number"),
        ("2 3 0\n0 0 1 2\n", "ends early"),
    ],
)
def test_bad_ele_files_name_the_line(tmp_path, ele, message):
    from nonobtuse.io import read_mesh

    (tmp_path / "a.node").write_text(NODE)
    (tmp_path / "a.ele").write_text(ele)
    with pytest.raises(InvalidInputError, match=message) as e:
        read_mesh(tmp_path / "a.ele")
    assert "a.ele:" in str(e.value)


def test_json_domain_markers_are_read(tmp_path):
    import json

    path = tmp_path / "d.json"
    path.write_text(json.dumps({"points": [[0, 0], [1, 0], [0, 1]], "segments": [[0, 1], [1, 2], [2, 0]],
                                "point_markers": [1, 2, 3], "segment_markers": [4, 5, 6]}))  # fmt: skip
    d = load_domain(path)
    assert d.point_markers.tolist() == [1, 2, 3] and d.segment_markers.tolist() == [4, 5, 6]
    path.write_text(json.dumps({"points": [[0, 0], [1, 0], [0, 1]], "segment_markers": [4]}))
    with pytest.raises(InvalidInputError, match="1 segment_markers for 0 segments"):
        load_domain(path)


def test_cli_refine_writes_markers_and_check_reads_triangle_files(tmp_path, capsys):
    from nonobtuse.cli import main
    from nonobtuse.io import read_mesh

    out = tmp_path / "la.1.poly"
    assert main(["refine", str(shared("la.poly")), "-o", str(out)]) == 0
    mesh = read_mesh(tmp_path / "la.1.ele")
    assert {101, 102, 103} <= set(mesh.segment_markers.tolist()) and mesh.regions is not None
    capsys.readouterr()
    assert main(["check", str(tmp_path / "la.1.node")]) == 0  # the refined triangles, not a new CDT
    assert f"{len(mesh.triangles)} triangles" in capsys.readouterr().out


BIG = 2**40


@settings(max_examples=20, deadline=10_000, derandomize=True)
@given(
    suffix=st.sampled_from([".json", ".ele", ".vtu", ".msh"]),
    seed=st.integers(min_value=0, max_value=2**32 - 1),
    wide=st.booleans(),
)
def test_any_markers_and_regions_round_trip(suffix, seed, wide):
    import dataclasses
    import tempfile

    from nonobtuse.io import read_mesh, write_mesh

    base = marked_mesh(float_regions=True)
    rng = np.random.default_rng(seed)
    limit = BIG if wide else 2**31 - 1
    mesh = dataclasses.replace(
        base,
        point_markers=rng.integers(-limit, limit, len(base.points)),
        segment_markers=rng.integers(-limit, limit, len(base.segments)),
        regions=rng.choice([-1e300, -0.1, 0.0, 1 / 3, 7.0, 2.5e9, 1e-300], len(base.triangles)),
    )
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / f"m{suffix}"
        if suffix == ".msh" and wide:  # Gmsh tags are 32-bit: refused, never wrapped around
            with pytest.raises(InvalidInputError, match="does not fit in 32 bits"):
                write_mesh(mesh, path)
            return
        write_mesh(mesh, path)
        assert_same_markers(read_mesh(path), mesh)
