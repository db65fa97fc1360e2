"""Termination map of the 3D Gabriel repair: where does ``refine_gabriel`` stop on small input angles?

For each PLC family of ``experiments.plc_families`` (fan: every k in 3..12), each angle theta and each
strategy (``STRATEGIES``: the split rules "midpoint" and "shells" alone, the "protected" and "mirrored"
strategies alone, and the "default": shells, then the protected strategy where shells does not converge, then
the mirrored one where that does not converge either), one case runs
``nonobtuse.mesh3d.refine_gabriel`` under its deterministic budgets (the default Steiner budget and the
default work budget ``max_work``, or ``--max-work``; no wall-clock ``time_limit``, so a case's outcome does
not depend on the machine's load), and records its status, Steiner points, smallest subsegment, work, time
and the strategy that produced the result. The case process is still killed after ``--time-limit`` seconds
(a safety net against a hang, not a budget): such a case has status "killed".

    python -m experiments.termination_map --quick        # < 2 min on 2 cores
    python -m experiments.termination_map                # theta = 1..10, 12..30 by 2, 35..120 by 5 (hours)

Writes OUT/termination_map[_quick].csv (one row per case), OUT/termination_frontier[_quick].csv (per family
and split: the smallest theta from which every larger theta of the grid converged) and
OUT/termination_map[_quick].png (status map and log Steiner count over theta).
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from pathlib import Path

if __package__ in (None, ""):  # run as a script: make `experiments` importable
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from experiments.plc_families import FAMILIES, make_plc
from experiments.plotting import legend, pyplot
from experiments.sweep import add_sweep_arguments, error_summary, output_stem, sweep_from_args, write_csv

# Strategy name -> refine_gabriel keyword arguments.
STRATEGIES = {
    "midpoint": {"split": "midpoint", "protected_fallback": False},
    "shells": {"split": "shells", "protected_fallback": False},
    "protected": {"split": "protected"},
    "mirrored": {"split": "mirrored"},
    "default": {"split": "shells"},
}
SPLITS = tuple(STRATEGIES)
FULL_THETAS = [float(t) for t in [*range(1, 11), *range(12, 31, 2), *range(35, 121, 5)]]  # dense where small
QUICK_THETAS = [2.0, 10.0, 30.0, 60.0, 90.0]
FAN_KS_FULL = list(range(3, 13))
FAN_KS_QUICK = [3, 6, 12]
QUICK_MAX_WORK = 2_000_000  # work units per strategy pass with --quick (refine_gabriel's default: >= 2e7)
KILL_SECONDS = {"quick": 120.0, "full": 900.0}  # safety net: the case process is killed (status "killed")
COLUMNS = ["family", "k", "theta", "split", "status", "strategy", "steiner_points", "smallest_subsegment",
           "work", "max_work", "seconds", "smallest_input_angle", "diagnosis"]
FRONTIER_COLUMNS = ["family", "k", "split", "converges_from_theta", "not_converged", "thetas",
                    "not_converged_thetas"]
CONVERGED = "converged"


def make_cases(quick: bool, max_work: int | None, thetas: list[float] | None = None,
               families: list[str] | None = None, fan_ks: list[int] | None = None) -> list[dict]:
    """Every (family, k, theta, strategy) the families accept, with the refinement's work budget per pass
    (None: refine_gabriel's default); the case key "split" names the strategy (one of ``STRATEGIES``)."""
    thetas = thetas or (QUICK_THETAS if quick else FULL_THETAS)
    cases = []
    for name in families or list(FAMILIES):
        fam = FAMILIES[name]
        if name == "fan":
            ks: list[int | None] = fan_ks or (FAN_KS_QUICK if quick else FAN_KS_FULL)
        else:
            ks = [fam.default_k if fam.uses_k else None]
        for k in ks:
            for theta in thetas:
                if fam.accepts(theta, k):
                    cases.extend({"family": name, "k": k, "theta": theta, "split": split,
                                  "max_work": max_work} for split in SPLITS)
    return cases


def run_case(case: dict) -> dict:
    """Repair one family member: the refinement's status and statistics, the wall time of the call, and the
    diagnosis in one line (with the smallest input angle the refinement measured, to check the family)."""
    from nonobtuse.mesh3d import refine_gabriel

    plc = make_plc(case["family"], case["theta"], case["k"])
    start = time.perf_counter()
    result = refine_gabriel(plc, max_work=case["max_work"], **STRATEGIES[case["split"]])
    seconds = time.perf_counter() - start
    stats = result.stats
    smallest_angle, diagnosis = summarize_diagnosis(stats.get("diagnosis"))
    return {"status": str(result.status), "strategy": stats["strategy"],
            "steiner_points": int(stats["steiner_points"]),
            "smallest_subsegment": float(stats["smallest_subsegment"]), "work": int(stats["work"]),
            "max_work": int(stats["max_work"]), "seconds": round(seconds, 4),
            "smallest_input_angle": smallest_angle, "diagnosis": diagnosis}


def summarize_diagnosis(diagnosis) -> tuple[float | None, str]:
    """(smallest input angle in degrees or None, one line): stop reason, smallest angle, busiest vertex.

    ``diagnosis`` is refine_gabriel's dict (smallest_angles: [{kind, degrees, ...}], steiner_per_vertex:
    [{where, count}], stop_reason); anything else is kept as text."""
    if not isinstance(diagnosis, dict):
        return None, str(diagnosis or "")[:200]
    angles = diagnosis.get("smallest_angles") or []
    smallest = min(angles, key=lambda a: a["degrees"], default=None)
    busiest = max(diagnosis.get("steiner_per_vertex") or [], key=lambda v: v["count"], default=None)
    parts = [str(diagnosis.get("stop_reason") or "")]
    if smallest:
        parts.append(f"smallest input angle {smallest['degrees']:.4g} deg ({smallest['kind']})")
    if busiest:
        parts.append(f"{busiest['count']} Steiner points near vertex {busiest['where']}")
    return (float(smallest["degrees"]) if smallest else None), "; ".join(p for p in parts if p)


def rows_from_records(records: list[dict]) -> list[dict]:
    """One CSV row per case, sorted by family, k, theta, split; a killed case has status "killed"."""
    rows = []
    for rec in records:
        row = dict(rec["case"])
        if rec["status"] == "ok":
            row.update(rec["result"])
        else:
            killed = rec["status"] == "timeout"
            why = "killed by the --time-limit safety net (not a refinement budget): " if killed else ""
            row.update(status="killed" if killed else "error", seconds=rec["seconds"],
                       diagnosis=why + error_summary(rec))
        rows.append(row)
    return sorted(rows, key=lambda r: (r["family"], r["k"] or 0, r["theta"], r["split"]))


def frontier(rows: list[dict]) -> list[dict]:
    """Per (family, k, split): the smallest theta such that this and every larger theta converged
    (None when the largest did not), and the thetas that did not converge."""
    groups: dict[tuple, list[dict]] = {}
    for row in rows:
        groups.setdefault((row["family"], row["k"], row["split"]), []).append(row)
    out = []
    for (family, k, split), group in sorted(groups.items(), key=lambda g: (g[0][0], g[0][1] or 0, g[0][2])):
        group.sort(key=lambda r: r["theta"])
        bound = None
        for row in reversed(group):
            if row["status"] != CONVERGED:
                break
            bound = row["theta"]
        failed = [r["theta"] for r in group if r["status"] != CONVERGED]
        out.append({"family": family, "k": k, "split": split, "converges_from_theta": bound,
                    "not_converged": len(failed), "thetas": len(group),
                    "not_converged_thetas": ";".join(f"{t:g}" for t in failed)})
    return out


def plot(rows: list[dict], path: Path) -> None:
    """One column per strategy; top: status over theta per family row; bottom: log Steiner count."""
    plt = pyplot()
    labels = sorted({_label(r) for r in rows}, key=_label_order)
    statuses = sorted({r["status"] for r in rows}, key=lambda s: (s != CONVERGED, s))
    colours = dict(zip(statuses, plt.get_cmap("tab10").colors[2:] + plt.get_cmap("tab10").colors[:2]))
    colours[CONVERGED] = "tab:green"
    fig, axes = plt.subplots(2, len(SPLITS), figsize=(6.5 * len(SPLITS), 9), sharex=True, squeeze=False)
    for col, split in enumerate(SPLITS):
        mine = [r for r in rows if r["split"] == split]
        ax = axes[0, col]
        for status in statuses:
            pts = [(r["theta"], labels.index(_label(r))) for r in mine if r["status"] == status]
            if pts:
                ax.scatter(*zip(*pts), marker="s", s=14, color=colours[status], label=status)
        ax.set_yticks(range(len(labels)), labels, fontsize=7)
        ax.set_title(f"split={split}: status")
        legend(ax, fontsize=7, loc="lower right")
        ax = axes[1, col]
        for label in labels:
            if label.startswith("fan") and label not in ("fan k=3", "fan k=12"):
                continue  # two fan curves keep the panel readable; the status map shows every k
            line = sorted((r["theta"], r["steiner_points"], r["status"] == CONVERGED) for r in mine
                          if _label(r) == label and _is_number(r.get("steiner_points")))
            if line:
                x, y, ok = zip(*line)
                (handle,) = ax.plot(x, [max(v, 0.5) for v in y], lw=1, label=label)
                ax.scatter([a for a, g in zip(x, ok) if not g], [max(v, 0.5) for v, g in zip(y, ok) if not g],
                           facecolors="none", edgecolors=handle.get_color(), s=18)
        ax.set_yscale("log")
        ax.set_xscale("log")
        ax.set_xlabel("theta (degrees)")
        ax.set_ylabel("Steiner points (0 drawn at 0.5; hollow: not converged)")
        legend(ax, fontsize=7)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _label(row: dict) -> str:
    return f"fan k={row['k']}" if row["family"] == "fan" else row["family"]


def _label_order(label: str) -> tuple:
    family, _, k = label.partition(" k=")
    return (list(FAMILIES).index(family), int(k) if k else 0)


def _is_number(value) -> bool:
    return isinstance(value, (int, float)) and not (isinstance(value, float) and math.isnan(value))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_sweep_arguments(parser)
    parser.add_argument("--thetas", type=lambda s: [float(t) for t in s.split(",")],
                        help="comma-separated angles in degrees instead of the default grid")
    parser.add_argument("--families", type=lambda s: s.split(","), help=f"subset of {','.join(FAMILIES)}")
    parser.add_argument("--ks", type=lambda s: [int(k) for k in s.split(",")],
                        help="comma-separated fan sizes k instead of the default")
    parser.add_argument("--max-work", type=int, help="refine_gabriel max_work per strategy pass, work units "
                        f"(default {QUICK_MAX_WORK} with --quick, else refine_gabriel's default)")
    args = parser.parse_args(argv)
    max_work = args.max_work or (QUICK_MAX_WORK if args.quick else None)
    cases = make_cases(args.quick, max_work, args.thetas, args.families, args.ks)
    records = sweep_from_args(args, run_case, cases, "termination_map",
                              time_limit=KILL_SECONDS["quick" if args.quick else "full"])
    rows = rows_from_records(records)
    stem = output_stem("termination_map", args.quick)
    write_csv(args.out / f"{stem}.csv", rows, COLUMNS)
    bounds = frontier(rows)
    write_csv(args.out / f"{output_stem('termination_frontier', args.quick)}.csv", bounds, FRONTIER_COLUMNS)
    plot(rows, args.out / f"{stem}.png")
    for b in bounds:
        print(f"{_label(b):>14} {b['split']:>8}: converges from theta={b['converges_from_theta']}"
              f" ({b['not_converged']}/{b['thetas']} not converged)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
