"""The 2D commands: nonobtuse triangulate / check / demo, and their exit codes."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from nonobtuse.cli import EXIT_INVALID, EXIT_OK, EXIT_VIOLATIONS, main


def cgshop_file(tmp_path: Path, name: str, points: list[tuple[float, float]]) -> Path:
    """A CG:SHOP 2025 instance whose boundary is the polygon through ``points`` in order."""
    path = tmp_path / f"{name}.instance.json"
    path.write_text(json.dumps({
        "instance_uid": name, "num_points": len(points), "points_x": [p[0] for p in points],
        "points_y": [p[1] for p in points], "region_boundary": list(range(len(points))), "num_constraints": 0,
        "additional_constraints": [],
    }))
    return path


def test_check_exit_codes(tmp_path, capsys):
    # (1,1) sees (0,0)-(2,0) at exactly 90 degrees: passes. (2,1) sees (0,0)-(4,0) at 126.87 degrees: fails.
    assert main(["check", str(cgshop_file(tmp_path, "right", [(0, 0), (2, 0), (1, 1)]))]) == EXIT_OK
    assert "OK" in capsys.readouterr().out
    assert main(["check", str(cgshop_file(tmp_path, "obtuse", [(0, 0), (4, 0), (2, 1)]))]) == EXIT_VIOLATIONS
    # The boundary crosses itself ((0,0)-(1,1) and (1,0)-(0,1) meet at (1/2,1/2)): invalid input.
    bowtie = cgshop_file(tmp_path, "bowtie", [(0, 0), (1, 1), (1, 0), (0, 1)])
    assert main(["check", str(bowtie)]) == EXIT_INVALID
    assert "invalid input" in capsys.readouterr().err


def test_open_boundary_needs_the_convex_hull_option(capsys):
    # box.poly (bundled with the io tests): only one side of its outer square [0,3]^2 is a segment, so its
    # boundary is open: invalid as given, a valid domain once closed by the convex hull. Then each outer side
    # can only face a corner of the hole [1,2]^2, e.g. (0,0)-(3,0) seen from (1,1): (-1,-1).(2,-1) = -1 < 0,
    # obtuse; from (2,1): (-2,-1).(1,-1) = -1: obtuse too. So the check finds violations.
    box = str(Path(__file__).parent / "data" / "box.poly")
    assert main(["check", box]) == EXIT_INVALID
    assert "convex_hull" in capsys.readouterr().err
    assert main(["check", "--convex-hull", box]) == EXIT_VIOLATIONS
    assert "NOT OK: 4 obtuse" in capsys.readouterr().out


def test_check_json_and_plot(tmp_path, capsys):
    domain = str(cgshop_file(tmp_path, "obtuse", [(0, 0), (4, 0), (2, 1)]))
    assert main(["check", "--json", domain, "--plot", str(tmp_path / "obtuse.png")]) == EXIT_VIOLATIONS
    assert (tmp_path / "obtuse.png").read_bytes().startswith(b"\x89PNG")
    report = json.loads(capsys.readouterr().out)
    assert report["ok"] is False
    assert report["edges"] == {"boundary": 3, "interface": 0, "interior": 0}
    assert [o["apex"] for o in report["offenders"]] == [2]


@pytest.mark.parametrize("suffix", [".json", ".vtu"])
def test_triangulate_then_check_the_mesh_file(tmp_path, capsys, suffix):
    # Square with its center: 4 triangles, every boundary angle exactly 90 degrees.
    domain = cgshop_file(tmp_path, "square", [(0, 0), (2, 0), (2, 2), (0, 2)])
    data = json.loads(domain.read_text())
    data["points_x"].append(1)
    data["points_y"].append(1)
    data["num_points"] = 5
    domain.write_text(json.dumps(data))
    out = tmp_path / f"square{suffix}"
    assert main(["triangulate", str(domain), "-o", str(out)]) == EXIT_OK
    assert "4 triangles" in capsys.readouterr().out
    assert main(["check", "--json", str(out)]) == EXIT_OK
    assert json.loads(capsys.readouterr().out)["triangles"] == 4


def test_demo_reports(capsys):
    assert main(["demo"]) == EXIT_OK
    out = capsys.readouterr().out
    assert "constrained Delaunay triangulation" in out
    assert "wrong-sign coefficients (exact)" in out
    assert "after: refine (greedy, converged" in out and "Triangle -pD on the same domain" in out


def test_demo_refinement_removes_every_wrong_sign_boundary_coefficient():
    from nonobtuse import control_volumes, refine, triangulate
    from nonobtuse.demo import CONDUCTIVITY, cross_section

    domain = cross_section()
    before = control_volumes(triangulate(domain), CONDUCTIVITY)
    result = refine(domain)
    after = control_volumes(result.mesh, CONDUCTIVITY)
    boundary = 0  # edge kind index of boundary edges (nonobtuse.certificate.KINDS)
    assert (before.kind[before.wrong_sign] == boundary).any()  # the demo starts with a real problem
    assert not (after.kind[after.wrong_sign] == boundary).any()
    assert result.stats["steiner_points"] >= result.stats["lower_bound"] > 0
