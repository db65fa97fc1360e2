"""Validation of a 2D domain (planar straight-line graph) before meshing.

:func:`validate_domain` returns a repaired copy of the domain or raises :class:`InvalidInputError` naming the
problem and where: the index (0-based), the coordinates and, when the domain was read from a file, the file
and line. Checks, in this order:

1. values: at least one point; every coordinate of points, holes and regions finite; segment indices in range.
2. duplicate points (exact equality of both coordinates): both indices named.
3. zero-length segments (both ends the same point).
4. segment intersections, decided exactly in C++ (:func:`nonobtuse._core.find_segment_intersections`):
   segments crossing away from their endpoints are refused (the pair named); a point lying strictly inside a
   segment splits it there (a repair), or is refused when ``split_points_on_segments=False``; collinear
   segments sharing a piece are split at each other's endpoints and the shared piece kept once (a repair), or
   refused when ``split_points_on_segments=False``.
5. duplicate segments (the same two points, either order) are dropped, keeping the first (a repair).
6. coverage (:func:`check_coverage`): hole seeds must lie inside a closed loop of segments (or inside the
   convex hull when ``domain.convex_hull``), region seeds inside the domain, neither exactly on a point or a
   segment; with ``require_closed``, the boundary must be closed and the domain non-empty.

Closed boundary rule. The domain is what the constrained Delaunay triangulation of the points and segments
covers once the exterior (triangles reachable from the unbounded face without crossing a segment) and the
holes are removed. The boundary is closed iff every segment has a domain triangle on at least one side. A
segment with no domain triangle on either side lies in the exterior (an outer boundary that does not close, as
in Triangle's box.poly, or a segment sticking out of the domain) or inside a hole; it is refused and its
dangling ends (points on exactly one segment) are named. Dangling segments inside the domain (cracks, wells,
face.poly's nostrils) have the domain on both sides and are allowed. With ``domain.convex_hull`` the hull
edges close the boundary.

Every repair is recorded as a sentence in ``Domain.repairs``. :func:`validate_domain` marks what it returns as
validated (``Domain.validated``), so the API entry points (:func:`ensure_validated`) never check it twice,
and hands it the triangulation of check 6, which :func:`nonobtuse.refine` takes over instead of triangulating
again.
Cost: O(n log n) for sorting and the triangulation, plus the box-intersection search for segment pairs
(near-linear for real inputs).
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from nonobtuse import _core
from nonobtuse.domain import Domain, SourceMap, mark_validated
from nonobtuse.errors import InvalidInputError

__all__ = [
    "check_coverage", "ensure_validated", "require_points_in_domain", "validate_domain", "validate_graph",
]

_SHOWN = 5  # how many offending items a message lists before "and N more"

# Seed places returned by _core.inspect_domain.
_INSIDE, _OUTSIDE, _ON_BOUNDARY = 0, 1, 2


def validate_domain(
    domain: Domain,
    *,
    split_points_on_segments: bool = True,
    require_closed: bool = True,
    decide_convex_hull: bool = False,
) -> Domain:
    """Check ``domain`` and return a repaired copy (``domain`` itself is not modified).

    Inputs: a :class:`Domain`; its ``convex_hull`` flag says whether the convex hull closes the boundary
    (with ``decide_convex_hull``, the flag is decided instead, see :func:`check_coverage`).
    Output: a Domain whose segments are split at every point lying on them and free of duplicates, with the
    repairs listed in ``repairs`` and ``origin`` line numbers following the split segments. With
    ``require_closed`` (the default) it is marked validated (``Domain.validated``: arrays of its own), and the
    API entry points take it as it is; a domain checked with ``require_closed=False`` is not marked.
    Guarantees (all decided exactly): finite coordinates, pairwise distinct points, no zero-length, crossing,
    overlapping or duplicate segments, no point strictly inside a segment, hole and region seeds inside the
    domain; with ``require_closed``, a closed boundary and at least one triangle (see the module docstring).
    Raises :class:`InvalidInputError` naming the first problem found and where.
    """
    d, triangulation = _check_coverage(
        validate_graph(domain, split_points_on_segments=split_points_on_segments),
        require_closed=require_closed,
        decide_convex_hull=decide_convex_hull,
        keep_triangulation=require_closed,
    )
    return mark_validated(d, triangulation) if require_closed else d


def ensure_validated(domain: Domain) -> Domain:
    """``domain`` itself when it is validated (``Domain.validated``), else ``validate_domain(domain)``: what
    the API entry points call, so that a domain is validated exactly once. Raises as validate_domain."""
    return domain if domain.validated else validate_domain(domain)


def validate_graph(domain: Domain, *, split_points_on_segments: bool = True) -> Domain:
    """Checks 1-5 of the module docstring (everything but coverage); returns the repaired copy."""
    d = dataclasses.replace(domain, repairs=list(domain.repairs))
    _check_values(d)
    _check_duplicate_points(d)
    _check_zero_length_segments(d)
    found = _core.find_segment_intersections(d.points, d.segments)
    crossings = found.crossings
    if len(crossings):
        s, t = crossings[0]
        raise _invalid(d, f"{_seg(d, s)} and {_seg(d, t)} cross away from their endpoints" + _more(crossings))
    overlaps = [(s, t) for s, t in found.overlaps if sorted(d.segments[s]) != sorted(d.segments[t])]
    on_segments = found.points_on_segments
    if not split_points_on_segments and overlaps:
        s, t = overlaps[0]
        raise _invalid(d, f"{_seg(d, s)} and {_seg(d, t)} are collinear and overlap" + _more(overlaps))
    if not split_points_on_segments and len(on_segments):
        p, s = on_segments[0]
        raise _invalid(d, f"{_pt(d, p)} lies inside {_seg(d, s)}" + _more(on_segments))
    if len(on_segments):
        _split_segments(d, on_segments, overlaps)
    _drop_duplicate_segments(d)
    return d


def check_coverage(
    domain: Domain, *, require_closed: bool = True, decide_convex_hull: bool = False
) -> Domain:
    """Check 6 of the module docstring on a domain that passed :func:`validate_graph`. Returns ``domain``,
    or with ``decide_convex_hull`` a copy whose ``convex_hull`` is decided: True for a point set (no
    segments), else False. Segments that enclose no area (an open polygon, or only dangling segments) are then
    an open boundary, refused naming its dangling ends: the convex hull closes such a domain only when asked
    (``convex_hull=True``). ``domain`` is not modified. Cost: one constrained Delaunay triangulation.
    """
    return _check_coverage(domain, require_closed=require_closed, decide_convex_hull=decide_convex_hull)[0]


def _check_coverage(
    domain: Domain, *, require_closed: bool, decide_convex_hull: bool, keep_triangulation: bool = False
) -> tuple[Domain, Any]:
    """check_coverage, and the triangulation it built (``_core.Triangulation2``) when ``keep_triangulation``
    and the domain has a triangle, else None."""
    d = domain
    if decide_convex_hull:
        d = dataclasses.replace(domain, convex_hull=len(domain.segments) == 0, repairs=list(domain.repairs))
    cov = _core.inspect_domain(
        d.points, d.segments, d.holes, d.regions, d.convex_hull, keep_triangulation=keep_triangulation
    )
    for kind, places, inside in (
        (
            "hole",
            cov.holes,
            "inside the convex hull" if d.convex_hull else "inside a closed loop of segments",
        ),
        ("region", cov.regions, "inside the domain (not in the exterior nor in a hole)"),
    ):
        bad = np.flatnonzero(places != _INSIDE)
        if len(bad):
            i = int(bad[0])
            where = "exactly on a point or a segment" if places[i] == _ON_BOUNDARY else f"not {inside}"
            raise _invalid(d, f"{_seed(d, kind, i)} lies {where}" + _more(bad))
    if not require_closed:
        return d, cov.triangulation
    outside = cov.segments_outside
    if len(outside):
        raise _invalid(d, _open_boundary_message(d, outside))
    if cov.domain_triangles == 0:
        raise _invalid(d, "the domain contains no triangle (are all points collinear?)")
    return d, cov.triangulation


def _open_boundary_message(d: Domain, outside: np.ndarray) -> str:
    degree = np.bincount(d.segments.ravel(), minlength=len(d.points))
    ends = [int(v) for v in np.unique(d.segments[outside].ravel()) if degree[v] == 1]
    msg = (
        f"{_seg(d, int(outside[0]))} has no domain triangle on either side: it lies in the exterior or in "
        "a hole" + _more(outside) + ". The boundary is not closed"
    )
    if ends:
        msg += "; dangling ends at " + ", ".join(_pt(d, v) for v in ends[:_SHOWN])
        msg += f" (and {len(ends) - _SHOWN} more)" if len(ends) > _SHOWN else ""
    hint = (
        "" if d.convex_hull
        else " (pass convex_hull=True, or --convex-hull to the command, to close it with the convex hull, "
        "like Triangle -c)"
    )
    return msg + hint


# ---- checks 1-3 --------------------------------------------------------------------------------------------


def _check_values(d: Domain) -> None:
    if len(d.points) == 0:
        raise _invalid(d, "the domain has no points")
    for kind, arr in (("point", d.points), ("hole", d.holes), ("region", d.regions)):
        bad = np.flatnonzero(~np.isfinite(arr).all(axis=1))
        if len(bad):
            i = int(bad[0])
            item = _pt(d, i) if kind == "point" else _seed(d, kind, i)
            raise _invalid(d, f"{item} has a coordinate or value that is not finite" + _more(bad))
    bad = np.flatnonzero(((d.segments < 0) | (d.segments >= len(d.points))).any(axis=1))
    if len(bad):
        s = int(bad[0])
        raise _invalid(
            d,
            f"segment {s}{_line(d, 'segments', s)} refers to a point that does not exist "
            f"({len(d.points)} points)" + _more(bad),
        )


def _check_duplicate_points(d: Domain) -> None:
    # Equal points have equal x: without two equal x (random inputs), one plain sort of x settles it (0.01 s
    # at 1e6 points against 0.2 s for the lexicographic sort below, which runs otherwise).
    x = np.sort(d.points[:, 0])
    if not (x[1:] == x[:-1]).any():
        return
    # Lexicographic order of (x, y), stable: as np.lexsort((y, x)), in half its time at 1e6 points (a complex
    # number orders by its real part, then its imaginary part; the points are finite here).
    xy = np.ascontiguousarray(d.points).view(np.complex128).ravel()
    order = np.argsort(xy, kind="stable")
    p = d.points[order]
    equal = np.flatnonzero((p[1:] == p[:-1]).all(axis=1))
    if len(equal):
        i, j = sorted((int(order[equal[0]]), int(order[equal[0] + 1])))
        raise _invalid(d, f"duplicate points: {_pt(d, i)} and {_pt(d, j)} are equal" + _more(equal))


def _check_zero_length_segments(d: Domain) -> None:
    bad = np.flatnonzero(d.segments[:, 0] == d.segments[:, 1])
    if len(bad):
        raise _invalid(d, f"{_seg(d, int(bad[0]))} has zero length" + _more(bad))


# ---- repairs -----------------------------------------------------------------------------------------------


def _split_segments(d: Domain, on_segments: np.ndarray, overlaps: list[tuple[int, int]]) -> None:
    """Replace every segment by the chain through the points lying inside it, ordered along the segment
    (lexicographic order of exact coordinates: the points are collinear)."""
    inside: dict[int, list[int]] = {}
    for p, s in on_segments:
        inside.setdefault(int(s), []).append(int(p))
    rows: list[tuple[int, int]] = []
    lines: list[int] = []
    seg_lines = _lines(d, "segments")
    for s, (a, b) in enumerate(d.segments):
        chain = [int(a), *sorted(inside.get(s, []), key=lambda v: tuple(d.points[v])), int(b)]
        if len(chain) > 2 and tuple(d.points[a]) > tuple(d.points[b]):
            chain[1:-1] = chain[-2:0:-1]
        rows.extend(zip(chain[:-1], chain[1:]))
        lines.extend([seg_lines[s]] * (len(chain) - 1))
        if len(chain) > 2:
            d.repairs.append(
                f"{_seg(d, s)} split at {len(chain) - 2} point(s) lying on it: {chain[1:-1][:_SHOWN]}"
            )
    for s, t in overlaps:
        d.repairs.append(f"{_seg(d, s)} and {_seg(d, t)} overlapped: the shared piece is kept once")
    d.segments = np.array(rows, dtype=np.int64).reshape(-1, 2)
    if d.segment_markers is not None:  # every piece keeps the marker of the segment it came from
        pieces = [len(inside.get(s, [])) + 1 for s in range(len(d.segment_markers))]
        d.segment_markers = np.repeat(d.segment_markers, pieces)
    _set_lines(d, "segments", lines)


def _drop_duplicate_segments(d: Domain) -> None:
    ends = np.sort(d.segments, axis=1)
    key = ends[:, 0] * max(len(d.points), 1) + ends[:, 1]  # one integer per point pair (indices are checked)
    _, first = np.unique(key, return_index=True)  # first occurrences (stable), a quarter of axis=0's time
    if len(first) == len(d.segments):
        return
    keep = np.sort(first)
    dropped = np.setdiff1d(np.arange(len(d.segments)), keep)
    d.repairs.append(
        f"dropped {len(dropped)} duplicate segment(s), e.g. {_seg(d, int(dropped[0]))} (the same two "
        "points as an earlier segment)"
    )
    lines = _lines(d, "segments")
    d.segments = np.ascontiguousarray(d.segments[keep])
    if d.segment_markers is not None:
        d.segment_markers = np.ascontiguousarray(d.segment_markers[keep])
    _set_lines(d, "segments", [lines[i] for i in keep])


# ---- messages ----------------------------------------------------------------------------------------------


def _num(x: float) -> str:
    return repr(float(x))


def _xy(p: np.ndarray) -> str:
    return f"({_num(p[0])}, {_num(p[1])})"


def _lines(d: Domain, kind: str) -> list[int]:
    n = len(getattr(d, kind))
    lines = getattr(d.origin, kind) if d.origin is not None else np.zeros(0, np.int64)
    return [int(x) for x in lines] if len(lines) == n else [0] * n


def _set_lines(d: Domain, kind: str, lines: list[int]) -> None:
    if d.origin is not None:
        changes: dict[str, Any] = {kind: np.array(lines, dtype=np.int64)}
        d.origin = dataclasses.replace(d.origin, **changes)


def _line(d: Domain, kind: str, i: int) -> str:
    line = _lines(d, kind)[i]
    if not line or d.origin is None:
        return ""
    other = d.origin.points_file if kind == "points" else None
    return f" (line {line} of {other})" if other else f" (line {line})"


def _invalid(d: Domain, message: str) -> InvalidInputError:
    """The error to raise: ``message`` prefixed with the domain's source, unless it was made in memory."""
    return InvalidInputError(message if d.source == "<memory>" else f"{d.source}: {message}")


