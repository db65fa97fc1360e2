"""What check3d, refine3d, check and export print and write besides the mesh: readable text, --plot, the
offenders .vtu, --quiet, and progress only on a terminal."""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path

import numpy as np
import pytest

from mesh3d_shapes import CUBE_POINTS, CUBE_TRIANGLES, TET_TRIANGLES, write_off
from nonobtuse.cli import EXIT_OK, EXIT_VIOLATIONS, main
from nonobtuse.mesh3d import check_gabriel, load_plc, tetrahedralize
from nonobtuse.mesh3d.offenders import encroaching_vertices
from test_cli_first_use import _Terminal
from test_mesh3d_cli import LOW_TET

RAMP = Path(__file__).parent / "data" / "3d" / "cad_ramp_5deg.off"


def test_check3d_text_is_aligned_lines_and_a_verdict(tmp_path, capsys):
    low_tet = write_off(tmp_path / "low.off", LOW_TET, TET_TRIANGLES.tolist())  # the apex encroaches the base
    cube = write_off(tmp_path / "cube.off", CUBE_POINTS, CUBE_TRIANGLES.tolist())
    assert main(["check3d", str(low_tet)]) == EXIT_VIOLATIONS
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == "low.off: 4 points, 1 tets, 4 boundary faces"  # the file name, not the folder
    assert lines[-1].startswith("  NOT OK: 1 boundary faces and ")
    pairs = lines[1:-1]
    key_then_gap = re.compile(r"  \S+(?: \S+)*  +")  # the key (single spaces inside) and the gap after it
    assert len({key_then_gap.match(line).end() for line in pairs}) == 1  # the values form one column
    assert any(line.split("  ")[1] == "boundary faces" and "1 of 4 encroached; deepest: face" in line
               for line in pairs)
    assert not any("{" in line for line in lines)  # no dict dumps
    assert main(["check3d", str(cube)]) == EXIT_OK
    assert capsys.readouterr().out.splitlines()[-1] == \
        "  OK: every boundary face and subsegment has an empty diametral sphere (exact)"


def test_refine3d_text_says_status_steiner_points_and_verdict(tmp_path, capsys):
    assert main(["refine3d", str(RAMP), "-o", str(tmp_path / "r.json")]) == EXIT_OK
    out = capsys.readouterr().out
    stats = json.loads((tmp_path / "r.json").read_text())["stats"]
    assert out.splitlines()[0].startswith(f"cad_ramp_5deg.off -> {tmp_path / 'r.json'}: converged, ")
    value = {line.split("  ")[1]: line.split("  ")[-1].strip() for line in out.splitlines()[1:]
             if len(line.split("  ")) > 2 and line.split("  ")[1]}
    assert value["Steiner points"].startswith(f"{stats['steiner_points']:,} (")
    assert value["encroached faces"] == "0" and value["encroached subsegments"] == "0"
    assert "smallest input angle" in value and "{" not in out
    assert out.splitlines()[-1].startswith("  OK: ")


def test_check3d_offenders_vtu_has_the_checks_offenders(tmp_path, capsys):
    import meshio

    vtu = tmp_path / "off.vtu"
    assert main(["check3d", str(RAMP), "--json"]) == EXIT_VIOLATIONS
    summary = json.loads(capsys.readouterr().out)
    assert main(["check3d", str(RAMP), "--offenders", str(vtu)]) == EXIT_VIOLATIONS
    m = meshio.read(vtu)
    cells = {c.type: len(c.data) for c in m.cells}
    report = check_gabriel(tetrahedralize(load_plc(RAMP), "cgal"))  # what check3d checked
    assert cells == {"triangle": summary["encroached_facets"], "line": summary["encroached_segments"],
                     "vertex": len(encroaching_vertices(report)[0])}
    assert f"offenders ({sum(cells.values())} cells) -> {vtu}" in capsys.readouterr().err
    rows = dict(zip([c.type for c in m.cells], m.cell_data["row"]))
    assert sorted(rows["triangle"]) == sorted(report.faces)
    depth = m.cell_data["depth"][0]
    assert np.all((depth > 0) & (depth <= 1))
    # the points are the mesh points the offenders use, each with its index in the mesh
    mesh = tetrahedralize(load_plc(RAMP), "cgal")
    assert np.array_equal(m.points, mesh.points[m.point_data["vertex"]])


def test_no_offenders_no_file(tmp_path, capsys):
    cube = write_off(tmp_path / "cube.off", CUBE_POINTS, CUBE_TRIANGLES.tolist())
    vtu = tmp_path / "none.vtu"
    assert main(["check3d", str(cube), "--offenders", str(vtu)]) == EXIT_OK
    assert not vtu.exists() and "no offenders (Gabriel)" in capsys.readouterr().err


def test_plots_are_written(tmp_path, capsys):
    for argv in (["check3d", str(RAMP)], ["refine3d", str(RAMP), "-o", str(tmp_path / "r.json")]):
        png = tmp_path / f"{argv[0]}.png"
        main([*argv, "--plot", str(png)])
        assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and png.stat().st_size > 10_000
        assert f"picture -> {png}" in capsys.readouterr().err


def test_picture_outputs_never_overwrite_the_input(tmp_path, capsys):
    off = tmp_path / "a.off"
    off.write_bytes(RAMP.read_bytes())
    assert main(["check3d", str(off), "--plot", str(off)]) == 2
    assert "refusing to write over the input" in capsys.readouterr().err
    assert off.read_bytes() == RAMP.read_bytes()


def refine3d_stderr(monkeypatch, tmp_path, *options: str, tty: bool) -> tuple[str, str]:
    err = _Terminal()
    if not tty:
        monkeypatch.setattr(err, "isatty", lambda: False)
    monkeypatch.setattr(sys, "stderr", err)
    out = tmp_path / "out.txt"
    monkeypatch.setattr(sys, "stdout", out.open("w"))
    main(["refine3d", str(RAMP), "-o", str(tmp_path / "r.json"), *options])
    sys.stdout.close()
    return "".join(err.lines), out.read_text()


@pytest.mark.parametrize(("options", "tty", "progress"), [
    ((), True, True), ((), False, False), (("--quiet",), True, False), (("--json",), True, True)])
def test_refine3d_progress_only_on_a_terminal(monkeypatch, tmp_path, options, tty, progress):
    err, out = refine3d_stderr(monkeypatch, tmp_path, *options, tty=tty)
    assert ("nonobtuse: refining" in err and "refine_gabriel: " in err) == progress
    assert ("refine_gabriel: " in err) == progress
    if "--json" in options:
        json.loads(out)  # progress never in the JSON
    if "--quiet" in options:
        assert out == ""


def test_quiet_prints_nothing_on_success(tmp_path, capsys):
    la = Path(__file__).parent / "data" / "box.poly"
    mesh = tmp_path / "box.json"
    main(["refine", str(la), "-o", str(mesh), "--convex-hull", "-q"])
    assert main(["check", str(mesh), "-q"]) == EXIT_OK
    assert main(["export", str(mesh), "-o", str(tmp_path / "box.uge"), "-q"]) == EXIT_OK
    assert main(["refine", str(la), "-o", str(tmp_path / "r.uge"), "--convex-hull", "-q"]) == EXIT_OK
    assert main(["refine3d", str(RAMP), "-o", str(tmp_path / "r3.uge"), "-q"]) == EXIT_OK
    assert capsys.readouterr() == ("", "")  # not even the export diagnostics
    assert all((tmp_path / name).stat().st_size > 0 for name in ("box.uge", "r.uge", "r3.uge"))
