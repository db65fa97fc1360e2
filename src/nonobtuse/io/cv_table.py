"""Plain tables of the control-volume grid, for any simulator: CSV and NPZ.

``OUT.csv`` (cells), ``OUT_connections.csv`` and ``OUT_boundary.csv``, comma-separated with a header line,
ids 0-based (cell i is mesh point ``point``), floats in shortest round-trip form::

    cell,point,x,y,z,volume,material
    cell_a,cell_b,area,distance,coefficient,sign,x,y,z      coefficient -area/distance, exact sign -1/0/1
    cell,marker,area,x,y,z

``OUT.npz``: the same columns as arrays, named as the :class:`~nonobtuse.io.cv_grid.ControlVolumeGrid`
fields (``point_index``, ``centers``, ``volumes``, ``materials``, ``connections``, ``areas``, ``distances``,
``signs``, ``face_centers``, ``boundary_cells``, ``boundary_markers``, ``boundary_areas``,
``boundary_centers``, ``elements``) plus ``coefficients``. Written atomically.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from nonobtuse.io._files import atomic_path, atomic_text
from nonobtuse.io.cv_grid import ControlVolumeGrid

NPZ_FIELDS = ("point_index", "centers", "elements", "volumes", "materials", "connections", "areas",
              "distances", "signs", "face_centers", "boundary_cells", "boundary_markers", "boundary_areas",
              "boundary_centers")


def text_rows(*columns: np.ndarray, sep: str = " ") -> str:
    """Lines of ``sep``-separated columns: integer arrays as integers, floats in shortest round-trip form."""
    text = [c.astype(str) if c.dtype.kind in "iu" else np.array([repr(float(x)) for x in c.tolist()])
            for c in columns]
    return "".join(sep.join(row) + "\n" for row in zip(*text))


def _table(path: Path, header: str, *columns: np.ndarray) -> None:
    with atomic_text(path) as f:
        f.write(header + "\n" + text_rows(*columns, sep=","))


def csv_paths(path: Path) -> list[Path]:
    """The three files :func:`write_csv` writes for ``OUT.csv``."""
    return [path, path.with_name(f"{path.stem}_connections.csv"), path.with_name(f"{path.stem}_boundary.csv")]


def write_csv(grid: ControlVolumeGrid, path: str | Path) -> list[Path]:
    """Write the cell, connection and boundary tables; returns their paths. Cost: O(n + c + b)."""
    cells, connections, boundary = csv_paths(Path(path))
    _table(cells, "cell,point,x,y,z,volume,material", np.arange(len(grid.volumes)), grid.point_index,
           *grid.centers.T, grid.volumes, grid.materials)
    _table(connections, "cell_a,cell_b,area,distance,coefficient,sign,x,y,z", *grid.connections.T, grid.areas,
           grid.distances, grid.coefficients, grid.signs.astype(np.int64), *grid.face_centers.T)
    _table(boundary, "cell,marker,area,x,y,z", grid.boundary_cells, grid.boundary_markers,
           grid.boundary_areas, *grid.boundary_centers.T)
    return [cells, connections, boundary]


def write_npz(grid: ControlVolumeGrid, path: str | Path) -> list[Path]:
    """Write every grid array (see the module docstring) to one uncompressed .npz; returns its path."""
    path = Path(path)
    arrays = {name: getattr(grid, name) for name in NPZ_FIELDS}
    with atomic_path(path) as tmp, open(tmp, "wb") as f:
        np.savez(f, coefficients=grid.coefficients, **arrays)
    return [path]


__all__ = ["NPZ_FIELDS", "csv_paths", "text_rows", "write_csv", "write_npz"]
