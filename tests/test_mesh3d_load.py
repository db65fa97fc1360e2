"""Readers of 3D inputs: every format on small files written here, facet merging, segments, the corpus."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from mesh3d_shapes import (
    CUBE_POINTS,
    CUBE_QUADS,
    CUBE_TRIANGLES,
    write_off,
    write_stl_ascii,
    write_stl_binary,
)
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d import load_plc

DATA3D = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "3d"


def cube_edges(points):
    """The 12 edges of a unit cube with these corners: pairs of corners differing in one coordinate."""
    return sorted((a, b) for a in range(8) for b in range(a + 1, 8) if (points[a] != points[b]).sum() == 1)


def assert_is_cube(plc, points=CUBE_POINTS):
    assert np.array_equal(plc.points, points)
    assert len(plc.triangles) == 12  # 6 squares, 2 triangles each
    # coplanar triangle pairs are merged: 6 facets, numbered 0..5
    assert sorted(set(plc.facet_ids.tolist())) == list(range(6))
    assert np.bincount(plc.facet_ids).tolist() == [2] * 6
    # segments: the cube edges, not the square diagonals (flat)
    assert [tuple(s) for s in plc.segments.tolist()] == cube_edges(points)


def test_off_with_quads(tmp_path):
    plc = load_plc(write_off(tmp_path / "cube.off", CUBE_POINTS, CUBE_QUADS.tolist()))
    assert_is_cube(plc)
    # triangles of one quad share its facet id (the quads are facets 0..5 in file order)
    assert plc.facet_ids.tolist() == [0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5]


def test_off_with_triangles_merges_coplanar_pairs(tmp_path):
    plc = load_plc(write_off(tmp_path / "cube.off", CUBE_POINTS, CUBE_TRIANGLES.tolist()))
    assert_is_cube(plc)
    # CUBE_TRIANGLES lists the first halves of the 6 squares, then the second halves
    assert plc.facet_ids.tolist() == [0, 1, 2, 3, 4, 5] * 2


def test_obj_with_texture_indices_and_negative_indices(tmp_path):
    lines = ["# cube", "o cube"] + [f"v {x} {y} {z}" for x, y, z in CUBE_POINTS]
    for t in CUBE_TRIANGLES[:6]:
        lines.append("f " + " ".join(f"{v + 1}/1/1" for v in t))
    for t in CUBE_TRIANGLES[6:]:
        lines.append("f " + " ".join(str(v - 8) for v in t))  # -8 is vertex 0 after 8 vertices
    (tmp_path / "cube.obj").write_text("\n".join(lines) + "\n")
    assert_is_cube(load_plc(tmp_path / "cube.obj"))


def test_ply_ascii(tmp_path):
    head = ["ply", "format ascii 1.0", "element vertex 8", "property double x", "property double y",
            "property double z", "element face 6", "property list uchar int vertex_indices", "end_header"]
    body = [" ".join(repr(float(c)) for c in p) for p in CUBE_POINTS] + ["4 " + " ".join(map(str, q))
                                                                         for q in CUBE_QUADS]
    (tmp_path / "cube.ply").write_text("\n".join(head + body) + "\n")
    assert_is_cube(load_plc(tmp_path / "cube.ply"))


@pytest.mark.parametrize("writer", [write_stl_ascii, write_stl_binary])
def test_stl_merges_equal_vertices_in_order_of_first_occurrence(tmp_path, writer):
    # 36 triangle corners, 8 distinct points; the first triangle is (0, 2, 3), so vertex order starts 0, 2, 3
    plc = load_plc(writer(tmp_path / "cube.stl", CUBE_POINTS, CUBE_TRIANGLES))
    first_seen = list(dict.fromkeys(CUBE_TRIANGLES.ravel().tolist()))
    assert_is_cube(plc, CUBE_POINTS[first_seen])


def test_stl_negative_zero_equals_zero(tmp_path):
    pts = CUBE_POINTS.copy()
    path = write_stl_ascii(tmp_path / "cube.stl", pts, CUBE_TRIANGLES)
    path.write_text(path.read_text().replace("vertex 0.0 0.0 0.0", "vertex -0.0 0.0 0.0", 1))
    assert len(load_plc(path).points) == 8


# box [0,4]^2 x [0,2] split at z = 1 into two regions; the bottom facet has a square hole
POLY_BOX_WITH_SQUARE_HOLE = """# box split into two regions, bottom facet with a hole
16 3 0 0
1 0 0 0
2 4 0 0
3 4 4 0
4 0 4 0
5 0 0 2
6 4 0 2
7 4 4 2
8 0 4 2
9 0 0 1
10 4 0 1
11 4 4 1
12 0 4 1
13 1 1 0
14 2 1 0
15 2 2 0
16 1 2 0
7 1
2 1 0
4 1 2 3 4
4 13 14 15 16
1 1.5 1.5 0
1 0 2
4 5 6 7 8
1 0 3
4 9 10 11 12
2 0 4
4 1 2 10 9
4 9 10 6 5
2 0 4
4 2 3 11 10
4 10 11 7 6
2 0 4
4 3 4 12 11
4 11 12 8 7
2 0 4
4 4 1 9 12
4 12 9 5 8
0
2
1 2 2 0.5 10
2 2 2 1.5 20
"""


def test_poly_facets_with_holes_and_regions(tmp_path):
    (tmp_path / "box.poly").write_text(POLY_BOX_WITH_SQUARE_HOLE)
    # the hole in the bottom facet leaves 4 edges with one face: the bottom facet and the lower side faces
    # peel off as dangling (the lower layer is open); the upper layer (sides, top, middle facet) encloses a
    # volume
    opened = load_plc(tmp_path / "box.poly")
    dangling = [w for w in opened.warnings if "dangling faces" in w]
    assert len(dangling) == 1 and dangling[0].startswith(f"{8 + 4 * 2} dangling faces")
    closed = POLY_BOX_WITH_SQUARE_HOLE.replace("7 1\n2 1 0\n", "8 1\n1 0 5\n4 13 14 15 16\n2 1 0\n")
    (tmp_path / "closed.poly").write_text(closed)
    plc = load_plc(tmp_path / "closed.poly")
    assert plc.points.shape == (16, 3)
    # facet 0 (the small square) 2 triangles; facet 1: the bottom square minus the hole: 8 vertices and 1 hole
    # give 8 + 2*1 - 2 = 8 triangles; facets 2, 3 (top, middle) 2 each; facets 4..7: two squares each, 4
    assert np.bincount(plc.facet_ids).tolist() == [2, 8, 2, 2, 4, 4, 4, 4]
    # the hole is not covered: the bottom facet's triangles have area 4*4 - 1*1 = 15
    p = plc.points[plc.triangles[plc.facet_ids == 1]]
    assert np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum() / 2 == 15.0
    assert plc.regions.tolist() == [[2, 2, 0.5, 10], [2, 2, 1.5, 20]]
    # segments: top 4 + bottom 4 box edges, 4 vertical box edges split at z = 1 into 8, the middle square's 4
    # edges (an internal facet, its edges in 3 faces: allowed in a .poly) and the small square's 4 edges: 24
    seg = {tuple(s) for s in plc.segments.tolist()}
    assert len(seg) == 24
    assert {(0, 1), (0, 8), (4, 8), (8, 9), (12, 13)} <= seg  # 0-based indices
    assert (4, 6) not in seg and (5, 7) not in seg  # a diagonal of the top square is flat


def test_poly_dangling_segment_inside_a_facet(tmp_path):
    # the top facet (file line "1 0 2": 1 polygon, marker 2) gets a second polygon of 2 vertices, its diagonal
    # 5-7 (1-based): the facet's triangulation must use it, and it becomes a PLC segment (0-based (4, 6))
    closed = POLY_BOX_WITH_SQUARE_HOLE.replace("7 1\n2 1 0\n", "8 1\n1 0 5\n4 13 14 15 16\n2 1 0\n")
    text = closed.replace("1 0 2\n4 5 6 7 8\n", "2 0 2\n4 5 6 7 8\n2 5 7\n")
    (tmp_path / "d.poly").write_text(text)
    plc = load_plc(tmp_path / "d.poly")
    top = np.sort(plc.triangles[plc.facet_ids == 2], axis=1).tolist()
    assert sorted(top) == [[4, 5, 6], [4, 6, 7]]
    seg = {tuple(s) for s in plc.segments.tolist()}
    assert len(seg) == 25 and (4, 6) in seg


def test_smesh_and_node_file(tmp_path):
    (tmp_path / "t.node").write_text("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n")
    (tmp_path / "t.smesh").write_text("0 3 0 0\n4 1\n3 0 2 1 5\n3 0 1 3 5\n3 0 3 2 5\n3 1 2 3 5\n0\n0\n")
    plc = load_plc(tmp_path / "t.smesh")
    assert plc.points.tolist() == [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    assert plc.triangles.tolist() == [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]
    assert plc.facet_ids.tolist() == [0, 1, 2, 3]
    assert len(plc.segments) == 6  # the 6 tet edges


def test_non_planar_facet_is_refused(tmp_path):
    pts = CUBE_POINTS.copy()
    pts[7, 2] = 1.0 + 2.0**-40  # lifts one corner of the top square off its plane
    with pytest.raises(InvalidInputError, match="not planar"):
        load_plc(write_off(tmp_path / "c.off", pts, CUBE_QUADS.tolist()))


def _corpus(name: str) -> Path:
    path = DATA3D / name
    if not path.exists():
        pytest.skip("../shared/data not present")
    return path


@pytest.mark.parametrize("name", sorted(p.name for p in DATA3D.glob("*") if p.suffix in
                                        (".off", ".obj", ".ply", ".stl", ".poly", ".smesh"))
                         if DATA3D.exists() else ["absent"])
def test_every_corpus_file_loads(name):
    # the non-manifold (cubes.off, gc_hourglass_ico.obj) and inconsistently oriented (schonhardt.off) inputs
    # included: they are valid PLCs
    plc = load_plc(_corpus(name))
    assert len(plc.triangles) > 0 and len(plc.segments) > 0


def test_schonhardt_is_reoriented_with_a_warning():
    plc = load_plc(_corpus("schonhardt.off"))
    assert len(plc.warnings) == 1 and plc.warnings[0].startswith("inconsistent orientation: 1 faces")
    # every undirected edge appears once in each direction after the fix
    d = np.concatenate([plc.triangles[:, [0, 1]], plc.triangles[:, [1, 2]], plc.triangles[:, [2, 0]]])
    assert len({tuple(e) for e in d.tolist()}) == len(d) == 24
    # outward: the bottom face (vertices 0, 1, 2 at z = 0, the others at z = 2) has a downward normal
    bottom = plc.triangles[np.isin(plc.triangles, [0, 1, 2]).all(axis=1)][0]
    p = plc.points[bottom]
    assert np.cross(p[1] - p[0], p[2] - p[0])[2] < 0


def test_sphere_stl_equals_sphere_off():
    off, stl = load_plc(_corpus("sphere.off")), load_plc(_corpus("sphere.stl"))
    # same point set up to float32 rounding (binary STL stores float32); map STL indices to OFF indices
    index = {tuple(p): i for i, p in enumerate(off.points.astype(np.float32).astype(np.float64).tolist())}
    to_off = np.array([index[tuple(p)] for p in stl.points.tolist()])
    assert len(set(to_off.tolist())) == len(off.points)

    def canon(t):  # a triangle up to rotation (orientation kept)
        k = int(np.argmin(t))
        return tuple(np.roll(t, -k).tolist())

    assert {canon(t) for t in to_off[stl.triangles]} == {canon(t) for t in off.triangles}


def test_manifold_smesh_is_oriented_outward(tmp_path):
    # facet orientation is free in TetGen files: the reversed faces (0, 1, 2) and (3, 2, 1) come out outward,
    # reversed, as (2, 1, 0) and (1, 2, 3) (normals -z and (1, 1, 1))
    (tmp_path / "t.smesh").write_text("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n"
                                      "4 0\n3 0 1 2\n3 0 1 3\n3 0 3 2\n3 3 2 1\n0\n0\n")
    assert load_plc(tmp_path / "t.smesh").triangles.tolist() == [[2, 1, 0], [0, 1, 3], [0, 3, 2], [1, 2, 3]]


@pytest.mark.parametrize("case", ["cube", "bad index", "negative index", "nan"])
def test_triangle_surfaces_take_the_vectorised_path_with_the_same_result(monkeypatch, case):
    # A surface of one-triangle facets is triangulated without a Python step per facet: the same triangles,
    # facet ids and segments, or the same message, as the loop over facets.
    from mesh3d_shapes import CUBE_POINTS, CUBE_TRIANGLES
    from nonobtuse.io.raw3d import Facet, RawInput
    from nonobtuse.mesh3d import load

    points, triangles = np.array(CUBE_POINTS, dtype=float), np.array(CUBE_TRIANGLES)
    if case == "bad index":
        triangles[5, 1] = 8
    if case == "negative index":
        triangles[7, 2] = -1
    if case == "nan":
        points[3, 2] = np.nan
    facets = [Facet([t], where=f"x.off:{k + 3}") for k, t in enumerate(triangles)]
    raw = RawInput(points, facets, source="x.off")

    def result():
        try:
            return [a.tolist() for a in load.triangulate_facets(raw)]
        except InvalidInputError as e:
            return str(e)

    fast = result()
    assert case != "cube" or load._triangle_facets(raw) is not None  # the fast path was taken
    monkeypatch.setattr(load, "_triangle_facets", lambda raw: None)
    assert fast == result()
    assert isinstance(fast, list) == (case == "cube")
