"""nonobtuse: Delaunay meshes fit for control-volume simulation, with as few Steiner points as possible."""

from __future__ import annotations

from nonobtuse.domain import Domain
from nonobtuse.errors import InternalError, InvalidInputError, NonobtuseError
from nonobtuse.mesh import Mesh

__all__ = ["Domain", "InternalError", "InvalidInputError", "Mesh", "NonobtuseError"]
__version__ = "0.1.0"
