"""Steiner points of the 2D boundary refinement against its lower bound, its baselines and its peers.

Corpus table: for every input of the 2D corpora (shared data 2d/, the CG:SHOP 2025 instances, generated
families) the Steiner points of ``nonobtuse.refine`` with the strategies greedy, project-flip and projection,
of Triangle's conforming Delaunay triangulation (``triangle.triangulate(..., 'pD')``, 'pcD' for convex-hull
domains), the lower bound (``RefineResult.stats["lower_bound"]``) and the CG:SHOP best-known Steiner count of
an all-triangles nonobtuse triangulation (a different, stronger problem: a reference, not a peer).
Scaling: Steiner points and time of each method on a generated star-shaped polygon of n vertices, n = 1e3..1e6
(--quick: up to 1e4), with growth exponents fitted by least squares on log-log axes.

    python -m experiments.steiner_study_2d --quick      # < 2 min on 2 cores
    python -m experiments.steiner_study_2d              # every instance, n up to 1e6

Writes OUT/steiner_study_2d[_quick].{csv,png}, OUT/steiner_study_2d_summary[_quick].csv,
OUT/steiner_scaling[_quick].{csv,png} and OUT/steiner_scaling_exponents[_quick].csv.
CGAL's make_conforming_Gabriel_2 is not a column: the 2D module does not expose it.

Caveat on Triangle: -D splits every encroached subsegment, interfaces included, while ``nonobtuse.refine``
refines boundary edges only, so on inputs with interior constraints Triangle does more work than ours.
"""

from __future__ import annotations

import argparse
import csv
import math
import os
import re
import sys
import time
from pathlib import Path

if __package__ in (None, ""):  # run as a script: make `experiments` importable
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import numpy as np

from experiments.plotting import legend, pyplot
from experiments.sweep import add_sweep_arguments, error_summary, output_stem, sweep_from_args, write_csv

STRATEGIES = ("greedy", "project-flip", "projection")
METHODS = (*STRATEGIES, "triangle-pD")
GENERATORS = ("star_polygon", "convex_polygon", "point_set")
SIZES = {"quick": [1000, 3000, 10000], "full": [1000, 3000, 10000, 30000, 100000, 300000, 1000000]}
CASE_SECONDS = {"quick": 60.0, "full": 1800.0}
QUICK_CGSHOP_MAX_POINTS = 20


def data_root() -> Path:
    """The shared data: $NONOBTUSE_DATA, else ../shared/data beside the repository."""
    return Path(os.environ.get("NONOBTUSE_DATA", Path(__file__).resolve().parents[2] / "shared" / "data"))


def _col(method: str) -> str:
    return method.replace("-", "_")


CORPUS_COLUMNS = (["corpus", "instance", "n_points", "n_segments", "convex_hull", "lower_bound"]
                  + [_col(m) for m in METHODS] + ["cgshop_best_known"]
                  + [f"{_col(m)}_status" for m in METHODS] + [f"{_col(m)}_seconds" for m in METHODS]
                  + ["error"])
SUMMARY_COLUMNS = ["method", "inputs", "steiner_total", "lower_bound_total", "at_lower_bound",
                   "below_lower_bound"]
SCALING_COLUMNS = ["generator", "n", "method", "steiner_points", "status", "seconds", "lower_bound", "error"]
EXPONENT_COLUMNS = ["method", "steiner_exponent", "time_exponent", "sizes_fitted"]


# ---------------------------------------------------------------------------------------------------- inputs

def generate(generator: str, n: int, seed: int):
    """A generated domain with n input points (a ``nonobtuse.Domain``, validated).

    star_polygon:   vertex j at angle 2 pi j / n, radius 1 + 2 u (2 pi / n), u uniform in [-1, 1]: a circle
                    roughened at the scale of its edges, so that its local shape does not change with n.
    convex_polygon: n // 2 points on the unit circle at sorted uniform angles (the polygon), and the other
                    points uniform in the open unit disk.
    point_set:      n uniform points in the unit square; the domain is their convex hull.
    """
    from nonobtuse import Domain
    from nonobtuse.validate import validate_domain

    rng = np.random.default_rng(seed)
    if generator == "point_set":
        return validate_domain(Domain(points=rng.random((n, 2)), convex_hull=True, source=f"point_set({n})"))
    if generator not in POLYGONS:
        raise ValueError(f"unknown generator {generator!r}; known: {', '.join(GENERATORS)}")
    points, m = POLYGONS[generator](rng, n)
    loop = np.arange(m)
    return validate_domain(Domain(points=points, segments=np.column_stack([loop, np.roll(loop, -1)]),
                                  source=f"{generator}({n})"))


