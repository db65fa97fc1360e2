"""Tetrahedral meshes of a PLC from three backends, all returned as a :class:`TetMesh` with the PLC's points
first, in input order, and positively oriented tets (exact orient3d; rows are swapped where needed).

What each backend guarantees:

- ``"cgal"``: the Delaunay tetrahedralization of the PLC's vertices (CGAL, exact predicates), no Steiner
  point. The boundary faces are the PLC's triangles as given (with their facets' markers; facet ids in
  face_facets) and the segments the PLC's; they are faces/edges of the tetrahedralization only where they are
  Delaunay. This is the "before" state of the Gabriel refinement. Where the tetrahedralization conforms to
  every facet (exact check), the tets are its cells in the PLC's regions: components of cells connected across
  faces on no facet, without the unbounded one and those of hole seeds (internal facets separate regions,
  orientation is not used), with region attributes from the seeds or, without seeds, numbered 1, 2, ... when
  there are several regions (``stats["volume_mesh"] == "built"``). Otherwise a flood fill would leak through
  the facets, and the tets are the Delaunay cells whose centroid (rounded to doubles) the surface winds round:
  exact integer winding number != 0 by ray casting (:func:`nonobtuse._core.surface_winding_numbers`), the
  generalized winding number the surface has there, so nested shells are inside and a cell crossed by a facet
  is inside when its centroid is; no regions, hole seeds not used. That needs a closed oriented surface (every
  edge traversed as often one way as the other, as validation orients closed surfaces); on any other (an open
  surface, internal or dangling facets) no tets are built. ``stats["volume_mesh"]`` says which. The exact
  Gabriel check reads only the boundary faces and points, the same in every case.
- ``"tetgen"``: TetGen through the ``tetgen`` package. Default switches ``pq1.414YAQ``: the boundary is kept
  (``Y``: no Steiner point on the boundary), interior quality points are added; ``switches=...`` passes any
  string (e.g. ``"pq1.414AQ"`` lets TetGen split the boundary). TetGen keeps the input points first and in
  order; holes and regions of the PLC are passed on (``A`` gives region attributes). Boundary faces are
  TetGen's faces on input facets, with their facet's marker (facet ids in face_facets).
- ``"ftetwild"``: fTetWild through ``pytetwild``. It remeshes the surface within an envelope (it moves it), so
  input points may be absent from the output. Output points exactly equal to an input point are mapped to that
  input index; absent input points are kept as unreferenced points so that the input comes first. Boundary
  faces are the tet faces with one tet (marker and facet -1: not known); segments are not known (empty).
"""

from __future__ import annotations

import contextlib
import importlib.util
import os
import sys
import tempfile
import time
from dataclasses import replace
from typing import Any

import numpy as np

from nonobtuse import _core
from nonobtuse.errors import InvalidInputError
from nonobtuse.io.raw3d import merge_equal_points
from nonobtuse.mesh3d.gabriel import power_of_two_exponent
from nonobtuse.mesh3d.load import facet_boundary_segments
from nonobtuse.mesh3d.plc import PLC, TetMesh, region_attributes

BACKENDS = ("cgal", "tetgen", "ftetwild")
TETGEN_DEFAULT_SWITCHES = "pq1.414YAQ"
# What the tetgen extension prints on every run (left out of the failure messages it is quoted in)
TETGEN_CHATTER = ("parsing switches", "success")


def positively_oriented(points: np.ndarray, tets: np.ndarray) -> np.ndarray:
    """`tets` (t, 4) with the first two vertices swapped where orient3d (exact) is negative. Raises on a flat
    tet (orient3d == 0)."""
    tets = np.asarray(tets, dtype=np.int64).reshape(-1, 4)
    s = _core.plc_orient3d(points, tets)
    if (s == 0).any():
        k = int(np.flatnonzero(s == 0)[0])
        raise InvalidInputError(f"tetrahedron {k} {tets[k].tolist()} is flat (four coplanar vertices)")
    out = tets.copy()
    neg = s < 0
    out[neg, 0], out[neg, 1] = tets[neg, 1], tets[neg, 0]
    return out


