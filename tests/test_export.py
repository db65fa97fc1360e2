"""Simulator exports (PFLOTRAN .uge/.ex, FEHM .stor/.fehmn/zones, TOUGH MESH, CSV/NPZ): round trips through
small readers written here (toughio for MESH), and the exported geometry against the Voronoi dual computed
independently from circumcenters."""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nonobtuse import Mesh
from nonobtuse.cli import main
from nonobtuse.demo import cross_section
from nonobtuse.errors import InvalidInputError
from nonobtuse.io import write_mesh
from nonobtuse.io.cv_grid import DEFAULT_BOUNDARY_MARKER, distinct_indices, grid_from_mesh
from nonobtuse.io.export import export_mesh, is_export_path
from nonobtuse.io.fehm import fehm_paths
from nonobtuse.io.pflotran import boundary_path
from nonobtuse.refinement import refine
from nonobtuse.triangulation import triangulate
from point_sets import point_set_mesh


def square_mesh() -> Mesh:
    """The unit square cut by the diagonal (0,0)-(1,1); segments: the four sides, bottom first, ccw."""
    p = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    sides = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])
    return Mesh(points=p, triangles=np.array([[0, 1, 2], [0, 2, 3]]), segments=sides, input_points=p,
                input_segments=sides)


def circumcenter_dual_lengths(mesh: Mesh) -> dict[tuple[int, int], float]:
    """Per edge (a < b): the signed length of its Voronoi dual clipped to the mesh, from circumcenters, in
    exact rationals: per triangle, the distance from the circumcenter to the edge's midpoint, negative when
    the circumcenter lies across the edge from the triangle. (Rounded once, at the division by |e|.)"""
    q = [(Fraction(x), Fraction(y)) for x, y in mesh.points.tolist()]
    exact: dict[tuple[int, int], Fraction] = {}
    for tri in mesh.triangles.tolist():
        (ax, ay), (bx, by), (cx, cy) = (q[v] for v in tri)
        # Circumcenter by Cramer's rule on 2 (p - a) . x = |p|^2 - |a|^2 for p = b, c.
        m11, m12, m21, m22 = 2 * (bx - ax), 2 * (by - ay), 2 * (cx - ax), 2 * (cy - ay)
        r1, r2 = bx * bx + by * by - ax * ax - ay * ay, cx * cx + cy * cy - ax * ax - ay * ay
        det = m11 * m22 - m12 * m21
        ox, oy = (r1 * m22 - m12 * r2) / det, (m11 * r2 - r1 * m21) / det
        for k in range(3):
            i, j, apex = tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]
            (ux, uy), (vx, vy), (wx, wy) = q[i], q[j], q[apex]
            nx, ny = -(vy - uy), vx - ux  # a normal of the edge; |n| = |e|
            side = 1 if nx * (wx - ux) + ny * (wy - uy) > 0 else -1  # toward the apex
            key = (min(i, j), max(i, j))
            piece = (ox - (ux + vx) / 2) * nx + (oy - (uy + vy) / 2) * ny
            exact[key] = exact.get(key, Fraction(0)) + side * piece
    length = {k: float(np.linalg.norm(mesh.points[k[1]] - mesh.points[k[0]])) for k in exact}
    return {k: float(v) / length[k] for k, v in exact.items()}


# --- small readers ------------------------------------------------------------------------------------------

def read_uge(path: Path) -> tuple[np.ndarray, np.ndarray]:
    lines = path.read_text().splitlines()
    head, n = lines[0].split()
    assert head == "CELLS"
    cells = np.array([[float(v) for v in line.split()] for line in lines[1:1 + int(n)]])
    head, c = lines[1 + int(n)].split()
    assert head == "CONNECTIONS"
    conns = np.array([[float(v) for v in line.split()] for line in lines[2 + int(n):]]).reshape(-1, 6)
    assert len(conns) == int(c)
    return cells, conns


