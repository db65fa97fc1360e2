"""The control-volume (Voronoi box, two-point flux) matrix of a 2D mesh, with exact coefficient signs.

For -div(k grad u) the flux between the control volumes of the ends of edge e = (a, b) is T_e (u_a - u_b) with

    T_e = sum over the triangles t on each side of e of  k_t * cot(angle of t opposite e) / 2,

which is k times the signed length of the Voronoi segment dual to e (per triangle: the signed distance from
the circumcenter to the midpoint of e, = (|e|/2) cot(apex), negative when the circumcenter lies across e from
the apex), divided by |e|. The matrix has A[a, b] = A[b, a] = -T_e and A[a, a] = sum of T_e over the edges at
a, so every row sums to 0. It is an M-matrix (off-diagonals <= 0) exactly when every T_e >= 0, which the C++
core decides exactly (``signs``); the float ``matrix`` is for solving.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Union

import numpy as np
import scipy.sparse

from nonobtuse import _core
from nonobtuse.certificate import core_mesh_arguments
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh import Mesh


@dataclass
class ControlVolumes:
    """The control-volume discretisation of one mesh.

    matrix:       (n, n) scipy.sparse CSR float64, symmetric, rows sum to 0 (up to rounding).
    areas:        (n,) float64 > 0 for every vertex of a triangle: the Voronoi control volume of each vertex
                  clipped to the domain (see :func:`voronoi_areas`); sums to the domain area.
    edges:        (E, 2) int64, a < b, sorted.
    kind:         (E,) int8 index into ``nonobtuse.certificate.KINDS`` (boundary, interface, interior).
    coefficients: (E,) float64 T_e (float evaluation).
    signs:        (E,) int8 exact sign of T_e: -1, 0, +1.
    """

    matrix: scipy.sparse.csr_matrix
    areas: np.ndarray
    edges: np.ndarray
    kind: np.ndarray
    coefficients: np.ndarray
    signs: np.ndarray

    @property
    def wrong_sign(self) -> np.ndarray:
        """Indices into ``edges`` of the coefficients that are exactly negative (a positive off-diagonal)."""
        return np.flatnonzero(self.signs < 0)

    @property
    def m_matrix(self) -> bool:
        """True when every off-diagonal entry is <= 0, decided exactly: the matrix is a (singular, Neumann)
        M-matrix, so the scheme satisfies the discrete maximum principle."""
        return not (self.signs < 0).any()


Conductivity = Union[dict[float, float], np.ndarray, None]


def triangle_conductivity(mesh: Mesh, conductivity: Conductivity) -> np.ndarray:
    """Conductivity per triangle, (m,) float64, finite and > 0.

    conductivity: None (k = 1 everywhere), a dict from region attribute to k (every attribute present in
    ``mesh.regions`` must be a key), or an array of one value per triangle.
    Raises InvalidInputError on a missing region, a wrong length, or a value that is not finite and > 0.
    """
    m = len(mesh.triangles)
    if conductivity is None:
        return np.ones(m)
    if isinstance(conductivity, dict):
        regions = np.zeros(m) if mesh.regions is None else np.asarray(mesh.regions, dtype=np.float64)
        missing = sorted(set(np.unique(regions).tolist()) - set(conductivity))
        if missing:
            raise InvalidInputError(f"conductivity has no value for region attribute(s) {missing}")
        k = np.array([conductivity[r] for r in regions.tolist()], dtype=np.float64)
    else:
        k = np.asarray(conductivity, dtype=np.float64)
        if k.shape != (m,):
            raise InvalidInputError(f"conductivity must have one value per triangle, shape ({m},), "
                                    f"got {k.shape}")
    bad = np.flatnonzero(~(np.isfinite(k) & (k > 0)))
    if bad.size:
        t = int(bad[0])
        raise InvalidInputError(f"conductivity of triangle {t} is {k[t]}; it must be finite and > 0")
    return k


def _corner_terms(points: np.ndarray, triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per triangle and corner j (the corner opposite edge j): cot of the angle at j, the squared length of
    the opposite edge, and twice the triangle area. Shapes (m, 3), (m, 3), (m,). Points (n, 2) (triangles
    counter-clockwise) or (n, 3)."""
    p = points[triangles]  # (m, 3, d)
    u = np.roll(p, -1, axis=1) - p  # corner j -> corner j+1
    v = np.roll(p, -2, axis=1) - p  # corner j -> corner j+2
    dot = np.einsum("mjk,mjk->mj", u, v)
    if p.shape[2] == 2:
        cross = u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]  # = twice the area at every corner (ccw)
    else:
        cross = np.linalg.norm(np.cross(u, v), axis=2)
    opposite = np.roll(p, -2, axis=1) - np.roll(p, -1, axis=1)
    return dot / cross, np.einsum("mjk,mjk->mj", opposite, opposite), cross[:, 0]


