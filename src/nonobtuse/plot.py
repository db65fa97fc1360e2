"""Pictures of 2D meshes and their nonobtuse-boundary check (matplotlib, Agg: no display needed).

Each panel draws the triangles in grey, the constrained segments in black, every boundary or interface edge
facing an obtuse angle in red with its diametral circle (the apex lies inside it: that is the defect) and its
apex, and the Steiner points in blue; a legend and a scale bar. The main panels may be vertically
exaggerated (thin layers kilometres long and metres thick), which is written on them: exaggeration distorts
the very angles being judged, so exaggerated panels leave the diametral circles to the close-ups. Below
them, close-ups at true scale on the worst offenders, each framing the offending edge's diametral circle:
readable even for a 1e-4 x 2.5e-7 sliver.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from nonobtuse.certificate import CheckReport, ObtuseAngle
from nonobtuse.io import atomic_path
from nonobtuse.mesh import Mesh

DIAMETRAL_GID = "diametral-circles"  # the gid of the collection of diametral circles, one per offending edge
MAX_CLOSE_UPS = 3
WIDTH_IN = 11.0


def _offending_edges(report: CheckReport) -> list[ObtuseAngle]:
    """One offender per offending edge (an interface edge may be obtuse on both sides): the larger angle."""
    seen: dict[tuple[int, int], ObtuseAngle] = {}
    for o in report.offenders:  # largest angle first
        seen.setdefault((min(o.edge), max(o.edge)), o)
    return list(seen.values())


def _nice_length(span: float) -> float:
    """A round length (1, 2 or 5 times a power of ten) near a fifth of ``span``."""
    target = span / 5 if span > 0 else 1.0
    power = 10.0 ** np.floor(np.log10(target))
    return float(min((1, 2, 5, 10), key=lambda m: abs(m * power - target)) * power)


def _draw(ax: Any, mesh: Mesh, report: CheckReport, exaggeration: float, unit: str,
          window: tuple[np.ndarray, float] | None = None) -> None:
    """One panel: the whole mesh, or at true scale the square of half-side ``window[1]`` around
    ``window[0]``."""
    from matplotlib.collections import EllipseCollection, LineCollection
    from mpl_toolkits.axes_grid1.anchored_artists import AnchoredSizeBar

    xy = mesh.points * np.array([1.0, exaggeration])
    ax.triplot(xy[:, 0], xy[:, 1], mesh.triangles, color="0.75", linewidth=0.3)
    ax.add_collection(LineCollection(xy[mesh.segments], colors="black", linewidths=0.8))
    steiner = xy[len(mesh.input_points):]
    if len(steiner):
        ax.plot(steiner[:, 0], steiner[:, 1], "o", color="tab:blue", markersize=3)
    offenders = _offending_edges(report)
    if offenders:
        edges = np.array([o.edge for o in offenders])
        ends = xy[edges]
        ax.add_collection(LineCollection(ends, colors="red", linewidths=1.6))
        if exaggeration == 1:  # exaggerated, a circle becomes a tall ellipse hiding the mesh: close-ups only
            diameters = np.linalg.norm(mesh.points[edges[:, 1]] - mesh.points[edges[:, 0]], axis=1)
            ax.add_collection(EllipseCollection(
                diameters, diameters, np.zeros(len(offenders)), units="xy", offsets=ends.mean(axis=1),
                offset_transform=ax.transData, facecolors="none", edgecolors="red", linewidths=0.8,
                linestyles="--", gid=DIAMETRAL_GID))
        apex = xy[[o.apex for o in offenders]]
        ax.plot(apex[:, 0], apex[:, 1], "^", color="red", markersize=4)
    if window is None:  # the limits grow to fill the panel: a sliver stays visible as a line
        ax.set_aspect("equal", adjustable="datalim")
        ax.autoscale_view()
    else:
        ax.set_aspect("equal")
        (cx, cy), half = window
        ax.set_xlim(cx - half, cx + half)
        ax.set_ylim(cy - half, cy + half)
    x0, x1 = ax.get_xlim()
    length = _nice_length(x1 - x0)
    ax.add_artist(AnchoredSizeBar(ax.transData, length, f"{length:g} {unit}".strip(), "lower right",
                                  frameon=True, size_vertical=0, pad=0.3))
    ax.set_xticks([])
    ax.set_yticks([])


def _windows(mesh: Mesh, report: CheckReport) -> list[tuple[np.ndarray, float]]:
    """The close-up windows of the worst offenders (largest angle first): each its diametral circle's
    bounding square, enlarged by a quarter."""
    out = []
    for o in _offending_edges(report)[:MAX_CLOSE_UPS]:
        a, b = mesh.points[o.edge[0]], mesh.points[o.edge[1]]
        out.append(((a + b) / 2, 0.625 * float(np.linalg.norm(b - a))))
    return out


def plot_stages(stages: list[tuple[str, Mesh, CheckReport]], path: str | Path, *,
                vertical_exaggeration: float = 1.0, title: str = "", unit: str = "") -> Any:
    """Writes a picture of one or more stages of a mesh (``(label, mesh, report)``, e.g. before and after
    refinement) to ``path`` (atomically; any format matplotlib knows, by suffix; PNG at 150 dpi): one main
    panel per stage, exaggerated ``vertical_exaggeration`` times in y (labelled so), then a row of close-ups
    at true scale per stage on the worst offenders of the first stage with any (the same windows in every
    stage, so a repair is seen in place). ``unit`` labels the scale bar. The figure is ``WIDTH_IN`` inches
    wide, its height follows the domain's exaggerated aspect (clamped). Returns the matplotlib Figure (closed;
    its artists are for inspection). ValueError for an exaggeration that is not a finite number > 0.
    Cost: O(m) per stage for m triangles."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if vertical_exaggeration <= 0 or not np.isfinite(vertical_exaggeration):
        raise ValueError(f"vertical_exaggeration must be a finite number > 0, got {vertical_exaggeration}")
    windows = next((_windows(m, r) for _, m, r in stages if r.offenders), [])
    span = np.ptp(stages[0][1].points, axis=0) * np.array([1.0, vertical_exaggeration])
    main_h = float(np.clip(WIDTH_IN * span[1] / span[0], 1.5, 6.0)) if span[0] > 0 else 6.0
    close_h = WIDTH_IN / MAX_CLOSE_UPS
    rows = [main_h] * len(stages) + ([close_h] * len(stages) if windows else [])
    fig = plt.figure(figsize=(WIDTH_IN, sum(rows) + 0.6 * len(rows)), constrained_layout=True)
    grid = fig.add_gridspec(len(rows), MAX_CLOSE_UPS, height_ratios=rows)
    shown = "" if vertical_exaggeration == 1 else (
        f", vertical exaggeration x{vertical_exaggeration:g} (angles distorted; diametral circles in the "
        "close-ups, at true scale)")
    for i, (label, mesh, report) in enumerate(stages):
        ax = fig.add_subplot(grid[i, :])
        _draw(ax, mesh, report, vertical_exaggeration, unit)
        worst = report.largest_obtuse
        status = "every boundary/interface angle nonobtuse" if worst is None else (
            f"edges facing an obtuse angle: {len(_offending_edges(report))}, worst {worst.degrees:.2f} deg")
        ax.set_title(f"{label}: {status}{shown}", fontsize=9)
    for i, (label, mesh, report) in enumerate(stages if windows else []):
        for j, window in enumerate(windows):
            ax = fig.add_subplot(grid[len(stages) + i, j])
            _draw(ax, mesh, report, 1.0, unit, window)
            ax.set_title(f"{label}: close-up {j + 1} (true scale){_angle_in(window, report)}", fontsize=8)
    return save_figure(fig, path, _legend_entries(stages), title)


