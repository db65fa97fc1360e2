"""2D subcommands: triangulate, check, demo."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from nonobtuse import demo
from nonobtuse.certificate import check
from nonobtuse.cli import guards
from nonobtuse.cli.exit_codes import EXIT_OK, EXIT_VIOLATIONS
from nonobtuse.domain import Domain
from nonobtuse.io import is_mesh_file, load_domain, mesh_output_paths, read_mesh, write_mesh
from nonobtuse.triangulation import triangulate
from nonobtuse.validate import require_points_in_domain


def load(args: argparse.Namespace) -> Domain:
    """The domain file ``args.input``, closed by the convex hull when ``--convex-hull`` was given."""
    return load_domain(args.input, convex_hull=True if args.convex_hull else None)


def add_domain_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--convex-hull", action="store_true", help="close the domain with the convex hull of its "
                   "points (Triangle -c), for an open boundary")


def _triangulate(args: argparse.Namespace) -> int:
    domain = load(args)
    guards.refuse_overwriting(guards.files_read(args.input, domain), mesh_output_paths(args.output))
    mesh = triangulate(domain)
    require_points_in_domain(domain, mesh.triangles)
    write_mesh(mesh, args.output)
    print(f"{args.input}: {len(mesh.points)} points, {len(mesh.triangles)} triangles -> {args.output}")
    return EXIT_OK


def _check(args: argparse.Namespace) -> int:
    path = Path(args.input)
    if args.plot:
        guards.refuse_overwriting([path], [Path(args.plot)])
    if is_mesh_file(path):
        mesh = read_mesh(path)
    else:
        domain = load(args)
        mesh = triangulate(domain)
        require_points_in_domain(domain, mesh.triangles)
    progress = guards.Progress(quiet=args.quiet, size=len(mesh.points))
    progress.start(f"checking {len(mesh.points):,} points, {len(mesh.triangles):,} triangles exactly")
    report = check(mesh)
    progress.done(f"{len(report.offenders):,} obtuse boundary/interface angles")
    report.source = str(path)
    if args.json:
        print(json.dumps(report.to_dict(), indent=1))
    elif not args.quiet:
        print(report.summary())
    if args.plot:
        from nonobtuse.plot import plot_check  # matplotlib only when asked

        progress.start(f"drawing {args.plot}")
        plot_check(mesh, report, args.plot, vertical_exaggeration=args.exaggeration)
        progress.done("drawn")
        if not args.quiet:
            print(f"picture -> {args.plot}", file=sys.stderr)
    return EXIT_OK if report.ok else EXIT_VIOLATIONS


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("triangulate", help="constrained Delaunay triangulation, no Steiner points")
    p.add_argument("input", help="domain: .poly, .node, CG:SHOP .json, domain .json")
    p.add_argument("-o", "--output", required=True, help="mesh file: .json, .node/.ele/.poly, .vtu, .msh")
    add_domain_options(p)
    p.set_defaults(func=_triangulate)

    p = sub.add_parser("check", help="exact check: is every boundary and interface angle nonobtuse? "
                       "(exit 0 yes, 1 no, 2 invalid input)")
    p.add_argument("input", help="a mesh file, checked as is (.json, .vtu, .msh, .ele, or a .node/.poly "
                   "with its .ele beside it: Triangle's triangles are read, not recomputed), or a domain "
                   "file (its constrained Delaunay triangulation is checked)")
    p.add_argument("--json", action="store_true", help="print the full report as JSON")
    add_domain_options(p)
    guards.add_plot_options(p, "the mesh")
    guards.add_quiet_option(p)
    p.set_defaults(func=_check)

    p = sub.add_parser("demo", help="run on a built-in thin-layer geological cross-section (2D) and a small "
                       "CAD part (3D)")
    p.add_argument("--plot", metavar="PNG", help="also draw the cross-section before and after refinement "
                   f"(vertical exaggeration x{demo.EXAGGERATION:g}, labelled; close-ups at true scale), and "
                   "the 3D part before and after repair beside it (PNG's name with _3d)")
    p.set_defaults(func=_demo)


def _demo(args: argparse.Namespace) -> int:
    if args.plot:
        guards.refuse_overwriting([demo.PART], [Path(args.plot), demo.part_picture_path(args.plot)])
    return demo.run(plot=args.plot)
