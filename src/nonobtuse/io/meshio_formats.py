"""VTK ``.vtu`` (written directly as binary appended raw: :func:`write_vtu`; read through meshio) and Gmsh
``.msh`` (format 2.2, binary, through meshio), and the conversion of a 2D :class:`~nonobtuse.mesh.Mesh` to
and from a ``meshio.Mesh``.

The meshio form: points padded with z = 0; cell blocks ``triangle`` then ``line`` (the constrained
subsegments); cell data ``region`` (the region attribute on triangles, 0 on lines) and ``marker`` (the
segment marker on lines, 0 on triangles) when the mesh has them; point data ``point_marker``.

In ``.msh`` the region and the segment marker are the integer physical tags (``gmsh:physical``, also written
as ``gmsh:geometrical``) of the triangles and of the lines. Region attributes are floats: when every one is
an integer they are their own tags, otherwise the distinct values, ascending, get the tags 1, 2, ... The
mapping is written beside the mesh as ``NAME.msh.regions.json`` (``{"tag_to_region": {"1": 0.25, ...}}``)
whenever the mesh has regions, and :func:`read_meshio` maps the tags back through it when it is there.
Point markers are ``$NodeData`` ``point_marker`` (floats, exact for markers up to 2**53).
"""

from __future__ import annotations

import contextlib
import io
import json
import warnings
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np

from nonobtuse.errors import InvalidInputError
from nonobtuse.io._files import atomic_path, atomic_text, read_text
from nonobtuse.markers import as_int32
from nonobtuse.mesh import Mesh


class MeshioFormat(NamedTuple):
    """meshio's names of one file format: to read it, and to write it."""

    read: str
    write: str


# The mesh formats written and read through meshio, by suffix: the one table the 2D and 3D readers and
# writers use. Gmsh is written as format 2.2, which needs no entity topology for mixed cell types.
FORMATS = {".vtu": MeshioFormat("vtu", "vtu"), ".msh": MeshioFormat("gmsh", "gmsh22")}
_INT32 = np.iinfo(np.int32)


def region_tags(regions: np.ndarray) -> tuple[np.ndarray, dict[int, float]]:
    """Integer tags (m,) int32 for float region attributes (m,), and the map tag -> attribute. Integer
    attributes in the int32 range are their own tags; otherwise the distinct values, ascending, get 1, 2..."""
    regions = np.asarray(regions, dtype=np.float64)
    integral = bool(np.all(regions == np.round(regions))) and bool(
        np.all((regions >= _INT32.min) & (regions <= _INT32.max))
    )
    if integral:
        tags = regions.astype(np.int32)
        return tags, {int(t): float(t) for t in np.unique(tags)}
    values, inverse = np.unique(regions, return_inverse=True)
    return (inverse.ravel() + 1).astype(np.int32), {i + 1: float(v) for i, v in enumerate(values)}


def to_meshio(mesh: Mesh, *, gmsh: bool = False) -> Any:
    """``mesh`` as a ``meshio.Mesh`` (the form in the module docstring). gmsh=True writes the region and
    segment markers as physical tags instead (the regions mapped by :func:`region_tags`)."""
    import meshio

    points = np.column_stack([mesh.points, np.zeros(len(mesh.points))])
    cells = [("triangle", mesh.triangles), ("line", mesh.segments)]
    m, k = len(mesh.triangles), len(mesh.segments)
    markers = np.zeros(k, np.int64) if mesh.segment_markers is None else mesh.segment_markers
    point_data = {}
    if mesh.point_markers is not None:
        point_data["point_marker"] = mesh.point_markers.astype(np.float64 if gmsh else np.int64)
    if gmsh:
        tags = region_tags(mesh.regions)[0] if mesh.regions is not None else np.zeros(m, np.int32)
        physical = [tags, as_int32(markers, "the .msh segment markers")]
        cell_data = {"gmsh:physical": physical, "gmsh:geometrical": physical}
    else:
        cell_data = {}
        if mesh.regions is not None:
            cell_data["region"] = [np.asarray(mesh.regions, np.float64), np.zeros(k)]
        if mesh.segment_markers is not None:
            cell_data["marker"] = [np.zeros(m, np.int64), markers]
    return meshio.Mesh(points, cells, cell_data=cell_data, point_data=point_data)


