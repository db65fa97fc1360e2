"""3D subcommands: check3d (tetrahedralize with a backend, exact Gabriel check of the boundary, control
volumes) and refine3d (Gabriel refinement of the boundary; writes the mesh)."""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from nonobtuse.cli import guards
from nonobtuse.cli.exit_codes import EXIT_NOT_CONVERGED, EXIT_OK, EXIT_VIOLATIONS
from nonobtuse.io._files import jsonable
from nonobtuse.mesh3d.gabriel import power_of_two_exponent
from nonobtuse.mesh3d.plc import TetMesh


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("check3d", help="tetrahedralize a 3D input and check its boundary facets and segments "
                                       "for encroachment (exact); report control-volume coefficients")
    p.add_argument("input", help=".off .obj .ply .stl .poly .smesh")
    p.add_argument("--backend", choices=("cgal", "tetgen", "ftetwild"), default="cgal")
    p.add_argument("--fix-orientation", action="store_true", help="reorient inconsistently oriented faces")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    p.set_defaults(func=run_check3d)

    p = sub.add_parser("refine3d", help="refine the boundary of a 3D input until every boundary facet and "
                                        "segment has an empty diametral sphere; write the tet mesh")
    p.add_argument("input", help=".off .obj .ply .stl .poly .smesh")
    p.add_argument("-o", "--output", required=True, help="output mesh: .json, .vtu or .msh")
    p.add_argument("--max-steiner", type=guards.count, default=None,
                   help="Steiner point budget (default: refine_gabriel's)")
    p.add_argument("--min-length", type=guards.non_negative, default=None,
                   help="no split may create an edge shorter than this (default: refine_gabriel's)")
    p.add_argument("--time-limit", type=guards.non_negative, default=None,
                   help="seconds for loading, refinement and the exact check of the result (default: "
                        "refine_gabriel's); the final Delaunay tetrahedralization, the control volumes and "
                        "the writing (near-linear in the output) come on top")
    p.add_argument("--split", choices=("shells", "midpoint", "greedy"), default="shells",
                   help="how encroached subsegments are split (see refine_gabriel)")
    p.add_argument("--fix-orientation", action="store_true", help="reorient inconsistently oriented faces")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    guards.add_timings_option(p)
    p.set_defaults(func=run_refine3d)


