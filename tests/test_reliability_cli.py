"""The command on the defects found by trying it as a new user: inputs written over, tracebacks on bad
options, a closed pipe, outputs that differ between identical runs, silent convex hulls and stray points, an
overlapping mesh certified, a refinement stopped by time reporting unchecked faces as not encroached."""

from __future__ import annotations

import hashlib
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import nonobtuse
from nonobtuse.certificate import check
from nonobtuse.cli import EXIT_BROKEN_PIPE, EXIT_INVALID, EXIT_OK, main
from nonobtuse.cli.mesh3d import _unchecked_as_unknown
from nonobtuse.errors import InvalidInputError
from nonobtuse.io import write_mesh
from nonobtuse.mesh import Mesh

SRC = Path(nonobtuse.__file__).resolve().parent.parent  # the imported package: src, or site-packages
SQUARE_NODE = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n"
SQUARE_POLY = SQUARE_NODE + "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n"
CORNER_TET_OFF = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"


def write(tmp_path: Path, name: str, text: str) -> Path:
    p = tmp_path / name
    p.write_text(text)
    return p


def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.mark.parametrize(
    "inputs, command",
    [
        ({"a.node": SQUARE_NODE}, ["refine", "a.node", "-o", "a.poly"]),  # a.poly writes a.node too
        ({"A.poly": SQUARE_POLY}, ["refine", "A.poly", "-o", "A.ele"]),
        ({"A.poly": SQUARE_POLY}, ["triangulate", "A.poly", "-o", "A.poly"]),
        ({"A.poly": SQUARE_POLY}, ["check", "A.poly", "--plot", "A.poly"]),
        # a .poly listing no vertices reads them from the .node beside it
        ({"B.poly": "0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", "B.node": SQUARE_NODE},
         ["refine", "B.poly", "-o", "B.ele"]),
        ({"t.off": CORNER_TET_OFF}, ["refine3d", "t.off", "-o", "t.off"]),
    ],
)
def test_an_input_is_never_written_over(tmp_path, inputs, command, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    for name, text in inputs.items():
        write(tmp_path, name, text)
    before = {name: digest(tmp_path / name) for name in inputs}
    assert main(command) == EXIT_INVALID
    assert "refusing to write over the input file" in capsys.readouterr().err
    assert {name: digest(tmp_path / name) for name in inputs} == before


def test_an_input_is_not_written_over_through_a_link(tmp_path, capsys):
    a = write(tmp_path, "a.poly", SQUARE_POLY)
    (tmp_path / "link.json").symlink_to(a)
    assert main(["refine", str(a), "-o", str(tmp_path / "link.json")]) == EXIT_INVALID
    assert a.read_text() == SQUARE_POLY


@pytest.mark.parametrize("option", [["--max-steiner", "99999999999999999999"], ["--max-steiner", "-3"],
                                    ["--max-steiner", "1.5"]])
def test_bad_budgets_are_usage_errors(tmp_path, option, capsys):
    a = write(tmp_path, "a.poly", SQUARE_POLY)
    with pytest.raises(SystemExit) as e:
        main(["refine", str(a), "-o", str(tmp_path / "o.json"), *option])
    assert e.value.code == EXIT_INVALID
    assert "expected a non-negative integer" in capsys.readouterr().err


def test_outputs_into_a_missing_folder_exit_2(tmp_path, capsys):
    a = write(tmp_path, "a.poly", SQUARE_POLY)
    assert main(["refine", str(a), "-o", str(tmp_path / "missing" / "o.json")]) == EXIT_INVALID
    assert "does not exist" in capsys.readouterr().err
    assert main(["refine", str(a), "-o", str(tmp_path)]) == EXIT_INVALID
    assert "it is a directory" in capsys.readouterr().err


def test_a_closed_pipe_ends_quietly(tmp_path):
    # check on a strip of flat triangles (every boundary side obtuse) prints a JSON report of about 1 MB, far
    # more than a pipe holds; the reader closes the pipe after the first line, so the writer meets EPIPE.
    n = 2000
    points = np.array([[float(i), 0.0] for i in range(n)] + [[i + 0.5, 0.1] for i in range(n - 1)])
    triangles = np.array([[i, i + 1, n + i] for i in range(n - 1)]
                         + [[i + 1, n + i + 1, n + i] for i in range(n - 2)])
    mesh = Mesh(points, triangles, np.array([[0, 1]]), points, np.array([[0, 1]]))
    path = tmp_path / "strip.json"
    write_mesh(mesh, path)
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    with subprocess.Popen([sys.executable, "-m", "nonobtuse.cli", "check", "--json", str(path)], env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE) as p:
        p.stdout.readline()
        p.stdout.close()
        err = p.stderr.read().decode()
        code = p.wait(timeout=120)
    assert "Traceback" not in err and "BrokenPipeError" not in err, err
    assert code == EXIT_BROKEN_PIPE


def test_identical_runs_write_identical_files(tmp_path, capsys):
    a = write(tmp_path, "a.poly", SQUARE_POLY.replace("2 1 0", "2 3 0"))  # a trapezoid with an obtuse corner
    t = write(tmp_path, "t.off", CORNER_TET_OFF)
    for command, out in ((["refine", str(a)], "a{}.json"), (["refine3d", str(t)], "t{}.json")):
        outs = [tmp_path / out.format(k) for k in range(2)]
        for o in outs:
            assert main([*command, "-o", str(o)]) == EXIT_OK
        assert outs[0].read_bytes() == outs[1].read_bytes()
        timed = tmp_path / out.format("timed")
        assert main([*command, "-o", str(timed), "--timings"]) == EXIT_OK
        assert isinstance(json.loads(timed.read_text())["stats"]["seconds"], float)


def test_an_open_polygon_is_refused_unless_the_hull_is_asked_for(tmp_path, capsys):
    # An L-shape whose closing segment (6, 1) is missing: its dangling ends are points 1 and 6 (ids).
    el = write(tmp_path, "L.poly", "6 2 0 0\n1 0 0\n2 2 0\n3 2 1\n4 1 1\n5 1 2\n6 0 2\n"
                                   "5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n0\n")
    assert main(["refine", str(el), "-o", str(tmp_path / "o.json")]) == EXIT_INVALID
    err = capsys.readouterr().err
    assert "dangling ends at point 0 (id 1 in the file)" in err and "point 5 (id 6 in the file)" in err
    assert "--convex-hull" in err
    assert main(["refine", "--convex-hull", str(el), "-o", str(tmp_path / "o.json")]) == EXIT_OK


def test_a_point_outside_the_domain_is_refused_by_name(tmp_path, capsys):
    p = write(tmp_path, "out.poly", "5 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 5 5\n4 0\n1 1 2\n2 2 3\n3 3 4\n"
                                    "4 4 1\n0\n")
    for command in (["refine", str(p), "-o", str(tmp_path / "o.json")],
                    ["triangulate", str(p), "-o", str(tmp_path / "o.json")], ["check", str(p)]):
        assert main(command) == EXIT_INVALID
        err = capsys.readouterr().err
        assert "point 4 (id 5 in the file) at (5.0, 5.0) (line 6) lies outside the domain" in err


def test_a_mesh_winding_twice_around_its_centre_is_not_certified(tmp_path, capsys):
    # Counter-clockwise triangles (0, k, k + 1) around (0,0), ring points at 72 k degrees, radius 1 + 0.05 k,
    # k = 0..9: every edge pairs up consistently, but the fan covers 648 degrees.
    ring = [[(1 + 0.05 * k) * math.cos(math.radians(72 * k)), (1 + 0.05 * k) * math.sin(math.radians(72 * k))]
            for k in range(10)]
    points = [[0.0, 0.0], *ring]
    rim = [[k, k + 1] for k in range(1, 10)]
    mesh = {"points": points, "triangles": [[0, k, k + 1] for k in range(1, 10)], "segments": rim,
            "input_points": points, "input_segments": rim}
    path = write(tmp_path, "twice.json", json.dumps(mesh))
    assert main(["check", str(path)]) == EXIT_INVALID
    assert "the triangles overlap" in capsys.readouterr().err  # the reader: its boundary crosses itself
    keys = ("points", "triangles", "segments", "input_points", "input_segments")
    arrays = [np.array(mesh[k]) for k in keys]
    with pytest.raises(InvalidInputError, match=r"around point 0 \(0, 0\) cover some directions from it"):
        check(Mesh(*arrays))  # the certificate: the fan at (0,0) covers 648 degrees


def test_unchecked_faces_are_not_reported_as_not_encroached():
    stats = {"encroached_facets": 0, "unchecked_faces": 341_970, "encroached_segments": 2,
             "unchecked_segments": 0}
    shown = _unchecked_as_unknown(stats)
    assert shown["encroached_facets"] == "at least 0, 341970 faces unchecked"
    assert shown["encroached_segments"] == 2


def test_overlapping_sheets_whose_boundaries_cross_are_refused(tmp_path, capsys):
    # Two squares of two triangles each, the second shifted by (1, 1) onto the first: every vertex's fan is
    # fine, but boundary edges cross.
    points = [[0, 0], [2, 0], [2, 2], [0, 2], [1, 1], [3, 1], [3, 3], [1, 3]]
    mesh = {"points": points, "triangles": [[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7]], "segments": [],
            "input_points": points, "input_segments": []}
    path = write(tmp_path, "overlap.json", json.dumps(mesh))
    assert main(["check", str(path)]) == EXIT_INVALID
    assert "boundary edges [1, 2] and [4, 5] cross: the triangles overlap" in capsys.readouterr().err
    mesh["points"] = mesh["input_points"] = [[x + 10 * (i >= 4), y] for i, (x, y) in enumerate(points)]
    assert main(["check", str(write(tmp_path, "apart.json", json.dumps(mesh)))]) == EXIT_OK
