"""3D facet markers and region attributes: read from .poly/.smesh/OBJ/PLY, carried through the backends and
refine_gabriel to every subfacet and tet (checked against the geometry: each subfacet lies in its facet's
plane, regions are constant between subfacets and right at the seeds), and written to every format."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d import TetMesh, load_plc, read_tetmesh, refine_gabriel, tetrahedralize, write_tetmesh

SHARED = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "3d"

# A truncated pyramid (bottom 2 x 1 at z = 0, top 1 x 0.5 at z = 0.6) cut at x = 1 by an internal facet
# (marker 3) into two regions: the left part's outer facets have marker 1, the right part's marker 2. The
# top corners lie inside the diametral spheres of the bottom triangles, so refinement adds points on the
# facets, slanted ones included.
SLAB = """\
# truncated pyramid with an internal facet
12 3 0 0
1 0 0 0
2 1 0 0
3 2 0 0
4 0 1 0
5 1 1 0
6 2 1 0
7 0.5 0.25 0.6
8 1 0.25 0.6
9 1.5 0.25 0.6
10 0.5 0.75 0.6
11 1 0.75 0.6
12 1.5 0.75 0.6
11 1
1 0 1
4 1 2 5 4
1 0 1
4 7 8 11 10
1 0 1
4 1 2 8 7
1 0 1
4 4 5 11 10
1 0 1
4 1 4 10 7
1 0 2
4 2 3 6 5
1 0 2
4 8 9 12 11
1 0 2
4 2 3 9 8
1 0 2
4 5 6 12 11
1 0 2
4 3 6 12 9
1 0 3
4 2 5 11 8
0
2
1 0.6 0.5 0.05 1.5
2 1.4 0.5 0.05 -2.25
"""
SLAB_MARKERS = [1] * 5 + [2] * 5 + [3]


def slab(tmp_path: Path):
    path = tmp_path / "slab.poly"
    path.write_text(SLAB)
    return load_plc(path)


def assert_subfacets_lie_in_their_facets(mesh: TetMesh, plc) -> None:
    """The corners of every boundary face lie in the plane of its facet: exactly for input points and for
    facets parallel to the axes, within 1e-12 of the size for Steiner points on slanted facets (rounded
    constructions), which is far below the distance between any two facet planes here."""
    first = {}
    for t, f in enumerate(plc.facet_ids.tolist()):
        first.setdefault(f, t)
    corners = plc.points[plc.triangles[[first[f] for f in mesh.face_facets.tolist()]]]
    a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
    normal = np.cross(b - a, c - a)
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    size = float(np.ptp(plc.points, axis=0).max())
    for corner in range(3):
        off = np.einsum("ij,ij->i", mesh.points[mesh.boundary_faces[:, corner]] - a, normal)
        assert np.abs(off).max() <= 1e-12 * size


def assert_regions_follow_the_seeds(mesh: TetMesh, plc) -> None:
    """Tets sharing a face that is not a subfacet have the same region; the tet holding a seed has its
    attribute."""
    faces = np.sort(mesh.tets[:, [[1, 2, 3], [0, 2, 3], [0, 1, 3], [0, 1, 2]]].reshape(-1, 3), axis=1)
    subfacets = {tuple(f) for f in np.sort(mesh.boundary_faces, axis=1).tolist()}
    owner: dict[tuple, int] = {}
    for i, f in enumerate(map(tuple, faces.tolist())):
        t = i // 4
        if f in owner and f not in subfacets:
            assert mesh.tet_regions[owner[f]] == mesh.tet_regions[t]
        owner[f] = t
    for x, y, z, attr in plc.regions:
        p = mesh.points[mesh.tets]  # (t, 4, 3)
        edges = np.transpose(p[:, 1:] - p[:, :1], (0, 2, 1))
        a = np.linalg.solve(edges, (np.array([x, y, z]) - p[:, 0])[:, :, None])[:, :, 0]
        inside = np.flatnonzero((a >= 0).all(axis=1) & (a.sum(axis=1) <= 1))
        assert len(inside) and (mesh.tet_regions[inside] == attr).all()


def test_poly_facet_markers_and_regions_are_read(tmp_path):
    plc = slab(tmp_path)
    assert plc.facet_markers.tolist() == SLAB_MARKERS
    assert plc.regions[:, 3].tolist() == [1.5, -2.25]


def test_refine_gabriel_carries_facet_markers_and_regions(tmp_path):
    plc = slab(tmp_path)
    res = refine_gabriel(plc)
    mesh = res.mesh
    assert res.status == "converged" and res.stats["steiner_on_facets"] > 0
    assert len(mesh.boundary_faces) > len(plc.triangles)
    assert_subfacets_lie_in_their_facets(mesh, plc)
    assert np.array_equal(mesh.face_markers, np.array(SLAB_MARKERS)[mesh.face_facets])
    assert sorted(set(mesh.face_markers.tolist())) == [1, 2, 3]
    assert sorted(set(mesh.tet_regions.tolist())) == [-2.25, 1.5]
    assert_regions_follow_the_seeds(mesh, plc)


def test_example_poly_through_refine_gabriel():
    path = SHARED / "example.poly"
    if not path.is_file():
        pytest.skip(f"{path} not present (../shared/data is the shared corpus)")
    plc = load_plc(path)
    assert sorted(set(plc.facet_markers.tolist())) == [1, 2, 3, 4, 9] and len(plc.regions) == 2
    res = refine_gabriel(plc)
    mesh = res.mesh
    assert res.status == "converged"
    assert_subfacets_lie_in_their_facets(mesh, plc)
    assert np.array_equal(mesh.face_markers, plc.facet_markers[mesh.face_facets])
    assert sorted(set(mesh.face_markers.tolist())) == [1, 2, 3, 4, 9]
    assert_regions_follow_the_seeds(mesh, plc)
    assert sorted(set(mesh.tet_regions.tolist())) == [10.0, 20.0]


def test_tetgen_backend_gives_facet_markers(tmp_path):
    pytest.importorskip("tetgen")
    plc = slab(tmp_path)
    mesh = tetrahedralize(plc, "tetgen")
    assert_subfacets_lie_in_their_facets(mesh, plc)
    assert np.array_equal(mesh.face_markers, np.array(SLAB_MARKERS)[mesh.face_facets])
    cgal = tetrahedralize(plc, "cgal")
    assert np.array_equal(cgal.face_markers, np.array(SLAB_MARKERS)[plc.facet_ids])


def test_smesh_markers_are_read(tmp_path):
    path = tmp_path / "tet.smesh"
    path.write_text("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 1\n3 0 2 1 5\n3 0 1 3 6\n3 0 3 2 7\n"
                    "3 1 2 3 8\n0\n0\n")  # fmt: skip
    assert load_plc(path).facet_markers.tolist() == [5, 6, 7, 8]
    path.write_text("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 2\n3 0 2 1 5\n")
    with pytest.raises(InvalidInputError, match="marker flag must be 0 or 1"):
        load_plc(path)


# A unit cube in OBJ whose top square is split between two groups: its two coplanar triangles must stay two
# facets (the marker boundary is a segment), while the other squares merge as usual.
def cube_obj(groups: tuple[str, str, str]) -> str:
    from mesh3d_shapes import CUBE_POINTS, CUBE_TRIANGLES

    lines = [f"v {x} {y} {z}" for x, y, z in CUBE_POINTS.tolist()]
    top = {1, 7}  # rows of CUBE_TRIANGLES on z = 1 (quad 1 = [4, 5, 7, 6])
    for i, t in enumerate(CUBE_TRIANGLES.tolist()):
        group = groups[0] if i not in top else groups[1 + (i == 7)]
        lines += [f"g {group}", "f " + " ".join(str(v + 1) for v in t)]
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize(("names", "markers"), [(("wall", "lid", "cap"), (1, 2, 3)),
                                                (("10", "20", "30"), (10, 20, 30))])  # fmt: skip
def test_obj_groups_are_facet_markers_and_keep_facets_apart(tmp_path, names, markers):
    path = tmp_path / "cube.obj"
    path.write_text(cube_obj(names))
    plc = load_plc(path)
    per_triangle = plc.facet_markers[plc.facet_ids]
    assert per_triangle[[1, 7]].tolist() == list(markers[1:]) and set(np.delete(per_triangle, [1, 7])) == {
        markers[0]}  # fmt: skip
    assert len(plc.facet_markers) == 7  # 5 merged squares + the two halves of the top
    top_diagonal = np.sort(np.intersect1d(plc.triangles[1], plc.triangles[7]))
    assert top_diagonal.tolist() in plc.segments.tolist()


def test_ply_face_property_is_the_facet_marker(tmp_path):
    from mesh3d_shapes import TET_POINTS, TET_TRIANGLES

    header = ["ply", "format ascii 1.0", "element vertex 4", "property float x", "property float y",
              "property float z", "element face 4", "property list uchar int vertex_indices",
              "property int marker", "end_header"]  # fmt: skip
    rows = [" ".join(map(str, p)) for p in TET_POINTS.tolist()]
    rows += [f"3 {a} {b} {c} {m}" for (a, b, c), m in zip(TET_TRIANGLES.tolist(), [4, 4, 5, 6])]
    path = tmp_path / "tet.ply"
    path.write_text("\n".join(header + rows) + "\n")
    plc = load_plc(path)
    assert plc.facet_markers[plc.facet_ids].tolist() == [4, 4, 5, 6]


@pytest.mark.parametrize("suffix", [".json", ".vtu", ".msh"])
def test_tet_meshes_round_trip_markers_facets_and_regions(tmp_path, suffix):
    mesh = refine_gabriel(slab(tmp_path)).mesh
    written = write_tetmesh(mesh, tmp_path / f"m{suffix}")
    assert [p.name for p in written] == [f"m{suffix}"] + (["m.msh.regions.json"] if suffix == ".msh" else [])
    back = read_tetmesh(written[0])
    assert np.array_equal(back.points, mesh.points)
    for name in ("tets", "boundary_faces", "face_markers", "face_facets", "tet_regions"):
        assert np.array_equal(getattr(back, name), getattr(mesh, name)), name
    assert back.tet_regions.dtype == np.float64


def test_tet_mesh_meshio_objects_round_trip(tmp_path):
    mesh = refine_gabriel(slab(tmp_path)).mesh
    m = mesh.to_meshio()
    assert [c.type for c in m.cells] == ["tetra", "triangle"]
    back = TetMesh.from_meshio(m)
    for name in ("points", "tets", "boundary_faces", "face_markers", "face_facets", "tet_regions"):
        assert np.array_equal(getattr(back, name), getattr(mesh, name)), name
    with pytest.raises(InvalidInputError, match="no tetra cells"):
        TetMesh.from_meshio(type(m)(m.points, [("triangle", mesh.boundary_faces)]))
