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
Vertex attributes, boundary markers and maximum areas are read (and checked to be numbers) but not kept: the
:class:`Domain` has no place for them. Every error names ``file:line``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from nonobtuse.domain import Domain, SourceMap
from nonobtuse.errors import InvalidInputError
from nonobtuse.io._files import Lines, atomic_text
from nonobtuse.mesh import Mesh


def read_node(path: Path) -> Domain:
    """A ``.node`` file as a point set (no segments; ``convex_hull=True``)."""
    lines = Lines(path)
    points, point_lines, first_id = _read_vertices(lines)
    if len(points) == 0:
        raise InvalidInputError(f"{path}: the .node file lists no vertices")
    lines.expect_end()
    origin = SourceMap(file=str(path), first_id=first_id, points=point_lines)
    return Domain(points, convex_hull=True, source=str(path), origin=origin)


def read_poly(path: Path) -> Domain:
    """A ``.poly`` file as a Domain (``convex_hull=False``; :func:`nonobtuse.io.load_domain` decides)."""
    lines = Lines(path)
    points, point_lines, first_id = _read_vertices(lines)
    points_file = None
    if len(points) == 0:
        node = path.with_suffix(".node")
        try:
            node_domain = read_node(node)
        except InvalidInputError as e:
            raise InvalidInputError(
                f"{path}: the vertex count is 0, so the vertices come from {node}: {e}"
            ) from None
        points, point_lines, first_id = (
            node_domain.points,
            node_domain.origin.points,
            node_domain.origin.first_id,
        )
        points_file = str(node)
    segments, segment_lines = _read_segments(lines, len(points), first_id)
    holes, hole_lines = _read_rows(lines, "hole", 3, required=True)
    regions, region_lines = _read_rows(
        lines, "regional attribute", 4, required=False, optional="the maximum area"
    )
    lines.expect_end()
    origin = SourceMap(
        file=str(path), first_id=first_id, points_file=points_file, points=point_lines,
        segments=segment_lines, holes=hole_lines, regions=region_lines,
    )  # fmt: skip
    return Domain(points, segments, holes[:, :2], regions[:, :3], source=str(path), origin=origin)


def _read_vertices(lines: Lines) -> tuple[np.ndarray, np.ndarray, int]:
    """Header and vertex lines: (points (n,2), 1-based line per point, first id)."""
    head = lines.next("the vertex count line")
    n = head.count(0, "the vertex count")
    dim = head.int(1, "the dimension") if len(head.tokens) > 1 else 2
    if dim != 2:
        raise head.error(f"the dimension must be 2, found {dim}")
    n_attr = head.count(2, "the number of vertex attributes") if len(head.tokens) > 2 else 0
    n_mark = head.count(3, "the number of boundary markers") if len(head.tokens) > 3 else 0
    if n_mark > 1:
        raise head.error(f"the number of boundary markers must be 0 or 1, found {n_mark}")
    points = np.empty((lines.room_for(n), 2), dtype=np.float64)
    point_lines = np.empty(lines.room_for(n), dtype=np.int64)
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
        if n_mark:
            line.int(3 + n_attr, "the boundary marker")
        point_lines[k] = line.number
    return points, point_lines, first_id


def _read_segments(lines: Lines, n_points: int, first_id: int) -> tuple[np.ndarray, np.ndarray]:
    head = lines.next("the segment count line")
    m = head.count(0, "the segment count")
    n_mark = head.count(1, "the number of boundary markers") if len(head.tokens) > 1 else 0
    segments = np.empty((lines.room_for(m), 2), dtype=np.int64)
    seg_lines = np.empty(lines.room_for(m), dtype=np.int64)
    for k in range(m):
        line = lines.next(f"segment {k + 1} of {m}").need(3 + n_mark, "id, endpoint, endpoint, markers")
        line.int(0, "the segment id")
        for j in (1, 2):
            v = line.int(j, "a segment endpoint") - first_id
            if not 0 <= v < n_points:
                raise line.error(
                    f"segment endpoint {v + first_id} does not exist: vertex ids run from {first_id} to "
                    f"{n_points - 1 + first_id}"
                )
            segments[k, j - 1] = v
        if n_mark:
            line.int(3, "the boundary marker")
        seg_lines[k] = line.number
    return segments, seg_lines


def _read_rows(
    lines: Lines, what: str, width: int, *, required: bool, optional: str | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """A count line and ``<id> <numbers...>`` lines of ``width`` tokens (plus the ``optional`` number when
    given). Returns (rows (k, width - 1) float64, line per row). A section not ``required`` may be absent."""
    if not required and lines.at_end():
        return np.zeros((0, width - 1)), np.zeros(0, dtype=np.int64)
    head = lines.next(f"the {what} count line")
    k = head.count(0, f"the {what} count")
    rows = np.empty((lines.room_for(k), width - 1), dtype=np.float64)
    row_lines = np.empty(lines.room_for(k), dtype=np.int64)
    names = ["x", "y", "attribute"]
    for i in range(k):
        line = lines.next(f"{what} {i + 1} of {k}").need(width, f"id, {', '.join(names[: width - 1])}")
        line.int(0, f"the {what} id")
        rows[i] = [line.float(j, names[j - 1]) for j in range(1, width)]
        if optional and len(line.tokens) > width:
            line.float(width, optional)
        row_lines[i] = line.number
    return rows, row_lines


def output_paths(path: Path) -> list[Path]:
    """The files :func:`write_triangle` writes for ``path``: its .node, .ele and .poly siblings."""
    stem = path.with_suffix("")
    return [stem.with_suffix(s) for s in (".node", ".ele", ".poly")]


def write_triangle(mesh: Mesh, path: Path) -> list[Path]:
    """Write ``stem.node`` (points), ``stem.ele`` (triangles, with the region attribute when present) and
    ``stem.poly`` (0 vertices, i.e. those of the .node; every constrained subsegment; no holes), ids 1-based,
    coordinates in shortest round-trip form (float64 exact). Each file atomically. Returns the paths."""
    node, ele, poly = output_paths(path)
    with atomic_text(node) as f:
        f.write(f"# written by nonobtuse\n{len(mesh.points)} 2 0 0\n")
        f.writelines(f"{i} {x!r} {y!r}\n" for i, (x, y) in enumerate(mesh.points.tolist(), start=1))
    with atomic_text(ele) as f:
        regions = mesh.regions is not None
        f.write(f"# written by nonobtuse\n{len(mesh.triangles)} 3 {int(regions)}\n")
        tri = (mesh.triangles + 1).tolist()
        attr = [f" {r!r}" for r in mesh.regions.tolist()] if regions else [""] * len(tri)
        f.writelines(f"{i} {a} {b} {c}{r}\n" for i, ((a, b, c), r) in enumerate(zip(tri, attr), start=1))
    with atomic_text(poly) as f:
        f.write(f"# written by nonobtuse; vertices in {node.name}\n0 2 0 0\n{len(mesh.segments)} 0\n")
        f.writelines(f"{i} {a} {b}\n" for i, (a, b) in enumerate((mesh.segments + 1).tolist(), start=1))
        f.write("0\n")
    return [node, ele, poly]