def from_meshio(m: Any, where: str = "<meshio>", region_map: dict[int, float] | None = None) -> Mesh:
    """A 2D :class:`Mesh` from a ``meshio.Mesh`` with triangle cells (and line cells for the segments).

    Regions from cell data ``region``, else ``gmsh:physical`` on the triangles (mapped through
    ``region_map`` when given); segment markers from ``marker``, else ``gmsh:physical`` on the lines; point
    markers from point data ``point_marker``. Such a mesh does not record its input domain: its
    ``input_points`` are all its points and ``input_segments`` its segments. Raises InvalidInputError (naming
    ``where``) for points off the plane z = 0, no triangle cells, or markers that are not integers.
    """
    points = np.ascontiguousarray(np.asarray(m.points)[:, :2], dtype=np.float64)
    if m.points.shape[1] > 2 and np.any(m.points[:, 2] != 0):
        raise InvalidInputError(f"{where}: the mesh is not planar (some z coordinate is not 0)")
    tri = [i for i, c in enumerate(m.cells) if c.type == "triangle"]
    if not tri:
        raise InvalidInputError(f"{where}: the mesh has no triangle cells")
    lines = [i for i, c in enumerate(m.cells) if c.type == "line"]
    triangles = np.concatenate([m.cells[i].data for i in tri]).astype(np.int64)
    segments = np.concatenate([m.cells[i].data for i in lines]).astype(np.int64).reshape(-1, 2)

    def cell_values(key: str, blocks: list[int]) -> np.ndarray | None:
        if key not in m.cell_data or not blocks:
            return None
        return np.concatenate([np.asarray(m.cell_data[key][i]).ravel() for i in blocks])

    regions = cell_values("region", tri)
    if regions is None:
        regions = regions_from_tags(cell_values("gmsh:physical", tri), region_map, where)
    markers = cell_values("marker", lines)
    if markers is None:
        markers = cell_values("gmsh:physical", lines)
    if markers is None and "marker" in m.cell_data and not lines:
        markers = np.zeros(0, np.int64)
    point_markers = m.point_data.get("point_marker")
    return Mesh(
        points, triangles, segments, points.copy(), segments.copy(),
        None if regions is None else np.asarray(regions, dtype=np.float64),
        point_markers=_integers(point_markers, "point_marker", where),
        segment_markers=_integers(markers, "segment marker", where),
    )  # fmt: skip


def _integers(values: Any, what: str, where: str) -> np.ndarray | None:
    if values is None:
        return None
    arr = np.asarray(values).ravel()
    if arr.dtype.kind == "f" and not np.all(arr == np.round(arr)):
        raise InvalidInputError(f"{where}: the {what}s must be integers")
    return arr.astype(np.int64)


def regions_from_tags(
    tags: np.ndarray | None, region_map: dict[int, float] | None, where: str
) -> np.ndarray | None:
    """Region attributes from gmsh physical tags: through ``region_map`` when given, else the tags
    themselves; None when there are no tags, or no map and every tag is 0 (gmsh's "no physical group")."""
    if tags is None or (region_map is None and not np.any(tags != 0)):
        return None
    return unmap_regions(tags, region_map, where) if region_map is not None else tags.astype(np.float64)


def unmap_regions(tags: np.ndarray, region_map: dict[int, float], where: str) -> np.ndarray:
    """The region attributes of physical ``tags`` through ``region_map``; InvalidInputError for a tag that
    is not in it."""
    missing = sorted(set(np.unique(tags).tolist()) - set(region_map))
    if missing:
        raise InvalidInputError(f"{where}: physical tags {missing[:5]} are not in the region map")
    keys = np.array(sorted(region_map), dtype=np.int64)
    values = np.array([region_map[k] for k in keys.tolist()], dtype=np.float64)
    return values[np.searchsorted(keys, tags)]


def region_map_path(path: Path) -> Path:
    """Where the tag -> region map of a .msh file lives: ``NAME.msh.regions.json`` beside it."""
    return path.with_name(path.name + ".regions.json")


def write_meshio(mesh: Mesh, path: Path) -> list[Path]:
    """Write .vtu (:func:`write_vtu`) or .msh (meshio; the module docstring), atomically; for a .msh of a mesh
    with regions also the region map beside it. Returns the paths written."""
    if path.suffix.lower() == ".vtu":
        write_vtu(mesh, path)
        return [path]
    import meshio

    with atomic_path(path) as tmp:
        meshio.write(tmp, to_meshio(mesh, gmsh=True), file_format=FORMATS[".msh"].write)
    if mesh.regions is None:
        return [path]
    return [path, write_region_map(path, mesh.regions)]


_VTK_TRIANGLE, _VTK_LINE = 5, 3
_VTK_TYPES = {"f": ("<f8", "Float64"), "i": ("<i8", "Int64"), "u": ("u1", "UInt8")}  # by numpy kind