def tet_faces_once(tets: np.ndarray) -> np.ndarray:
    """Faces (f, 3) belonging to exactly one tet, oriented outward (the tets positively oriented), in order of
    first occurrence."""
    # For a positive tet (a, b, c, d) the outward faces are (b, c, d), (a, d, c), (a, b, d), (a, c, b).
    idx = np.array([[1, 2, 3], [0, 3, 2], [0, 1, 3], [0, 2, 1]])
    faces = tets[:, idx].reshape(-1, 3)
    _, first, inv, count = np.unique(np.sort(faces, axis=1), axis=0, return_index=True, return_inverse=True,
                                     return_counts=True)
    once = count[inv.ravel()] == 1
    return faces[np.sort(np.flatnonzero(once))]


@contextlib.contextmanager
def _captured_stdout(into: list[str]):
    """Capture the C-level stdout (file descriptor 1) into ``into`` (its lines): the tetgen extension prints
    there ("parsing switches", "success", and its reasons when it fails), which would corrupt the --json
    output of the CLI and clutter its text."""
    sys.stdout.flush()
    saved = os.dup(1)
    with tempfile.TemporaryFile() as sink:
        try:
            os.dup2(sink.fileno(), 1)
            yield
        finally:
            os.dup2(saved, 1)
            os.close(saved)
            sink.seek(0)
            into.extend(sink.read().decode(errors="replace").splitlines())


@contextlib.contextmanager
def _in_temporary_directory():
    """Run with the working directory set to a fresh temporary directory, removed afterwards."""
    previous = os.getcwd()
    with tempfile.TemporaryDirectory(prefix="nonobtuse-ftetwild-") as tmp:
        os.chdir(tmp)
        try:
            yield
        finally:
            os.chdir(previous)


def _plc_arrays(plc: PLC) -> tuple[np.ndarray, ...]:
    """The PLC as the contiguous arrays the core takes: points, triangles, facet_ids, segments, holes,
    regions. Coordinates are scaled exactly by a power of two into a safe range
    (:func:`power_of_two_exponent`): the exact predicates decide the same, and float sums stay finite."""
    e = power_of_two_exponent(plc.points)
    regions = np.asarray(plc.regions, dtype=np.float64).reshape(-1, 4)
    return (np.ldexp(np.ascontiguousarray(plc.points, dtype=np.float64).reshape(-1, 3), -e),
            np.ascontiguousarray(plc.triangles, dtype=np.int64).reshape(-1, 3),
            np.ascontiguousarray(plc.facet_ids, dtype=np.int64).reshape(-1),
            np.ascontiguousarray(plc.segments, dtype=np.int64).reshape(-1, 2),
            np.ldexp(np.ascontiguousarray(plc.holes, dtype=np.float64).reshape(-1, 3), -e),
            np.ascontiguousarray(np.column_stack([np.ldexp(regions[:, :3], -e), regions[:, 3]])))


def _cgal(plc: PLC, options: dict[str, Any]) -> TetMesh:
    if options:
        raise InvalidInputError(f"backend 'cgal' takes no options, got {sorted(options)}")
    arrays = _plc_arrays(plc)
    d = _core.delaunay_restricted_to_plc(*arrays)
    uncovered = d["uncovered_facets"]
    if len(uncovered) == 0:
        tets, regions, volume_mesh = d["tets"], region_attributes(d["tet_regions"], plc, True), "built"
    else:
        regions = None
        ids = np.sort(plc.facet_ids)  # np.unique hashes: 0.76 s for a million distinct ids, this 0.03
        facets = int(np.count_nonzero(ids[1:] != ids[:-1])) + 1
        # Found from the one-triangle facets alone (delaunay_cells given), the count is a lower bound when
        # some facet has several triangles.
        some = "at least " if len(d["delaunay_cells"]) and facets < len(plc.triangles) else ""
        why = (f"the Delaunay tetrahedralization of the vertices does not conform to {some}{len(uncovered)} "
               f"of {facets} facets (e.g. facet {int(uncovered[0])})")
        tets, volume_mesh = _tets_by_winding_number(arrays[0], plc.triangles, why, d["delaunay_cells"])
    return TetMesh(plc.points.copy(), tets, plc.triangles.copy(), plc.markers_of_facets(plc.facet_ids),
                   plc.segments.copy(), regions, {"volume_mesh": volume_mesh},
                   face_facets=plc.facet_ids.copy())


