"""The whole process a user runs, ours against Triangle -pD driven from Python, side by side in one run: read
a .poly, (validate,) refine, write .vtu, write .json, with the wall time of each phase and the peak memory.

Inputs: a disk of ``h = min(4000, n / 2)`` boundary vertices (a closed loop, 1-based ids, vertex and segment
marker columns) with ``n - h`` random interior points, coordinates random float64 in shortest round-trip form,
at n = 1e4, 1e5, 1e6 (seed 0), written once to ``OUT/cache/``.

- ours: :func:`nonobtuse.io.triangle.read_poly`, the validation of :func:`nonobtuse.io.load_domain`
  (:func:`nonobtuse.validate.validate_domain`, which marks the domain validated), :func:`nonobtuse.refine`
  (greedy), :func:`nonobtuse.io.write_mesh` to .vtu and to .json.
- Triangle: the reader a user would write (``triangle.load``), ``triangle.triangulate(..., "pDQ")``, meshio
  for the .vtu (its defaults), ``json.dump`` of the arrays' ``tolist()`` for the .json.

Each (tool, n) runs in a child process of its own; the child reports the wall seconds of each phase and its
peak resident memory (``resource.getrusage``, ru_maxrss) after the .vtu (the issue's pipeline: read + refine +
write .vtu) and after the .json. Runs of the two tools alternate, best of ``--repeat`` each (a shared
machine).

    PYTHONPATH=src .venv/bin/python -m experiments.bench_pipeline [--quick] [--sizes 10000 1000000]
        [--repeat 1] [--out OUT]

Writes OUT/bench_pipeline.csv (OUT: default experiments/results; ``--quick``: n = 1e4 and 1e5,
bench_pipeline_quick.csv) and prints the table with the ratios ours / Triangle of the pipeline time and of
the peak memory.
"""

from __future__ import annotations

import argparse
import csv
import json
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from experiments.outputs import add_out_option, out_dir

ROOT = Path(__file__).resolve().parents[1]
PHASES = {
    "ours": ("read", "validate", "refine", "write_vtu", "write_json"),
    "triangle": ("read", "refine", "write_vtu", "write_json"),
}


