"""The paper's Figure 6 phenomenon (section 5.1): one obtuse triangle whose repair must travel through n
constraint edges, for every refinement method, not only for midpoint splitting.

The paper's figure is not in our text copy; it is described as a "quality" PSLG (every angle not between two
constraint edges within 30..120 degrees) with one obtuse triangle (120 degrees at p, opposite the edge o_1)
whose repair "necessarily induces" one Steiner point on each of n highlighted edges. We build two families
for which we prove that claim for every valid refinement (valid: Steiner points only on constraint segments,
and every constraint subsegment has, on each side, no visible vertex strictly inside its open diametral disk).

Lemma (forced interval). Let a vertex v of a valid refinement see the constraint segment e = [a, b] and lie
strictly inside its diametral disk, at height h over its foot f on e. For any lengths alpha, beta > 0 with
alpha beta >= h^2 and [f - alpha, f + beta] inside the open segment (a, b), the refinement has a Steiner
point on e in [f - alpha, f + beta]. Proof: the subsegment [s, t] containing f must not have v strictly
inside its disk: (f - s)(t - f) <= h^2 <= alpha beta, so f - s <= alpha or t - f <= beta, and s or t is a
vertex on e other than a, b. (No shorter choice works: s = f - alpha', t = f + h^2 / alpha' is a valid
subsegment for every alpha'.) Chaining: if every refinement has a Steiner point somewhere in a set I_k on
e_k and every point of I_k is strictly inside e_{k+1}'s disk and sees it, the union over q in I_k of the
intervals above is a set I_{k+1} on e_{k+1} with the same property.

1. :func:`figure6` -- n thin layers (n >= 1, H = 0.3, y_k = k H / n):
- the highlighted edges e_k = (-1, y_k) -- (1, y_k), k = 1..n: interior interfaces of length 2, e_1 = o_1;
- p = (0, y_1 - 1/sqrt(3)), an isolated input point below e_1: the triangle (-1, y_1), (1, y_1), p has
  120 degrees at p, the only obtuse angle of the input;
- the outer boundary, a regular 24-gon of radius 3 about the origin (its edges' diametral disks reach
  no closer than 3 (cos 7.5 - sin 7.5) > 2.5 to the origin, and every inner point is within 1.05 of it).
Every other side is initially fine: the endpoint (+-1, y_j) is at squared distance 1 + (y_j - y_k)^2 > 1 from
the centre (0, y_k) of e_k's diametral disk (radius 1); p sees only e_1 (the segment from p to any point of
e_k, k >= 2, crosses e_1 at |x| < 1); the outer vertices are at distance >= 2.7 from every centre.
Bound (alpha = beta = h): p forces I_1 = [-h_1, h_1], h_1 = y_1 - p_y = 1/sqrt(3); the points of
I_k = [-(h_1 + y_k - y_1), h_1 + y_k - y_1] see e_{k+1} (nothing lies between the layers) at height
y_{k+1} - y_k, strictly inside its disk since (h_1 + H)^2 + (H/n)^2 < 0.88^2 + 0.09 < 1, and I_{k+1} stays
within |x| < 0.9. :func:`forced_intervals` computes the I_k exactly (rationals of the stored coordinates).
The triangles between layers are needles (aspect n / 0.15).

2. :func:`figure6_fan` -- a fan of n arms (n >= 7): arms (c, end_k) from the junction c = (0, 0) to
end_k = (cos k phi, sin k phi), k = 1..n, phi = 1 / n radian (SPREAD = 1 radian in all), and p = (r, 0) with
r = cos phi - sin phi / sqrt(3), so that the triangle (c, p, end_1) has 120 degrees at p. The boundary loop is
c, p, end_1, .., end_n, c (so c-p, p-end_1, the arcs end_k-end_{k+1} and arm n are boundary edges, arms
1..n-1 interfaces); the CDT triangles are (c, p, end_1) and (c, end_k, end_{k+1}), all of whose edges are
constraints, so every angle lies between two constraint edges and the 30..120 degree condition holds (as
the paper's wording allows: only angles not between two constraint edges are bounded). Initially only
arm 1's side facing p is obtuse (end_j is on or outside arm k's disk: end_j . (end_j - end_k) =
1 - cos((j - k) phi) >= 0; p sees no arm but arm 1). Bound (alpha = (1 - eta) f, eta = 2^-20): a point
t end_k, 0 < t <= T_k, sees arm k+1 at the angle phi from c, at f = t cos phi, h = t sin phi, and forces
[eta f, t G] with G = cos phi + sin^2 phi / ((1 - eta) cos phi), so I_{k+1} = (0, T_k G] on arm k+1:
T_k ~ r / cos^k phi < (1 - phi / sqrt(3)) (1 + phi / 2) < cos phi for every k <= n when phi < 0.15.
:func:`fan_forced_intervals` computes the T_k exactly (rounded up). In practice the junction of angle
1/n radian dominates: every method needs about n^2 points (concentric shells on n arms).

Why not the paper's quality with propagation through segment ends (the first family's mechanism): the drift
argument cannot give it while segment lengths stay within a bounded ratio of the obtuse triangle's size. If
no angle below 30 degrees has a non-constraint edge, the CDT triangle on the side of e_{k+1} facing e_k has
base angles >= 30 degrees (unless e_k itself is its edge: a junction, as in the fan), and a point beyond a
constrained triangle edge does not see e_{k+1}; so every forcing point q of I_k is seen from a corner c of
e_{k+1} at an angle in [30, 90) degrees, in a sector of opening <= 60 degrees. Let rho_k be the largest
|q - c| over I_k. The interval forced by the farthest q is at least 2 h >= rho_k long (alpha + beta >=
2 sqrt(alpha beta), h = rho sin(angle) >= rho / 2), so |I_{k+1}| >= rho_k; and I_{k+1} lies in such a sector
of e_{k+2}'s disk, whose part within distance R of its apex has diameter < R (the disk cuts the sector), so
rho_{k+1} > |I_{k+1}| >= rho_k: the forced sets never shrink, and the gap (a fixed factor once rho / |e| is
bounded below) makes them grow geometrically until they leave the disks. Such propagation over n segments
needs segments whose length relative to the obtuse triangle grows with n, or angles below 30 degrees (this
bounds our argument, not every argument). A short numerical search over period-2 zigzag / herringbone chains
(congruent segments rotated +-theta and translated; random restarts and differential evolution over 9
parameters, about 30 minutes) found no chain propagating further than near-parallel thin layers. (The strip
of isosceles triangles the paper's picture suggests, this script's previous family, propagates under
midpoint splitting only: there our greedy stopped after 8 points at every n while Triangle -pD and CGAL
needed n + 3.)

We refine each instance with nonobtuse.refine (greedy and project-flip; budget n^2 + 1000 on the fan, up to
n = 300), Triangle -pD and CGAL make_conforming_Gabriel_2: layers for n = 10..10,000, the fan for
n = 10..1,000.

    PYTHONPATH=src .venv/bin/python -m experiments.figure6_propagation [--quick] [--out OUT]

Writes OUT/figure6_propagation.csv (one row per family and n; OUT: default experiments/results) and .png
(--quick: n up to 1,000 and 100, *_quick.* files) and prints the table and the fitted exponent of each
count against n.
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
from experiments.outputs import add_out_option, out_dir  # noqa: E402
from nonobtuse import Domain  # noqa: E402
from nonobtuse.certificate import check_mesh  # noqa: E402
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


def figure6_fan(n: int) -> Domain:
    """The fan of the module docstring: points (n + 2, 2) float64 -- c = (0, 0), p = (r, 0), then
    end_k = (cos k phi, sin k phi) for k = 1..n (phi = SPREAD / n); segments: the boundary loop c, p,
    end_1, .., end_n, c (counter-clockwise; its last edge is arm n), then the interfaces (c, end_k),
    k = 1..n-1. Raises ValueError for n < 7 (the chain needs phi < 0.15, see the docstring)."""
    if n < 7:
        raise ValueError(f"n must be >= 7, got {n}")
    phi = SPREAD / n
    k = np.arange(1, n + 1)
    r = math.cos(phi) - math.sin(phi) / math.sqrt(3)  # 120 degrees at p in the triangle (c, p, end_1)
    pts = np.vstack([[[0.0, 0.0], [r, 0.0]], np.column_stack([np.cos(k * phi), np.sin(k * phi)])])
    loop = [(i, (i + 1) % (n + 2)) for i in range(n + 2)]
    arms = [(0, i + 1) for i in range(1, n)]
    return Domain(points=pts, segments=np.array(loop + arms, dtype=np.int64), source=f"figure6_fan(n={n})")


def fan_forced_intervals(domain: Domain, eta: Fraction = Fraction(1, 2**20)) -> list[Fraction]:
    """T_k, k = 1..n, exact rationals (rounded up to doubles): every valid refinement of ``figure6_fan(n)``
    has a Steiner point c + t (end_k - c) on arm k with 0 < t <= T_k (module docstring; ``eta`` is the
    choice a = (1 - eta) f there). Raises ValueError where the induction's hypotheses fail. Cost: O(n)."""
    ends = [tuple(Fraction(float(x)) for x in q) for q in domain.points[1:]]  # end_0 = p, end_1..end_n
    t_max, bounds = Fraction(1), []
    for k, (e, u) in enumerate(zip(ends[:-1], ends[1:])):  # forcing points t e, t in (0, t_max], on arm k
        dot, cross = e[0] * u[0] + e[1] * u[1], e[0] * u[1] - e[1] * u[0]
        uu = u[0] ** 2 + u[1] ** 2
        # t e strictly inside the diametral disk of arm k+1, (t e).(t e - u) < 0, for every t in (0, t_max]
        if not 0 < t_max * (e[0] ** 2 + e[1] ** 2) < dot:
            raise ValueError(f"the forcing points of arm {k} are not strictly inside the disk of arm {k + 1}")
        # the forced interval [eta f, t G] of t e on arm k+1 (in fractions of arm k+1); union: (0, t_max G]
        g = dot / uu + cross**2 / ((1 - eta) * dot * uu)
        t_max = Fraction(math.nextafter(float(t_max * g), math.inf))
        if t_max >= 1:
            raise ValueError(f"the forced interval of arm {k + 1} reaches its end")
        bounds.append(t_max)
    return bounds


