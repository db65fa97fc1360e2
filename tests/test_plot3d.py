"""The 3D pictures: PNGs of the figure's size, and the artists drawn match what the exact check computed
(one red face per encroached face, one marker per encroaching vertex and per Steiner point), not pixels."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from nonobtuse import plot3d
from nonobtuse.mesh3d import check_gabriel, load_plc, refine_gabriel, tetrahedralize
from nonobtuse.mesh3d.offenders import encroaching_vertices
from test_plot import expected_size, png_size

RAMP = Path(__file__).parent / "data" / "3d" / "cad_ramp_5deg.off"  # 2 of 12 faces encroached as given


def artists(ax, gid: str) -> list:
    return [a for a in [*ax.collections, *ax.lines] if a.get_gid() == gid]


def red_faces(ax) -> int:
    (faces,) = artists(ax, plot3d.FACES_GID)
    return int(np.all(np.isclose(faces.get_facecolor(), plot3d.RED_RGBA), axis=1).sum())


def markers(ax, gid: str) -> int:
    return sum(len(a._offsets3d[0]) for a in artists(ax, gid))


@pytest.fixture(scope="module")
def ramp_stages():
    plc = load_plc(RAMP)
    before = tetrahedralize(plc, "cgal")
    after = refine_gabriel(plc)
    assert after.status == "converged"
    return [("before", before, check_gabriel(before)), ("after", after.mesh, after.report)]


def test_before_and_after_draw_what_the_check_found(tmp_path, ramp_stages):
    path = tmp_path / "ramp.png"
    fig = plot3d.plot_gabriel_stages(ramp_stages, path, title="cad_ramp_5deg.off")
    assert png_size(path) == expected_size(fig)
    main_before, close_before, main_after, close_after = fig.axes  # stage by stage: main, then close-up
    _, before, report = ramp_stages[0]
    assert not report.ok
    assert red_faces(main_before) == len(report.faces)
    assert markers(main_before, plot3d.ENCROACHERS_GID) == len(encroaching_vertices(report)[0])
    assert red_faces(main_after) == 0 and markers(main_after, plot3d.ENCROACHERS_GID) == 0
    _, after, _ = ramp_stages[1]
    assert markers(main_after, plot3d.STEINER_GID) == after.stats["steiner_points"] > 0
    # the close-ups draw the diametral circle of the deepest encroached face, in both stages
    assert len(artists(close_before, plot3d.CIRCLE_GID)) == len(artists(close_after, plot3d.CIRCLE_GID)) == 1
    assert fig._suptitle.get_text() == "cad_ramp_5deg.off"


def test_a_gabriel_mesh_has_no_close_up(tmp_path, ramp_stages):
    fig = plot3d.plot_gabriel(ramp_stages[1][1], ramp_stages[1][2], tmp_path / "after.png")
    assert len(fig.axes) == 1 and (tmp_path / "after.png").stat().st_size > 0


def test_large_surfaces_are_subsampled_keeping_every_offender(tmp_path, ramp_stages, monkeypatch):
    monkeypatch.setattr(plot3d, "MAX_DRAWN_FACES", 4)
    _, before, report = ramp_stages[0]
    fig = plot3d.plot_gabriel(before, report, tmp_path / "few.png")
    (faces,) = artists(fig.axes[0], plot3d.FACES_GID)
    step = -(-len(before.boundary_faces) // 4)
    assert red_faces(fig.axes[0]) == len(report.faces)
    assert len(faces.get_facecolor()) < len(before.boundary_faces)
    assert f"every {step}th face drawn" in fig.axes[0].get_title()
