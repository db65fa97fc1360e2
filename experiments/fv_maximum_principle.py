"""The discrete maximum principle on exported control-volume coefficients: our meshes against the plain
constrained Delaunay mesh (2D) and TetGen -pq (3D).

For each mesh the grid is exported to .npz (``nonobtuse.io.export``) and read back; the two-point-flux
matrix is assembled from the exported coefficients alone (A_ab = -area/distance, rows summing to 0) and two
steady diffusion problems are solved with scipy.sparse:

Both fix u on the two ends of the part, the boundary cells within 5 % of the bounding box's x extent from
either end (the left and right sides of the section), and leave every other cell free, with no flux through
the rest of the boundary (Neumann), so wrong-signed couplings between boundary cells matter too:

- **Dirichlet ends**: u = 1 on the left end, 0 on the right end, no source. The discrete maximum principle
  says every free cell has 0 <= u <= 1; ``cells_outside`` counts the cells that leave [0, 1] by more than
  1e-9 and ``max_overshoot`` is the largest excursion.
- **Point sources** (inverse positivity): u = 0 on both ends, a unit source in one free cell. An M-matrix has
  a nonnegative inverse, so every response is >= 0; ``negative_responses`` counts the (source, cell) pairs
  below -1e-9 times the source cell's own response. Sources: the free cells touching a wrong-signed
  connection, else (a certified mesh has none) every k-th free cell; at most 200.

Cases: the 2D geological section of ``nonobtuse.demo`` (refined by ``nonobtuse.refine`` against its plain
constrained Delaunay triangulation) and a 3D part from ``../shared/data/3d`` (joint.off: ``refine_gabriel``
against TetGen ``-pq1.414``). ``--quick`` runs the 2D section only.

    PYTHONPATH=src python -m experiments.fv_maximum_principle [--quick] [--part PATH] [--out OUT]

Outputs ``OUT/fv_maximum_principle.csv`` (counts; OUT: default experiments/results) and
``fv_maximum_principle.png`` (per mesh,
the cells where either problem breaks the principle, coloured by the overshoot or the negative response),
``*_quick.*`` with ``--quick``.
"""

from __future__ import annotations

import argparse
import csv
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

import numpy as np
import scipy.sparse
import scipy.sparse.linalg

from experiments.outputs import add_out_option, out_dir
from nonobtuse.demo import cross_section
from nonobtuse.io.export import export_mesh
from nonobtuse.refinement import refine
from nonobtuse.triangulation import triangulate

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_PART = ROOT / ".." / "shared" / "data" / "3d" / "joint.off"
TOLERANCE = 1e-9
MAX_SOURCES = 200
END_FRACTION = 0.05
COLUMNS = ("case", "mesh", "cells", "connections", "negative_coefficients", "fixed_cells",
           "cells_outside",
           "max_overshoot", "sources", "negative_responses", "most_negative_response", "seconds")


def load_exported(npz: Path) -> dict[str, np.ndarray]:
    with np.load(npz) as z:
        return {k: z[k] for k in z.files}


def laplacian(g: dict[str, np.ndarray]) -> scipy.sparse.csr_matrix:
    """The two-point-flux matrix of the exported coefficients: off-diagonal -area/distance, rows sum to 0."""
    n = len(g["volumes"])
    a, b = g["connections"].T
    off = scipy.sparse.coo_matrix((g["coefficients"], (a, b)), shape=(n, n))
    off = (off + off.T).tocsr()
    return (off - scipy.sparse.diags(np.asarray(off.sum(axis=1)).ravel())).tocsr()


