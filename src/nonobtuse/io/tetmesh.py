"""Writing and reading tetrahedral meshes: the JSON schema, and .vtu / .msh through meshio. Writes are atomic
(a temporary file in the target directory, then os.replace).

JSON schema (one object): ``points`` (n, 3) floats, the PLC's points first and in input order; ``tets`` (t, 4)
positively oriented; ``boundary_faces`` (f, 3); ``face_markers`` (f,) the input facet's marker of each face;
``face_facets`` (f,) its input facet id (optional); ``segments`` (k, 2); ``tet_regions`` (t,) the region
attribute of each tet (optional); ``stats`` with at least ``status``, ``steiner_points``,
``encroached_facets``, ``encroached_segments``, ``seconds`` (null when not known). Floats are written with
repr, so they read back bit for bit.

meshio form (:meth:`TetMesh.to_meshio`): cell blocks ``tetra`` then ``triangle`` (the boundary faces);
cell data ``region`` (the region attribute on tets, 0 on triangles; when the mesh has regions), ``marker``
(the face marker on triangles, 0 on tets) and ``facet`` (the facet id on triangles, -1 on tets; when
known). In .msh the physical tag of a tet is its region (mapped to integers as in 2D, with the map beside
the file as ``NAME.msh.regions.json``) and of a triangle its face marker; the geometrical tag of a
triangle is its facet id + 1 (0 when unknown).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np

from nonobtuse.errors import InvalidInputError
from nonobtuse.io._files import atomic_path, atomic_text, jsonable
from nonobtuse.io.meshio_formats import FORMATS as MESHIO_FORMATS
from nonobtuse.io.meshio_formats import (
    meshio_read,
    read_region_map,
    region_tags,
    regions_from_tags,
    write_region_map,
)
from nonobtuse.markers import as_int32
from nonobtuse.mesh3d.plc import TetMesh

REQUIRED_STATS = ("status", "steiner_points", "encroached_facets", "encroached_segments", "seconds")


def tetmesh_to_dict(mesh: TetMesh) -> dict[str, Any]:
    """The JSON schema object of `mesh` (stats keys of REQUIRED_STATS filled with None when absent)."""
    stats = {k: None for k in REQUIRED_STATS}
    stats.update(jsonable(mesh.stats))
    out = {"points": mesh.points.tolist(), "tets": np.asarray(mesh.tets).tolist(),
           "boundary_faces": np.asarray(mesh.boundary_faces).tolist(),
           "face_markers": np.asarray(mesh.face_markers).tolist(),
           "segments": np.asarray(mesh.segments).tolist(), "stats": stats}
    if mesh.tet_regions is not None:
        out["tet_regions"] = np.asarray(mesh.tet_regions).tolist()
    if mesh.face_facets is not None:
        out["face_facets"] = np.asarray(mesh.face_facets).tolist()
    return out


def write_tetmesh(mesh: TetMesh, path: str | Path) -> list[Path]:
    """Write `mesh` to `path` by suffix: .json (schema above), .vtu or .msh (the meshio form above; a .msh
    of a mesh with regions also writes its region map). Atomic. Returns the paths written."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".json":
        text = json.dumps(tetmesh_to_dict(mesh))
        with atomic_text(path) as f:
            f.write(text)
        return [path]
    if suffix not in MESHIO_FORMATS:
        raise InvalidInputError(f"{path}: unknown mesh format {suffix!r}; expected .json, .vtu or .msh")
    import meshio

    gmsh = MESHIO_FORMATS[suffix].write == "gmsh22"
    with atomic_path(path) as tmp:
        meshio.write(tmp, tetmesh_to_meshio(mesh, gmsh=gmsh), file_format=MESHIO_FORMATS[suffix].write,
                     **({"binary": False} if gmsh else {}))
    if not (gmsh and mesh.tet_regions is not None):
        return [path]
    return [path, write_region_map(path, mesh.tet_regions)]


