"""One runner for the experiments: ``python -m experiments`` lists them, ``python -m experiments NAME
[ARGS]`` runs ``experiments/NAME.py`` exactly as ``python -m experiments.NAME [ARGS]`` does (same arguments,
same outputs, same exit code). Every module of the package that runs as a script is listed, with the first
paragraph of its docstring, so a new experiment appears without being registered here."""

from __future__ import annotations

import ast
import runpy
import sys
import textwrap
from pathlib import Path

HERE = Path(__file__).resolve().parent
SCRIPT_GUARD = 'if __name__ == "__main__":'


def runnable() -> dict[str, str]:
    """Name -> first docstring paragraph (one line) of every ``experiments/NAME.py`` with a script guard,
    by name. Reads the sources without importing them (no heavy imports to list)."""
    found = {}
    for path in sorted(HERE.glob("*.py")):
        source = path.read_text()
        if path.stem.startswith("_") or SCRIPT_GUARD not in source:
            continue
        doc = ast.get_docstring(ast.parse(source)) or ""
        found[path.stem] = " ".join(doc.split("\n\n")[0].split())
    return found


def usage(experiments: dict[str, str]) -> str:
    width = max(map(len, experiments))
    lines = ["usage: python -m experiments NAME [ARGS]   (the same as python -m experiments.NAME [ARGS]; "
             "NAME --help for its options)", "", "experiments:"]
    for name, doc in experiments.items():
        wrapped = textwrap.wrap(doc, 110 - width - 4) or [""]
        lines += [f"  {name:<{width}}  {wrapped[0]}"] + [f"  {'':<{width}}  {w}" for w in wrapped[1:]]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    experiments = runnable()
    if not argv or argv[0] in ("-h", "--help", "list"):
        print(usage(experiments))
        return 0
    name, rest = argv[0], argv[1:]
    if name not in experiments:
        print(f"python -m experiments: unknown experiment {name!r}; one of {', '.join(experiments)}",
              file=sys.stderr)
        return 2
    sys.argv = [f"experiments.{name}", *rest]
    try:
        runpy.run_module(f"experiments.{name}", run_name="__main__", alter_sys=True)
    except SystemExit as e:  # the experiment's own exit code (argparse's 2, fuzz's 1, ...)
        return e.code if isinstance(e.code, int) else (0 if e.code is None else 1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
