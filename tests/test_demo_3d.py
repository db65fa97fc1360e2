"""The demo's 3D part: the bundled CAD part is checked, repaired and certified (demo --plot's pictures are
checked in test_plot.py, the light install in test_cli_first_use.py)."""

from __future__ import annotations

import sys

from nonobtuse import demo
from nonobtuse.mesh3d import check_gabriel, load_plc, refine_gabriel
from nonobtuse.plot3d import unrepaired_mesh


def test_the_part_is_bundled_with_its_provenance():
    assert demo.PART.is_file()
    sources = (demo.PART.parent / "SOURCES.md").read_text()
    assert demo.PART.name in sources and "CC0" in sources


def test_run_part_reports_the_exact_checks_before_and_after():
    lines: list[str] = []
    demo.run_part(lines.append)
    plc = load_plc(demo.PART)
    before, how = unrepaired_mesh(plc)
    report = check_gabriel(before)
    assert not report.ok  # the demo starts with a real problem
    after = refine_gabriel(plc)
    assert after.status == "converged" and check_gabriel(after.mesh).ok
    text = "\n".join(lines)
    assert f"before: {how}:" in text
    assert (f"non-Gabriel (exact): {len(report.faces)} of {report.n_faces} boundary faces, "
            f"{len(report.segments)} of {report.n_segments} subsegments") in text
    assert (f"non-Gabriel (exact): 0 of {len(after.mesh.boundary_faces)} boundary faces, 0 of "
            f"{len(after.mesh.segments)} subsegments") in text
    assert f"Steiner points: {after.stats['steiner_points']} (" in text
    assert "negative control-volume couplings: 0 of" in text


def test_without_tetgen_the_cgal_backend_tetrahedralizes_the_part(monkeypatch):
    monkeypatch.setitem(sys.modules, "tetgen", None)  # as in the light install (the demo extra)
    mesh, how = unrepaired_mesh(load_plc(demo.PART))
    assert how.startswith("the cgal backend (TetGen not installed") and len(mesh.tets) > 0
    assert mesh.stats["backend"] == "cgal"
