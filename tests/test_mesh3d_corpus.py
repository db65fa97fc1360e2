"""The committed 3D corpus (tests/data/3d, rebuilt by experiments/corpus3d.py): every kind of PLC loads,
tetrahedralizes with the cgal backend, is checked exactly and refined; regions land on the right tets and
internal facets are part of the certificate."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from experiments import corpus3d

from nonobtuse import _core
from nonobtuse.cli import EXIT_NOT_CONVERGED, EXIT_OK, EXIT_VIOLATIONS, main
from nonobtuse.mesh3d import PLC, check_gabriel, load_plc, refine_gabriel, tetrahedralize

DATA = Path(__file__).parent / "data" / "3d"
FILES = sorted(p.name for p in DATA.glob("*") if p.suffix in (".off", ".poly"))
# What each file is made to contain (experiments/corpus3d.py): the warnings its loading must give.
WARNINGS = {"window_box_fin.poly": ["2 dangling faces"],
            "schonhardt.off": ["inconsistent orientation: 1 faces"]}
# Axis-aligned boxes the multi-region PLCs fill: (lo, hi) of their volume.
BOXES = {"two_cubes_face.poly": ([0, 0, 0], [2, 1, 1]), "layered_box.poly": ([0, 0, 0], [4, 4, 3]),
         "window_box_fin.poly": ([0, 0, 0], [2, 2, 1])}


def tet_volumes(points: np.ndarray, tets: np.ndarray) -> np.ndarray:
    p = points[tets]
    return np.einsum("ij,ij->i", p[:, 1] - p[:, 0], np.cross(p[:, 2] - p[:, 0], p[:, 3] - p[:, 0])) / 6


def enclosed_volume(plc: PLC, name: str) -> float:
    """The volume the PLC encloses: its box for the multi-region files, else the divergence theorem on its
    (outward oriented, closed) triangles."""
    if name in BOXES:
        lo, hi = BOXES[name]
        return float(np.prod(np.subtract(hi, lo)))
    p = plc.points[plc.triangles]
    return float(np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6)


def facet_areas(points: np.ndarray, faces: np.ndarray, markers: np.ndarray) -> dict[int, float]:
    p = points[faces]
    area = np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1) / 2
    return {int(m): float(area[markers == m].sum()) for m in np.unique(markers)}


def test_the_corpus_is_small_and_complete():
    assert len(FILES) == 13
    assert sum((DATA / f).stat().st_size for f in FILES) < 2_000_000


def same_but_for_last_bits(built: str, committed: str) -> bool:
    """Token by token: words and integers equal, floats within 1e-14 relative (the generator's norms go
    through BLAS, whose kernels differ by CPU in the last bit: icosphere_jitter.off on an AVX-512 machine)."""
    a, b = built.split(), committed.split()
    if len(a) != len(b):
        return False
    for x, y in zip(a, b):
        if x == y:
            continue
        try:
            u, v = float(x), float(y)
        except ValueError:
            return False
        if "." not in x + y or abs(u - v) > 1e-14 * max(abs(u), abs(v)):
            return False
    return True


def test_the_generator_rebuilds_the_committed_files(tmp_path):
    pytest.importorskip("skimage", reason="the marching-cubes files need scikit-image (experiments extra)")
    for path in corpus3d.build(tmp_path):
        assert same_but_for_last_bits(path.read_text(), (DATA / path.name).read_text()), path.name
    assert not same_but_for_last_bits("OFF 1 0.5", "OFF 1 0.5000001")
    assert not same_but_for_last_bits("1 2", "1 3")


@pytest.mark.parametrize("name", FILES)
def test_loads_with_the_warnings_it_is_made_for(name):
    plc = load_plc(DATA / name)
    expected = WARNINGS.get(name, [])
    assert len(plc.warnings) == len(expected)
    assert all(w.startswith(e) for w, e in zip(plc.warnings, expected))


@pytest.mark.parametrize("name", FILES)
def test_cgal_backend_tets_fill_the_plc_and_the_check_is_exact(name):
    plc = load_plc(DATA / name)
    mesh = tetrahedralize(plc, "cgal")
    assert np.all(_core.plc_orient3d(mesh.points, mesh.tets) > 0)
    report = check_gabriel(mesh)
    assert report.n_faces == len(plc.triangles)  # every facet, internal and dangling ones too
    if mesh.stats["volume_mesh"] == "built":
        # conforming: the flood fill found exactly the enclosed volume
        volume = tet_volumes(mesh.points, mesh.tets).sum()
        assert volume == pytest.approx(enclosed_volume(plc, name), rel=1e-9)
    else:  # on these files a Delaunay edge crosses a facet, whose subfacets then are no Delaunay faces
        assert mesh.stats["volume_mesh"].startswith("by winding number") and not report.ok


def expected_layer(c: np.ndarray) -> float:
    """The region attribute (1, 2, 3 from the bottom) of a point of the layered box."""
    below = [c[2] > corpus3d.interface_height_at(k, c[0], c[1]) for k in (1, 2)]
    return 1.0 + sum(below)


def check_regions(name: str, points: np.ndarray, tets: np.ndarray, regions: np.ndarray) -> None:
    centroids = points[tets].mean(axis=1)
    if name == "two_cubes_face.poly":  # seeds: attribute 1 in x < 1, 2 in x > 1
        assert np.array_equal(regions, np.where(centroids[:, 0] < 1, 1.0, 2.0))
    elif name == "layered_box.poly":
        assert np.array_equal(regions, [expected_layer(c) for c in centroids])
    elif name == "cubes_edge.off":  # no seeds: the two cubes are regions 1 and 2, in some order
        left = centroids[:, 0] < 1
        assert len(set(regions[left])) == 1 and len(set(regions[~left])) == 1
        assert {regions[left][0], regions[~left][0]} == {1.0, 2.0}


@pytest.mark.parametrize("name", ["two_cubes_face.poly", "layered_box.poly", "cubes_edge.off"])
def test_region_attributes_land_on_the_tets_of_their_region(name):
    plc = load_plc(DATA / name)
    mesh = tetrahedralize(plc, "cgal")
    assert mesh.stats["volume_mesh"] == "built"
    check_regions(name, mesh.points, mesh.tets, mesh.tet_regions)
    result = refine_gabriel(plc, time_limit=60)
    assert result.status == "converged" and check_gabriel(result.mesh).ok
    check_regions(name, result.mesh.points, result.mesh.tets, result.mesh.tet_regions)


def test_internal_facets_are_refined_and_certified():
    # the two wavy interfaces of the layered box are internal facets (facet ids of their triangles; marker
    # 11 and 12 in the file); the Delaunay tetrahedralization of the input has encroached interface faces
    plc = load_plc(DATA / "layered_box.poly")
    interface = set(range(2, 2 + 2 * len(corpus3d.layer_grid()[1])))  # after the bottom and top facets
    before = check_gabriel(tetrahedralize(plc, "cgal"))
    assert set(plc.facet_ids[before.faces].tolist()) & interface
    result = refine_gabriel(plc, time_limit=60)
    assert result.status == "converged"
    # the certificate covers every facet, the interfaces included, once: the boundary faces of each facet
    # have the area of the facet
    got = facet_areas(result.mesh.points, result.mesh.boundary_faces, result.mesh.face_facets)
    want = facet_areas(plc.points, plc.triangles, plc.facet_ids)
    assert got.keys() == want.keys() and interface <= got.keys()
    assert all(got[f] == pytest.approx(want[f], rel=1e-12) for f in want)
    assert check_gabriel(result.mesh).ok and result.report.n_faces == len(result.mesh.boundary_faces)


@pytest.mark.parametrize("name", FILES)
def test_refine_gabriel_status_is_the_exact_check(name):
    plc = load_plc(DATA / name)
    result = refine_gabriel(plc, time_limit=3)
    report = check_gabriel(result.mesh)
    complete = result.stats["unchecked_faces"] == 0 and result.stats["unchecked_segments"] == 0
    assert (result.status == "converged") == (report.ok and complete)
    assert result.stats["warnings"] == list(plc.warnings)
    if result.stats["volume_mesh"] == "built" and len(result.mesh.tets):
        total = tet_volumes(result.mesh.points, result.mesh.tets).sum()
        assert total == pytest.approx(enclosed_volume(plc, name), rel=1e-9)


def test_check3d_and_refine3d_run_on_a_multi_region_plc(tmp_path, capsys):
    path = DATA / "layered_box.poly"
    assert main(["check3d", str(path), "--json"]) == EXIT_VIOLATIONS
    out = json.loads(capsys.readouterr().out)
    assert out["encroached_facets"] > 0 and out["warnings"] == []
    code = main(["refine3d", str(path), "-o", str(tmp_path / "out.json"), "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == (EXIT_OK if out["status"] == "converged" else EXIT_NOT_CONVERGED)
    written = json.loads((tmp_path / "out.json").read_text())
    assert sorted(set(written["tet_regions"])) == [1.0, 2.0, 3.0]


def test_check3d_reports_the_orientation_warning(capsys):
    assert main(["check3d", str(DATA / "schonhardt.off"), "--json"]) == EXIT_VIOLATIONS
    out = json.loads(capsys.readouterr().out)
    assert len(out["warnings"]) == 1 and out["warnings"][0].startswith("inconsistent orientation")


def test_loading_never_modifies_the_corpus():
    before = {f: (DATA / f).read_bytes() for f in FILES}
    for f in FILES:
        load_plc(DATA / f)
    assert {f: (DATA / f).read_bytes() for f in FILES} == before


@pytest.mark.parametrize("suffix", [".vtu", ".msh"])
def test_region_attributes_reach_the_meshio_formats(tmp_path, suffix):
    meshio = pytest.importorskip("meshio")
    from nonobtuse.mesh3d import write_tetmesh

    result = refine_gabriel(load_plc(DATA / "layered_box.poly"), time_limit=60)
    write_tetmesh(result.mesh, tmp_path / f"out{suffix}")
    back = meshio.read(tmp_path / f"out{suffix}")
    # .vtu: the region attribute is cell data "region" ("marker" holds the face markers, 0 on tets);
    # .msh: the physical tag of a tet (the integer regions of the layered box map to themselves)
    key = "region" if suffix == ".vtu" else "gmsh:physical"
    tetra = [k for k, block in enumerate(back.cells) if block.type == "tetra"]
    assert len(tetra) == 1
    assert sorted(set(result.mesh.tet_regions.tolist())) == [1.0, 2.0, 3.0]
    regions = np.asarray(back.cell_data[key][tetra[0]], dtype=np.float64)
    assert np.array_equal(regions, result.mesh.tet_regions)
