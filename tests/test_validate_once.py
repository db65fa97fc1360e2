"""Validation happens once, at the API entry: a validated Domain (``Domain.validated``, set only by
nonobtuse.validate) is never checked again, an unvalidated one exactly once, and no entry point modifies its
argument. Validator runs are counted at the two exact C++ validators every validation calls."""

from __future__ import annotations

import copy
import dataclasses
import pickle

import numpy as np
import pytest

import nonobtuse
from nonobtuse import Domain, _core
from nonobtuse.cli import main
from nonobtuse.domain import kept_triangulation
from nonobtuse.errors import InvalidInputError
from nonobtuse.io import load_domain
from nonobtuse.validate import check_coverage, ensure_validated, validate_domain

# A square with a point on its bottom edge (validation splits segment 0 there) and one interior point.
POINTS = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0], [2.0, 0.0], [2.0, 3.9]]
LOOP = [[0, 1], [1, 2], [2, 3], [3, 0]]
POLY = "6 2 0 0\n" + "".join(f"{i} {x} {y}\n" for i, (x, y) in enumerate(POINTS)) + "4 0\n" + "".join(
    f"{i} {a} {b}\n" for i, (a, b) in enumerate(LOOP)
) + "0\n"


@pytest.fixture
def validator_runs(monkeypatch):
    """How many times each exact validator of nonobtuse.validate ran since the fixture was made."""
    runs = {"find_segment_intersections": 0, "inspect_domain": 0}
    for name in runs:
        real = getattr(_core, name)

        def counted(*args, _real=real, _name=name, **kwargs):
            runs[_name] += 1
            return _real(*args, **kwargs)

        monkeypatch.setattr(_core, name, counted)
    return runs


def square() -> Domain:
    return Domain(POINTS, LOOP)


ENTRY_POINTS = {
    "triangulate": nonobtuse.triangulate,
    "check": nonobtuse.check,
    "refine": nonobtuse.refine,
}


@pytest.mark.parametrize("entry", ENTRY_POINTS)
def test_a_validated_domain_is_not_validated_again(entry, validator_runs):
    domain = validate_domain(square())
    assert domain.validated
    validator_runs.update(dict.fromkeys(validator_runs, 0))
    ENTRY_POINTS[entry](domain)
    assert validator_runs == {"find_segment_intersections": 0, "inspect_domain": 0}


@pytest.mark.parametrize("entry", ENTRY_POINTS)
def test_an_unvalidated_domain_is_validated_exactly_once(entry, validator_runs):
    domain = square()
    assert not domain.validated
    ENTRY_POINTS[entry](domain)
    assert validator_runs == {"find_segment_intersections": 1, "inspect_domain": 1}


@pytest.mark.parametrize("command", ["triangulate", "check", "refine"])
def test_the_cli_validates_a_file_once(command, tmp_path, validator_runs):
    (tmp_path / "sq.poly").write_text(POLY)
    output = [] if command == "check" else ["-o", str(tmp_path / "o.json")]
    # check exits 1: the apex (2, 3.9) is obtuse opposite the top edge; refine repairs that
    assert main([command, str(tmp_path / "sq.poly"), *output]) == (1 if command == "check" else 0)
    assert validator_runs == {"find_segment_intersections": 1, "inspect_domain": 1}


def test_unvalidated_and_validated_domains_refine_alike():
    # The point on segment 0 is split into the boundary either way: the same mesh.
    a, b = nonobtuse.refine(square()), nonobtuse.refine(validate_domain(square()))
    assert a.mesh.segments.tolist() == b.mesh.segments.tolist()
    assert np.array_equal(a.mesh.points, b.mesh.points)
    assert a.stats["steiner_points"] == b.stats["steiner_points"] > 0
    assert a.mesh.input_segments.tolist() == validate_domain(square()).segments.tolist()


def snapshot(d: Domain) -> dict:
    return {f.name: (np.array(v) if isinstance(v := getattr(d, f.name), np.ndarray) else v)
            for f in dataclasses.fields(d)} | {"repairs": list(d.repairs), "validated": d.validated}


def same(a: dict, b: dict) -> bool:
    return a.keys() == b.keys() and all(
        np.array_equal(a[k], b[k]) if isinstance(a[k], np.ndarray) else a[k] == b[k] for k in a
    )


@pytest.mark.parametrize("entry", ENTRY_POINTS)
@pytest.mark.parametrize("validated", [False, True])
def test_no_entry_point_modifies_its_argument(entry, validated):
    domain = validate_domain(square()) if validated else square()
    before = snapshot(domain)
    ENTRY_POINTS[entry](domain)
    assert same(snapshot(domain), before)


