"""The ``nonobtuse`` command. Each command group registers its subcommands from its own module.

Exit codes: 0 success (and, for checks, every angle nonobtuse); 1 a check found violations; 2 invalid input;
3 a refinement stopped before converging (budget, time, minimum length).
"""

from __future__ import annotations

import argparse
import sys

from nonobtuse.errors import InvalidInputError

EXIT_OK, EXIT_VIOLATIONS, EXIT_INVALID, EXIT_NOT_CONVERGED = 0, 1, 2, 3


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="nonobtuse",
        description="Delaunay meshes fit for control-volume simulation: exact nonobtuse-boundary checks and "
        "repair with few Steiner points.",
        epilog="exit codes: 0 ok, 1 a check found violations, 2 invalid input, 3 refinement did not converge",
    )
    sub = parser.add_subparsers(dest="command", required=True)
    from nonobtuse import cli_2d, cli_3d, cli_refine  # each module adds its subcommands and sets func=

    cli_2d.register(sub)
    cli_refine.register(sub)
    cli_3d.register(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        return int(args.func(args))
    except InvalidInputError as e:
        print(f"nonobtuse: invalid input: {e}", file=sys.stderr)
        return EXIT_INVALID


if __name__ == "__main__":
    sys.exit(main())
