"""The check3d and refine3d commands: exit codes and output."""

from __future__ import annotations

import importlib.util
import json
import time
from pathlib import Path

import numpy as np
import pytest
from experiments.plc_families import make_plc

from mesh3d_shapes import CUBE_POINTS, CUBE_TRIANGLES, TET_TRIANGLES, write_off
from nonobtuse.cli import EXIT_INVALID, EXIT_NOT_CONVERGED, EXIT_OK, EXIT_VIOLATIONS, main
from nonobtuse.io.tetmesh import read_tetmesh_json
from nonobtuse.mesh3d import check_gabriel

# A low tet: the apex (1, 1, 2) is at distance sqrt(1 + 1 + 4) < 2 sqrt(2) from the circumcenter (2, 2, 0)
# of the base (0,0,0), (4,0,0), (0,4,0), i.e. strictly inside the base's diametral sphere.
LOW_TET = np.array([[0, 0, 0], [4, 0, 0], [0, 4, 0], [1, 1, 2]])


@pytest.fixture
def cube(tmp_path):
    return write_off(tmp_path / "cube.off", CUBE_POINTS, CUBE_TRIANGLES.tolist())


@pytest.fixture
def low_tet(tmp_path):
    return write_off(tmp_path / "low.off", LOW_TET, TET_TRIANGLES.tolist())


def test_check3d_gabriel_cube_exits_0(cube, capsys):
    # each boundary triangle is half a unit square: its diametral sphere has the square's diagonal as
    # diameter; the fourth corner lies on it, not inside, and the other cube corners are farther. Segments
    # likewise.
    assert main(["check3d", str(cube), "--json"]) == EXIT_OK
    out = json.loads(capsys.readouterr().out)
    assert out["encroached_facets"] == 0 and out["encroached_segments"] == 0 and out["gabriel"]["ok"]


def test_check3d_keeps_freed_memory_on_glibc():
    import platform

    from nonobtuse.cli.mesh3d import keep_freed_memory

    if platform.libc_ver()[0] != "glibc":
        pytest.skip("mallopt is glibc's")
    assert keep_freed_memory()


def test_check3d_encroached_exits_1(low_tet, capsys):
    assert main(["check3d", str(low_tet), "--backend", "tetgen"]) == EXIT_VIOLATIONS
    assert "boundary faces        1 of 4 encroached" in capsys.readouterr().out  # the base
    assert main(["check3d", str(low_tet), "--json"]) == EXIT_VIOLATIONS
    deepest = json.loads(capsys.readouterr().out)["gabriel"]["deepest_faces"][0]
    assert deepest["vertex"] == 3  # the apex encroaches the base


@pytest.mark.skipif(importlib.util.find_spec("pytetwild") is None,
                    reason="backend ftetwild needs the pytetwild package, not installed")
def test_check3d_ftetwild_checks_its_own_boundary(cube, capsys):
    code = main(["check3d", str(cube), "--backend", "ftetwild", "--json"])
    out = json.loads(capsys.readouterr().out)
    assert out["backend"] == "ftetwild"
    # fTetWild remeshes the surface: every boundary face of its mesh is checked, and no segments (it reports
    # none)
    assert out["gabriel"]["checked_faces"] == out["boundary_faces"] > 12
    assert out["gabriel"]["checked_segments"] == 0 and out["encroached_segments"] == 0
    assert out["steiner_points"] == out["points"] - 8
    # it moves the surface at most within its envelope (1e-3 of the diagonal): the unit cube's volume stays ~1
    assert out["control_volumes"]["total_volume"] == pytest.approx(1.0, abs=1e-2)
    assert code == (EXIT_OK if out["encroached_facets"] == 0 else EXIT_VIOLATIONS)
    assert out["gabriel"]["ok"] == (out["encroached_facets"] == 0)


def test_check3d_invalid_input_exits_2(tmp_path, capsys):
    path = write_off(tmp_path / "open.off", CUBE_POINTS, CUBE_TRIANGLES[:-1].tolist())
    assert main(["check3d", str(path)]) == EXIT_INVALID
    assert "surface not closed" in capsys.readouterr().err


def test_refine3d_converges_and_writes(low_tet, tmp_path, capsys):
    out = tmp_path / "out.json"
    assert main(["refine3d", str(low_tet), "-o", str(out), "--json", "--max-steiner", "500"]) == EXIT_OK
    stats = json.loads(out.read_text())["stats"]
    assert stats["status"] == "converged"
    assert stats["encroached_facets"] == 0 and stats["encroached_segments"] == 0
    assert check_gabriel(read_tetmesh_json(out)).ok  # the certificate holds for the mesh as written
    assert stats["steiner_points"] > 0  # the tet is encroached, so the refinement had to add points
    assert isinstance(stats["negative_couplings"], int)
    assert json.loads(capsys.readouterr().out)["output"] == str(out)


def test_refine3d_without_budget_exits_3(low_tet, tmp_path):
    assert main(["refine3d", str(low_tet), "-o", str(tmp_path / "o.vtu"), "--max-steiner", "0"]) == \
        EXIT_NOT_CONVERGED



def write_poly(path: Path, plc) -> Path:
    """A TetGen .poly file of `plc`: one facet per facet id, listing its triangles as polygons (no holes)."""
    lines = [f"{len(plc.points)} 3 0 0"]
    lines += [f"{i} {x!r} {y!r} {z!r}" for i, (x, y, z) in enumerate(plc.points.tolist())]
    ids = np.unique(plc.facet_ids)
    lines.append(f"{len(ids)} 0")
    for f in ids:
        tris = plc.triangles[plc.facet_ids == f]
        lines.append(f"{len(tris)} 0")
        lines += [f"3 {a} {b} {c}" for a, b, c in tris.tolist()]
    path.write_text("\n".join(lines + ["0", "0"]) + "\n")
    return path


def test_refine3d_time_limit_covers_the_whole_command(tmp_path, capsys):
    # fan k=12 at 3 degrees, midpoint split: Steiner points crowd at the axis, and an exact check of that
    # state takes tens of seconds, so a check outside the time limit would show.
    path = write_poly(tmp_path / "fan.poly", make_plc("fan", 3.0, 12))
    start = time.perf_counter()
    code = main(["refine3d", str(path), "-o", str(tmp_path / "f.json"), "--split", "midpoint", "--min-length",
                 "0", "--time-limit", "2", "--json"])
    elapsed = time.perf_counter() - start
    assert code == EXIT_NOT_CONVERGED
    out = json.loads(capsys.readouterr().out)
    # It stalls (a split point rounds onto a vertex) or runs out of time; either way the exact check of the
    # crowded result is cut at the limit (the unlimited check of it took 25 s here), its rows left unchecked.
    assert out["status"] in ("stalled", "budget_exhausted")
    assert out["unchecked_faces"] + out["unchecked_segments"] > 0
    assert elapsed < 2.0 + 5.0  # slack: final Delaunay mesh, control volumes and writing (not time-limited)