def read_ex(path: Path) -> np.ndarray:
    lines = path.read_text().splitlines()
    head, n = lines[0].split()
    assert head == "CONNECTIONS"
    rows = np.array([[float(v) for v in line.split()] for line in lines[1:]]).reshape(-1, 5)
    assert len(rows) == int(n)
    return rows


def read_stor(path: Path) -> dict:
    """Parse a .stor file into its blocks, checking every count the header announces."""
    lines = path.read_text().splitlines()
    assert lines[0].startswith("fehmstor ascir8i4")
    ncoef, neq, ptr_size, area_coefs, ncon_max = (int(v) for v in lines[2].split())
    assert ptr_size == ncoef + neq + 1 and area_coefs == 1
    tokens = " ".join(lines[3:]).split()
    volumes = np.array(tokens[:neq], dtype=float)
    rest = tokens[neq:]
    stream = np.array(rest[:neq + 1 + ncoef], dtype=np.int64)
    rest = rest[neq + 1 + ncoef:]
    coef_ptr = np.array(rest[:ncoef + neq + 1], dtype=np.int64)
    rest = rest[ncoef + neq + 1:]
    diagonal = np.array(rest[:neq], dtype=np.int64)
    values = np.array(rest[neq:], dtype=float)
    assert len(values) == ncoef
    return {"neq": neq, "ncoef": ncoef, "ncon_max": ncon_max, "volumes": volumes,
            "pointers": stream[:neq + 1], "columns": stream[neq + 1:], "coef_ptr": coef_ptr,
            "diagonal": diagonal, "values": values}


def read_zones(path: Path) -> dict[str, np.ndarray]:
    tokens = path.read_text().split()
    assert tokens[0] == "zone" and tokens[-1] == "stop"
    zones, k = {}, 1
    while tokens[k] != "stop":
        name = tokens[k + 1]
        assert tokens[k + 2] == "nnum"
        count = int(tokens[k + 3])
        zones[name] = np.array(tokens[k + 4:k + 4 + count], dtype=np.int64)
        k += 4 + count
    return zones


# --- the grid itself ----------------------------------------------------------------------------------------

def test_unit_square_by_hand(tmp_path):
    # Two right triangles: every vertex gets a quarter of the square (x thickness 2 = 0.5). Each side's dual
    # runs from its midpoint to the circumcenter (the square's centre): length 1/2, area 1/2 * 2 = 1. The
    # diagonal's dual is a point (both circumcenters on it): area exactly 0, coefficient 0.0.
    g = grid_from_mesh(square_mesh(), thickness=2.0)
    np.testing.assert_allclose(g.volumes, 0.5, rtol=1e-15)
    diagonal = (g.connections == [0, 2]).all(axis=1)
    assert g.signs[diagonal].tolist() == [0] and g.areas[diagonal].tolist() == [0.0]
    np.testing.assert_allclose(g.areas[~diagonal], 1.0, rtol=1e-15)
    np.testing.assert_allclose(g.distances[~diagonal], 1.0)
    assert g.negative_coefficients == 0
    # Boundary: 4 sides x 2 halves of 0.5 x 2.
    assert len(g.boundary_cells) == 8
    np.testing.assert_allclose(g.boundary_areas, 1.0)
    assert set(g.boundary_markers.tolist()) == {DEFAULT_BOUNDARY_MARKER}


@pytest.mark.parametrize("refined", [False, True])
def test_areas_are_the_circumcenter_dual_lengths(refined):
    mesh = refine(cross_section()).mesh if refined else triangulate(cross_section())
    thickness = 3.0
    g = grid_from_mesh(mesh, thickness=thickness)
    expected = circumcenter_dual_lengths(mesh)
    got = {(int(mesh_a), int(mesh_b)): area / thickness for (mesh_a, mesh_b), area
           in zip(g.point_index[g.connections].tolist(), g.areas.tolist())}
    assert got.keys() == expected.keys()
    scale = max(abs(v) for v in expected.values())
    np.testing.assert_allclose([got[k] for k in expected], list(expected.values()), rtol=1e-9,
                               atol=1e-12 * scale)
    u, v = (mesh.points[mesh.triangles[:, k]] - mesh.points[mesh.triangles[:, 0]] for k in (1, 2))
    domain_area = 0.5 * (u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]).sum()
    assert g.volumes.sum() == pytest.approx(domain_area * thickness, rel=1e-12)
    # The refined mesh is certified: no wrong-signed coefficient; the plain CDT of the section has some.
    assert (g.negative_coefficients == 0) == refined
    # The exact signs are the exact oracle's.
    assert [int(np.sign(got_sign)) for got_sign in g.signs.tolist()] == [
        int(np.sign(expected[k])) for k in map(tuple, g.point_index[g.connections].tolist())]


