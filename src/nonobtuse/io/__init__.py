"""Reading 2D domains and meshes, writing meshes.

Domains (:func:`load_domain`), chosen by suffix (a file without a known suffix whose content starts with ``{``
is read as JSON):

- Triangle ``.poly`` and ``.node`` (see :mod:`nonobtuse.io.triangle`).
- CG:SHOP 2025 instance ``.json``: ``points_x``, ``points_y`` (numbers), ``region_boundary`` (indices of the
  boundary polygon, counter-clockwise, closed implicitly), ``additional_constraints`` (index pairs).
- nonobtuse domain ``.json``, every key but ``points`` optional, indices 0-based::

      {"points": [[x, y], ...],        # coordinates (numbers)
       "segments": [[i, j], ...],      # boundary loops and interior constraints (interfaces, cracks, wells)
       "holes": [[x, y], ...],         # seeds of removed regions
       "regions": [[x, y, attr], ...], # the region around the seed gets the attribute (e.g. a material id)
       "point_markers": [m, ...],      # boundary marker (integer) per point, as Triangle's vertex markers
       "segment_markers": [m, ...],    # boundary marker per segment (e.g. a boundary condition id)
       "convex_hull": false}           # true: the domain is the convex hull (Triangle -c); absent: decided

Meshes (:func:`write_mesh`, :func:`read_mesh`), chosen by suffix:

- nonobtuse mesh ``.json`` (indices 0-based)::

      {"points": [[x, y], ...],          # the input points first, in input order, then Steiner points
       "triangles": [[i, j, k], ...],    # counter-clockwise
       "segments": [[i, j], ...],        # every constrained subsegment (boundary, interface, dangling)
       "input_points": [[x, y], ...],    # the domain as given
       "input_segments": [[i, j], ...],
       "regions": [attr, ...],           # optional: the region attribute of each triangle
       "point_markers": [m, ...],        # optional: the boundary marker (integer) of each point
       "segment_markers": [m, ...],      # optional: the boundary marker (integer) of each segment
       "stats": {...}}                   # free-form statistics (status, Steiner counts, timings)

- Triangle ``.node``/``.ele``/``.poly`` (written together, with marker columns and the region as the triangle
  attribute; any of the three suffixes names them). Read back, and Triangle's own output read, as a mesh when
  the ``.ele`` is there: ``read_mesh("a.ele")`` (or ``a.node``/``a.poly`` with ``a.ele`` beside them) reads
  Triangle's triangles; it never re-triangulates the ``.node``. :func:`is_mesh_file` says so for the CLI.
- ``.vtu`` and ``.msh`` through meshio (triangles, segments as line cells, region, segment markers and point
  markers; in ``.msh`` the region and segment marker are physical tags and the tag-to-region map is written
  beside it as ``NAME.msh.regions.json``; see :mod:`nonobtuse.io.meshio_formats`). The .vtu is written
  directly, binary appended raw.

Floats are written in shortest round-trip form, so reading gives back the same float64 values. Writes are
atomic (a temporary file beside the target, then os.replace); input files are never modified. Every problem
with a file is an :class:`~nonobtuse.errors.InvalidInputError` naming the file (and line, for text formats).
"""

from __future__ import annotations

import os
from pathlib import Path

from nonobtuse.domain import Domain
from nonobtuse.errors import InvalidInputError
from nonobtuse.io import json_formats, triangle
from nonobtuse.io.meshio_formats import FORMATS as _MESHIO_FORMATS
from nonobtuse.io.meshio_formats import read_meshio, write_meshio
from nonobtuse.mesh import Mesh
from nonobtuse.validate import check_coverage, validate_graph

__all__ = ["is_mesh_file", "load_domain", "read_mesh", "write_mesh"]

_TRIANGLE_SUFFIXES = (".node", ".ele", ".poly")


