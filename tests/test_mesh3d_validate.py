"""Every kind of invalid 3D input gives an InvalidInputError naming the problem and where."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from mesh3d_shapes import (
    CUBE_POINTS,
    CUBE_TRIANGLES,
    TET_POINTS,
    TET_TRIANGLES,
    two_tets_touching_at_a_vertex,
    write_off,
)
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d import PLC, load_plc, validate_plc
from nonobtuse.mesh3d.validate3d import edge_faces, reversed_faces, unique_rows


def load_off(tmp_path, points, faces, **kw):
    path = write_off(tmp_path / "x.off", np.asarray(points, dtype=float), np.asarray(faces).tolist())
    return load_plc(path, **kw)


def test_empty_file(tmp_path):
    (tmp_path / "e.off").write_text("  \n")
    with pytest.raises(InvalidInputError, match="e.off: the file is empty"):
        load_plc(tmp_path / "e.off")


def test_no_faces(tmp_path):
    with pytest.raises(InvalidInputError, match="no facet"):
        load_off(tmp_path, TET_POINTS, np.zeros((0, 3), dtype=int))


@pytest.mark.parametrize("name, content, message", [
    ("w.off", "PLY\n3 1 0\n", "not an OFF file"),
    ("w.off", "OFF\n1 0 0\n0 zero 0\n", "w.off:3: vertex 0 must be a number, found 'zero'"),
    ("w.stl", "hello world, this is not an STL file" * 3, "not an STL file"),
    ("w.ply", "OFF\n", "not a PLY file"),
    ("w.xyz", "1 2 3\n", "unknown 3D format"),
    ("w.off", b"\xff\xfe\x00OFF", "w.off: cannot read the file"),
])
def test_wrong_format(tmp_path, name, content, message):
    path = tmp_path / name
    path.write_bytes(content if isinstance(content, bytes) else content.encode())
    with pytest.raises(InvalidInputError, match=message):
        load_plc(path)


def test_truncated_file_names_what_is_missing(tmp_path):
    (tmp_path / "t.off").write_text("OFF\n4 4 0\n0 0 0\n1 0 0\n")
    with pytest.raises(InvalidInputError, match="t.off:4: the file ends early: expected vertex 2"):
        load_plc(tmp_path / "t.off")


def test_face_index_out_of_range(tmp_path):
    with pytest.raises(InvalidInputError, match="refers to vertex 9, but there are 4 vertices"):
        load_off(tmp_path, TET_POINTS, [[0, 1, 9], [0, 1, 2], [1, 2, 3], [0, 2, 3]])


@pytest.mark.parametrize("bad", [np.nan, np.inf])
def test_nan_and_inf(tmp_path, bad):
    pts = TET_POINTS.copy()
    pts[2, 1] = bad
    with pytest.raises(InvalidInputError, match="vertex 2 has a NaN or infinite coordinate"):
        load_off(tmp_path, pts, TET_TRIANGLES)


def test_not_closed_names_a_boundary_edge(tmp_path):
    # the tet without its face (1, 2, 3): the three edges of that face are boundary edges, and every face
    # peels off as dangling, so nothing encloses a volume
    with pytest.raises(InvalidInputError, match=r"not closed: 3 boundary edges, e\.g\. edge \(1, 2\).*"
                                                r"no part of it encloses a volume"):
        load_off(tmp_path, TET_POINTS, TET_TRIANGLES[:3])


def test_a_dangling_fin_is_kept_with_a_warning(tmp_path):
    # a tet and a fin triangle hanging off its edge (0, 1), outside the tet: a dangling facet
    pts = np.concatenate([TET_POINTS, [[0.5, -1, -1]]])
    plc = load_off(tmp_path, pts, np.concatenate([TET_TRIANGLES, [[0, 1, 4]]]))
    assert len(plc.triangles) == 5
    assert [w for w in plc.warnings if w.startswith("1 dangling faces")]


def test_a_dangling_chain_peels_off_face_by_face(tmp_path):
    # a strip of two fins: only the outer one has an open edge at first; peeling it opens the inner one
    pts = np.concatenate([TET_POINTS, [[0.5, -1, -1], [1.5, -1, -1]]])
    plc = load_off(tmp_path, pts, np.concatenate([TET_TRIANGLES, [[0, 1, 4], [1, 5, 4]]]))
    assert [w for w in plc.warnings if w.startswith("2 dangling faces")]


def test_non_manifold_edge_is_accepted(tmp_path):
    # a tet plus a second tet (0, 1, 4, 5) hanging off its edge (0, 1): edge (0, 1) lies in 4 faces
    pts = np.concatenate([TET_POINTS, [[0.5, -1, -1], [0.5, -2, 1]]])
    second = np.array([[0, 1, 4], [0, 5, 1], [0, 4, 5], [1, 5, 4]])
    plc = load_off(tmp_path, pts, np.concatenate([TET_TRIANGLES, second]))
    ef = edge_faces(plc.triangles)
    assert ef.count.max() == 4 and plc.warnings == ()
    assert np.all(_component_volumes(plc) > 0)  # both tets outward


def test_non_manifold_vertex_is_accepted(tmp_path):
    pts, tris = two_tets_touching_at_a_vertex()
    plc = load_off(tmp_path, pts, tris)
    assert len(plc.triangles) == 8 and plc.warnings == ()


def _component_volumes(plc) -> np.ndarray:
    """Signed volume of every group of 4 consecutive faces (the tets of these tests)."""
    p = plc.points[plc.triangles]
    return np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).reshape(-1, 4).sum(axis=1) / 6


def test_inconsistent_orientation_is_reoriented_with_a_warning(tmp_path):
    tris = CUBE_TRIANGLES.copy()
    tris[3] = tris[3][::-1]
    fixed = load_off(tmp_path, CUBE_POINTS, tris)
    assert np.array_equal(fixed.triangles, CUBE_TRIANGLES)  # face 3 flipped back, the rest already outward
    assert len(fixed.warnings) == 1
    assert fixed.warnings[0].startswith("inconsistent orientation: 1 faces (e.g. face 3 ")


def test_an_inward_surface_is_made_outward_without_a_warning(tmp_path):
    fixed = load_off(tmp_path, CUBE_POINTS, CUBE_TRIANGLES[:, ::-1])
    assert np.array_equal(fixed.triangles, CUBE_TRIANGLES)  # every face reversed back
    assert fixed.warnings == ()


def test_poly_facets_are_oriented_without_a_warning(tmp_path):
    tris = CUBE_TRIANGLES.copy()
    tris[3] = tris[3][::-1]
    plc = validate_plc(PLC(CUBE_POINTS, tris, np.arange(12)), oriented_format=False)
    assert np.array_equal(plc.triangles, CUBE_TRIANGLES) and plc.warnings == ()


def test_degenerate_face_repeated_vertex(tmp_path):
    with pytest.raises(InvalidInputError, match=r"degenerate face 1 \[0, 0, 3\]: a repeated vertex"):
        load_off(tmp_path, TET_POINTS, [[0, 2, 1], [0, 0, 3], [0, 3, 2], [1, 2, 3]])


def test_degenerate_face_exactly_collinear(tmp_path):
    # a flat "tet": the apex (0.5, 0, 0) lies on edge (0, 1) exactly, so faces (0, 1, 3) etc. have zero area
    pts = TET_POINTS.copy()
    pts[3] = [0.5, 0, 0]
    with pytest.raises(InvalidInputError, match=r"degenerate face 1 \[0, 1, 3\]: its vertices are exactly "
                                                r"collinear"):
        load_off(tmp_path, pts, TET_TRIANGLES)


def test_nearly_collinear_face_is_not_degenerate(tmp_path):
    # apex 2^-30 off the line: exact arithmetic sees a (thin) triangle; the input is a valid, thin tet
    pts = TET_POINTS.copy()
    pts[3] = [0.5, 2.0**-30, 2.0**-30]
    assert len(load_off(tmp_path, pts, TET_TRIANGLES).triangles) == 4


def test_duplicate_face(tmp_path):
    tris = np.concatenate([TET_TRIANGLES, [[2, 1, 0]]])  # face 0 again, rotated and reversed
    with pytest.raises(InvalidInputError, match=r"duplicate face: faces 0 and 4"):
        load_off(tmp_path, TET_POINTS, tris)


def test_self_intersection_names_two_faces(tmp_path):
    # two tets; the second is the first shifted by (0.2, 0.2, 0.2): their surfaces cross
    pts = np.concatenate([TET_POINTS, TET_POINTS + 0.2])
    with pytest.raises(InvalidInputError, match=r"self-intersection: faces \d+ \[.*\] and \d+ \[.*\] "
                                                r"intersect"):
        load_off(tmp_path, pts, np.concatenate([TET_TRIANGLES, TET_TRIANGLES + 4]))


def test_disjoint_shells_are_valid(tmp_path):
    # the same two tets, the second shifted by 2: no intersection
    pts = np.concatenate([TET_POINTS, TET_POINTS + 2.0])
    plc = load_off(tmp_path, pts, np.concatenate([TET_TRIANGLES, TET_TRIANGLES + 4]))
    assert len(plc.segments) == 12


def test_multi_region_poly_with_an_internal_facet_is_accepted(tmp_path):
    # two unit cubes stacked along z sharing the internal facet z = 1: its edges lie in 3 faces, legitimate
    # in a .poly with two regions
    pts = [[x, y, z] for z in (0, 1, 2) for y in (0, 1) for x in (0, 1)]
    sq = lambda z, a, b, c, d: f"1\n4 {4 * z + a} {4 * z + b} {4 * z + c} {4 * z + d}"  # noqa: E731
    facets = [sq(0, 0, 1, 3, 2), sq(1, 0, 1, 3, 2), sq(2, 0, 1, 3, 2)]
    for z in (0, 1):
        lo, hi = 4 * z, 4 * z + 4
        for a, b in ((0, 1), (1, 3), (3, 2), (2, 0)):
            facets.append(f"1\n4 {lo + a} {lo + b} {hi + b} {hi + a}")
    text = f"{len(pts)} 3 0 0\n" + "".join(f"{i} {x} {y} {z}\n" for i, (x, y, z) in enumerate(pts))
    text += f"{len(facets)} 0\n" + "\n".join(facets) + "\n0\n2\n1 0.5 0.5 0.5 1\n2 0.5 0.5 1.5 2\n"
    (tmp_path / "two.poly").write_text(text)
    plc = load_plc(tmp_path / "two.poly")
    assert len(plc.triangles) == 22  # 11 squares


CUBES_EDGE = Path(__file__).parent / "data" / "3d" / "cubes_edge.off"


@settings(derandomize=True, deadline=5000, max_examples=30)
@given(st.lists(st.booleans(), min_size=24, max_size=24))
def test_any_orientation_of_two_cubes_sharing_an_edge_is_restored(flips):
    # cubes_edge.off loads outward: triangles 0..11 are the first cube's six squares, 12..23 the second's.
    # Reversing any subset, validation gives the same triangles back and counts, per cube, the faces in the
    # minority orientation as reversed.
    plc = load_plc(CUBES_EDGE)
    flip = np.array(flips)
    t = plc.triangles.copy()
    t[flip] = t[flip][:, ::-1]
    fixed = validate_plc(replace(plc, triangles=t, warnings=()))
    assert np.array_equal(fixed.triangles, plc.triangles)
    reversed_faces = sum(min(k, 12 - k) for k in (int(flip[:12].sum()), int(flip[12:].sum())))
    if reversed_faces:
        assert len(fixed.warnings) == 1
        assert fixed.warnings[0].startswith(f"inconsistent orientation: {reversed_faces} faces")
    else:
        assert fixed.warnings == ()


@settings(max_examples=60, deadline=2000, derandomize=True)
@given(st.integers(1, 3), st.integers(0, 40), st.integers(1, 2**21), st.integers(0, 2**32 - 1))
def test_unique_rows_is_numpy_unique_of_the_rows(width, k, top, seed):
    # Small and large index ranges (the key path, and the fallback once top**width no longer fits in int64).
    rows = np.random.default_rng(seed).integers(0, top, (k, width))
    options = {"return_index": True, "return_inverse": True, "return_counts": True}
    expected, got = np.unique(rows, axis=0, **options), unique_rows(rows, **options)
    assert got[0].tolist() == expected[0].tolist() and got[0].shape == expected[0].shape
    for a, b in zip(got[1:], expected[1:]):
        assert a.ravel().tolist() == b.ravel().tolist()
    assert unique_rows(rows).tolist() == np.unique(rows, axis=0).tolist()


@settings(max_examples=40, deadline=2000, derandomize=True)
@given(st.integers(1, 30), st.integers(3, 12), st.integers(0, 2**32 - 1))
def test_reversed_faces_is_the_edge_table_of_the_reversed_triangles(m, n, seed):
    # Random triangles (distinct corners; few points, so shared edges) and a random set of them reversed.
    rng = np.random.default_rng(seed)
    t = np.array([rng.choice(n, 3, replace=False) for _ in range(m)], dtype=np.int64)
    flip = rng.random(m) < 0.5
    reversed_t = t.copy()
    reversed_t[flip] = reversed_t[flip][:, ::-1]
    expected, got = edge_faces(reversed_t), reversed_faces(edge_faces(t), flip)
    for name in ("edges", "count", "of_corner"):
        assert getattr(got, name).tolist() == getattr(expected, name).tolist()
