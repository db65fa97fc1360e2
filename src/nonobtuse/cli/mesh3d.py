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
from typing import TYPE_CHECKING, Any, Callable

from nonobtuse.cli import guards
from nonobtuse.cli.exit_codes import EXIT_NOT_CONVERGED, EXIT_OK, EXIT_VIOLATIONS
from nonobtuse.errors import InvalidInputError
from nonobtuse.io import jsonable

if TYPE_CHECKING:  # the 3D modules are imported when a command runs
    from nonobtuse.mesh3d import PLC, Gabriel3DResult
    from nonobtuse.plot3d import Stage


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("check3d", help="tetrahedralize a 3D input and check its boundary facets and segments "
                                       "for encroachment (exact); report control-volume coefficients")
    p.add_argument("input", help=".off .obj .ply .stl .poly .smesh")
    p.add_argument("--backend", choices=("cgal", "tetgen", "ftetwild"), default="cgal")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    _add_picture_options(p, "the boundary")
    guards.add_quiet_option(p)
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
    p.add_argument("--region-volumes", action="store_true",
                   help="the volume constraints of the .poly region list (the fifth number of a region line; "
                        "TetGen's -a without a number) hold too; the smallest bound that applies wins")
    p.add_argument("--radius-edge", type=guards.positive, default=None,
                   help="largest circumradius / shortest edge of a tet, > 1 (TetGen's -q, e.g. 2.0)")
    p.add_argument("--quality-start", choices=("boundary", "tetgen"), default="boundary",
                   help="with a bound: start from the input boundary alone (default), or let TetGen split "
                        "the facets and seed interior points first (TetGen has no time limit; see "
                        "refine_quality3d)")
    p.add_argument("--json", action="store_true", help="print one JSON object instead of text")
    guards.add_timings_option(p)
    _add_picture_options(p, "the boundary before (the input tetrahedralized by TetGen when installed, else "
                            "the cgal backend) and after refinement")
    guards.add_quiet_option(p)
    p.set_defaults(func=run_refine3d)


def _add_picture_options(p: argparse.ArgumentParser, what: str) -> None:
    p.add_argument("--plot", metavar="PNG", help=f"also draw {what}: non-Gabriel faces and encroached "
                   "subsegments in red, the encroaching vertices, Steiner points in blue, and a close-up of "
                   "the worst offender with its diametral sphere")
    p.add_argument("--offenders", metavar="VTU", help="also write the non-Gabriel boundary faces, encroached "
                   "subsegments and encroaching vertices as a .vtu for ParaView (cell data: row, facet, "
                   "marker, vertex, depth)")


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


def _print(summary: dict[str, Any], args: argparse.Namespace, text: Callable[[], str]) -> None:
    """``summary`` as JSON with --json, else ``text()``; nothing with --quiet."""
    if args.json:
        print(json.dumps(_finite_or_none(jsonable(summary)), allow_nan=False))
    elif not args.quiet:
        print(text())


def _picture_outputs(args: argparse.Namespace) -> list[Path]:
    return [Path(p) for p in (args.plot, args.offenders) if p]


def keep_freed_memory() -> bool:
    """Ask glibc's malloc to keep freed memory for reuse instead of handing it back to the kernel: no
    ``mmap`` per large block (numpy arrays, CGAL's cell blocks) and no trimming of the heap. check3d
    allocates and frees arrays of hundreds of MB one after the other, and every fresh mapping is page-faulted
    and zeroed again by the kernel: on the 1e6-face torus of ``bench_gabriel3d`` that was 7.2 of 54 CPU
    seconds (system time), 2.0 with this, at the same peak memory (1.13 GB). Results do not change. True
    when set; False (nothing done) on a C library without ``mallopt`` (not glibc)."""
    import ctypes

    m_trim_threshold, m_mmap_max = -1, -4  # glibc's malloc.h
    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (OSError, AttributeError):
        return False
    return bool(mallopt(m_mmap_max, 0)) and bool(mallopt(m_trim_threshold, 2**31 - 1))


