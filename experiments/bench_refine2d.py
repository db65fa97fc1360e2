"""Benchmark of nonobtuse boundary refinement against Triangle -pD, side by side in one process on the same
inputs: Steiner points and wall time per strategy, beside the lower bound and CGAL make_conforming_Gabriel_2.

Inputs: the CG:SHOP 2025 categories ortho, point-set, simple-polygon, the PSLG categories (interior
constraints) simple-polygon-exterior and simple-polygon-exterior-20 (../shared/data/cgshop25) and la.poly (a
soil cross-section with interfaces, ../shared/data/2d), and generated
domains of 1e3 .. 1e6 vertices: convex polygons with interior points, star-shaped (non-convex) polygons
with interior points, and thin layers (a 1000 m x 1 m strip whose top and bottom are polylines, with
interior points).

    PYTHONPATH=src .venv/bin/python -m experiments.bench_refine2d [--quick] [--pslg] [--ratio] [--out OUT]

Writes OUT/bench_refine2d.csv and .png (OUT: default experiments/results) and prints a table. --quick:
generated sizes up to 1e4. --pslg: only the PSLG inputs, with the CG:SHOP best known counts beside; writes
OUT/bench_refine2d_pslg.csv. --ratio: only wall time against Triangle -pD on the convex
polygon, the star-shaped polygon and the thin layer at 1e6 vertices (seed 0), runs interleaved, best of 3 each
(for a shared machine).
"""

from __future__ import annotations

import argparse
import csv
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "tests"), str(ROOT / "experiments")]  # nonobtuse: installed or PYTHONPATH=src

import nonobtuse  # noqa: E402
from cgshop_best_known import best_known  # noqa: E402
from experiments.outputs import add_out_option, out_dir  # noqa: E402
from nonobtuse import Domain  # noqa: E402
from nonobtuse.io import load_domain  # noqa: E402
from nonobtuse.peers import triangle_pd  # noqa: E402
from nonobtuse.validate import ensure_validated  # noqa: E402
from refine_helpers import SHARED, cgshop_domain  # noqa: E402

STRATEGIES = ("greedy", "project-flip", "projection")


def loop(n: int) -> np.ndarray:
    i = np.arange(n, dtype=np.int64)
    return np.c_[i, (i + 1) % n]  # not a list of tuples (180 MB at 1e6, in bench_scaling's peak memory)


def convex(n: int, rng) -> Domain:
    h = max(3, int(np.sqrt(n)))
    a = np.sort(rng.uniform(0, 2 * np.pi, h))
    r, b = np.sqrt(rng.uniform(0, 0.9, n - h)), rng.uniform(0, 2 * np.pi, n - h)
    hull = np.c_[np.cos(a), np.sin(a)] * 1e4
    inner = np.c_[r * np.cos(b), r * np.sin(b)] * 1e4
    pts = np.unique(np.round(np.r_[hull, inner]), axis=0)
    return Domain(points=pts, convex_hull=True)


def star(n: int, rng) -> Domain:
    h = max(8, int(np.sqrt(n)))
    a = (np.arange(h) + rng.uniform(0.1, 0.9, h)) * (2 * np.pi / h)  # separated angles: a simple polygon
    outer = np.round(np.c_[np.cos(a), np.sin(a)] * rng.uniform(5e3, 1e4, h)[:, None])
    m = n - h
    r, b = rng.uniform(0, 4.5e3, m), rng.uniform(0, 2 * np.pi, m)
    inner = np.unique(np.round(np.c_[r * np.cos(b), r * np.sin(b)]), axis=0)
    return Domain(points=np.r_[outer, inner], segments=loop(h))


def thin_layer(n: int, rng) -> Domain:
    """1000 m long, ~1 m thick: bottom y = 0.1 sin(x / 50), top 1 + 0.1 sin(x / 70), k vertices each, interior
    points in between (coordinates in mm, integers)."""
    k = max(4, int(np.sqrt(n)))
    x = np.linspace(0, 1e6, k)
    bottom = np.c_[x, np.round(100 * np.sin(x / 5e4))]
    top = np.c_[x[::-1], np.round(1000 + 100 * np.sin(x[::-1] / 7e4))]
    m = n - 2 * k
    px = np.round(rng.uniform(1e3, 1e6 - 1e3, m))
    lo, hi = 100 * np.sin(px / 5e4) + 150, 1000 + 100 * np.sin(px / 7e4) - 150
    py = np.round(lo + rng.uniform(0, 1, m) * (hi - lo))
    inner = np.unique(np.c_[px, py], axis=0)
    return Domain(points=np.r_[bottom, top, inner], segments=loop(2 * k))


def cgal_gabriel(domain: Domain) -> tuple[int, float]:
    """CGAL make_conforming_Gabriel_2 on the domain's CDT (both sides of every constraint)."""
    from nonobtuse import _core

    t0 = time.perf_counter()
    n = _core.conforming_gabriel_steiner_points(
        domain.points, domain.segments, domain.holes, domain.regions, bool(domain.convex_hull)
    )
    return n, time.perf_counter() - t0