def load_domain(
    path: str | os.PathLike, *, split_points_on_segments: bool = True, convex_hull: bool | None = None
) -> Domain:
    """Read a domain (.poly, .node, CG:SHOP .json, nonobtuse domain .json) and validate it
    (:func:`nonobtuse.validate.validate_domain`, boundary required closed).

    convex_hull: True closes the domain with the convex hull (Triangle -c: needed for an outer boundary that
    does not close, like box.poly); False takes the domain to be what the closed segment loops enclose; None
    decides: the file's own ``convex_hull`` when it has one (domain .json), else True for a point set and for
    segments that enclose no area at all (only dangling constraints, as in the CDT library's inputs), else
    False. Returns the validated, possibly repaired Domain (see its ``repairs``). Raises InvalidInputError
    naming the file, and the line where known. Cost: reading plus validation, O(n log n).
    """
    path = Path(path)
    domain, file_hull = _read_domain(path)
    if convex_hull is None:
        convex_hull = file_hull
    domain.convex_hull = bool(convex_hull)
    d = validate_graph(domain, split_points_on_segments=split_points_on_segments)
    return check_coverage(d, require_closed=True, decide_convex_hull=convex_hull is None)


def _read_domain(path: Path) -> tuple[Domain, bool | None]:
    suffix = path.suffix.lower()
    if suffix == ".poly":
        return triangle.read_poly(path), None
    if suffix == ".node":
        return triangle.read_node(path), True
    if suffix == ".json" or _looks_like_json(path):
        return json_formats.domain_from_json(path, json_formats.read_json(path))
    raise InvalidInputError(f"{path}: unknown domain format '{path.suffix}' (expected .poly, .node or .json)")


def _looks_like_json(path: Path) -> bool:
    try:
        with open(path, "rb") as f:
            return f.read(64).lstrip().startswith(b"{")
    except OSError as e:
        raise InvalidInputError(f"{path}: cannot read the file ({e})") from None


def is_mesh_file(path: str | os.PathLike) -> bool:
    """True for .vtu/.msh files, Triangle meshes (an ``.ele`` file, or a ``.node``/``.poly`` with the ``.ele``
    of the same name beside it) and JSON files holding an object with ``triangles`` (a nonobtuse mesh); False
    for anything else, including unreadable files (the reader will name the problem)."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix in _MESHIO_FORMATS or suffix == ".ele":
        return True
    if suffix in _TRIANGLE_SUFFIXES:
        return triangle.triangle_mesh_files(path)[1].is_file()
    if suffix != ".json" and not (path.is_file() and _looks_like_json(path)):
        return False
    try:
        data = json_formats.read_json(path)
    except InvalidInputError:
        return False
    return isinstance(data, dict) and "triangles" in data


def read_mesh(path: str | os.PathLike) -> Mesh:
    """Read a mesh: nonobtuse mesh .json (see the module docstring), Triangle .node/.ele/.poly (the .ele and
    .node must exist; :func:`nonobtuse.io.triangle.read_triangle_mesh`), .vtu or .msh (meshio). Only the
    .json records the input domain; from the others every point counts as an input point. Checks structure
    (keys, shapes, index ranges), not geometry. Raises InvalidInputError naming the file."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix in _MESHIO_FORMATS:
        return read_meshio(path)
    if suffix in _TRIANGLE_SUFFIXES:
        return triangle.read_triangle_mesh(path)
    if suffix == ".json" or _looks_like_json(path):
        return json_formats.mesh_from_json(path, json_formats.read_json(path))
    raise InvalidInputError(
        f"{path}: unknown mesh format '{path.suffix}' (expected .json, .node/.ele/.poly, .vtu or .msh)"
    )


def write_mesh(mesh: Mesh, path: str | os.PathLike) -> list[Path]:
    """Write ``mesh`` by suffix: .json (the nonobtuse mesh schema), .node/.ele/.poly (all three, same stem),
    .vtu/.msh (meshio; a .msh of a mesh with regions also writes its tag-to-region map beside it). Markers
    and regions go into every format. Atomic per file. Returns the paths written."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".json":
        json_formats.write_mesh_json(mesh, path)
        return [path]
    if suffix in _TRIANGLE_SUFFIXES:
        return triangle.write_triangle(mesh, path)
    if suffix in _MESHIO_FORMATS:
        return write_meshio(mesh, path)
    raise InvalidInputError(
        f"{path}: unknown mesh format '{path.suffix}' (expected .json, .node/.ele/.poly, .vtu or .msh)"
    )
