"""Small closed surfaces shared by the 3D tests, and writers for the surface formats."""

from __future__ import annotations

import struct
from pathlib import Path

import numpy as np

# Unit cube: vertex i has coordinates (i & 1, (i >> 1) & 1, (i >> 2) & 1).
CUBE_POINTS = np.array([[i & 1, (i >> 1) & 1, (i >> 2) & 1] for i in range(8)], dtype=np.float64)
# Outward quads (counter-clockwise seen from outside).
CUBE_QUADS = np.array([[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]])
CUBE_TRIANGLES = np.concatenate([CUBE_QUADS[:, [0, 1, 2]], CUBE_QUADS[:, [0, 2, 3]]])

# A tetrahedron, outward: (0,0,0), (1,0,0), (0,1,0), (0,0,1).
TET_POINTS = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
TET_TRIANGLES = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])


def write_off(path: Path, points: np.ndarray, faces) -> Path:
    lines = ["OFF", f"{len(points)} {len(faces)} 0"]
    lines += [" ".join(repr(float(x)) for x in p) for p in points]
    lines += [" ".join(str(v) for v in [len(f), *f]) for f in faces]
    path.write_text("\n".join(lines) + "\n")
    return path


def write_stl_ascii(path: Path, points: np.ndarray, triangles: np.ndarray) -> Path:
    out = ["solid test"]
    for t in triangles:
        out += ["facet normal 0 0 0", "outer loop"]
        out += ["vertex " + " ".join(repr(float(x)) for x in points[v]) for v in t]
        out += ["endloop", "endfacet"]
    path.write_text("\n".join(out + ["endsolid test"]) + "\n")
    return path


def write_stl_binary(path: Path, points: np.ndarray, triangles: np.ndarray) -> Path:
    data = b"solid but binary".ljust(80, b" ") + struct.pack("<I", len(triangles))
    for t in triangles:
        data += struct.pack("<12fH", 0, 0, 0, *points[t].ravel(), 0)
    path.write_bytes(data)
    return path


def two_tets_touching_at_a_vertex() -> tuple[np.ndarray, np.ndarray]:
    """Two closed tets sharing vertex 0 only: a non-manifold vertex."""
    pts = np.concatenate([TET_POINTS, -TET_POINTS[1:]])
    second = np.where(TET_TRIANGLES == 0, 0, TET_TRIANGLES + 3)[:, ::-1]  # mirrored: reverse to stay outward
    return pts, np.concatenate([TET_TRIANGLES, second])
