"""Pictures of a 3D mesh's boundary and its exact Gabriel check (matplotlib's mplot3d on Agg: offscreen, no
display and no heavy 3D package).

Each main panel draws the boundary faces (subfacets) in grey, the encroached (non-Gabriel) faces in red, the
encroached subsegments as red lines, the vertices encroaching them as red triangles and the Steiner points in
blue. Below, a close-up at true scale of the worst offender of the first stage that has one (its deepest
encroached face, else subsegment): the offending face, its diametral sphere as a wire sphere with its great
circle in the face's plane (for a face, the circle through its corners), the encroaching vertex, and the
faces around it; the same window in every stage, so a repair is seen in place. Surfaces with more than
``MAX_DRAWN_FACES`` faces are subsampled (every k-th face that is not an offender; the panel says so).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d import tetrahedralize
from nonobtuse.mesh3d.gabriel import GabrielReport
from nonobtuse.mesh3d.plc import PLC, TetMesh
from nonobtuse.mesh3d.tetrahedralize import TETGEN_DEFAULT_SWITCHES
from nonobtuse.plot import save_figure

MAX_DRAWN_FACES = 20_000  # mplot3d sorts and draws polygons in Python: about a second per 20,000
PANEL_IN = 5.5
LEGEND_COLUMNS_PER_PANEL = 2  # legend entries side by side per panel width
GREY, RED, BLUE = "0.8", "tab:red", "tab:blue"
# gids of the artists, for inspection: the faces (one collection per panel), the encroaching vertices, the
# Steiner points, the encroached subsegments, the great circle of the diametral sphere
FACES_GID, ENCROACHERS_GID, STEINER_GID, SEGMENTS_GID, CIRCLE_GID = (
    "boundary-faces", "encroaching-vertices", "steiner-points", "encroached-subsegments", "diametral-circle")
RED_RGBA = (0.84, 0.15, 0.16, 0.95)

Stage = tuple[str, TetMesh, GabrielReport]


def unrepaired_mesh(plc: PLC) -> tuple[TetMesh, str]:
    """The mesh a "before" panel shows for ``plc`` (the demo's, refine3d's) and what made it: TetGen with its
    default switches when the ``tetgen`` package is installed (the 3d extra) and succeeds, else the cgal
    backend. Raises what the cgal backend raises on an input it refuses."""
    try:
        return tetrahedralize(plc, "tetgen"), f"TetGen -{TETGEN_DEFAULT_SWITCHES}"
    except ImportError:
        why = "TetGen not installed: pip install 'nonobtuse[3d]'"
    except InvalidInputError:
        why = "TetGen failed on this input"
    return tetrahedralize(plc, "cgal"), f"the cgal backend ({why})"


def _steiner_points(mesh: TetMesh) -> np.ndarray:
    """The Steiner points (s, 3) of ``mesh``: the last ``stats["steiner_points"]`` (none if unknown)."""
    s = int(mesh.stats.get("steiner_points") or 0)
    return np.asarray(mesh.points, dtype=np.float64)[len(mesh.points) - s:] if s else np.zeros((0, 3))


def _sphere(mesh: TetMesh, report: GabrielReport) -> tuple[np.ndarray, float, np.ndarray | None, int] | None:
    """The diametral sphere of the worst offender of ``report`` (deepest face, else deepest subsegment): its
    centre (3,), radius, the unit normal of the face (None for a subsegment) and the encroaching vertex; None
    when the mesh is Gabriel. Floating point: for drawing only."""
    points = np.asarray(mesh.points, dtype=np.float64)
    if len(report.faces):
        i = int(np.argmax(report.face_depths))
        a, b, c = points[np.asarray(mesh.boundary_faces)[report.faces[i]]]
        u, v = b - a, c - a
        n = np.cross(u, v)
        centre = a + np.cross(np.dot(u, u) * v - np.dot(v, v) * u, n) / (2 * np.dot(n, n))
        return centre, float(np.linalg.norm(a - centre)), n / np.linalg.norm(n), int(report.face_vertices[i])
    if len(report.segments):
        i = int(np.argmax(report.segment_depths))
        a, b = points[np.asarray(mesh.segments)[report.segments[i]]]
        return (a + b) / 2, float(np.linalg.norm(b - a)) / 2, None, int(report.segment_vertices[i])
    return None


def _drawn_faces(mesh: TetMesh, report: GabrielReport, window: tuple[np.ndarray, float] | None
                 ) -> tuple[np.ndarray, np.ndarray, int]:
    """The rows of mesh.boundary_faces to draw, whether each is encroached, and the subsampling step k (1:
    every face). In a window (centre, half-side): the faces with every corner inside it."""
    faces = np.asarray(mesh.boundary_faces, dtype=np.int64).reshape(-1, 3)
    bad = np.zeros(len(faces), dtype=bool)
    bad[report.faces] = True
    rows = np.arange(len(faces))
    if window is not None:
        centre, half = window
        corners = np.asarray(mesh.points, dtype=np.float64)[faces]
        rows = rows[np.all(np.abs(corners - centre).max(axis=2) <= half, axis=1)]
    step = max(1, -(-len(rows) // MAX_DRAWN_FACES))
    if step > 1:  # keep every offender, every k-th other face
        rows = rows[bad[rows] | (np.arange(len(rows)) % step == 0)]
    return rows, bad[rows], step


def _draw(ax: Any, mesh: TetMesh, report: GabrielReport, window: tuple[np.ndarray, float] | None) -> int:
    """One 3D panel of ``mesh`` (whole, or the cube ``window``); returns the subsampling step."""
    from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection

    points = np.asarray(mesh.points, dtype=np.float64)
    rows, bad, step = _drawn_faces(mesh, report, window)
    polys = points[np.asarray(mesh.boundary_faces, dtype=np.int64).reshape(-1, 3)[rows]]
    colours = np.where(bad[:, None], np.array(RED_RGBA), np.array([0.8, 0.8, 0.8, 0.45]))
    ax.add_collection3d(Poly3DCollection(polys, facecolors=colours, edgecolors=(0.35, 0.35, 0.35, 0.5),
                                         linewidths=0.15 if window is None else 0.5, gid=FACES_GID))
    segments = points[np.asarray(mesh.segments, dtype=np.int64).reshape(-1, 2)[report.segments]]
    if window is not None:  # the subsegments with both ends in the window
        segments = segments[np.all(np.abs(segments - window[0]).max(axis=2) <= window[1], axis=1)]
    if len(segments):
        ax.add_collection3d(Line3DCollection(segments, colors=RED, linewidths=1.6, gid=SEGMENTS_GID))
    steiner = _steiner_points(mesh)
    encroachers = points[np.unique(np.concatenate([report.face_vertices, report.segment_vertices]))]
    if window is not None:
        centre, half = window
        steiner = steiner[np.abs(steiner - centre).max(axis=1) <= half]
        encroachers = encroachers[np.abs(encroachers - centre).max(axis=1) <= half]
    if len(steiner):
        ax.scatter(*steiner.T, s=2 if window is None else 4, color=BLUE, depthshade=False, gid=STEINER_GID)
    if len(encroachers):
        ax.scatter(*encroachers.T, s=14 if window is None else 40, marker="^", color=RED, depthshade=False,
                   gid=ENCROACHERS_GID)
    lo, hi = (points.min(axis=0), points.max(axis=0)) if window is None else (window[0] - window[1],
                                                                              window[0] + window[1])
    for set_lim, a, b in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), lo, hi):
        set_lim(a, b)
    ax.set_box_aspect(np.maximum(hi - lo, 1e-3 * float(np.max(hi - lo))))  # true scale
    ax.tick_params(labelsize=6)
    return step


def _draw_sphere(ax: Any, centre: np.ndarray, radius: float, normal: np.ndarray | None) -> None:
    """The diametral sphere as a light wire sphere, and its great circle in the face's plane (dashed)."""
    u, v = np.mgrid[0:2 * np.pi:25j, 0:np.pi:13j]
    x, y, z = (centre[:, None, None] + radius * np.array([np.cos(u) * np.sin(v), np.sin(u) * np.sin(v),
                                                          np.cos(v)]))
    ax.plot_wireframe(x, y, z, color=RED, linewidth=0.25, alpha=0.35)
    if normal is not None:
        e1 = np.cross(normal, [1.0, 0, 0] if abs(normal[0]) < 0.9 else [0, 1.0, 0])
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(normal, e1)
        t = np.linspace(0, 2 * np.pi, 121)
        circle = centre + radius * (np.cos(t)[:, None] * e1 + np.sin(t)[:, None] * e2)
        ax.plot(*circle.T, color=RED, linestyle="--", linewidth=1.0, gid=CIRCLE_GID)


