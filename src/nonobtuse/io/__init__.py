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

3D: :func:`load_plc` (OFF, OBJ, PLY, STL surfaces and TetGen .poly/.smesh PLCs, see
:mod:`nonobtuse.mesh3d.load`), :func:`write_tetmesh` and :func:`read_tetmesh_json` (see
:mod:`nonobtuse.io.tetmesh`); they are imported on first use, so 2D work does not load the 3D pipeline.

One module per format family: :mod:`~nonobtuse.io.triangle`, :mod:`~nonobtuse.io.json_formats`,
:mod:`~nonobtuse.io.meshio_formats` (the one table of meshio formats), :mod:`~nonobtuse.io.surfaces`,
:mod:`~nonobtuse.io.tetgen`, :mod:`~nonobtuse.io.tetmesh`; :mod:`~nonobtuse.io.raw3d` is what a 3D file holds
before its facets are triangulated. Shared plumbing for every writer, public here: :func:`atomic_path`,
:func:`atomic_text` (atomic writes), :func:`require_writable` (the output's folder, checked before any work)
and :func:`jsonable` (numpy values to JSON ones).

Floats are written in shortest round-trip form, so reading gives back the same float64 values. Writes are
atomic (a temporary file beside the target, then os.replace); input files are never modified. Every problem
with a file is an :class:`~nonobtuse.errors.InvalidInputError` naming the file (and line, for text formats).
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from nonobtuse import _core
from nonobtuse.domain import Domain
from nonobtuse.errors import InvalidInputError
from nonobtuse.io import json_formats, triangle
from nonobtuse.io._files import atomic_path, atomic_text, jsonable, require_writable
from nonobtuse.io.meshio_formats import FORMATS as _MESHIO_FORMATS
from nonobtuse.io.meshio_formats import read_meshio, region_map_path, write_meshio
from nonobtuse.mesh import Mesh
from nonobtuse.validate import validate_domain

if TYPE_CHECKING:
    from nonobtuse.io.tetmesh import read_tetmesh_json, write_tetmesh
    from nonobtuse.mesh3d.load import load_plc

__all__ = [
    "atomic_path", "atomic_text", "is_mesh_file", "jsonable", "load_domain", "load_plc", "mesh_output_paths",
    "read_mesh", "read_tetmesh_json", "require_writable", "write_mesh", "write_tetmesh",
]

_3D_ENTRY_POINTS = {"load_plc": "nonobtuse.mesh3d.load", "read_tetmesh_json": "nonobtuse.io.tetmesh",
                    "write_tetmesh": "nonobtuse.io.tetmesh"}


def __getattr__(name: str) -> Any:
    """The 3D entry points, imported on first use (PEP 562)."""
    if name in _3D_ENTRY_POINTS:
        import importlib

        return getattr(importlib.import_module(_3D_ENTRY_POINTS[name]), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


_TRIANGLE_SUFFIXES = (".node", ".ele", ".poly")


def load_domain(
    path: str | os.PathLike, *, split_points_on_segments: bool = True, convex_hull: bool | None = None
) -> Domain:
    """Read a domain (.poly, .node, CG:SHOP .json, nonobtuse domain .json) and validate it
    (:func:`nonobtuse.validate.validate_domain`, boundary required closed).

    convex_hull: True closes the domain with the convex hull (Triangle -c: needed for an outer boundary that
    does not close, like box.poly); False takes the domain to be what the closed segment loops enclose; None
    decides: the file's own ``convex_hull`` when it has one (domain .json), else True for a point set (no
    segments), else False (segments that enclose no area, such as an open polygon or the CDT library's
    dangling constraints, are then refused as an open boundary: never closed by the hull unasked). Returns
    the validated (``Domain.validated``), possibly repaired Domain (see its ``repairs``). Raises
    InvalidInputError naming the file, and the line where known. Cost: reading plus validation, O(n log n).
    """
    path = Path(path)
    domain, file_hull = _read_domain(path)
    if convex_hull is None:
        convex_hull = file_hull
    domain.convex_hull = bool(convex_hull)
    return validate_domain(
        domain, split_points_on_segments=split_points_on_segments, decide_convex_hull=convex_hull is None
    )


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
    (keys, shapes, index ranges, finite coordinates) and that the boundary does not cross itself
    (:func:`require_simple_boundary`); orientation and the embedding around each vertex are checked by
    :func:`nonobtuse.check`. Raises InvalidInputError naming the file."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix in _MESHIO_FORMATS:
        mesh = read_meshio(path)
    elif suffix in _TRIANGLE_SUFFIXES:
        mesh = triangle.read_triangle_mesh(path)
    elif suffix == ".json" or _looks_like_json(path):
        mesh = json_formats.mesh_from_json(path, json_formats.read_json(path))
    else:
        raise InvalidInputError(
            f"{path}: unknown mesh format '{path.suffix}' (expected .json, .node/.ele/.poly, .vtu or .msh)"
        )
    try:
        require_simple_boundary(mesh)
    except InvalidInputError as e:
        raise InvalidInputError(f"{path}: {e}") from None
    return mesh


def require_simple_boundary(mesh: Mesh) -> None:
    """InvalidInputError when two boundary edges of ``mesh`` (edges of one triangle only) cross, overlap, or
    one passes through a vertex of another, or two boundary vertices coincide: the triangles then overlap
    (decided exactly, :func:`nonobtuse._core.find_segment_intersections`). With the embedding check around
    every vertex (the certificate), this rules out overlaps whose sheets' boundaries meet; sheets lying
    wholly on top of one another without their boundaries meeting are not detected. Cost: O(m log m) for m
    triangles plus the box-intersection search over the boundary edges."""
    t = np.asarray(mesh.triangles, dtype=np.int64).reshape(-1, 3)
    edges = np.sort(np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]), axis=1)
    n = len(mesh.points)
    keys, count = np.unique(edges[:, 0] * n + edges[:, 1], return_counts=True)  # indices checked < n
    once = keys[count == 1]
    boundary = np.column_stack([once // n, once % n])
    vertices, local = np.unique(boundary, return_inverse=True)
    points = np.ascontiguousarray(np.asarray(mesh.points, dtype=np.float64)[vertices])
    order = np.lexsort((points[:, 1], points[:, 0]))
    same = np.flatnonzero((points[order][1:] == points[order][:-1]).all(axis=1))
    if len(same):
        a, b = sorted(int(vertices[order[k]]) for k in (same[0], same[0] + 1))
        raise InvalidInputError(f"boundary points {a} and {b} coincide at {points[order[same[0]]].tolist()}")
    found = _core.find_segment_intersections(points, np.ascontiguousarray(local.reshape(-1, 2)))
    for kind, what in (("crossings", "cross"), ("overlaps", "overlap")):
        if len(getattr(found, kind)):
            s, u = (vertices[local.reshape(-1, 2)[k]].tolist() for k in getattr(found, kind)[0])
            raise InvalidInputError(f"boundary edges {s} and {u} {what}: the triangles overlap")
    if len(found.points_on_segments):
        p, s = found.points_on_segments[0]
        raise InvalidInputError(f"point {int(vertices[p])} lies inside boundary edge "
                                f"{vertices[local.reshape(-1, 2)[s]].tolist()}: the triangles overlap")


def mesh_output_paths(path: str | os.PathLike) -> list[Path]:
    """The files :func:`write_mesh` writes for ``path`` (three for a Triangle suffix, else ``path``)."""
    path = Path(path)
    if path.suffix.lower() in _TRIANGLE_SUFFIXES:
        return triangle.output_paths(path)
    return [path, region_map_path(path)] if path.suffix.lower() == ".msh" else [path]


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
