"""``nonobtuse export MESH -o OUT``: simulator input from a 2D or 3D mesh; and the output step of ``refine``
and ``refine3d`` (:func:`write_output`), the one place that decides between a simulator export and a mesh
file."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from nonobtuse.cli import guards
from nonobtuse.cli.exit_codes import EXIT_OK, EXIT_VIOLATIONS
from nonobtuse.errors import InvalidInputError
from nonobtuse.io.cv_grid import AnyMesh, ControlVolumeGrid
from nonobtuse.io.export import export_mesh, is_export_path
from nonobtuse.mesh3d.plc import TetMesh

FORMATS_HELP = (".uge (PFLOTRAN, plus .ex per boundary marker), .stor (FEHM, plus .fehmn and zone files), "
                "MESH or .tough (TOUGH2/3), .csv, .npz")


def read_any_mesh(path: Path) -> AnyMesh:
    """A 2D mesh (.json mesh schema, .vtu, .msh) or a 3D mesh (.json with ``tets``, as refine3d writes)."""
    from nonobtuse.io import is_mesh_file, read_mesh
    from nonobtuse.io.json_formats import read_json
    from nonobtuse.io.tetmesh import read_tetmesh_json

    if path.suffix.lower() == ".json":
        data = read_json(path)
        if isinstance(data, dict) and "tets" in data:
            return read_tetmesh_json(path)
    if not is_mesh_file(path):
        raise InvalidInputError(f"{path}: not a mesh file (expected a 2D mesh .json/.vtu/.msh or a 3D mesh "
                                ".json from refine3d; make one with triangulate, refine or refine3d)")
    return read_mesh(path)


def write_output(mesh: AnyMesh, path: str | Path, *, thickness: float = 1.0,
                 quiet: bool = False) -> ControlVolumeGrid | None:
    """Write ``mesh`` to ``path``: a simulator export when the name is one (the LaGriT-style diagnostics go to
    stderr unless ``quiet``; returns the grid), else the 2D or 3D mesh writer (returns None)."""
    if is_export_path(path):
        grid, paths = export_mesh(mesh, path, thickness=thickness)
        if not quiet:
            print(grid.diagnostics(), file=sys.stderr)
            print(f"wrote {', '.join(str(p) for p in paths)}", file=sys.stderr)
        return grid
    if isinstance(mesh, TetMesh):
        from nonobtuse.io.tetmesh import write_tetmesh

        write_tetmesh(mesh, path)
    else:
        from nonobtuse.io import write_mesh

        write_mesh(mesh, path)
    return None


def run(args: argparse.Namespace) -> int:
    if not is_export_path(args.output):
        raise InvalidInputError(f"{args.output}: not an export format (expected {FORMATS_HELP})")
    mesh = read_any_mesh(Path(args.input))
    progress = guards.Progress(quiet=args.quiet, size=len(mesh.points))
    progress.start(f"control volumes of {len(mesh.points):,} points; writing {args.output}")
    grid, paths = export_mesh(mesh, args.output, thickness=args.thickness)
    progress.done(f"{grid.negative_coefficients:,} negative coefficients")
    if not args.quiet:
        print(f"{args.input} -> {', '.join(str(p) for p in paths)}")
        print(grid.diagnostics())
    return EXIT_OK if grid.negative_coefficients == 0 else EXIT_VIOLATIONS


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("export", help="write simulator input (PFLOTRAN, FEHM, TOUGH, CSV/NPZ) from a mesh; "
                       "exit 1 when a coefficient has the wrong sign (exact)",
                       description="Build the Voronoi control volumes of a 2D or 3D mesh (exact coefficient "
                       f"signs) and write them; the format follows the output name: {FORMATS_HELP}.")
    p.add_argument("input", help="2D mesh (.json, .vtu, .msh) or 3D mesh .json (from refine3d)")
    p.add_argument("-o", "--output", required=True, help="output file; the format follows the name")
    p.add_argument("--thickness", type=float, default=1.0, help="2D: extrusion thickness (default 1)")
    guards.add_quiet_option(p)
    p.set_defaults(func=run)
