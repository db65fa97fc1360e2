"""Typed results across the binding: the committed stubs of _core are what pybind11-stubgen generates from the
built extension (``make stubs``), the result classes are read-only, and mypy is clean on the package."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import nonobtuse
from nonobtuse import _core

# SRC: where the built package is imported from (src, or site-packages when installed); ROOT: the repository
# (pyproject.toml's mypy settings and the committed stubs).
SRC = Path(nonobtuse.__file__).parent.parent
ROOT = Path(__file__).resolve().parents[1]


def run(args: list[str], cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", *args], cwd=cwd, capture_output=True, text=True, timeout=240,
                          env={**os.environ, "PYTHONPATH": str(SRC)})


@pytest.mark.skipif(importlib.util.find_spec("pybind11_stubgen") is None,
                    reason="pybind11-stubgen is not installed (pip install -e '.[dev]')")
def test_committed_stubs_are_the_generated_ones(tmp_path):
    out = run(["pybind11_stubgen", "nonobtuse._core", "-o", str(tmp_path), "--exit-code"], ROOT)
    assert out.returncode == 0, out.stderr
    generated = (tmp_path / "nonobtuse" / "_core.pyi").read_text()
    assert generated == (ROOT / "src" / "nonobtuse" / "_core.pyi").read_text(), "stale stubs: run make stubs"


@pytest.mark.skipif(importlib.util.find_spec("mypy") is None,
                    reason="mypy is not installed (pip install -e '.[dev]')")
def test_mypy_is_clean_on_the_package():
    out = run(["mypy"], ROOT)  # the settings and the files are pyproject.toml's
    assert out.returncode == 0, out.stdout + out.stderr


def test_results_are_typed_read_only_objects():
    square = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [2, 3.9]], dtype=np.float64)
    loop = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])
    r = _core.refine(square, loop, np.zeros((0, 2)), np.zeros((0, 3)), False)
    assert isinstance(r, _core.Refine2DResult) and isinstance(r.mesh, _core.Mesh2D)
    # (2, 3.9) is obtuse opposite the top edge: one Steiner point, its foot, repairs it
    assert (r.status, r.steiner_points, r.lower_bound, r.optimal) == ("converged", 1, 1, True)
    assert r.mesh.points.shape == (6, 2) and r.mesh.points.dtype == np.float64
    assert r.edges.dtype == np.int64 and r.edges[:, 2].sum() == 1
    assert repr(r) == "<Refine2DResult status=converged steiner_points=1 lower_bound=1>"
    with pytest.raises(AttributeError):
        r.steiner_points = 0  # type: ignore[misc]
