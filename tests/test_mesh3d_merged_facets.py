"""Coplanar triangles of a surface merged into one facet: a non-convex facet with holes that touches itself
at a vertex, loaded, refined and certified."""

from __future__ import annotations

import numpy as np
import pytest

from mesh3d_shapes import write_off
from nonobtuse.mesh3d import check_gabriel, load_plc, refine_gabriel


def grid(x: int, y: int) -> int:
    return 5 * y + x


def box_with_two_pyramids() -> tuple[np.ndarray, list[list[int]]]:
    """A box [0, 4]^2 x [0, 1] whose top is a 4 x 4 grid of unit quads (vertices grid(x, y) at z = 1) except
    cells (1, 1) and (2, 2), which carry pyramids of height 1/2 (apexes 29 and 30). The two footprints share
    only the vertex (2, 2, 1): the flat part of the top is one facet with two holes that touch at that vertex.
    Bottom corners 25..28; the side polygons list every top grid vertex on their upper edge (no T-junctions).
    """
    top = [[x, y, 1.0] for y in range(5) for x in range(5)]
    bottom = [[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0]]
    apexes = [[1.5, 1.5, 1.5], [2.5, 2.5, 1.5]]
    points = np.array(top + bottom + apexes, dtype=np.float64)
    faces = []
    for j in range(4):
        for i in range(4):
            # counter-clockwise seen from +z
            cell = [grid(i, j), grid(i + 1, j), grid(i + 1, j + 1), grid(i, j + 1)]
            if (i, j) in ((1, 1), (2, 2)):
                apex = 29 if i == 1 else 30
                faces += [[cell[k], cell[(k + 1) % 4], apex] for k in range(4)]
            else:
                faces.append(cell)
    faces.append([25, 28, 27, 26])  # bottom, seen from -z
    faces.append([25, 26] + [grid(x, 0) for x in (4, 3, 2, 1, 0)])  # y = 0
    faces.append([26, 27] + [grid(4, y) for y in (4, 3, 2, 1, 0)])  # x = 4
    faces.append([27, 28] + [grid(x, 4) for x in (0, 1, 2, 3, 4)])  # y = 4
    faces.append([28, 25] + [grid(0, y) for y in (0, 1, 2, 3, 4)])  # x = 0
    return points, faces


@pytest.fixture
def plc(tmp_path):
    points, faces = box_with_two_pyramids()
    return load_plc(write_off(tmp_path / "box.off", points, faces))


def test_flat_cells_merge_into_one_facet_with_touching_holes(plc):
    # The 14 flat quads (2 triangles each, all corners at z = 1) are one facet, numbered 0 (the first triangle
    # is flat); the 8 pyramid triangles are not coplanar with another or with the top (apexes 1/2 above it): 8
    # facets. Bottom and 4 sides: 5 facets.
    ids = plc.facet_ids
    flat = (plc.points[plc.triangles][:, :, 2] == 1.0).all(axis=1)
    assert flat.sum() == 28
    assert (ids[flat] == 0).all() and (ids[~flat] != 0).all()
    assert len(np.unique(ids)) == 1 + 8 + 5
    # Segments: the 16 unit edges around the top, the 8 footprint edges, 8 pyramid ridges, 4 bottom edges and
    # 4 vertical box edges; the grid edges between flat cells and the quads' diagonals are not segments.
    assert len(plc.segments) == 16 + 8 + 8 + 4 + 4
    flat_inner = {(grid(1, 0), grid(1, 1)), (grid(0, 1), grid(1, 1)), (grid(3, 3), grid(3, 4))}
    assert not flat_inner & {tuple(s) for s in plc.segments.tolist()}


def test_refinement_keeps_the_holes_and_converges(plc):
    res = refine_gabriel(plc, max_steiner=2000, time_limit=20)
    assert res.status == "converged", res.stats["diagnosis"]["stop_reason"]
    assert check_gabriel(res.mesh).ok  # the certificate, recomputed on the mesh as returned
    mesh = res.mesh
    # Facet 0 is covered exactly by its subfacets: area 16 - 2 footprints = 14 (the holes are not filled, and
    # the touching vertex does not join them into the facet's domain).
    p = mesh.points[mesh.boundary_faces[mesh.face_facets == 0]]
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum()
    assert area == pytest.approx(14.0, abs=1e-12)
    assert np.allclose(p[:, :, 2], 1.0)
    # The volume: the box 16, plus two pyramids of base 1 and height 1/2 (1/6 each).
    q = mesh.points[mesh.tets]
    volume = np.linalg.det(q[:, 1:] - q[:, :1]).sum() / 6.0
    assert volume == pytest.approx(16.0 + 2.0 / 6.0, abs=1e-12)