def _polar(radii, angles) -> np.ndarray:
    return np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])


def _star_polygon(rng: np.random.Generator, n: int) -> tuple[np.ndarray, int]:
    angles = 2 * np.pi * np.arange(n) / n
    return _polar(1 + 2 * rng.uniform(-1, 1, n) * (2 * np.pi / n), angles), n


def _convex_polygon(rng: np.random.Generator, n: int) -> tuple[np.ndarray, int]:
    m = n // 2
    boundary = _polar(1.0, np.sort(rng.uniform(0, 2 * np.pi, m)))
    inside = _polar(np.sqrt(rng.random(n - m)), rng.uniform(0, 2 * np.pi, n - m))
    return np.vstack([boundary, inside]), m


# generator -> (rng, n) -> (points, m): the first m points are the polygon, in order; the rest lie inside.
POLYGONS = {"star_polygon": _star_polygon, "convex_polygon": _convex_polygon}


def load_case_domain(case: dict):
    """The case's domain. A file whose segments do not enclose a domain (Triangle's box.poly, meant for
    ``triangle -c``) is read again as the convex hull of its points; ``domain.convex_hull`` then says so."""
    if case["corpus"] == "generated":
        return generate(case["generator"], case["n"], case["seed"])
    from nonobtuse.errors import InvalidInputError
    from nonobtuse.io import load_domain

    path = data_root() / case["path"]
    try:
        return load_domain(path)
    except InvalidInputError as enclosed_error:
        try:
            return load_domain(path, convex_hull=True)
        except InvalidInputError:
            raise enclosed_error from None


def corpus_cases(quick: bool, seed: int, pattern: str | None = None) -> list[dict]:
    """One case per input: every file of 2d/ and cgshop25/ (quick: CG:SHOP instances of <= 20 points only),
    and the generated families at n = 100 (full: also 1000)."""
    root = data_root()
    cases = []
    for path in sorted((root / "2d").glob("*")) if (root / "2d").is_dir() else []:
        if path.suffix in (".poly", ".node"):
            cases.append({"corpus": "2d", "instance": path.stem, "path": f"2d/{path.name}"})
    for path in sorted((root / "cgshop25").glob("*.instance.json")) if (root / "cgshop25").is_dir() else []:
        n = int(re.search(r"_(\d+)_[0-9a-f]+\.instance\.json$", path.name).group(1))
        if not quick or n <= QUICK_CGSHOP_MAX_POINTS:
            cases.append({"corpus": "cgshop25", "instance": path.name.removesuffix(".instance.json"),
                          "path": f"cgshop25/{path.name}"})
    for generator in GENERATORS:
        for n in [100] if quick else [100, 1000]:
            cases.append({"corpus": "generated", "instance": f"{generator}_{n}_seed{seed}",
                          "generator": generator, "n": n, "seed": seed})
    return [c for c in cases if pattern is None or re.search(pattern, c["instance"])]


def scaling_cases(quick: bool, seed: int, sizes: list[int] | None = None) -> list[dict]:
    return [{"corpus": "generated", "generator": "star_polygon", "n": n, "seed": seed, "method": method}
            for n in sizes or SIZES["quick" if quick else "full"] for method in METHODS]


# ---------------------------------------------------------------------------------------------------- methods

def run_method(domain, method: str) -> dict:
    """Steiner points, status, seconds (and the lower bound, for our strategies) of one method on a domain."""
    start = time.perf_counter()
    if method == "triangle-pD":
        from nonobtuse.peers import triangle_pd

        steiner, seconds = triangle_pd(domain)
        return {"steiner_points": steiner, "status": "converged", "seconds": seconds, "lower_bound": None}
    import nonobtuse

    result = nonobtuse.refine(domain, strategy=method)
    return {"steiner_points": int(result.mesh.steiner_points), "status": str(result.status),
            "seconds": time.perf_counter() - start, "lower_bound": int(result.stats["lower_bound"])}


