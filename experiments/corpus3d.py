"""The small 3D test corpus of `tests/data/3d/`, rebuilt deterministically:
``python -m experiments.corpus3d [--out DIR]`` (needs scikit-image, the experiments extra);
``python -m experiments.corpus3d --table`` then runs the default ``refine_gabriel`` (as ``nonobtuse
refine3d``) on every file and writes the status table (`experiments/results/corpus3d_refine.md`).

Families (provenance and sizes in `tests/data/3d/SOURCES.md`):

- scan-like surfaces with skinny triangles: marching cubes (scikit-image, Lewiner) of a torus, of a gyroid
  piece cut by a ball and of two spheres touching through a thin neck; jittered icospheres;
- CAD-like parts with 1-5 degree angles: a knife prism (2 degree dihedral), a block with a ramp (5 degree
  dihedral at the ramp's foot), a block with a thin spike (3 degree apex angle between its edges);
- non-manifold and multi-region PLCs: two cubes sharing a face (an internal facet, two region seeds), a box of
  three geological layers with wavy interfaces (region attributes 1, 2, 3), two cubes sharing an edge, two
  octahedra sharing a vertex (an hourglass), a box with a window facet filling a hole of its top facet and a
  dangling fin standing on its bottom;
- the Schonhardt polyhedron (a triangular prism twisted by 30 degrees; no tetrahedralization without Steiner
  points), written with one face reversed, as found in the wild.

Every coordinate is a float64 written with repr (exact round trip); marching-cubes vertices are float32 values
widened exactly. Every file is checked by `load_plc` after writing.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable
from pathlib import Path

import numpy as np

from nonobtuse.io._files import atomic_text

OUT = Path(__file__).resolve().parent.parent / "tests" / "data" / "3d"
SEED = 20261202

Polygons = list[list[int]]


def write_off(path: Path, points: np.ndarray, faces: Polygons | np.ndarray) -> None:
    """OFF with one polygon per face (0-based indices)."""
    with atomic_text(path) as f:
        f.write(f"OFF\n{len(points)} {len(faces)} 0\n")
        f.writelines(" ".join(repr(float(x)) for x in p) + "\n" for p in points)
        rows = faces.tolist() if isinstance(faces, np.ndarray) else faces
        f.writelines(" ".join(str(int(v)) for v in [len(q), *q]) + "\n" for q in rows)


def write_poly(path: Path, points: np.ndarray, facets: list[tuple], regions: list[tuple] = ()) -> None:
    """TetGen .poly (1-based nodes): facets as (polygons, boundary marker[, facet hole points]), no volume
    holes, regions (x, y, z, attribute)."""
    with atomic_text(path) as f:
        f.write(f"{len(points)} 3 0 0\n")
        f.writelines(f"{i + 1} " + " ".join(repr(float(x)) for x in p) + "\n" for i, p in enumerate(points))
        f.write(f"{len(facets)} 1\n")
        for polygons, marker, *facet_holes in facets:
            holes = facet_holes[0] if facet_holes else []
            f.write(f"{len(polygons)} {len(holes)} {marker}\n")
            f.writelines(" ".join(str(v) for v in [len(q), *(i + 1 for i in q)]) + "\n" for q in polygons)
            f.writelines(f"{k + 1} " + " ".join(repr(float(x)) for x in h) + "\n"
                         for k, h in enumerate(holes))
        f.write("0\n")
        f.write(f"{len(regions)}\n")
        f.writelines(f"{k + 1} " + " ".join(repr(float(x)) for x in r) + "\n" for k, r in enumerate(regions))


# ---------------------------------------------------------------------------------------------------------
# Scan-like surfaces


def marching_cubes(field: Callable[[np.ndarray, np.ndarray, np.ndarray], np.ndarray], n: int,
                   half: float) -> tuple[np.ndarray, np.ndarray]:
    """The level-0 surface of `field` on an n^3 grid over [-half, half]^3 (scikit-image, Lewiner), outward.
    The grid is offset by an irrational fraction of a cell so that no grid value is exactly 0 (no degenerate
    triangles)."""
    from skimage.measure import marching_cubes as mc

    step = 2 * half / (n - 1)
    axis = -half + step * (np.arange(n) + 0.1234567)
    x, y, z = np.meshgrid(axis, axis, axis, indexing="ij")
    verts, faces, _, _ = mc(field(x, y, z).astype(np.float32), 0.0, spacing=(step,) * 3,
                            method="lewiner")
    points = (verts + np.float32(axis[0])).astype(np.float32).astype(np.float64)
    # scikit-image orients faces towards increasing field values; the inside has negative values here
    return points, faces[:, ::-1].astype(np.int64)


def torus(x, y, z):
    return (np.sqrt(x * x + y * y) - 1.0) ** 2 + z * z - 0.4**2


def gyroid_piece(x, y, z):
    s = 2.2
    g = np.sin(s * x) * np.cos(s * y) + np.sin(s * y) * np.cos(s * z) + np.sin(s * z) * np.cos(s * x)
    return np.maximum(g - 0.3, np.sqrt(x * x + y * y + z * z) - 1.6)


def two_spheres(x, y, z):
    # radius 0.8 at x = -0.79 and 0.79: they overlap by 0.02, a thin neck of skinny triangles
    left, right = np.sqrt((x + 0.79) ** 2 + y * y + z * z), np.sqrt((x - 0.79) ** 2 + y * y + z * z)
    return np.minimum(left, right) - 0.8


def icosphere(subdivisions: int) -> tuple[np.ndarray, np.ndarray]:
    """Unit icosphere: an icosahedron with each triangle split in 4, `subdivisions` times; outward."""
    t = (1 + 5**0.5) / 2
    p = [[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
         [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]]
    f = [[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2],
         [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11],
         [6, 2, 10], [8, 6, 7], [9, 8, 1]]
    points = [np.array(q, dtype=np.float64) / np.linalg.norm(q) for q in p]
    mid: dict[tuple[int, int], int] = {}  # edge -> its midpoint, projected on the sphere

    def middle(a: int, b: int) -> int:
        k = (min(a, b), max(a, b))
        if k not in mid:
            m = points[a] + points[b]
            points.append(m / np.linalg.norm(m))
            mid[k] = len(points) - 1
        return mid[k]

    for _ in range(subdivisions):
        f = [g for a, b, c in f for g in ([a, middle(a, b), middle(c, a)], [b, middle(b, c), middle(a, b)],
                                          [c, middle(c, a), middle(b, c)], [middle(a, b), middle(b, c),
                                                                            middle(c, a)])]
    return np.array(points), np.array(f, dtype=np.int64)


def jittered_icosphere(subdivisions: int, jitter: float, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """An icosphere whose vertices move by up to `jitter` times the edge length along random tangent
    directions (seeded): a convex-ish surface of skinny, nearly flat triangles."""
    points, faces = icosphere(subdivisions)
    rng = np.random.default_rng(seed)
    edge = np.linalg.norm(points[faces[0, 0]] - points[faces[0, 1]])
    d = rng.normal(size=points.shape)
    d -= (d * points).sum(axis=1, keepdims=True) * points  # tangent
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    return points + jitter * edge * rng.uniform(size=(len(points), 1)) * d, faces


# ---------------------------------------------------------------------------------------------------------
# CAD-like parts (polygonal faces, counter-clockwise seen from outside)


def prism(profile: np.ndarray, depth: float) -> tuple[np.ndarray, Polygons]:
    """The prism over a counter-clockwise polygon `profile` (k, 2) in the xy plane, z from 0 to depth."""
    k = len(profile)
    points = np.concatenate([np.column_stack([profile, np.full(k, z)]) for z in (0.0, depth)])
    faces = [list(range(k))[::-1], list(range(k, 2 * k))]
    faces += [[i, (i + 1) % k, k + (i + 1) % k, k + i] for i in range(k)]
    return points, faces


def knife(degrees: float) -> tuple[np.ndarray, Polygons]:
    """A triangular prism whose cross-section has an apex angle of `degrees` (a knife edge)."""
    h = np.tan(np.radians(degrees) / 2) * 4.0
    return prism(np.array([[0.0, 0.0], [4.0, -h], [4.0, h]]), 1.0)


def ramp_block(degrees: float) -> tuple[np.ndarray, Polygons]:
    """A block 4 x 1 x 1 whose top falls into a ramp meeting the bottom at `degrees` (profile in xz)."""
    length = 1.0 / np.tan(np.radians(degrees))
    profile = np.array([[0.0, 0.0], [2.0 + length, 0.0], [2.0, 1.0], [0.0, 1.0]])  # x, z
    points, faces = prism(profile, 1.0)
    return points[:, [0, 2, 1]] * [1, -1, 1], faces  # the profile in xz, extruded along -y: still outward


def spike_block(degrees: float) -> tuple[np.ndarray, Polygons]:
    """A unit cube with a square pyramid on its top face whose opposite lateral edges meet at `degrees`."""
    h = 0.1 * 2**0.5 / np.tan(np.radians(degrees) / 2)  # base half-diagonal 0.1 sqrt(2), apex over the centre
    c = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]]
    b = [[0.4, 0.4, 1], [0.6, 0.4, 1], [0.6, 0.6, 1], [0.4, 0.6, 1]]
    points = np.array(c + b + [[0.5, 0.5, 1 + h]], dtype=np.float64)
    faces = [[0, 3, 2, 1], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7],
             # the top square around the pyramid's base: four trapezoids, merged into one facet on loading
             [4, 5, 9, 8], [5, 6, 10, 9], [6, 7, 11, 10], [7, 4, 8, 11],
             [8, 9, 12], [9, 10, 12], [10, 11, 12], [11, 8, 12]]
    return points, faces


# ---------------------------------------------------------------------------------------------------------
# Non-manifold and multi-region PLCs


def box_points(lo, hi) -> np.ndarray:
    """The 8 corners of an axis-aligned box; corner i has x from bit 0, y from bit 1, z from bit 2."""
    return np.array([[(hi if i & 1 else lo)[0], (hi if i & 2 else lo)[1], (hi if i & 4 else lo)[2]]
                     for i in range(8)], dtype=np.float64)


BOX_QUADS = [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]]


def two_cubes_sharing_a_face() -> tuple[np.ndarray, list[tuple[Polygons, int]], list]:
    """Unit cubes [0,1]^3 and [1,2]x[0,1]^2; the square x = 1 is an internal facet; regions 1 and 2."""
    right_side = box_points([1, 0, 0], [2, 1, 1])[[1, 3, 5, 7]]
    points = np.concatenate([box_points([0, 0, 0], [1, 1, 1]), right_side])
    # right cube corners: x = 1 side = left cube's 1, 3, 5, 7; x = 2 side = new points 8, 9, 10, 11
    right = {0: 1, 1: 8, 2: 3, 3: 9, 4: 5, 5: 10, 6: 7, 7: 11}
    left_faces = [q for k, q in enumerate(BOX_QUADS) if k != 5]
    right_faces = [[right[v] for v in q] for k, q in enumerate(BOX_QUADS) if k != 4]
    facets = [([q], 1) for q in left_faces] + [([q], 2) for q in right_faces] + [([[1, 3, 7, 5]], 3)]
    return points, facets, [(0.5, 0.5, 0.5, 1.0), (1.5, 0.5, 0.5, 2.0)]


LAYER_GRID = 6  # interface vertices per side
LAYER_BOX = (4.0, 4.0)


def interface_heights(k: int, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Height of wavy interface k (1 or 2) at grid vertices (x, y) of the layered box."""
    base = {1: 1.0, 2: 2.0}[k]
    return base + 0.25 * np.sin(1.3 * x + 0.7 * k) * np.cos(0.9 * y - 0.4 * k)


