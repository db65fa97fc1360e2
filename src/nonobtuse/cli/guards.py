"""What every subcommand checks before it works: option values (argparse types, so a bad value is a usage
error, exit 2) and output paths (never one of the input files, every folder present)."""

from __future__ import annotations

import argparse
import dataclasses
import math
import os
import sys
import time
from pathlib import Path

from nonobtuse.domain import Domain
from nonobtuse.errors import InvalidInputError
from nonobtuse.io import require_writable
from nonobtuse.mesh import Mesh

MAX_COUNT = 2**62  # budgets cross into C++ as 64-bit integers


def count(text: str) -> int:
    """An argparse type: a non-negative integer below 2^62 (a Steiner budget)."""
    try:
        n = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a non-negative integer, found {text!r}") from None
    if not 0 <= n < MAX_COUNT:
        raise argparse.ArgumentTypeError(f"expected a non-negative integer below 2^62, found {text}")
    return n


def non_negative(text: str) -> float:
    """An argparse type: a finite number >= 0 (a length or a time limit)."""
    try:
        x = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, found {text!r}") from None
    if not math.isfinite(x) or x < 0:
        raise argparse.ArgumentTypeError(f"expected a finite number >= 0, found {text}")
    return x


def positive(text: str) -> float:
    """An argparse type: a finite number > 0 (a vertical exaggeration)."""
    x = non_negative(text)
    if x == 0:
        raise argparse.ArgumentTypeError("expected a finite number > 0, found 0")
    return x


def add_plot_options(p: argparse.ArgumentParser, what: str) -> None:
    p.add_argument("--plot", metavar="PNG", help=f"also draw {what}: edges facing an obtuse angle in red "
                   "with their diametral circles and apex, Steiner points in blue, close-ups of the worst at "
                   "true scale")
    p.add_argument("--exaggeration", type=positive, default=1.0,
                   help="vertical exaggeration of the main panels (labelled on them; default 1)")


def _same_file(a: Path, b: Path) -> bool:
    if a.resolve() == b.resolve():
        return True
    try:
        return os.path.samefile(a, b)
    except OSError:  # one of them does not exist
        return False


def refuse_overwriting(inputs: list[Path], outputs: list[Path]) -> None:
    """InvalidInputError unless every output can be written (its folder exists, it is not a directory) and
    none is one of the input files (same resolved path, or the same inode through a link)."""
    for out in outputs:
        for read in inputs:
            if _same_file(out, read):
                raise InvalidInputError(f"{out}: refusing to write over the input file {read}")
        require_writable(out)


def files_read(path: str | os.PathLike, domain: Domain) -> list[Path]:
    """The files a 2D domain was read from: ``path``, and the .node file of a .poly listing no vertices."""
    points_file = domain.origin.points_file if domain.origin is not None else None
    return [Path(path)] + ([Path(points_file)] if points_file else [])


def add_timings_option(p: argparse.ArgumentParser) -> None:
    p.add_argument("--timings", action="store_true", help="also record the seconds taken in the mesh file's "
                   "stats (without it the file is the same, byte for byte, for the same input and options)")


def without_timings(mesh: Mesh, keep: bool) -> Mesh:
    """``mesh`` with ``stats["seconds"]`` dropped unless ``keep``: timings differ between identical runs."""
    if keep:
        return mesh
    return dataclasses.replace(mesh, stats={k: v for k, v in mesh.stats.items() if k != "seconds"})


PROGRESS_MIN_POINTS = 100_000  # a 2D refine, check or export below this: about a second, no progress


def add_quiet_option(p: argparse.ArgumentParser) -> None:
    p.add_argument("-q", "--quiet", action="store_true", help="print nothing on success (no summary, no "
                   "progress); errors still go to stderr")


class Progress:
    """Progress lines on stderr for long work: only when stderr is a terminal, the input has at least
    ``min_size`` points (default ``PROGRESS_MIN_POINTS``; a 3D refinement is long from a few hundred, so it
    passes 0) and ``quiet`` is false (pipes, logs, tests and ``--json`` readers see nothing). ``start`` and
    ``done`` frame one step; ``done`` adds the seconds since ``start``."""

    def __init__(self, *, quiet: bool, size: int, min_size: int = PROGRESS_MIN_POINTS) -> None:
        self.active = not quiet and size >= min_size and sys.stderr.isatty()
        self._t0 = time.perf_counter()

    def start(self, what: str) -> None:
        if self.active:
            self._t0 = time.perf_counter()
            print(f"nonobtuse: {what} ...", file=sys.stderr, flush=True)

    def done(self, what: str) -> None:
        if self.active:
            print(f"nonobtuse: {what} ({time.perf_counter() - self._t0:.1f} s)", file=sys.stderr, flush=True)
