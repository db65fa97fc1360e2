"""The 2D pictures: files written as PNGs of the figure's size, and the artists drawn match what the check
computed (one diametral circle per offending edge, one marker per Steiner point), not pixels."""

from __future__ import annotations

import json
import struct

import numpy as np
import pytest

from nonobtuse.certificate import check
from nonobtuse.cli import EXIT_OK, EXIT_VIOLATIONS, main
from nonobtuse.domain import Domain
from nonobtuse.mesh import Mesh
from nonobtuse.plot import DIAMETRAL_GID, MAX_CLOSE_UPS, plot_check, plot_stages
from nonobtuse.refinement import refine
from nonobtuse.triangulation import triangulate

DPI = 150


def png_size(path) -> tuple[int, int]:
    """Width and height from the PNG's IHDR chunk (bytes 16-24), after checking the signature."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", data[16:24])


def expected_size(fig) -> tuple[int, int]:
    w, h = fig.get_size_inches() * DPI
    return round(w), round(h)


def circles(ax) -> int:
    """The number of diametral circles drawn on ``ax``."""
    return sum(len(c.get_offsets()) for c in ax.collections if c.get_gid() == DIAMETRAL_GID)


def offending_edges(report) -> int:
    return len({tuple(sorted(o.edge)) for o in report.offenders})


def sliver() -> Mesh:
    """A 1e-4 x 2.5e-7 rectangle with a point in the middle of its top side: the bottom side faces that point
    at an angle of nearly 180 degrees, the two top halves face the bottom corners at nearly 90 + 0 degrees."""
    pts = np.array([[0, 0], [1e-4, 0], [1e-4, 2.5e-7], [0, 2.5e-7], [5e-5, 2.5e-7]])
    seg = np.array([[0, 1], [1, 2], [2, 4], [4, 3], [3, 0]])
    tri = np.array([[0, 1, 4], [1, 2, 4], [0, 4, 3]])
    return Mesh(points=pts, triangles=tri, segments=seg, input_points=pts, input_segments=seg)


def test_sliver_picture_has_one_circle_per_offending_edge_and_true_scale_close_ups(tmp_path):
    mesh = sliver()
    report = check(mesh)
    report.source = str(tmp_path / "deep" / "folder" / "sliver.json")
    assert report.offenders
    path = tmp_path / "sliver.png"
    fig = plot_check(mesh, report, path)
    assert png_size(path) == expected_size(fig)
    main_ax, *close_ups = fig.axes
    assert circles(main_ax) == offending_edges(report)
    assert len(close_ups) == min(MAX_CLOSE_UPS, offending_edges(report))
    assert all("true scale" in ax.get_title() for ax in close_ups)
    # each close-up frames its edge's diametral circle: the apex of the worst offender is inside the window
    worst = report.largest_obtuse
    x0, x1 = close_ups[0].get_xlim()
    y0, y1 = close_ups[0].get_ylim()
    ax_, ay_ = mesh.points[worst.apex]
    assert x0 < ax_ < x1 and y0 < ay_ < y1
    assert x1 - x0 == pytest.approx(y1 - y0)  # square window at true scale
    assert fig.get_suptitle() == "sliver.json"  # the file name, never the folder


def test_refine_before_after_marks_every_steiner_point(tmp_path):
    # An obtuse triangle: the base (0,0)-(4,0) faces (1,1) at 135 degrees.
    domain = Domain(points=np.array([[0.0, 0], [4, 0], [1, 1]]), segments=np.array([[0, 1], [1, 2], [2, 0]]))
    before, result = triangulate(domain), refine(domain)
    steiner = len(result.mesh.points) - len(domain.points)
    assert result.converged and steiner > 0
    path = tmp_path / "stages.png"
    fig = plot_stages([("before", before, check(before)), ("after", result.mesh, check(result.mesh))], path)
    assert png_size(path) == expected_size(fig)
    ax_before, ax_after = fig.axes[:2]
    assert circles(ax_before) == offending_edges(check(before)) > 0
    assert circles(ax_after) == 0
    blue = [line for line in ax_after.get_lines() if line.get_color() == "tab:blue"]
    assert sum(len(line.get_xdata()) for line in blue) == steiner
    labels = [t.get_text() for t in fig.legends[0].get_texts()]
    assert {"Steiner points", "its diametral circle", "obtuse apex"} <= set(labels)
    # close-ups: the same windows before and after
    rows = fig.axes[2:]
    assert len(rows) == 2 * min(MAX_CLOSE_UPS, offending_edges(check(before)))
    half = len(rows) // 2
    assert [ax.get_xlim() for ax in rows[:half]] == [ax.get_xlim() for ax in rows[half:]]


def test_exaggeration_is_labelled_and_leaves_the_circles_to_the_close_ups(tmp_path):
    mesh = sliver()
    report = check(mesh)
    fig = plot_check(mesh, report, tmp_path / "sliver.png", vertical_exaggeration=100.0)
    main_ax, *close_ups = fig.axes
    assert "vertical exaggeration x100" in main_ax.get_title()
    assert circles(main_ax) == 0
    assert circles(close_ups[0]) == offending_edges(report)  # the window frames the only offending edge


def test_interface_edge_obtuse_on_both_sides_gets_one_circle(tmp_path):
    # The interface (0,0)-(4,0) faces (2,0.5) above and (2,-0.5) below, both obtuse: two offenders, one edge.
    pts = np.array([[0.0, 0], [4, 0], [2, 0.5], [2, -0.5]])
    seg = np.array([[0, 1], [1, 2], [2, 0], [0, 3], [3, 1]])
    mesh = Mesh(points=pts, triangles=np.array([[0, 1, 2], [0, 3, 1]]), segments=seg, input_points=pts,
                input_segments=seg)
    report = check(mesh)
    assert len(report.offenders) == 2
    fig = plot_check(mesh, report, tmp_path / "interface.png")
    assert circles(fig.axes[0]) == offending_edges(report) == 1


def test_figure_height_follows_the_aspect(tmp_path):
    square = Domain(points=np.array([[0.0, 0], [1, 0], [1, 1], [0, 1]]),
                    segments=np.array([[0, 1], [1, 2], [2, 3], [3, 0]]))
    strip = Domain(points=square.points * [1, 0.1], segments=square.segments)
    heights = []
    for name, d in (("square", square), ("strip", strip)):
        m = triangulate(d)
        heights.append(plot_check(m, check(m), tmp_path / f"{name}.png").get_size_inches()[1])
    assert heights[0] > heights[1]


def test_exaggeration_must_be_positive(tmp_path):
    mesh = sliver()
    with pytest.raises(ValueError, match="exaggeration"):
        plot_check(mesh, check(mesh), tmp_path / "x.png", vertical_exaggeration=0.0)
    assert not (tmp_path / "x.png").exists()


def test_cli_refine_and_check_and_demo_write_pictures(tmp_path, capsys):
    domain = tmp_path / "obtuse.json"
    domain.write_text(json.dumps({"points": [[0, 0], [4, 0], [1, 1]], "segments": [[0, 1], [1, 2], [2, 0]]}))
    assert main(["refine", str(domain), "-o", str(tmp_path / "out.json"), "--plot",
                 str(tmp_path / "refine.png"), "--exaggeration", "3"]) == EXIT_OK
    assert main(["check", str(domain), "--plot", str(tmp_path / "check.png")]) == EXIT_VIOLATIONS
    assert main(["demo", "--plot", str(tmp_path / "demo.png")]) == EXIT_OK
    assert f"picture -> {tmp_path / 'demo_3d.png'}" in capsys.readouterr().out  # the demo's 3D part beside
    for name in ("refine", "check", "demo", "demo_3d"):
        width, height = png_size(tmp_path / f"{name}.png")
        assert width > 0 and height > 0
    with pytest.raises(SystemExit) as usage:
        main(["check", str(domain), "--plot", str(tmp_path / "zero.png"), "--exaggeration", "0"])
    assert usage.value.code == 2 and not (tmp_path / "zero.png").exists()
