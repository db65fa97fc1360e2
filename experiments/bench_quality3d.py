"""Interior quality in 3D: refine_quality3d against TetGen -pq R -a V on the 3D corpus.

For every input of ../shared/data/3d and tests/data/3d (or the paths given), with the same bounds for both:
radius-edge R (default 2.0) and maximum volume V = --volume-fraction (default 1e-3) times the volume of the
input's bounding box:

- tetgen: TetGen ``-pq R -a V`` (splits the boundary as it likes; its mesh is not Gabriel-checked by TetGen);
- ours:   refine_quality3d (the Gabriel repair of the input boundary, interior points outside every closed
          diametral sphere, circumcenter rounds; time_limit --time-limit, or none with --deterministic:
          the work budgets alone, so the outcome does not depend on the machine's load); with
          --start tetgen its TetGen start instead (TetGen's facet splits and -Y points first; rows
          "ours-tetgen").

Columns: input, method, status, points, boundary_points (vertices of boundary faces and segments),
interior_points, tets, worst_radius_edge, max_volume (largest tet volume; both floating point, over every
tet), volume_bound (V), encroached_facets, encroached_segments (the exact check_gabriel of the mesh as
returned), small_angle_tets and worst_radius_edge_outside / max_volume_outside (ours: the tets the
small-angle rule left over a bound, and the quality of the others), seconds, cpu_seconds (of the child).
Each method runs in a child process killed after 2 time_limit + 60 s, or --timeout with --deterministic
(status "timeout": TetGen has no time limit). CSV to DIR/bench_quality3d.csv (``--quick``:
bench_quality3d_quick.csv; ``--start tetgen``: bench_quality3d_tetgen[_quick].csv) and a Markdown table on
stdout.

Run: ``PYTHONPATH=src .venv/bin/python -m experiments.bench_quality3d [--quick] [--out DIR] [files...]``
(--quick: inputs up to 500 triangles, 20 s each for ours; --deterministic [--timeout S]: no time limit).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Any

import numpy as np

from experiments.sweep import output_stem, run_case_limited, write_csv
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d import check_gabriel, load_plc, tetrahedralize
from nonobtuse.mesh3d.load import PLC_SUFFIXES, SURFACE_SUFFIXES
from nonobtuse.mesh3d.quality3d import refine_quality3d, tet_quality

ROOT = Path(__file__).resolve().parents[1]
CORPORA = [ROOT / ".." / "shared" / "data" / "3d", ROOT / "tests" / "data" / "3d"]
RESULTS = ROOT / "experiments" / "results"
COLUMNS = ["input", "method", "status", "points", "boundary_points", "interior_points", "tets",
           "worst_radius_edge", "max_volume", "volume_bound", "encroached_facets", "encroached_segments",
           "small_angle_tets", "worst_radius_edge_outside", "max_volume_outside", "seconds", "cpu_seconds"]


def measure(name: str, method: str, mesh, status: str, volume_bound: float, seconds: tuple[float, float],
            stats: dict[str, Any] | None = None) -> dict[str, Any]:
    """One CSV row: counts, tet quality and the exact Gabriel check of mesh; with ours' stats, the tets left
    alone by the small-angle rule and the quality of the others. seconds: (wall, CPU) of the method."""
    report = check_gabriel(mesh)
    on = np.zeros(len(mesh.points), dtype=bool)
    on[np.asarray(mesh.boundary_faces, dtype=np.int64).ravel()] = True
    on[np.asarray(mesh.segments, dtype=np.int64).ravel()] = True
    q = tet_quality(mesh)
    return {"input": name, "method": method, "status": status, "points": len(mesh.points),
            "boundary_points": int(on.sum()), "interior_points": int((~on).sum()), "tets": q["tets"],
            "worst_radius_edge": _round(q["worst_radius_edge"]), "max_volume": _round(q["max_volume"]),
            "volume_bound": _round(volume_bound), "encroached_facets": len(report.faces),
            "encroached_segments": len(report.segments),
            **({} if stats is None else {
                "small_angle_tets": stats["small_angle_tets"],
                "worst_radius_edge_outside": _round(stats["worst_radius_edge_outside_small_angles"]),
                "max_volume_outside": _round(stats["max_volume_outside_small_angles"])}),
            "seconds": round(seconds[0], 3), "cpu_seconds": round(seconds[1], 3)}


def _round(x: float | None) -> float | None:
    return None if x is None else float(f"{x:.4g}")


def run_case(case: dict[str, Any]) -> dict[str, Any]:
    """One row (the sweep task, run in a child process): case has path, name, method ("tetgen", "ours" or
    "ours-tetgen"), start (refine_quality3d's), radius_edge, volume_fraction, time_limit."""
    plc = load_plc(case["path"])
    extent = plc.points.max(axis=0) - plc.points.min(axis=0)
    bound = case["volume_fraction"] * float(np.prod(extent))
    name, r = case["name"], case["radius_edge"]
    t0, cpu0 = time.perf_counter(), time.process_time()

    def spent() -> tuple[float, float]:
        return time.perf_counter() - t0, time.process_time() - cpu0

    if case["method"] == "tetgen":
        try:
            tm = tetrahedralize(plc, "tetgen", switches=f"pq{r!r}a{bound!r}AQ")
        except InvalidInputError as e:
            return {"input": name, "method": "tetgen", "status": f"failed: {str(e)[-60:]}"}
        return measure(name, "tetgen", tm, "ok", bound, spent())
    result = refine_quality3d(plc, max_volume=bound, radius_edge=r, time_limit=case["time_limit"],
                              start=case["start"])
    return measure(name, case["method"], result.mesh, result.status, bound, spent(), result.stats)


def bench_one(name: str, path: Path, args: argparse.Namespace) -> list[dict[str, Any]]:
    """The rows of TetGen and ours on one input, each in a child process killed after 2 time_limit + 60 s
    or args.timeout without a time limit (TetGen has no time limit of its own: -pq ran for minutes on
    mc_torus.off)."""
    rows = []
    for method in ("tetgen", "ours" if args.start == "boundary" else "ours-tetgen"):
        case = {"path": str(path), "name": name, "method": method, "start": args.start,
                "radius_edge": args.radius_edge, "volume_fraction": args.volume_fraction,
                "time_limit": args.time_limit}
        kill = args.timeout if args.time_limit is None else 2 * args.time_limit + 60
        record = run_case_limited("experiments.bench_quality3d:run_case", case, kill)
        if record["status"] == "ok":
            rows.append(record["result"])
        else:
            rows.append({"input": name, "method": method, "status": record["status"],
                         "seconds": record["seconds"]})
    return rows


def markdown_table(rows: list[dict[str, Any]]) -> str:
    """The rows as a Markdown table (the README's form), one line per row."""
    lines = ["| " + " | ".join(COLUMNS) + " |", "|" + " --- |" * len(COLUMNS)]
    lines += ["| " + " | ".join(str(r.get(c, "")) for c in COLUMNS) + " |" for r in rows]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("inputs", nargs="*", type=Path, help="default: every 3D file of the two corpora")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--out", type=Path, default=RESULTS, help="directory of the CSV")
    ap.add_argument("--radius-edge", type=float, default=2.0)
    ap.add_argument("--volume-fraction", type=float, default=1e-3)
    ap.add_argument("--time-limit", type=float, default=None, help="seconds for ours (default 120, quick 20)")
    ap.add_argument("--deterministic", action="store_true",
                    help="no time limit for ours: its work budgets alone (outcomes independent of the load)")
    ap.add_argument("--timeout", type=float, default=600.0,
                    help="with --deterministic: seconds after which a child is killed (default 600)")
    ap.add_argument("--start", choices=("boundary", "tetgen"), default="boundary",
                    help="refine_quality3d's start (default: its default, boundary)")
    args = ap.parse_args(argv)
    args.max_triangles = 500 if args.quick else 10**9
    args.time_limit = None if args.deterministic else args.time_limit or (20.0 if args.quick else 120.0)
    suffixes = SURFACE_SUFFIXES + PLC_SUFFIXES
    inputs = args.inputs or [p for d in CORPORA if d.is_dir() for p in sorted(d.glob("*"))
                             if p.suffix in suffixes]
    if not inputs:
        print("no inputs", file=sys.stderr)
        return 2
    rows: list[dict[str, Any]] = []
    stem = "bench_quality3d" if args.start == "boundary" else "bench_quality3d_tetgen"
    out = args.out / f"{output_stem(stem, args.quick)}.csv"
    for path in inputs:
        print(f"bench_quality3d: {path.name}", file=sys.stderr)
        name = f"{path.resolve().parents[2].name}/{path.name}"  # shared/... or tests/...: the corpus
        try:
            plc = load_plc(path)
        except InvalidInputError as e:
            rows.append({"input": name, "status": f"invalid: {e}"[:60]})
            continue
        too_big = len(plc.triangles) > args.max_triangles
        rows += [{"input": name, "status": "skipped (size)"}] if too_big else bench_one(name, path, args)
        write_csv(out, rows, COLUMNS)  # after every input: a long run shows its rows as it goes
    print(markdown_table(rows))
    print(f"\nwrote {out}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