def tetmesh_to_meshio(mesh: TetMesh, *, gmsh: bool = False) -> Any:
    """`mesh` as a ``meshio.Mesh`` (module docstring); gmsh=True: physical and geometrical tags instead."""
    import meshio

    tets = np.asarray(mesh.tets, dtype=np.int64).reshape(-1, 4)
    faces = np.asarray(mesh.boundary_faces, dtype=np.int64).reshape(-1, 3)
    t, f = len(tets), len(faces)
    markers = np.asarray(mesh.face_markers, dtype=np.int64)
    facets = None if mesh.face_facets is None else np.asarray(mesh.face_facets, dtype=np.int64)
    regions = None if mesh.tet_regions is None else np.asarray(mesh.tet_regions, dtype=np.float64)
    if gmsh:
        tags = np.zeros(t, np.int32) if regions is None else region_tags(regions)[0]
        geometrical = np.zeros(f, np.int32) if facets is None else (facets + 1).astype(np.int32)
        physical = [tags, as_int32(markers, "the .msh face markers")]
        data = {"gmsh:physical": physical, "gmsh:geometrical": [tags, geometrical]}
    else:
        data = {"marker": [np.zeros(t, np.int64), markers]}
        if regions is not None:
            data["region"] = [regions, np.zeros(f)]
        if facets is not None:
            data["facet"] = [np.full(t, -1, np.int64), facets]
    blocks = [i for i, n in enumerate((t, f)) if n]  # meshio's VTU writer fails on an empty block (no tets)
    cells = [[("tetra", tets), ("triangle", faces)][i] for i in blocks]
    return meshio.Mesh(mesh.points, cells, cell_data={k: [v[i] for i in blocks] for k, v in data.items()})


def tetmesh_from_meshio(
    m: Any, where: str = "<meshio>", region_map: dict[int, float] | None = None
) -> TetMesh:
    """A TetMesh from a ``meshio.Mesh`` with tetra (and triangle) cells, reading the data
    :func:`tetmesh_to_meshio` writes (or gmsh tags: physical tags as regions and face markers, geometrical
    tags - 1 as facet ids). Every point counts as given; segments are not stored in these formats (empty).
    Raises InvalidInputError naming ``where`` for a mesh with no tetra cells."""
    tet_blocks = [i for i, c in enumerate(m.cells) if c.type == "tetra"]
    face_blocks = [i for i, c in enumerate(m.cells) if c.type == "triangle"]
    if not tet_blocks:
        raise InvalidInputError(f"{where}: the mesh has no tetra cells")

    def values(key: str, blocks: list[int]) -> np.ndarray | None:
        if key not in m.cell_data:
            return None
        return np.concatenate([np.asarray(m.cell_data[key][i]).ravel() for i in blocks] or [np.zeros(0)])

    tets = np.concatenate([m.cells[i].data for i in tet_blocks]).astype(np.int64)
    faces = np.concatenate([m.cells[i].data for i in face_blocks] or [np.zeros((0, 3))]).astype(np.int64)
    regions, markers, facets = (values(k, b) for k, b in
                                (("region", tet_blocks), ("marker", face_blocks), ("facet", face_blocks)))
    if regions is None:
        regions = regions_from_tags(values("gmsh:physical", tet_blocks), region_map, where)
    if markers is None:
        markers = values("gmsh:physical", face_blocks)
    if facets is None and (geometrical := values("gmsh:geometrical", face_blocks)) is not None:
        facets = geometrical - 1
    return TetMesh(
        np.ascontiguousarray(m.points, dtype=np.float64), tets, faces,
        np.zeros(len(faces), np.int64) if markers is None else markers.astype(np.int64),
        tet_regions=None if regions is None else regions.astype(np.float64),
        face_facets=None if facets is None else facets.astype(np.int64),
    )  # fmt: skip


def read_tetmesh(path: str | Path) -> TetMesh:
    """Read a TetMesh from .json (:func:`read_tetmesh_json`), .vtu or .msh (:func:`tetmesh_from_meshio`; a
    .msh with a region map beside it gets its float regions back). InvalidInputError names the file."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".json":
        return read_tetmesh_json(path)
    if suffix not in MESHIO_FORMATS:
        raise InvalidInputError(f"{path}: unknown mesh format {suffix!r}; expected .json, .vtu or .msh")
    m = meshio_read(path, MESHIO_FORMATS[suffix].read)
    return tetmesh_from_meshio(m, str(path), read_region_map(path) if suffix == ".msh" else None)


def read_tetmesh_json(path: str | Path) -> TetMesh:
    """Read a TetMesh written by :func:`write_tetmesh` as .json."""
    path = Path(path)
    try:
        d = json.loads(path.read_text())
        return TetMesh(np.array(d["points"], dtype=np.float64).reshape(-1, 3),
                       np.array(d["tets"], dtype=np.int64).reshape(-1, 4),
                       np.array(d["boundary_faces"], dtype=np.int64).reshape(-1, 3),
                       np.array(d["face_markers"], dtype=np.int64),
                       np.array(d["segments"], dtype=np.int64).reshape(-1, 2),
                       np.array(d["tet_regions"], dtype=np.float64) if "tet_regions" in d else None,
                       d.get("stats", {}),
                       np.array(d["face_facets"], dtype=np.int64) if "face_facets" in d else None)
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise InvalidInputError(f"{path}: not a 3D mesh JSON file ({type(e).__name__}: {e})") from None
