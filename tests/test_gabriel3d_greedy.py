"""refine_gabriel(split="greedy"): Greedy-Refine along subsegments, through the API, the CLI, the corpus."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from mesh3d_shapes import write_off
from nonobtuse.cli import EXIT_OK, main
from nonobtuse.errors import InvalidInputError
from nonobtuse.io.tetmesh import read_tetmesh_json
from nonobtuse.mesh3d import check_gabriel, load_plc, refine_gabriel
from nonobtuse.mesh3d.plc import PLC

DATA = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "3d"

# A 10 x 2 x 2 box whose top facet (z = 2) is a fan around the extra vertex 8 = (3, 0.5, 2); outward faces.
BOX_POINTS = np.array(
    [[0, 0, 0], [10, 0, 0], [10, 2, 0], [0, 2, 0], [0, 0, 2], [10, 0, 2], [10, 2, 2], [0, 2, 2], [3, 0.5, 2]],
    dtype=np.float64,
)
BOX_FACETS = [
    [[0, 3, 2], [0, 2, 1]],  # bottom
    [[4, 5, 8], [5, 6, 8], [6, 7, 8], [7, 4, 8]],  # top
    [[0, 1, 5], [0, 5, 4]],
    [[1, 2, 6], [1, 6, 5]],
    [[2, 3, 7], [2, 7, 6]],
    [[3, 0, 4], [3, 4, 7]],
]


def box() -> PLC:
    tris = [t for f in BOX_FACETS for t in f]
    ids = [i for i, f in enumerate(BOX_FACETS) for _ in f]
    return PLC(points=BOX_POINTS, triangles=np.array(tris), facet_ids=np.array(ids))


def test_greedy_splits_of_the_box_by_hand():
    # Every box corner sees its edges at right angles (no acute input vertex): greedy applies everywhere.
    # Level 1 scans the subsegments. The bottom edge [0, 1] = (0,0,0)-(10,0,0) has vertex 8 inside its
    # sphere (distance sqrt(4 + 0.25 + 4) = 2.87 from (5, 0, 0) < 5). Greedy: from 0, w = (3, 0.5, 2):
    # 13.25 / 30 = 0.442; from 1, w = (-7, 0.5, 2): 53.25 / 70 = 0.761, whose rest 0.239 is under the 1/4
    # guard; so the shells rule splits at the midpoint (5, 0, 0) (both ends are input vertices), the first
    # Steiner point. The top edge [4, 5] = (0,0,2)-(10,0,2) then has 8 (distance 2.06 from (5, 0, 2)) and
    # (5, 0, 0) (distance 2) inside. From 4: min(9.25 / 30, 29 / 50) = 0.308; from 5: w = (-7, 0.5, 0) gives
    # 49.25 / 70 = 0.704 and w = (-5, 0, -2) gives 29 / 50 = 0.58; min 0.58, the longer piece, rest 0.42:
    # x = (4.2, 0, 2).
    res = refine_gabriel(box(), split="greedy")
    assert res.status == "converged"
    assert check_gabriel(res.mesh).ok
    steiner = res.mesh.points[len(BOX_POINTS) :]
    np.testing.assert_array_equal(steiner[0], [5.0, 0.0, 0.0])
    assert np.min(np.linalg.norm(steiner - [4.2, 0.0, 2.0], axis=1)) < 1e-12
    assert res.stats["greedy_splits"] >= 1  # at least the top edge's
    # Measured: 7 points against 10 for shells and midpoint (which split the three long edges near x = 5 and
    # cascade); only "fewer" is asserted.
    assert res.stats["steiner_points"] < refine_gabriel(box(), split="shells").stats["steiner_points"]


def test_greedy_is_deterministic():
    a = refine_gabriel(box(), split="greedy")
    b = refine_gabriel(box(), split="greedy")
    np.testing.assert_array_equal(a.mesh.points, b.mesh.points)
    np.testing.assert_array_equal(a.mesh.tets, b.mesh.tets)


def test_unknown_split_rule_is_invalid_input():
    with pytest.raises(InvalidInputError, match="greedy"):
        refine_gabriel(box(), split="sideways")  # type: ignore[arg-type]


def test_cli_split_greedy(tmp_path, capsys):
    path = write_off(tmp_path / "box.off", BOX_POINTS, [t for f in BOX_FACETS for t in f])
    out = tmp_path / "box.json"
    assert main(["refine3d", str(path), "-o", str(out), "--split", "greedy", "--json"]) == EXIT_OK
    stats = json.loads(out.read_text())["stats"]
    assert stats["status"] == "converged"
    assert stats["greedy_splits"] >= 1  # the option reached the refinement
    assert check_gabriel(read_tetmesh_json(out)).ok  # the certificate holds for the mesh as written
    assert json.loads(capsys.readouterr().out)["output"] == str(out)


# Corpus inputs on which split="greedy" converged in experiments/bench_gabriel3d.py, each within ~2 s (not the
# 4 s fandisk.off, where greedy is almost never used, nor gc_spot.ply).
CONVERGING = [
    "anchor.off",
    "example.poly",
    "joint.off",
    "rotor.off",
    "slit-2.smesh",
    "sphere.off",
    "spike-1-10.smesh",
    "wedge-1.smesh",
]


@pytest.mark.parametrize("name", CONVERGING)
def test_greedy_certificate_on_corpus(name):
    if not DATA.is_dir():
        pytest.skip("../shared/data not present")
    plc = load_plc(DATA / name)
    res = refine_gabriel(plc, split="greedy")
    assert res.status == "converged", res.stats["diagnosis"]["stop_reason"]
    assert check_gabriel(res.mesh).ok  # recomputed independently of the refinement's own certificate
    np.testing.assert_array_equal(res.mesh.points[: len(plc.points)], plc.points)
