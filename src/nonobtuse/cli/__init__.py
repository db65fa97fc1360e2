"""The ``nonobtuse`` command. Each command group registers its subcommands from its own module; the exit
codes are in :mod:`nonobtuse.cli.exit_codes`."""

from __future__ import annotations

import argparse
import os
import signal
import sys

from nonobtuse.cli.exit_codes import EXIT_INVALID, EXIT_NOT_CONVERGED, EXIT_OK, EXIT_VIOLATIONS
from nonobtuse.errors import InvalidInputError

__all__ = ["EXIT_BROKEN_PIPE", "EXIT_INVALID", "EXIT_NOT_CONVERGED", "EXIT_OK", "EXIT_VIOLATIONS",
           "build_parser", "main"]


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="nonobtuse",
        description="Delaunay meshes fit for control-volume simulation: exact nonobtuse-boundary checks and "
        "repair with few Steiner points.",
        epilog="exit codes: 0 ok, 1 a check found violations, 2 invalid input, 3 refinement did not converge",
    )
    from nonobtuse import __version__

    parser.add_argument("--version", action="version", version=f"nonobtuse {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    # each module adds its subcommands and sets func=
    from nonobtuse.cli import export, mesh2d, mesh3d, refine

    mesh2d.register(sub)
    refine.register(sub)
    mesh3d.register(sub)
    export.register(sub)
    return parser


EXIT_BROKEN_PIPE = 128 + signal.SIGPIPE  # what a shell reports for a Unix tool killed by SIGPIPE


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return int(args.func(args))
    except InvalidInputError as e:
        print(f"nonobtuse: invalid input: {e}", file=sys.stderr)
        return EXIT_INVALID
    except ModuleNotFoundError as e:  # an optional package (the 3d or demo extra) is not installed
        print(f"nonobtuse: {e}", file=sys.stderr)
        return EXIT_INVALID
    except BrokenPipeError:  # the reader of stdout went away (`nonobtuse check ... | head`): stop quietly
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())  # so that flushing stdout at exit does not fail again
        return EXIT_BROKEN_PIPE


if __name__ == "__main__":
    sys.exit(main())
