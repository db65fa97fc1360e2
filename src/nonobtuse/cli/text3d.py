"""The text output of ``check3d`` and ``refine3d``: a header line, aligned key/value lines with units and a
verdict line, like 2D ``check``. ``--json`` prints the same dicts as JSON instead (unchanged by this module).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

SHOWN_ANGLES = 3  # smallest input angles listed in refine3d's text (all are in --json)
SHOWN_PLACES = 3  # input vertices and segments with the most Steiner points


def aligned(pairs: list[tuple[str, str]], indent: str = "  ") -> list[str]:
    """``key   value`` lines, the values aligned one column after the longest key."""
    width = max((len(k) for k, _ in pairs), default=0)
    return [f"{indent}{k:<{width}}  {v}" for k, v in pairs]


def _number(x: Any) -> str:
    """A count with thousands separators, a float in 4 significant digits, None as "n/a", text as it is."""
    if x is None:
        return "n/a"
    if isinstance(x, str):
        return x
    if isinstance(x, int):
        return f"{x:,}"
    return f"{x:.4g}"


def _deepest(entries: list[dict[str, Any]], rows: str) -> str:
    """", deepest: face 4 by vertex 6, 0.28 of the radius inside" for the first of ``deepest_faces``."""
    if not entries:
        return ""
    d = entries[0]
    return f"; deepest: {rows} {d['index']} by vertex {d['vertex']}, {d['depth']:.3g} of the radius inside"


def _control_volumes(cv: dict[str, Any]) -> list[tuple[str, str]]:
    flat = cv.get("flat_in_floating_point", 0)
    return [
        ("control-volume edges", _number(cv["edges"])),
        ("negative couplings", f"{_number(cv['negative_couplings'])} (smallest coupling "
                               f"{_number(cv['min_coupling'])}; floating point)"),
        ("zero couplings", _number(cv["zero_couplings"])),
        ("total volume", _number(cv["total_volume"]) + "  (length units cubed)"
         + (f"; {flat:,} tets flat in floating point, their circumcenters exact" if flat else "")),
    ]


def _verdict(facets: Any, segments: Any) -> str:
    """OK / NOT OK / UNKNOWN for the encroached counts (ints, or the strings of an unchecked certificate)."""
    if isinstance(facets, str) or isinstance(segments, str):
        return (f"UNKNOWN: the exact check did not reach every row (time limit): encroached faces {facets}, "
                f"subsegments {segments}")
    if facets == 0 and segments == 0:
        return "OK: every boundary face and subsegment has an empty diametral sphere (exact)"
    return (f"NOT OK: {facets:,} boundary faces and {segments:,} subsegments have a vertex strictly inside "
            "their diametral sphere (exact)")


def check3d_text(summary: dict[str, Any]) -> str:
    """The lines ``check3d`` prints for :func:`nonobtuse.mesh3d.boundary_certificate`'s dict (with ``input``
    and ``backend``)."""
    g = summary["gabriel"]
    steiner = summary["steiner_points"]
    pairs = [
        ("backend", summary["backend"]),
        ("points", _number(summary["points"]) + ("" if steiner is None else f" ({steiner:,} Steiner)")),
        ("tets", _number(summary["tets"])),
        ("boundary faces", f"{summary['encroached_facets']:,} of {g['checked_faces']:,} encroached"
                           + _deepest(g["deepest_faces"], "face")),
        ("subsegments", f"{summary['encroached_segments']:,} of {g['checked_segments']:,} encroached"
                        + _deepest(g["deepest_segments"], "segment")),
        *_control_volumes(summary["control_volumes"]),
    ]
    pairs += [("warning", w) for w in summary.get("warnings", [])]
    lines = [f"{Path(summary['input']).name}: {summary['points']:,} points, {summary['tets']:,} tets, "
             f"{summary['boundary_faces']:,} boundary faces"]
    return "\n".join(lines + aligned(pairs) + ["  " + _verdict(summary["encroached_facets"],
                                                               summary["encroached_segments"])])


def _angles(diagnosis: dict[str, Any]) -> list[tuple[str, str]]:
    angles = diagnosis.get("smallest_angles", [])[:SHOWN_ANGLES]
    return [("smallest input angle" if i == 0 else "", f"{a['degrees']:.3g} deg {a['kind']} at vertices "
             f"{a['vertices']}" + (f", facets {a['facets']}" if a["facets"] else ""))
            for i, a in enumerate(angles)]


def _places(diagnosis: dict[str, Any]) -> list[tuple[str, str]]:
    out = []
    for key, what in (("steiner_per_vertex", "near vertex"), ("steiner_per_segment", "on segment")):
        shown = diagnosis.get(key, [])[:SHOWN_PLACES]
        if shown:
            out.append((f"most points {what}", ", ".join(f"{c['where']}: {c['count']:,}" for c in shown)))
    return out


def refine3d_text(stats: dict[str, Any], input_path: str, output_path: str) -> str:
    """The lines ``refine3d`` prints for ``refine_gabriel``'s stats (encroached counts may be the strings
    of a certificate the time limit cut short), or for ``refine_quality3d``'s (with interior points)."""
    if "interior_points" in stats:
        return _quality3d_text(stats, input_path, output_path)
    diagnosis = stats.get("diagnosis", {})
    other = stats.get("other_attempt") or ""
    pairs = [
        ("status", f"{stats['status']}: {diagnosis.get('stop_reason', '')}".rstrip(": ")),
        ("strategy", stats["strategy"] + (f" (other attempt: {other})" if other else "")),
        ("Steiner points", f"{stats['steiner_points']:,} ({stats['steiner_on_segments']:,} on segments, "
                           f"{stats['steiner_on_facets']:,} in facets)"),
        ("encroached faces", _number(stats["encroached_facets"])),
        ("encroached subsegments", _number(stats["encroached_segments"])),
        ("smallest subsegment", _number(stats["smallest_subsegment"]) + " (length units)"),
        ("limits", f"max_steiner {stats['max_steiner']:,}, min_length {_number(stats['min_length'])}"),
        ("negative couplings", f"{_number(stats['negative_couplings'])} (floating point)"),
        ("seconds", f"{stats['seconds']:.2f} s"),
        *_angles(diagnosis),
        *_places(diagnosis),
    ]
    if stats.get("protecting_balls"):
        pairs.insert(3, ("protecting balls", _number(stats["protecting_balls"])))
    pairs += [("warning", w) for w in stats.get("warnings", [])]
    head = (f"{Path(input_path).name} -> {output_path}: {stats['status']}, {stats['steiner_points']:,} "
            "Steiner points")
    return "\n".join([head] + aligned(pairs) + ["  " + _verdict(stats["encroached_facets"],
                                                                stats["encroached_segments"])])


