"""3D data model: piecewise linear complexes (the input) and tetrahedral meshes (the output)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np


@dataclass
class PLC:
    """A piecewise linear complex in 3D.

    points:     (n, 3) float64.
    triangles:  (m, 3) int64: the facets, triangulated; consistently oriented (outward for a closed surface).
    facet_ids:  (m,) int64: the input facet (polygon) each triangle belongs to. Triangles of one planar
                polygon share an id; in a triangle soup (OFF/STL/...) the loader merges adjacent exactly
                coplanar triangles into one facet.
    segments:   (k, 2) int64: PLC segments: edges where two facets meet at a non-flat angle, plus dangling
                input segments.
    holes:      (h, 3) float64 volume-hole seeds.
    regions:    (r, 4) float64 rows x, y, z, attribute.
    source:     where it came from, for messages.
    warnings:   what validation accepted but a user should know (dangling faces, faces it reoriented).
    facet_markers: (F,) int64 the marker of each facet id (F = facet_ids.max() + 1): TetGen's facet boundary
                marker, an OBJ group, a PLY face property; None when the input has none (every marker 0).
    region_volumes: (r,) float64 the volume constraint of each row of regions (TetGen's region list), NaN
                where none; empty when the input has no such list.
    """

    points: np.ndarray
    triangles: np.ndarray
    facet_ids: np.ndarray
    segments: np.ndarray = field(default_factory=lambda: np.zeros((0, 2), dtype=np.int64))
    holes: np.ndarray = field(default_factory=lambda: np.zeros((0, 3), dtype=np.float64))
    regions: np.ndarray = field(default_factory=lambda: np.zeros((0, 4), dtype=np.float64))
    source: str = "<memory>"
    warnings: tuple[str, ...] = ()
    facet_markers: np.ndarray | None = None
    region_volumes: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.float64))

    def markers_of_facets(self, facets: np.ndarray) -> np.ndarray:
        """The markers (k,) int64 of facet ids (k,): ``facet_markers[facets]``, 0 for every facet when the PLC
        has no markers, -1 where the facet id is -1 (unknown, e.g. fTetWild's remeshed boundary)."""
        facets = np.asarray(facets, dtype=np.int64).ravel()
        if self.facet_markers is None:
            return np.where(facets < 0, -1, 0).astype(np.int64)
        return np.where(facets < 0, -1, self.facet_markers[np.maximum(facets, 0)]).astype(np.int64)


@dataclass
class TetMesh:
    """A tetrahedral mesh of a PLC.

    points:          (n, 3) float64; the PLC's points first, in input order, Steiner points after.
    tets:            (t, 4) int64, positively oriented.
    boundary_faces:  (f, 3) int64: the triangles covering the PLC's facets (subfacets).
    face_markers:    (f,) int64: the marker of the input facet of each boundary face (subfacets keep their
                     facet's marker; 0 when the PLC has no markers, -1 when the facet is unknown).
    segments:        (k, 2) int64: subsegments of the PLC's segments.
    tet_regions:     (t,) float64 region attribute per tet, or None.
    stats:           backend, timings, refinement status and diagnosis.
    face_facets:     (f,) int64: the input facet id of each boundary face (-1: unknown), or None.
    """

    points: np.ndarray
    tets: np.ndarray
    boundary_faces: np.ndarray
    face_markers: np.ndarray
    segments: np.ndarray = field(default_factory=lambda: np.zeros((0, 2), dtype=np.int64))
    tet_regions: np.ndarray | None = None
    stats: dict[str, Any] = field(default_factory=dict)
    face_facets: np.ndarray | None = None

    def to_meshio(self) -> Any:
        """This mesh as a ``meshio.Mesh``: cell blocks ``tetra`` and ``triangle`` (the boundary faces), cell
        data ``region``, ``marker`` and ``facet`` (see :mod:`nonobtuse.io.tetmesh`)."""
        from nonobtuse.io.tetmesh import tetmesh_to_meshio

        return tetmesh_to_meshio(self)

    @classmethod
    def from_meshio(cls, m: Any) -> TetMesh:
        """A TetMesh from a ``meshio.Mesh`` with tetra (and triangle) cells; data read as :meth:`to_meshio`
        writes it, or from gmsh tags. Raises InvalidInputError when there are no tetra cells."""
        from nonobtuse.io.tetmesh import tetmesh_from_meshio

        return tetmesh_from_meshio(m)


def region_attributes(tet_regions: np.ndarray, plc: PLC, conforming: bool) -> np.ndarray | None:
    """The region attribute per tet (t,) float64 to report for a mesh of `plc`: `tet_regions` as computed, or
    None when the PLC has no region seeds and either the tets form a single region (nothing to tell apart) or
    the mesh does not conform to the facets (`conforming` False: its components, numbered when there are no
    seeds, are then pieces cut by the leaks, not the PLC's regions)."""
    tet_regions = np.asarray(tet_regions, dtype=np.float64)
    one_value = not len(tet_regions) or tet_regions.min() == tet_regions.max()  # O(t), no sort
    if not len(plc.regions) and (not conforming or one_value):
        return None
    return tet_regions