@settings(max_examples=25, deadline=5000, derandomize=True)
@given(st.integers(0, 2**32 - 1))
def test_boundary_pieces_cover_the_boundary(seed):
    mesh = point_set_mesh(np.random.default_rng(seed).random((12, 2)))
    g = grid_from_mesh(mesh, thickness=1.0)
    boundary = np.sort(mesh.segments, axis=1)
    length = np.linalg.norm(mesh.points[boundary[:, 1]] - mesh.points[boundary[:, 0]], axis=1).sum()
    assert g.boundary_areas.sum() == pytest.approx(length, rel=1e-12)
    assert (g.boundary_areas > 0).all()


def test_segment_markers_become_boundary_zones(tmp_path):
    mesh = square_mesh()
    mesh.segment_markers = np.array([101, 102, 103, 102])  # bottom, right, top, left
    out = tmp_path / "sq.uge"
    export_mesh(mesh, out, thickness=1.0)
    for marker, side_length in ((101, 1.0), (102, 2.0), (103, 1.0)):
        rows = read_ex(boundary_path(out, marker))
        assert rows[:, 4].sum() == pytest.approx(side_length)
    bottom = read_ex(boundary_path(out, 101))
    assert sorted(bottom[:, 0].astype(int).tolist()) == [1, 2]  # cells of (0,0) and (1,0), 1-based
    np.testing.assert_allclose(sorted(bottom[:, 1].tolist()), [0.25, 0.75])  # half-segment centroids


def test_bad_thickness_and_empty_mesh():
    with pytest.raises(InvalidInputError, match="thickness"):
        grid_from_mesh(square_mesh(), thickness=0.0)
    m = square_mesh()
    m.triangles = np.zeros((0, 3), dtype=np.int64)
    with pytest.raises(InvalidInputError, match="no elements"):
        grid_from_mesh(m)


# --- round trips --------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def demo_mesh() -> Mesh:
    return refine(cross_section()).mesh


def test_uge_round_trip(tmp_path, demo_mesh):
    grid, paths = export_mesh(demo_mesh, tmp_path / "demo.uge", thickness=2.0)
    cells, conns = read_uge(paths[0])
    np.testing.assert_array_equal(cells[:, 0], np.arange(1, len(grid.volumes) + 1))
    np.testing.assert_array_equal(cells[:, 1:4], grid.centers)
    np.testing.assert_array_equal(cells[:, 4], grid.volumes)
    np.testing.assert_array_equal(conns[:, :2].astype(int) - 1, grid.connections)
    np.testing.assert_array_equal(conns[:, 2:5], grid.face_centers)
    np.testing.assert_array_equal(conns[:, 5], grid.areas)
    assert (conns[:, 5] >= 0).all()
    ex = read_ex(boundary_path(paths[0], DEFAULT_BOUNDARY_MARKER))
    np.testing.assert_array_equal(ex[:, 0].astype(int) - 1, grid.boundary_cells)
    np.testing.assert_array_equal(ex[:, 4], grid.boundary_areas)