def test_check_coverage_decides_the_hull_on_a_copy():
    # A point set (no segments): the hull is decided True, on the copy only.
    d = Domain([[0, 0], [1, 0], [0, 1], [1, 1]])
    out = check_coverage(d, decide_convex_hull=True)
    assert out.convex_hull and not d.convex_hull and out is not d
    # Only dangling segments (they enclose nothing): decided False on the copy, so refused as an open
    # boundary (the hull closes it only when asked); the argument is untouched either way.
    d = Domain([[0, 0], [1, 0], [0, 1], [1, 1]], [[0, 3]])
    with pytest.raises(InvalidInputError, match=r"not closed; dangling ends at .*convex_hull=True"):
        check_coverage(d, decide_convex_hull=True)
    assert not d.convex_hull and d.repairs == []
    d.convex_hull = True
    out = check_coverage(d, decide_convex_hull=False)
    assert out is d and d.convex_hull


def test_load_domain_marks_the_domain_validated(tmp_path):
    (tmp_path / "sq.poly").write_text(POLY)
    d = load_domain(tmp_path / "sq.poly")
    assert d.validated and ensure_validated(d) is d
    assert d.segments.tolist() == [[0, 4], [4, 1], [1, 2], [2, 3], [3, 0]]  # the repair


def test_only_the_validator_marks_and_any_change_unmarks():
    given = np.array(POINTS)
    d = validate_domain(Domain(given, LOOP))
    assert d.validated and not Domain(given, LOOP).validated
    given[0, 0] = -1.0  # the caller's arrays are not the validated domain's
    assert d.points[0, 0] == 0.0 and d.validated
    assert not dataclasses.replace(d).validated
    d.holes = np.zeros((0, 2))
    assert not d.validated
    assert not validate_domain(square(), require_closed=False).validated  # a partial check does not mark


def holed_square_with_regions() -> Domain:
    """A square with a square hole, an interface across it and two region seeds."""
    pts = [[0, 0], [6, 0], [6, 6], [0, 6], [2, 2], [4, 2], [4, 4], [2, 4], [3, 0], [3, 2], [1.1, 5.2]]
    segs = [[0, 8], [8, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4], [8, 9]]
    return Domain(pts, segs, holes=[[3, 3]], regions=[[1, 1, 1.0], [5, 1, 2.0]])


KEPT_TRIANGULATION_CASES = {
    "holed square with regions": holed_square_with_regions,
    "point set": lambda: Domain(np.random.default_rng(3).uniform(0, 1, (200, 2)), convex_hull=True),
    "square": square,
}


def refined(domain: Domain) -> tuple[dict, dict]:
    r = nonobtuse.refine(domain)
    arrays = {k: getattr(r.mesh, k) for k in ("points", "triangles", "segments", "regions")}
    return arrays, {k: v for k, v in r.stats.items() if k != "seconds"}


@pytest.mark.parametrize("case", KEPT_TRIANGULATION_CASES)
def test_refine_takes_over_the_triangulation_of_validation(case):
    # The validated domain carries validation's triangulation; refine takes it (it is empty afterwards) and
    # the result equals a refine that triangulates on its own (a copy carries no triangulation).
    domain = validate_domain(KEPT_TRIANGULATION_CASES[case]())
    kept = kept_triangulation(domain)
    assert kept is not None and not kept.empty
    assert kept_triangulation(copy.deepcopy(domain)) is None and copy.deepcopy(domain).validated
    alone = refined(copy.deepcopy(domain))
    taken = refined(domain)
    assert kept.empty
    assert same(taken[0], alone[0]) and taken[1] == alone[1]
    assert same(refined(domain)[0], alone[0])  # once taken, refine triangulates again


def test_a_kept_triangulation_of_another_domain_is_not_used():
    # Editing a validated domain's arrays in place is not detected by the Domain; the core compares the
    # domain it is given with the one the kept triangulation was built of, and triangulates again.
    domain = validate_domain(holed_square_with_regions())
    domain.points[10] = [1.3, 5.1]  # the interior point, still inside
    kept = kept_triangulation(domain)
    edited = refined(domain)
    assert kept.empty  # taken, and dropped
    assert edited[0]["points"][10].tolist() == [1.3, 5.1]  # the kept one has the point at (1.1, 5.2)
    assert same(edited[0], refined(validate_domain(dataclasses.replace(domain)))[0])


def test_assigning_a_field_drops_the_kept_triangulation():
    domain = validate_domain(square())
    assert kept_triangulation(domain) is not None
    domain.regions = np.zeros((0, 3))
    assert kept_triangulation(domain) is None
    assert kept_triangulation(pickle.loads(pickle.dumps(validate_domain(square())))) is None
