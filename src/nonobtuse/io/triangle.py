"""Shewchuk's Triangle file formats: ``.node`` and ``.poly`` in, ``.node``/``.ele``/``.poly`` out.

Reading follows Triangle's documentation (https://www.cs.cmu.edu/~quake/triangle.poly.html):

- ``.node``: a header ``<#vertices> [<dimension = 2> [<#attributes> [<#boundary markers = 0|1>]]]``, then one
  line per vertex ``<id> <x> <y> [attributes...] [marker]``.
- ``.poly``: a .node-style header and vertices (a vertex count of 0 means: read the vertices from the
  ``.node``
  file beside it), then ``<#segments> [<#markers>]`` and ``<id> <a> <b> [marker]`` lines, then ``<#holes>``
  and ``<id> <x> <y>`` lines, then optionally ``<#regions>`` and ``<id> <x> <y> <attribute> [<max area>]``
  lines.

``#`` starts a comment anywhere on a line; blank lines are skipped. Ids are 0- or 1-based, decided by the
first vertex's id; vertices must be numbered consecutively from it, and segment endpoints use the same base.
Vertex and segment boundary markers are kept (``Domain.point_markers`` / ``segment_markers``, None when the
file has no marker column); regional maximum areas are kept (``Domain.region_max_areas``, NaN where a
region gives none); vertex attributes are read (and checked to be numbers) but not kept. Every error names
``file:line``.

Blocks of plain numeric lines (the vertices, segments and triangles) are parsed in one numpy pass
(:meth:`nonobtuse.io._files.Lines.numbers`); anything unusual in a block (comments, blank lines, extra
columns, nan, ids out of order or out of range) sends it to the line-by-line reader, which gives the same
values and names the problem.

Meshes: :func:`write_triangle` writes ``.node``/``.ele``/``.poly`` with marker columns;
:func:`read_triangle_mesh` reads them back (or Triangle's own output) as a :class:`Mesh`.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from nonobtuse.domain import Domain, SourceMap
from nonobtuse.errors import InvalidInputError
from nonobtuse.io._files import Line, Lines, atomic_text
from nonobtuse.mesh import Mesh


def read_node(path: Path) -> Domain:
    """A ``.node`` file as a point set (no segments; ``convex_hull=True``)."""
    lines = Lines(path)
    points, point_lines, first_id, markers = _read_vertices(lines)
    if len(points) == 0:
        raise InvalidInputError(f"{path}: the .node file lists no vertices")
    lines.expect_end()
    origin = SourceMap(file=str(path), first_id=first_id, points=point_lines)
    return Domain(points, convex_hull=True, source=str(path), origin=origin, point_markers=markers)


def read_poly(path: Path) -> Domain:
    """A ``.poly`` file as a Domain (``convex_hull=False``; :func:`nonobtuse.io.load_domain` decides)."""
    lines = Lines(path)
    points, point_lines, first_id, point_markers = _read_vertices(lines)
    points_file = None
    if len(points) == 0:
        node = path.with_suffix(".node")
        try:
            node_domain = read_node(node)
        except InvalidInputError as e:
            raise InvalidInputError(
                f"{path}: the vertex count is 0, so the vertices come from {node}: {e}"
            ) from None
        origin = node_domain.origin or SourceMap(str(node))  # read_node records the lines
        points, point_lines, first_id = node_domain.points, origin.points, origin.first_id
        point_markers = node_domain.point_markers
        points_file = str(node)
    segments, segment_lines, segment_markers = _read_segments(lines, len(points), first_id)
    holes, hole_lines = _read_rows(lines, "hole", 3, required=True)
    regions, region_lines = _read_rows(
        lines, "regional attribute", 4, required=False, optional="the maximum area"
    )  # rows x, y, attribute, maximum area (NaN when absent)
    lines.expect_end()
    origin = SourceMap(
        file=str(path), first_id=first_id, points_file=points_file, points=point_lines,
        segments=segment_lines, holes=hole_lines, regions=region_lines,
    )  # fmt: skip
    return Domain(
        points, segments, holes[:, :2], regions[:, :3], source=str(path), origin=origin,
        point_markers=point_markers, segment_markers=segment_markers, region_max_areas=regions[:, 3],
    )  # fmt: skip


def _optional_count(head: Line, k: int, what: str, default: int = 0) -> int:
    """Token ``k`` of a header line as a count, or ``default`` when the line is shorter."""
    return head.count(k, what) if len(head.tokens) > k else default


def _read_vertices(lines: Lines) -> tuple[np.ndarray, np.ndarray, int, np.ndarray | None]:
    """Header and vertex lines: (points (n,2), 1-based line per point, first id, markers (n,) or None)."""
    head = lines.next("the vertex count line")
    n = head.count(0, "the vertex count")
    dim = head.int(1, "the dimension") if len(head.tokens) > 1 else 2
    if dim != 2:
        raise head.error(f"the dimension must be 2, found {dim}")
    n_attr = _optional_count(head, 2, "the number of vertex attributes")
    n_mark = _optional_count(head, 3, "the number of boundary markers")
    if n_mark > 1:
        raise head.error(f"the number of boundary markers must be 0 or 1, found {n_mark}")
    width = 3 + n_attr + n_mark
    fast = lines.numbers(n, width, (0, width - 1) if n_mark else (0,))
    if fast is not None:
        values, point_lines = fast
        ids = values[:, 0].astype(np.int64)
        if ids[0] in (0, 1) and np.array_equal(ids, np.arange(ids[0], ids[0] + n)):
            lines.skip(n)
            markers = values[:, -1].astype(np.int64) if n_mark else None
            return np.ascontiguousarray(values[:, 1:3]), point_lines, int(ids[0]), markers
    room = lines.room_for(n)
    points = np.empty((room, 2), dtype=np.float64)
    point_lines = np.empty(room, dtype=np.int64)
    markers = np.zeros(room, dtype=np.int64) if n_mark else None
    try:
        first_id = _vertex_lines(lines, n, n_attr, n_mark, points, point_lines, markers)
    except InvalidInputError as e:
        if room == n:
            raise
        # a count the rest of the file cannot hold: the line blamed may belong to a later section, so also
        # name the count and its line
        raise InvalidInputError(f"{e} (the vertex count {n} at {head.file}:{head.number} is more than the "
                                f"{room} lines after it)") from None
    return points, point_lines, first_id, markers


def _vertex_lines(lines: Lines, n: int, n_attr: int, n_mark: int, points: np.ndarray, point_lines: np.ndarray,
                  markers: np.ndarray | None) -> int:
    """Read ``n`` vertex lines one by one into ``points``, ``point_lines`` and ``markers``; the first id."""
    first_id = 0
    for k in range(n):
        line = lines.next(f"vertex {k + 1} of {n}").need(3 + n_attr + n_mark, "id, x, y, attributes, markers")
        vid = line.int(0, "the vertex id")
        if k == 0:
            if vid not in (0, 1):
                raise line.error(f"the first vertex id must be 0 or 1, found {vid}")
            first_id = vid
        elif vid != first_id + k:
            raise line.error(f"vertex ids must be consecutive: expected {first_id + k}, found {vid}")
        points[k] = line.float(1, "x"), line.float(2, "y")
        for j in range(3, 3 + n_attr):
            line.float(j, f"vertex attribute {j - 2}")
        if markers is not None:
            markers[k] = line.int(3 + n_attr, "the boundary marker")
        point_lines[k] = line.number
    return first_id


def _read_segments(
    lines: Lines, n_points: int, first_id: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """The segment section: (segments (m, 2) 0-based, line per segment, markers (m,) or None)."""
    head = lines.next("the segment count line")
    m = head.count(0, "the segment count")
    n_mark = _optional_count(head, 1, "the number of boundary markers")
    if n_mark > 1:
        raise head.error(f"the number of boundary markers must be 0 or 1, found {n_mark}")
    fast = lines.numbers(m, 3 + n_mark, tuple(range(3 + n_mark)))
    if fast is not None and (segments := _ids_in_range(fast[0][:, 1:3], n_points, first_id)) is not None:
        lines.skip(m)
        return segments, fast[1], fast[0][:, 3].astype(np.int64) if n_mark else None
    markers = np.zeros(lines.room_for(m), dtype=np.int64) if n_mark else None
    segments = np.empty((lines.room_for(m), 2), dtype=np.int64)
    seg_lines = np.empty(lines.room_for(m), dtype=np.int64)
    for k in range(m):
        line = lines.next(f"segment {k + 1} of {m}").need(3 + n_mark, "id, endpoint, endpoint, markers")
        line.int(0, "the segment id")
        segments[k] = _vertex_ids(line, 2, n_points, first_id, "segment endpoint")
        if markers is not None:
            markers[k] = line.int(3, "the boundary marker")
        seg_lines[k] = line.number
    return segments, seg_lines, markers


def _ids_in_range(ids: np.ndarray, n_points: int, first_id: int) -> np.ndarray | None:
    """Integer-valued float ids (k, c) as 0-based int64 indices, or None when one is out of range (the
    line-by-line reader then names it)."""
    v = ids.astype(np.int64) - first_id
    return np.ascontiguousarray(v) if len(v) == 0 or (v.min() >= 0 and v.max() < n_points) else None


def _vertex_ids(line: Line, count: int, n_points: int, first_id: int, what: str) -> list[int]:
    """Tokens 1..count of ``line`` as 0-based vertex indices; the error names the id and the valid range."""
    ids = []
    for j in range(1, count + 1):
        v = line.int(j, f"a {what}") - first_id
        if not 0 <= v < n_points:
            raise line.error(
                f"{what} {v + first_id} does not exist: vertex ids run from {first_id} to "
                f"{n_points - 1 + first_id}"
            )
        ids.append(v)
    return ids


def _read_rows(
    lines: Lines, what: str, width: int, *, required: bool, optional: str | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """A count line and ``<id> <numbers...>`` lines of ``width`` tokens (plus the ``optional`` number when
    given). Returns (rows (k, width - 1) float64, plus a last column holding the optional number or NaN when
    ``optional`` is given; line per row). A section not ``required`` may be absent."""
    cols = width - 1 + bool(optional)
    if not required and lines.at_end():
        return np.zeros((0, cols)), np.zeros(0, dtype=np.int64)
    head = lines.next(f"the {what} count line")
    k = head.count(0, f"the {what} count")
    rows = np.full((lines.room_for(k), cols), np.nan, dtype=np.float64)
    row_lines = np.empty(lines.room_for(k), dtype=np.int64)
    names = ["x", "y", "attribute"]
    for i in range(k):
        line = lines.next(f"{what} {i + 1} of {k}").need(width, f"id, {', '.join(names[: width - 1])}")
        line.int(0, f"the {what} id")
        rows[i, : width - 1] = [line.float(j, names[j - 1]) for j in range(1, width)]
        if optional and len(line.tokens) > width:
            rows[i, width - 1] = line.float(width, optional)
        row_lines[i] = line.number
    return rows, row_lines


def output_paths(path: Path) -> list[Path]:
    """The files :func:`write_triangle` writes for ``path``: its .node, .ele and .poly siblings."""
    return list(triangle_mesh_files(path))


def write_triangle(mesh: Mesh, path: Path) -> list[Path]:
    """Write ``stem.node`` (points, with a boundary marker column when the mesh has point markers),
    ``stem.ele`` (triangles, with the region attribute when present) and ``stem.poly`` (0 vertices, i.e.
    those of the .node; every constrained subsegment, with a marker column when the mesh has segment
    markers; no holes), ids 1-based, coordinates in shortest round-trip form (float64 exact). Each file
    atomically. Returns the paths."""
    node, ele, poly = triangle_mesh_files(path)
    with atomic_text(node) as f:
        f.write(f"# written by nonobtuse\n{len(mesh.points)} 2 0 {int(mesh.point_markers is not None)}\n")
        markers = _column(mesh.point_markers, len(mesh.points))
        rows = zip(mesh.points.tolist(), markers)
        f.writelines(f"{i} {x!r} {y!r}{m}\n" for i, ((x, y), m) in enumerate(rows, start=1))
    with atomic_text(ele) as f:
        regions = mesh.regions
        f.write(f"# written by nonobtuse\n{len(mesh.triangles)} 3 {int(regions is not None)}\n")
        tri = (mesh.triangles + 1).tolist()
        attr = _column(None if mesh.regions is None else np.asarray(mesh.regions, np.float64), len(tri))
        f.writelines(f"{i} {a} {b} {c}{r}\n" for i, ((a, b, c), r) in enumerate(zip(tri, attr), start=1))
    with atomic_text(poly) as f:
        marked = int(mesh.segment_markers is not None)
        f.write(f"# written by nonobtuse; vertices in {node.name}\n0 2 0 0\n{len(mesh.segments)} {marked}\n")
        markers = _column(mesh.segment_markers, len(mesh.segments))
        rows = zip((mesh.segments + 1).tolist(), markers)
        f.writelines(f"{i} {a} {b}{m}\n" for i, ((a, b), m) in enumerate(rows, start=1))
        f.write("0\n")
    return [node, ele, poly]


def _column(values: np.ndarray | None, n: int) -> list[str]:
    """One optional trailing column: ``" value"`` per row (repr: floats round-trip), or empty strings."""
    return [""] * n if values is None else [f" {v!r}" for v in values.tolist()]


def triangle_mesh_files(path: Path) -> tuple[Path, Path, Path]:
    """The ``.node``, ``.ele`` and ``.poly`` files of the mesh that ``path`` (any of the three) names; the
    stem may hold dots (Triangle's ``la.1.ele``)."""
    stem = path.with_suffix("")
    node, ele, poly = (stem.with_name(stem.name + s) for s in (".node", ".ele", ".poly"))
    return node, ele, poly


def read_triangle_mesh(path: Path) -> Mesh:
    """A mesh in Triangle's files (ours or Triangle's own output, e.g. ``la.1.node``/``.ele``/``.poly``):
    ``path`` is any of the three; the ``.node`` and ``.ele`` must exist.

    points and point markers from the ``.node``; triangles (as listed: Triangle writes them
    counter-clockwise) and the first triangle attribute as the region from the ``.ele`` (second-order
    triangles, 6 nodes, are refused); segments and segment markers from the ``.poly`` when it exists (its
    vertex count must be 0 or its vertices those of the .node), else the edges with a triangle on one side
    only. Such files do not record the input domain: every point counts as an input point. Checks structure
    (counts, ids, index ranges), not geometry. Raises InvalidInputError naming file:line."""
    node, ele, poly = triangle_mesh_files(path)
    for f in (node, ele):
        if not f.is_file():
            raise InvalidInputError(f"{path}: a Triangle mesh needs {f.name} beside it, and it is missing")
    lines = Lines(node)
    points, _, first_id, point_markers = _read_vertices(lines)
    lines.expect_end()
    triangles, regions = _read_elements(Lines(ele), len(points), first_id)
    if poly.is_file():
        segments, segment_markers = _read_poly_segments(poly, points, first_id)
    else:
        segments, segment_markers = _boundary_edges(triangles), None
    return Mesh(
        points, triangles, segments, points.copy(), segments.copy(), regions,
        stats={"source": str(path)}, point_markers=point_markers, segment_markers=segment_markers,
    )  # fmt: skip


def _read_elements(lines: Lines, n_points: int, first_id: int) -> tuple[np.ndarray, np.ndarray | None]:
    """The .ele file: (triangles (m, 3) 0-based, the first attribute (m,) or None)."""
    head = lines.next("the triangle count line")
    m = head.count(0, "the triangle count")
    corners = _optional_count(head, 1, "the number of nodes per triangle", 3)
    if corners != 3:
        raise head.error(f"only 3-node triangles are read, found {corners} nodes per triangle")
    n_attr = _optional_count(head, 2, "the number of attributes")
    fast = lines.numbers(m, 4 + n_attr, (1, 2, 3))
    if fast is not None and (triangles := _ids_in_range(fast[0][:, 1:4], n_points, first_id)) is not None:
        lines.skip(m)
        lines.expect_end()
        return triangles, np.ascontiguousarray(fast[0][:, 4]) if n_attr else None
    triangles = np.empty((m, 3), dtype=np.int64)
    regions = np.empty(m, dtype=np.float64) if n_attr else None
    for k in range(m):
        line = lines.next(f"triangle {k + 1} of {m}").need(4 + n_attr, "id, three corners, attributes")
        triangles[k] = _vertex_ids(line, 3, n_points, first_id, "triangle corner")
        if regions is not None:
            regions[k] = line.float(4, "the triangle attribute")
    lines.expect_end()
    return triangles, regions


def _read_poly_segments(
    poly: Path, points: np.ndarray, first_id: int
) -> tuple[np.ndarray, np.ndarray | None]:
    lines = Lines(poly)
    own, _, _, _ = _read_vertices(lines)
    if len(own) and not np.array_equal(own, points):
        raise InvalidInputError(f"{poly}: its vertices are not those of the .node file beside it")
    segments, _, markers = _read_segments(lines, len(points), first_id)
    return segments, markers


def _boundary_edges(triangles: np.ndarray) -> np.ndarray:
    """The edges (k, 2), a < b, sorted, that have a triangle on one side only."""
    e = np.sort(np.stack([triangles, np.roll(triangles, -1, axis=1)], axis=2).reshape(-1, 2), axis=1)
    edges, count = np.unique(e, axis=0, return_counts=True)
    return np.ascontiguousarray(edges[count == 1])
