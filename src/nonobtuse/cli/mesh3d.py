"""3D subcommands: check3d (tetrahedralize with a backend, exact Gabriel check of the boundary, control
volumes) and refine3d (Gabriel refinement of the boundary; writes the mesh)."""

from __future__ import annotations

import argparse
import json
import sys
import time
from dataclasses import replace
from typing import Any

from nonobtuse.cli.exit_codes import EXIT_NOT_CONVERGED, EXIT_OK, EXIT_VIOLATIONS
from nonobtuse.io._files import jsonable


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
    p.add_argument("--max-steiner", type=int, default=None,
                   help="Steiner point budget (default: refine_gabriel's)")
    p.add_argument("--min-length", type=float, default=None,
                   help="no split may create an edge shorter than this (default: refine_gabriel's)")
    p.add_argument("--time-limit", type=float, default=None,
                   help="seconds for loading, refinement and the exact check of the result (default: "
                        "refine_gabriel's); the final Delaunay tetrahedralization, the control volumes and "
                        "the writing (near-linear in the output) come on top")
    p.add_argument("--split", choices=("shells", "midpoint", "greedy", "protected"), default="shells",
                   help="how encroached subsegments are split (see refine_gabriel)")
    p.add_argument("--fix-orientation", action="store_true", help="reorient inconsistently oriented faces")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    p.set_defaults(func=run_refine3d)


def _print(summary: dict[str, Any], as_json: bool) -> None:
    if as_json:
        print(json.dumps(jsonable(summary)))
    else:
        for k, v in summary.items():
            print(f"{k}: {v}")


def run_check3d(args: argparse.Namespace) -> int:
    from nonobtuse.mesh3d import check_gabriel, control_volumes3d, load_plc, tetrahedralize

    plc = load_plc(args.input, fix_orientation=args.fix_orientation)
    mesh = tetrahedralize(plc, args.backend)
    report = check_gabriel(mesh)
    facets, segments = len(report.faces), len(report.segments)
    summary = {"input": args.input, "backend": args.backend, "points": len(mesh.points),
               "tets": len(mesh.tets),
               "boundary_faces": len(mesh.boundary_faces), "steiner_points": mesh.stats["steiner_points"],
               "encroached_facets": facets, "encroached_segments": segments,
               "gabriel": report.to_dict(), "control_volumes": control_volumes3d(mesh).to_dict()}
    _print(summary, args.json)
    return EXIT_OK if facets == 0 and segments == 0 else EXIT_VIOLATIONS


def run_refine3d(args: argparse.Namespace) -> int:
    from nonobtuse.mesh3d import control_volumes3d, load_plc, refine_gabriel, write_tetmesh

    t0 = time.perf_counter()
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
             "negative_couplings": control_volumes3d(result.mesh).negative_couplings}
    write_tetmesh(replace(result.mesh, stats={**result.mesh.stats, **stats}), args.output)
    print(f"refine3d: {result.status} after {stats['seconds']:.2f} s; wrote {args.output}", file=sys.stderr)
    _print({"input": args.input, "output": args.output, **stats}, args.json)
    return EXIT_OK if result.status == "converged" else EXIT_NOT_CONVERGED
