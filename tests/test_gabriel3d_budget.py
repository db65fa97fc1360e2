"""The 3D Gabriel repair's default stop is a deterministic work budget, not wall time."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d import load_plc, refine_gabriel

DATA = Path(__file__).parent / "data" / "3d"
SCHONHARDT = DATA / "schonhardt.off"  # converges through the protected rerun
ICOSPHERE = DATA / "icosphere_jitter.off"  # converges in the first pass, after a few hundred insertions


def same_result(a, b) -> bool:
    return (a.status == b.status and a.stats["work"] == b.stats["work"]
            and a.stats["strategy"] == b.stats["strategy"]
            and np.array_equal(a.mesh.points, b.mesh.points) and np.array_equal(a.mesh.tets, b.mesh.tets))


def test_default_has_no_time_limit_and_a_work_budget():
    res = refine_gabriel(load_plc(SCHONHARDT))
    assert res.stats["time_limit"] is None
    assert 0 < res.stats["work"] <= 2 * res.stats["max_work"]  # two strategy passes, a budget each
    assert res.status == "converged" and res.report.ok


def test_no_time_limit_and_a_generous_one_give_the_same_result():
    plc = load_plc(SCHONHARDT)
    untimed = refine_gabriel(plc)
    timed = refine_gabriel(plc, time_limit=1e6)
    assert timed.stats["time_limit"] == 1e6
    assert same_result(untimed, timed)


def test_work_budget_stop_is_reproducible():
    plc = load_plc(ICOSPHERE)
    full = refine_gabriel(plc)
    cut = full.stats["work"] // 3
    first, again = (refine_gabriel(plc, max_work=cut, protected_fallback=False) for _ in range(2))
    assert first.status == "budget_exhausted"
    assert "max_work" in first.stats["diagnosis"]["stop_reason"]
    assert first.stats["max_work"] == cut
    assert same_result(first, again)
    assert 0 < first.stats["steiner_points"] < full.stats["steiner_points"]
    nothing = refine_gabriel(plc, max_work=0, protected_fallback=False)
    assert nothing.status == "budget_exhausted" and nothing.stats["steiner_points"] == 0


def test_protected_rerun_has_its_own_work_budget():
    plc = load_plc(SCHONHARDT)
    protected = refine_gabriel(plc, split="protected")
    budget = protected.stats["work"]  # what the protected strategy alone needs
    res = refine_gabriel(plc, max_work=budget)
    # The shells pass alone stops at that budget; the rerun, with a budget of its own, still converges.
    assert "max_work" in res.stats["other_attempt"]
    assert res.stats["work"] > budget
    assert res.status == "converged" and res.stats["strategy"] == "shells+protected"
    assert np.array_equal(res.mesh.points, protected.mesh.points)


@pytest.mark.parametrize("bad", [-1, True, 1.5, 2**62])
def test_bad_max_work_is_invalid_input(bad):
    plc = load_plc(SCHONHARDT)
    with pytest.raises(InvalidInputError, match="max_work"):
        refine_gabriel(plc, max_work=bad)
