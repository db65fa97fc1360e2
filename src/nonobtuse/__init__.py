"""nonobtuse: Delaunay meshes fit for control-volume simulation, with as few Steiner points as possible."""

from __future__ import annotations

from nonobtuse.domain import Domain
from nonobtuse.errors import InternalError, InvalidInputError, NonobtuseError
from nonobtuse.mesh import Mesh
from nonobtuse.refine import RefineResult, refine

__all__ = ["Domain", "InternalError", "InvalidInputError", "Mesh", "NonobtuseError", "RefineResult", "refine"]
__version__ = "0.1.0"
