"""Constrained Delaunay triangulation of a 2D domain (the C++ core, CGAL exact predicates)."""

from __future__ import annotations

from typing import Any, overload

from nonobtuse import _core
from nonobtuse.domain import Domain
from nonobtuse.markers import mesh_markers
from nonobtuse.mesh import Mesh
from nonobtuse.validate import ensure_validated, require_points_in_domain


@overload
def triangulate(domain: Domain) -> Mesh: ...
@overload
def triangulate(domain: dict[str, Any]) -> dict[str, Any]: ...
def triangulate(domain: Domain | dict[str, Any]) -> Mesh | dict[str, Any]:
    """Constrained Delaunay triangulation (CDT) of ``domain``, without Steiner points.

    Input: a :class:`Domain`; unless it is already validated (``Domain.validated``: from ``load_domain`` or
    ``validate_domain``) it is validated once here (duplicates, crossings, points inside segments, open
    loops...), which may give a repaired copy (e.g. segments split at points lying on them). ``domain`` is
    not modified.
    Output: a :class:`Mesh` whose points are the validated domain's points in order, triangles (m, 3)
    counter-clockwise covering the domain minus holes, segments every constrained edge bordering the domain,
    ``regions`` the region attribute per triangle (0 where no seed reached), ``input_points`` /
    ``input_segments`` the validated domain, ``stats["repairs"]`` what validation changed, ``point_markers`` /
    ``segment_markers`` the domain's markers by Triangle's rules (:mod:`nonobtuse.markers`).
    Given a ``triangle`` package input dict (:mod:`nonobtuse.triangle_dict`), returns a dict in
    ``triangle.triangulate``'s output convention (what ``triangle.triangulate(d, "p")`` gives, ``"pc"`` for a
    point set).
    Raises :class:`InvalidInputError` for a domain that cannot be triangulated, or with input points outside
    it (in the exterior or a hole: no triangle would use them; it says what and where).
    Cost: O(n log n) expected for n points.
    """
    if isinstance(domain, dict):
        from nonobtuse.triangle_dict import mesh_to_dict, validated_domain

        return mesh_to_dict(triangulate(validated_domain(domain)), domain)
    valid = ensure_validated(domain)
    out = _core.triangulate(valid.points, valid.segments, valid.holes, valid.regions, valid.convex_hull)
    require_points_in_domain(valid, out.triangles)
    stats = {"source": valid.source, "repairs": list(valid.repairs)}
    return mesh_of_core(out, valid, out.triangle_region, stats)


def mesh_of_core(m: _core.Mesh2D, domain: Domain, regions: Any, stats: dict[str, Any]) -> Mesh:
    """The :class:`Mesh` of the core's triangulation ``m`` of the validated ``domain`` (its input points and
    segments recorded, its markers carried by Triangle's rules), with ``regions`` per triangle (or None) and
    ``stats``."""
    mesh = Mesh(
        points=m.points,
        triangles=m.triangles,
        segments=m.segments,
        input_points=domain.points.copy(),
        input_segments=domain.segments.copy(),
        regions=regions,
        stats=stats,
    )
    mesh_markers(mesh, domain)
    return mesh
