"""Timing of 2D domain validation (nonobtuse.validate.validate_domain) on large generated inputs and Sweden.

Run: PYTHONPATH=src .venv/bin/python -m experiments.validate2d_timing [n]   (default n = 1_000_000)
Prints seconds for: n uniform random points (convex hull), a smooth star-shaped n-gon
(r = 1 + 0.2 sin 7t), and cdt_Constrained_Sweden.poly with convex_hull=True when ../shared/data is present;
then what validating once saves: triangulate on the n-gon as validated (not checked again) and as built
(validated once inside).
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

from nonobtuse import triangulate
from nonobtuse.domain import Domain
from nonobtuse.io import load_domain
from nonobtuse.validate import validate_domain


def timed(label: str, f) -> None:
    t = time.perf_counter()
    f()
    print(f"{label}: {time.perf_counter() - t:.2f} s")


def main(n: int) -> None:
    rng = np.random.default_rng(1)
    timed(f"{n} random points", lambda: validate_domain(Domain(rng.random((n, 2)), convex_hull=True)))
    t = np.sort(rng.random(n)) * 2 * np.pi
    r = 1 + 0.2 * np.sin(7 * t)
    polygon = Domain(np.column_stack([r * np.cos(t), r * np.sin(t)]),
                     np.column_stack([np.arange(n), (np.arange(n) + 1) % n]))  # fmt: skip
    timed(f"{n}-gon", lambda: validate_domain(polygon))
    valid = validate_domain(polygon)
    timed(f"{n}-gon triangulate, validated domain (no second check)", lambda: triangulate(valid))
    timed(f"{n}-gon triangulate, unvalidated domain (checked once inside)", lambda: triangulate(polygon))
    shared = Path(__file__).resolve().parents[1] / ".." / "shared" / "data"
    sweden = shared / "2d" / "cdt_Constrained_Sweden.poly"
    if sweden.exists():
        timed("Sweden (2619 segments, convex hull)", lambda: load_domain(sweden, convex_hull=True))


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000)
