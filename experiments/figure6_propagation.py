"""The paper's Figure 6 phenomenon (section 5.1): one obtuse triangle whose repair must travel through n
interfaces, for every refinement method, not only for midpoint splitting.

The paper's figure is not in our text copy; it is described as a "quality" PSLG (angles between 30 and 120
degrees) with one obtuse triangle (120 degrees at p, opposite the edge o_1) whose repair "necessarily induces"
one Steiner point on each of n highlighted edges. :func:`figure6` builds a family for which we can prove
that claim for every valid refinement; its triangles are thin layers (needles), not the paper's quality
triangles -- see "Why not quality" below.

The family, for n >= 1 (H = 0.3, y_k = k H / n):
- the highlighted edges e_k = (-1, y_k) -- (1, y_k), k = 1..n: interior interfaces of length 2 (n thin
  layers), e_1 = o_1;
- p = (0, y_1 - 1/sqrt(3)), an isolated input point below e_1: the triangle (-1, y_1), (1, y_1), p has
  120 degrees at p, the only obtuse angle of the input;
- the outer boundary, a regular 24-gon of radius 3 about the origin (its edges' diametral disks reach
  no closer than 3 (cos 7.5 - sin 7.5) > 2.5 to the origin, and every inner point is within 1.05 of it).
Every other side is initially fine: the endpoint (+-1, y_j) is at squared distance 1 + (y_j - y_k)^2 > 1 from
the centre (0, y_k) of e_k's diametral disk (radius 1); p sees only e_1 (the segment from p to any point of
e_k, k >= 2, crosses e_1 at |x| < 1); the outer vertices are at distance >= 2.7 from every centre.

Lower bound (valid = Steiner points only on constraint segments, and every constraint subsegment has, on each
side, no visible vertex strictly inside its open diametral disk). Lemma: if a vertex v of a valid refinement
sees the constraint segment e = [a, b] and lies strictly inside its diametral disk, with foot f on e at
distance h, and a and b are farther than h from f along e, then the refinement has a Steiner point on e within
h of f. Proof: the subsegment [s, t] containing f has v strictly outside or on its disk, i.e.
(f - s)(t - f) <= h^2 (v is at height h over f), so min(f - s, t - f) <= h; that endpoint is a vertex on e
other than a, b. Induction: p forces a Steiner point on e_1 in I_1 = [-h_1, h_1], h_1 = y_1 - p_y = 1/sqrt(3);
a point (x, y_k) with x in I_k = [-(h_1 + (y_k - y_1)), +(h_1 + (y_k - y_1))] sees e_{k+1} (nothing lies
between the layers) at height y_{k+1} - y_k, strictly inside its disk because
(h_1 + H)^2 + (H/n)^2 < 0.88^2 + 0.09 < 1, and |x| + h < 0.9 keeps a, b farther than h; so every refinement
has a Steiner point in I_{k+1} on e_{k+1}. Hence every valid refinement has >= n Steiner points (the line
"n" on the plot). :func:`forced_intervals` computes the I_k exactly (rationals of the stored coordinates)
and the test checks the invariant for small n.

Why not the paper's 30-120 degree quality: this argument cannot give it while segment lengths stay within a
bounded ratio of the obtuse triangle's size. If no input angle is below 30 degrees except between two
constraints, the CDT triangle on the side of e_{k+1} facing e_k has base angles >= 30 degrees and no point of
e_k inside, and a point beyond a constrained triangle edge does not see e_{k+1}; so every forcing point q of
I_k is seen from a corner c of e_{k+1} at an angle in [30, 90) degrees, in a sector of opening <= 60 degrees.
Let rho_k be the largest |q - c| over I_k. Any forced interval [f - a, f + b] of a point at height h needs
a b >= h^2 (else a subsegment avoids it), so it is at least 2 h >= rho_k long for the farthest q
(h = rho sin(angle) >= rho / 2): |I_{k+1}| >= rho_k. And I_{k+1} lies in such a sector of e_{k+2}'s disk,
whose part within distance R of its apex has diameter < R (the disk cuts the sector), so
rho_{k+1} > |I_{k+1}| >= rho_k: the forced sets never shrink, and the gap (a fixed factor for rho / |e|
bounded below, as it is once rho cannot shrink and |e| is bounded) makes them grow geometrically until
they leave the disks. Propagation over n segments under the quality bound therefore needs segments whose
length relative to the obtuse triangle grows with n, or angles below 30 degrees (this bounds our argument,
not every argument). A short numerical search over period-2 zigzag / herringbone chains (congruent
segments rotated +-theta and translated; random restarts and differential evolution over 9 parameters, about
30 minutes) found no chain propagating further than near-parallel thin layers like these. (The strip of
isosceles triangles the paper's picture suggests, this script's previous family, propagates under midpoint
splitting only: there our greedy stopped after 8 points at every n while Triangle -pD and CGAL needed n + 3.)

We refine each instance with nonobtuse.refine (greedy and project-flip), Triangle -pD and CGAL
make_conforming_Gabriel_2, for n from 10 to 10,000:

    PYTHONPATH=src .venv/bin/python experiments/figure6_propagation.py [--quick]

Writes experiments/results/figure6_propagation.csv and .png (--quick: n up to 1,000, *_quick.* files) and
prints the table and the least-squares slope of each count against n.
"""

from __future__ import annotations

import argparse
import csv
import math
import sys
from fractions import Fraction
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "experiments")]  # nonobtuse: installed or PYTHONPATH=src

import nonobtuse  # noqa: E402
from bench_refine2d import cgal_gabriel  # noqa: E402
from nonobtuse import Domain  # noqa: E402
from nonobtuse.check import check_mesh  # noqa: E402
from nonobtuse.peers import triangle_pd  # noqa: E402