def layer_grid() -> tuple[np.ndarray, np.ndarray]:
    """The xy grid (g, 2) of the interfaces and its triangles (t, 3), each cell split along its diagonal from
    (i, j) to (i + 1, j + 1)."""
    n = LAYER_GRID
    xs, ys = np.linspace(0, LAYER_BOX[0], n), np.linspace(0, LAYER_BOX[1], n)
    grid = np.array([[x, y] for y in ys for x in xs])
    tris = []
    for j in range(n - 1):
        for i in range(n - 1):
            a, b, c, d = j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i
            tris += [[a, b, c], [a, c, d]]
    return grid, np.array(tris, dtype=np.int64)


def interface_height_at(k: int, x: float, y: float) -> float:
    """Height of the piecewise linear interface k of the layered box at any (x, y) inside it."""
    grid, tris = layer_grid()
    z = interface_heights(k, grid[:, 0], grid[:, 1])
    for t in tris:
        a, b, c = grid[t]
        m = np.array([b - a, c - a]).T
        u, v = np.linalg.solve(m, np.array([x, y]) - a)
        if u >= -1e-12 and v >= -1e-12 and u + v <= 1 + 1e-12:
            return float(z[t[0]] + u * (z[t[1]] - z[t[0]]) + v * (z[t[2]] - z[t[0]]))
    raise ValueError(f"({x}, {y}) is outside the layered box")