def test_stor_round_trip(tmp_path, demo_mesh):
    grid, paths = export_mesh(demo_mesh, tmp_path / "demo.stor")
    s = read_stor(paths[0])
    n = len(grid.volumes)
    assert s["neq"] == n and s["ncoef"] == n + 2 * len(grid.connections)
    np.testing.assert_allclose(s["volumes"], grid.volumes, rtol=1e-11)
    assert s["pointers"][0] == n + 1 and s["pointers"][-1] == n + 1 + s["ncoef"]
    assert s["ncon_max"] == np.diff(s["pointers"]).max()
    np.testing.assert_array_equal(s["coef_ptr"], np.r_[np.arange(1, s["ncoef"] + 1), np.zeros(n + 1)])
    # Rebuild the matrix from the rows; compare with -area/distance per connection, 0 on the diagonal.
    matrix = {}
    for i in range(n):
        for k in range(s["pointers"][i] - n - 1, s["pointers"][i + 1] - n - 1):
            matrix[(i, int(s["columns"][k]) - 1)] = s["values"][s["coef_ptr"][k] - 1]
        # the diagonal pointer is the position of (i, i) in the stream of row pointers and columns
        assert s["columns"][s["diagonal"][i] - (n + 1) - 1] == i + 1
    assert all(matrix[(i, i)] == 0 for i in range(n))
    for (a, b), c in zip(grid.connections.tolist(), grid.coefficients.tolist()):
        assert matrix[(a, b)] == matrix[(b, a)] == pytest.approx(c, rel=1e-11, abs=1e-300)
    assert len(matrix) == s["ncoef"]
    assert max(matrix.values()) <= 0  # certified: no positive off-diagonal


def test_fehmn_and_zones(tmp_path, demo_mesh):
    grid, _ = export_mesh(demo_mesh, tmp_path / "demo.stor")
    p = fehm_paths(tmp_path / "demo.stor")
    text = p["fehmn"].read_text().split("\n")
    assert text[0] == "coor" and int(text[1]) == len(grid.volumes)
    coords = np.array([[float(v) for v in line.split()[1:]] for line in text[2:2 + len(grid.volumes)]])
    np.testing.assert_array_equal(coords, grid.centers)
    elem = text.index("elem")
    assert text[elem + 1].split() == ["3", str(len(grid.elements))]
    material = read_zones(p["material"])
    assert sorted(material) == [f"region_{r:g}" for r in sorted(set(demo_mesh.regions.tolist()))]
    for r, cells in grid.region_cells.items():
        np.testing.assert_array_equal(material[f"region_{r:g}"], cells + 1)
    boundary = read_zones(p["boundary"])
    np.testing.assert_array_equal(boundary[f"marker_{DEFAULT_BOUNDARY_MARKER}"],
                                  np.unique(grid.boundary_cells) + 1)


def test_tough_mesh_reads_back_with_toughio(tmp_path, demo_mesh):
    toughio = pytest.importorskip("toughio")
    grid, paths = export_mesh(demo_mesh, tmp_path / "MESH", thickness=2.0)
    d = toughio.read_input(paths[0], file_format="tough")
    names = list(d["elements"])
    assert len(names) == len(grid.volumes) == len(set(names))
    np.testing.assert_allclose([d["elements"][k]["volume"] for k in names], grid.volumes, rtol=1e-6)
    np.testing.assert_allclose([d["elements"][k]["center"] for k in names], grid.centers, rtol=1e-6,
                               atol=1e-9)
    materials = np.unique(grid.materials)
    assert [d["elements"][k]["material"] for k in names] == (np.searchsorted(materials, grid.materials)
                                                            + 1).tolist()
    conns = d["connections"]
    assert len(conns) == len(grid.connections)
    index = {name: i for i, name in enumerate(names)}
    pairs = [[index[k[:5]], index[k[5:]]] for k in conns]
    assert pairs == grid.connections.tolist()
    # 10 columns: 6 to 7 significant digits, 5 for tiny values (2.1185e-13)
    np.testing.assert_allclose([c["interface_area"] for c in conns.values()], grid.areas, rtol=1e-4)
    np.testing.assert_allclose([sum(c["nodal_distances"]) for c in conns.values()], grid.distances, rtol=1e-6)


