"""Pictures of a 2D mesh and its nonobtuse-boundary check (matplotlib, no display needed)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from nonobtuse.certificate import CheckReport
from nonobtuse.mesh import Mesh


def plot_check(mesh: Mesh, report: CheckReport, path: str | Path, *, vertical_exaggeration: float = 1.0,
               title: str | None = None) -> None:
    """Writes a picture of ``mesh`` (any format matplotlib knows, by suffix): triangles in grey, constrained
    segments in black, each boundary or interface edge facing an obtuse angle in red with its apex marked.
    vertical_exaggeration scales y (thin layers kilometres long and metres thick need 20-100).
    Cost: O(m) for m triangles."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection

    xy = mesh.points * np.array([1.0, vertical_exaggeration])
    fig, ax = plt.subplots(figsize=(12, 5))
    ax.triplot(xy[:, 0], xy[:, 1], mesh.triangles, color="0.75", linewidth=0.3)
    ax.add_collection(LineCollection(xy[mesh.segments], colors="black", linewidths=0.8))
    if report.offenders:
        bad = np.array([o.edge for o in report.offenders])
        ax.add_collection(LineCollection(xy[bad], colors="red", linewidths=1.6))
        apex = xy[[o.apex for o in report.offenders]]
        ax.plot(apex[:, 0], apex[:, 1], "o", color="red", markersize=2)
    ax.set_xlabel("x")
    ax.set_ylabel(f"y x {vertical_exaggeration:g}" if vertical_exaggeration != 1 else "y")
    ax.set_aspect("equal")
    ax.autoscale_view()
    status = "OK" if report.ok else f"{len(report.offenders)} obtuse boundary/interface angles"
    ax.set_title(f"{title or report.source}: {status}")
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    plt.close(fig)