def run_check3d(args: argparse.Namespace) -> int:
    from nonobtuse.cli.text3d import check3d_text
    from nonobtuse.mesh3d import boundary_certificate, check_gabriel, load_plc, tetrahedralize

    guards.refuse_overwriting(_files_read(args.input), _picture_outputs(args))
    keep_freed_memory()  # for the rest of the process (a command line run: it ends with it)
    plc = load_plc(args.input)
    progress = guards.Progress(quiet=args.quiet, size=len(plc.triangles), min_size=CHECK3D_PROGRESS_FACES)
    progress.start(f"tetrahedralizing {len(plc.points):,} points, {len(plc.triangles):,} triangles "
                   f"({args.backend})")
    mesh = tetrahedralize(plc, args.backend)
    progress.done(f"{len(mesh.tets):,} tets; checking {len(mesh.boundary_faces):,} boundary faces exactly")
    report = check_gabriel(mesh)  # the one exact check: the summary and the pictures read it
    summary = {"input": args.input, "backend": args.backend, **boundary_certificate(mesh, report)}
    _print(summary, args, lambda: check3d_text(summary))
    if args.plot or args.offenders:
        _pictures(args, [("mesh", mesh, report)])
    gabriel = summary["encroached_facets"] == 0 and summary["encroached_segments"] == 0
    return EXIT_OK if gabriel else EXIT_VIOLATIONS


CHECK3D_PROGRESS_FACES = 10_000  # below this check3d takes about a second: no progress lines


def _pictures(args: argparse.Namespace, stages: list[Stage]) -> None:
    """--plot (every stage) and --offenders (the last stage's offenders), with a line on stderr for each."""
    if args.plot:
        from nonobtuse.plot3d import plot_gabriel_stages  # matplotlib only when asked

        plot_gabriel_stages(stages, args.plot, title=Path(args.input).name)
        _say(args, f"picture -> {args.plot}")
    if args.offenders:
        from nonobtuse.mesh3d.offenders import write_offenders

        _, mesh, report = stages[-1]
        cells = write_offenders(mesh, report, args.offenders)
        _say(args, f"offenders ({cells:,} cells) -> {args.offenders}" if cells else
             f"no offenders (Gabriel): {args.offenders} not written")


def _say(args: argparse.Namespace, line: str) -> None:
    if not args.quiet:
        print(line, file=sys.stderr)


def run_refine3d(args: argparse.Namespace) -> int:
    from nonobtuse.cli.export import write_output
    from nonobtuse.cli.text3d import refine3d_text
    from nonobtuse.mesh3d import load_plc, refine_gabriel

    t0 = time.perf_counter()
    guards.refuse_overwriting(_files_read(args.input), [Path(args.output)] + _picture_outputs(args))
    if args.region_max_volume and args.max_volume is not None:
        raise InvalidInputError("give --max-volume or --region-max-volume, not both")
    plc = load_plc(args.input)
    limits = {k: v for k, v in (("max_steiner", args.max_steiner), ("min_length", args.min_length),
                                  ("time_limit", args.time_limit)) if v is not None}
    progress = guards.Progress(quiet=args.quiet, size=len(plc.points), min_size=0)  # long from a few points
    progress.start(f"refining {args.input}: {len(plc.points):,} points, {len(plc.triangles):,} triangles "
                   f"({', '.join(f'{k}={v}' for k, v in limits.items()) or 'default limits'})")
    # started=t0: --time-limit and stats["seconds"] cover loading too
    if args.max_volume is not None or args.radius_edge is not None or args.region_max_volume or \
            args.region_volumes:
        from nonobtuse.mesh3d.quality3d import refine_quality3d

        volume = dict(args.region_max_volume) if args.region_max_volume else args.max_volume
        result: Any = refine_quality3d(plc, max_volume=volume, radius_edge=args.radius_edge,
                                       start=args.quality_start, region_volumes=args.region_volumes,
                                       split=args.split,
                                       progress=progress.active or None, started=t0, **limits)
    else:
        result = refine_gabriel(plc, split=args.split, progress=progress.active or None, started=t0, **limits)
    progress.done(f"{result.status}; writing {args.output}")
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
    write_output(replace(result.mesh, stats=written), args.output, quiet=args.quiet)
    shown = _unchecked_as_unknown(stats)
    _print({"input": args.input, "output": args.output, **shown}, args,
           lambda: refine3d_text(shown, args.input, args.output))
    if args.plot or args.offenders:
        _pictures(args, _refine3d_stages(plc, result))
    return EXIT_OK if result.status == "converged" else EXIT_NOT_CONVERGED


def _refine3d_stages(plc: PLC, result: Gabriel3DResult) -> list[Stage]:
    """(label, mesh, report) before (:func:`nonobtuse.plot3d.unrepaired_mesh`) and after."""
    from nonobtuse.mesh3d import check_gabriel
    from nonobtuse.plot3d import unrepaired_mesh

    before, how = unrepaired_mesh(plc)
    after = result.report or check_gabriel(result.mesh)  # refine_gabriel's certificate of its mesh
    return [(f"before ({how.split(' (')[0]})", before, check_gabriel(before)),
            ("after refine3d", result.mesh, after)]


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
