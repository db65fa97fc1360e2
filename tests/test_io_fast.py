"""The fast paths of the readers and writers give exactly what the plain ones give: the vectorised block
reader of Triangle files (same arrays, markers, line numbers and error messages as the line-by-line
reader), the streaming .json writer (byte-identical to json.dump of the lists) and the appended raw .vtu
writer (read back by meshio as the meshio form of the mesh)."""

from __future__ import annotations

import json
from dataclasses import fields
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nonobtuse.errors import InvalidInputError
from nonobtuse.io import _files, json_formats, read_mesh, triangle, write_mesh
from nonobtuse.io.meshio_formats import to_meshio
from nonobtuse.mesh import Mesh

DATA = Path(__file__).parent / "data"
SHARED = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "2d"


def _line_by_line(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(_files, "numeric_rows", lambda *args, **kwargs: None)


def _read(read, path: Path):
    """The reader's result as comparable data, or its error message."""
    try:
        return read(path)
    except InvalidInputError as e:
        return str(e)


def _assert_same(a, b) -> None:
    """Equal messages, or equal objects field by field (arrays bit for bit, with their dtype and shape)."""
    assert type(a) is type(b)
    if isinstance(a, str):
        assert a == b
        return
    for f in fields(a):
        x, y = getattr(a, f.name), getattr(b, f.name)
        if f.name == "origin" and x is not None:
            _assert_same(x, y)
        elif isinstance(x, np.ndarray):
            assert (x.dtype, x.shape, x.tobytes()) == (y.dtype, y.shape, y.tobytes()), f.name
        else:
            assert x == y, f.name


def _both(monkeypatch: pytest.MonkeyPatch, read, path: Path) -> None:
    fast = _read(read, path)
    with monkeypatch.context() as m:
        _line_by_line(m)
        slow = _read(read, path)
    _assert_same(fast, slow)


def _triangle_inputs() -> list[Path]:
    files = sorted(DATA.glob("*.poly")) + sorted(DATA.glob("*.node"))
    if SHARED.is_dir():
        files += sorted(SHARED.glob("*.poly")) + sorted(SHARED.glob("*.node"))
    return files


@pytest.mark.parametrize("path", _triangle_inputs(), ids=lambda p: f"{p.parent.name}/{p.name}")
def test_fast_reader_equals_line_by_line_on_real_inputs(monkeypatch, path):
    read = triangle.read_poly if path.suffix == ".poly" else triangle.read_node
    _both(monkeypatch, read, path)


def test_real_inputs_take_the_fast_path(monkeypatch):
    calls = []
    real = _files.numeric_rows
    monkeypatch.setattr(_files, "numeric_rows", lambda *a, **k: calls.append(r := real(*a, **k)) or r)
    triangle.read_poly(DATA / "cdt_cdt.poly")
    assert calls and all(r is not None for r in calls)


GOOD = """\
# header comment
5 2 1 1
1 0.5 0 7 1
2 4 0 -1e-3 1
3 4 4 .5 2
4 0 4 5. -3
5 1 1 0 0
4 1
1 1 2 5
2 2 3 5
3 3 4 6
4 4 1 6
0
"""

# Each one an input the fast path must hand to the line-by-line reader: accepted there or refused with
# its file:line message.
VARIANTS = {
    "good": lambda s: s,
    "comment in the block": lambda s: s.replace("3 4 4 .5 2", "3 4 4 .5 2 # c"),
    "blank line in the block": lambda s: s.replace("3 4 4 .5 2\n", "3 4 4 .5 2\n\n"),
    "extra token": lambda s: s.replace("3 4 4 .5 2", "3 4 4 .5 2 9"),
    "missing token": lambda s: s.replace("3 4 4 .5 2", "3 4 4 .5"),
    "ragged but same count": lambda s: s.replace("1 0.5 0 7 1\n2", "1 0.5 0 7 1 2\n"),
    "float id": lambda s: s.replace("2 4 0 -1e-3 1", "2.0 4 0 -1e-3 1"),
    "exponent marker": lambda s: s.replace("4 0 4 5. -3", "4 0 4 5. 1e1"),
    "float segment endpoint": lambda s: s.replace("2 2 3 5", "2 2 3.0 5"),
    "nan coordinate": lambda s: s.replace("1 0.5 0 7", "1 nan 0 7"),
    "underscore": lambda s: s.replace("1 0.5 0 7", "1 1_0 0 7"),
    "two numbers in a token": lambda s: s.replace("1 0.5 0 7", "1 0.5-1 7"),
    "not a number": lambda s: s.replace("1 0.5 0 7", "1 0.5. 0 7"),
    "ids from 0": lambda s: "".join(
        f"{int(ln.split()[0]) - 1} {ln.split(' ', 1)[1]}\n" if 2 <= k <= 6 else ln + "\n"
        for k, ln in enumerate(s.splitlines())
    ),
    "ids not consecutive": lambda s: s.replace("4 0 4 5.", "6 0 4 5."),
    "first id 2": lambda s: s.replace("1 0.5 0 7 1", "2 0.5 0 7 1"),
    "endpoint out of range": lambda s: s.replace("4 4 1 6", "4 4 9 6"),
    "huge marker": lambda s: s.replace("4 0 4 5. -3", f"4 0 4 5. {2**60 + 1}"),
    "non-ASCII space": lambda s: s.replace("1 0.5 0 7", "1 0.5\u00a00 7"),
    "file ends early": lambda s: s[: s.index("4 1\n")],
    "content after the end": lambda s: s + "1 2\n",
}


@pytest.mark.parametrize("variant", sorted(VARIANTS))
def test_fast_reader_variants(tmp_path, monkeypatch, variant):
    path = tmp_path / "v.poly"
    path.write_text(VARIANTS[variant](GOOD), encoding="utf-8")
    _both(monkeypatch, triangle.read_poly, path)


def test_variant_results_are_what_the_file_says(tmp_path):
    path = tmp_path / "v.poly"
    path.write_text(GOOD)
    d = triangle.read_poly(path)
    assert d.points.tolist() == [[0.5, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0], [1.0, 1.0]]
    assert d.point_markers.tolist() == [1, 1, 2, -3, 0]
    assert d.segments.tolist() == [[0, 1], [1, 2], [2, 3], [3, 0]]
    assert d.segment_markers.tolist() == [5, 5, 6, 6]
    assert d.origin.points.tolist() == [3, 4, 5, 6, 7] and d.origin.segments.tolist() == [9, 10, 11, 12]
    path.write_text(VARIANTS["huge marker"](GOOD))
    assert triangle.read_poly(path).point_markers[3] == 2**60 + 1


@pytest.mark.parametrize("regions", [False, True])
def test_fast_mesh_reader_equals_line_by_line(tmp_path, monkeypatch, regions):
    """.node/.ele/.poly written by us read back the same on both paths, and as written."""
    mesh = _mesh(50, seed=3)
    mesh = Mesh(
        mesh.points, mesh.triangles, mesh.segments, mesh.points.copy(), mesh.segments.copy(),
        mesh.regions if regions else None, stats={"source": str(tmp_path / "m.ele")},
        point_markers=mesh.point_markers, segment_markers=mesh.segment_markers,
    )  # fmt: skip
    write_mesh(mesh, tmp_path / "m.ele")
    _both(monkeypatch, read_mesh, tmp_path / "m.ele")
    _assert_same(read_mesh(tmp_path / "m.ele"), mesh)
    ele = tmp_path / "m.ele"
    ele.write_text(ele.read_text().replace("\n3 ", "\n3 1e9 ", 1))
    _both(monkeypatch, read_mesh, ele)


TOKEN = st.text(alphabet="0123456789.eE+-", min_size=1, max_size=8)


@settings(max_examples=300, deadline=2000, derandomize=True)
@given(st.lists(st.lists(TOKEN, min_size=3, max_size=3), min_size=1, max_size=4))
def test_numeric_rows_agree_with_float_and_int(rows):
    """Whatever plain numeric tokens the fast path accepts, it reads as float() (and column 0 as int())."""
    got = _files.numeric_rows([" ".join(r) for r in rows], 3, (0,))
    if got is None:
        return
    for row, values in zip(rows, got.tolist()):
        assert [float(t) for t in row] == values
        assert int(row[0]) == values[0]


def _axis(rng: np.random.Generator, m: int, special: float) -> np.ndarray:
    """m strictly increasing coordinates of magnitudes 1e-30 to 1e30, both signs, ``special`` among them."""
    v = rng.normal(size=m) * 10.0 ** rng.integers(-30, 30, size=m)
    v[0] = special
    v = np.unique(v)  # sorted; keeps -0.0
    assert len(v) == m
    return v


def _mesh(n: int, seed: int) -> Mesh:
    """A valid mesh of about n points (read_mesh refuses overlapping triangles): a tensor grid of random
    strictly increasing x and y values (so every cell is a proper rectangle and its two triangles are
    counter-clockwise, exactly) cut by random diagonals, the points in random order, one at (-0.0, 5e-324)."""
    rng = np.random.default_rng(seed)
    nx = max(1, int(np.sqrt(n)))
    ny = -(-n // nx)
    x, y = _axis(rng, nx, -0.0), _axis(rng, ny, 5e-324)
    grid = np.column_stack([np.repeat(x, ny), np.tile(y, nx)])  # grid point i * ny + j is (x[i], y[j])
    special = int(np.flatnonzero(x == 0)[0]) * ny + int(np.flatnonzero(y == 5e-324)[0])
    order = rng.permutation(len(grid))
    at = int(np.flatnonzero(order == special)[0])
    order[[0, at]] = order[[at, 0]]
    new = np.empty_like(order)
    new[order] = np.arange(len(order))  # new index of grid point g
    points = grid[order]
    assert points[0].tolist() == [-0.0, 5e-324] and np.signbit(points[0, 0])
    i, j = (a.ravel() for a in np.meshgrid(np.arange(nx - 1), np.arange(ny - 1), indexing="ij"))
    a, b, c, d = (new[(i + di) * ny + j + dj] for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)))  # CCW
    flip = rng.integers(0, 2, size=len(a)).astype(bool)
    first = np.where(flip[:, None], np.column_stack([a, b, d]), np.column_stack([a, b, c]))
    second = np.where(flip[:, None], np.column_stack([b, c, d]), np.column_stack([a, c, d]))
    triangles = np.concatenate([first, second]).reshape(-1, 3)
    edges = np.unique(np.sort(triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1), axis=0)
    segments = edges[rng.permutation(len(edges))[:n]].reshape(-1, 2)
    m, k = len(points), max(1, len(points) // 2)
    return Mesh(
        points, triangles, segments, points[:k].copy(), rng.integers(0, k, size=(3, 2)),
        rng.normal(size=len(triangles)), stats={"status": "ok", "seconds": 0.5, "per_edge": np.arange(3)},
        point_markers=rng.integers(-(2**40), 2**40, size=m),
        segment_markers=rng.integers(0, 9, size=len(segments)),
    )  # fmt: skip


def _json_dump_of_lists(mesh: Mesh) -> str:
    """The .json the mesh schema defines, written the plain way (json.dump of the lists)."""
    data = {k: getattr(mesh, k).tolist() for k in json_formats.MESH_ARRAYS if getattr(mesh, k) is not None}
    data["stats"] = mesh.stats
    return json.dumps(data, allow_nan=False, separators=(",", ":"), default=json_formats._plain) + "\n"


@pytest.mark.parametrize("n", [1, 7, 5000])
def test_json_writer_is_byte_identical_to_json_dump(tmp_path, n):
    mesh = _mesh(n, seed=n)
    write_mesh(mesh, tmp_path / "m.json")
    assert (tmp_path / "m.json").read_text() == _json_dump_of_lists(mesh)
    back = read_mesh(tmp_path / "m.json")
    assert np.array_equal(back.points, mesh.points) and np.array_equal(back.regions, mesh.regions)
    assert np.array_equal(np.signbit(back.points), np.signbit(mesh.points))


def test_json_writer_refuses_nan_and_writes_nothing(tmp_path):
    mesh = _mesh(5, seed=1)
    mesh.points[2, 1] = np.nan
    with pytest.raises(ValueError, match="JSON compliant"):
        write_mesh(mesh, tmp_path / "m.json")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("regions", [False, True])
@pytest.mark.parametrize("markers", [False, True])
@pytest.mark.parametrize("segments", [0, 40])
def test_vtu_writer_gives_meshio_the_meshio_form(tmp_path, regions, markers, segments):
    """meshio reads the appended raw .vtu back as the meshio form of the mesh, every array bit for bit."""
    import meshio

    full = _mesh(60, seed=segments + 2 * regions + markers)
    mesh = Mesh(
        full.points, full.triangles, full.segments[:segments], full.input_points, full.input_segments,
        full.regions if regions else None, {}, point_markers=full.point_markers if markers else None,
        segment_markers=full.segment_markers[:segments] if markers else None,
    )  # fmt: skip
    write_mesh(mesh, tmp_path / "m.vtu")
    back, want = meshio.read(tmp_path / "m.vtu"), to_meshio(mesh)
    assert back.points.tobytes() == want.points.tobytes()
    blocks = [(c.type, c.data.astype(np.int64).tobytes()) for c in want.cells if len(c.data)]
    assert [(c.type, c.data.astype(np.int64).tobytes()) for c in back.cells] == blocks
    assert sorted(back.cell_data) == sorted(want.cell_data)
    for key, values in want.cell_data.items():
        got = np.concatenate([np.ravel(v) for v in back.cell_data[key]])
        assert got.tobytes() == np.concatenate([np.ravel(v) for v in values]).astype(got.dtype).tobytes()
        assert got.dtype == np.concatenate(values).dtype
    assert sorted(back.point_data) == sorted(want.point_data)
    for key, values in want.point_data.items():
        assert back.point_data[key].tobytes() == values.tobytes()
    assert [p.name for p in tmp_path.iterdir()] == ["m.vtu"]


def _raw_input(path: Path):
    """read_off's or read_tetgen's result as plain data (points bytes, facet loops, holes and places,
    markers, volume holes and regions), or its message."""
    from nonobtuse.io.surfaces import read_off
    from nonobtuse.io.tetgen import read_tetgen

    try:
        raw = (read_off if path.suffix == ".off" else read_tetgen)(path)
    except InvalidInputError as e:
        return str(e)
    facets = [([loop.tolist() for loop in f.loops], f.holes.tolist(), f.where) for f in raw.facets]
    markers = None if raw.facet_markers is None else raw.facet_markers.tolist()
    arrays = [(a.dtype, a.shape, a.tobytes()) for a in (raw.points, raw.holes, raw.regions)]
    return arrays, facets, markers


def _raw_both(monkeypatch: pytest.MonkeyPatch, path: Path):
    """:func:`_raw_input` with the fast path, asserted equal to it without; returns it."""
    fast = _raw_input(path)
    with monkeypatch.context() as m:
        _line_by_line(m)
        assert _raw_input(path) == fast
    return fast


OFF = "OFF\n# a tetrahedron\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1.5e0\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"
OFF_VARIANTS = {
    "good": OFF,
    "comment in the vertices": OFF.replace("1 0 0\n", "1 0 0 # c\n"),
    "colour after a vertex": OFF.replace("1 0 0\n", "1 0 0 255\n"),
    "missing coordinate": OFF.replace("1 0 0\n", "1 0\n"),
    "nan": OFF.replace("0 1 0\n", "0 nan 0\n"),
    "not a number": OFF.replace("0 1 0\n", "0 1x 0\n"),
}


def _off_files() -> list[Path]:
    """The OFF and TetGen inputs of ../shared/data/3d."""
    shared = SHARED.parent / "3d"
    names = ("*.off", "*.smesh", "*.poly")
    return sorted(p for n in names for p in shared.glob(n)) if shared.is_dir() else []


SMESH = "8 3 0 1\n" + "".join(
    f"{i} {x} {y} {z} 7\n" for i, (x, y, z) in enumerate(np.ndindex(2, 2, 2), start=1)
) + "6 1\n4 1 2 4 3 1\n4 5 6 8 7 2\n4 1 2 6 5 3\n4 3 4 8 7 4\n4 1 3 7 5 5\n4 2 4 8 6 6\n0\n0\n"
SMESH_VARIANTS = {
    "good": SMESH,
    "no marker column": SMESH.replace("8 3 0 1", "8 3 0 0"),
    "index 1.0": SMESH.replace("\n2 0 0 1 7", "\n2.0 0 0 1 7"),
    "header count not a number": SMESH.replace("8 3 0 1", "8 3 x 1"),
    "comment": SMESH.replace("\n3 0 1 0 7", "\n3 0 1 0 7 # c"),
}


@pytest.mark.parametrize("variant", sorted(SMESH_VARIANTS))
def test_fast_tetgen_node_reader_variants(tmp_path, monkeypatch, variant):
    path = tmp_path / "cube.smesh"
    path.write_text(SMESH_VARIANTS[variant])
    fast = _raw_both(monkeypatch, path)
    if variant == "good":
        assert fast[0][0][2] == np.array(list(np.ndindex(2, 2, 2)), np.float64).tobytes()


@pytest.mark.parametrize("variant", sorted(OFF_VARIANTS))
def test_fast_off_reader_variants(tmp_path, monkeypatch, variant):
    path = tmp_path / "t.off"
    path.write_text(OFF_VARIANTS[variant])
    _raw_both(monkeypatch, path)


@pytest.mark.skipif(not _off_files(), reason="../shared/data/3d (the real 3D inputs) is absent")
@pytest.mark.parametrize("path", _off_files(), ids=lambda p: p.name)
def test_fast_3d_readers_equal_line_by_line_on_real_inputs(monkeypatch, path):
    _raw_both(monkeypatch, path)


@pytest.mark.parametrize("bad_row", [None, 69_000])
def test_fast_reader_across_chunks(tmp_path, monkeypatch, bad_row):
    """70,000 vertices span two chunks of the block reader; an unusual token in the second chunk sends the
    whole block to the line-by-line reader."""
    rng = np.random.default_rng(5)
    rows = [f"{i} {x!r} {y!r}" for i, (x, y) in enumerate(rng.normal(size=(70_000, 2)).tolist())]
    if bad_row is not None:
        rows[bad_row] = f"{bad_row} 1_5 0"
    path = tmp_path / "big.node"
    path.write_text(f"{len(rows)} 2 0 0\n" + "\n".join(rows) + "\n")
    _both(monkeypatch, triangle.read_node, path)
