"""The boundary Steiner points taken back after the quality refinement converged (quality2d_prune.cpp): on the
three inputs where our boundary tied with Triangle -pqD's before, fewer points than Triangle's now, the
certificate checked exactly and the bound reached; the same output on a second run."""

from __future__ import annotations

import numpy as np
import pytest

import nonobtuse
from nonobtuse.demo import cross_section
from nonobtuse.io import load_domain
from nonobtuse.peers import triangle_quality
from nonobtuse.validate import ensure_validated
from refine_helpers import SHARED, obtuse_constraint_sides

pytest.importorskip("triangle")


def tied_inputs() -> list[tuple[str, float]]:
    return [("demo", 25.0), ("face.poly", 25.0), ("spiral.node", 30.0)]


def domain(name: str) -> nonobtuse.Domain:
    if name == "demo":
        return ensure_validated(cross_section())
    path = SHARED / "2d" / name
    if not path.exists():
        pytest.skip(f"{path} is absent")
    return load_domain(path)


@pytest.mark.parametrize(("name", "degrees"), tied_inputs())
def test_fewer_boundary_points_than_triangle_where_we_tied(name: str, degrees: float) -> None:
    d = domain(name)
    r = nonobtuse.refine(d, min_angle=degrees)
    assert r.converged
    assert obtuse_constraint_sides(r.mesh) == 0
    assert r.stats["quality"]["min_angle_outside_small_angles_degrees"] >= degrees
    ours = int(np.count_nonzero(np.unique(r.mesh.segments) >= len(d.points)))
    assert ours == r.stats["steiner_points"]
    theirs = triangle_quality(d, degrees)
    assert ours < theirs["boundary_steiner"]
    assert len(r.mesh.points) <= 1.1 * theirs["vertices"]


def test_the_pruned_output_is_deterministic() -> None:
    d = domain("demo")
    first, second = (nonobtuse.refine(d, min_angle=25) for _ in range(2))
    assert np.array_equal(first.mesh.points, second.mesh.points)
    assert np.array_equal(first.mesh.triangles, second.mesh.triangles)