def run_corpus_case(case: dict) -> dict:
    """Every method on one input; a method that raises is recorded as status "error: ..." and the rest run."""
    domain = load_case_domain(case)
    row: dict = {"n_points": len(domain.points), "n_segments": len(domain.segments),
                 "convex_hull": domain.convex_hull}
    for method in METHODS:
        try:
            res = run_method(domain, method)
        except Exception as e:  # one failing method must not hide the others' numbers
            row[f"{_col(method)}_status"] = f"error: {type(e).__name__}: {e}"[:200]
            continue
        row[_col(method)] = res["steiner_points"]
        row[f"{_col(method)}_status"] = res["status"]
        row[f"{_col(method)}_seconds"] = round(res["seconds"], 4)
        if res["lower_bound"] is not None:
            row["lower_bound"] = res["lower_bound"]
    return row


def run_scaling_case(case: dict) -> dict:
    """One method on the generated polygon of size n (generation time excluded)."""
    domain = load_case_domain(case)
    res = run_method(domain, case["method"])
    return {**res, "n_points": len(domain.points)}


# ---------------------------------------------------------------------------------------------------- outputs

def best_known() -> dict[str, int]:
    """CG:SHOP 2025 best-known Steiner counts of all-triangle nonobtuse triangulations, by instance id."""
    path = data_root() / "cgshop25" / "best_known.csv"
    if not path.exists():
        return {}
    with open(path) as f:
        return {r["instance_uid"]: int(r["best_known_steiner"]) for r in csv.DictReader(f)}


def corpus_rows(records: list[dict]) -> list[dict]:
    known = best_known()
    rows = []
    for rec in records:
        case = rec["case"]
        row = {"corpus": case["corpus"], "instance": case["instance"],
               "cgshop_best_known": known.get(case["instance"])}
        if rec["status"] == "ok":
            row.update(rec["result"])
        else:
            row["error"] = f"{rec['status']}: {error_summary(rec)}"
        rows.append(row)
    return sorted(rows, key=lambda r: (r["corpus"], r.get("n_points") or 0, r["instance"]))


def scaling_rows(records: list[dict]) -> list[dict]:
    rows = []
    for rec in records:
        case = rec["case"]
        row = {"generator": case["generator"], "n": case["n"], "method": case["method"]}
        if rec["status"] == "ok":
            row.update({k: rec["result"][k] for k in ("steiner_points", "status", "seconds", "lower_bound")})
        else:
            row.update(status="killed" if rec["status"] == "timeout" else "error", seconds=rec["seconds"],
                       error=error_summary(rec))
        rows.append(row)
    return sorted(rows, key=lambda r: (r["method"], r["n"]))


def summary(rows: list[dict]) -> list[dict]:
    """Per method, over the inputs with a lower bound where the method converged: their number, Steiner total,
    lower-bound total, inputs at the bound, inputs below it (a bound violation: a bug to report)."""
    out = []
    for method in METHODS:
        col = _col(method)
        ok = [r for r in rows if r.get("lower_bound") is not None and r.get(f"{col}_status") == "converged"]
        out.append({"method": method, "inputs": len(ok), "steiner_total": sum(r[col] for r in ok),
                    "lower_bound_total": sum(r["lower_bound"] for r in ok),
                    "at_lower_bound": sum(r[col] == r["lower_bound"] for r in ok),
                    "below_lower_bound": sum(r[col] < r["lower_bound"] for r in ok)})
    return out


def fit_exponent(xs: list[float], ys: list[float]) -> float:
    """Slope of the least-squares line through (log x, log y); NaN with fewer than 2 positive points."""
    pts = [(math.log(x), math.log(y)) for x, y in zip(xs, ys) if x > 0 and y > 0]
    if len(pts) < 2:
        return float("nan")
    lx, ly = np.array(pts).T
    return float(np.polyfit(lx, ly, 1)[0])


def exponents(rows: list[dict]) -> list[dict]:
    """Per method, growth exponents of Steiner points and time over the converged sizes."""
    out = []
    for method in METHODS:
        ok = [r for r in rows if r["method"] == method and r["status"] == "converged"]
        n = [r["n"] for r in ok]
        out.append({"method": method,
                    "steiner_exponent": round(fit_exponent(n, [r["steiner_points"] for r in ok]), 3),
                    "time_exponent": round(fit_exponent(n, [r["seconds"] for r in ok]), 3),
                    "sizes_fitted": len(ok)})
    return out