SPREAD = 1.0  # radians spanned by the fan's arms
LAYERS_NS = [10, 30, 100, 300, 1000, 3000, 10000]
FAN_NS, FAN_OURS_MAX_N = [10, 30, 100, 300, 1000], 300  # fan: quadratic counts; ours stop at n = 300
FAMILIES = {  # name: (builder, lower bound, Steiner budget of nonobtuse.refine (None: its default))
    "layers": (figure6, lambda d: len(forced_intervals(d)), lambda n: None),
    "fan": (figure6_fan, lambda d: len(fan_forced_intervals(d)), lambda n: n * n + 1000),
}
KEYS = ("greedy_steiner", "project-flip_steiner", "triangle_pD_steiner", "cgal_gabriel_steiner")


def measure(family: str, n: int, ours: bool = True) -> dict:
    """One row: the proven lower bound and each method's Steiner points, status and seconds (blank for
    our strategies when ``ours`` is False)."""
    build, lower_bound, budget = FAMILIES[family]
    d = build(n)
    row: dict = {"family": family, "n": n, "lower_bound": lower_bound(d)}
    for strategy in ("greedy", "project-flip") if ours else ():
        r = nonobtuse.refine(d, strategy=strategy, max_steiner=budget(n))
        if r.converged and not check_mesh(r.mesh).ok:
            raise nonobtuse.InternalError(f"{d.source} {strategy}: converged but the exact check fails")
        row[f"{strategy}_steiner"], row[f"{strategy}_status"] = r.stats["steiner_points"], r.status
        row[f"{strategy}_seconds"] = round(r.stats["seconds"], 3)
        if strategy == "greedy":  # propagation is tracked by the greedy strategy only
            row["propagation_depth"] = r.stats["diagnosis"]["propagation_depth"]
    for key, peer in (("triangle_pD", triangle_pd), ("cgal_gabriel", cgal_gabriel)):
        row[f"{key}_steiner"], seconds = peer(d)
        row[f"{key}_seconds"] = round(seconds, 3)
    return row


