"""``nonobtuse refine IN -o OUT``: nonobtuse boundary refinement of a 2D domain file."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from nonobtuse.cli import guards
from nonobtuse.cli.exit_codes import EXIT_NOT_CONVERGED, EXIT_OK
from nonobtuse.cli.mesh2d import add_domain_options, load
from nonobtuse.domain import Domain
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh import Mesh
from nonobtuse.refinement import MAX_MIN_ANGLE, QUALITY_BOUNDARIES, STRATEGIES, default_steiner_budget

PER_EDGE_KEYS = ("edges", "diagnosis")  # in --json only with --verbose: one entry per input edge


def summary(stats: dict) -> dict:
    """The --json summary without --verbose: ``stats`` without the per-edge keys, but with the diagnosis's
    ``stop_reason`` (as ``{"diagnosis": {"stop_reason": ...}}``, where refine3d's JSON has it)."""
    out = {k: v for k, v in stats.items() if k not in PER_EDGE_KEYS}
    out["diagnosis"] = {"stop_reason": stats["diagnosis"]["stop_reason"]}
    return out


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser(
        "refine",
        help="add the fewest Steiner points on boundary edges so that every boundary triangle is nonobtuse",
        description="Refine the boundary of a 2D domain (.poly, .node, CG:SHOP or domain .json) and write "
        "the constrained Delaunay mesh (.json mesh schema, .node/.ele/.poly, .vtu, .msh) or simulator input "
        "(.uge, .stor, MESH, .csv, .npz; see `nonobtuse export`). Exit code 3 when "
        "refinement did not converge (budget spent, or stalled): the partial mesh is still written.",
    )
    p.add_argument("input", help="domain file")
    p.add_argument("-o", "--output", required=True,
                   help="mesh file or simulator input; the format follows the name")
    p.add_argument("--thickness", type=float, default=1.0,
                   help="simulator input: extrusion thickness (default 1)")
    p.add_argument("--strategy", choices=STRATEGIES, default="greedy", help="default: greedy")
    b0, b1 = default_steiner_budget(0), default_steiner_budget(1)  # the core's rule, affine in n
    p.add_argument("--max-steiner", type=guards.count, default=None,
                   help=f"Steiner budget (default: {b1 - b0} n + {b0} for n input points)")
    p.add_argument("--threads", type=int, default=2,
                   help="threads for the whole-mesh passes of large inputs (default 2; same output)")
    add_quality_options(p)
    p.add_argument("--json", action="store_true", help="print the summary statistics as JSON on stdout")
    p.add_argument("--verbose", action="store_true", help="with --json: also the per-edge statistics and "
                   "the diagnosis (one entry per input edge: large on big inputs)")
    guards.add_quiet_option(p)
    guards.add_timings_option(p)
    guards.add_plot_options(p, "the constrained Delaunay triangulation before and the mesh after refinement")
    add_domain_options(p)
    p.set_defaults(func=run)


def region_area(text: str) -> tuple[float, float]:
    """An argparse type: ``ATTRIBUTE=AREA`` (a region attribute and its largest triangle area)."""
    attribute, sep, area = text.partition("=")
    try:
        pair = float(attribute), guards.positive(area)
    except (ValueError, argparse.ArgumentTypeError):
        pair = None
    if not sep or pair is None or pair[0] != pair[0]:
        raise argparse.ArgumentTypeError(f"expected ATTRIBUTE=AREA with a positive AREA, found {text!r}")
    return pair


def add_quality_options(p: argparse.ArgumentParser) -> None:
    """Interior quality and size (Triangle's -q and -a; off by default: the paper's minimal mode)."""
    g = p.add_argument_group("interior quality (off by default; the boundary stays certified)")
    g.add_argument("--min-angle", type=guards.positive, default=None, metavar="DEG",
                   help=f"refine triangles with an angle below DEG degrees (at most {MAX_MIN_ANGLE:g}; "
                   "Triangle's -q; skinny triangles at input angles below 60 degrees are left alone)")
    g.add_argument("--max-area", type=guards.positive, default=None, metavar="A",
                   help="refine triangles larger than A (Triangle's -a A)")
    g.add_argument("--region-area", type=region_area, action="append", default=None, metavar="ATTR=A",
                   help="refine triangles of the region with attribute ATTR larger than A (repeatable)")
    g.add_argument("--region-areas", action="store_true",
                   help="refine triangles larger than their region's maximum area in the .poly region list "
                   "(Triangle's -a without a number)")
    g.add_argument("--max-interior", type=guards.count, default=None, metavar="N",
                   help="interior point budget (default 10 n + 100000 + 4 area / smallest area limit)")
    g.add_argument("--quality-boundary", choices=QUALITY_BOUNDARIES, default="best",
                   help="greedy strategy: Triangle's midpoints, the minimal boundary first, or the better of "
                   "the two (default best: two runs, about twice the time)")


def _size(args: argparse.Namespace) -> dict[float, float] | str | None:
    """refine's ``size``: the --region-area pairs, or "regions" for --region-areas (both: refused)."""
    if args.region_areas and args.region_area:
        raise InvalidInputError("--region-areas and --region-area exclude each other")
    return "regions" if args.region_areas else dict(args.region_area) if args.region_area else None


def run(args: argparse.Namespace) -> int:
    from nonobtuse.cli.export import write_output
    from nonobtuse.io import mesh_output_paths
    from nonobtuse.refinement import refine

    domain = load(args)
    plots = [Path(args.plot)] if args.plot else []
    guards.refuse_overwriting(guards.files_read(args.input, domain), mesh_output_paths(args.output) + plots)
    progress = guards.Progress(quiet=args.quiet, size=len(domain.points))
    progress.start(f"refining {len(domain.points)} points, {len(domain.segments)} segments ({args.strategy})")
    result = refine(domain, strategy=args.strategy, max_steiner=args.max_steiner, threads=args.threads,
                    min_angle=args.min_angle, max_area=args.max_area,
                    size=_size(args), max_interior=args.max_interior, quality_boundary=args.quality_boundary)
    progress.done(f"{result.status}, {result.stats['steiner_points']} Steiner points; writing {args.output}")
    write_output(guards.without_timings(result.mesh, args.timings), args.output, thickness=args.thickness,
                 quiet=args.quiet)
    s = result.stats
    if args.json:
        json.dump(s if args.verbose else summary(s), sys.stdout,
                  default=list)  # stats["edges"] is a sequence made on access
        print()
    elif not args.quiet:
        print(
            f"{args.input}: {s['status']} ({s['diagnosis']['stop_reason']}), {s['steiner_points']} Steiner "
            f"points ({args.strategy}), lower bound {s['lower_bound']}, optimal {s['optimal']}, "
            f"{s['seconds']:.3f} s -> {args.output}"
        )
        if s["quality"] is not None:
            q = s["quality"]
            print(f"  interior: {q['interior_points']} points ({q['boundary_splits']} of the boundary points "
                  f"for them), {q['triangles']} triangles, smallest angle "
                  f"{q['min_angle_outside_small_angles_degrees']:.2f} deg outside small input angles "
                  f"({q['small_angle_triangles']} triangles left there, {q['bad_triangles']} bad elsewhere)")
    if args.plot:
        _plot(domain, result.mesh, args)
    return EXIT_OK if result.converged else EXIT_NOT_CONVERGED


def _plot(domain: Domain, refined: Mesh, args: argparse.Namespace) -> None:
    """The before/after picture: the constrained Delaunay triangulation of ``domain`` and ``refined``."""
    from nonobtuse.certificate import check
    from nonobtuse.plot import plot_stages
    from nonobtuse.triangulation import triangulate

    before = triangulate(domain)
    plot_stages([("before", before, check(before)), ("after refine", refined, check(refined))], args.plot,
                vertical_exaggeration=args.exaggeration, title=Path(args.input).name)
    if not args.quiet:
        print(f"picture -> {args.plot}", file=sys.stderr)