def triangle_voronoi_shares(points: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """The part of each triangle nearer to each of its corners than to the other two, as areas (m, 3) float64.

    points: (n, 2) with counter-clockwise triangles, or (n, 3) (a surface). triangles: (m, 3) int64.
    - nonobtuse triangle (circumcenter inside or on it): corner a of (a, b, c) gets the quadrilateral
      a, mid(ab), circumcenter, mid(ac): (|ab|^2 cot C + |ac|^2 cot B) / 8;
    - triangle obtuse at c: the bisector of ac cuts ab before its midpoint, so a gets the triangle
      a, (that point), mid(ac): |ac|^2 tan A / 8; likewise b; c gets the rest (> 0).
    Both formulas agree on right triangles, so deciding "obtuse" in floats is harmless. Every share is >= 0
    and the three shares sum to the triangle's area (up to rounding). Cost: O(m).
    """
    cot, sq, twice_area = _corner_terms(points, triangles)
    # Nonobtuse split: corner j gets (|j j+1|^2 cot(j+2) + |j j+2|^2 cot(j+1)) / 8; |j j+1| is opposite j+2.
    share = (np.roll(sq * cot, -2, axis=1) + np.roll(sq * cot, -1, axis=1)) / 8
    obtuse_rows, obtuse_corner = np.nonzero(cot < 0)
    # The acute corners of a triangle obtuse at o get |corner o|^2 tan(corner) / 8; the edge from corner
    # o + shift to o is opposite corner o + 2 shift = corner + shift (mod 3).
    for shift in (1, 2):
        corner = (obtuse_corner + shift) % 3
        share[obtuse_rows, corner] = sq[obtuse_rows, (corner + shift) % 3] / (8 * cot[obtuse_rows, corner])
    rest = share[obtuse_rows, (obtuse_corner + 1) % 3] + share[obtuse_rows, (obtuse_corner + 2) % 3]
    share[obtuse_rows, obtuse_corner] = twice_area[obtuse_rows] / 2 - rest
    return share


def voronoi_areas(mesh: Mesh) -> np.ndarray:
    """Area of each vertex's Voronoi control volume clipped to the domain, (n,) float64: the sum of its
    :func:`triangle_voronoi_shares`, so the areas sum to the domain area (up to rounding). Cost: O(m)."""
    share = triangle_voronoi_shares(mesh.points, mesh.triangles)
    return np.bincount(mesh.triangles.ravel(), weights=share.ravel(), minlength=len(mesh.points))


def control_volumes(mesh: Mesh, conductivity: Conductivity = None) -> ControlVolumes:
    """The control-volume matrix, Voronoi areas and exact coefficient signs of ``mesh`` (see the module text).

    mesh: counter-clockwise triangles (InvalidInputError otherwise). conductivity: see
    :func:`triangle_conductivity`. Cost: O(m log m) for m triangles.
    """
    k = triangle_conductivity(mesh, conductivity)
    c = _core.coupling_signs(*core_mesh_arguments(mesh), k)
    cot, _, _ = _corner_terms(mesh.points, mesh.triangles)
    # Add each side's k_t cot(apex) / 2; `corner` is the apex's position (0, 1, 2) in its triangle.
    coefficients = np.zeros(len(c.edges))
    for side in (0, 1):
        has = np.flatnonzero(c.triangle[:, side] >= 0)
        t, apex = c.triangle[has, side], c.apex[has, side]
        corner = np.argmax(mesh.triangles[t] == apex[:, None], axis=1)
        coefficients[has] += k[t] * cot[t, corner] / 2
    n = len(mesh.points)
    a, b = c.edges[:, 0], c.edges[:, 1]
    off = scipy.sparse.coo_matrix((-coefficients, (a, b)), shape=(n, n))
    off = (off + off.T).tocsr()
    diagonal = -np.asarray(off.sum(axis=1)).ravel()
    matrix = (off + scipy.sparse.diags(diagonal)).tocsr()
    return ControlVolumes(matrix=matrix, areas=voronoi_areas(mesh), edges=c.edges, kind=c.kind,
                          coefficients=coefficients, signs=c.sign)


__all__ = [
    "ControlVolumes", "control_volumes", "triangle_conductivity", "triangle_voronoi_shares", "voronoi_areas",
]
