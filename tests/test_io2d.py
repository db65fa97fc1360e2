"""nonobtuse.io: readers (Triangle .poly/.node, CG:SHOP and domain JSON), mesh writers and readers, atomic
writes, and every real 2D input either loading or refused with a clear message."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from nonobtuse.errors import InvalidInputError
from nonobtuse.io import is_mesh_file, load_domain, read_mesh, write_mesh
from nonobtuse.mesh import Mesh

DATA = Path(__file__).parent / "data"
SHARED = Path(__file__).resolve().parents[1] / ".." / "shared" / "data"


def write(tmp_path: Path, name: str, text: str) -> Path:
    p = tmp_path / name
    p.write_text(text)
    return p


# A unit-free square 0..4 with a square hole 1..3, 1-based, with comments, blank lines, one vertex attribute,
# boundary markers, a hole and two regions (one with a maximum area, one without).
SQUARE_WITH_HOLE = """\
# square with a square hole
8 2 1 1   # header

1 0 0 0.5 1
2 4 0 0.5 1
3 4 4 0.5 1
4 0 4 0.5 1
5 1 1 0.5 0
6 3 1 0.5 0
7 3 3 0.5 0
8 1 3 0.5 0
8 1
1 1 2 1
2 2 3 1
3 3 4 1
4 4 1 1
5 5 6 0
6 6 7 0
7 7 8 0
8 8 5 0
1
1 2 2
2
1 0.5 0.5 7 0.1
2 3.5 3.5 7
"""


def test_poly_reader_reads_every_section(tmp_path):
    d = load_domain(write(tmp_path, "sq.poly", SQUARE_WITH_HOLE))
    assert d.points.tolist() == [[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [3, 1], [3, 3], [1, 3]]
    # 1-based ids in the file become 0-based indices.
    assert d.segments.tolist() == [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4]]
    assert d.holes.tolist() == [[2, 2]]
    assert d.regions.tolist() == [[0.5, 0.5, 7], [3.5, 3.5, 7]]
    assert not d.convex_hull and d.repairs == []
    assert d.origin.first_id == 1
    assert d.origin.points.tolist() == [4, 5, 6, 7, 8, 9, 10, 11]  # line numbers, counting the blank line 3
    assert d.origin.segments[0] == 13 and d.origin.holes.tolist() == [22]
    assert d.origin.regions.tolist() == [24, 25]


def test_poly_zero_based_and_minimal_header(tmp_path):
    # Header with the vertex count only (dimension 2, no attributes, no markers by default); 0-based ids.
    d = load_domain(write(tmp_path, "tri.poly", "3\n0 0 0\n1 1 0\n2 0 1\n3\n0 0 1\n1 1 2\n2 2 0\n0\n"))
    assert d.origin.first_id == 0
    assert d.segments.tolist() == [[0, 1], [1, 2], [2, 0]]
    assert len(d.regions) == 0  # the regions section is optional


def test_poly_with_zero_vertices_reads_the_node_beside_it(tmp_path):
    write(tmp_path, "t.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n")
    d = load_domain(write(tmp_path, "t.poly", "0 2 0 0\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n"))
    assert d.points.tolist() == [[0, 0], [1, 0], [0, 1]]
    assert d.origin.points_file == str(tmp_path / "t.node")
    assert d.segments.tolist() == [[0, 1], [1, 2], [2, 0]]


def test_node_file_is_a_point_set_on_its_convex_hull(tmp_path):
    d = load_domain(write(tmp_path, "p.node", "4 2 0 0\n1 0 0\n2 2 0\n3 0 2\n4 0.5 0.5\n"))
    assert d.convex_hull and len(d.segments) == 0 and len(d.points) == 4


@pytest.mark.parametrize(
    "text, where, message",
    [
        # header says 4 vertices, the file ends after 3: reported at the last line
        ("4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n", ":4:", "ends early: expected vertex 4 of 4"),
        ("3 2 0 0\n1 0 0\n2 1 abc\n3 0 1\n", ":3:", "y must be a number, found 'abc'"),
        ("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 9\n0\n", ":6:", "segment endpoint 9 does not exist"),
        ("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 0\n0\n", ":6:", "segment endpoint 0 does not exist"),
        ("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 2\n0\n0\n7 7\n", ":9:", "unexpected content after the last"),
        ("3 2 0 1\n1 0 0 1\n2 1 0\n3 0 1 1\n", ":3:", "expected id, x, y, attributes, markers (4 values)"),
        ("3 3 0 0\n1 0 0\n2 1 0\n3 0 1\n", ":1:", "the dimension must be 2, found 3"),
        ("3 2 0 0\n2 0 0\n3 1 0\n4 0 1\n", ":2:", "the first vertex id must be 0 or 1, found 2"),
        ("3 2 0 0\n1 0 0\n3 1 0\n4 0 1\n", ":3:", "consecutive: expected 2, found 3"),
        ("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 2\n", ":6:", "ends early: expected the hole count line"),
        ("-3 2 0 0\n", ":1:", "the vertex count must not be negative"),
        ("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n1\n1 0.5\n", ":7:", "expected id, x, y (3 values)"),
        (
            "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n0\n1\n1 0.2 0.2\n",
            ":8:",
            "expected id, x, y, attribute (4 values)",
        ),
        (
            "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n0\n1\n1 .2 .2 1 big\n",
            ":8:",
            "the maximum area must be a number",
        ),
        ("3 2 0 0\n1 1_0 0\n2 1 0\n3 0 1\n", ":2:", "x must be a number, found '1_0'"),
        ("3.5 2 0 0\n", ":1:", "the vertex count must be an integer"),
    ],
)
def test_poly_errors_name_file_and_line(tmp_path, text, where, message):
    p = write(tmp_path, "bad.poly", text)
    with pytest.raises(InvalidInputError) as e:
        load_domain(p)
    assert f"{p}{where}" in str(e.value) and message in str(e.value)


def test_poly_with_zero_vertices_and_no_node_names_both_files(tmp_path):
    p = write(tmp_path, "lonely.poly", "0 2 0 0\n0 0\n0\n")
    with pytest.raises(
        InvalidInputError, match=r"vertex count is 0, so the vertices come from .*lonely\.node"
    ):
        load_domain(p)


def test_node_errors(tmp_path):
    with pytest.raises(InvalidInputError, match=r"p\.node: the \.node file lists no vertices"):
        load_domain(write(tmp_path, "p.node", "0 2 0 0\n"))


@pytest.mark.parametrize(
    "name, content, message",
    [
        ("x.off", "OFF\n3 1 0\n", "unknown domain format '.off'"),
        ("e.poly", "  \n\n", "the file is empty"),
        ("e.json", "", "the file is empty"),
        ("bad.json", '{"points": [[0, 0],\n [1, ]]}', "bad.json:2: not valid JSON"),
        ("bin.poly", b"\xff\xfe\x00junk", "cannot read the file"),
    ],
)
def test_unreadable_files(tmp_path, name, content, message):
    p = tmp_path / name
    p.write_bytes(content if isinstance(content, bytes) else content.encode())
    with pytest.raises(InvalidInputError, match=message):
        load_domain(p)


def test_missing_file_is_named(tmp_path):
    with pytest.raises(InvalidInputError, match=r"nothing\.poly: cannot read the file"):
        load_domain(tmp_path / "nothing.poly")


def test_cgshop_instance_loop_and_constraints():
    d = load_domain(DATA / "cgshop_l_shape.instance.json")
    # region_boundary [0..5] closes into 6 segments, then the additional constraint (6, 3).
    assert d.segments.tolist() == [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5], [5, 0], [6, 3]]
    assert d.points[6].tolist() == [1, 1] and not d.convex_hull


def test_cgshop_errors(tmp_path):
    base = {"points_x": [0, 1, 0], "points_y": [0, 0, 1], "region_boundary": [0, 1, 2]}
    cases = [
        ({**base, "points_y": [0, 0]}, "points_x has 3 values but points_y has 2"),
        ({**base, "region_boundary": [0, 1]}, "at least 3 points"),
        ({**base, "points_x": [0, 1, "a"]}, r"points_x\[2\] must be a number"),
        ({**base, "points_x": [0, 1, 2**53 + 1]}, "not exactly representable as a float64"),
        ({**base, "region_boundary": [0, 1, 5]}, "refers to a point that does not exist"),
        ({k: v for k, v in base.items() if k != "region_boundary"}, "needs the list 'region_boundary'"),
    ]
    for i, (data, message) in enumerate(cases):
        p = write(tmp_path, f"c{i}.json", json.dumps(data))
        with pytest.raises(InvalidInputError, match=message):
            load_domain(p)


def test_domain_json_every_key(tmp_path):
    data = {
        "points": [[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [3, 1], [2, 3]],
        "segments": [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 4]],
        "holes": [[2, 2]],
        "regions": [[0.5, 0.5, 3]],
        "convex_hull": False,
    }
    d = load_domain(write(tmp_path, "d.json", json.dumps(data)))
    assert d.points.tolist() == data["points"] and d.segments.tolist() == data["segments"]
    assert d.holes.tolist() == [[2, 2]] and d.regions.tolist() == [[0.5, 0.5, 3]]
    assert d.points.dtype == np.float64 and d.segments.dtype == np.int64


def test_domain_json_convex_hull_from_the_file_and_from_the_caller(tmp_path):
    # One side of a square and a fourth point: open, so refused unless the convex hull closes it.
    data = {"points": [[0, 0], [1, 0], [1, 1], [0, 1]], "segments": [[0, 1], [1, 2]]}
    p = write(tmp_path, "open.json", json.dumps(data))
    with pytest.raises(InvalidInputError, match="boundary is not closed; dangling ends at point 0"):
        load_domain(p)  # nothing enclosed: the convex hull closes it only when asked
    assert load_domain(write(tmp_path, "hull.json", json.dumps({**data, "convex_hull": True}))).convex_hull
    q = write(tmp_path, "closed_by_file.json", json.dumps({**data, "convex_hull": False}))
    with pytest.raises(InvalidInputError, match="boundary is not closed"):
        load_domain(q)
    assert load_domain(q, convex_hull=True).convex_hull


@pytest.mark.parametrize(
    "data, message",
    [
        ([1, 2], "expected a JSON object, found list"),
        ({"point": [[0, 0]]}, "needs 'points'"),
        ({"points": [[0, 0], [1, 0], [0, 1]], "segment": []}, r"unknown key\(s\) \['segment'\]"),
        ({"points": [[0, 0], [1, 0], [0, 1, 2]]}, r"points\[2\] must be a list of 2 numbers"),
        ({"points": [[0, 0], [1, 0], [0, True]]}, r"points\[2\] must be a number"),
        (
            {"points": [[0, 0], [1, 0], [0, 1]], "segments": [[0, 1.5]]},
            r"segments\[0\] must be a list of 2 int",
        ),
        ({"points": [[0, 0], [1, 0], [0, 1]], "convex_hull": "yes"}, "'convex_hull' must be true or false"),
        ({"points": "many"}, "points must be a list, found str"),
        ({"points": [[0, 0]], "triangles": []}, "this is a mesh"),
    ],
)
def test_domain_json_errors(tmp_path, data, message):
    with pytest.raises(InvalidInputError, match=message):
        load_domain(write(tmp_path, "d.json", json.dumps(data)))


def test_json_without_suffix_is_sniffed(tmp_path):
    d = load_domain(write(tmp_path, "domain", '{"points": [[0, 0], [1, 0], [0, 1]]}'))
    assert d.convex_hull and len(d.points) == 3


# ---- meshes ----


def two_triangle_mesh(regions=True) -> Mesh:
    # The unit square split along its diagonal plus a Steiner point at the middle of the bottom edge; floats
    # that need all 17 digits (0.1, 1/3) check the round trip is exact.
    pts = np.array([[0, 0], [1, 0], [1, 1], [0.1, 1 / 3], [0.5, 0]])
    tri = np.array([[0, 4, 3], [4, 1, 2], [4, 2, 3]])
    seg = np.array([[0, 4], [4, 1], [1, 2], [2, 3], [3, 0]])
    return Mesh(
        pts, tri, seg, pts[:4].copy(), np.array([[0, 1], [1, 2], [2, 3], [3, 0]]),
        np.array([1.0, 2.0, 2.0]) if regions else None,
        {"status": "converged", "steiner_points": np.int64(1), "seconds": np.float64(0.25),
         "v": np.arange(2)},
    )  # fmt: skip


def assert_same_mesh(a: Mesh, b: Mesh) -> None:
    for name in ("points", "triangles", "segments", "input_points", "input_segments"):
        assert np.array_equal(getattr(a, name), getattr(b, name)), name
    assert (a.regions is None) == (b.regions is None)
    if a.regions is not None:
        assert np.array_equal(a.regions, b.regions)


@pytest.mark.parametrize("regions", [True, False])
def test_mesh_json_round_trip_is_exact(tmp_path, regions):
    mesh = two_triangle_mesh(regions)
    p = tmp_path / "m.json"
    assert write_mesh(mesh, p) == [p]
    back = read_mesh(p)
    assert_same_mesh(mesh, back)
    assert back.stats == {"status": "converged", "steiner_points": 1, "seconds": 0.25, "v": [0, 1]}
    assert back.steiner_points == 1
    assert set(json.loads(p.read_text())) == {
        "points",
        "triangles",
        "segments",
        "input_points",
        "input_segments",
        "stats",
    } | ({"regions"} if regions else set())
    assert is_mesh_file(p)
    assert list(tmp_path.iterdir()) == [p]  # no temporary file left


def test_mesh_write_is_atomic_and_replaces(tmp_path):
    p = tmp_path / "m.json"
    p.write_text("old")
    bad = two_triangle_mesh()
    bad.points = bad.points.copy()
    bad.points[4, 0] = np.nan  # json refuses NaN (allow_nan=False): the write fails half way
    with pytest.raises(ValueError):
        write_mesh(bad, p)
    assert p.read_text() == "old" and list(tmp_path.iterdir()) == [p]
    write_mesh(two_triangle_mesh(), p)
    assert read_mesh(p).points[3, 1] == 1 / 3


@pytest.mark.parametrize(
    "change, message",
    [
        (lambda d: d.pop("input_points"), r"missing \['input_points'\]"),
        (lambda d: d.update(extra=1), r"unknown \['extra'\]"),
        (
            lambda d: d["triangles"].append([0, 1, 9]),
            r"triangles\[3\] = \[0, 1, 9\] refers to a missing point",
        ),
        (lambda d: d["input_points"].__setitem__(0, [5, 5]), "the first 4 points must be the input points"),
        (lambda d: d["regions"].pop(), "2 regions for 3 triangles"),
        (lambda d: d.update(stats=[]), "'stats' must be an object"),
    ],
)
def test_mesh_json_errors(tmp_path, change, message):
    p = tmp_path / "m.json"
    write_mesh(two_triangle_mesh(), p)
    data = json.loads(p.read_text())
    change(data)
    p.write_text(json.dumps(data))
    with pytest.raises(InvalidInputError, match=message):
        read_mesh(p)


def test_triangle_mesh_files(tmp_path):
    mesh = two_triangle_mesh()
    paths = write_mesh(mesh, tmp_path / "out.ele")
    assert [p.name for p in paths] == ["out.node", "out.ele", "out.poly"]
    # The .poly lists 0 vertices: loading it reads out.node; its segments are the mesh's subsegments.
    d = load_domain(tmp_path / "out.poly")
    assert np.array_equal(d.points, mesh.points) and np.array_equal(d.segments, mesh.segments)
    ele = [
        line.split() for line in (tmp_path / "out.ele").read_text().splitlines() if not line.startswith("#")
    ]
    assert ele[0] == ["3", "3", "1"]
    assert [[int(v) - 1 for v in row[1:4]] for row in ele[1:]] == mesh.triangles.tolist()
    assert [float(row[4]) for row in ele[1:]] == [1.0, 2.0, 2.0]


@pytest.mark.parametrize("suffix", [".vtu", ".msh"])
def test_meshio_round_trip(tmp_path, suffix):
    mesh = two_triangle_mesh()
    p = tmp_path / f"m{suffix}"
    written = write_mesh(mesh, p)
    back = read_mesh(p)
    assert np.array_equal(back.points, mesh.points)
    assert np.array_equal(back.triangles, mesh.triangles) and np.array_equal(back.segments, mesh.segments)
    assert np.array_equal(back.regions, mesh.regions)
    assert is_mesh_file(p) and sorted(tmp_path.iterdir()) == sorted(written) and written[0] == p


def test_is_mesh_file_and_unknown_mesh_formats(tmp_path):
    assert not is_mesh_file(write(tmp_path, "d.json", '{"points": [[0, 0]]}'))
    assert not is_mesh_file(write(tmp_path, "d.poly", "3\n"))
    assert not is_mesh_file(write(tmp_path, "broken.json", "{"))
    with pytest.raises(InvalidInputError, match="unknown mesh format '.off'"):
        read_mesh(write(tmp_path, "m.off", "OFF"))
    with pytest.raises(InvalidInputError, match="unknown mesh format '.stl'"):
        write_mesh(two_triangle_mesh(), tmp_path / "m.stl")
    with pytest.raises(InvalidInputError, match="not a nonobtuse mesh"):
        read_mesh(tmp_path / "d.json")


# ---- real inputs ----


def test_bundled_inputs_load_or_are_refused_as_expected():
    # ditch: 11 points, 12 segments, a closed cross-section with 2 interface segments (SOURCES.md).
    d = load_domain(DATA / "cdt_ditch.poly")
    assert (len(d.points), len(d.segments), d.convex_hull, d.repairs) == (11, 12, False, [])
    # clusters: a box with 8 segments radiating from vertex 2 inside it, dangling ends inside the domain.
    assert len(load_domain(DATA / "clusters.poly").segments) == 12
    # cdt.poly lists segment "1 1" twice (lines 154 and 155: 0 0 in the original 0-based file).
    with pytest.raises(InvalidInputError, match=r"segment 49 \(points 0, 0: .*\(line 154\) has zero length"):
        load_domain(DATA / "cdt_cdt.poly")
    # points_on_constraint_edge: the segment from (0, 1) to (14, 1) passes through points 6 = (6, 1) and
    # 7 = (8, 1) (1-based ids), i.e. indices 5 and 6; it encloses nothing, so only the convex hull (asked for)
    # makes it a domain.
    with pytest.raises(InvalidInputError, match="not closed; dangling ends at point 0"):
        load_domain(DATA / "cdt_points_on_constraint_edge.poly")
    d = load_domain(DATA / "cdt_points_on_constraint_edge.poly", convex_hull=True)
    assert d.segments.tolist() == [[0, 5], [5, 6], [6, 11]] and d.convex_hull
    assert len(d.repairs) == 1 and "split at 2 point(s)" in d.repairs[0]
    assert d.origin.segments.tolist() == [16, 16, 16]
    with pytest.raises(
        InvalidInputError, match=r"point 5 \(id 6 in the file\) at \(6\.0, 1\.0\) \(line 8\) lies in"
    ):
        load_domain(DATA / "cdt_points_on_constraint_edge.poly", split_points_on_segments=False)
    # box.poly: only the left side (1, 2) of the outer square is a segment; both its ends dangle.
    with pytest.raises(InvalidInputError, match=r"not closed; dangling ends at point 0 \(id 1 in the file\)"):
        load_domain(DATA / "box.poly")
    d = load_domain(DATA / "box.poly", convex_hull=True)
    assert d.convex_hull and len(d.segments) == 5


def test_bundled_inputs_are_never_modified(tmp_path):
    before = {p.name: p.read_bytes() for p in DATA.iterdir() if p.is_file()}
    for p in DATA.glob("*.poly"):
        try:
            load_domain(p)
        except InvalidInputError:
            pass
    assert {p.name: p.read_bytes() for p in DATA.iterdir() if p.is_file()} == before


def shared_files():
    if not SHARED.is_dir():
        return []
    return (
        sorted((SHARED / "2d").glob("*.poly"))
        + sorted((SHARED / "2d").glob("*.node"))
        + sorted((SHARED / "cgshop25").glob("*.instance.json"))
    )


@pytest.mark.parametrize("path", shared_files() or [None], ids=lambda p: p.name if p else "absent")
def test_shared_inputs_load_or_raise_a_clear_error(path):
    if path is None:
        pytest.skip("../shared/data not present")
    try:
        d = load_domain(path)
    except InvalidInputError as e:
        assert str(e).startswith(f"{path}: ")
        # the refused ones, worked out from SOURCES.md: zero-length edges, an open outer boundary,
        # Sweden's one dangling end (a segment out in the sea), and a constraint among points that encloses
        # nothing; the convex hull closes the last three
        assert path.name in {"cdt_cdt.poly", "box.poly", "cdt_Constrained_Sweden.poly",
                             "cdt_points_on_constraint_edge.poly"}, str(e)
        if path.name != "cdt_cdt.poly":
            assert "not closed" in str(e)
            assert load_domain(path, convex_hull=True).convex_hull
        return
    assert len(d.points) > 0
    if path.suffix == ".json":
        assert not d.convex_hull  # CG:SHOP instances have a closed region boundary


@pytest.mark.parametrize(
    "body, message",
    [
        # vertex 2 (line 3) has a NaN coordinate
        (
            "1 0 0\n2 nan 0\n3 0 1\n4 1 1\n0\n0\n",
            r"point 1 \(id 2 in the file\) at \(nan, 0\.0\) \(line 3\) has a",
        ),
        # vertices 1 (line 2) and 4 (line 5) coincide; -0.0 equals 0.0
        ("1 0 0\n2 1 0\n3 0 1\n4 -0.0 0\n0\n0\n", r"point 0 .*\(line 2\) and point 3 .*\(line 5\) are equal"),
        # the diagonals 1-4 (line 7) and 2-3 (line 8) cross at (0.5, 0.5)
        (
            "1 0 0\n2 1 0\n3 0 1\n4 1 1\n2 0\n1 1 4\n2 2 3\n0\n",
            r"segment 0 .*\(line 7\) and segment 1 .*\(line 8\)",
        ),
    ],
)
def test_validation_messages_carry_file_lines(tmp_path, body, message):
    p = write(tmp_path, "v.poly", "4 2 0 0\n" + body)
    with pytest.raises(InvalidInputError, match=message) as e:
        load_domain(p, convex_hull=True)
    assert str(e.value).startswith(f"{p}: ")
