"""``nonobtuse refine``: files in, mesh out, exit codes. Needs nonobtuse.io (helper io2d)."""

from __future__ import annotations

import json

import pytest

pytest.importorskip("nonobtuse.io", reason="nonobtuse.io (helper io2d) not merged yet")

from nonobtuse.cli import main  # noqa: E402

# Figure 5's quadrilateral as a CG:SHOP instance: one Steiner point at (90, 0) (worked out in
# cpp/tests/greedy_refine_test.cpp).
FIGURE_5 = {
    "instance_uid": "figure5",
    "num_points": 4,
    "points_x": [0, 100, 90, 0],
    "points_y": [0, 0, 20, 60],
    "region_boundary": [0, 1, 2, 3],
    "num_constraints": 0,
    "additional_constraints": [],
}


@pytest.fixture
def figure5(tmp_path):
    path = tmp_path / "figure5.instance.json"
    path.write_text(json.dumps(FIGURE_5))
    return path


def test_refine_writes_the_mesh_and_stats(figure5, tmp_path, capsys):
    out = tmp_path / "out.json"
    assert main(["refine", str(figure5), "-o", str(out), "--json"]) == 0
    stats = json.loads(capsys.readouterr().out)
    assert stats["status"] == "converged" and stats["steiner_points"] == 1 and stats["optimal"] is True
    mesh = json.loads(out.read_text())
    assert mesh["points"][4] == [90.0, 0.0]
    assert mesh["stats"]["lower_bound"] == 1


def test_budget_exhausted_exits_3(figure5, tmp_path):
    out = tmp_path / "out.json"
    assert main(["refine", str(figure5), "-o", str(out), "--max-steiner", "0"]) == 3
    assert out.exists()  # the partial mesh is still written


@pytest.mark.parametrize("strategy", ["project-flip", "projection"])
def test_baselines_from_the_cli(figure5, tmp_path, strategy):
    # The foot of c = (90, 20) is the one point for both baselines too.
    out = tmp_path / "out.json"
    assert main(["refine", str(figure5), "-o", str(out), "--strategy", strategy]) == 0
    assert len(json.loads(out.read_text())["points"]) == 5


def test_threads_option(figure5, tmp_path, capsys):
    out = tmp_path / "out.json"
    assert main(["refine", str(figure5), "-o", str(out), "--threads", "1"]) == 0
    assert len(json.loads(out.read_text())["points"]) == 5
    assert main(["refine", str(figure5), "-o", str(tmp_path / "bad.json"), "--threads", "0"]) == 2
    assert "threads must be a positive integer" in capsys.readouterr().err
    assert not (tmp_path / "bad.json").exists()
