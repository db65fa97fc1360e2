"""PFLOTRAN explicit unstructured grid: ``.uge`` (cells and connections) and ``.ex`` boundary connections.

``OUT.uge`` (``GRID / TYPE UNSTRUCTURED_EXPLICIT OUT.uge``), ids 1-based::

    CELLS <n>
    <id> <x> <y> <z> <volume>                 one per control volume (a mesh vertex and its Voronoi cell)
    CONNECTIONS <c>
    <id_up> <id_dn> <x> <y> <z> <area>        one per mesh edge: the dual face's centre (the edge midpoint)
                                              and area

``OUT_boundary_<marker>.ex``, one per boundary marker (``REGION ... FILE OUT_boundary_<marker>.ex``)::

    CONNECTIONS <k>
    <id> <x> <y> <z> <area>                   one per boundary face piece of that marker

Floats are written in shortest round-trip form (they read back as the same float64). Atomic per file.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from nonobtuse.io._files import atomic_text
from nonobtuse.io.cv_grid import ControlVolumeGrid
from nonobtuse.io.cv_table import text_rows


def boundary_path(path: Path, marker: int) -> Path:
    """The .ex file of one boundary marker beside ``path``."""
    return path.with_name(f"{path.stem}_boundary_{marker}.ex")


def write_uge(grid: ControlVolumeGrid, path: str | Path) -> list[Path]:
    """Write ``path`` (.uge) and one .ex file per boundary marker beside it. Returns the paths written.
    Cost: O(n + c + b) lines."""
    path = Path(path)
    n, c = len(grid.volumes), len(grid.connections)
    ids = np.arange(1, n + 1)
    with atomic_text(path) as f:
        f.write(f"CELLS {n}\n")
        f.write(text_rows(ids, *grid.centers.T, grid.volumes))
        f.write(f"CONNECTIONS {c}\n")
        up, down = grid.connections.T + 1
        f.write(text_rows(up, down, *grid.face_centers.T, grid.areas))
    written = [path]
    for marker in np.unique(grid.boundary_markers).tolist():
        rows = np.flatnonzero(grid.boundary_markers == marker)
        ex = boundary_path(path, marker)
        with atomic_text(ex) as f:
            f.write(f"CONNECTIONS {len(rows)}\n")
            f.write(text_rows(grid.boundary_cells[rows] + 1, *grid.boundary_centers[rows].T,
                          grid.boundary_areas[rows]))
        written.append(ex)
    return written


__all__ = ["boundary_path", "write_uge"]
