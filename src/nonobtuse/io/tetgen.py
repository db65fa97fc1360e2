"""TetGen PLC files: .poly (facets of polygons with facet holes) and .smesh (one polygon per facet), with
facet boundary markers (when the facet header's marker flag is 1), volume holes and regions; nodes from the
sibling .node file when the node count is 0. Errors name file:line."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from nonobtuse.io._files import Line, Lines
from nonobtuse.io.raw3d import Facet, RawInput, floats, ints

SUFFIXES = (".poly", ".smesh")


def read_tetgen(path: Path) -> RawInput:
    """TetGen .poly (facets of polygons with facet holes) or .smesh (one polygon per facet)."""
    lines = Lines(path)
    head = lines.next("the node header")
    n_nodes = head.count(0, "the number of nodes")
    dim = head.int(1, "the dimension") if len(head.tokens) > 1 else 3
    if dim != 3:
        raise head.error(f"dimension {dim}: only 3D PLCs are read here")
    if n_nodes == 0:
        points, first_index = _read_nodes(Lines(path.with_suffix(".node")))
    else:
        points, first_index = _node_rows(lines, n_nodes, _node_width(head))
    base = first_index if first_index in (0, 1) else 0
    facet_head = lines.next("the facet header")
    n_facets = facet_head.count(0, "the number of facets")
    marked = facet_head.count(1, "the boundary marker flag") if len(facet_head.tokens) > 1 else 0
    if marked > 1:
        raise facet_head.error(f"the boundary marker flag must be 0 or 1, found {marked}")
    read_facet = _smesh_facet if path.suffix == ".smesh" else _poly_facet
    rows = [read_facet(lines, base, j, bool(marked)) for j in range(n_facets)]
    holes = _point_list(lines, "hole", 3)
    regions, volumes = _region_list(lines) if not lines.at_end() else (np.zeros((0, 4)), np.zeros(0))
    markers = np.array([m for _, m in rows], dtype=np.int64) if marked else None
    return RawInput(points, [f for f, _ in rows], holes, regions, source=str(path), facet_markers=markers,
                    region_volumes=volumes)


def _node_width(head: Line) -> int:
    """The tokens of a node line the header announces: index, x, y, z, attributes, marker (the fast path's
    guess; the line-by-line reader needs only the first four)."""
    return 4 + sum(int(t) for t in head.tokens[2:4] if t.isascii() and t.isdigit())


def _node_rows(lines: Lines, n: int, width: int) -> tuple[np.ndarray, int]:
    """n node lines "index x y z ..."; returns the coordinates and the first index (0 or 1 based)."""
    fast = lines.numbers(n, width, (0,))
    if fast is not None:
        lines.skip(n)
        return np.ascontiguousarray(fast[0][:, 1:4]), int(fast[0][0, 0])
    rows = [lines.next(f"node {i}").need(4, f"node {i}: an index and 3 coordinates") for i in range(n)]
    points = np.array([floats(r, 1, 3, f"node {i}") for i, r in enumerate(rows)], dtype=np.float64)
    return points.reshape(-1, 3), (rows[0].int(0, "the node index") if rows else 0)


def _read_nodes(lines: Lines) -> tuple[np.ndarray, int]:
    head = lines.next("the node header")
    n = head.count(0, "the number of nodes")
    if n == 0:
        raise head.error("no nodes")
    return _node_rows(lines, n, _node_width(head))


def _loop(line: Line, base: int, what: str) -> np.ndarray:
    n = line.count(0, f"the vertex count of {what}")
    return np.array(ints(line, 1, n, what), dtype=np.int64) - base


def _smesh_facet(lines: Lines, base: int, j: int, marked: bool) -> tuple[Facet, int]:
    """``<n> v1 ... vn [marker]``: the facet and its marker (0 when not ``marked`` or absent)."""
    line = lines.next(f"facet {j}")
    loop = _loop(line, base, f"facet {j}")
    at = len(loop) + 1
    marker = line.int(at, f"the boundary marker of facet {j}") if marked and len(line.tokens) > at else 0
    return Facet([loop], where=f"{line.file}:{line.number}"), marker


def _poly_facet(lines: Lines, base: int, j: int, marked: bool) -> tuple[Facet, int]:
    """``<#polygons> [#holes] [marker]``, the polygons, the hole points: the facet and its marker (0 when
    not ``marked`` or absent, as TetGen reads it)."""
    head = lines.next(f"facet {j}")
    n_polygons = head.count(0, f"the polygon count of facet {j}")
    n_holes = head.count(1, f"the hole count of facet {j}") if len(head.tokens) > 1 else 0
    marker = head.int(2, f"the boundary marker of facet {j}") if marked and len(head.tokens) > 2 else 0
    loops = [_loop(lines.next(f"facet {j} polygon {k}"), base, f"facet {j} polygon {k}")
             for k in range(n_polygons)]
    holes = [floats(lines.next(f"facet {j} hole {k}"), 1, 3, f"facet {j} hole {k}") for k in range(n_holes)]
    where = f"{head.file}:{head.number}"
    return Facet(loops, np.array(holes, dtype=np.float64).reshape(-1, 3), where), marker


def _region_list(lines: Lines) -> tuple[np.ndarray, np.ndarray]:
    """``<index> x y z attribute [max volume]`` lines: the rows (r, 4) and the volume constraints (r,), NaN
    where a line has none."""
    n = lines.next("the region list").count(0, "the number of regions")
    rows = [lines.next(f"region {k}") for k in range(n)]
    regions = np.array([floats(r, 1, 4, f"region {k}") for k, r in enumerate(rows)], dtype=np.float64)
    volumes = np.array([r.float(5, f"the volume constraint of region {k}") if len(r.tokens) > 5 else np.nan
                        for k, r in enumerate(rows)], dtype=np.float64)
    for k in np.flatnonzero(np.isinf(volumes)):
        raise rows[k].error(f"the volume constraint of region {k} must be finite, found {volumes[k]}")
    return regions.reshape(-1, 4), volumes


def _point_list(lines: Lines, what: str, cols: int) -> np.ndarray:
    n = lines.next(f"the {what} list").count(0, f"the number of {what}s")
    rows = [floats(lines.next(f"{what} {k}"), 1, cols, f"{what} {k}") for k in range(n)]
    return np.array(rows, dtype=np.float64).reshape(-1, cols)
