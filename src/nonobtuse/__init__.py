"""nonobtuse: Delaunay meshes fit for control-volume simulation, with as few Steiner points as possible."""

from __future__ import annotations

from nonobtuse.certificate import CheckReport, check
from nonobtuse.control_volumes import ControlVolumes, control_volumes
from nonobtuse.domain import Domain
from nonobtuse.errors import InternalError, InvalidInputError, NonobtuseError
from nonobtuse.mesh import Mesh
from nonobtuse.refinement import RefineResult, refine
from nonobtuse.triangulation import triangulate

__all__ = [
    "CheckReport", "ControlVolumes", "Domain", "InternalError", "InvalidInputError", "Mesh", "NonobtuseError",
    "RefineResult", "check", "control_volumes", "refine", "triangulate",
]
__version__ = "0.1.0"