def _finite_or_none(x: Any) -> Any:
    """``x`` with every float that is NaN or infinite replaced by None (JSON has no such numbers)."""
    if isinstance(x, float):
        return x if math.isfinite(x) else None
    if isinstance(x, dict):
        return {k: _finite_or_none(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_finite_or_none(v) for v in x]
    return x


def _ldexp_or_none(x: float | None, k: int) -> float | None:
    """x * 2^k, or None when x is None, not finite, or the product over- or underflows."""
    if x is None or not math.isfinite(x):
        return None
    try:
        y = math.ldexp(x, k)
    except OverflowError:
        return None
    return y if y != 0 or x == 0 else None


def control_volume_summary(mesh: TetMesh) -> dict[str, Any]:
    """The control-volume summary of ``mesh`` (:meth:`ControlVolumes3D.to_dict`), computed on the points
    scaled exactly by a power of two into a safe range and scaled back (None where the value overflows
    float64). ``flat_in_floating_point``: tets whose volume is positive (exact orientation) but 0 in floating
    point; their circumcentres cannot be computed, so min_coupling and total_volume are then None when not
    finite, and negative_couplings counts the other edges only."""
    from nonobtuse.mesh3d.control_volumes3d import control_volumes3d, signed_tet_volumes

    e = power_of_two_exponent(mesh.points)
    scaled = replace(mesh, points=np.ldexp(np.asarray(mesh.points, dtype=np.float64), -e))
    with np.errstate(all="ignore"):  # flat tets give NaN, counted below
        summary = control_volumes3d(scaled).to_dict()
        flat = int((signed_tet_volumes(scaled.points, np.asarray(scaled.tets).reshape(-1, 4)) == 0).sum())
    summary["min_coupling"] = _ldexp_or_none(summary["min_coupling"], e)
    summary["total_volume"] = _ldexp_or_none(summary["total_volume"], 3 * e)
    summary["flat_in_floating_point"] = flat
    return summary


def _print(summary: dict[str, Any], as_json: bool) -> None:
    if as_json:
        print(json.dumps(_finite_or_none(jsonable(summary)), allow_nan=False))
    else:
        for k, v in summary.items():
            print(f"{k}: {v}")


def run_check3d(args: argparse.Namespace) -> int:
    from nonobtuse.mesh3d import check_gabriel, load_plc, tetrahedralize

    plc = load_plc(args.input, fix_orientation=args.fix_orientation)
    mesh = tetrahedralize(plc, args.backend)
    report = check_gabriel(mesh)
    facets, segments = len(report.faces), len(report.segments)
    summary = {"input": args.input, "backend": args.backend, "points": len(mesh.points),
               "tets": len(mesh.tets),
               "boundary_faces": len(mesh.boundary_faces), "steiner_points": mesh.stats["steiner_points"],
               "encroached_facets": facets, "encroached_segments": segments,
               "gabriel": report.to_dict(), "control_volumes": control_volume_summary(mesh)}
    _print(summary, args.json)
    return EXIT_OK if facets == 0 and segments == 0 else EXIT_VIOLATIONS


def run_refine3d(args: argparse.Namespace) -> int:
    from nonobtuse.mesh3d import load_plc, refine_gabriel, write_tetmesh

    t0 = time.perf_counter()
    guards.refuse_overwriting(_files_read(args.input), [Path(args.output)])
    plc = load_plc(args.input, fix_orientation=args.fix_orientation)
    limits = {k: v for k, v in (("max_steiner", args.max_steiner), ("min_length", args.min_length),
                                  ("time_limit", args.time_limit)) if v is not None}
    print(f"refine3d: {args.input}: {len(plc.points)} points, {len(plc.triangles)} triangles; refining "
          f"({', '.join(f'{k}={v}' for k, v in limits.items()) or 'default limits'})", file=sys.stderr)
    if args.time_limit is not None:  # --time-limit covers loading too
        limits["time_limit"] = max(0.0, args.time_limit - (time.perf_counter() - t0))
    result = refine_gabriel(plc, split=args.split, progress=True, **limits)
    # The certificate is refine_gabriel's exact check of result.mesh, the arrays written below unchanged
    # (float64 coordinates, written exactly); it ran within the time limit, and rows it did not reach make the
    # status budget_exhausted. A second, unbounded check here would break --time-limit.
    stats = {**result.stats, "seconds": time.perf_counter() - t0,
             "negative_couplings": control_volume_summary(result.mesh)["negative_couplings"]}
    written = {**result.mesh.stats, **stats}
    if not args.timings:  # the file is then the same for the same input and options
        written["seconds"] = None
    write_tetmesh(replace(result.mesh, stats=written), args.output)
    print(f"refine3d: {result.status} after {stats['seconds']:.2f} s; wrote {args.output}", file=sys.stderr)
    _print({"input": args.input, "output": args.output, **_unchecked_as_unknown(stats)}, args.json)
    return EXIT_OK if result.status == "converged" else EXIT_NOT_CONVERGED


def _files_read(path: str) -> list[Path]:
    """The input file, and for a TetGen .poly/.smesh the .node file beside it (read when the file lists no
    nodes; counted as read whenever it exists)."""
    p = Path(path)
    node = p.with_suffix(".node")
    return [p] + ([node] if p.suffix.lower() in (".poly", ".smesh") and node.exists() else [])


def _unchecked_as_unknown(stats: dict[str, Any]) -> dict[str, Any]:
    """``stats`` with the encroachment counts of a certificate that did not reach every row (time limit) shown
    as ``"unknown: N unchecked"``: an unchecked face is not a Gabriel face."""
    out = dict(stats)
    for kind, rows in (("facets", "faces"), ("segments", "segments")):
        unchecked = stats.get(f"unchecked_{rows}", 0)
        if unchecked:
            found = stats[f"encroached_{kind}"]
            out[f"encroached_{kind}"] = f"at least {found}, {unchecked} {rows} unchecked"
    return out
