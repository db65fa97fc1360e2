"""The built-in demo: a thin-layer geological cross-section, kilometres long and metres thick, in 2D; and a
small CAD part in 3D.

Four layers separated by three wavy interfaces (interior constraints), a wavy topography on top, each layer
with its own region attribute and conductivity. Every curve is sampled at its own spacing, as digitised
horizons are, so the constrained Delaunay triangulation is full of flat triangles: obtuse angles on the
boundary and on the interfaces, hence wrong-sign control-volume coefficients. The refinement step extends
:func:`run` then refines the boundary and the interfaces with the fewest Steiner points it can and reports the
same figures again, beside the lower bound and Triangle -pD's count for the same domain. The quality mode
(:func:`run_quality`: ``refine(min_angle=25)``, every triangle at least 25 degrees, the boundary still
certified) follows, beside Triangle -pq25D.

The 3D part (:func:`run_part`) is CGAL's ``joint`` CAD part (446 triangles, genus 2; bundled as package data,
CC0, see ``data/SOURCES.md``): tetrahedralized by TetGen (``-pq1.414Y``: the boundary as given) when the
``tetgen`` package is installed, else by the cgal backend (Delaunay, with the exact winding-number
fallback), checked exactly for Gabriel boundary faces and subsegments, repaired by
:func:`nonobtuse.mesh3d.refine_gabriel` and certified.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np

from nonobtuse.certificate import KINDS, check_mesh
from nonobtuse.control_volumes import control_volumes
from nonobtuse.domain import Domain
from nonobtuse.mesh import Mesh
from nonobtuse.mesh3d import GabrielReport, TetMesh, check_gabriel, load_plc, refine_gabriel
from nonobtuse.mesh3d.gabriel import control_volume_summary
from nonobtuse.refinement import RefineResult, refine
from nonobtuse.triangulation import triangulate

LENGTH_M = 4000.0
# Curves from bottom to top: mean elevation (m), wave amplitude (m), wavelength (m), phase, sample count.
CURVES = (
    (0.0, 0.0, 1.0, 0.0, 23),  # flat base
    (9.0, 2.0, 1700.0, 0.3, 61),
    (21.0, 2.5, 2300.0, 1.9, 47),
    (30.0, 1.5, 900.0, 4.1, 83),
    (42.0, 3.0, 3100.0, 2.7, 37),  # topography
)
EXAGGERATION = 20.0  # vertical exaggeration of the demo's picture: 4 km by 42 m is a line at true scale
# Region attribute (layer number, bottom = 1) -> conductivity (e.g. m/day): shale, sand, silt, gravel.
CONDUCTIVITY = {1.0: 1e-3, 2.0: 5.0, 3.0: 0.1, 4.0: 20.0}
QUALITY_MIN_ANGLE = 25.0  # degrees: the demo's quality mode, Triangle's -q25
PART = Path(__file__).parent / "data" / "joint.off"  # the 3D part: CGAL's joint.off (CC0; data/SOURCES.md)


def _curve(mean: float, amplitude: float, wavelength: float, phase: float, samples: int) -> np.ndarray:
    x = np.linspace(0.0, LENGTH_M, samples)
    return np.column_stack([x, mean + amplitude * np.sin(2 * np.pi * x / wavelength + phase)])


def cross_section() -> Domain:
    """The demo domain (deterministic): points of every curve, each curve a chain of segments, the two
    vertical sides as chains through the curves' end points, and one region seed per layer (attribute = layer
    number)."""
    curves = [_curve(*c) for c in CURVES]
    first = np.cumsum([0] + [len(c) for c in curves])  # index of each curve's first point
    segments = [np.column_stack([np.arange(s, e - 1), np.arange(s + 1, e)]) for s, e in zip(first, first[1:])]
    left, right = first[:-1], first[1:] - 1
    segments.append(np.column_stack([left[:-1], left[1:]]))
    segments.append(np.column_stack([right[:-1], right[1:]]))
    middle = LENGTH_M / 2
    mid_y = [c[np.argmin(np.abs(c[:, 0] - middle)), 1] for c in curves]  # the curves' heights near x = L/2
    layers = enumerate(zip(mid_y, mid_y[1:]))
    regions = np.array([(middle, (lo + hi) / 2, layer + 1.0) for layer, (lo, hi) in layers])
    return Domain(points=np.vstack(curves), segments=np.vstack(segments), regions=regions,
                  source="built-in cross-section")


def stage_report(title: str, mesh: Mesh, conductivity: dict[float, float] = CONDUCTIVITY) -> str:
    """A compact report of one mesh: size, exact angle check, control-volume coefficient signs."""
    report = check_mesh(mesh)
    cv = control_volumes(mesh, conductivity)
    wrong = cv.kind[cv.wrong_sign]
    by_kind = ", ".join(f"{int((wrong == k).sum())} {name}" for k, name in enumerate(KINDS))
    worst = report.largest_obtuse
    lines = [
        f"{title}: {len(mesh.points)} points ({mesh.steiner_points} Steiner), "
        f"{len(mesh.triangles)} triangles",
        f"  edges: {report.edges['boundary']} boundary, {report.edges['interface']} interface, "
        f"{report.edges['interior']} interior",
        f"  obtuse angles opposite boundary/interface edges: {len(report.offenders)}"
        + (f", worst {worst.degrees:.3f} deg at point {worst.apex} (edge {worst.edge})" if worst else ""),
        f"  wrong-sign coefficients (exact): {len(cv.wrong_sign)} ({by_kind}); M-matrix: "
        f"{'yes' if cv.m_matrix else 'no'}",
        f"  control volumes: total area {cv.areas.sum():.1f} m^2, smallest {cv.areas.min():.3g} m^2",
    ]
    return "\n".join(lines)


def run(out: Callable[[str], None] = print, plot: str | Path | None = None) -> int:
    """Build the cross-section, triangulate it, refine it (the minimal mode, then the quality mode:
    :func:`run_quality`), report; with ``plot``, also write the before / after / quality picture there
    (vertical exaggeration ``EXAGGERATION``, labelled; close-ups at true scale).
    Then the 3D part (:func:`run_part`; its picture at :func:`part_picture_path` of ``plot``).
    Returns the exit code (0)."""
    domain = cross_section()
    out(f"{domain.source}: {LENGTH_M / 1000:g} km long, {CURVES[-1][0]:g} m thick, {len(CURVES) - 2} "
        f"interfaces, {len(domain.points)} points, {len(domain.segments)} segments")
    before = triangulate(domain)
    out(stage_report("before: constrained Delaunay triangulation", before))
    result = refine(domain)
    s = result.stats
    out(stage_report(f"after: refine (greedy, {s['status']} in {s['seconds']:.2f} s)", result.mesh))
    out(f"  Steiner points: {s['steiner_points']} (lower bound {s['lower_bound']})")
    out(f"  Triangle -pD on the same domain: {_triangle_pd_summary(domain)}")
    quality = run_quality(domain, out)
    if plot is not None:
        from nonobtuse.plot import plot_stages  # matplotlib only when asked

        plot_stages([(label, mesh, check_mesh(mesh)) for label, mesh in (
                        ("before", before), ("after refine", result.mesh),
                        (f"after refine(min_angle={QUALITY_MIN_ANGLE:g})", quality.mesh))],
                    plot, vertical_exaggeration=EXAGGERATION, title=domain.source, unit="m")
        out(f"picture -> {plot}")
    run_part(out, None if plot is None else part_picture_path(plot))
    return 0


def run_quality(domain: Domain, out: Callable[[str], None] = print) -> RefineResult:
    """The quality mode on the demo domain: ``refine(domain, min_angle=QUALITY_MIN_ANGLE)``, reported in three
    lines (points on constraints and inside; smallest angle and the exact boundary certificate; Triangle
    ``-pq25D``'s counts). Returns the result. Cost: a fraction of a second."""
    r = refine(domain, min_angle=QUALITY_MIN_ANGLE)
    s, q = r.stats, r.stats["quality"]
    out(f"quality: refine(min_angle={QUALITY_MIN_ANGLE:g}) ({s['status']} in {s['seconds']:.2f} s): "
        f"{len(r.mesh.points)} points ({s['steiner_points']} on boundary/interfaces, {s['interior_points']} "
        f"inside), {len(r.mesh.triangles)} triangles")
    out(f"  smallest angle {q['min_angle_degrees']:.2f} deg; obtuse angles opposite boundary/interface edges "
        f"(exact): {s['obtuse_boundary_sides']}")
    out(f"  Triangle -pq{QUALITY_MIN_ANGLE:g}D on the same domain: {_triangle_quality_summary(domain)}")
    return r


def part_picture_path(plot: str | Path) -> Path:
    """Where ``demo --plot PLOT`` draws the 3D part: beside PLOT, ``_3d`` added to its stem."""
    plot = Path(plot)
    return plot.with_name(f"{plot.stem}_3d{plot.suffix}")


def part_report(title: str, mesh: TetMesh, report: GabrielReport) -> str:
    """A compact report of one 3D mesh: size, exact Gabriel check, control-volume coupling signs."""
    cv = control_volume_summary(mesh)
    return "\n".join([
        f"{title}: {len(mesh.points)} points, {len(mesh.tets)} tets, {len(mesh.boundary_faces)} boundary "
        "faces",
        f"  non-Gabriel (exact): {len(report.faces)} of {report.n_faces} boundary faces, "
        f"{len(report.segments)} of {report.n_segments} subsegments",
        f"  negative control-volume couplings: {cv['negative_couplings']} of {cv['edges']} edges"
        if len(mesh.tets) else "  control volumes: none (no tets)",
    ])


def run_part(out: Callable[[str], None] = print, plot: str | Path | None = None) -> None:
    """The 3D part of the demo: load ``PART``, tetrahedralize it (:func:`nonobtuse.plot3d.unrepaired_mesh`),
    check it, repair it with :func:`refine_gabriel` (defaults), report; with ``plot``, draw both stages there
    (:func:`nonobtuse.plot3d.plot_gabriel_stages`). Cost: about a second (the picture a few more)."""
    plc = load_plc(PART)
    out(f"3D: {PART.name} (CAD part, CC0): {len(plc.points)} points, {len(plc.triangles)} triangles")
    from nonobtuse.plot3d import unrepaired_mesh

    before, how = unrepaired_mesh(plc)
    before_report = check_gabriel(before)
    out(part_report(f"before: {how}", before, before_report))
    result = refine_gabriel(plc)
    s = result.stats
    report = result.report or check_gabriel(result.mesh)  # refine_gabriel's certificate of its mesh
    out(part_report(f"after: refine_gabriel ({s['strategy']}, {s['status']} in {s['seconds']:.2f} s)",
                    result.mesh, report))
    out(f"  Steiner points: {s['steiner_points']} ({s['steiner_on_segments']} on segments, "
        f"{s['steiner_on_facets']} in facets); certificate: "
        f"{'every boundary face and subsegment Gabriel (exact)' if report.ok else 'NOT Gabriel'}")
    if plot is not None:
        from nonobtuse.plot3d import plot_gabriel_stages

        plot_gabriel_stages([(f"before ({how.split(' (')[0]})", before, before_report),
                             ("after refine_gabriel", result.mesh, report)], plot, title=PART.name)
        out(f"picture -> {plot}")


def _triangle_quality_summary(domain: Domain) -> str:
    from nonobtuse.peers import triangle_quality

    try:
        t = triangle_quality(domain, QUALITY_MIN_ANGLE)
    except ImportError:
        return "not measured (the 'triangle' package is not installed; pip install 'nonobtuse[dev]')"
    return (f"{t['vertices']} points ({t['boundary_steiner']} on boundary/interfaces), smallest angle "
            f"{t['min_angle']:.2f} deg ({t['seconds']:.2f} s)")


def _triangle_pd_summary(domain: Domain) -> str:
    from nonobtuse.peers import triangle_pd

    try:
        steiner, seconds = triangle_pd(domain)
    except ImportError:
        return "not measured (the 'triangle' package is not installed; pip install 'nonobtuse[dev]')"
    return f"{steiner} Steiner points ({seconds:.2f} s)"
