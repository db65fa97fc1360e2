"""Reference counts for the 2D benchmarks: the CG:SHOP 2025 best known Steiner counts (every triangle
nonobtuse, a stronger requirement than ours)."""

from __future__ import annotations

import csv
from functools import lru_cache
from pathlib import Path

SHARED = Path(__file__).resolve().parents[1] / ".." / "shared" / "data"


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
