"""``nonobtuse refine IN -o OUT``: nonobtuse boundary refinement of a 2D domain file."""

from __future__ import annotations

import argparse
import json
import sys

from nonobtuse.cli.exit_codes import EXIT_NOT_CONVERGED, EXIT_OK
from nonobtuse.refine import STRATEGIES


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
    p.add_argument("--max-steiner", type=int, default=None, help="Steiner budget (default: 10 n + 1000)")
    p.add_argument("--threads", type=int, default=2,
                   help="threads for the whole-mesh passes of large inputs (default 2; same output)")
    p.add_argument("--json", action="store_true", help="print the statistics as JSON on stdout")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from nonobtuse.cli.export import write_output
    from nonobtuse.io import load_domain
    from nonobtuse.refine import refine

    result = refine(load_domain(args.input), strategy=args.strategy, max_steiner=args.max_steiner,
                    threads=args.threads)
    write_output(result.mesh, args.output, thickness=args.thickness)
    s = result.stats
    if args.json:
        json.dump(s, sys.stdout)
        print()
    else:
        print(
            f"{args.input}: {s['status']}, {s['steiner_points']} Steiner points ({args.strategy}), "
            f"lower bound {s['lower_bound']}, optimal {s['optimal']}, {s['seconds']:.3f} s -> {args.output}"
        )
    return EXIT_OK if result.converged else EXIT_NOT_CONVERGED