def plot_scaling(rows: list[dict], fits: list[dict], path: Path) -> None:
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    slope = {f["method"]: f for f in fits}
    for method in METHODS:
        ok = [r for r in rows if r["method"] == method and r["status"] == "converged"]
        if not ok:
            continue
        n = [r["n"] for r in ok]
        axes[0].plot(n, [max(r["steiner_points"], 0.5) for r in ok], "o-",
                     label=f"{method} (n^{slope[method]['steiner_exponent']:.2f})")
        axes[1].plot(n, [r["seconds"] for r in ok], "o-",
                     label=f"{method} (n^{slope[method]['time_exponent']:.2f})")
    lower = sorted((r["n"], r["lower_bound"]) for r in rows
                   if r["method"] == "greedy" and r.get("lower_bound"))
    if lower:
        axes[0].plot(*zip(*lower), "k--", label="lower bound")
    for ax, what in zip(axes, ("Steiner points", "seconds")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("input vertices n (star polygon)")
        ax.set_ylabel(what)
        legend(ax, fontsize=8)
    fig.suptitle("Scaling of the 2D boundary refinement (exponents: log-log least squares)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_corpus(rows: list[dict], path: Path) -> None:
    """Steiner points of each method per input, inputs sorted by lower bound; lower bound and best known."""
    plt = pyplot()
    rows = sorted((r for r in rows if r.get("lower_bound") is not None), key=lambda r: (r["lower_bound"],
                                                                                         r["instance"]))
    fig, ax = plt.subplots(figsize=(12, 4.8))
    x = np.arange(len(rows))
    for method, marker in zip(METHODS, "o^sv"):
        pts = [(i, r[_col(method)]) for i, r in enumerate(rows) if r.get(_col(method)) is not None]
        if pts:
            ax.scatter(*zip(*[(i, max(v, 0.5)) for i, v in pts]), marker=marker, s=16, label=method,
                       alpha=0.8)
    ax.scatter(x, [max(r["lower_bound"], 0.5) for r in rows], marker="_", color="k", s=80,
               label="lower bound")
    known = [(i, r["cgshop_best_known"]) for i, r in enumerate(rows)
             if r.get("cgshop_best_known") is not None]
    if known:
        ax.scatter(*zip(*known), marker="x", color="k", s=16, label="CG:SHOP best known (all triangles)")
    ax.set_yscale("log")
    ax.set_xlabel("input (sorted by lower bound)")
    ax.set_ylabel("Steiner points (0 drawn at 0.5)")
    legend(ax, fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_sweep_arguments(parser)
    parser.add_argument("--instances", metavar="REGEX", help="only the corpus inputs whose name matches")
    parser.add_argument("--sizes", type=lambda s: [int(float(v)) for v in s.split(",")],
                        help="comma-separated scaling sizes instead of the default")
    args = parser.parse_args(argv)
    limit = CASE_SECONDS["quick" if args.quick else "full"]
    out = Path(args.out)

    records = sweep_from_args(args, run_corpus_case, corpus_cases(args.quick, args.seed, args.instances),
                              "steiner_study_2d", time_limit=limit)
    rows = corpus_rows(records)
    stem = output_stem("steiner_study_2d", args.quick)
    write_csv(out / f"{stem}.csv", rows, CORPUS_COLUMNS)
    plot_corpus(rows, out / f"{stem}.png")
    totals = summary(rows)
    write_csv(out / f"{output_stem('steiner_study_2d_summary', args.quick)}.csv", totals, SUMMARY_COLUMNS)
    for t in totals:
        print(f"{t['method']:>12}: {t['steiner_total']} Steiner points on {t['inputs']} inputs (lower bound "
              f"{t['lower_bound_total']}); at the bound on {t['at_lower_bound']}, below it on "
              f"{t['below_lower_bound']}")

    records = sweep_from_args(args, run_scaling_case, scaling_cases(args.quick, args.seed, args.sizes),
                              "steiner_scaling", time_limit=limit)
    rows = scaling_rows(records)
    fits = exponents(rows)
    write_csv(out / f"{output_stem('steiner_scaling', args.quick)}.csv", rows, SCALING_COLUMNS)
    write_csv(out / f"{output_stem('steiner_scaling_exponents', args.quick)}.csv", fits, EXPONENT_COLUMNS)
    plot_scaling(rows, fits, out / f"{output_stem('steiner_scaling', args.quick)}.png")
    for f in fits:
        print(f"{f['method']:>12}: Steiner ~ n^{f['steiner_exponent']}, time ~ n^{f['time_exponent']}"
              f" ({f['sizes_fitted']} sizes)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
