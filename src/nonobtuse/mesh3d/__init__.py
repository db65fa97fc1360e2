"""The 3D module: PLC input, tetrahedralization backends, exact Gabriel check and refinement, control
volumes."""

from __future__ import annotations

from nonobtuse.io.tetmesh import read_tetmesh, read_tetmesh_json, write_tetmesh
from nonobtuse.mesh3d.control_volumes3d import ControlVolumes3D, control_volumes3d
from nonobtuse.mesh3d.gabriel import (
    Gabriel3DResult,
    GabrielReport,
    boundary_certificate,
    check_gabriel,
    refine_gabriel,
)
from nonobtuse.mesh3d.load import load_plc
from nonobtuse.mesh3d.plc import PLC, TetMesh
from nonobtuse.mesh3d.tetrahedralize import tetrahedralize
from nonobtuse.mesh3d.validate3d import validate_plc

__all__ = [
    "PLC", "ControlVolumes3D", "Gabriel3DResult", "GabrielReport", "TetMesh", "boundary_certificate",
    "check_gabriel", "control_volumes3d", "load_plc", "read_tetmesh", "read_tetmesh_json", "refine_gabriel",
    "tetrahedralize",
    "validate_plc", "write_tetmesh",
]
