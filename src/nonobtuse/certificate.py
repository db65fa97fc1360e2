"""The exact nonobtuse-boundary certificate of a 2D mesh.

A control-volume (Voronoi box) discretisation is an M-matrix when every edge's coupling coefficient is >= 0.
On a Delaunay mesh this holds for interior edges; a boundary edge needs the angle opposite it to be at most 90
degrees, and an interface edge (between materials) needs that on each side separately. :func:`check` decides
every angle exactly (CGAL exact predicates on the coordinates as stored); degrees are for display only.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from nonobtuse import _core
from nonobtuse.domain import Domain
from nonobtuse.mesh import Mesh
from nonobtuse.triangulation import triangulate

KINDS = ("boundary", "interface", "interior")  # index = EdgeKind in cpp/include/nonobtuse/check2d.h
ANGLES = ("acute", "right", "obtuse")  # index = AngleClass in cpp/include/nonobtuse/types.h
OBTUSE = 2


def core_mesh_arguments(mesh: Mesh) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The arrays ``_core.classify_edges`` / ``_core.coupling_signs`` take: points, triangles, segments, and
    the region attribute per triangle (empty when the mesh has none)."""
    regions = np.zeros(0) if mesh.regions is None else np.asarray(mesh.regions, dtype=np.float64)
    return mesh.points, mesh.triangles, mesh.segments, regions


def classify_edges(mesh: Mesh) -> dict[str, np.ndarray]:
    """Every edge of ``mesh`` classified exactly: see ``_core.EdgeClassification`` (edges sorted by (a, b),
    a < b; kind, per side [left, right] triangle, apex and angle class, locally_delaunay), as a dict of
    those arrays. Raises InvalidInputError for a mesh that is not a counter-clockwise manifold
    triangulation. Cost: O(m log m)."""
    c = _core.classify_edges(*core_mesh_arguments(mesh))
    return {"edges": c.edges, "kind": c.kind, "triangle": c.triangle, "apex": c.apex, "angle": c.angle,
            "locally_delaunay": c.locally_delaunay}


def apex_angle_degrees(points: np.ndarray, a: np.ndarray, b: np.ndarray, apex: np.ndarray) -> np.ndarray:
    """Angle at ``apex`` of the triangles (a, apex, b) in degrees, in floating point (for display only).
    a, b, apex: (k,) int index arrays into points (n, 2). Returns (k,) float64."""
    u, v = points[a] - points[apex], points[b] - points[apex]
    cross = u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
    dot = np.einsum("ij,ij->i", u, v)
    return np.degrees(np.arctan2(np.abs(cross), dot))


@dataclass(frozen=True)
class ObtuseAngle:
    """One side of a boundary or interface edge whose angle opposite the edge is exactly obtuse."""

    edge: tuple[int, int]
    kind: str  # "boundary" or "interface"
    triangle: int
    apex: int
    points: tuple[tuple[float, float], ...]  # a, b, apex
    degrees: float  # float display of the angle at apex; the class OBTUSE is exact

    def to_dict(self) -> dict[str, Any]:
        return {"edge": list(self.edge), "kind": self.kind, "triangle": self.triangle, "apex": self.apex,
                "points": [list(p) for p in self.points], "degrees": self.degrees}


