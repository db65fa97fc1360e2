"""TOUGH2 / TOUGH3 ``MESH`` file: the ELEME and CONNE blocks in their fixed columns.

ELEME, one record per control volume (mesh vertex)::

    cols  1-5  element name        three letters and two digits: AAA00, AAA01, ..., AAA99, AAB00, ...
         16-20 material            rock type index (the i-th distinct region attribute, ascending; 1 without
                                   regions), right-justified
         21-30 VOLX                Voronoi volume
         51-80 X, Y, Z             the mesh vertex

CONNE, one record per mesh edge::

    cols  1-10 the two element names
         26-30 ISOT                1, 2 or 3: the axis along which the edge mostly runs (permeability index)
         31-50 D1, D2              distances from each element to the dual face: |e| / 2 each
         51-60 AREAX               dual face area (exact sign; negative only on an uncertified mesh)
         61-70 BETAX               cos(angle between gravity (-z) and the line from element 1 to element 2)

Each block ends with a blank record. A number takes its 10 columns exactly when it fits (``0.25``), else with
as many digits as fit, in fixed notation or with a short exponent (``1.234567e2``, which a Fortran E/G edit
descriptor reads): 6 to 8 significant digits, 5 for tiny values (``2.1185e-13``). Boundary faces are not in
MESH (TOUGH models them as extra elements): use the FEHM zones or PFLOTRAN .ex files for them. Written
atomically.
"""

from __future__ import annotations

import string
from pathlib import Path

import numpy as np

from nonobtuse.errors import InvalidInputError
from nonobtuse.io._files import atomic_text
from nonobtuse.io.cv_grid import ControlVolumeGrid

MAX_ELEMENTS = 26**3 * 100
_RULER = "----1----*----2----*----3----*----4----*----5----*----6----*----7----*----8"


def element_name(i: int) -> str:
    """The 5-character name of element ``i`` (0-based): three letters, then ``i % 100`` in two digits."""
    letters, number = divmod(i, 100)
    a, rest = divmod(letters, 26 * 26)
    b, c = divmod(rest, 26)
    upper = string.ascii_uppercase
    return f"{upper[a]}{upper[b]}{upper[c]}{number:02d}"


def fortran_e10(x: float) -> str:
    """``x`` in at most 10 characters: its shortest round-trip form when that fits, else whichever of fixed
    notation and E notation with the shortest exponent (``1.234567e2``) keeps it closer."""
    exact = repr(float(x))
    if len(exact) <= 10:
        return exact
    candidates = []
    decimals = 10 - len(f"{x:.0f}") - 1  # room after the point in fixed notation
    if decimals >= 1:
        candidates.append(f"{x:.{decimals}f}")
    exponent = int(f"{x:e}".split("e")[1])
    for digits in range(8, -1, -1):  # the exponent can grow when the mantissa rounds up (9.99e9 -> 1.0e10)
        mantissa, e = f"{x:.{digits}e}".split("e")
        text = f"{mantissa}e{int(e)}"
        if len(text) <= 10:
            candidates.append(text)
            break
    if not candidates:
        raise InvalidInputError(f"{x!r} (exponent {exponent}) does not fit in a TOUGH 10-column field")
    return min(candidates, key=lambda c: abs(float(c) - x))


def write_tough_mesh(grid: ControlVolumeGrid, path: str | Path) -> list[Path]:
    """Write the MESH file (layout in the module docstring). Raises InvalidInputError beyond
    :data:`MAX_ELEMENTS` cells (the 5-character names run out). Cost: O(n + c)."""
    path = Path(path)
    n = len(grid.volumes)
    if n > MAX_ELEMENTS:
        raise InvalidInputError(f"{path}: {n} control volumes; TOUGH's element names allow at most "
                                f"{MAX_ELEMENTS}")
    names = [element_name(i) for i in range(n)]
    rock = np.searchsorted(np.unique(grid.materials), grid.materials) + 1
    a, b = grid.connections.T
    direction = grid.centers[b] - grid.centers[a]
    isot = np.argmax(np.abs(direction), axis=1) + 1
    beta = -direction[:, 2] / grid.distances + 0.0  # + 0.0: level connections get 0.0, not -0.0
    with atomic_text(path) as f:
        f.write(f"ELEME{_RULER}\n")
        for i, (x, y, z) in enumerate(grid.centers.tolist()):
            f.write(f"{names[i]}{'':10}{rock[i]:>5d}{fortran_e10(grid.volumes[i]):>10}{'':20}"
                    f"{fortran_e10(x):>10}{fortran_e10(y):>10}{fortran_e10(z):>10}\n")
        f.write(f"\nCONNE{_RULER}\n")
        for k in range(len(a)):
            half = fortran_e10(grid.distances[k] / 2)
            f.write(f"{names[a[k]]}{names[b[k]]}{'':15}{isot[k]:>5d}{half:>10}{half:>10}"
                    f"{fortran_e10(grid.areas[k]):>10}{fortran_e10(beta[k]):>10}\n")
        f.write("\n")
    return [path]


__all__ = ["MAX_ELEMENTS", "element_name", "fortran_e10", "write_tough_mesh"]