def layered_box() -> tuple[np.ndarray, list[tuple[Polygons, int]], list]:
    """A 4 x 4 x 3 box of three layers separated by two wavy interfaces (triangulated, each triangle a facet);
    the side walls are split into one polygon per layer; region attributes 1, 2, 3 from bottom to top."""
    n = LAYER_GRID
    grid, tris = layer_grid()
    # the boundary of the grid, counter-clockwise seen from above
    ring = (list(range(n)) + [i * n + n - 1 for i in range(1, n)] + [n * n - 1 - i for i in range(1, n)]
            + [(n - 1 - i) * n for i in range(1, n - 1)])
    heights = [np.zeros(len(grid)), interface_heights(1, grid[:, 0], grid[:, 1]),
               interface_heights(2, grid[:, 0], grid[:, 1]), np.full(len(grid), 3.0)]
    index: dict[tuple[int, int], int] = {}  # (level, grid vertex) -> point
    points = []
    for level in range(4):
        for v in (ring if level in (0, 3) else range(len(grid))):  # bottom and top: only their boundary
            index[level, v] = len(points)
            points.append([*grid[v], heights[level][v]])
    facets: list[tuple[Polygons, int]] = [([[index[0, v] for v in ring[::-1]]], 1),
                                          ([[index[3, v] for v in ring]], 2)]
    for level in (1, 2):
        facets += [([[index[level, v] for v in t]], 10 + level) for t in tris.tolist()]
    sides = [ring[s * (n - 1):s * (n - 1) + n] if s < 3 else ring[3 * (n - 1):] + [ring[0]] for s in range(4)]
    for side in sides:
        for level in range(3):
            wall = [index[level, v] for v in side] + [index[level + 1, v] for v in side[::-1]]
            facets.append(([wall], 3))
    centre = (n // 2) * n + n // 2
    regions = [(*grid[centre], (heights[k][centre] + heights[k + 1][centre]) / 2, float(k + 1))
               for k in range(3)]
    return np.array(points, dtype=np.float64), facets, regions


def cubes_sharing_an_edge() -> tuple[np.ndarray, Polygons]:
    """Cubes [0,1]^3 and [1,2]x[1,2]x[0,1]: they share the edge x = y = 1 (a non-manifold edge)."""
    a, b = box_points([0, 0, 0], [1, 1, 1]), box_points([1, 1, 0], [2, 2, 1])
    points = np.concatenate([a, b[[1, 2, 3, 5, 6, 7]]])
    of_b = {0: 3, 1: 8, 2: 9, 3: 10, 4: 7, 5: 11, 6: 12, 7: 13}  # b's corner 0 is a's 3, b's 4 is a's 7
    return points, BOX_QUADS + [[of_b[v] for v in q] for q in BOX_QUADS]


def hourglass() -> tuple[np.ndarray, np.ndarray]:
    """Two octahedra touching at one vertex (the origin): a non-manifold vertex."""
    up = np.array([[0, 0, 0], [1, 0, 1], [0, 1, 1], [-1, 0, 1], [0, -1, 1], [0, 0, 2]], dtype=np.float64)
    tri = [[0, 2, 1], [0, 3, 2], [0, 4, 3], [0, 1, 4], [5, 1, 2], [5, 2, 3], [5, 3, 4], [5, 4, 1]]
    down = up[1:] * [1, 1, -1]
    points = np.concatenate([up, down])
    lower = [[0 if v == 0 else v + 5 for v in t[::-1]] for t in tri]  # mirrored: reversed to stay outward
    return points, np.array(tri + lower, dtype=np.int64)


def window_box_with_fin() -> tuple[np.ndarray, list[tuple[Polygons, int]]]:
    """A 2 x 2 x 1 box whose top facet has a square hole filled by a separate window facet, and a dangling
    square fin standing inside on the bottom facet (its foot is a segment of the bottom facet)."""
    box = box_points([0, 0, 0], [2, 2, 1])
    window = np.array([[0.5, 0.5, 1], [1.5, 0.5, 1], [1.5, 1.5, 1], [0.5, 1.5, 1]])
    fin = np.array([[0.5, 1.0, 0], [1.5, 1.0, 0], [1.5, 1.0, 0.6], [0.5, 1.0, 0.6]])
    points = np.concatenate([box, window, fin])
    top = [[4, 5, 7, 6], [8, 9, 10, 11]]  # outer polygon and the window's, cut out by a facet hole point
    facets = [([q], 1) for k, q in enumerate(BOX_QUADS) if k not in (0, 1)]
    facets += [([[0, 2, 3, 1], [12, 13]], 1), (top, 2, [[1.0, 1.0, 1.0]]), ([[8, 9, 10, 11]], 3),
               ([[12, 13, 14, 15]], 4)]
    return points, facets


def schonhardt(twist_degrees: float = 30.0) -> tuple[np.ndarray, np.ndarray]:
    """Schonhardt's polyhedron: a triangular prism whose top is twisted by `twist_degrees`, each side quad
    split along the diagonal that makes it reflex; face 0 is written reversed (inconsistent orientation)."""
    angles = np.radians([90.0, 210.0, 330.0])
    bottom = np.column_stack([np.cos(angles), np.sin(angles), np.zeros(3)])
    t = angles + np.radians(twist_degrees)
    top = np.column_stack([np.cos(t), np.sin(t), np.full(3, 1.5)])
    points = np.concatenate([bottom, top])
    faces = [[0, 1, 2], [3, 4, 5]]  # face 0 reversed on purpose: outward would be [0, 2, 1]
    for i in range(3):
        j = (i + 1) % 3
        faces += [[i, j, 3 + j], [i, 3 + j, 3 + i]]  # diagonal (i, 3 + j): reflex for a positive twist
    return points, np.array(faces, dtype=np.int64)


# ---------------------------------------------------------------------------------------------------------


def build(out: Path) -> list[Path]:
    """Write every corpus file into `out`; return their paths in order."""
    out.mkdir(parents=True, exist_ok=True)
    written = []

    def off(name: str, points: np.ndarray, faces) -> None:
        write_off(out / name, points, faces)
        written.append(out / name)

    def poly(name: str, points: np.ndarray, facets, regions=()) -> None:
        write_poly(out / name, points, facets, list(regions))
        written.append(out / name)

    off("mc_torus.off", *marching_cubes(torus, 22, 1.6))
    off("mc_gyroid.off", *marching_cubes(gyroid_piece, 20, 1.8))
    off("mc_two_spheres.off", *marching_cubes(two_spheres, 22, 1.7))
    off("icosphere_jitter.off", *jittered_icosphere(2, 0.3, SEED))
    off("cad_knife_2deg.off", *knife(2.0))
    off("cad_ramp_5deg.off", *ramp_block(5.0))
    off("cad_spike_3deg.off", *spike_block(3.0))
    points, facets, regions = two_cubes_sharing_a_face()
    poly("two_cubes_face.poly", points, facets, regions)
    points, facets, regions = layered_box()
    poly("layered_box.poly", points, facets, regions)
    off("cubes_edge.off", *cubes_sharing_an_edge())
    off("hourglass.off", *hourglass())
    poly("window_box_fin.poly", *window_box_with_fin())
    off("schonhardt.off", *schonhardt())
    return written


def refine_table(paths: list[Path]) -> str:
    """Markdown table of the default refine_gabriel on each file: status (with the strategy when it is not the
    first pass's), points, Steiner points, work units, seconds."""
    from nonobtuse.mesh3d import load_plc, refine_gabriel

    rows = ["| file | input points | status | Steiner points | work units | seconds |",
            "| --- | --- | --- | --- | --- | --- |"]
    for path in paths:
        plc = load_plc(path)
        result = refine_gabriel(plc)
        stats = result.stats
        strategy = f" ({stats['strategy']})" if stats["strategy"] != "shells" else ""
        rows.append(f"| {path.name} | {len(plc.points)} | {result.status}{strategy} | "
                    f"{stats['steiner_points']:,} | {stats['work']:,} | {stats['seconds']:.1f} |")
        print(rows[-1], flush=True)
    return "\n".join(rows) + "\n"


def main(argv: list[str] | None = None) -> None:
    from nonobtuse.mesh3d import load_plc

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=OUT)
    ap.add_argument("--table", action="store_true",
                    help="refine every file of --out with the defaults instead of writing them")
    args = ap.parse_args(argv)
    if args.table:
        paths = sorted(p for p in args.out.glob("*") if p.suffix in (".off", ".poly"))
        results = Path(__file__).resolve().parent / "results"
        with atomic_text(results / "corpus3d_refine.md") as f:
            f.write(refine_table(paths))
        return
    for path in build(args.out):
        plc = load_plc(path)
        print(f"{path.name}: {len(plc.points)} points, {len(plc.triangles)} triangles, "
              f"{len(np.unique(plc.facet_ids))} facets, {len(plc.segments)} segments, {path.stat().st_size} "
              f"bytes; warnings: {list(plc.warnings)}")


if __name__ == "__main__":
    main()
