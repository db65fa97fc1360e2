"""First use of the command line: --version, the --json summary, --quiet, progress lines, and a light
install (the default 3D backend without the optional packages)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import nonobtuse
from mesh3d_shapes import CUBE_POINTS, CUBE_TRIANGLES, write_off
from nonobtuse.cli import guards, main

SRC = Path(nonobtuse.__file__).resolve().parent.parent

# An obtuse triangle: the edge (0,0)-(4,0) faces a 135-degree angle, so refine adds Steiner points.
OBTUSE = {"points": [[0, 0], [4, 0], [1, 1]], "segments": [[0, 1], [1, 2], [2, 0]]}


@pytest.fixture
def obtuse(tmp_path):
    path = tmp_path / "obtuse.json"
    path.write_text(json.dumps(OBTUSE))
    return path


def test_version_prints_the_package_version(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["--version"])
    assert stop.value.code == 0
    assert capsys.readouterr().out.strip() == f"nonobtuse {nonobtuse.__version__}"


def test_json_is_a_summary_unless_verbose(obtuse, tmp_path, capsys):
    assert main(["refine", str(obtuse), "-o", str(tmp_path / "a.json"), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert main(["refine", str(obtuse), "-o", str(tmp_path / "b.json"), "--json", "--verbose"]) == 0
    full = json.loads(capsys.readouterr().out)
    assert summary["steiner_points"] == full["steiner_points"] > 0
    assert "edges" not in summary
    assert summary["diagnosis"] == {"stop_reason": full["diagnosis"]["stop_reason"]}
    assert len(full["edges"]) == len(OBTUSE["segments"])
    assert set(full) - set(summary) == {"edges"} and len(full["diagnosis"]) > 1


def test_quiet_prints_nothing_and_still_writes(obtuse, tmp_path, capsys):
    out = tmp_path / "q.json"
    assert main(["refine", str(obtuse), "-o", str(out), "--quiet"]) == 0
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err == ""
    assert len(json.loads(out.read_text())["points"]) > len(OBTUSE["points"])


class _Terminal:
    """A stand-in stderr that says it is a terminal and keeps what is written."""

    def __init__(self) -> None:
        self.lines: list[str] = []

    def isatty(self) -> bool:
        return True

    def write(self, text: str) -> None:
        self.lines.append(text)

    def flush(self) -> None:
        pass


@pytest.mark.parametrize(("quiet", "size", "tty", "expected"), [
    (False, guards.PROGRESS_MIN_POINTS, True, 2),
    (True, guards.PROGRESS_MIN_POINTS, True, 0),
    (False, guards.PROGRESS_MIN_POINTS - 1, True, 0),
    (False, guards.PROGRESS_MIN_POINTS, False, 0),
])
def test_progress_only_on_a_terminal_for_large_inputs(monkeypatch, quiet, size, tty, expected):
    err = _Terminal()
    if not tty:
        monkeypatch.setattr(err, "isatty", lambda: False)
    monkeypatch.setattr(sys, "stderr", err)
    progress = guards.Progress(quiet=quiet, size=size)
    progress.start("refining")
    progress.done("converged")
    assert len([line for line in err.lines if line.startswith("nonobtuse: ")]) == expected


OPTIONAL = ("tetgen", "pytetwild", "triangle", "open3d")


def run_without_optional_packages(*args: str) -> subprocess.CompletedProcess:
    """``nonobtuse ARGS`` in a fresh interpreter where the optional packages (the 3d and demo extras) cannot
    be imported, as after a plain ``pip install .``."""
    hide = "; ".join(f"sys.modules[{name!r}] = None" for name in OPTIONAL)
    code = f"import sys; {hide}; from nonobtuse.cli import main; sys.exit(main(sys.argv[1:]))"
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    return subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True, env=env,
                          timeout=120)


def test_check3d_default_backend_without_optional_packages(tmp_path):
    cube = write_off(tmp_path / "cube.off", CUBE_POINTS, CUBE_TRIANGLES)
    done = run_without_optional_packages("check3d", str(cube))
    assert done.returncode in (0, 1), done.stderr
    assert "Traceback" not in done.stderr


def test_check3d_winding_number_fallback_needs_no_optional_package():
    # The Schönhardt prism: no tetrahedralization of its vertices conforms, so the cgal backend selects cells
    # by the exact winding number (C++, no optional package); the prism's faces are not Gabriel.
    schonhardt = Path(__file__).parent / "data" / "3d" / "schonhardt.off"
    done = run_without_optional_packages("check3d", str(schonhardt), "--json")
    assert done.returncode == 1, done.stderr
    report = json.loads(done.stdout)
    assert report["backend"] == "cgal" and report["tets"] > 0


def test_demo_without_the_demo_extra_says_what_is_not_measured():
    done = run_without_optional_packages("demo")
    assert done.returncode == 0, done.stderr
    assert "not measured (the 'triangle' package is not installed" in done.stdout
    # the 3D part: no TetGen, so the cgal backend tetrahedralizes; the repair is still certified
    assert "before: the cgal backend (TetGen not installed: pip install 'nonobtuse[3d]')" in done.stdout
    assert "certificate: every boundary face and subsegment Gabriel (exact)" in done.stdout
