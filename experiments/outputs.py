"""Where the experiments write: the one ``--out DIR`` option every experiment that writes files takes.

The convention: ``--out DIR`` (default ``experiments/results``) is the folder of every CSV, PNG and table the
experiment writes, under the names its docstring gives (``--quick`` adds ``_quick`` to the stem); inputs it
generates and case records go to ``DIR/cache/`` (git ignores ``experiments/results/cache``). The folder is
created when missing. Experiments that only print take no ``--out``.
"""

from __future__ import annotations

import argparse
from pathlib import Path

RESULTS_DIR = Path(__file__).resolve().parent / "results"


def add_out_option(parser: argparse.ArgumentParser, what: str = "the CSV and PNG outputs") -> None:
    """Adds ``--out DIR`` (a Path, default ``RESULTS_DIR``) to ``parser``."""
    parser.add_argument("--out", type=Path, default=RESULTS_DIR, metavar="DIR",
                        help=f"directory of {what}; generated inputs and case records go to DIR/cache/ "
                             "(default experiments/results)")


def out_dir(args: argparse.Namespace, *, cache: bool = False) -> Path:
    """``args.out`` (or its ``cache`` subfolder), created when missing."""
    path = Path(args.out) / ("cache" if cache else "")
    path.mkdir(parents=True, exist_ok=True)
    return path