@dataclass
class CheckReport:
    """Exact nonobtuse-boundary certificate of one mesh.

    edges:        number of edges per kind ("boundary", "interface", "interior").
    angles:       per kind, the number of edge sides (angles opposite the edge) per class ("acute", "right",
                  "obtuse"); a boundary edge has one side, the others two.
    offenders:    every obtuse side of a boundary or interface edge, largest angle first.
    not_locally_delaunay: interior edges (a, b) failing the exact incircle test (empty for a constrained
                  Delaunay triangulation; constrained edges need not be locally Delaunay).
    points, triangles: size of the mesh checked.
    """

    edges: dict[str, int]
    angles: dict[str, dict[str, int]]
    offenders: list[ObtuseAngle]
    not_locally_delaunay: list[tuple[int, int]]
    points: int
    triangles: int
    source: str = "<memory>"

    @property
    def ok(self) -> bool:
        """True when no boundary or interface edge has an obtuse angle opposite it (exact)."""
        return not self.offenders

    @property
    def largest_obtuse(self) -> ObtuseAngle | None:
        """The offender with the largest angle (float comparison of exactly obtuse angles), or None."""
        return self.offenders[0] if self.offenders else None

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary (the ``--json`` output)."""
        worst = self.largest_obtuse
        return {
            "source": self.source, "ok": self.ok, "points": self.points, "triangles": self.triangles,
            "edges": dict(self.edges), "angles": {k: dict(v) for k, v in self.angles.items()},
            "largest_obtuse_degrees": worst.degrees if worst else None,
            "offenders": [o.to_dict() for o in self.offenders],
            "not_locally_delaunay": [list(e) for e in self.not_locally_delaunay],
        }

    def summary(self) -> str:
        """A few readable lines."""
        lines = [f"{self.source}: {self.points} points, {self.triangles} triangles"]
        for kind in KINDS:
            a = self.angles[kind]
            lines.append(f"  {kind:9} edges {self.edges[kind]:7}   angles: {a['acute']} acute, "
                         f"{a['right']} right, {a['obtuse']} obtuse")
        if self.ok:
            lines.append("  OK: every boundary and interface angle is nonobtuse (exact)")
        else:
            worst = self.offenders[0]
            lines.append(f"  NOT OK: {len(self.offenders)} obtuse boundary/interface angles; largest "
                         f"{worst.degrees:.4f} deg at point {worst.apex} opposite edge {worst.edge}")
        if self.not_locally_delaunay:
            lines.append(f"  {len(self.not_locally_delaunay)} edges are not locally Delaunay")
        return "\n".join(lines)


def _offenders(mesh: Mesh, c: _core.EdgeClassification) -> list[ObtuseAngle]:
    found = []
    guarded = c.kind != KINDS.index("interior")
    for side in (0, 1):
        idx = np.flatnonzero(guarded & (c.triangle[:, side] >= 0) & (c.angle[:, side] == OBTUSE))
        a, b, apex = c.edges[idx, 0], c.edges[idx, 1], c.apex[idx, side]
        degrees = apex_angle_degrees(mesh.points, a, b, apex)
        for i, e, deg in zip(idx, zip(a, b, apex), degrees):
            pts = tuple((float(mesh.points[v, 0]), float(mesh.points[v, 1])) for v in e)
            found.append(ObtuseAngle((int(e[0]), int(e[1])), KINDS[c.kind[i]], int(c.triangle[i, side]),
                                     int(e[2]), pts, float(deg)))
    found.sort(key=lambda o: (-o.degrees, o.edge, o.apex))
    return found


def check_mesh(mesh: Mesh) -> CheckReport:
    """The exact certificate of ``mesh`` (see :class:`CheckReport`). Cost: O(m log m) for m triangles."""
    c = _core.classify_edges(*core_mesh_arguments(mesh))
    edges, angles = {}, {}
    for k, kind in enumerate(KINDS):
        of_kind = c.kind == k
        edges[kind] = int(of_kind.sum())
        present = (c.triangle >= 0) & of_kind[:, None]
        angles[kind] = {name: int((present & (c.angle == j)).sum()) for j, name in enumerate(ANGLES)}
    bad = c.edges[(c.kind == KINDS.index("interior")) & (c.locally_delaunay == 0)]
    return CheckReport(edges=edges, angles=angles, offenders=_offenders(mesh, c),
                       not_locally_delaunay=[(int(a), int(b)) for a, b in bad], points=len(mesh.points),
                       triangles=len(mesh.triangles), source=str(mesh.stats.get("source", "<memory>")))


def check(domain_or_mesh: Domain | Mesh | dict[str, Any]) -> CheckReport:
    """Exact nonobtuse-boundary check. A :class:`Domain` is validated (unless ``Domain.validated``) and
    triangulated first (constrained Delaunay, no Steiner points); a :class:`Mesh` is checked as given. A
    ``triangle`` package dict (:mod:`nonobtuse.triangle_dict`) is a mesh when it has ``triangles`` (e.g.
    ``triangle.triangulate``'s output), else a domain. See :func:`check_mesh`."""
    if isinstance(domain_or_mesh, dict):
        from nonobtuse.triangle_dict import mesh_from_dict, validated_domain

        d = domain_or_mesh
        return check_mesh(mesh_from_dict(d) if "triangles" in d else triangulate(validated_domain(d)))
    if isinstance(domain_or_mesh, Domain):
        return check_mesh(triangulate(domain_or_mesh))
    return check_mesh(domain_or_mesh)
