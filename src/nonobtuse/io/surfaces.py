"""Triangle-surface formats: OFF, OBJ, PLY (through meshio) and STL (binary and ASCII; exactly equal vertices
are merged, first occurrence first). Each reader returns a :class:`~nonobtuse.io.raw3d.RawInput` of one
polygon per face; OFF and OBJ errors name file:line.

Facet markers where the format has them: OBJ groups (``g name``; faces before the first ``g`` are in no
group, marker 0): when every group name is an integer it is the marker, otherwise the groups are numbered
1, 2, ... in order of first appearance. PLY: an integer face property named one of :data:`PLY_MARKERS`."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from nonobtuse.errors import InvalidInputError
from nonobtuse.io._files import Lines
from nonobtuse.io.raw3d import Facet, RawInput, TriangleFacets, floats, ints, merge_equal_points, points_array

SUFFIXES = (".off", ".obj", ".ply", ".stl")
PLY_MARKERS = ("marker", "boundary_marker", "label", "group")  # the first present is the facet marker


def read_off(path: Path) -> RawInput:
    lines = Lines(path)
    head = lines.next("the OFF header")
    if not head.tokens[0].upper().endswith("OFF"):
        raise head.error(f"not an OFF file: the first line is {' '.join(head.tokens)!r}, expected 'OFF'")
    counts = head if len(head.tokens) > 1 else lines.next("the OFF counts")
    start = 1 if counts is head else 0
    nv, nf = (counts.count(start + k, "the OFF counts") for k in range(2))
    fast = lines.numbers(nv, 3)
    pts: np.ndarray | list[list[float]]
    if fast is not None:
        lines.skip(nv)
        pts = fast[0]
    else:
        pts = [floats(lines.next(f"vertex {i}"), 0, 3, f"vertex {i}") for i in range(nv)]
    triangles = _off_triangles(lines, nf)
    if triangles is not None:
        return RawInput(points_array(pts), triangles, source=str(path))
    facets = []
    for j in range(nf):
        line = lines.next(f"face {j}")
        n = line.count(0, f"the vertex count of face {j}")
        facets.append(Facet([np.array(ints(line, 1, n, f"face {j}"), dtype=np.int64)],
                            where=f"{line.file}:{line.number}"))
    return RawInput(points_array(pts), facets, source=str(path))


def _off_triangles(lines: Lines, nf: int) -> TriangleFacets | None:
    """The next ``nf`` faces when every one is a triangle on a plain numeric line (``3 i j k``: the fast
    path, :meth:`Lines.numbers`), else None and nothing consumed (the line reader names any problem)."""
    fast = lines.numbers(nf, 4, (0, 1, 2, 3))
    if fast is None or not np.all(fast[0][:, 0] == 3):
        return None
    lines.skip(nf)
    corners = fast[0][:, 1:].astype(np.int64)
    return TriangleFacets(corners, str(lines.file), fast[1])


def read_obj(path: Path) -> RawInput:
    lines = Lines(path)
    pts, facets, groups, group = [], [], [], None
    while not lines.at_end():
        line = lines.next("a line")
        if line.tokens[0] == "g":
            group = " ".join(line.tokens[1:])
        elif line.tokens[0] == "v":
            pts.append(floats(line, 1, 3, "a vertex"))
        elif line.tokens[0] == "f":
            line.tokens = [w.split("/")[0] for w in line.tokens]  # v/vt/vn: the vertex index
            idx = ints(line, 1, len(line.tokens) - 1, "a face")
            if 0 in idx:
                raise line.error("face vertex index 0: OBJ indices start at 1 (negative ones count back from "
                                 "the last vertex)")
            # OBJ indices are 1-based; negative ones count back from the last vertex read so far
            idx = [i - 1 if i > 0 else len(pts) + i for i in idx]
            facets.append(Facet([np.array(idx, dtype=np.int64)], where=f"{line.file}:{line.number}"))
            groups.append(group)
    return RawInput(points_array(pts), facets, source=str(path), facet_markers=_group_markers(groups))


def _group_markers(groups: list[str | None]) -> np.ndarray | None:
    """Markers of the OBJ faces from their group names (None: no group), or None when there is no group."""
    names = list(dict.fromkeys(g for g in groups if g is not None))
    if not names:
        return None
    if all(re.fullmatch(r"[+-]?\d+", g) for g in names):
        number = {g: int(g) for g in names}
    else:
        number = {g: i for i, g in enumerate(names, start=1)}
    return np.array([0 if g is None else number[g] for g in groups], dtype=np.int64)


def read_ply(path: Path) -> RawInput:
    import meshio

    if not path.read_bytes()[:3] == b"ply":
        raise InvalidInputError(f"{path}: not a PLY file (it does not start with 'ply')")
    try:
        m = meshio.read(path, file_format="ply")
    except Exception as e:  # meshio raises bare errors of many types on malformed files
        raise InvalidInputError(f"{path}: malformed PLY file: {e}") from None
    facets, markers = [], []
    key = next((k for k in PLY_MARKERS if k in m.cell_data), None)
    for i, block in enumerate(m.cells):
        if block.type in ("triangle", "quad", "polygon"):
            facets += [Facet([np.asarray(c, dtype=np.int64)], where=f"{path}: face") for c in block.data]
            if key is not None:
                markers.append(np.asarray(m.cell_data[key][i]).ravel())
    facet_markers = None
    if key is not None:
        facet_markers = np.concatenate(markers) if markers else np.zeros(0)
        if facet_markers.dtype.kind == "f" and not np.all(facet_markers == np.round(facet_markers)):
            raise InvalidInputError(f"{path}: the face property '{key}' must hold integers (facet markers)")
        facet_markers = facet_markers.astype(np.int64)
    points = np.asarray(m.points, dtype=np.float64)
    return RawInput(points, facets, source=str(path), facet_markers=facet_markers)


_STL_RECORD = np.dtype([("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])


def read_stl(path: Path) -> RawInput:
    data = path.read_bytes()
    if not data.strip():
        raise InvalidInputError(f"{path}: the file is empty")
    n = int.from_bytes(data[80:84], "little") if len(data) >= 84 else -1
    if n >= 0 and 84 + 50 * n == len(data):  # binary (the header may still start with "solid")
        corners = np.frombuffer(data, dtype=_STL_RECORD, count=n, offset=84)["v"].reshape(-1, 3)
    elif data.lstrip()[:5].lower() == b"solid":
        nums = re.findall(rb"vertex\s+(\S+)\s+(\S+)\s+(\S+)", data)
        try:
            corners = np.array([[float(x) for x in row] for row in nums], dtype=np.float64).reshape(-1, 3)
        except ValueError:
            raise InvalidInputError(f"{path}: malformed ASCII STL vertex line") from None
        if len(corners) % 3:
            raise InvalidInputError(f"{path}: ASCII STL with {len(corners)} vertices, not a multiple of 3")
    else:
        raise InvalidInputError(f"{path}: not an STL file (neither binary of consistent size nor 'solid' "
                                f"ASCII)")
    points, inverse = merge_equal_points(corners.astype(np.float64))
    faces = inverse.reshape(-1, 3)
    return RawInput(points, [Facet([f]) for f in faces], source=str(path))
