"""Writing and reading tetrahedral meshes: the JSON schema, and .vtu / .msh through meshio. Writes are atomic
(a temporary file in the target directory, then os.replace).

JSON schema (one object): ``points`` (n, 3) floats, the PLC's points first and in input order; ``tets`` (t, 4)
positively oriented; ``boundary_faces`` (f, 3); ``face_markers`` (f,); ``segments`` (k, 2); ``stats`` with at
least ``status``, ``steiner_points``, ``encroached_facets``, ``encroached_segments``, ``seconds`` (null when
not known). Floats are written with repr, so they read back bit for bit.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np

from nonobtuse.errors import InvalidInputError
from nonobtuse.io._files import atomic_path, atomic_text, jsonable
from nonobtuse.io.meshio_formats import FORMATS as MESHIO_FORMATS
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
    return out


def write_tetmesh(mesh: TetMesh, path: str | Path) -> None:
    """Write `mesh` to `path` by suffix: .json (schema above), .vtu or .msh (meshio: tetra and triangle
    blocks, cell data "marker": face markers on triangles, region attribute (or 0) on tets). Atomic."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".json":
        text = json.dumps(tetmesh_to_dict(mesh))
        with atomic_text(path) as f:
            f.write(text)
    elif suffix in MESHIO_FORMATS:
        with atomic_path(path) as tmp:
            _write_meshio(mesh, tmp, MESHIO_FORMATS[suffix].write)
    else:
        raise InvalidInputError(f"{path}: unknown mesh format {suffix!r}; expected .json, .vtu or .msh")


def _write_meshio(mesh: TetMesh, tmp: Path, fmt: str) -> None:
    import meshio

    tets = np.asarray(mesh.tets, dtype=np.int64)
    regions = np.zeros(len(tets)) if mesh.tet_regions is None else np.asarray(mesh.tet_regions, dtype=float)
    blocks = [("tetra", tets, regions.astype(np.int64)),
              ("triangle", np.asarray(mesh.boundary_faces, dtype=np.int64).reshape(-1, 3),
               np.asarray(mesh.face_markers, dtype=np.int64))]
    blocks = [b for b in blocks if len(b[1])]  # meshio's VTU writer fails on an empty block (no tets)
    cells = [(kind, rows) for kind, rows, _ in blocks]
    data = {"marker": [markers for _, _, markers in blocks]}
    if fmt == "gmsh22":  # gmsh needs its physical/geometrical tags
        data = {"gmsh:physical": data["marker"], "gmsh:geometrical": data["marker"]}
    meshio.write(tmp, meshio.Mesh(mesh.points, cells, cell_data=data), file_format=fmt,
                 **({"binary": False} if fmt == "gmsh22" else {}))


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
                       d.get("stats", {}))
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise InvalidInputError(f"{path}: not a 3D mesh JSON file ({type(e).__name__}: {e})") from None