def converged(rows: list, key: str) -> list:
    """The rows where the method of ``key`` ran and (for our strategies) converged."""
    status = key.replace("_steiner", "_status")
    return [r for r in rows if r.get(key) is not None and r.get(status, "converged") == "converged"]


def exponent(rows: list, key: str) -> float:
    """Least-squares slope of log(Steiner points) against log(n) over the converged rows (nan if < 2)."""
    ok = converged(rows, key)
    if len(ok) < 2:
        return math.nan
    x, y = (np.log([float(r[c]) for r in ok]) for c in ("n", key))
    return float(np.polyfit(x, y, 1)[0])


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="n up to 1,000 (fan: 100); writes *_quick.* files")
    add_out_option(ap)
    args = ap.parse_args()
    plan = [("layers", n, True) for n in LAYERS_NS if not args.quick or n <= 1000]
    plan += [("fan", n, n <= FAN_OURS_MAX_N) for n in FAN_NS if not args.quick or n <= 100]
    rows = []
    for family, n, ours in plan:
        rows.append(measure(family, n, ours))
        print(" ".join(f"{k}={v}" for k, v in rows[-1].items()), flush=True)
    out = out_dir(args)
    stem = "figure6_propagation" + ("_quick" if args.quick else "")
    with open(out / f"{stem}.csv", "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(dict.fromkeys(k for r in rows for k in r)))
        w.writeheader()
        w.writerows(rows)
    for family in FAMILIES:
        for k in KEYS:
            e = exponent([r for r in rows if r["family"] == family], k)
            print(f"{family}: {k} " + (f"grows as n^{e:.2f}" if math.isfinite(e) else "converged < 2 times"))
    plot(rows, out / f"{stem}.png")


def plot(rows: list, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    titles = {
        "layers": "n thin layers over one 120° triangle",
        "fan": "fan of n arms, 1/n rad apart (ours to n = 300)",
    }
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, family in zip(axes, FAMILIES):
        mine = [r for r in rows if r["family"] == family]
        for k, mk in zip(KEYS, "os^v"):
            ok = converged(mine, k)
            e, name = exponent(mine, k), k.removesuffix("_steiner")
            stopped = [r["n"] for r in mine if r not in ok and r.get(k) is not None]
            label = f"{name} (n^{e:.2f})" if not stopped else f"{name} (budget spent from n = {stopped[0]})"
            ax.loglog([r["n"] for r in ok], [max(r[k], 1) for r in ok], mk + "-", label=label)
        ax.loglog(
            [r["n"] for r in mine], [r["lower_bound"] for r in mine], "k:", label="proven lower bound n"
        )
        ax.set(xlabel="highlighted edges n", ylabel="Steiner points", title=titles[family])
        ax.legend(fontsize=7)
    fig.suptitle(
        "Figure 6 families: one obtuse triangle, every valid refinement needs >= n points", fontsize=9
    )
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