def _id(d: Domain, i: int) -> str:
    origin: SourceMap | None = d.origin
    return f" (id {i + origin.first_id} in the file)" if origin is not None and origin.first_id else ""


def _pt(d: Domain, i: int) -> str:
    return f"point {i}{_id(d, i)} at {_xy(d.points[i])}{_line(d, 'points', i)}"


def _seg(d: Domain, s: int) -> str:
    a, b = (int(v) for v in d.segments[s])
    ends = f"{_xy(d.points[a])}-{_xy(d.points[b])}" if max(a, b) < len(d.points) and min(a, b) >= 0 else "?"
    return f"segment {s} (points {a}, {b}: {ends}){_line(d, 'segments', s)}"


def _seed(d: Domain, kind: str, i: int) -> str:
    row = d.holes[i] if kind == "hole" else d.regions[i]
    values = f" attribute {_num(row[2])}" if kind == "region" else ""
    return f"{kind} seed {i} at {_xy(row)}{values}{_line(d, kind + 's', i)}"


def _more(items) -> str:
    return f" (and {len(items) - 1} more)" if len(items) > 1 else ""


def require_points_in_domain(domain: Domain, mesh_triangles: np.ndarray) -> None:
    """InvalidInputError naming the points of ``domain`` that no triangle uses: they lie outside the domain
    (in the exterior or in a hole), and a mesh keeping them unreferenced would be silently wrong.
    mesh_triangles: (m, 3) int indices of a mesh whose first points are ``domain.points`` in order.
    Cost: O(m).
    """
    n = len(domain.points)
    used = np.zeros(n, dtype=bool)
    corners = np.asarray(mesh_triangles).ravel()
    used[corners[corners < n]] = True
    bad = np.flatnonzero(~used)
    if len(bad):
        raise _invalid(
            domain,
            f"{_pt(domain, int(bad[0]))} lies outside the domain (in the exterior or in a hole: no triangle "
            "uses it)" + _more(bad) + "; remove it, or close the boundary around it",
        )