def write_vtu(mesh: Mesh, path: Path) -> None:
    """The meshio form of ``mesh`` (the module docstring: points with z = 0, the triangles then the
    segments as line cells, cell data ``region``/``marker``, point data ``point_marker``) as a VTK XML
    UnstructuredGrid, binary appended raw (little-endian, UInt64 block headers, uncompressed), atomically.
    Each array goes from numpy to the file directly, so memory stays at one array's copy (meshio's writer
    builds base64 strings and zlib-compresses, about 8x slower). Cost: O(n) writes, no compression."""
    m, k = len(mesh.triangles), len(mesh.segments)
    cell_data = {}
    if mesh.regions is not None:
        cell_data["region"] = np.concatenate([np.asarray(mesh.regions, np.float64), np.zeros(k)])
    if mesh.segment_markers is not None:
        cell_data["marker"] = np.concatenate([np.zeros(m, np.int64), mesh.segment_markers])
    point_data = {} if mesh.point_markers is None else {"point_marker": mesh.point_markers}
    points = np.zeros((len(mesh.points), 3), dtype="<f8")
    points[:, :2] = mesh.points
    sections = {
        "Points": {"Points": points},
        "Cells": {
            "connectivity": np.concatenate([mesh.triangles.ravel(), mesh.segments.ravel()]),
            "offsets": np.concatenate([np.arange(1, m + 1) * 3, 3 * m + np.arange(1, k + 1) * 2]),
            "types": np.repeat(np.array([_VTK_TRIANGLE, _VTK_LINE], np.uint8), [m, k]),
        },
        "PointData": point_data,
        "CellData": cell_data,
    }
    blocks, xml, offset = [], [], 0
    for section, arrays in sections.items():
        xml.append(f"<{section}>")
        for name, values in arrays.items():
            dtype, vtk_type = _VTK_TYPES[values.dtype.kind]
            values = np.ascontiguousarray(values, dtype=dtype)
            width = values.shape[1] if values.ndim == 2 else 1
            xml.append(
                f'<DataArray type="{vtk_type}" Name="{name}" NumberOfComponents="{width}" '
                f'format="appended" offset="{offset}"/>'
            )
            blocks.append(values)
            offset += 8 + values.nbytes
        xml.append(f"</{section}>")
    head = (
        '<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" '
        f'header_type="UInt64">\n<UnstructuredGrid>\n<Piece NumberOfPoints="{len(points)}" '
        f'NumberOfCells="{m + k}">\n' + "\n".join(xml) + '\n</Piece>\n</UnstructuredGrid>\n'
        '<AppendedData encoding="raw">\n_'
    )
    with atomic_path(path) as tmp, open(tmp, "wb") as f:
        f.write(head.encode("ascii"))
        for values in blocks:
            f.write(np.uint64(values.nbytes).astype("<u8").tobytes())
            f.write(values.data.cast("B"))
        f.write(b"\n</AppendedData>\n</VTKFile>\n")


def write_region_map(path: Path, regions: np.ndarray) -> Path:
    """Write the tag -> region map of :func:`region_tags` beside the .msh file ``path``, atomically; returns
    its path."""
    table = region_map_path(path)
    with atomic_text(table) as f:
        mapping = region_tags(regions)[1]
        json.dump({"tag_to_region": {str(k): v for k, v in mapping.items()}}, f, indent=1)
        f.write("\n")
    return table


def read_region_map(path: Path) -> dict[int, float] | None:
    """The tag -> region map beside the .msh file ``path``, or None when there is none."""
    table = region_map_path(path)
    if not table.is_file():
        return None
    try:
        data = json.loads(read_text(table))["tag_to_region"]
        return {int(k): float(v) for k, v in data.items()}
    except (json.JSONDecodeError, KeyError, TypeError, ValueError, AttributeError) as e:
        raise InvalidInputError(f"{table}: not a region map ({type(e).__name__}: {e})") from None


def meshio_read(path: Path, file_format: str) -> Any:
    """``meshio.read`` with InvalidInputError naming ``path`` for any failure: an empty file, any exception
    meshio raises, and the ``sys.exit(1)`` meshio calls (after printing its ReadError to stdout and a line
    to stderr) when its reader gives up; what meshio printed becomes part of the message."""
    import meshio

    if path.is_file() and path.stat().st_size == 0:
        raise InvalidInputError(f"{path}: the file is empty")
    printed = io.StringIO()
    try:
        with (warnings.catch_warnings(), contextlib.redirect_stdout(printed),
              contextlib.redirect_stderr(printed)):
            warnings.simplefilter("ignore")  # meshio warns about formats details it skips
            return meshio.read(path, file_format=file_format)
    except SystemExit:
        lines = [line.strip() for line in printed.getvalue().splitlines()]
        detail = "; ".join(line for line in lines if line and "Couldn't read file" not in line)
        raise InvalidInputError(f"{path}: cannot read the mesh as {file_format}"
                                + (f" ({detail})" if detail else "")) from None
    except Exception as e:  # meshio raises many types (ReadError, ValueError, KeyError) for broken files
        raise InvalidInputError(f"{path}: cannot read the mesh ({type(e).__name__}: {e})") from None


def read_meshio(path: Path) -> Mesh:
    """Triangles and line cells of a .vtu/.msh file, with regions and markers (:func:`from_meshio`; a .msh
    with a region map beside it gets its float regions back)."""
    m = meshio_read(path, FORMATS[path.suffix.lower()].read)
    region_map = read_region_map(path) if path.suffix.lower() == ".msh" else None
    return from_meshio(m, str(path), region_map)
