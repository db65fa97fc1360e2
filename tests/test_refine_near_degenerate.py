"""Near-degenerate fans off the grid: refine must end with a status, never an exception or a crash.

Found by a hypothesis search over the fans of tests/test_pslg.py with float (not 0.1-grid, not whole-degree)
coordinates and angles, then shrunk by hand to the inputs below. Before the fixes, the first raised
InternalError("the refined boundary s-p-e crosses a constraint": a rounded Steiner point off one arm's line
lay beyond the other arm) and the second killed the interpreter with SIGFPE (an infinite candidate
coordinate, from a subnormal slope, reached GMP). Greedy converges on both (its shells handle the junction);
the baselines have no shells and may exhaust their budget at a 1e-50 rad junction, but end with a status.
"""

from __future__ import annotations

import subprocess
import sys
import textwrap

import numpy as np
import pytest

import nonobtuse
from nonobtuse import Domain
from nonobtuse.certificate import check_mesh

SQUARE = [(-10.0, -10.0), (10.0, -10.0), (10.0, 10.0), (-10.0, 10.0)]
SQUARE_LOOP = [(0, 1), (1, 2), (2, 3), (3, 0)]


@pytest.mark.parametrize("strategy", ["greedy", "project-flip", "projection"])
def test_two_arms_at_a_junction_angle_of_1e_50_end_with_a_status(strategy):
    # Two interior segments from the centre of a square to (3, 1e-100) and (3, 1e-50): an acute junction of
    # 1e-50 radians (both arms off the axis; with one arm on the axis, or at 1e-8 / 1e-6, refine converges).
    pts = np.array([*SQUARE, (0.0, 0.0), (3.0, 1e-100), (3.0, 1e-50)])
    d = Domain(points=pts, segments=np.array([*SQUARE_LOOP, (4, 5), (4, 6)]))
    res = nonobtuse.refine(d, strategy=strategy, max_steiner=2000)
    assert res.status in ("converged", "stalled", "budget_exhausted")
    assert res.converged == check_mesh(res.mesh).ok
    if strategy == "greedy":
        assert res.converged


def test_a_subnormal_coordinate_does_not_kill_the_process():
    # An arm from the centre to (4.039275, 8.99e-309) (a subnormal y) and an isolated point (1.8, 0) about
    # 4e-309 below it, strictly inside its diametral disk. Every strategy used to raise SIGFPE inside GMP,
    # which kills the interpreter, hence the subprocess.
    code = textwrap.dedent(f"""
        import numpy as np, nonobtuse
        from nonobtuse import Domain
        pts = np.array({SQUARE!r} + [(0.0, 0.0), (4.039275, 8.987686180033967e-309), (1.8, 0.0)])
        seg = np.array({SQUARE_LOOP!r} + [(4, 5)])
        for strategy in ("greedy", "project-flip", "projection"):
            print(nonobtuse.refine(Domain(points=pts, segments=seg), strategy=strategy).status)
    """)
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert run.returncode == 0, f"exit {run.returncode}: {run.stderr[-300:]}"
    assert run.stdout.split() == ["converged"] * 3