def _status(report: GabrielReport) -> str:
    if report.ok:
        return "Gabriel: every boundary face and subsegment (exact)"
    return (f"encroached: {len(report.faces):,} of {report.n_faces:,} faces, {len(report.segments):,} "
            "subsegments")


def plot_gabriel_stages(stages: list[Stage], path: str | Path, *, title: str = "") -> Any:
    """Writes a picture of one or more stages of a 3D mesh (``(label, mesh, report)``: e.g. the input's
    tetrahedralization before and the refined mesh after, each with its :func:`check_gabriel` report) to
    ``path`` (atomically; any format matplotlib knows, by suffix; PNG at 150 dpi): one main panel per stage,
    then, when a stage has an offender, a close-up per stage at true scale on the worst offender of the
    first stage that has one (see the module docstring). ``title`` (e.g. the input's file name) heads the
    figure. Returns the matplotlib Figure (closed; its artists are for inspection). Cost: O(f log f) for f
    faces drawn (at most ``MAX_DRAWN_FACES`` non-offending faces per panel)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    found = [(i, s) for i, s in enumerate(_sphere(m, r) for _, m, r in stages) if s is not None]
    origin, worst = found[0] if found else (-1, None)  # the first stage with an offender, and its worst
    rows = 2 if worst is not None else 1
    fig = plt.figure(figsize=(PANEL_IN * len(stages), PANEL_IN * rows + 0.6), constrained_layout=True)
    for i, (label, mesh, report) in enumerate(stages):
        ax = fig.add_subplot(rows, len(stages), i + 1, projection="3d")
        step = _draw(ax, mesh, report, None)
        shown = "" if step == 1 else f", every {step}th face drawn (all offenders)"
        ax.set_title(f"{label}\n{_status(report)}{shown}", fontsize=8)
        if worst is None:
            continue
        centre, radius, normal, vertex = worst
        ax = fig.add_subplot(rows, len(stages), len(stages) + i + 1, projection="3d")
        _draw(ax, mesh, report, (centre, 1.3 * radius))
        _draw_sphere(ax, centre, radius, normal)
        if i == origin:
            ax.scatter(*np.asarray(mesh.points, dtype=np.float64)[vertex], s=120, marker="*", color=RED,
                       edgecolors="black", depthshade=False)
        ax.set_title(f"{label}: the deepest offender, true scale\n(diametral sphere radius {radius:.3g}, "
                     f"encroached by vertex {vertex})" if i == origin else f"{label}: the same place, true "
                     f"scale\n(where {stages[origin][0]} had its deepest offender)", fontsize=8)
    return save_figure(fig, path, _legend_entries(stages, worst is not None), title, fontsize=7,
                       ncols=LEGEND_COLUMNS_PER_PANEL * len(stages))


def _legend_entries(stages: list[Stage], sphere: bool) -> tuple[list[Any], list[str]]:
    """Legend handles for every kind of artist some panel draws."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    entries: list[tuple[Any, str]] = [(Patch(facecolor=GREY, edgecolor="0.35"), "boundary faces")]
    if any(not r.ok for _, _, r in stages):
        entries += [(Patch(facecolor=RED), "non-Gabriel face"),
                    (Line2D([], [], color=RED, linewidth=1.6), "encroached subsegment"),
                    (Line2D([], [], marker="^", color=RED, linestyle=""), "encroaching vertex")]
    if any(len(_steiner_points(m)) for _, m, _ in stages):
        entries.append((Line2D([], [], marker="o", color=BLUE, linestyle="", markersize=3), "Steiner points"))
    if sphere:
        star = Line2D([], [], marker="*", color=RED, markeredgecolor="black", linestyle="", markersize=9)
        circle = Line2D([], [], color=RED, linestyle="--")
        entries += [(circle, "diametral sphere, circle in the face's plane"),
                    (star, "its deepest encroaching vertex")]
    return [h for h, _ in entries], [t for _, t in entries]


def plot_gabriel(mesh: TetMesh, report: GabrielReport, path: str | Path, *, title: str = "") -> Any:
    """:func:`plot_gabriel_stages` of the one stage ``mesh`` with its ``report``."""
    return plot_gabriel_stages([("mesh", mesh, report)], path, title=title)