def write_disk_poly(path: Path, n: int, seed: int = 0) -> None:
    """The benchmark input of ``n`` vertices (module docstring)."""
    rng = np.random.default_rng(seed)
    h = min(4000, n // 2)
    a = np.arange(h) * (2 * np.pi / h)
    r, b = np.sqrt(rng.uniform(0, 0.95, n - h)), rng.uniform(0, 2 * np.pi, n - h)
    points = np.r_[np.c_[np.cos(a), np.sin(a)], np.c_[r * np.cos(b), r * np.sin(b)]] * rng.uniform(1, 2)
    markers = np.r_[np.ones(h, np.int64), np.zeros(n - h, np.int64)]
    with open(path, "w") as f:
        f.write(f"# benchmark disk: {h} boundary vertices, {n - h} interior points\n{n} 2 0 1\n")
        rows = enumerate(zip(points.tolist(), markers.tolist()), start=1)
        f.writelines(f"{i} {x!r} {y!r} {m}\n" for i, ((x, y), m) in rows)
        f.write(f"{h} 1\n")
        f.writelines(f"{i} {i} {i % h + 1} 1\n" for i in range(1, h + 1))
        f.write("0\n")


def run_ours(path: Path, out: Path) -> dict[str, float]:
    from nonobtuse.io import triangle, write_mesh
    from nonobtuse.refinement import refine
    from nonobtuse.validate import validate_domain

    clock = _Clock()
    domain = triangle.read_poly(path)
    clock.lap("read")
    domain = validate_domain(domain, decide_convex_hull=True)  # as load_domain: refine takes it as it is
    clock.lap("validate")
    mesh = refine(domain).mesh
    clock.lap("refine")
    write_mesh(mesh, out.with_suffix(".vtu"))
    clock.lap("write_vtu")
    write_mesh(mesh, out.with_suffix(".json"))
    clock.lap("write_json")
    return clock.record


def run_triangle(path: Path, out: Path) -> dict[str, float]:
    import meshio
    import triangle

    clock = _Clock()
    data = triangle.load(str(path.parent), path.stem)
    clock.lap("read")
    t = triangle.triangulate(data, "pDQ")
    clock.lap("refine")
    points = np.column_stack([t["vertices"], np.zeros(len(t["vertices"]))])
    cells = [("triangle", t["triangles"]), ("line", t["segments"])]
    meshio.write(out.with_suffix(".vtu"), meshio.Mesh(points, cells))
    clock.lap("write_vtu")
    with open(out.with_suffix(".json"), "w") as f:
        json.dump({k: t[k].tolist() for k in ("vertices", "triangles", "segments")}, f)
    clock.lap("write_json")
    return clock.record


class _Clock:
    """Wall seconds per phase and the peak memory (MB) after the .vtu and after the .json."""

    def __init__(self) -> None:
        self.record: dict[str, float] = {}
        self._t = time.perf_counter()

    def lap(self, phase: str) -> None:
        now = time.perf_counter()
        self.record[phase] = now - self._t
        self._t = now
        if phase.startswith("write_"):
            self.record[f"peak_mb_{phase[6:]}"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def child(tool: str, path: Path) -> dict[str, float]:
    """One run in a fresh process: ``python bench_pipeline.py --child TOOL PATH`` prints its record."""
    proc = subprocess.run(
        [sys.executable, __file__, "--child", tool, str(path)], capture_output=True, text=True, check=True
    )
    return json.loads(proc.stdout.splitlines()[-1])


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--quick", action="store_true", help="n = 1e4 and 1e5")
    p.add_argument("--sizes", type=int, nargs="+", help="vertex counts (default 1e4 1e5 1e6)")
    p.add_argument("--repeat", type=int, default=1, help="runs per tool and size, best kept (default 1)")
    p.add_argument("--child", nargs=2, metavar=("TOOL", "PATH"), help=argparse.SUPPRESS)
    add_out_option(p, "the CSV")
    args = p.parse_args()
    if args.child:
        tool, path = args.child[0], Path(args.child[1])
        run = run_ours if tool == "ours" else run_triangle
        print(json.dumps(run(path, path.with_name(f"{path.stem}.{tool}.out"))))
        return
    sizes = args.sizes or ([10_000, 100_000] if args.quick else [10_000, 100_000, 1_000_000])
    cache = out_dir(args, cache=True)
    rows = []
    for n in sizes:
        path = cache / f"bench_pipeline_{n}.poly"
        if not path.is_file():
            write_disk_poly(path, n)
        best: dict[str, dict[str, float]] = {}
        for _ in range(args.repeat):
            for tool in PHASES:
                rec = child(tool, path)
                rec["total"] = sum(rec[k] for k in PHASES[tool] if k != "write_json")
                if tool not in best or rec["total"] < best[tool]["total"]:
                    best[tool] = rec
        for tool, rec in best.items():
            rows.append({"n": n, "tool": tool, **{k: round(v, 3) for k, v in rec.items()}})
        ours, tri = best["ours"], best["triangle"]
        print(
            f"n={n}: ours {ours['total']:.2f} s ({_phases(ours, 'ours')}), {ours['peak_mb_vtu']:.0f} MB | "
            f"Triangle {tri['total']:.2f} s ({_phases(tri, 'triangle')}), {tri['peak_mb_vtu']:.0f} MB | "
            f"time ratio {ours['total'] / tri['total']:.2f}, memory ratio "
            f"{ours['peak_mb_vtu'] / tri['peak_mb_vtu']:.2f}",
            flush=True,
        )
    out = out_dir(args) / ("bench_pipeline_quick.csv" if args.quick else "bench_pipeline.csv")
    fields = ["n", "tool", "total", *PHASES["ours"], "peak_mb_vtu", "peak_mb_json"]
    with open(out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)
    print(f"wrote {out} (total: read + validate + refine + write .vtu; .json apart)")


def _phases(rec: dict[str, float], tool: str) -> str:
    return ", ".join(f"{k} {rec[k]:.2f}" for k in PHASES[tool])


if __name__ == "__main__":
    main()
