"""Tetrahedralization backends on a cube: input points first and in order, positive tets, the whole volume."""

from __future__ import annotations

import numpy as np
import pytest

from mesh3d_shapes import CUBE_POINTS, CUBE_TRIANGLES
from nonobtuse import _core
from nonobtuse.errors import InvalidInputError
from nonobtuse.mesh3d import PLC, tetrahedralize
from nonobtuse.mesh3d.control_volumes3d import signed_tet_volumes
from nonobtuse.mesh3d.load import facet_boundary_segments, merge_coplanar_facets
from nonobtuse.mesh3d.tetrahedralize import input_points_first, tet_faces_once


def cube_plc() -> PLC:
    plc = merge_coplanar_facets(PLC(CUBE_POINTS, CUBE_TRIANGLES, np.arange(12)))
    segments = facet_boundary_segments(plc.triangles, plc.facet_ids)
    return PLC(plc.points, plc.triangles, plc.facet_ids, segments)


def volume(mesh) -> float:
    return float(signed_tet_volumes(mesh.points, mesh.tets).sum())


def check_common(mesh, plc):
    assert np.array_equal(mesh.points[: len(plc.points)], plc.points)  # input points first, in order
    assert (_core.plc_orient3d(mesh.points, mesh.tets) == 1).all()  # positively oriented (exact)
    assert volume(mesh) == pytest.approx(1.0, abs=1e-12)  # the unit cube, all of it
    # the boundary faces close up: every edge in exactly two boundary faces
    e = np.sort(np.concatenate([mesh.boundary_faces[:, [0, 1]], mesh.boundary_faces[:, [1, 2]],
                                mesh.boundary_faces[:, [2, 0]]]), axis=1)
    assert (np.unique(e, axis=0, return_counts=True)[1] == 2).all()


def test_cgal_backend_is_the_delaunay_tetrahedralization_of_the_vertices():
    mesh = tetrahedralize(cube_plc(), "cgal")
    check_common(mesh, cube_plc())
    assert len(mesh.points) == 8 and mesh.stats["steiner_points"] == 0
    assert len(mesh.tets) in (5, 6)  # the 8 corners are co-spherical: CGAL's symbolic perturbation decides
    assert np.array_equal(mesh.boundary_faces, CUBE_TRIANGLES)
    assert len(mesh.segments) == 12


def test_tetgen_backend_keeps_the_boundary_with_Y():
    plc = cube_plc()
    mesh = tetrahedralize(plc, "tetgen")
    check_common(mesh, plc)
    assert len(mesh.boundary_faces) == 12  # Y: the 12 input triangles, not split
    assert sorted(np.bincount(mesh.face_facets).tolist()) == [2] * 6  # facet ids of the 6 squares
    assert len(mesh.segments) == 12


def test_tetgen_switches_can_split_the_boundary():
    plc = cube_plc()
    mesh = tetrahedralize(plc, "tetgen", switches="pq1.2a0.01AQ")  # volume bound 0.01: needs many points
    check_common(mesh, plc)
    assert len(mesh.tets) >= 100  # volume 1 with tets of volume <= 0.01
    assert len(mesh.boundary_faces) > 12 and mesh.stats["steiner_points"] > 0


def test_ftetwild_backend_on_the_cube():
    plc = cube_plc()
    mesh = tetrahedralize(plc, "ftetwild", edge_length_r=0.5, optimize=False)
    # fTetWild may move the surface within its envelope (1e-3 of the bounding box diagonal): the volume
    # is close to 1, and the corners, kept where they are, come first
    assert np.array_equal(mesh.points[:8], plc.points)
    assert (_core.plc_orient3d(mesh.points, mesh.tets) == 1).all()
    assert volume(mesh) == pytest.approx(1.0, abs=1e-2)
    assert len(mesh.boundary_faces) >= 12 and (mesh.face_markers == -1).all()


def test_unknown_backend_and_option():
    with pytest.raises(InvalidInputError, match="unknown backend 'gmsh'"):
        tetrahedralize(cube_plc(), "gmsh")
    with pytest.raises(InvalidInputError, match="takes only switches"):
        tetrahedralize(cube_plc(), "tetgen", quality=2)


def test_input_points_first_renumbers_and_keeps_absent_inputs():
    inputs = np.array([[0.0, 0, 0], [1, 0, 0], [5, 5, 5]])
    # a mesh whose points are (1,0,0), (0,0,0), (0,1,0), (0,0,1): inputs 1 and 0 in another order, input 2
    # absent
    points = np.array([[1.0, 0, 0], [0, 0, 0], [0, 1, 0], [0, 0, 1]])
    merged, tets = input_points_first(inputs, points, np.array([[0, 1, 2, 3]]))
    assert merged.tolist() == [[0, 0, 0], [1, 0, 0], [5, 5, 5], [0, 1, 0], [0, 0, 1]]
    assert tets.tolist() == [[1, 0, 3, 4]]


def test_tet_faces_once_are_outward():
    tets = np.array([[0, 1, 2, 4]])  # (0,0,0), (1,0,0), (0,1,0), (0,0,1): positive
    faces = tet_faces_once(tets)
    p = CUBE_POINTS[faces]
    normals = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    centroid = CUBE_POINTS[[0, 1, 2, 4]].mean(axis=0)
    assert ((normals * (p[:, 0] - centroid)).sum(axis=1) > 0).all()


def test_input_points_first_refuses_equal_inputs():
    inputs = np.array([[0.0, 0, 0], [1, 0, 0], [-0.0, 0, 0]])  # rows 0 and 2 equal (-0.0 == 0.0)
    points = np.array([[1.0, 0, 0], [0, 0, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(InvalidInputError, match="two equal points"):
        input_points_first(inputs, points, np.array([[0, 1, 2, 3]]))
    merged, tets = input_points_first(inputs[:2], points, np.array([[0, 1, 2, 3]]))
    assert merged.tolist() == [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    assert tets.tolist() == [[1, 0, 2, 3]]
