"""Writing tet meshes: JSON round trip bit for bit, meshio formats, atomic writes."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d import TetMesh, read_tetmesh_json, write_tetmesh


def small_mesh() -> TetMesh:
    # two tets sharing face (1, 2, 3); 0.1 and 1/3 are not exact in binary: the round trip must keep every bit
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.1, 1 / 3, 1.0]])
    tets = np.array([[0, 1, 2, 3], [1, 4, 2, 3]])
    faces = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 4]])
    return TetMesh(points, tets, faces, np.array([0, 1, 2, 3]), np.array([[0, 1], [1, 2]]),
                   stats={"status": "converged", "steiner_points": 1, "seconds": 0.5, "note": np.int64(3)})


def test_json_round_trip_is_exact_and_has_the_schema(tmp_path):
    m = small_mesh()
    write_tetmesh(m, tmp_path / "m.json")
    d = json.loads((tmp_path / "m.json").read_text())
    assert set(d) >= {"points", "tets", "boundary_faces", "segments", "stats"}
    # keys absent from the mesh's stats are written as null
    assert d["stats"]["encroached_facets"] is None and d["stats"]["status"] == "converged"
    r = read_tetmesh_json(tmp_path / "m.json")
    assert np.array_equal(r.points, m.points) and r.points[4, 1] == 1 / 3
    for name in ("tets", "boundary_faces", "face_markers", "segments"):
        assert np.array_equal(getattr(r, name), getattr(m, name))
    assert r.stats["note"] == 3


@pytest.mark.parametrize("suffix", [".vtu", ".msh"])
def test_meshio_formats(tmp_path, suffix):
    import meshio

    m = small_mesh()
    write_tetmesh(m, tmp_path / f"m{suffix}")
    r = meshio.read(tmp_path / f"m{suffix}")
    assert np.array_equal(r.points, m.points)
    assert np.array_equal(r.cells_dict["tetra"], m.tets)
    assert np.array_equal(r.cells_dict["triangle"], m.boundary_faces)


def test_failed_write_leaves_the_old_file_and_no_temporary(tmp_path, monkeypatch):
    import meshio

    def half_write(path, *args, **kwargs):  # writes part of the file, then fails like a full disk
        Path(path).write_text("partial")
        raise OSError("disk full")

    monkeypatch.setattr(meshio, "write", half_write)
    target = tmp_path / "m.vtu"
    target.write_text("old")
    with pytest.raises(OSError, match="disk full"):
        write_tetmesh(small_mesh(), target)
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["m.vtu"]


def test_unknown_suffix_and_bad_json(tmp_path):
    with pytest.raises(InvalidInputError, match="unknown mesh format"):
        write_tetmesh(small_mesh(), tmp_path / "m.obj")
    (tmp_path / "bad.json").write_text('{"points": []}')
    with pytest.raises(InvalidInputError, match="not a 3D mesh JSON file"):
        read_tetmesh_json(tmp_path / "bad.json")