def test_csv_and_npz_round_trip(tmp_path, demo_mesh):
    grid, paths = export_mesh(demo_mesh, tmp_path / "demo.csv")
    cells = np.loadtxt(paths[0], delimiter=",", skiprows=1)
    np.testing.assert_array_equal(cells[:, 5], grid.volumes)
    conns = np.loadtxt(paths[1], delimiter=",", skiprows=1)
    np.testing.assert_array_equal(conns[:, :2].astype(int), grid.connections)
    np.testing.assert_array_equal(conns[:, 2], grid.areas)
    np.testing.assert_array_equal(conns[:, 3], grid.distances)
    _, (npz,) = export_mesh(demo_mesh, tmp_path / "demo.npz")
    with np.load(npz) as z:
        np.testing.assert_array_equal(z["areas"], grid.areas)
        np.testing.assert_array_equal(z["connections"], grid.connections)
        np.testing.assert_array_equal(z["coefficients"], grid.coefficients)


def test_output_is_deterministic(tmp_path, demo_mesh):
    for name in ("a.uge", "a.stor", "MESH", "a.csv"):
        (tmp_path / "1").mkdir(exist_ok=True)
        (tmp_path / "2").mkdir(exist_ok=True)
        _, first = export_mesh(demo_mesh, tmp_path / "1" / name)
        _, second = export_mesh(demo_mesh, tmp_path / "2" / name)
        assert [p.read_bytes() for p in first] == [p.read_bytes() for p in second]


# --- CLI ----------------------------------------------------------------------------------------------------

def test_cli_export_and_refine_to_simulator_formats(tmp_path, capsys):
    mesh_file = tmp_path / "sq.json"
    write_mesh(square_mesh(), mesh_file)
    assert main(["export", str(mesh_file), "-o", str(tmp_path / "sq.uge"), "--thickness", "2"]) == 0
    out = capsys.readouterr().out
    assert "negative coefficients (exact sign of -area/distance > 0): 0" in out
    cells, _ = read_uge(tmp_path / "sq.uge")
    np.testing.assert_allclose(cells[:, 4], 0.5)
    domain = tmp_path / "sq.poly"
    domain.write_text("4 2 0 0\n1 0 0\n2 3 0\n3 3 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n")
    assert main(["refine", str(domain), "-o", str(tmp_path / "r.stor")]) == 0
    assert "negative coefficients" in capsys.readouterr().err
    assert read_stor(tmp_path / "r.stor")["values"].max() <= 0


def test_cli_export_refuses_bad_input(tmp_path, capsys):
    mesh_file = tmp_path / "sq.json"
    write_mesh(square_mesh(), mesh_file)
    assert main(["export", str(mesh_file), "-o", str(tmp_path / "sq.xyz")]) == 2
    assert "not an export format" in capsys.readouterr().err
    domain = tmp_path / "d.poly"
    domain.write_text("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n")
    assert main(["export", str(domain), "-o", str(tmp_path / "d.uge")]) == 2
    assert "not a mesh file" in capsys.readouterr().err
    assert not (tmp_path / "d.uge").exists()


def test_cli_export_exits_1_on_wrong_signs(tmp_path):
    mesh_file = tmp_path / "cdt.json"
    write_mesh(triangulate(cross_section()), mesh_file)
    assert main(["export", str(mesh_file), "-o", str(tmp_path / "cdt.uge")]) == 1


def test_export_names():
    assert all(is_export_path(p) for p in ("a.uge", "b.STOR", "MESH", "x/MESH", "c.tough", "d.csv", "e.npz"))
    assert not any(is_export_path(p) for p in ("a.json", "a.vtu", "mesh", "a.mesh"))


# --- 3D -----------------------------------------------------------------------------------------------------

