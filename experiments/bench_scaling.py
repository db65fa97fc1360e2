"""Time and memory against n for the 2D input families, nonobtuse against Triangle -pD, with fitted exponents.

Families (seeded, built in the case process; ``n`` vertices):
- ``star``: a random star-shaped polygon, vertices at random angles (sorted) and radii in [0.5, 1], no
  interior points (the family where the disk walks' visibility cost grew as n^1.4);
- ``polygon``: a convex polygon (vertices at random angles on the unit circle), no interior points;
- ``thin_layer``: the 1000 m x 1 m strip of ``bench_refine2d.thin_layer`` (2 sqrt(n) boundary vertices);
- ``convex``: ``bench_refine2d.convex``: a convex hull of sqrt(n) points around random interior points;
- ``point_set``: n uniform random points, the convex hull as boundary.

Each (family, n, tool) runs in a case process of its own (``experiments/sweep.py``): ``ours`` is
``validate_domain`` + ``nonobtuse.refine`` (greedy, the whole in-memory process; the file pipeline is
``bench_pipeline``), ``triangle`` is ``triangle.triangulate(..., "pDQ")`` (``pcDQ`` for the point set).
Recorded: wall seconds of that call, Steiner points and the case process's peak resident memory (ru_maxrss,
interpreter and input included, the same for both tools). Exponents are least-squares slopes of log(seconds)
and log(peak MB) against log(n) over the sizes n >= 1e4 that finished (all finished sizes when none is that
large).

    PYTHONPATH=src:. .venv/bin/python -m experiments.bench_scaling [--quick] [--sizes 1e4,1e5]
        [--families star,polygon] [--tools ours,triangle] [--out DIR] [--time-limit S] [--workers 1]

Writes OUT/bench_scaling.csv (one row per case), OUT/bench_scaling_exponents.csv and OUT/bench_scaling.png
(``--quick``: n = 2e3, 5e3, 1e4 and ``_quick`` files). Run it with ``--workers 1`` when timing (the default of
the sweep runner is one case process per CPU).
"""

from __future__ import annotations

import argparse
import resource
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

from experiments.bench_refine2d import convex, loop, thin_layer
from experiments.steiner_study_2d import fit_exponent
from experiments.sweep import add_sweep_arguments, output_stem, sweep_from_args, write_csv

FAMILIES = ("star", "polygon", "thin_layer", "convex", "point_set")
TOOLS = ("ours", "triangle")
SIZES = {"full": [10_000, 30_000, 100_000, 300_000, 1_000_000], "quick": [2_000, 5_000, 10_000]}
CASE_SECONDS = {"full": 900.0, "quick": 120.0}
FIT_FROM = 10_000
COLUMNS = ["family", "n", "tool", "status", "seconds", "steiner_points", "peak_mb"]
EXPONENT_COLUMNS = ["family", "tool", "time_exponent", "memory_exponent", "sizes_fitted", "largest_n"]


def domain_of(family: str, n: int, seed: int):
    """The input of ``family`` with ``n`` vertices (module docstring)."""
    from nonobtuse import Domain

    rng = np.random.default_rng(seed)
    if family in ("star", "polygon"):
        a = np.sort(rng.uniform(0, 2 * np.pi, n))
        r = rng.uniform(0.5, 1.0, n) if family == "star" else np.ones(n)
        return Domain(points=np.c_[r * np.cos(a), r * np.sin(a)], segments=loop(n))
    if family == "thin_layer":
        return thin_layer(n, rng)
    if family == "convex":
        return convex(n, rng)
    if family == "point_set":
        return Domain(points=rng.uniform(0, 1, (n, 2)), convex_hull=True)
    raise ValueError(f"unknown family {family!r}")