def ends(g: dict[str, np.ndarray]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The fixed cells on the left and right ends (module docstring) and the free cells."""
    boundary = np.unique(g["boundary_cells"])
    x = g["centers"][:, 0]
    margin = END_FRACTION * (x.max() - x.min())
    left = boundary[x[boundary] <= x.min() + margin]
    right = boundary[x[boundary] >= x.max() - margin]
    free = np.setdiff1d(np.arange(len(x)), np.concatenate([left, right]))
    return left, right, free


def dirichlet_ends(g: dict[str, np.ndarray], a: scipy.sparse.csr_matrix) -> tuple[np.ndarray, np.ndarray]:
    """The free cells and their excursion outside [0, 1] for u = 1 on the left end, 0 on the right."""
    left, right, free = ends(g)
    rhs = -a[free][:, left] @ np.ones(len(left))
    u = scipy.sparse.linalg.spsolve(a[free][:, free].tocsc(), rhs)
    return free, np.maximum(np.maximum(u - 1.0, -u), 0.0)


def point_sources(g: dict[str, np.ndarray], a: scipy.sparse.csr_matrix) -> tuple[int, int, np.ndarray]:
    """(sources, negative responses, per free cell the most negative relative response to any source, <= 0)
    for unit sources (module docstring)."""
    _, _, free = ends(g)
    position = np.full(len(g["volumes"]), -1)
    position[free] = np.arange(len(free))
    wrong = np.unique(g["connections"][g["signs"] < 0])
    sources = position[wrong[position[wrong] >= 0]]
    if len(sources) == 0:
        sources = np.arange(0, len(free), max(1, len(free) // MAX_SOURCES))
    sources = sources[:MAX_SOURCES]
    lu = scipy.sparse.linalg.splu(a[free][:, free].tocsc())
    negative, worst = 0, np.zeros(len(free))
    for s in sources.tolist():
        e = np.zeros(len(free))
        e[s] = 1.0
        u = lu.solve(e)
        relative = u / u[s]
        negative += int((relative < -TOLERANCE).sum())
        worst = np.minimum(worst, relative)
    return len(sources), negative, worst


def measure(case: str, label: str, mesh: Any, workdir: Path) -> tuple[dict[str, Any], dict[str, Any]]:
    t0 = time.perf_counter()
    grid, _ = export_mesh(mesh, workdir / f"{case}_{label}.npz")
    g = load_exported(workdir / f"{case}_{label}.npz")
    a = laplacian(g)
    free, excursion = dirichlet_ends(g, a)
    sources, negative, worst = point_sources(g, a)
    outside = excursion > TOLERANCE
    violation = np.maximum(excursion, -worst)  # per free cell: overshoot or negative response
    bad = violation > TOLERANCE
    row = {"case": case, "mesh": label, "cells": len(g["volumes"]), "connections": len(g["connections"]),
           "negative_coefficients": grid.negative_coefficients,
           "fixed_cells": len(g["volumes"]) - len(free), "cells_outside": int(outside.sum()),
           "max_overshoot": float(excursion.max()) if len(excursion) else 0.0, "sources": sources,
           "negative_responses": negative,
           "most_negative_response": float(worst.min()) if len(worst) else 0.0,
           "seconds": round(time.perf_counter() - t0, 2)}
    picture = {"centers": g["centers"], "bad": free[bad], "violation": violation[bad],
               "title": f"{int(outside.sum())} cells outside [0, 1], {int((worst < -TOLERANCE).sum())} cells "
                        f"with a negative response"}
    print(f"{case:12} {label:22} {row['cells']:7} cells, {row['negative_coefficients']:5} negative "
          f"coefficients, {row['cells_outside']:5} cells outside [0, 1] (max {row['max_overshoot']:.3g}), "
          f"{negative} negative responses to {sources} sources", file=sys.stderr)
    return row, picture


def meshes_2d() -> list[tuple[str, Any]]:
    domain = cross_section()
    return [("constrained Delaunay", triangulate(domain)), ("nonobtuse refine", refine(domain).mesh)]


def meshes_3d(part: Path) -> list[tuple[str, Any]]:
    from nonobtuse.mesh3d import load_plc, refine_gabriel, tetrahedralize

    plc = load_plc(part)
    result = refine_gabriel(plc)
    print(f"refine_gabriel({part.name}): {result.status}", file=sys.stderr)
    return [("TetGen -pq1.414", tetrahedralize(plc, "tetgen", switches="pq1.414AQ")),
            (f"refine_gabriel ({result.status})", result.mesh)]


def plot(pictures: list[tuple[str, str, dict[str, Any]]], path: Path) -> None:
    from experiments.plotting import pyplot

    plt = pyplot()
    fig, axes = plt.subplots(len(pictures), 1, figsize=(11, 2.6 * len(pictures)), squeeze=False)
    for ax, (case, label, p) in zip(axes[:, 0], pictures):
        c = p["centers"]
        ax.scatter(c[:, 0], c[:, 1], s=1, color="0.75", linewidths=0)
        if len(p["bad"]):
            sc = ax.scatter(c[p["bad"], 0], c[p["bad"], 1], s=12, c=p["violation"], cmap="Reds", vmin=0,
                            linewidths=0)
            fig.colorbar(sc, ax=ax, label="overshoot / -response")
        ax.set_title(f"{case}, {label}: {p['title']} (x-y view; grey: every cell)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="the 2D section only")
    parser.add_argument("--part", type=Path, default=DEFAULT_PART, help="3D part (default joint.off)")
    add_out_option(parser)
    args = parser.parse_args(argv)
    cases = [("2d section", meshes_2d)]
    if not args.quick:
        cases.append((f"3d {args.part.stem}", lambda: meshes_3d(args.part)))
    rows, pictures = [], []
    with tempfile.TemporaryDirectory() as tmp:
        for case, make in cases:
            for label, mesh in make():
                row, picture = measure(case.replace(" ", "_"), label.split(" (")[0].replace(" ", "_"), mesh,
                                       Path(tmp))
                row["case"], row["mesh"] = case, label
                rows.append(row)
                pictures.append((case, label, picture))
    suffix = "_quick" if args.quick else ""
    out = out_dir(args)
    with open(out / f"fv_maximum_principle{suffix}.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    plot(pictures, out / f"fv_maximum_principle{suffix}.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
