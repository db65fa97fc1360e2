"""VTK ``.vtu`` and Gmsh ``.msh`` (format 2.2) through meshio: triangles, constrained segments as line cells,
the region attribute as triangle cell data ``region`` (.vtu) or as the integer physical tag (.msh; 0 when the
mesh has no regions)."""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import NamedTuple

import numpy as np

from nonobtuse.errors import InvalidInputError
from nonobtuse.io._files import atomic_path
from nonobtuse.mesh import Mesh


class MeshioFormat(NamedTuple):
    """meshio's names of one file format: to read it, and to write it."""

    read: str
    write: str


# The mesh formats written and read through meshio, by suffix: the one table the 2D and 3D readers and
# writers use. Gmsh is written as format 2.2, which needs no entity topology for mixed cell types.
FORMATS = {".vtu": MeshioFormat("vtu", "vtu"), ".msh": MeshioFormat("gmsh", "gmsh22")}


def write_meshio(mesh: Mesh, path: Path) -> None:
    """Points padded with z = 0 (both formats are 3D); cell blocks ``triangle`` then ``line``; cell data
    ``region`` (0 on line cells) when the mesh has regions. Atomic."""
    import meshio

    points = np.column_stack([mesh.points, np.zeros(len(mesh.points))])
    cells = [("triangle", mesh.triangles), ("line", mesh.segments)]
    regions = np.zeros(len(mesh.triangles)) if mesh.regions is None else np.asarray(mesh.regions, np.float64)
    if path.suffix.lower() == ".msh":  # Gmsh: the region is the triangle's physical tag, an integer
        if np.any(regions != np.round(regions)):
            raise InvalidInputError(
                f"{path}: .msh stores regions as integer physical tags; these are not integers"
            )
        tags = [regions.astype(np.int32), np.zeros(len(mesh.segments), np.int32)]
        cell_data: dict[str, list[np.ndarray]] = {"gmsh:physical": tags, "gmsh:geometrical": tags}
    else:
        cell_data = {"region": [regions, np.zeros(len(mesh.segments))]} if mesh.regions is not None else {}
    with atomic_path(path) as tmp:
        fmt = FORMATS[path.suffix.lower()].write
        meshio.write(tmp, meshio.Mesh(points, cells, cell_data=cell_data), file_format=fmt)


def read_meshio(path: Path) -> Mesh:
    """Triangles and line cells of a .vtu/.msh file. Such files do not record the input domain: the mesh's
    ``input_points`` are all its points and ``input_segments`` its segments (no Steiner points known)."""
    import meshio

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # meshio warns about formats details it skips
            m = meshio.read(path, file_format=FORMATS[path.suffix.lower()].read)
    except Exception as e:  # meshio raises many types (ReadError, ValueError, KeyError) for broken files
        raise InvalidInputError(f"{path}: cannot read the mesh ({type(e).__name__}: {e})") from None
    points = np.ascontiguousarray(m.points[:, :2], dtype=np.float64)
    if m.points.shape[1] > 2 and np.any(m.points[:, 2] != 0):
        raise InvalidInputError(f"{path}: the mesh is not planar (some z coordinate is not 0)")
    tri = [(i, c.data) for i, c in enumerate(m.cells) if c.type == "triangle"]
    if not tri:
        raise InvalidInputError(f"{path}: the mesh has no triangle cells")
    lines = [c.data for c in m.cells if c.type == "line"]
    triangles = np.concatenate([t for _, t in tri]).astype(np.int64)
    segments = np.concatenate(lines).astype(np.int64) if lines else np.zeros((0, 2), np.int64)
    regions = None
    key = "gmsh:physical" if path.suffix.lower() == ".msh" else "region"
    if key in m.cell_data:
        regions = np.concatenate([np.asarray(m.cell_data[key][i], dtype=np.float64) for i, _ in tri])
    return Mesh(points, triangles, segments, points.copy(), segments.copy(), regions)
