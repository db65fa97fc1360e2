"""Boundary Gabriel property of 3D meshes: TetGen, fTetWild and our refinement on the 3D corpus.

For every input of ../shared/data/3d (or the paths given) and every method, the exact check of nonobtuse
(check_gabriel: a boundary subfacet/subsegment is encroached when a mesh vertex lies strictly inside its
diametral sphere) is run on the mesh produced:

- tetgen-pq: TetGen ``-pq1.414`` (quality; splits the boundary as it likes);
- tetgen-pD: TetGen ``-pD`` (conforming Delaunay);
- tetgen-pY: TetGen ``-pY`` (keeps the boundary: no boundary Steiner point);
- ftetwild:  fTetWild (remeshes the surface within an envelope);
- ours:      refine_gabriel with its defaults (boundary Steiner points until no boundary facet or segment is
             encroached): concentric shells, then the protected strategy where shells does not converge;
- ours-greedy: the same with split="greedy" (Greedy-Refine along subsegments; shells at acute input vertices);
- ours-protected: split="protected" (protecting balls at apex vertices from the start).

Columns: input, method, status, strategy (ours: the strategy of the returned mesh, e.g. "shells+protected"
after a fallback), points, boundary_steiner (boundary-face vertices that are not input points), steiner (all
output points that are not input points), boundary_faces, encroached_facets, encroached_segments ("n/a" for
fTetWild, whose output does not mark segments), seconds, vs_tetgen_pq (seconds / tetgen-pq's seconds on the
same input; refine3d's target is <= 2), cpu_seconds and cpu_vs_tetgen_pq (the same in CPU seconds of this
process, steadier than wall time on a loaded machine; every method runs in-process). ``--methods tetgen-pq
ours`` runs only those rows. ``--repeat K`` runs the methods of an input K times, interleaved, and keeps each
method's least seconds and least CPU seconds (:func:`fastest`): TetGen's time on a small input swings by half
between single runs, so that the ratio of one run says little. CSV to bench_gabriel3d.csv
(bench_gabriel3d_quick.csv with --quick) in --out DIR (default experiments/results), and a table on stdout.

``--scaling [FACES...]``: instead, check3d end to end (a fresh ``nonobtuse check3d --json`` process) on
jittered tori (:func:`torus_surface`) of 1e4, 1e5, 1e6 faces (or those given), with the cgal and tetgen
backends: faces, points, backend, exit, seconds, cpu_seconds, load (1-minute average at the start), peak_mb
to bench_gabriel3d_scaling.csv; the tori are written to DIR/cache.

Run: ``PYTHONPATH=src .venv/bin/python -m experiments bench_gabriel3d [--quick] [--out DIR] [files...]``
(default: our refinement limited to 60 s and its default budget, 10 n + 10,000 points; --quick: inputs
up to 500 triangles, our refinement limited to 20 s and 2,000 points, about 1 min).
"""

from __future__ import annotations

import argparse
import os
import sys
import time
from pathlib import Path
from typing import Any, Callable

import numpy as np

from experiments.outputs import add_out_option, out_dir
from experiments.sweep import output_stem, write_csv
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d import check_gabriel, load_plc, refine_gabriel, tetrahedralize
from nonobtuse.mesh3d.load import PLC_SUFFIXES, SURFACE_SUFFIXES

ROOT = Path(__file__).resolve().parents[1]
DATA3D = ROOT / ".." / "shared" / "data" / "3d"
COLUMNS = ["input", "method", "status", "strategy", "points", "boundary_steiner", "steiner", "boundary_faces",
           "encroached_facets", "encroached_segments", "seconds", "vs_tetgen_pq", "cpu_seconds",
           "cpu_vs_tetgen_pq"]
METHODS = ("tetgen-pq", "tetgen-pD", "tetgen-pY", "ftetwild", "ours", "ours-greedy", "ours-protected")


