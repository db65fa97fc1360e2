"""Small dihedral angles along input segments: the spike family (a cone over a regular 10-gon, its side
facets meet the base at about 90 - theta degrees), which the default strategy did not converge on from 45
degrees; the mirrored strategy (mirrored facet meshes along those segments, cpp/src/gabriel3d_mirror.h) is the
default's third pass, after shells and the protected rerun."""

from __future__ import annotations

import numpy as np
import pytest
from experiments.plc_families import make_plc

from nonobtuse.mesh3d import check_gabriel, refine_gabriel


def assert_certified(res, plc) -> None:
    assert res.status == "converged", res.stats["diagnosis"]["stop_reason"]
    again = check_gabriel(res.mesh)  # exact, independent of the refinement's own certificate
    assert again.ok and again.n_faces > 0 and len(res.mesh.tets) > 0
    np.testing.assert_array_equal(res.mesh.points[: len(plc.points)], plc.points)


@pytest.mark.parametrize("theta", [45.0, 60.0])
def test_default_converges_on_the_spike(theta):
    plc = make_plc("spike", theta)
    res = refine_gabriel(plc)
    assert_certified(res, plc)
    assert res.stats["strategy"] == "shells+protected"
    assert res.stats["other_attempt"].startswith("shells: ")


def test_mirrored_strategy_converges_on_the_spike_at_80_degrees():
    # The side facets meet the base at 10.5 degrees; the corner fans are mirror images (the sphere points are
    # mirrored once every protecting ball has its points), which the shells and protected strategies lack.
    plc = make_plc("spike", 80.0)
    res = refine_gabriel(plc, split="mirrored")
    assert_certified(res, plc)
    assert res.stats["steiner_points"] < 1000


def test_default_converges_on_the_spike_at_65_degrees_through_the_mirrored_pass():
    # Shells and the protected rerun stop early here (under a second together); the mirrored pass needs its
    # two corner rules: images of sphere points are sphere points; a protected piece [e, x_s] is not split.
    plc = make_plc("spike", 65.0)
    res = refine_gabriel(plc)
    assert_certified(res, plc)
    assert res.stats["strategy"] == "shells+mirrored"


@pytest.mark.slow
def test_default_converges_on_the_spike_at_80_degrees_through_the_mirrored_pass():
    # Shells and the protected rerun end at max_steiner (about 10 s together); the mirrored pass converges.
    plc = make_plc("spike", 80.0)
    res = refine_gabriel(plc)
    assert_certified(res, plc)
    assert res.stats["strategy"] == "shells+mirrored"
    shells, protected = res.stats["other_attempt"].split("; ")
    assert shells.startswith("shells: ") and protected.startswith("protected: ")


def test_mirrored_strategy_runs_alone_and_reports_what_the_exact_check_says():
    res = refine_gabriel(make_plc("spike", 45.0), split="mirrored")
    assert res.stats["strategy"] == "mirrored"
    assert res.stats["other_attempt"] == ""
    assert (res.status == "converged") == check_gabriel(res.mesh).ok
