"""check3d --plot/--offenders draw the offenders of the one exact check the report is made of: the exact
kernel (``_core.check_gabriel``) runs once per check3d, pictures or not."""

from __future__ import annotations

import json

import numpy as np
import pytest

from mesh3d_shapes import TET_TRIANGLES, write_off
from nonobtuse import _core
from nonobtuse.cli import EXIT_VIOLATIONS, main

# The apex (1, 1, 2) is strictly inside the diametral sphere of the base (centre (2, 2, 0), radius 2 sqrt(2)):
# the base is the one non-Gabriel face.
LOW_TET = np.array([[0, 0, 0], [4, 0, 0], [0, 4, 0], [1, 1, 2]])


@pytest.fixture
def exact_checks(monkeypatch):
    calls = []

    def counted(*args):
        calls.append(len(args[1]))
        return check(*args)

    check = _core.check_gabriel
    monkeypatch.setattr(_core, "check_gabriel", counted)
    return calls


PICTURES = [[], ["--offenders", "off.vtu"], ["--plot", "p.png", "--offenders", "o.vtu"]]


@pytest.mark.parametrize("pictures", PICTURES)
def test_check3d_runs_the_exact_check_once(tmp_path, capsys, exact_checks, pictures):
    pytest.importorskip("meshio")
    if "--plot" in pictures:
        pytest.importorskip("matplotlib")
    path = write_off(tmp_path / "low.off", LOW_TET, TET_TRIANGLES.tolist())
    args = [a if not a.endswith((".vtu", ".png")) else str(tmp_path / a) for a in pictures]
    assert main(["check3d", str(path), "--json", *args]) == EXIT_VIOLATIONS
    out = json.loads(capsys.readouterr().out)
    assert out["encroached_facets"] == 1
    assert exact_checks == [4]  # one check, of the tet's four faces
    for a in args:
        if a.startswith(str(tmp_path)):
            assert (tmp_path / a).stat().st_size > 0
