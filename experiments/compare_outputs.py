"""2D refinement outputs saved once and compared later: identical Steiner points after a speed change.

``save`` refines every input below (greedy, default budget) and writes, per input, the mesh points, the
status, the Steiner count and the lower bound to ``DIR/NAME.npz``; ``compare`` refines them again and reports,
per input, whether the counts, the bound, the status and every coordinate (bit for bit) are identical. Exit
status 1 when any differs. The inputs: the ``bench_scaling`` families (star 1k, 5k, 10k, 30k; polygon, thin
layer, convex and point set at 1e4 and 1e5) and every 2D file of the shared corpus (``../shared/data/2d``; an
open boundary closed by the convex hull; files validation refuses are skipped).

    PYTHONPATH=src:. .venv/bin/python -m experiments.compare_outputs save DIR [--quick]
    PYTHONPATH=src:. .venv/bin/python -m experiments.compare_outputs compare DIR [--quick]

Keep DIR outside the repository (a scratch folder): it is the reference of one checkout.
``--quick`` keeps the inputs under 1e4 vertices and the corpus.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

from experiments.bench_scaling import domain_of

CORPUS = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "2d"
FAMILY_SIZES = [("star", 1_000), ("star", 5_000), ("star", 10_000), ("star", 30_000)] + [
    (f, n) for f in ("polygon", "thin_layer", "convex", "point_set") for n in (10_000, 100_000)
]


def inputs(quick: bool):
    """(name, loader) pairs: the families, then the shared 2D corpus files (when present)."""
    for family, n in FAMILY_SIZES:
        if not quick or n < 10_000:
            yield f"{family}_{n}", lambda family=family, n=n: domain_of(family, n, 0)
    if CORPUS.is_dir():
        for path in sorted(CORPUS.iterdir()):
            if path.suffix in (".poly", ".node"):
                yield path.stem, lambda path=path: corpus_domain(path)


def corpus_domain(path: Path):
    """The corpus file as the command reads it, closed by the convex hull when its boundary is open
    (box.poly); None when validation refuses it either way (cdt_cdt.poly's zero-length segments)."""
    from nonobtuse import InvalidInputError
    from nonobtuse.io import load_domain

    for hull in (None, True):
        try:
            return load_domain(path, convex_hull=hull)
        except InvalidInputError:
            pass
    return None


def outcome(domain) -> dict[str, np.ndarray]:
    """The compared fields of refining ``domain`` with the defaults."""
    from nonobtuse import refine

    r = refine(domain)
    return {"points": r.mesh.points, "status": np.array(r.status),
            "steiner_points": np.array(r.stats["steiner_points"]),
            "lower_bound": np.array(r.stats["lower_bound"])}


def differences(saved: dict[str, np.ndarray], now: dict[str, np.ndarray]) -> list[str]:
    """What differs between two outcomes (empty when identical bit for bit)."""
    keys = ("status", "steiner_points", "lower_bound")
    out = [f"{k}: {saved[k]} -> {now[k]}" for k in keys if saved[k] != now[k]]
    a, b = saved["points"], now["points"]
    if a.shape != b.shape:
        out.append(f"points: shape {a.shape} -> {b.shape}")
    elif not np.array_equal(a.view(np.uint64), b.view(np.uint64)):
        out.append(f"points: {int(np.any(a != b, axis=1).sum())} differ")
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=("save", "compare"))
    parser.add_argument("dir", type=Path, help="folder of the saved outcomes (outside the repository)")
    parser.add_argument("--quick", action="store_true",
                        help="only the inputs under 1e4 vertices and the corpus")
    args = parser.parse_args(argv)
    args.dir.mkdir(parents=True, exist_ok=True)
    failed = 0
    for name, load in inputs(args.quick):
        domain = load()
        if domain is None:
            print(f"{name}: invalid input (skipped)")
            continue
        now = outcome(domain)
        path = args.dir / f"{name}.npz"
        if args.mode == "save":
            np.savez(path, **now)
            print(f"{name}: saved {int(now['steiner_points'])} Steiner points ({now['status']})")
            continue
        if not path.exists():
            print(f"{name}: no saved outcome")
            failed += 1
            continue
        with np.load(path) as f:
            diff = differences(dict(f), now)
        failed += bool(diff)
        verdict = "; ".join(diff) if diff else "identical"
        print(f"{name}: {verdict} ({int(now['steiner_points'])} Steiner points)")
    if args.mode == "compare":
        print(f"{failed} differ" if failed else "all identical")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