STACK_HEIGHT = 0.3  # H: total height of the n layers (segment length 2)
OUTER_VERTICES, OUTER_RADIUS = 24, 3.0


def figure6(n: int) -> Domain:
    """The family described in the module docstring: points (24 + 2 n + 1, 2) float64 -- the outer 24-gon
    (counter-clockwise), then e_k's endpoints (-1, y_k), (1, y_k) for k = 1..n, then p last; segments: the
    outer loop, then e_1..e_n (segment 24 + k - 1 is e_k). One region, no holes."""
    if n < 1:
        raise ValueError(f"n must be >= 1, got {n}")
    angles = 2 * np.pi * np.arange(OUTER_VERTICES) / OUTER_VERTICES
    outer = OUTER_RADIUS * np.column_stack([np.cos(angles), np.sin(angles)])
    y = np.arange(1, n + 1) * (STACK_HEIGHT / n)
    ends = np.column_stack([np.tile([-1.0, 1.0], n), np.repeat(y, 2)])
    p = np.array([[0.0, y[0] - 1 / math.sqrt(3)]])
    loop = np.column_stack([np.arange(OUTER_VERTICES), (np.arange(OUTER_VERTICES) + 1) % OUTER_VERTICES])
    layers = OUTER_VERTICES + np.arange(2 * n).reshape(n, 2)
    return Domain(
        points=np.vstack([outer, ends, p]),
        segments=np.vstack([loop, layers]).astype(np.int64),
        source=f"figure6(n={n})",
    )


def forced_intervals(domain: Domain) -> list[tuple[Fraction, Fraction]]:
    """The intervals I_k = [lo, hi] (x coordinates, exact rationals of the stored floats) of e_k, k = 1..n,
    in which every valid refinement of ``figure6(n)`` has a Steiner point (module docstring, Lemma).
    Raises ValueError where the induction's hypotheses fail: I_k not strictly inside e_{k+1}'s diametral
    disk, or an end of e_k within h of the foot. Cost: O(n) rational operations."""
    pts = domain.points
    heights = [Fraction(float(y)) for y in pts[OUTER_VERTICES:-1:2, 1]]
    p = [Fraction(float(c)) for c in pts[-1]]
    intervals, (f_lo, f_hi), below = [], (p[0], p[0]), p[1]
    for k, y in enumerate(heights):  # the forcing points lie in [f_lo, f_hi] at height `below`
        h = y - below
        # strictly inside the disk of e_k (centre (0, y), radius 1): both ends of the convex range of feet
        if any(x * x + h * h >= 1 for x in (f_lo, f_hi)):
            raise ValueError(f"I_{k} is not strictly inside the diametral disk of e_{k + 1}")
        if f_lo - h <= -1 or f_hi + h >= 1:
            raise ValueError(f"an end of e_{k + 1} lies within h of a foot")
        intervals.append((f_lo - h, f_hi + h))
        (f_lo, f_hi), below = intervals[-1], y
    return intervals


def measure(n: int) -> dict:
    d = figure6(n)
    row: dict = {"n": n, "lower_bound": len(forced_intervals(d))}
    for strategy in ("greedy", "project-flip"):
        r = nonobtuse.refine(d, strategy=strategy)
        if r.converged and not check_mesh(r.mesh).ok:
            raise nonobtuse.InternalError(f"figure6 n={n} {strategy}: converged but the exact check fails")
        row[f"{strategy}_steiner"], row[f"{strategy}_status"] = r.stats["steiner_points"], r.status
        row[f"{strategy}_seconds"] = round(r.stats["seconds"], 3)
        if strategy == "greedy":  # propagation is tracked by the greedy strategy only
            row["propagation_depth"] = r.stats["diagnosis"]["propagation_depth"]
    for key, peer in (("triangle_pD", triangle_pd), ("cgal_gabriel", cgal_gabriel)):
        row[f"{key}_steiner"], seconds = peer(d)
        row[f"{key}_seconds"] = round(seconds, 3)
    return row


KEYS = ("greedy_steiner", "project-flip_steiner", "triangle_pD_steiner", "cgal_gabriel_steiner")


def slope(rows: list, key: str) -> float:
    """Least-squares slope of Steiner points against n (points per highlighted edge)."""
    n = np.array([r["n"] for r in rows], dtype=float)
    return float(np.polyfit(n, np.array([r[key] for r in rows], dtype=float), 1)[0])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="n up to 1,000; writes *_quick.* files")
    args = ap.parse_args()
    ns = [10, 30, 100, 300, 1000] + ([] if args.quick else [3000, 10000])
    rows = []
    for n in ns:
        rows.append(measure(n))
        print(" ".join(f"{k}={v}" for k, v in rows[-1].items()), flush=True)
    out = ROOT / "experiments" / "results"
    out.mkdir(parents=True, exist_ok=True)
    stem = "figure6_propagation" + ("_quick" if args.quick else "")
    with open(out / f"{stem}.csv", "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    for k in KEYS:
        print(f"slope {k}: {slope(rows, k):.3f} Steiner points per highlighted edge")
    plot(rows, out / f"{stem}.png")


def plot(rows: list, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    n = np.array([r["n"] for r in rows])
    fig, ax = plt.subplots(figsize=(6, 4))
    for k, mk in zip(KEYS, "os^v"):
        label = k.removesuffix("_steiner")
        ax.loglog(n, [max(r[k], 1) for r in rows], mk + "-", label=f"{label} (slope {slope(rows, k):.2f})")
    ax.loglog(n, [r["lower_bound"] for r in rows], "k:", label="n: proven lower bound, every method")
    ax.set(
        xlabel="highlighted edges n (layers)",
        ylabel="Steiner points",
        title="Figure 6 family: one 120° triangle, n thin layers",
    )
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