def ridge_area(vertices: np.ndarray, normal: np.ndarray) -> float:
    """Area of a convex planar polygon given by its vertices in any order (sorted by angle about the centroid
    in the plane with that normal)."""
    c = vertices.mean(axis=0)
    u = np.cross(normal, [1.0, 0.0, 0.0] if abs(normal[0]) < 0.9 else [0.0, 1.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(normal / np.linalg.norm(normal), u)
    xy = np.column_stack([(vertices - c) @ u, (vertices - c) @ v])
    xy = xy[np.argsort(np.arctan2(xy[:, 1], xy[:, 0]))]
    return 0.5 * abs(float(np.dot(xy[:, 0], np.roll(xy[:, 1], -1)) - np.dot(xy[:, 1], np.roll(xy[:, 0], -1))))


@settings(max_examples=5, deadline=20000, derandomize=True)
@given(st.integers(0, 2**32 - 1))
def test_3d_areas_and_volumes_are_qhull_voronoi_ridges_and_cells(seed):
    # A random point cloud's Delaunay tetrahedralization: the dual face of an edge whose ends are both inside
    # the hull is the whole Voronoi ridge, and a cell whose vertex and neighbours are all inside is its whole
    # Voronoi region. scipy (Qhull) computes both on its own.
    scipy_spatial = pytest.importorskip("scipy.spatial")
    from nonobtuse import _core
    from nonobtuse.mesh3d import TetMesh

    points = np.random.default_rng(seed).random((60, 3))
    tets = _core.delaunay_tetrahedra(points)
    mesh = TetMesh(points, tets, np.zeros((0, 3), np.int64), np.zeros(0, np.int64))
    grid = grid_from_mesh(mesh)
    hull = set(scipy_spatial.ConvexHull(points).vertices.tolist())
    vor = scipy_spatial.Voronoi(points)
    ridges = {tuple(sorted(p)): r for p, r in zip(vor.ridge_points.tolist(), vor.ridge_vertices)}
    checked = 0
    for (a, b), area in zip(grid.point_index[grid.connections].tolist(), grid.areas.tolist()):
        if a in hull or b in hull:
            continue
        ridge = vor.vertices[ridges[(a, b)]]
        assert area == pytest.approx(ridge_area(ridge, points[b] - points[a]), rel=1e-7, abs=1e-12)
        checked += 1
    assert checked > 0
    neighbours = {i: set() for i in range(len(points))}
    for a, b in grid.point_index[grid.connections].tolist():
        neighbours[a].add(b)
        neighbours[b].add(a)
    for cell, point in enumerate(grid.point_index.tolist()):
        if point in hull or neighbours[point] & hull:
            continue
        region = vor.vertices[vor.regions[vor.point_region[point]]]
        assert grid.volumes[cell] == pytest.approx(scipy_spatial.ConvexHull(region).volume, rel=1e-7)
    # Interior edges of a Delaunay mesh have nonnegative dual areas: the exact signs say so too.
    inside = ~np.isin(grid.point_index[grid.connections], list(hull)).any(axis=1)
    assert (grid.signs[inside] >= 0).all()


def test_3d_cube_exports_exact_zeros(tmp_path):
    # The Kuhn cube: face and long diagonals have dual area exactly 0 (cospherical corners).
    from mesh3d_shapes import CUBE_POINTS, CUBE_TRIANGLES
    from nonobtuse.mesh3d import TetMesh

    kuhn = [[0, 1, 3, 7], [0, 3, 2, 7], [0, 2, 6, 7], [0, 6, 4, 7], [0, 4, 5, 7], [0, 5, 1, 7]]
    faces = CUBE_TRIANGLES
    mesh = TetMesh(CUBE_POINTS, np.array(kuhn), faces, np.tile(np.arange(6), 2) + 10)  # quad q: rows q, q + 6
    grid, paths = export_mesh(mesh, tmp_path / "cube.stor")
    axis = grid.distances == 1.0
    assert (grid.signs[~axis] == 0).all() and (grid.areas[~axis] == 0.0).all()
    np.testing.assert_allclose(grid.areas[axis], 0.25, rtol=1e-14)
    s = read_stor(paths[0])
    assert s["values"].max() == 0.0
    zones = read_zones(fehm_paths(tmp_path / "cube.stor")["boundary"])
    assert sorted(zones) == [f"marker_{m}" for m in range(10, 16)]  # one zone per facet marker
    assert all(len(cells) == 4 for cells in zones.values())  # every cube face has 4 corners
    assert grid.boundary_areas.sum() == pytest.approx(6.0)


def test_3d_corner_tet_has_negative_coefficients():
    # Vertex 0 of (0, e_x, e_y, e_z) encroaches the face (e_x, e_y, e_z): its three edges' dual pieces are
    # exactly negative (see cpp/tests/control_volumes3d_test.cpp for the values by hand).
    from nonobtuse.mesh3d import TetMesh

    p = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    no_faces = np.zeros((0, 3), np.int64)
    grid = grid_from_mesh(TetMesh(p, np.array([[0, 1, 2, 3]]), no_faces, np.zeros(0, np.int64)))
    assert grid.signs.tolist() == [1, 1, 1, -1, -1, -1]  # (0,1) (0,2) (0,3) (1,2) (1,3) (2,3)
    assert grid.negative_coefficients == 3 and (grid.areas[3:] < 0).all()
    assert grid.volumes.sum() == pytest.approx(1 / 6)


def test_refine3d_writes_uge_with_no_negative_coefficient(tmp_path, capsys):
    from mesh3d_shapes import TET_TRIANGLES, write_off

    corners = np.array([[0, 0, 0], [4, 0, 0], [0, 4, 0], [1, 1, 2]])
    low = write_off(tmp_path / "low.off", corners, TET_TRIANGLES.tolist())
    out = tmp_path / "low.uge"
    assert main(["refine3d", str(low), "-o", str(out), "--max-steiner", "500"]) == 0
    assert "negative coefficients (exact sign of -area/distance > 0): 0" in capsys.readouterr().err
    cells, conns = read_uge(out)
    assert (conns[:, 5] >= 0).all()
    assert cells[:, 4].sum() == pytest.approx(4 * 4 / 2 * 2 / 3)  # base area 8 times height 2 over 3
    # Boundary files are grouped by facet marker; OFF has none, so every facet has marker 0 and the whole
    # boundary is one file, whose pieces cover the tet's surface.
    markers = sorted(int(p.stem.rsplit("_", 1)[1]) for p in tmp_path.glob("low_boundary_*.ex"))
    assert markers == [0]
    c = corners[TET_TRIANGLES]
    surface = np.linalg.norm(np.cross(c[:, 1] - c[:, 0], c[:, 2] - c[:, 0]), axis=1).sum() / 2
    assert read_ex(boundary_path(out, 0))[:, 4].sum() == pytest.approx(surface, rel=1e-12)


def test_fv_maximum_principle_quick(tmp_path):
    # The solve experiment on the 2D section: the plain CDT's wrong-signed coefficients break the discrete
    # maximum principle (cells outside [0, 1], negative Green's function entries); the refined mesh's do not.
    import csv

    from experiments.fv_maximum_principle import main as experiment

    assert experiment(["--quick", "--out", str(tmp_path)]) == 0
    with open(tmp_path / "fv_maximum_principle_quick.csv") as f:
        rows = {r["mesh"]: r for r in csv.DictReader(f)}
    cdt, ours = rows["constrained Delaunay"], rows["nonobtuse refine"]
    assert int(cdt["negative_coefficients"]) > 0 and int(cdt["cells_outside"]) > 0
    assert int(cdt["negative_responses"]) > 0
    assert int(ours["negative_coefficients"]) == 0 and int(ours["cells_outside"]) == 0
    assert int(ours["negative_responses"]) == 0 and int(ours["sources"]) > 0
    assert (tmp_path / "fv_maximum_principle_quick.png").stat().st_size > 0


@given(st.lists(st.integers(-(2**62), 2**62), max_size=60), st.sampled_from([np.int64, np.int32]))
def test_distinct_indices_is_np_unique(values, dtype):
    a = np.array([v % 2**31 - 2**30 for v in values] if dtype is np.int32 else values, dtype=dtype)
    for b in (a, a[: len(a) // 2 * 2].reshape(-1, 2)):
        got, want = distinct_indices(b), np.unique(b)
        assert got.dtype == want.dtype and got.tolist() == want.tolist()
