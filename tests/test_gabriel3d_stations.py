"""refine_gabriel's stations (cpp/src/gabriel3d_stations.h): near-parallel close segments (a thin strip)
matched point for point, in the protected rerun. Every converged case is re-certified by the exact check of
the returned mesh, and its tetrahedra fill the volume of the PLC."""

from __future__ import annotations

from pathlib import Path

import pytest

from nonobtuse.mesh3d import load_plc, refine_gabriel
from test_gabriel3d_protected import assert_certified

DATA = Path(__file__).resolve().parents[1] / ".." / "shared" / "data" / "3d"


def strip_box_off(length: float = 256.0, w0: float = 15 * 2.0**-15, w1: float = 2.0**-11) -> str:
    """A box [0, length] x [0, 1] x [0, 1] whose edge y = z = 0 is cut off by a chamfer strip, w0 deep at
    x = 0 and w1 at the far end (its long sides 6.5e-4 to 7e-4 apart, under 2.7e-6 of the length), split by
    its diagonal: two near-parallel segments that share no vertex, as on step.off. The caps are slanted
    (x = z / 8, x = length + y / 4) so that the strip's corners are not right angles; every coordinate is
    dyadic, so the caps are exactly planar."""
    start = [(z / 8, y, z) for y, z in [(w0, 0), (0, w0), (0, 1), (1, 1), (1, 0)]]
    end = [(length + y / 4, y, z) for y, z in [(w1, 0), (0, w1), (0, 1), (1, 1), (1, 0)]]
    a, a1, s01, s11, s10, b, b1, e01, e11, e10 = range(10)
    faces = [(s10, s11, s01, a1, a), (b, e10, e11, e01, b1), (a, s10, e10, b), (s01, e01, e11, s11),
             (s10, s11, e11, e10), (a1, b1, e01, s01), (a, b, b1), (a, b1, a1)]
    lines = ["OFF", f"{len(start) + len(end)} {len(faces)} 0"]
    lines += [" ".join(repr(float(c)) for c in p) for p in start + end]
    lines += [f"{len(f)} " + " ".join(map(str, f)) for f in faces]
    return "\n".join(lines) + "\n"


def test_thin_strip_box_converges_with_stations(tmp_path):
    path = tmp_path / "strip_box.off"
    path.write_text(strip_box_off())
    plc = load_plc(path)
    # The first pass alone cascades between the strip's long sides (shells put their points at unrelated
    # positions along them).
    assert refine_gabriel(plc, protected_fallback=False).status != "converged"
    res = refine_gabriel(plc)
    assert_certified(res, plc)
    assert res.stats["strategy"] == "shells+protected"


def test_step_off_converges_with_defaults():
    if not (DATA / "step.off").exists():
        pytest.skip("../shared/data not present")
    plc = load_plc(DATA / "step.off")
    res = refine_gabriel(plc)
    assert_certified(res, plc)
    assert res.stats["strategy"] == "shells+protected"
