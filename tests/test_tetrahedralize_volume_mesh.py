"""The cgal backend on surfaces whose inside winding numbers cannot say (an open surface, a surface with an
internal facet): no tets, the reason in stats["volume_mesh"], and the exact boundary check still runs."""

from __future__ import annotations

import numpy as np
import pytest
from experiments.bench_gabriel3d import torus_surface

from nonobtuse.mesh3d import PLC, boundary_certificate, check_gabriel, tetrahedralize


def torus_plc(triangles: np.ndarray, points: np.ndarray) -> PLC:
    return PLC(points, triangles, np.arange(len(triangles)))


def closed_torus() -> tuple[np.ndarray, np.ndarray]:
    return torus_surface(400, seed=1)


def test_closed_torus_gets_tets_by_winding_number():
    points, triangles = closed_torus()
    mesh = tetrahedralize(torus_plc(triangles, points), "cgal")
    assert mesh.stats["volume_mesh"].startswith(("built", "by winding number"))
    assert len(mesh.tets) > 0


@pytest.mark.parametrize("kind", ["open", "internal facet"])
def test_cgal_builds_no_tets_where_the_surface_is_not_closed_and_oriented(kind):
    points, triangles = closed_torus()
    if kind == "open":
        triangles = triangles[1:]  # one triangle removed: its three edges bound a hole
    else:  # a triangle inside the tube at angle 0 (the tube's centre circle passes through (4, 0, 0))
        inner = np.array([[4.2, 0.0, 0.0], [3.9, 0.1, 0.1], [3.9, -0.1, -0.1]])
        triangles = np.concatenate([triangles, [[len(points), len(points) + 1, len(points) + 2]]])
        points = np.concatenate([points, inner])
    mesh = tetrahedralize(torus_plc(triangles, points), "cgal")
    assert len(mesh.tets) == 0, mesh.stats["volume_mesh"]
    assert mesh.stats["volume_mesh"].startswith("not built")
    assert "not closed and oriented" in mesh.stats["volume_mesh"]
    certificate = boundary_certificate(mesh)  # the exact check needs only the boundary faces and points
    report = check_gabriel(mesh)
    assert certificate["tets"] == 0
    assert certificate["boundary_faces"] == len(triangles)
    assert certificate["encroached_facets"] == len(report.faces)
