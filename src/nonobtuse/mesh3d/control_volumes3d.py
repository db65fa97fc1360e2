"""Voronoi control volumes of a tetrahedral mesh, by the per-tet decomposition used in LaGriT / FEHM.

Within a tet T = (a, b, c, d) the piece of the Voronoi face dual to edge e = (i, j) is the quadrilateral
(M, C_f1, C_T, C_f2): M the midpoint of e, C_f1 and C_f2 the circumcenters of the two faces of T containing e,
C_T the circumcenter of T. All four points are equidistant from i and j, so the quadrilateral lies in the
bisector plane of e. Its signed area is measured along the direction i -> j; it is positive when T's
circumcenter lies on the side of the faces that T occupies, and negative for obtuse configurations. Summing
the pieces of all tets around e gives the dual area A_e; the coupling coefficient of e is A_e / |e|, and a
negative coefficient breaks the M-matrix property. The part of T nearest to i is the union of the pyramids
with apex i over the three pieces of the edges at i, of volume A * |e| / 6 each, so the Voronoi cell volumes
of all vertices sum to the mesh volume (signed pieces, exactly up to rounding).

The sign of every A_e (negative, zero or positive) is decided exactly by the C++ core
(``_core.control_volumes3d``, or ``_core.dual_area_signs`` for the signs alone: interval arithmetic, exact
arithmetic when the interval contains 0); the floats give magnitudes only, so a coefficient that is exactly 0
is 0.0 and never a rounding-noise -4e-16.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from nonobtuse import _core
from nonobtuse.mesh3d.plc import TetMesh

# The six edges (i, j) of a positively oriented tet (0, 1, 2, 3) with the other two vertices (k, l) ordered
# so that (i, j, k, l) is an even permutation of (0, 1, 2, 3), hence positively oriented as well.
_EDGE_FRAMES = np.array([[0, 1, 2, 3], [0, 2, 3, 1], [0, 3, 1, 2], [1, 2, 0, 3], [1, 3, 2, 0], [2, 3, 0, 1]])


@dataclass
class ControlVolumes3D:
    """Control-volume data of a tet mesh.

    edges:        (e, 2) int64, a < b, sorted.
    dual_areas:   (e,) float64 signed area of the Voronoi face dual to each edge, clipped to the mesh: the
                  exact sign times the float magnitude (exactly 0.0 where the area is exactly 0).
    lengths:      (e,) edge lengths.
    couplings:    (e,) dual_areas / lengths: the finite-volume coupling coefficients.
    volumes:      (n,) Voronoi cell volume of every point (clipped to the mesh; 0 for unused points).
    signs:        (e,) int8 exact sign of each dual area: -1, 0, +1.
    negative_couplings: number of edges whose coupling is exactly negative (a positive off-diagonal).
    exact_evaluations: edges whose sign the interval filter left to exact arithmetic.
    flat_in_floating_point: tets whose volume is positive (exact orientation) but whose circumcenter
                  denominator is 0 in floating point: their circumcenters are computed exactly and rounded.
    """

    edges: np.ndarray
    dual_areas: np.ndarray
    lengths: np.ndarray
    couplings: np.ndarray
    volumes: np.ndarray
    signs: np.ndarray
    negative_couplings: int
    exact_evaluations: int = 0
    flat_in_floating_point: int = 0

    def to_dict(self) -> dict:
        """Summary for JSON output."""
        return {"edges": len(self.edges), "negative_couplings": self.negative_couplings,
                "zero_couplings": int((self.signs == 0).sum()),
                "min_coupling": float(self.couplings.min()) if len(self.couplings) else None,
                "total_volume": float(self.volumes.sum())}


def signed_tet_volumes(points: np.ndarray, tets: np.ndarray) -> np.ndarray:
    """Signed volumes (t,) of tets (t, 4): det[b-a, c-a, d-a] / 6, positive for positively oriented tets."""
    p = points[tets]
    a = p[:, 0]
    return np.einsum("ij,ij->i", p[:, 1] - a, np.cross(p[:, 2] - a, p[:, 3] - a)) / 6.0


def triangle_circumcenters(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """Circumcenters (k, 3) of triangles with corners a, b, c (each (k, 3)) in 3D."""
    u, v = b - a, c - a
    w = np.cross(u, v)
    num = (u * u).sum(1)[:, None] * np.cross(v, w) + (v * v).sum(1)[:, None] * np.cross(w, u)
    return a + num / (2.0 * (w * w).sum(1)[:, None])


def tet_circumcenters(a: np.ndarray, b: np.ndarray, c: np.ndarray, d: np.ndarray) -> np.ndarray:
    """Circumcenters (k, 3) of tets with corners a, b, c, d (each (k, 3))."""
    u, v, w = b - a, c - a, d - a
    num = ((u * u).sum(1)[:, None] * np.cross(v, w) + (v * v).sum(1)[:, None] * np.cross(w, u)
           + (w * w).sum(1)[:, None] * np.cross(u, v))
    return a + num / (2.0 * _triple_products(u, v, w)[:, None])


def _triple_products(u: np.ndarray, v: np.ndarray, w: np.ndarray) -> np.ndarray:
    """u . (v x w) per row (k,), in the order of the circumcenters' denominator."""
    return (u * np.cross(v, w)).sum(1)


