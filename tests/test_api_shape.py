"""The shape of the public API: functions do not shadow their modules, the 3D API returns complete stats (the
CLI adds nothing to them), check3d's report comes from the API."""

from __future__ import annotations

import ast
import importlib
import importlib.util
import json
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

import nonobtuse
from mesh3d_shapes import write_off
from nonobtuse.cli import main
from nonobtuse.mesh3d import (
    boundary_certificate,
    check_gabriel,
    control_volumes3d,
    load_plc,
    refine_gabriel,
    tetrahedralize,
)
from nonobtuse.mesh3d.gabriel import control_volume_summary

# Apex 0.1 above the centre of an equilateral base: it encroaches the base facet, refinement has work to do.
S = np.sqrt(3) / 2
FLAT_TET_POINTS = np.array([[1, 0, 0], [-0.5, S, 0], [-0.5, -S, 0], [0, 0, 0.1]])
FLAT_TET_FACES = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]]


@pytest.fixture
def flat_tet(tmp_path):
    return write_off(tmp_path / "flat.off", FLAT_TET_POINTS, FLAT_TET_FACES)


@pytest.mark.parametrize(
    ("name", "module"), [("check", "certificate"), ("triangulate", "triangulation"), ("refine", "refinement")]
)
def test_functions_do_not_shadow_modules(name, module):
    function = getattr(nonobtuse, name)
    assert callable(function) and function.__module__ == f"nonobtuse.{module}"
    assert importlib.util.find_spec(f"nonobtuse.{name}") is None  # no module of the function's name
    assert getattr(importlib.import_module(f"nonobtuse.{module}"), name) is function


def test_refine_gabriel_stats_are_complete(flat_tet):
    plc = load_plc(flat_tet)
    before = time.perf_counter()
    res = refine_gabriel(plc, max_steiner=40)
    took = time.perf_counter() - before
    assert res.stats["negative_couplings"] == control_volumes3d(res.mesh).negative_couplings
    assert 0 < res.stats["seconds"] <= took
    assert res.mesh.stats is res.stats


def test_refine_gabriel_counts_time_from_started(flat_tet):
    plc = load_plc(flat_tet)
    long_ago = time.perf_counter() - 100.0
    res = refine_gabriel(plc, max_steiner=10**6, time_limit=50.0, started=long_ago)
    # the 50 s were spent before the call: no insertion, and the input is not Gabriel
    assert res.status == "budget_exhausted" and res.stats["steiner_points"] == 0
    assert res.stats["seconds"] >= 100.0


def test_boundary_certificate_is_check_gabriel_and_control_volumes(flat_tet):
    mesh = tetrahedralize(load_plc(flat_tet), "cgal")
    cert = boundary_certificate(mesh)
    report, cv = check_gabriel(mesh), control_volumes3d(mesh)
    assert cert["encroached_facets"] == len(report.faces) > 0  # the apex encroaches the base
    assert cert["encroached_segments"] == len(report.segments)
    assert cert["gabriel"] == report.to_dict() and cert["control_volumes"] == control_volume_summary(mesh)
    # coordinates of order 1: the power-of-two scaling is exact, the summary is the plain one plus the count
    # of tets flat in floating point (none here)
    assert cert["control_volumes"] == {**cv.to_dict(), "flat_in_floating_point": 0}
    assert (cert["points"], cert["tets"], cert["boundary_faces"]) == (
        len(mesh.points), len(mesh.tets), len(mesh.boundary_faces))
    assert cert["steiner_points"] == mesh.stats["steiner_points"]


def test_cli_reports_what_the_api_returns(flat_tet, tmp_path, capsys):
    assert main(["check3d", str(flat_tet), "--json"]) == 1  # not Gabriel
    printed = json.loads(capsys.readouterr().out)
    cert = boundary_certificate(tetrahedralize(load_plc(flat_tet), "cgal"))
    assert printed == {"input": str(flat_tet), "backend": "cgal", **json.loads(json.dumps(cert))}
    out = tmp_path / "out.json"
    main(["refine3d", str(flat_tet), "-o", str(out), "--max-steiner", "40", "--json"])
    printed = json.loads(capsys.readouterr().out)
    res = refine_gabriel(load_plc(flat_tet), max_steiner=40)
    assert printed.keys() == {"input", "output", *res.stats}
    assert json.loads(out.read_text())["stats"].keys() == res.stats.keys()


SRC = Path(nonobtuse.__file__).parent


def private_io_imports() -> list[str]:
    """Modules of the package outside io/ that import a private module of nonobtuse.io."""
    found = []
    for path in sorted(SRC.rglob("*.py")):
        if path.parent.name == "io":
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            names = [node.module or ""] if isinstance(node, ast.ImportFrom) else (
                [a.name for a in node.names] if isinstance(node, ast.Import) else [])
            found += [f"{path.relative_to(SRC)}: {n}" for n in names if n.startswith("nonobtuse.io._")]
    return found


def test_io_privates_stay_inside_io():
    assert private_io_imports() == []


def test_every_reading_entry_point_is_reached_through_io():
    import nonobtuse.io as io
    import nonobtuse.mesh3d as mesh3d

    for name in ("load_plc", "read_tetmesh_json", "write_tetmesh"):
        assert getattr(io, name) is getattr(mesh3d, name)
    with pytest.raises(AttributeError, match="no attribute 'load_mesh3d'"):
        io.load_mesh3d  # noqa: B018


def test_2d_io_does_not_load_the_3d_pipeline():
    code = "import sys, nonobtuse.io; print(any(m.startswith('nonobtuse.mesh3d') for m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                         env={**os.environ, "PYTHONPATH": str(SRC.parent)})
    assert out.stdout.strip() == "False"