def run_case(case: dict[str, Any]) -> dict[str, Any]:
    """One (family, n, tool, seed) case: seconds, Steiner points and peak memory (module docstring)."""
    domain = domain_of(case["family"], case["n"], case["seed"])
    if case["tool"] == "ours":
        from nonobtuse import refine
        from nonobtuse.validate import validate_domain

        t0 = time.perf_counter()
        steiner = refine(validate_domain(domain)).stats["steiner_points"]
        seconds = time.perf_counter() - t0
    else:
        from nonobtuse.peers import triangle_pd

        steiner, seconds = triangle_pd(domain)
    peak_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return {"seconds": seconds, "steiner_points": int(steiner), "peak_mb": peak_mb}


def rows_of(records: list[dict]) -> list[dict]:
    rows = []
    for r in records:
        row = {**{k: r["case"][k] for k in ("family", "n", "tool")}, "status": r["status"]}
        rows.append({**row, **(r["result"] or {})})
    return sorted(rows, key=lambda row: (row["family"], row["tool"], row["n"]))


def exponents(rows: list[dict]) -> list[dict]:
    fits = []
    for family in dict.fromkeys(row["family"] for row in rows):
        for tool in TOOLS:
            ok = [r for r in rows if (r["family"], r["tool"], r["status"]) == (family, tool, "ok")]
            ok = [r for r in ok if r["n"] >= FIT_FROM] or ok
            if not ok:
                continue
            ns = [r["n"] for r in ok]
            fits.append({
                "family": family, "tool": tool,
                "time_exponent": round(fit_exponent(ns, [r["seconds"] for r in ok]), 3),
                "memory_exponent": round(fit_exponent(ns, [r["peak_mb"] for r in ok]), 3),
                "sizes_fitted": len(ok), "largest_n": max(ns),
            })  # fmt: skip
    return fits


def plot(rows: list[dict], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    for i, family in enumerate(dict.fromkeys(row["family"] for row in rows)):
        for tool, style in zip(TOOLS, ("-o", "--s")):
            ok = [r for r in rows if (r["family"], r["tool"], r["status"]) == (family, tool, "ok")]
            if ok:
                for ax, key in zip(axes, ("seconds", "peak_mb")):
                    ax.loglog([r["n"] for r in ok], [r[key] for r in ok], style, color=f"C{i}",
                              label=f"{family} ({tool})")
    axes[0].set(xlabel="vertices n", ylabel="wall seconds", title="validate + refine (ours), Triangle -pD")
    axes[1].set(xlabel="vertices n", ylabel="peak resident MB", title="peak memory of the case process")
    axes[0].legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_sweep_arguments(parser)
    parser.add_argument("--sizes", type=lambda s: [int(float(v)) for v in s.split(",")],
                        help="comma-separated vertex counts instead of the default")
    parser.add_argument("--families", type=lambda s: s.split(","), default=list(FAMILIES),
                        help=f"comma-separated subset of {','.join(FAMILIES)}")
    parser.add_argument("--tools", type=lambda s: s.split(","), default=list(TOOLS), help="ours,triangle")
    args = parser.parse_args(argv)
    mode = "quick" if args.quick else "full"
    cases = [{"family": f, "n": n, "tool": t, "seed": args.seed}
             for f in args.families for n in (args.sizes or SIZES[mode]) for t in args.tools]
    records = sweep_from_args(args, "experiments.bench_scaling:run_case", cases, "bench_scaling",
                              time_limit=CASE_SECONDS[mode])
    rows, out = rows_of(records), Path(args.out)
    fits = exponents(rows)
    write_csv(out / f"{output_stem('bench_scaling', args.quick)}.csv", rows, COLUMNS)
    write_csv(out / f"{output_stem('bench_scaling_exponents', args.quick)}.csv", fits, EXPONENT_COLUMNS)
    plot(rows, out / f"{output_stem('bench_scaling', args.quick)}.png")
    for f in fits:
        print(f"{f['family']:>10} {f['tool']:>8}: time ~ n^{f['time_exponent']}, memory ~ n^"
              f"{f['memory_exponent']} ({f['sizes_fitted']} sizes up to {f['largest_n']})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
