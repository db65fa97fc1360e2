"""``stats["diagnosis"]["stop_reason"]`` of 2D refinement: the same field and words as refine_gabriel's (a
budget by its option's name), consistent with the status and the counts
(the CLI's JSON and summary: test_quality2d.py)."""

from __future__ import annotations

import re

from hypothesis import given, settings
from hypothesis import strategies as st

import nonobtuse
from refine_helpers import star

CONVERGED = "every boundary side has a nonobtuse apex"


def check_reason(res: nonobtuse.RefineResult) -> str:
    """The stop reason of res, checked against its status and counts; returned."""
    s, reason = res.stats, res.stats["diagnosis"]["stop_reason"]
    q = s["quality"]
    if res.status == "converged":
        assert reason == CONVERGED + ("" if q is None else " and every triangle meets the quality bounds "
                                      "outside small input angles")
    elif res.status == "budget_exhausted":
        budget = re.fullmatch(r"(max_steiner|max_interior) \((\d+)\) reached", reason)
        assert budget is not None, reason
        name, n = budget[1], int(budget[2])
        if name == "max_steiner":
            assert n == s["max_steiner"] == s["steiner_points"]
        else:
            assert n == q["interior_budget"] == q["interior_points"]
            assert s["steiner_points"] < s["max_steiner"]
    else:
        assert res.status == "stalled" and "remain" in reason
        split_failed = reason.endswith("could be split (no point passes the exact checks)")
        assert (s["obtuse_boundary_sides"] > 0) == split_failed
    return reason


@settings(max_examples=25, deadline=20000, derandomize=True)
@given(seed=st.integers(0, 2**32 - 1), n=st.integers(5, 14),
       max_steiner=st.one_of(st.none(), st.integers(0, 6)),
       max_interior=st.one_of(st.none(), st.integers(0, 20)), min_angle=st.sampled_from([None, 20.0, 28.0]))
def test_stop_reason_agrees_with_status_and_budgets(seed: int, n: int, max_steiner: int | None,
                                                      max_interior: int | None,
                                                      min_angle: float | None) -> None:
    quality = min_angle is not None or max_interior is not None
    res = nonobtuse.refine(star(seed, n), max_steiner=max_steiner, min_angle=min_angle,
                           max_area=None if not quality or min_angle is not None else 1e4,
                           max_interior=max_interior)
    check_reason(res)


def test_each_budget_is_named() -> None:
    d = star(5, 14)
    assert nonobtuse.refine(d).stats["diagnosis"]["stop_reason"] == CONVERGED
    assert check_reason(nonobtuse.refine(d, max_steiner=0)) == "max_steiner (0) reached"
    assert check_reason(nonobtuse.refine(d, max_area=100.0, max_interior=3)) == "max_interior (3) reached"
