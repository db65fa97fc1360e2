"""The offenders of a 3D Gabriel check as a mesh for ParaView: the encroached boundary faces (triangles), the
encroached subsegments (lines) and the vertices encroaching them (vertex cells), with cell data saying which
input facet, which marker and how deep the encroachment is."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from nonobtuse.mesh3d.gabriel import GabrielReport
from nonobtuse.mesh3d.plc import TetMesh


def encroaching_vertices(report: GabrielReport) -> tuple[np.ndarray, np.ndarray]:
    """The distinct mesh vertices (v,) int64, ascending, that are the deepest encroacher of some encroached
    face or subsegment of ``report``, and for each the largest depth (v,) float64 it reaches."""
    vertices = np.concatenate([report.face_vertices, report.segment_vertices]).astype(np.int64)
    depths = np.concatenate([report.face_depths, report.segment_depths]).astype(np.float64)
    unique, inverse = np.unique(vertices, return_inverse=True)
    deepest = np.full(len(unique), -np.inf)
    np.maximum.at(deepest, inverse, depths)
    return unique, deepest


def offenders_to_meshio(mesh: TetMesh, report: GabrielReport) -> Any:
    """A ``meshio.Mesh`` of the offenders of ``report`` (its points: the mesh points they use, ascending,
    with point data ``vertex``, their index in ``mesh.points``), cell blocks (empty ones left out)
    ``triangle``: the encroached rows of mesh.boundary_faces, ``line``: the encroached rows of mesh.segments,
    ``vertex``: the vertices of :func:`encroaching_vertices`. Cell data: ``row`` (the face's or subsegment's
    row in the mesh; the vertex index for vertex cells), ``facet`` (input facet id of a face, -1 otherwise or
    when unknown), ``marker`` (the face's marker, 0 otherwise), ``vertex`` (the deepest encroaching vertex;
    itself for a vertex cell), ``depth`` (1 - distance to the sphere's centre / radius, in (0, 1]: the
    fraction of the radius by which the vertex is inside; for a vertex cell the largest it reaches). Depths
    are floating point, for display; which faces are encroached is the exact check's answer. None when there
    is no offender."""
    import meshio

    if report.ok:
        return None
    faces = np.asarray(mesh.boundary_faces, dtype=np.int64).reshape(-1, 3)[report.faces]
    segments = np.asarray(mesh.segments, dtype=np.int64).reshape(-1, 2)[report.segments]
    vertices, vertex_depths = encroaching_vertices(report)
    used, local = np.unique(np.concatenate([faces.ravel(), segments.ravel(), vertices]), return_inverse=True)
    cut = np.cumsum([faces.size, segments.size])
    facet_ids = (np.full(len(mesh.boundary_faces), -1, np.int64) if mesh.face_facets is None
                 else np.asarray(mesh.face_facets, dtype=np.int64))
    markers = np.asarray(mesh.face_markers, dtype=np.int64)
    blocks = [
        ("triangle", local[:cut[0]].reshape(-1, 3), report.faces, facet_ids[report.faces],
         markers[report.faces], report.face_vertices, report.face_depths),
        ("line", local[cut[0]:cut[1]].reshape(-1, 2), report.segments, np.full(len(segments), -1),
         np.zeros(len(segments)), report.segment_vertices, report.segment_depths),
        ("vertex", local[cut[1]:].reshape(-1, 1), vertices, np.full(len(vertices), -1),
         np.zeros(len(vertices)), vertices, vertex_depths),
    ]
    blocks = [b for b in blocks if len(b[1])]  # meshio's VTU writer fails on an empty block
    names = ("row", "facet", "marker", "vertex", "depth")
    types = (np.int64, np.int64, np.int64, np.int64, np.float64)
    cell_data = {name: [np.asarray(b[2 + i], dtype=t) for b in blocks] for i, (name, t) in
                 enumerate(zip(names, types))}
    return meshio.Mesh(np.asarray(mesh.points, dtype=np.float64)[used], [(b[0], b[1]) for b in blocks],
                       point_data={"vertex": used}, cell_data=cell_data)


def write_offenders(mesh: TetMesh, report: GabrielReport, path: str | Path) -> int:
    """Write :func:`offenders_to_meshio` to ``path`` (.vtu, binary; atomically) and return its number of
    cells (encroached faces + encroached subsegments + distinct encroaching vertices). A Gabriel mesh has no
    offender: nothing is written (a VTU without points is not read back by meshio) and 0 is returned. Cost:
    linear in the offenders, plus O(n) to select their points."""
    import meshio

    from nonobtuse.io import atomic_path

    m = offenders_to_meshio(mesh, report)
    if m is None:
        return 0
    with atomic_path(Path(path)) as tmp:
        meshio.write(tmp, m, file_format="vtu")
    return sum(len(c.data) for c in m.cells)
