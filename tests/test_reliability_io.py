"""Readers and writers on nasty inputs: byte order marks, huge counts, deep JSON, numbers float64 cannot hold,
OBJ index 0, a self-crossing facet; output paths that cannot be written; file modes under the umask."""

from __future__ import annotations

import json
import os
import stat

import numpy as np
import pytest

from nonobtuse.errors import InvalidInputError
from nonobtuse.io import load_domain, read_mesh, write_mesh
from nonobtuse.mesh import Mesh
from nonobtuse.mesh3d import load_plc

CORNER_TET_OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"


def triangle_mesh() -> Mesh:
    points = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    segments = np.array([[0, 1], [1, 2], [2, 0]])
    return Mesh(points, np.array([[0, 1, 2]]), segments, points, segments)


def test_a_byte_order_mark_is_not_part_of_the_first_token(tmp_path):
    plain, bom = tmp_path / "plain.obj", tmp_path / "bom.obj"
    plain.write_text(CORNER_TET_OBJ)
    bom.write_bytes(b"\xef\xbb\xbf" + CORNER_TET_OBJ.encode())
    a, b = load_plc(plain), load_plc(bom)
    assert len(b.points) == 4
    assert np.array_equal(a.points, b.points) and np.array_equal(a.triangles, b.triangles)
    node = tmp_path / "square.node"
    node.write_bytes(b"\xef\xbb\xbf4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n")
    assert load_domain(node).points.tolist() == [[0, 0], [1, 0], [1, 1], [0, 1]]


def test_a_huge_declared_count_is_an_early_end_not_a_memory_error(tmp_path):
    p = tmp_path / "huge.node"
    p.write_text("1000000000000 2 0 0\n1 0 0\n2 1 0\n3 0 1\n")
    with pytest.raises(InvalidInputError, match=r"huge.node:4: the file ends early: expected vertex 4 of 1"):
        load_domain(p)


def test_json_nested_too_deeply_is_invalid_input(tmp_path):
    p = tmp_path / "deep.json"
    p.write_text("[" * 100_000 + "]" * 100_000)
    with pytest.raises(InvalidInputError, match="nested too deeply"):
        load_domain(p)


def test_a_mesh_with_a_number_too_large_for_float64_is_refused(tmp_path):
    p = tmp_path / "inf.json"
    write_mesh(triangle_mesh(), p)
    p.write_text(p.read_text().replace('"points":[[0.0,0.0],[1.0,0.0]', '"points":[[0.0,0.0],[1e400,0.0]', 1))
    with pytest.raises(InvalidInputError, match=r"points\[1\] = \[inf, 0.0\] is not finite"):
        read_mesh(p)


def test_obj_index_zero_is_named_as_such(tmp_path):
    p = tmp_path / "zero.obj"
    p.write_text(CORNER_TET_OBJ.replace("f 1 3 2", "f 0 3 2"))
    with pytest.raises(InvalidInputError, match=r"zero.obj:5: face vertex index 0: OBJ indices start at 1"):
        load_plc(p)


def test_a_self_crossing_quad_is_reported_as_crossing(tmp_path):
    # (0,0,0) -> (1,1,0) -> (1,0,0) -> (0,1,0) is a bow tie: zero signed area, its edges cross at (1/2, 1/2).
    p = tmp_path / "bowtie.off"
    p.write_text("OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n4 0 3 1 2\n3 0 1 4\n3 1 2 4\n")
    with pytest.raises(InvalidInputError, match=r"bowtie.off:8\): segment .* crosses another segment") as e:
        load_plc(p)
    assert "duplicate" not in str(e.value)


@pytest.mark.parametrize("suffix", [".json", ".node", ".vtu"])
def test_outputs_into_a_missing_folder_or_onto_a_directory_are_invalid_input(tmp_path, suffix):
    with pytest.raises(InvalidInputError, match="the folder .*missing does not exist"):
        write_mesh(triangle_mesh(), tmp_path / "missing" / f"m{suffix}")
    (tmp_path / f"d{suffix}").mkdir()
    with pytest.raises(InvalidInputError, match="it is a directory"):
        write_mesh(triangle_mesh(), tmp_path / f"d{suffix}")


@pytest.mark.parametrize("umask", [0o022, 0o002, 0o077])
def test_written_files_get_the_mode_the_umask_gives(tmp_path, umask):
    previous = os.umask(umask)
    try:
        written = [p for name in ("m.node", "m.json") for p in write_mesh(triangle_mesh(), tmp_path / name)]
    finally:
        os.umask(previous)
    for path in written:
        assert stat.S_IMODE(path.stat().st_mode) == 0o666 & ~umask, path
    assert json.loads((tmp_path / "m.json").read_text())["triangles"] == [[0, 1, 2]]


def test_an_infinite_coordinate_is_refused_before_any_arithmetic_warns(tmp_path):
    # 1e400 reads as infinity; the quad's normal would be computed from it (RuntimeWarnings, errors here).
    p = tmp_path / "inf.off"
    p.write_text("OFF\n5 5 0\n0 0 0\n1e400 0 0\n1 1 0\n0 1 0\n0 0 1\n4 0 3 2 1\n3 0 1 4\n3 1 2 4\n3 2 3 4\n"
                 "3 3 0 4\n")
    with pytest.raises(InvalidInputError, match=r"vertex 1 has a NaN or infinite coordinate \[inf, 0.0"):
        load_plc(p)
