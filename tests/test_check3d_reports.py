"""check3d's report on every input of tests/data/3d (cgal and tetgen backends) is the one main gave before
the load, tetrahedralize and control-volume paths were made faster: the loaded PLC (triangles, facet ids,
segments, warnings), the cgal tets, the exact certificate and the control-volume summary.

tests/data/check3d/reports_main.json was written by :func:`reports` on main at efcd16b (regenerate with
``PYTHONPATH=src .venv/bin/python tests/test_check3d_reports.py OUT.json`` only when a change of results is
intended). Exact quantities (counts, digests, which faces are encroached) must be equal; floating-point
magnitudes (depths, min_coupling, total_volume) agree to 1e-12 relative. One intended change: the
winding-number path's volume_mesh text counted every facet as not conforming on main (its flood fill leaked,
so no face was covered); it now counts the one-triangle facets that are not Delaunay faces, so that number is
not compared."""

from __future__ import annotations

import hashlib
import json
import re
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from nonobtuse.io import jsonable
from nonobtuse.mesh3d import boundary_certificate, load_plc, tetrahedralize

DATA = Path(__file__).parent / "data"
PINNED = DATA / "check3d" / "reports_main.json"
INPUTS = sorted(p for p in (DATA / "3d").iterdir() if p.suffix in (".off", ".poly"))


def digest(*arrays: np.ndarray) -> str:
    h = hashlib.sha256()
    for a in arrays:
        h.update(np.ascontiguousarray(a, dtype=np.int64).tobytes())
    return h.hexdigest()[:16]


def report(path: Path, backend: str) -> dict[str, Any]:
    """What the pinned file holds for one input and backend."""
    plc = load_plc(path)
    mesh = tetrahedralize(plc, backend)
    tets = np.unique(np.sort(mesh.tets, axis=1), axis=0) if backend == "cgal" else None  # tetgen: its own
    return jsonable({"triangles": len(plc.triangles), "segments": len(plc.segments),
                     "facets": len(np.unique(plc.facet_ids)), "warnings": list(plc.warnings),
                     "volume_mesh": mesh.stats.get("volume_mesh"),
                     "plc_digest": digest(plc.triangles, plc.facet_ids, plc.segments),
                     "tets_digest": None if tets is None else digest(tets), **boundary_certificate(mesh)})


def reports() -> dict[str, Any]:
    return {f"{p.name} {b}": report(p, b) for p in INPUTS for b in ("cgal", "tetgen")}


NOT_CONFORMING = re.compile(r"does not conform to (at least )?\d+ of (\d+) facets \(e\.g\. facet \d+\)")


def without_count(volume_mesh: str | None) -> str | None:
    return volume_mesh and NOT_CONFORMING.sub(r"does not conform to some of \2 facets", volume_mesh)


def assert_same(got: Any, want: Any, where: str) -> None:
    if where.endswith(".volume_mesh"):
        got, want = without_count(got), without_count(want)
    if isinstance(want, dict):
        assert sorted(got) == sorted(want), where
        for k in want:
            assert_same(got[k], want[k], f"{where}.{k}")
    elif isinstance(want, list):
        assert len(got) == len(want), where
        for i, (g, w) in enumerate(zip(got, want)):
            assert_same(g, w, f"{where}[{i}]")
    elif isinstance(want, float):
        assert got == pytest.approx(want, rel=1e-12, abs=0), where
    else:
        assert got == want, where


@pytest.mark.parametrize("path", INPUTS, ids=lambda p: p.name)
@pytest.mark.parametrize("backend", ["cgal", "tetgen"])
def test_report_is_mains(path: Path, backend: str) -> None:
    if backend == "tetgen":
        pytest.importorskip("tetgen")
    want = json.loads(PINNED.read_text())[f"{path.name} {backend}"]
    assert_same(report(path, backend), want, f"{path.name} {backend}")


if __name__ == "__main__":
    Path(sys.argv[1]).write_text(json.dumps(reports(), indent=1, sort_keys=True) + "\n")
