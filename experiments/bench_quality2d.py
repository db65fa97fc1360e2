"""Benchmark of interior quality refinement (refine(min_angle=...)) against Triangle -pqXD on the same inputs:
total vertices, boundary Steiner points (on constraints), interior points, smallest angle, wall time.

Inputs: the 2D polygons and PSLGs of ../shared/data/2d (those validation accepts, with their holes; a point
set over its convex hull) and the demo's cross-section (nonobtuse.demo.cross_section). Each runs at 25
degrees; 30 degrees too on the inputs without input angles below 60 degrees (where Triangle and we both refine
every triangle). Triangle gets the same points, segments and holes, with -pq<deg>D (conforming Delaunay, no
area bound). Boundary Steiner points are counted the same way for both tools: output vertices beyond the
input's that lie on an output segment (ours is checked against refine's stats["steiner_points"]).
Our smallest angle is the one outside small-input-angle regions (triangles there are left alone, as Triangle
does), and both counts are given. boundary_mode: which boundary refine kept (its quality_boundary="best":
"midpoints" or "minimal"); removed: the boundary Steiner points it took back after convergence (already
subtracted from boundary_steiner).

    PYTHONPATH=src .venv/bin/python -m experiments bench_quality2d [--out DIR]

Writes bench_quality2d.csv in --out DIR (default experiments/results) and prints a table with the vertex ratio
ours / Triangle's.
"""

from __future__ import annotations

import argparse
import csv
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path[:0] = [str(ROOT / "tests")]

import nonobtuse  # noqa: E402
from experiments.outputs import add_out_option, out_dir  # noqa: E402
from nonobtuse import Domain, InvalidInputError  # noqa: E402
from nonobtuse.demo import cross_section  # noqa: E402
from nonobtuse.io import load_domain  # noqa: E402
from nonobtuse.peers import triangle_quality  # noqa: E402
from nonobtuse.validate import ensure_validated  # noqa: E402
from refine_helpers import SHARED  # noqa: E402


def min_input_angle(d: Domain) -> float:
    """The smallest angle (degrees) between two input segments at a common vertex (180 without any)."""
    best = 180.0
    around: dict[int, list[int]] = {}
    for a, b in d.segments.tolist():
        around.setdefault(a, []).append(b)
        around.setdefault(b, []).append(a)
    for v, ws in around.items():
        if len(ws) < 2:
            continue
        u = d.points[ws] - d.points[v]
        ang = np.sort(np.arctan2(u[:, 1], u[:, 0]))
        gaps = np.diff(np.r_[ang, ang[0] + 2 * np.pi])
        best = min(best, float(np.degrees(gaps.min())))
    return best


def triangle_q(d: Domain, degrees: float) -> dict:
    t = triangle_quality(d, degrees)
    return {"tri_vertices": t["vertices"], "tri_boundary_steiner": t["boundary_steiner"],
            "tri_min_angle": round(t["min_angle"], 3), "tri_seconds": round(t["seconds"], 4)}


def ours(d: Domain, degrees: float) -> dict:
    t0 = time.perf_counter()
    r = nonobtuse.refine(d, min_angle=degrees)
    seconds = time.perf_counter() - t0
    q = r.stats["quality"]
    boundary_steiner = int(np.count_nonzero(np.unique(r.mesh.segments) >= len(d.points)))
    if boundary_steiner != r.stats["steiner_points"]:
        raise RuntimeError(f"{boundary_steiner} output vertices on segments beyond the input's, "
                           f"stats say {r.stats['steiner_points']} Steiner points")
    return {"status": r.status, "certificate": r.stats["obtuse_boundary_sides"],
            "vertices": len(r.mesh.points), "boundary_steiner": boundary_steiner,
            "removed": q["boundary_points_removed"],
            "interior": r.stats["interior_points"], "boundary_mode": q["boundary"],
            "min_angle_outside": round(q["min_angle_outside_small_angles_degrees"], 3),
            "min_angle": round(q["min_angle_degrees"], 3),
            "small_angle_triangles": q["small_angle_triangles"],
            "seconds": round(seconds, 4)}


def inputs() -> list[tuple[str, Domain]]:
    out = [("demo cross_section", ensure_validated(cross_section()))]
    folder = SHARED / "2d"
    for path in sorted(folder.glob("*")) if folder.is_dir() else []:
        if path.suffix not in (".poly", ".node"):
            continue
        try:
            out.append((path.name, load_domain(path)))
        except InvalidInputError as e:
            print(f"skipped {path.name}: {e}", file=sys.stderr)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_out_option(ap, "bench_quality2d.csv")
    args = ap.parse_args()
    rows = []
    for name, d in inputs():
        small = min_input_angle(d)
        for degrees in (25.0, 30.0) if small >= 60 else (25.0,):
            row = {"input": name, "points": len(d.points), "min_input_angle": round(small, 2),
                   "degrees": degrees, **ours(d, degrees), **triangle_q(d, degrees)}
            row["vertex_ratio"] = round(row["vertices"] / row["tri_vertices"], 3)
            rows.append(row)
            r = row
            print(f"{name:28s} {degrees:4g} deg  ours {r['vertices']:6d} v ({r['boundary_steiner']:5d} bnd "
                  f"after {r['removed']} removed, "
                  f"{r['status']}, min {r['min_angle_outside']:6.2f}, {r['seconds']:.3f} s)  triangle "
                  f"{r['tri_vertices']:6d} v ({r['tri_boundary_steiner']:5d} bnd, "
                  f"min {r['tri_min_angle']:6.2f}, "
                  f"{r['tri_seconds']:.3f} s)  ratio {r['vertex_ratio']:.3f}", flush=True)
    path = out_dir(args) / "bench_quality2d.csv"
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    ratios = np.array([r["vertex_ratio"] for r in rows])
    fewer = sum(r["boundary_steiner"] < r["tri_boundary_steiner"] for r in rows)
    tied = [f"{r['input']} {r['degrees']:g}" for r in rows
            if r["boundary_steiner"] == r["tri_boundary_steiner"]]
    more = sum(r["boundary_steiner"] > r["tri_boundary_steiner"] for r in rows)
    adds = [r for r in rows if r["tri_boundary_steiner"] > 0]
    fewer_where_adds = sum(r["boundary_steiner"] < r["tri_boundary_steiner"] for r in adds)
    print(f"vertex ratio ours / Triangle: median {np.median(ratios):.3f}, max {ratios.max():.3f}; boundary "
          f"Steiner points fewer on {fewer} of {len(rows)}, more on {more}, equal on {len(tied)} "
          f"({', '.join(tied)}); fewer on {fewer_where_adds} of the {len(adds)} where Triangle adds any "
          f"-> {path}")


if __name__ == "__main__":
    main()