def run(name: str, category: str, domain: Domain, rows: list, best: bool = False) -> None:
    domain = ensure_validated(domain)  # once, outside the timings: refine alone is timed
    row = {"input": name, "category": category, "vertices": len(domain.points)}
    for s in STRATEGIES:
        t0 = time.perf_counter()
        r = nonobtuse.refine(domain, strategy=s)
        row[f"{s}_steiner"], row[f"{s}_seconds"] = r.stats["steiner_points"], time.perf_counter() - t0
        row[f"{s}_status"] = r.status
        row["lower_bound"] = r.stats["lower_bound"]
    row["triangle_pD_steiner"], row["triangle_pD_seconds"] = triangle_pd(domain)
    row["cgal_gabriel_steiner"], row["cgal_gabriel_seconds"] = cgal_gabriel(domain)
    if best:  # the PSLG categories: CG:SHOP's best known all-triangle counts (issue 4)
        row["best_known_steiner"] = best_known(name)
    rows.append(row)
    print(
        f"{name:40s} n={row['vertices']:8d} lb={row['lower_bound']:7d} "
        + " ".join(f"{s}={row[f'{s}_steiner']}({row[f'{s}_seconds']:.2f}s)" for s in STRATEGIES)
        + f" triangle-pD={row['triangle_pD_steiner']}({row['triangle_pD_seconds']:.2f}s)"
        + f" cgal-gabriel={row['cgal_gabriel_steiner']}({row['cgal_gabriel_seconds']:.2f}s)",
        flush=True,
    )


def ratio(repeats: int = 3) -> None:
    """Wall seconds of nonobtuse.refine (greedy) and Triangle -pD on the 1e6 inputs, interleaved, best of
    `repeats` each, and their ratio."""
    for gen in (convex, star, thin_layer):
        domain = ensure_validated(gen(10**6, np.random.default_rng(0)))
        ours, peer = [], []
        for _ in range(repeats):
            t0 = time.perf_counter()
            nonobtuse.refine(domain)
            ours.append(time.perf_counter() - t0)
            peer.append(triangle_pd(domain)[1])
        print(
            f"{gen.__name__:10s} n={len(domain.points)} greedy={min(ours):.2f}s triangle-pD={min(peer):.2f}s "
            f"ratio={min(ours) / min(peer):.2f}",
            flush=True,
        )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="generated inputs up to 1e4 vertices")
    ap.add_argument("--pslg", action="store_true", help="only the PSLG inputs (CG:SHOP *-exterior*, la.poly)")
    ap.add_argument("--ratio", action="store_true", help="wall time against Triangle -pD at 1e6, best of 3")
    add_out_option(ap)
    args = ap.parse_args()
    if args.ratio:
        ratio()
        return
    rows: list[dict] = []
    cg = SHARED / "cgshop25"
    if cg.exists():
        for f in sorted(cg.glob("*.instance.json")):
            cat = f.name.split("_")[0]
            if cat in ("ortho", "point-set", "simple-polygon") and not args.pslg:
                run(f.name.split(".")[0], cat, cgshop_domain(f), rows)
            elif cat in ("simple-polygon-exterior", "simple-polygon-exterior-20"):
                run(f.name.split(".")[0], cat, cgshop_domain(f), rows, best=True)
    la = SHARED / "2d" / "la.poly"
    if la.exists():
        run("la", "la.poly", load_domain(la), rows, best=True)
    sizes = [] if args.pslg else [10**3, 10**4] if args.quick else [10**3, 10**4, 10**5, 10**6]
    for n in sizes:
        for gen in (convex, star, thin_layer):
            try:
                run(f"{gen.__name__}_{n}", gen.__name__, gen(n, np.random.default_rng(n)), rows)
            except nonobtuse.InvalidInputError as e:  # a generated input that is not a valid domain
                print(f"{gen.__name__}_{n}: skipped, {e}")
    out = out_dir(args)
    stem = "bench_refine2d_pslg" if args.pslg else "bench_refine2d"
    with open(out / f"{stem}.csv", "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(dict.fromkeys(k for r in rows for k in r)))
        w.writeheader()
        w.writerows(rows)
    print("\ncategory totals (Steiner points):")
    cats = sorted({r["category"] for r in rows}, key=lambda c: [r["category"] for r in rows].index(c))
    keys = (
        ["lower_bound"]
        + [f"{s}_steiner" for s in STRATEGIES]
        + ["triangle_pD_steiner", "cgal_gabriel_steiner", "best_known_steiner"]
    )
    print(f"{'category':26s} " + " ".join(f"{k:>20s}" for k in keys))
    for c in cats:
        tot = [sum(r.get(k) or 0 for r in rows if r["category"] == c) for k in keys]
        print(f"{c:26s} " + " ".join(f"{t:20d}" for t in tot))
    if not args.pslg:
        plot(rows, out / "bench_refine2d.png")


def plot(rows: list, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    gen = [r for r in rows if r["category"] in ("convex", "star", "thin_layer")]
    fig, ax = plt.subplots(1, 2, figsize=(11, 4))
    for c, mk in (("convex", "o"), ("star", "s"), ("thin_layer", "^")):
        rs = [r for r in gen if r["category"] == c]
        n = [r["vertices"] for r in rs]
        for s, col in (("greedy", "C0"), ("triangle_pD", "C3"), ("project-flip", "C1")):
            ax[0].loglog(n, [max(r[f"{s}_steiner"], 1) for r in rs], mk + "-", color=col, label=f"{s} {c}")
            ax[1].loglog(n, [r[f"{s}_seconds"] for r in rs], mk + "-", color=col, label=f"{s} {c}")
        ax[0].loglog(n, [max(r["lower_bound"], 1) for r in rs], mk + ":", color="k", label=f"lower bound {c}")
    ax[0].set(xlabel="input vertices", ylabel="Steiner points")
    ax[1].set(xlabel="input vertices", ylabel="seconds")
    ax[0].legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
