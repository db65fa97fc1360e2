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

from nonobtuse.cli import guards
from nonobtuse.cli.exit_codes import EXIT_NOT_CONVERGED, EXIT_OK, EXIT_VIOLATIONS
from nonobtuse.errors import InvalidInputError
from nonobtuse.io import jsonable


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("check3d", help="tetrahedralize a 3D input and check its boundary facets and segments "
                                       "for encroachment (exact); report control-volume coefficients")
    p.add_argument("input", help=".off .obj .ply .stl .poly .smesh")
    p.add_argument("--backend", choices=("cgal", "tetgen", "ftetwild"), default="cgal")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    p.set_defaults(func=run_check3d)

    p = sub.add_parser("refine3d", help="refine the boundary of a 3D input until every boundary facet and "
                                        "segment has an empty diametral sphere; write the tet mesh")
    p.add_argument("input", help=".off .obj .ply .stl .poly .smesh")
    p.add_argument("-o", "--output", required=True, help="output mesh (.json, .vtu, .msh) or simulator input "
                   "(.uge, .stor, MESH, .csv, .npz; see `nonobtuse export`)")
    p.add_argument("--max-steiner", type=guards.count, default=None,
                   help="Steiner point budget (default: refine_gabriel's)")
    p.add_argument("--min-length", type=guards.non_negative, default=None,
                   help="no split may create an edge shorter than this (default: refine_gabriel's)")
    p.add_argument("--time-limit", type=guards.non_negative, default=None,
                   help="seconds for loading, refinement and the exact check of the result (default: "
                        "refine_gabriel's); the final Delaunay tetrahedralization, the control volumes and "
                        "the writing (near-linear in the output) come on top")
    p.add_argument("--split", choices=("shells", "midpoint", "greedy", "protected"), default="shells",
                   help="how encroached subsegments are split (see refine_gabriel)")
    p.add_argument("--max-volume", type=guards.positive, default=None,
                   help="largest tet volume (TetGen's -a): interior points are added, never in a boundary "
                        "diametral sphere (see refine_quality3d)")
    p.add_argument("--region-max-volume", type=_region_volume, action="append", default=None,
                   metavar="ATTR=V", help="largest tet volume in the region with attribute ATTR (repeatable)")
    p.add_argument("--radius-edge", type=guards.positive, default=None,
                   help="largest circumradius / shortest edge of a tet, > 1 (TetGen's -q, e.g. 2.0)")
    p.add_argument("--quality-start", choices=("tetgen", "boundary"), default="tetgen",
                   help="with a bound: let TetGen split the facets and seed interior points first (default), "
                        "or start from the input boundary alone (TetGen has no time limit; see "
                        "refine_quality3d)")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    guards.add_timings_option(p)
    p.set_defaults(func=run_refine3d)


def _region_volume(text: str) -> tuple[float, float]:
    """An argparse type: ATTR=V, a region attribute and a volume bound > 0."""
    attr, sep, volume = text.partition("=")
    try:
        return float(attr), guards.positive(volume)
    except (ValueError, argparse.ArgumentTypeError):
        raise argparse.ArgumentTypeError(f"expected ATTR=V (a region attribute and a volume > 0), found "
                                         f"{text!r}") from None


def _finite_or_none(x: Any) -> Any:
    """``x`` with every float that is NaN or infinite replaced by None (JSON has no such numbers)."""
    if isinstance(x, float):
        return x if math.isfinite(x) else None
    if isinstance(x, dict):
        return {k: _finite_or_none(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_finite_or_none(v) for v in x]
    return x


def _print(summary: dict[str, Any], as_json: bool) -> None:
    if as_json:
        print(json.dumps(_finite_or_none(jsonable(summary)), allow_nan=False))
    else:
        for k, v in summary.items():
            print(f"{k}: {v}")


def run_check3d(args: argparse.Namespace) -> int:
    from nonobtuse.mesh3d import boundary_certificate, load_plc, tetrahedralize

    plc = load_plc(args.input)
    summary = {"input": args.input, "backend": args.backend,
               **boundary_certificate(tetrahedralize(plc, args.backend))}
    _print(summary, args.json)
    gabriel = summary["encroached_facets"] == 0 and summary["encroached_segments"] == 0
    return EXIT_OK if gabriel else EXIT_VIOLATIONS


def run_refine3d(args: argparse.Namespace) -> int:
    from nonobtuse.cli.export import write_output
    from nonobtuse.mesh3d import load_plc, refine_gabriel

    t0 = time.perf_counter()
    guards.refuse_overwriting(_files_read(args.input), [Path(args.output)])
    if args.region_max_volume and args.max_volume is not None:
        raise InvalidInputError("give --max-volume or --region-max-volume, not both")
    plc = load_plc(args.input)
    limits = {k: v for k, v in (("max_steiner", args.max_steiner), ("min_length", args.min_length),
                                  ("time_limit", args.time_limit)) if v is not None}
    print(f"refine3d: {args.input}: {len(plc.points)} points, {len(plc.triangles)} triangles; refining "
          f"({', '.join(f'{k}={v}' for k, v in limits.items()) or 'default limits'})", file=sys.stderr)
    # started=t0: --time-limit and stats["seconds"] cover loading too
    if args.max_volume is not None or args.radius_edge is not None or args.region_max_volume:
        from nonobtuse.mesh3d.quality3d import refine_quality3d

        volume = dict(args.region_max_volume) if args.region_max_volume else args.max_volume
        result: Any = refine_quality3d(plc, max_volume=volume, radius_edge=args.radius_edge,
                                       start=args.quality_start, split=args.split, progress=True,
                                       started=t0, **limits)
    else:
        result = refine_gabriel(plc, split=args.split, progress=True, started=t0, **limits)
    # The certificate is refine_gabriel's (or refine_quality3d's) exact check of result.mesh, the arrays
    # written below unchanged (float64 coordinates, written exactly); it ran within the time limit, and rows
    # it did not reach make the status budget_exhausted. A second, unbounded check here would break
    # --time-limit.
    stats = result.stats
    written = dict(stats)
    if not args.timings:  # the file is then the same for the same input and options
        written["seconds"] = None
        if "boundary_repair" in written:  # refine_quality3d's first repair
            written["boundary_repair"] = {**written["boundary_repair"], "seconds": None}
    write_output(replace(result.mesh, stats=written), args.output)
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
