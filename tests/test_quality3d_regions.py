"""Region volume constraints from a TetGen .poly region list (the fifth number of a region line) in
refine_quality3d and refine3d --region-volumes."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from nonobtuse.cli import EXIT_INVALID, EXIT_OK, main
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d import check_gabriel, load_plc, read_tetmesh_json
from nonobtuse.mesh3d.control_volumes3d import signed_tet_volumes
from nonobtuse.mesh3d.quality3d import refine_quality3d, region_volume_bounds

TWO_CUBES = Path(__file__).resolve().parent / "data" / "3d" / "two_cubes_face.poly"


def two_cubes_with(tmp_path: Path, region_lines: list[str]) -> Path:
    """two_cubes_face.poly (unit cubes [0,1]^3 and [1,2]x[0,1]^2, seeds 1 and 2) with its region list
    replaced by `region_lines`."""
    lines = TWO_CUBES.read_text().splitlines()
    at = len(lines) - 3  # "2", then the two region lines
    assert lines[at].strip() == "2", "two_cubes_face.poly no longer ends with its two-line region list"
    path = tmp_path / "two_cubes_volumes.poly"
    path.write_text("\n".join(lines[:at] + [str(len(region_lines))] + region_lines) + "\n")
    return path


def region_max_volumes(mesh) -> dict[float, float]:
    volumes = signed_tet_volumes(mesh.points, np.asarray(mesh.tets))
    regions = np.asarray(mesh.tet_regions)
    return {float(a): float(volumes[regions == a].max()) for a in np.unique(regions)}


def test_poly_region_volumes_are_read(tmp_path):
    plc = load_plc(two_cubes_with(tmp_path, ["1 0.5 0.5 0.5 1.0 0.01", "2 1.5 0.5 0.5 2.0"]))
    assert plc.regions[:, 3].tolist() == [1.0, 2.0]
    assert plc.region_volumes[0] == 0.01 and math.isnan(plc.region_volumes[1])
    assert region_volume_bounds(plc) == {1.0: 0.01}
    # TetGen ignores a constraint <= 0; two seeds of one attribute: the smaller bound
    plc = load_plc(two_cubes_with(tmp_path, ["1 0.5 0.5 0.5 1.0 -1", "2 1.5 0.5 0.5 1.0 0.2",
                                             "3 0.2 0.2 0.2 1.0 0.3"]))
    assert region_volume_bounds(plc) == {1.0: 0.2}
    plain = load_plc(TWO_CUBES)
    assert plain.region_volumes.shape == (2,) and region_volume_bounds(plain) == {}


def test_infinite_region_volume_names_the_line(tmp_path):
    path = two_cubes_with(tmp_path, ["1 0.5 0.5 0.5 1.0 inf", "2 1.5 0.5 0.5 2.0"])
    line = len(path.read_text().splitlines()) - 1
    with pytest.raises(InvalidInputError, match=rf"{path.name}:{line}.*volume constraint of region 0"):
        load_plc(path)


def test_region_volumes_hold_in_their_regions(tmp_path):
    plc = load_plc(two_cubes_with(tmp_path, ["1 0.5 0.5 0.5 1.0 0.01", "2 1.5 0.5 0.5 2.0 0.1"]))
    r = refine_quality3d(plc, region_volumes=True, start="boundary")
    assert r.status == "converged" and check_gabriel(r.mesh).ok
    worst = region_max_volumes(r.mesh)
    assert worst[1.0] <= 0.01 and 0.01 < worst[2.0] <= 0.1  # region 2 was not refined to region 1's bound
    # a global bound and the region list: the smaller one holds in each region
    r = refine_quality3d(plc, max_volume=0.05, region_volumes=True, start="boundary")
    worst = region_max_volumes(r.mesh)
    assert r.status == "converged" and worst[1.0] <= 0.01 and 0.01 < worst[2.0] <= 0.05
    # without region_volumes the list is not used (TetGen's -a without a number asks for it)
    r = refine_quality3d(plc, radius_edge=2.0, start="boundary")
    assert region_max_volumes(r.mesh)[1.0] > 0.01


def test_region_volumes_without_constraints_are_refused():
    with pytest.raises(InvalidInputError, match="no volume constraint"):
        refine_quality3d(load_plc(TWO_CUBES), region_volumes=True)


def test_refine3d_region_volumes(tmp_path, capsys):
    poly = two_cubes_with(tmp_path, ["1 0.5 0.5 0.5 1.0 0.01", "2 1.5 0.5 0.5 2.0 0.1"])
    out = tmp_path / "q.json"
    assert main(["refine3d", str(poly), "-o", str(out), "--region-volumes", "--region-max-volume", "2=0.05",
                 "--quality-start", "boundary", "--json"]) == EXIT_OK
    summary = json.loads(capsys.readouterr().out)
    mesh = read_tetmesh_json(out)
    worst = region_max_volumes(mesh)
    assert summary["status"] == "converged" and worst[1.0] <= 0.01 and 0.01 < worst[2.0] <= 0.05
    assert summary["max_volume_bound"] == {"1.0": 0.01, "2.0": 0.05}
    no_constraints = ["refine3d", str(TWO_CUBES), "-o", str(tmp_path / "n.json"), "--region-volumes"]
    assert main(no_constraints) == EXIT_INVALID