def _tets_by_winding_number(points: np.ndarray, triangles: np.ndarray, why: str,
                            cells: np.ndarray) -> tuple[np.ndarray, str]:
    """The Delaunay cells of ``points`` (n, 3), scaled into a safe range, that the closed oriented surface
    ``triangles`` (m, 3) winds around (exact; see the module docstring), and the ``volume_mesh`` text, which
    starts "by winding number"; (0, 4) cells and a text starting "not built" when the surface is not closed
    and oriented. ``why``: why the flood fill was not used. ``cells``: the Delaunay cells when
    delaunay_restricted_to_plc already built them, else (0, 4). Cost: O(n log n) for the Delaunay
    tetrahedralization (when not given), plus the ray casts (linear on surfaces without long vertical
    stacks)."""
    edge = _core.plc_unbalanced_edge(points, triangles)
    if edge is not None:
        return np.zeros((0, 4), dtype=np.int64), (
            f"not built: {why}, and the surface is not closed and oriented (edge {edge} is traversed more "
            f"often one way than the other: an open surface, internal or dangling facets), so winding "
            f"numbers do not say what is inside; --backend tetgen builds one")
    given = cells if len(cells) else None  # the general path of delaunay_restricted_to_plc gives none
    return _core.delaunay_cells_inside_surface(points, triangles, given), (
        f"by winding number (exact): {why}; the cells whose centroid the surface winds around, no regions")


def _tetgen(plc: PLC, options: dict[str, Any]) -> TetMesh:
    import tetgen

    switches = options.pop("switches", TETGEN_DEFAULT_SWITCHES)
    if options:
        raise InvalidInputError(f"backend 'tetgen' takes only switches=..., got {sorted(options)}")
    tg = tetgen.TetGen(plc.points, plc.triangles.astype(np.int32), (plc.facet_ids + 1).astype(np.int32))
    for h in plc.holes:
        tg.add_hole(h)
    for r in plc.regions:
        tg.add_region(int(r[3]), r[:3])
    printed: list[str] = []
    try:
        with _captured_stdout(printed):
            node, elem, attr, markers = tg.tetrahedralize(switches=switches)
    except RuntimeError as e:
        said = [line.strip() for line in printed if line.strip() and line.strip() not in TETGEN_CHATTER]
        raise InvalidInputError(f"TetGen failed on {plc.source} with switches {switches!r}: {e}"
                                + (f" (TetGen said: {' '.join(said[-5:])})" if said else "")) from None
    n = len(plc.points)
    if len(node) < n or not np.array_equal(node[:n], plc.points):
        raise InvalidInputError(f"TetGen merged or moved input points of {plc.source} (duplicate vertices?)")
    node = np.asarray(node, dtype=np.float64)
    faces = np.asarray(tg.trifaces, dtype=np.int64).reshape(-1, 3)
    face_facets = np.asarray(markers, dtype=np.int64) - 1  # TetGen was given facet id + 1 as the marker
    regions = np.asarray(attr, dtype=np.float64).ravel() if attr is not None and np.size(attr) else None
    return TetMesh(node, positively_oriented(node, elem), faces, plc.markers_of_facets(face_facets),
                   facet_boundary_segments(faces, face_facets), regions, {"switches": switches},
                   face_facets=face_facets)


