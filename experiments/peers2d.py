"""Peers and reference counts for the 2D benchmarks: CGAL make_conforming_Gabriel_2 and the CG:SHOP 2025 best
known Steiner counts (all-triangle nonobtuse, a stronger requirement than ours)."""

from __future__ import annotations

import csv
import time
from functools import lru_cache
from pathlib import Path

from nonobtuse import Domain, _core

SHARED = Path(__file__).resolve().parents[1] / ".." / "shared" / "data"


def cgal_gabriel(domain: Domain) -> tuple[int, float]:
    """Steiner points and seconds of CGAL make_conforming_Gabriel_2 on the domain's constrained Delaunay
    triangulation (every constraint Gabriel on both sides, exterior included)."""
    t0 = time.perf_counter()
    n = _core.conforming_gabriel_points(
        domain.points, domain.segments, domain.holes, domain.regions, bool(domain.convex_hull)
    )
    return n - len(domain.points), time.perf_counter() - t0


@lru_cache(maxsize=1)
def _best_known() -> dict[str, int]:
    path = SHARED / "cgshop25" / "best_known.csv"
    if not path.exists():
        return {}
    with path.open() as fh:
        return {r["instance_uid"]: int(r["best_known_steiner"]) for r in csv.DictReader(fh)}


def best_known(instance_uid: str) -> int | None:
    """best_known.csv's best_known_steiner for a CG:SHOP instance uid, None when unknown."""
    return _best_known().get(instance_uid)
