"""nonobtuse.validate: every kind of invalid domain, every repair, and a seeded property test of crossings."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from nonobtuse.domain import Domain
from nonobtuse.errors import InvalidInputError
from nonobtuse.validate import validate_domain

SQUARE = [[0, 0], [4, 0], [4, 4], [0, 4]]
LOOP = [[0, 1], [1, 2], [2, 3], [3, 0]]


def square(extra_points=(), extra_segments=(), **kw) -> Domain:
    return Domain(SQUARE + list(extra_points), LOOP + list(extra_segments), **kw)


def test_valid_square_is_returned_unchanged():
    d = square()
    v = validate_domain(d)
    assert v is not d and v.repairs == [] and np.array_equal(v.segments, d.segments)


@pytest.mark.parametrize(
    "domain, message",
    [
        (Domain(np.zeros((0, 2))), "the domain has no points"),
        (square([[1, np.nan]]), r"point 4 at \(1\.0, nan\) has a coordinate or value that is not finite"),
        (square(holes=[[np.inf, 1]]), r"hole seed 0 at \(inf, 1\.0\) has a coordinate"),
        (square(regions=[[1, 1, np.nan]]), r"region seed 0 at \(1\.0, 1\.0\) attribute nan has"),
        (square(extra_segments=[[0, 7]]), "segment 4 refers to a point that does not exist"),
        # point 5 repeats point 2 = (4, 4): both named, in index order
        (
            square([[1, 1], [4, 4]]),
            r"duplicate points: point 2 at \(4\.0, 4\.0\) and point 5 at \(4\.0, 4\.0\)",
        ),
        (square(extra_segments=[[2, 2]]), r"segment 4 \(points 2, 2: .*\) has zero length"),
        # the diagonals (0, 2) and (1, 3) cross at (2, 2)
        (
            square(extra_segments=[[0, 2], [1, 3]]),
            r"segment 4 \(points 0, 2.*and segment 5 \(points 1, 3.*cross",
        ),
    ],
)
def test_each_invalid_kind_is_named(domain, message):
    with pytest.raises(InvalidInputError, match=message):
        validate_domain(domain)


def test_duplicate_points_with_every_other_x_distinct():
    # Random x are all distinct: validation passes on one sort of x; one repeated point is still named.
    points = np.random.default_rng(1).uniform(0, 1, (50, 2))
    assert len(validate_domain(Domain(points=points, convex_hull=True)).points) == 50
    points[37] = points[12]
    with pytest.raises(InvalidInputError, match=r"duplicate points: point 12 at .* and point 37 at"):
        validate_domain(Domain(points=points, convex_hull=True))


def test_duplicate_segments_are_dropped_and_recorded():
    d = validate_domain(square(extra_segments=[[1, 0], [2, 3]]))  # (1, 0) repeats (0, 1) reversed
    assert d.segments.tolist() == LOOP
    assert len(d.repairs) == 1 and "dropped 2 duplicate segment(s)" in d.repairs[0]


def test_point_on_segment_splits_it_or_is_refused():
    # (2, 0) lies inside the bottom side; (1, 0) too; the side is replaced by the chain 0 - 5 - 4 - 1.
    dom = square([[2, 0], [1, 0]])
    d = validate_domain(dom)
    assert d.segments.tolist() == [[0, 5], [5, 4], [4, 1], [1, 2], [2, 3], [3, 0]]
    assert len(d.repairs) == 1 and "split at 2 point(s)" in d.repairs[0]
    assert dom.segments.tolist() == LOOP  # the input domain is not modified
    # Reversed segment direction: the chain runs from 1 back to 0.
    d = validate_domain(Domain(SQUARE + [[2, 0], [1, 0]], [[1, 0], [1, 2], [2, 3], [3, 0]]))
    assert d.segments[:3].tolist() == [[1, 4], [4, 5], [5, 0]]
    with pytest.raises(InvalidInputError, match=r"point 4 at \(2\.0, 0\.0\) lies inside segment 0"):
        validate_domain(dom, split_points_on_segments=False)


def test_collinear_overlap_is_repaired_or_refused():
    # Segment 4 runs from (2, 0) back to (0, 0) over (1, 0): it overlaps the bottom side (segment 0) on 0..2.
    dom = square([[2, 0], [1, 0]], [[4, 0]])
    with pytest.raises(InvalidInputError, match=r"segment 0 .* and segment 4 .* are collinear and overlap"):
        validate_domain(dom, split_points_on_segments=False)
    d = validate_domain(dom)
    # segment 0 -> 0-5, 5-4, 4-1; segment 4 (4 to 0) -> 4-5, 5-0: both pieces repeat, and are dropped.
    assert d.segments.tolist() == [[0, 5], [5, 4], [4, 1], [1, 2], [2, 3], [3, 0]]
    assert any("overlapped" in r for r in d.repairs) and any("dropped 2 duplicate" in r for r in d.repairs)


def test_open_boundary_names_the_dangling_ends():
    # Three sides of the square: nothing is enclosed, both ends (points 0 and 3) dangle.
    dom = Domain(SQUARE, LOOP[:3])
    with pytest.raises(
        InvalidInputError, match=r"not closed; dangling ends at point 0 .*, point 3 .*convex_hull=True"
    ):
        validate_domain(dom)
    assert validate_domain(dom, require_closed=False).segments.tolist() == LOOP[:3]
    dom.convex_hull = True
    assert validate_domain(dom).convex_hull


def test_segment_sticking_out_is_refused_but_a_crack_inside_is_allowed():
    # (4, 4)-(6, 6) leaves the square: exterior on both sides; (1, 1)-(2, 2) is a crack inside it.
    with pytest.raises(
        InvalidInputError, match=r"segment 4 \(points 2, 4.*dangling ends at point 4 at \(6\.0, 6\.0\)"
    ):
        validate_domain(square([[6, 6]], [[2, 4]]))
    assert validate_domain(square([[1, 1], [2, 2]], [[4, 5]])).repairs == []


@pytest.mark.parametrize(
    "kw, message",
    [
        ({"holes": [[5, 5]]}, r"hole seed 0 at \(5\.0, 5\.0\) lies not inside a closed loop"),
        ({"holes": [[0, 2]]}, r"hole seed 0 at \(0\.0, 2\.0\) lies exactly on a point or a segment"),
        (
            {"regions": [[-1, 1, 3]]},
            r"region seed 0 at \(-1\.0, 1\.0\) attribute 3\.0 lies not inside the domain",
        ),
        ({"regions": [[4, 4, 3]]}, "region seed 0 .* lies exactly on a point or a segment"),
        # a hole seed removing the whole square: each side has a hole on one side, the exterior on the other
        ({"holes": [[1, 1]]}, "segment 0 .* has no domain triangle on either side"),
    ],
)
def test_seeds(kw, message):
    with pytest.raises(InvalidInputError, match=message):
        validate_domain(square(**kw))


def test_hole_and_region_seeds_inside_the_domain_pass():
    inner = [[1, 1], [3, 1], [3, 3], [1, 3]]
    d = validate_domain(
        square(inner, [[4, 5], [5, 6], [6, 7], [7, 4]], holes=[[2, 2]], regions=[[0.5, 0.5, 1]])
    )
    assert d.repairs == []
    # A region seed inside the hole is outside the domain.
    with pytest.raises(InvalidInputError, match="region seed 0 .* lies not inside the domain"):
        validate_domain(
            square(inner, [[4, 5], [5, 6], [6, 7], [7, 4]], holes=[[2, 2]], regions=[[2.5, 2, 1]])
        )


def test_collinear_points_have_no_triangle():
    with pytest.raises(InvalidInputError, match="the domain contains no triangle"):
        validate_domain(Domain([[0, 0], [1, 1], [2, 2]], convex_hull=True))
    with pytest.raises(InvalidInputError, match="hole seed 0 .* lies not inside the convex hull"):
        validate_domain(Domain([[0, 0], [1, 1], [2, 2]], holes=[[0.5, 0.5]], convex_hull=True))


def test_exactness_near_misses_are_not_reported():
    # (2, 1e-300) is not on the bottom side y = 0 and a segment ending there does not touch it: both valid.
    d = validate_domain(square([[2, 1e-300], [2, 1]], [[4, 5]]))
    assert d.repairs == []


# ---- property test: non-crossing stars, then one crossing ----
# Each star lives in its own 2 x 2 cell: a center near the cell's middle and spokes of length at most
# 0.375 * sqrt(2) < 1 in distinct compass directions, so spokes of one star meet only at the center and stars
# never meet. Every coordinate is a multiple of 1/64 (dyadic), so the constructions below are exact.

DIRECTIONS = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1)]


@st.composite
def stars(draw):
    points, segments = [], []
    n_cells = draw(st.integers(1, 6))
    for cell in range(n_cells):
        cx = 2 * cell + 1 + draw(st.integers(-6, 6)) / 64
        cy = 1 + draw(st.integers(-6, 6)) / 64
        center = len(points)
        points.append([cx, cy])
        for dx, dy in draw(st.lists(st.sampled_from(DIRECTIONS), min_size=1, max_size=8, unique=True)):
            r = draw(st.sampled_from([0.125, 0.25, 0.375]))
            segments.append([center, len(points)])
            points.append([cx + r * dx, cy + r * dy])
    return points, segments


@settings(derandomize=True, deadline=None, max_examples=60)
@given(stars(), st.data())
def test_random_non_crossing_segments_pass_and_an_added_crossing_is_named(star, data):
    points, segments = star
    d = validate_domain(Domain(points, segments), require_closed=False)
    assert d.repairs == [] and d.segments.tolist() == segments
    # Cross spoke s at its midpoint m = c + (r/2) d with the segment m +- (r/4) d_perp: it reaches at most
    # r |d| / 4 from m, the next spoke (45 degrees away) is r |d| / 2 from m along that line: only s crosses.
    s = data.draw(st.integers(0, len(segments) - 1))
    c, e = np.array(points[segments[s][0]]), np.array(points[segments[s][1]])
    m, half = (c + e) / 2, (e - c) / 2
    perp = np.array([-half[1], half[0]]) / 2
    n = len(points)
    crossing = Domain(points + [list(m + perp), list(m - perp)], segments + [[n, n + 1]])
    with pytest.raises(InvalidInputError) as err:
        validate_domain(crossing, require_closed=False)
    assert f"segment {s} (" in str(err.value) and f"segment {len(segments)} (" in str(err.value)
    assert "cross away from their endpoints" in str(err.value)


@settings(derandomize=True, deadline=None, max_examples=40)
@given(stars(), st.data())
def test_points_placed_on_segments_split_them_into_chains(star, data):
    points, segments = star
    # Put points at c + (k/8)(e - c), 0 < k < 8, on some spokes: exact (dyadic), strictly inside, distinct.
    added = []
    for s in data.draw(st.lists(st.integers(0, len(segments) - 1), max_size=4, unique=True)):
        c, e = np.array(points[segments[s][0]]), np.array(points[segments[s][1]])
        for k in data.draw(st.lists(st.integers(1, 7), min_size=1, max_size=3, unique=True)):
            added.append(list(c + (k / 8) * (e - c)))
    d = validate_domain(Domain(points + added, segments), require_closed=False)
    # Each added point splits one spoke once: one more segment per point, and each joins two subsegments.
    assert len(d.segments) == len(segments) + len(added)
    degree = np.bincount(d.segments.ravel(), minlength=len(points) + len(added))
    assert all(degree[len(points) :] == 2)
    assert (len(d.repairs) > 0) == (len(added) > 0)
    # The result is a valid graph with nothing left to split.
    again = validate_domain(d, split_points_on_segments=False, require_closed=False)
    assert again.repairs == d.repairs and np.array_equal(again.segments, d.segments)