def save_figure(fig: Any, path: str | Path, legend: tuple[list[Any], list[str]], title: str,
                fontsize: float = 8, ncols: int | None = None) -> Any:
    """Adds the legend (handles, labels) below the panels, ``ncols`` entries a row (None: all in one row),
    and the title (a file name, never a folder) to ``fig``, writes it to ``path`` atomically (PNG at 150 dpi;
    the format follows the suffix), closes it and returns it (its artists are for inspection)."""
    import matplotlib.pyplot as plt

    handles, labels = legend
    fig.legend(handles, labels, loc="outside lower center", ncols=min(ncols or len(handles), len(handles)),
               fontsize=fontsize, frameon=False)
    if title:
        fig.suptitle(title, fontsize=10)
    with atomic_path(Path(path)) as tmp:
        fig.savefig(tmp, dpi=150)
    plt.close(fig)
    return fig


def _angle_in(window: tuple[np.ndarray, float], report: CheckReport) -> str:
    """", worst D deg" for the largest obtuse angle of ``report`` facing an edge centred at the window's
    centre, or "" when none does (the edge was repaired)."""
    centre = window[0]
    for o in report.offenders:  # largest angle first
        a, b = np.asarray(o.points[0]), np.asarray(o.points[1])
        if np.array_equal((a + b) / 2, centre):
            return f", {o.degrees:.2f} deg"
    return ""


def _legend_entries(stages: list[tuple[str, Mesh, CheckReport]]) -> tuple[list[Any], list[str]]:
    """Legend handles for every kind of artist any stage draws (the first panel may lack Steiner points)."""
    from matplotlib.lines import Line2D

    entries = [(Line2D([], [], color="0.75", linewidth=0.6), "triangles"),
               (Line2D([], [], color="black", linewidth=0.8), "boundary / interface segments")]
    if any(len(m.points) > len(m.input_points) for _, m, _ in stages):
        entries.append((Line2D([], [], marker="o", color="tab:blue", linestyle="", markersize=3),
                        "Steiner points"))
    if any(r.offenders for _, _, r in stages):
        entries += [(Line2D([], [], color="red", linewidth=1.6), "edge facing an obtuse angle"),
                    (Line2D([], [], color="red", linewidth=0.8, linestyle="--"), "its diametral circle"),
                    (Line2D([], [], marker="^", color="red", linestyle="", markersize=4), "obtuse apex")]
    return [h for h, _ in entries], [t for _, t in entries]


def plot_check(mesh: Mesh, report: CheckReport, path: str | Path, *, vertical_exaggeration: float = 1.0,
               title: str | None = None, unit: str = "") -> Any:
    """:func:`plot_stages` of the one stage ``mesh`` with its ``report``, titled ``title`` or the file name
    (never the folder) of ``report.source``."""
    name = title if title is not None else Path(report.source).name
    return plot_stages([("mesh", mesh, report)], path, vertical_exaggeration=vertical_exaggeration,
                       title=name, unit=unit)
