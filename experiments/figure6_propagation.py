"""The paper's Figure 6 family (section 5.1): one obtuse triangle whose repair travels along a chain of
interfaces.

The paper shows a "quality" PSLG (every angle between 30 and 120 degrees) whose triangles are all
constrained, with a single obtuse triangle (120 degrees at p, opposite edge o_1), and states that repairing
o_1 induces Omega(n) Steiner points, one per highlighted edge. The picture itself is not in our text copy, so
this script builds the closest family we can state exactly: a zigzag strip of n + 1 isosceles triangles with
apex angle `apex` (default 30 degrees, base angles 75), every edge a constraint (the n highlighted edges
e_1..e_n are the interfaces between consecutive triangles, the rails the outer boundary), plus the triangle
(p, v_0, v_1) on e_0 = o_1 with a 120 degree angle at p, the only obtuse one. A Steiner point on e_k within
cos(apex) |e_k| of the vertex it shares with e_{k+1} lies inside the diametral disk of e_{k+1} (Figure 6's
mechanism), so a method that repairs each edge with one point near the foot of its encroacher (midpoint
splitting: Triangle -pD, CGAL) walks the whole strip. The sensitive greedy need not: on e_{k+1} it puts its
first point at the start of e_{k+2}'s forbidden interval and its next ones out of it where it can, and the
cascade stops after a few edges (measured: the same handful of points for every n, 8 with propagation depth
6 in results/figure6_propagation.csv, against n + 3 for Triangle -pD and CGAL). So this family shows the
Omega(n) of midpoint refinement, not a lower bound for every method; we did not find a quality family that
forces one point per edge on every refinement (a random search over zigzag strips with nonobtuse triangles
found none where greedy's count grows with n).

We measure, for n from 10 to 10,000, the Steiner points of nonobtuse.refine (greedy), Triangle -pD and CGAL
make_conforming_Gabriel_2, and fit the slope of each against n.

    PYTHONPATH=src .venv/bin/python experiments/figure6_propagation.py [--quick] [--apex DEG]

Writes experiments/results/figure6_propagation.csv and .png and prints the table and the fitted slopes.
--quick: n up to 1,000.
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "experiments")]  # nonobtuse: installed or PYTHONPATH=src

import nonobtuse  # noqa: E402
from bench_refine2d import cgal_gabriel, triangle_pd  # noqa: E402
from nonobtuse import Domain  # noqa: E402
from nonobtuse.check import check_mesh  # noqa: E402


def figure6(n: int, apex: float = 30.0) -> Domain:
    """The strip: v_k = (k sin(apex/2), 0) for even k and (k sin(apex/2), cos(apex/2)) for odd k, k = 0..n+1
    (unit edges e_k = (v_k, v_{k+1}), apex angle at every v_k between e_{k-1} and e_k), rails v_k v_{k+2}, and
    p outside e_0 with a 120 degree angle at p. Points: n + 3, float64; segments: every edge (closed outer
    loop p, v_0, bottom rail, v_{n+1} or v_n, top rail, v_1, p, plus the e_k inside)."""
    half = math.radians(apex) / 2
    v = [(k * math.sin(half), 0.0 if k % 2 == 0 else math.cos(half)) for k in range(n + 2)]
    a, c = np.array(v[0]), np.array(v[1])
    mid, d = (a + c) / 2, c - a
    outward = np.array([-d[1], d[0]]) / np.linalg.norm(d)  # left of v_0 -> v_1: away from v_2
    p = mid + outward * np.linalg.norm(d) / 2 * math.tan(math.radians(30))  # isosceles, 120 degrees at p
    pts = np.array(v + [tuple(p)])
    P = n + 2
    bottom, top = list(range(0, n + 2, 2)), list(range(1, n + 2, 2))
    segs = [(P, 0), (1, P)] + [(k, k + 1) for k in range(n + 1)]
    segs += [(r[i], r[i + 1]) for r in (bottom, top) for i in range(len(r) - 1)]
    return Domain(points=pts, segments=np.array(segs, dtype=np.int64), source=f"figure6(n={n}, apex={apex})")


def measure(n: int, apex: float) -> dict:
    d = figure6(n, apex)
    r = nonobtuse.refine(d)
    if r.converged and not check_mesh(r.mesh).ok:
        raise nonobtuse.InternalError(f"figure6 n={n}: converged but the exact check fails")
    g = r.stats["diagnosis"]
    return {
        "n": n,
        "greedy_steiner": r.stats["steiner_points"],
        "greedy_status": r.status,
        "lower_bound": r.stats["lower_bound"],
        "propagation_depth": g["propagation_depth"],
        "initial_violations": g["initial_violations"],
        "triangle_pD_steiner": triangle_pd(d)[0],
        "cgal_gabriel_steiner": cgal_gabriel(d)[0],
    }


def slope(rows: list, key: str) -> float:
    """Least-squares slope of Steiner points against n (points per highlighted edge)."""
    n = np.array([r["n"] for r in rows], dtype=float)
    return float(np.polyfit(n, np.array([r[key] for r in rows], dtype=float), 1)[0])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="n up to 1,000")
    ap.add_argument("--apex", type=float, default=30.0, help="apex angle of the strip triangles (30..120)")
    args = ap.parse_args()
    ns = [10, 30, 100, 300, 1000] + ([] if args.quick else [3000, 10000])
    keys = ("greedy_steiner", "triangle_pD_steiner", "cgal_gabriel_steiner")
    rows = []
    for n in ns:
        rows.append(measure(n, args.apex))
        print(" ".join(f"{k}={v}" for k, v in rows[-1].items()), flush=True)
    out = ROOT / "experiments" / "results"
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "figure6_propagation.csv", "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    for k in keys:
        print(f"slope {k}: {slope(rows, k):.3f} Steiner points per highlighted edge")
    plot(rows, keys, args.apex, out / "figure6_propagation.png")


def plot(rows: list, keys: tuple, apex: float, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = np.array([r["n"] for r in rows])
    fig, ax = plt.subplots(figsize=(6, 4))
    for k, mk in zip(keys, "os^"):
        ax.loglog(n, [max(r[k], 1) for r in rows], mk + "-", label=f"{k} (slope {slope(rows, k):.2f})")
    ax.loglog(n, n, "k:", label="n (one point per highlighted edge)")
    ax.set(xlabel="highlighted edges n", ylabel="Steiner points", title=f"Figure 6 family, apex {apex:g} deg")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