def _robust_tet_circumcenters(points: np.ndarray, tets: np.ndarray) -> np.ndarray:
    """Circumcenters (t, 3) of tets (t, 4) over points: :func:`tet_circumcenters`, except that a tet flat in
    floating point (denominator 0, where the doubles give NaN or inf; its exact volume is positive) gets its
    circumcenter computed exactly and rounded to nearest (:func:`exact_circumspheres`), as the C++ core's
    control volumes do; a center beyond the double range is inf."""
    p = points[tets]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        centers = tet_circumcenters(p[:, 0], p[:, 1], p[:, 2], p[:, 3])
    a = p[:, 0]
    flat = np.flatnonzero(_triple_products(p[:, 1] - a, p[:, 2] - a, p[:, 3] - a) == 0)
    centers[flat] = exact_circumspheres(points, tets[flat])[0]
    return centers


def dual_area_pieces(points: np.ndarray, tets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per tet and local edge (t, 6): the edge as global vertex pairs (t, 6, 2) and the signed area of the
    quadrilateral piece of its dual Voronoi face inside the tet (t, 6). Tets must be positively oriented."""
    ct = _robust_tet_circumcenters(points, tets)
    frames = tets[:, _EDGE_FRAMES]  # (t, 6, 4): i, j, k, l
    x = points[frames]  # (t, 6, 4, 3)
    xi, xj, xk, xl = (x[:, :, q].reshape(-1, 3) for q in range(4))
    m = 0.5 * (xi + xj)
    c1 = triangle_circumcenters(xi, xj, xk)
    c2 = triangle_circumcenters(xi, xj, xl)
    c = np.repeat(ct, 6, axis=0)
    # Quadrilateral M -> C(ijk) -> C_T -> C(ijl): for (i, j, k, l) positive (det[j-i, k-i, l-i] > 0) and a
    # circumcenter inside the tet it runs counter-clockwise seen from j, so its area vector points
    # along i -> j.
    area_vec = 0.5 * (np.cross(c1 - m, c - m) + np.cross(c - m, c2 - m))
    e = xj - xi
    signed = (area_vec * e).sum(1) / np.linalg.norm(e, axis=1)
    return frames[:, :, :2], signed.reshape(-1, 6)


def _shares(points: np.ndarray, pairs: np.ndarray, pieces: np.ndarray) -> np.ndarray:
    """Per tet and local vertex (t, 4): the pyramids with apex at the vertex over the pieces of its three
    edges (``pairs``, ``pieces`` from :func:`dual_area_pieces`), volume piece * |e| / 6 each."""
    lengths = np.linalg.norm(points[pairs[..., 1]] - points[pairs[..., 0]], axis=2)
    pyramid = pieces * lengths / 6.0  # (t, 6)
    shares = np.zeros((len(pieces), 4))
    for f, (i, j) in enumerate(_EDGE_FRAMES[:, :2]):
        shares[:, i] += pyramid[:, f]
        shares[:, j] += pyramid[:, f]
    return shares


def tet_voronoi_shares(points: np.ndarray, tets: np.ndarray) -> np.ndarray:
    """The part of each tet nearest to each of its four vertices, as signed volumes (t, 4) float64: the
    vertex's Voronoi cell within the tet. points (n, 3) float64, tets (t, 4) int64 positively oriented. The
    four shares sum to the tet's volume (up to rounding); a share can be negative only where the tet's
    circumcenter lies outside it. Cost: O(t)."""
    points = np.asarray(points, dtype=np.float64)
    tets = np.asarray(tets, dtype=np.int64).reshape(-1, 4)
    return _shares(points, *dual_area_pieces(points, tets))


def control_volumes3d(mesh: TetMesh) -> ControlVolumes3D:
    """Voronoi dual areas (exact signs), coupling coefficients and cell volumes of `mesh`.

    mesh: tets positively oriented (InvalidInputError naming the tet otherwise). The C++ core
    (``_core.control_volumes3d``) computes it all in one pass: the magnitudes with the arithmetic of
    :func:`dual_area_pieces` and :func:`tet_voronoi_shares`, operation for operation, summed in tet order.
    Cost: O(t) for t tets (a counting sort of the 6 t edge pieces), plus exact arithmetic for the edges the
    interval filter cannot decide (dual areas that are zero or nearly so: 262k of 7.3M edges on the 1e6-face
    torus of ``bench_gabriel3d``, whose cross-sections are nearly cocircular).
    """
    points = np.ascontiguousarray(mesh.points, dtype=np.float64).reshape(-1, 3)
    tets = np.ascontiguousarray(mesh.tets, dtype=np.int64).reshape(-1, 4)
    d = _core.control_volumes3d(points, tets)
    signs, dual, lengths = d["sign"], d["dual_areas"], d["lengths"]
    couplings = dual / lengths
    return ControlVolumes3D(d["edges"].reshape(-1, 2), dual, lengths, couplings, d["volumes"], signs,
                            int((signs < 0).sum()), int(d["exact_evaluations"]),
                            int(d["flat_in_floating_point"]))


def exact_circumspheres(points: np.ndarray, tets: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Circumcenters (t, 3), circumradii (t,) and signed volumes (t,) of tets (t, 4) int64 over points (n, 3),
    each computed exactly (the C++ core, CGAL's exact kernel) and rounded to nearest; inf beyond the double
    range; a coplanar tet gets an inf center and radius and volume 0. For tets flat or nearly so in floating
    point: tens of microseconds each."""
    centers, squared, volumes = _core.exact_tet_circumspheres(
        np.ascontiguousarray(points, dtype=np.float64).reshape(-1, 3),
        np.ascontiguousarray(tets, dtype=np.int64).reshape(-1, 4))
    return centers, np.sqrt(squared), volumes