def measure(name: str, method: str, plc, mesh, status: str, started: tuple[float, float]) -> dict[str, Any]:
    """One CSV row: counts of the mesh and its exact Gabriel check, and the seconds since started (a clocks()
    reading) without that check."""
    seconds, cpu_seconds = (now - then for now, then in zip(clocks(), started))
    report = check_gabriel(mesh)
    n = len(plc.points)
    bverts = np.unique(mesh.boundary_faces)
    return {"input": name, "method": method, "status": status, "points": len(mesh.points),
            "boundary_steiner": int((bverts >= n).sum()), "steiner": len(mesh.points) - n,
            "boundary_faces": len(mesh.boundary_faces), "encroached_facets": len(report.faces),
            # fTetWild does not say which of its edges are segments: nothing to check there
            "encroached_segments": len(report.segments) if len(mesh.segments) else "n/a",
            "seconds": round(seconds, 3), "cpu_seconds": round(cpu_seconds, 3)}


def clocks() -> tuple[float, float]:
    """Wall and CPU seconds (this process, all threads)."""
    return time.perf_counter(), time.process_time()


def torus_surface(faces: int, seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """A closed torus (major radius 4, minor 1) of about ``faces`` triangles: a u-by-v grid (u = 2v) of
    points moved along the torus by up to a fifth of a grid step (seeded), each grid square cut into two
    triangles, outward. Points (n, 3) float64, triangles (2n, 3) int64, n = u v; built with numpy in O(n)."""
    v = max(3, int(round((faces / 4) ** 0.5)))
    u = 2 * v
    rng = np.random.default_rng(seed)
    a = (np.arange(u)[:, None] + rng.uniform(-0.2, 0.2, (u, v))) * (2 * np.pi / u)
    b = (np.arange(v)[None, :] + rng.uniform(-0.2, 0.2, (u, v))) * (2 * np.pi / v)
    ring = 4.0 + np.cos(b)
    points = np.column_stack([(ring * np.cos(a)).ravel(), (ring * np.sin(a)).ravel(), np.sin(b).ravel()])
    i, j = np.meshgrid(np.arange(u), np.arange(v), indexing="ij")
    p00, p10, p01, p11 = (((i + di) % u) * v + (j + dj) % v for di, dj in ((0, 0), (1, 0), (0, 1), (1, 1)))
    triangles = np.concatenate([np.stack([p00, p10, p11], -1).reshape(-1, 3),
                                np.stack([p00, p11, p01], -1).reshape(-1, 3)])
    return points, triangles


def write_off(path: Path, points: np.ndarray, triangles: np.ndarray) -> None:
    """OFF of a triangle surface (coordinates with repr's 17 digits: read back exactly), atomically."""
    from nonobtuse.io import atomic_text

    with atomic_text(path) as f:
        f.write(f"OFF\n{len(points)} {len(triangles)} 0\n")
        np.savetxt(f, points, fmt="%.17g")
        np.savetxt(f, np.column_stack([np.full(len(triangles), 3), triangles]), fmt="%d")


def run_backend(name: str, plc, method: str, backend: str, **options) -> dict[str, Any]:
    t0 = clocks()
    try:
        mesh = tetrahedralize(plc, backend, **options)
    except InvalidInputError as e:
        reason = str(e).replace(f"on {plc.source} ", "")  # no machine paths in the csv
        return {"input": name, "method": method, "status": f"failed: {reason[:60]}"}
    return measure(name, method, plc, mesh, "ok", t0)


def run_ours(name: str, plc, max_steiner: int | None, time_limit: float,
             split: str = "shells") -> dict[str, Any]:
    t0 = clocks()
    result = refine_gabriel(plc, max_steiner=max_steiner, time_limit=time_limit, split=split)
    method = "ours" if split == "shells" else f"ours-{split}"
    row = measure(name, method, plc, result.mesh, result.status, t0)
    row["strategy"] = result.stats["strategy"]
    return row


def bench_one(path: Path, args: argparse.Namespace) -> list[dict[str, Any]]:
    name = path.name
    try:
        plc = load_plc(path)
    except InvalidInputError as e:
        return [{"input": name, "method": "-", "status": f"invalid: {str(e)[:40]}"}]
    if len(plc.triangles) > args.max_triangles:
        return [{"input": name, "method": "-", "status": f"skipped: {len(plc.triangles)} triangles"}]
    run: dict[str, Callable[[], dict[str, Any]]] = {
        "tetgen-pq": lambda: run_backend(name, plc, "tetgen-pq", "tetgen", switches="pq1.414AQ"),
        "tetgen-pD": lambda: run_backend(name, plc, "tetgen-pD", "tetgen", switches="pDAQ"),
        "tetgen-pY": lambda: run_backend(name, plc, "tetgen-pY", "tetgen", switches="pYAQ"),
        "ftetwild": lambda: (run_backend(name, plc, "ftetwild", "ftetwild")
                             if len(plc.triangles) <= args.ftetwild_max_triangles
                             else {"input": name, "method": "ftetwild", "status": "skipped (size)"}),
        "ours": lambda: run_ours(name, plc, args.max_steiner, args.time_limit),
        "ours-greedy": lambda: run_ours(name, plc, args.max_steiner, args.time_limit, split="greedy"),
        "ours-protected": lambda: run_ours(name, plc, args.max_steiner, args.time_limit, split="protected"),
    }
    methods = [method for method in METHODS if method in args.methods]
    runs: dict[str, list[dict[str, Any]]] = {method: [] for method in methods}
    for _ in range(args.repeat):
        for method in methods:
            runs[method].append(run[method]())
    return with_time_ratios([fastest(runs[method]) for method in methods])


TIMES = ("seconds", "cpu_seconds")


def fastest(runs: list[dict[str, Any]]) -> dict[str, Any]:
    """One row for repeated runs of one method on one input: the first run's row with the least seconds and
    the least CPU seconds of all runs (each clock's least disturbed run). Where the runs' other columns differ
    (every method here should be deterministic), a warning on stderr names the input and method."""
    row = dict(runs[0])
    if any({k: v for k, v in r.items() if k not in TIMES} != {k: v for k, v in row.items() if k not in TIMES}
           for r in runs[1:]):
        print(f"bench_gabriel3d: {row['input']} {row['method']}: the repeated runs' results differ; the "
              "first run's are kept", file=sys.stderr)
    for column in TIMES:
        values = [r[column] for r in runs if r.get(column) is not None]
        if values:
            row[column] = min(values)
    return row


def with_time_ratios(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """The rows of one input with vs_tetgen_pq and cpu_vs_tetgen_pq: each row's seconds over the tetgen-pq
    row's (blank when either has no time, e.g. a failed run)."""
    for column, ratio in (("seconds", "vs_tetgen_pq"), ("cpu_seconds", "cpu_vs_tetgen_pq")):
        pq = next((r.get(column) for r in rows if r["method"] == "tetgen-pq"), None)
        for r in rows:
            if pq and r.get(column) is not None:
                r[ratio] = round(r[column] / pq, 2)
    return rows


SCALING_COLUMNS = ["faces", "points", "backend", "exit", "seconds", "cpu_seconds", "load", "peak_mb"]


def check3d_scaling(args: argparse.Namespace) -> list[dict[str, Any]]:
    """check3d end to end (``nonobtuse check3d FILE --backend B --json`` in a fresh process: load, validate,
    tetrahedralize, exact check, control volumes, JSON) on :func:`torus_surface` of each size in
    args.scaling, written to the cache first; wall seconds, CPU seconds (user + system) and peak resident
    memory of the process, and the 1-minute load average when it started (the machine is shared: the wall
    time follows the others' load, the CPU time much less)."""
    import resource
    import subprocess

    rows = []
    for faces in args.scaling:
        path = out_dir(args, cache=True) / f"torus_{faces}.off"
        points, triangles = torus_surface(faces)
        if not path.exists():
            write_off(path, points, triangles)
        for backend in args.scaling_backends:
            print(f"bench_gabriel3d: check3d {path.name} --backend {backend}", file=sys.stderr)
            load = os.getloadavg()[0]
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            t0 = time.perf_counter()
            command = [sys.executable, "-c", "import sys; from nonobtuse.cli import main; sys.exit(main())",
                       "check3d", str(path), "--backend", backend, "--json"]
            done = subprocess.run(command, capture_output=True, text=True)
            seconds = time.perf_counter() - t0
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpu = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
            peak = after.ru_maxrss / 1024  # the largest child so far
            if done.returncode not in (0, 1):  # 1: not Gabriel, an answer
                print(done.stderr[-500:], file=sys.stderr)
            rows.append({"faces": len(triangles), "points": len(points),
                         "backend": backend, "exit": done.returncode, "seconds": round(seconds, 2),
                         "cpu_seconds": round(cpu, 2), "load": round(load, 1), "peak_mb": round(peak)})
    return rows


def print_table(rows: list[dict[str, Any]]) -> None:
    widths = {c: max(len(c), *(len(str(r.get(c, ""))) for r in rows)) for c in COLUMNS}
    print("  ".join(c.ljust(widths[c]) for c in COLUMNS))
    for r in rows:
        print("  ".join(str(r.get(c, "")).ljust(widths[c]) for c in COLUMNS))


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("inputs", nargs="*", type=Path, help="default: every file of ../shared/data/3d")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--scaling", type=int, nargs="*", default=None, metavar="FACES",
                    help="instead: the check3d scaling rows on tori of these face counts (default 1e4 "
                         "1e5 1e6) to bench_gabriel3d_scaling.csv")
    ap.add_argument("--scaling-backends", nargs="+", default=["cgal", "tetgen"], choices=("cgal", "tetgen"))
    ap.add_argument("--methods", nargs="+", default=list(METHODS), choices=METHODS,
                    help="only these rows per input (vs_tetgen_pq needs tetgen-pq)")
    ap.add_argument("--repeat", type=int, default=1, metavar="K",
                    help="run the methods of each input K times, interleaved; keep each one's least times")
    add_out_option(ap, "bench_gabriel3d.csv")
    args = ap.parse_args(argv)
    if args.repeat < 1:
        ap.error(f"--repeat must be at least 1 (got {args.repeat})")
    if args.scaling is not None:
        args.scaling = args.scaling or [10**4, 10**5, 10**6]
        rows = check3d_scaling(args)
        path = out_dir(args) / "bench_gabriel3d_scaling.csv"
        write_csv(path, rows, SCALING_COLUMNS)
        print("\n".join("  ".join(str(r[c]) for c in SCALING_COLUMNS) for r in rows))
        return 0
    quick = args.quick
    args.max_triangles = 500 if quick else 10**9
    args.ftetwild_max_triangles = 500 if quick else 20000
    args.max_steiner = 2000 if quick else None  # full: refine_gabriel's default budget
    args.time_limit = 20.0 if quick else 60.0
    inputs = args.inputs or sorted(p for p in DATA3D.glob("*") if p.suffix in SURFACE_SUFFIXES + PLC_SUFFIXES)
    if not inputs:
        print(f"no inputs (is {DATA3D} present?)", file=sys.stderr)
        return 2
    rows = []
    for path in inputs:
        print(f"bench_gabriel3d: {path.name}", file=sys.stderr)
        rows += bench_one(path, args)
    path = out_dir(args) / f"{output_stem('bench_gabriel3d', quick)}.csv"
    write_csv(path, rows, COLUMNS)
    print_table(rows)
    print(f"\nwrote {path}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