def _load_ftetwild():
    """pytetwild's extension module, loaded without the package __init__ (which imports pyvista)."""
    spec = importlib.util.find_spec("pytetwild")
    if spec is None or not spec.submodule_search_locations:
        raise ModuleNotFoundError("backend 'ftetwild' needs the pytetwild package (pip install pytetwild)")
    from pathlib import Path

    so = next(Path(spec.submodule_search_locations[0]).glob("PyfTetWildWrapper*.so"))
    ext_spec = importlib.util.spec_from_file_location("pytetwild.PyfTetWildWrapper", so)
    module = importlib.util.module_from_spec(ext_spec)
    ext_spec.loader.exec_module(module)
    return module


def _ftetwild(plc: PLC, options: dict[str, Any]) -> TetMesh:
    opts = {"optimize": True, "skip_simplify": False, "edge_length_r": 0.05, "edge_length_abs": 0.0,
            "epsilon": 1e-3, "stop_energy": 10.0, "coarsen": False, "num_threads": 1, "num_opt_iter": 80,
            "loglevel": 6, "quiet": True, "vtk_ordering": False, "disable_filtering": False}
    unknown = set(options) - set(opts)
    if unknown:
        raise InvalidInputError(f"backend 'ftetwild': unknown options {sorted(unknown)}; "
                                f"known {sorted(opts)}")
    opts.update(options)
    wrapper = _load_ftetwild()
    no_sizing_field = (np.empty((0, 3)), np.empty((0, 4), dtype=np.int32), np.empty(0))
    with _in_temporary_directory():  # fTetWild writes __tracked_surface.stl into the working directory
        v, t = wrapper.tetrahedralize_mesh(plc.points, plc.triangles.astype(np.uint32), *opts.values(),
                                           *no_sizing_field)
    points, tets = input_points_first(plc.points, np.asarray(v, dtype=np.float64), np.asarray(t, np.int64))
    tets = positively_oriented(points, tets)
    faces = tet_faces_once(tets)
    unknown_facets = np.full(len(faces), -1, dtype=np.int64)
    return TetMesh(points, tets, faces, unknown_facets.copy(), stats={"ftetwild_options": opts},
                   face_facets=unknown_facets)


def input_points_first(inputs: np.ndarray, points: np.ndarray,
                       tets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Renumber a mesh (points, tets) so that `inputs` come first in their order: an output point exactly
    equal to an input point takes its index, the other output points follow in their order."""
    merged, inv = merge_equal_points(np.concatenate([inputs, points]))
    n = len(inputs)
    # merge_equal_points numbers by first occurrence: the first n rows hold max + 1 distinct points, so the
    # inputs are distinct iff that is n (O(n), where counting the distinct numbers sorted them); then they are
    # 0..n-1 and the new points n.. in order
    if n and int(inv[:n].max()) + 1 != n:
        raise InvalidInputError("the input has two equal points")
    return merged, inv[n:][tets]


_BACKEND_FUNCS = {"cgal": _cgal, "tetgen": _tetgen, "ftetwild": _ftetwild}


def tetrahedralize(plc: PLC, backend: str = "cgal", **options: Any) -> TetMesh:
    """Tetrahedralize `plc` with `backend` ("cgal", "tetgen" or "ftetwild"; options per backend: tetgen
    ``switches=``, ftetwild the pytetwild keywords such as ``edge_length_r=``, ``epsilon=``).

    Returns a TetMesh: points (input points first, in input order), positively oriented tets, boundary faces
    with markers, segments; stats with backend, seconds, steiner_points (output points not in the input) and
    warnings (the PLC's, from validation).
    What each backend guarantees is in the module docstring. Raises InvalidInputError for an unknown backend
    or option, or when the backend fails on the input.
    """
    if backend not in _BACKEND_FUNCS:
        raise InvalidInputError(f"unknown backend {backend!r}; expected one of {BACKENDS}")
    t0 = time.perf_counter()
    mesh = _BACKEND_FUNCS[backend](plc, dict(options))
    seconds = time.perf_counter() - t0
    stats = {"backend": backend, "seconds": seconds, "steiner_points": len(mesh.points) - len(plc.points),
             "warnings": list(plc.warnings), **mesh.stats}
    return replace(mesh, stats=stats)
