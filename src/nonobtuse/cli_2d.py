"""2D subcommands: triangulate, check, demo."""

from __future__ import annotations

import argparse


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("demo", help="run on a built-in thin-layer geological cross-section")
    p.set_defaults(func=lambda args: 0)
