"""3D inputs far from float64's comfortable range: the core works on points scaled exactly by a power of two,
so a corner tetrahedron gives the same result, scaled, at every scale from 1e-300 to 1e300; and flat-in-float
tets never make the reports NaN."""

from __future__ import annotations

import json

import numpy as np
import pytest

from nonobtuse.cli import EXIT_INVALID, EXIT_OK, EXIT_VIOLATIONS, main
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d import check_gabriel, load_plc, read_tetmesh_json, refine_gabriel
from nonobtuse.mesh3d.gabriel import power_of_two_exponent

CORNER_TET = np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]])
FACES = "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"


def corner_tet_off(tmp_path, scale: float):
    p = tmp_path / f"tet{scale:g}.off"
    rows = "".join(" ".join(repr(float(x)) for x in row) + "\n" for row in CORNER_TET * scale)
    p.write_text(f"OFF\n4 4 0\n{rows}{FACES}")
    return p


def uv_sphere_off(tmp_path, rings: int, sectors: int):
    points = [[0.0, 0.0, 1.0]]
    for i in range(1, rings):
        theta = np.pi * i / rings
        phi = 2 * np.pi * np.arange(sectors) / sectors
        points += [[np.sin(theta) * np.cos(f), np.sin(theta) * np.sin(f), np.cos(theta)] for f in phi]
    points.append([0.0, 0.0, -1.0])
    ring = lambda i, j: 1 + i * sectors + j % sectors  # noqa: E731
    faces = [[0, ring(0, j), ring(0, j + 1)] for j in range(sectors)]
    for i in range(rings - 2):
        for j in range(sectors):
            a, b, c, d = ring(i, j), ring(i + 1, j), ring(i + 1, j + 1), ring(i, j + 1)
            faces += [[a, b, c], [a, c, d]]
    south = len(points) - 1
    faces += [[south, ring(rings - 2, j + 1), ring(rings - 2, j)] for j in range(sectors)]
    p = tmp_path / f"uv{rings}x{sectors}.off"
    p.write_text(f"OFF\n{len(points)} {len(faces)} 0\n" + "".join(" ".join(repr(float(x)) for x in q) + "\n"
                 for q in points) + "".join(f"3 {a} {b} {c}\n" for a, b, c in faces))
    return p


def test_the_scaling_exponent_is_zero_in_the_safe_range_and_exact_outside():
    assert power_of_two_exponent(CORNER_TET * 1e6) == 0
    for scale in (1e-300, 1e-100, 1e100, 1e300):
        p = CORNER_TET * scale
        e = power_of_two_exponent(p)
        assert 0.5 <= np.abs(np.ldexp(p, -e)).max() < 1
        assert np.array_equal(np.ldexp(np.ldexp(p, -e), e), p)
    with pytest.raises(InvalidInputError, match="span too many magnitudes"):
        power_of_two_exponent(np.array([[1e300, 0, 0], [5e-324, 0, 0]]))


@pytest.mark.parametrize("scale", [1e-300, 1e-150, 1e-100, 1e100, 1e150, 1e160, 1e300])
def test_a_corner_tetrahedron_refines_the_same_at_every_scale(tmp_path, scale):
    unit = refine_gabriel(load_plc(corner_tet_off(tmp_path, 1.0)))
    result = refine_gabriel(load_plc(corner_tet_off(tmp_path, scale)))
    assert unit.status == result.status == "converged"
    e = power_of_two_exponent(result.mesh.points)
    # The same mesh up to the exact power-of-two scaling of the input: compare on the scaled-back points.
    expected = refine_gabriel(load_plc(corner_tet_off(tmp_path, float(np.ldexp(scale, -e)))))
    assert np.array_equal(np.ldexp(result.mesh.points, -e), expected.mesh.points)
    assert np.array_equal(result.mesh.tets, expected.mesh.tets)
    assert check_gabriel(result.mesh).ok  # the exact certificate of the points as returned
    assert len(result.mesh.points) == len(unit.mesh.points)


@pytest.mark.parametrize("scale", [1e-300, 1e300])
def test_refine3d_and_check3d_at_extreme_scales(tmp_path, scale, capsys):
    off = corner_tet_off(tmp_path, scale)
    out = tmp_path / "out.json"
    assert main(["refine3d", str(off), "-o", str(out), "--json"]) == EXIT_OK
    assert check_gabriel(read_tetmesh_json(out)).ok
    capsys.readouterr()
    # The face opposite the corner has the corner strictly inside its diametral sphere (at any scale).
    assert main(["check3d", str(off), "--json"]) == EXIT_VIOLATIONS
    summary = json.loads(capsys.readouterr().out)
    assert summary["tets"] == 1 and summary["encroached_facets"] == 1
    assert summary["control_volumes"]["edges"] == 6


def test_refine3d_refuses_bad_limits(tmp_path, capsys):
    off = corner_tet_off(tmp_path, 1.0)
    for option in (["--max-steiner", "-1"], ["--max-steiner", "99999999999999999999"],
                   ["--min-length", "nan"], ["--time-limit", "-1"], ["--time-limit", "inf"]):
        with pytest.raises(SystemExit) as e:
            main(["refine3d", str(off), "-o", str(tmp_path / "o.json"), *option])
        assert e.value.code == EXIT_INVALID, option
    assert "expected" in capsys.readouterr().err
    plc = load_plc(off)
    for limits in ({"max_steiner": -1}, {"min_length": float("nan")}, {"time_limit": -1.0}):
        with pytest.raises(InvalidInputError, match="must be"):
            refine_gabriel(plc, **limits)


def test_check3d_json_stays_json_when_tets_are_flat_in_floating_point(tmp_path, capsys):
    # A UV sphere 30 x 40: CGAL's Delaunay tetrahedralization has 25 tets of positive exact volume whose float
    # triple product is 0 (cocircular ring points); their circumcentres are not computable.
    off = uv_sphere_off(tmp_path, 30, 40)
    main(["check3d", str(off), "--json"])
    summary = json.loads(capsys.readouterr().out)  # json.loads accepts NaN: check there is none
    assert "NaN" not in json.dumps(summary)
    assert summary["tets"] > 0
    assert summary["control_volumes"]["flat_in_floating_point"] > 0


def test_coordinates_near_the_float64_maximum_need_no_overflowing_float(tmp_path):
    # A square pyramid with coordinates up to 1.7e308: its bounding-box diagonal (2.9e308) overflows float64,
    # the default min_length (1e-6 of it) does not. Warnings are errors in the suite.
    p = tmp_path / "pyramid.off"
    p.write_text("OFF\n5 5 0\n0 0 0\n1.7e308 0 0\n1.7e308 1.7e308 0\n0 1.7e308 0\n0 0 1.7e308\n"
                 "4 0 3 2 1\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n")
    result = refine_gabriel(load_plc(p))
    assert result.status == "converged"
    assert 2.9e302 < result.stats["min_length"] < 3e302
    assert check_gabriel(result.mesh).ok
