"""Simulator exports of a 2D or 3D mesh: the one place that picks a writer from the output name.

=================  ==========================================================================================
``OUT.uge``        PFLOTRAN explicit unstructured grid, plus ``OUT_boundary_<marker>.ex`` (:mod:`.pflotran`)
``OUT.stor``       FEHM sparse matrix, plus ``OUT.fehmn`` and zone files (:mod:`.fehm`)
``MESH``, ``.tough``  TOUGH2/TOUGH3 ELEME and CONNE blocks (:mod:`.tough`)
``OUT.csv``        cell, connection and boundary tables (:mod:`.cv_table`)
``OUT.npz``        the same as numpy arrays (:mod:`.cv_table`)
=================  ==========================================================================================

Every format is written from one :class:`~nonobtuse.io.cv_grid.ControlVolumeGrid` (Voronoi volumes, dual face
areas with exact signs, distances, boundary pieces with markers).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

from nonobtuse.errors import InvalidInputError
from nonobtuse.io import cv_table, fehm, pflotran, tough
from nonobtuse.io.cv_grid import AnyMesh, ControlVolumeGrid, grid_from_mesh

Writer = Callable[[ControlVolumeGrid, Path], list[Path]]
_BY_SUFFIX: dict[str, Writer] = {".uge": pflotran.write_uge, ".stor": fehm.write_fehm,
                                 ".tough": tough.write_tough_mesh, ".csv": cv_table.write_csv,
                                 ".npz": cv_table.write_npz}
EXPORT_NAMES = (*_BY_SUFFIX, "MESH")


def _writer(path: Path) -> Writer | None:
    if path.name == "MESH":
        return tough.write_tough_mesh
    return _BY_SUFFIX.get(path.suffix.lower())


def is_export_path(path: str | os.PathLike) -> bool:
    """True when ``path`` names a simulator export (.uge, .stor, MESH or .tough, .csv, .npz)."""
    return _writer(Path(path)) is not None


def export_mesh(mesh: AnyMesh, path: str | os.PathLike, *, thickness: float = 1.0
                ) -> tuple[ControlVolumeGrid, list[Path]]:
    """Build the control-volume grid of ``mesh`` (2D Mesh extruded by ``thickness``, or 3D TetMesh) and write
    it in the format ``path`` names. Returns the grid (for its ``diagnostics()``) and the paths written.
    Raises InvalidInputError on an unknown format or a mesh that has no control volumes. Cost: the grid,
    O(m log m), plus the writing, linear in its size."""
    path = Path(path)
    writer = _writer(path)
    if writer is None:
        raise InvalidInputError(f"{path}: unknown export format '{path.suffix}' (expected .uge, .stor, "
                                "MESH or .tough, .csv, .npz)")
    grid = grid_from_mesh(mesh, thickness=thickness)
    return grid, writer(grid, path)


__all__ = ["EXPORT_NAMES", "export_mesh", "is_export_path"]