def _quality3d_text(stats: dict[str, Any], input_path: str, output_path: str) -> str:
    """The lines of ``refine3d --radius-edge/--max-volume``: points by kind, the bounds against what the mesh
    reaches, the certificate's counts (``boundary_repair`` and the rest only in --json)."""
    bound = stats.get("max_volume_bound")
    pairs = [
        ("status", f"{stats['status']}: {stats.get('last_repair', '')}".rstrip(": ")),
        ("points added", f"{stats['steiner_points']:,} (the mesh has {stats['boundary_points']:,} boundary "
                         f"and {stats['interior_points']:,} interior points)"),
        ("tets", f"{_number(stats['tets'])} ({_number(stats['bad_tets'])} over a bound, "
                 f"{_number(stats['small_angle_tets'])} of them left alone near small input angles"
                 + (f" (also at {stats['cascades_left_alone']} boundary pieces whose split cascaded)"
                    if stats.get("cascades_left_alone") else "") + ", " +
                 f"{_number(stats['rounds'])} round{'' if stats['rounds'] == 1 else 's'})"),
        ("worst radius-edge", f"{_number(stats['worst_radius_edge'])} "
                              f"({_number(stats['worst_radius_edge_outside_small_angles'])} outside small "
                              f"angles; bound {_number(stats['radius_edge'])})"),
        ("largest volume", f"{_number(stats['max_volume'])} (bound "
                           f"{_number(bound) if not isinstance(bound, dict) else 'per region'}; length units "
                           "cubed)"),
        ("encroached faces", _number(stats["encroached_facets"])),
        ("encroached subsegments", _number(stats["encroached_segments"])),
        ("negative couplings", f"{_number(stats['negative_couplings'])} (floating point)"),
        ("seconds", f"{stats['seconds']:.2f} s"),
    ]
    pairs += [("warning", w) for w in stats.get("warnings", [])]
    head = (f"{Path(input_path).name} -> {output_path}: {stats['status']}, "
            f"{stats['interior_points']:,} interior and {stats['boundary_points']:,} boundary points")
    return "\n".join([head] + aligned(pairs) + ["  " + _verdict(stats["encroached_facets"],
                                                                stats["encroached_segments"])])
