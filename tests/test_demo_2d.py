"""The demo's 2D quality part: refine(min_angle=25) on the cross-section, reported with figures recomputed
here from the mesh (angles in floating point, the boundary certificate by the exact rational oracle)."""

from __future__ import annotations

import numpy as np
import pytest

from nonobtuse import demo
from nonobtuse.refinement import refine
from refine_helpers import obtuse_constraint_sides
from test_quality2d import smallest_angles


def test_run_quality_reports_what_the_mesh_has():
    lines: list[str] = []
    r = demo.run_quality(demo.cross_section(), lines.append)
    assert r.converged
    assert obtuse_constraint_sides(r.mesh) == 0  # every side of every boundary and interface edge, exactly
    angles = smallest_angles(r.mesh)
    assert angles.min() >= demo.QUALITY_MIN_ANGLE - 1e-9
    minimal = refine(demo.cross_section())
    assert len(r.mesh.points) > len(minimal.mesh.points)  # the quality mode does add points
    text = "\n".join(lines)
    assert (f"{len(r.mesh.points)} points ({r.stats['steiner_points']} on boundary/interfaces, "
            f"{r.stats['interior_points']} inside), {len(r.mesh.triangles)} triangles") in text
    assert (f"smallest angle {angles.min():.2f} deg; obtuse angles opposite boundary/interface edges "
            "(exact): 0") in text
    assert len(lines) == 3  # short


def test_run_quality_compares_with_triangle():
    triangle = pytest.importorskip("triangle")
    lines: list[str] = []
    demo.run_quality(demo.cross_section(), lines.append)
    d = demo.cross_section()
    out = triangle.triangulate({"vertices": d.points, "segments": d.segments}, "pq25DQ")
    on_segments = int(np.count_nonzero(np.unique(out["segments"]) >= len(d.points)))
    assert (f"Triangle -pq25D on the same domain: {len(out['vertices'])} points ({on_segments} on "
            "boundary/interfaces)") in lines[-1]
