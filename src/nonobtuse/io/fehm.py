"""FEHM input: the ``.stor`` sparse matrix file (LaGriT's ASCII layout), ``.fehmn`` coordinates and elements,
and zone files per region and per boundary marker.

``OUT.stor`` (LaGriT ``dump/stor`` layout, no compression; FEHM reads it free-format after line 3)::

    fehmstor ascir8i4 nonobtuse Sparse Matrix Voronoi Coefficients      title
    nonobtuse 3-D Linear Diffusion Model (matbld3d_nstor)               no time stamp (deterministic output)
    NCOEF NEQ NCOEF+NEQ+1 1 NCON_MAX                                    5 I10
    NEQ Voronoi volumes                                                 5 per line, E20.12
    NEQ+1 row pointers, then NCOEF column indices                       one stream, 5 I10 per line
    NCOEF coefficient pointers (1..NCOEF), then NEQ+1 zeros             one stream
    NEQ diagonal pointers (positions of the diagonal in the first stream)
    NCOEF coefficients: -area/distance off the diagonal, 0 on it        5 per line, E20.12

NEQ is the number of cells (mesh vertices); row i lists its neighbours and i itself in ascending order; NCOEF
is the number of row entries, NCON_MAX the longest row. Ids are 1-based.

``OUT.fehmn``: ``coor`` (NEQ lines ``id x y z``), ``elem`` (``nodes-per-element count`` then ``id n1 .. nk``),
``stop``. ``OUT_material.zone``: one zone per region attribute (the cells touching that region; FEHM lets a
later zone override an earlier one for a node on an interface). ``OUT_boundary.zone``: one zone per boundary
marker (the cells with a boundary face piece of that marker). Zone records: ``zone``, then per zone its
number (I5, zero padded) and name, ``nnum``, the count and the ids (10 per line), then ``stop``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from nonobtuse.io._files import atomic_text
from nonobtuse.io.cv_grid import ControlVolumeGrid, distinct_indices


def _columns(values: np.ndarray, fmt: str, per_line: int = 5) -> str:
    """``values`` formatted with ``fmt``, ``per_line`` to a line."""
    items = [fmt.format(v) for v in values.tolist()]
    return "".join("".join(items[i:i + per_line]) + "\n" for i in range(0, len(items), per_line))


def _ints(values: np.ndarray) -> str:
    return _columns(np.asarray(values, dtype=np.int64), "{:10d}")


def _floats(values: np.ndarray) -> str:
    return _columns(np.asarray(values, dtype=np.float64), "{:20.12E}")


def stor_matrix(grid: ControlVolumeGrid) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The .stor rows: row pointers (NEQ+1,) in the file's convention (first = NEQ+1), column indices
    (NCOEF,) 1-based with the diagonal, and the coefficient of each entry (NCOEF,) (0 on the diagonal)."""
    n = len(grid.volumes)
    a, b = grid.connections.T
    rows = np.concatenate([a, b, np.arange(n)])
    cols = np.concatenate([b, a, np.arange(n)])
    values = np.concatenate([grid.coefficients, grid.coefficients, np.zeros(n)])
    order = np.lexsort((cols, rows))
    counts = np.bincount(rows, minlength=n)
    pointers = n + 1 + np.concatenate([[0], np.cumsum(counts)])
    return pointers, cols[order] + 1, values[order]


def write_stor(grid: ControlVolumeGrid, path: Path) -> None:
    """Write the .stor file (layout in the module docstring). Cost: O(n + c)."""
    n = len(grid.volumes)
    pointers, cols, values = stor_matrix(grid)
    ncoef = len(cols)
    row_of = np.repeat(np.arange(n), np.diff(pointers))
    # Column entry k sits at position n + 2 + k of the stream (row pointers, then columns), 1-based.
    diagonal = n + 2 + np.flatnonzero(cols == row_of + 1)
    with atomic_text(path) as f:
        f.write("fehmstor ascir8i4 nonobtuse Sparse Matrix Voronoi Coefficients\n")
        f.write(f"nonobtuse {grid.dimension}-D Linear Diffusion Model (matbld{grid.dimension}d_nstor)\n")
        f.write(f"{ncoef:10d}{n:10d}{ncoef + n + 1:10d}{1:10d}{int(np.diff(pointers).max()):10d}\n")
        f.write(_floats(grid.volumes))
        f.write(_ints(np.concatenate([pointers, cols])))
        f.write(_ints(np.concatenate([np.arange(1, ncoef + 1), np.zeros(n + 1, dtype=np.int64)])))
        f.write(_ints(diagonal))
        f.write(_floats(values))


def write_fehmn(grid: ControlVolumeGrid, path: Path) -> None:
    """Write the .fehmn coordinates and elements."""
    n, elements = len(grid.volumes), grid.elements
    with atomic_text(path) as f:
        f.write(f"coor\n{n:10d}\n")
        for i, (x, y, z) in enumerate(grid.centers.tolist(), start=1):
            f.write(f"{i:10d} {x!r} {y!r} {z!r}\n")
        f.write(f"\nelem\n{elements.shape[1]:10d}{len(elements):10d}\n")
        for i, row in enumerate((elements + 1).tolist(), start=1):
            f.write(f"{i:10d}" + "".join(f"{v:10d}" for v in row) + "\n")
        f.write("\nstop\n")


def write_zones(zones: list[tuple[str, np.ndarray]], path: Path) -> None:
    """Write named zones (name, 0-based cells) in FEHM zone format, numbered 1, 2, ... in the given order."""
    with atomic_text(path) as f:
        f.write("zone\n")
        for number, (name, cells) in enumerate(zones, start=1):
            f.write(f"{number:05d}  {name}\nnnum\n{len(cells):10d}\n")
            f.write(_columns(np.asarray(cells, dtype=np.int64) + 1, "{:10d}", per_line=10))
        f.write("stop\n")


def fehm_paths(path: Path) -> dict[str, Path]:
    """The files :func:`write_fehm` writes for ``OUT.stor``."""
    return {"stor": path, "fehmn": path.with_suffix(".fehmn"),
            "material": path.with_name(f"{path.stem}_material.zone"),
            "boundary": path.with_name(f"{path.stem}_boundary.zone")}


def write_fehm(grid: ControlVolumeGrid, path: str | Path) -> list[Path]:
    """Write ``OUT.stor``, ``OUT.fehmn``, ``OUT_material.zone`` and ``OUT_boundary.zone``; returns them."""
    paths = fehm_paths(Path(path))
    write_stor(grid, paths["stor"])
    write_fehmn(grid, paths["fehmn"])
    write_zones([(f"region_{r:g}", c) for r, c in sorted(grid.region_cells.items())], paths["material"])
    markers = distinct_indices(grid.boundary_markers).tolist()
    cells, of = grid.boundary_cells, grid.boundary_markers
    boundary = [(f"marker_{m}", distinct_indices(cells[of == m])) for m in markers]
    write_zones(boundary, paths["boundary"])
    return list(paths.values())


__all__ = ["fehm_paths", "stor_matrix", "write_fehm"]
