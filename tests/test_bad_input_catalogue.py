"""The bad-input catalogue: one line per kind of bad input file or bad option, for every reader and command.

Each case writes its files into an empty folder (the table holds their text), runs the ``nonobtuse`` command
there and asserts:

- the exit code (2 for bad input or options, unless the case says otherwise);
- the words of the message on stderr that name the problem and the place (file:line, index, option);
- no traceback and no warning on stderr;
- every input file is unchanged (SHA-256 before and after), and a refused run leaves no file behind (no
  output, no temporary file).

Most cases call :func:`nonobtuse.cli.main` in this process; those marked ``subprocess`` run ``python -m`` in a
child process, which also catches signals (a floating-point trap kills the process with exit -8) and anything
printed outside the CLI's own error path.

Cases marked ``defect`` are the defects issue 13 lists, written as they should behave; they are strict xfails,
so each one fails the suite the day its fix lands, and the mark must then go.

Adding a case is one line: ``K(id, command line, words, {file name: text})``. File names in the command line
are relative to the case's folder.
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import json
import os
import shlex
import subprocess
import sys
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

import pytest

import nonobtuse
from nonobtuse.cli import main
from nonobtuse.mesh3d import load_plc, tetrahedralize

DEFECT = "issue 13 defect, fix under way"


@dataclass(frozen=True)
class K:
    """One catalogue case: ``argv`` (a command line without ``nonobtuse``), the ``words`` stderr must contain,
    the ``files`` to create (name -> text or bytes), the expected exit ``code``, and whether it is a listed
    ``defect`` (strict xfail) or needs a ``subprocess``."""

    id: str
    argv: str
    words: tuple[str, ...]
    files: dict[str, str | bytes] = field(default_factory=dict)
    code: int = 2
    defect: bool = False
    subprocess: bool = False


# ---- file builders -----------------------------------------------------------------------------------------

SQUARE = [(0, 0), (4, 0), (4, 4), (0, 4)]
LOOP4 = [(0, 1), (1, 2), (2, 3), (3, 0)]
TET = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
TET_FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]  # outward


def poly(points=SQUARE, segments=LOOP4, holes=(), regions=None, head: str | None = None) -> str:
    """A Triangle .poly file, ids 1-based; ``head`` replaces the vertex header line."""
    out = [head or f"{len(points)} 2 0 0"]
    out += [f"{i} {x} {y}" for i, (x, y) in enumerate(points, 1)]
    out += [f"{len(segments)} 0"] + [f"{i} {a + 1} {b + 1}" for i, (a, b) in enumerate(segments, 1)]
    out += [f"{len(holes)}"] + [f"{i} {x} {y}" for i, (x, y) in enumerate(holes, 1)]
    if regions is not None:
        out += [f"{len(regions)}"] + [f"{i} {x} {y} {a}" for i, (x, y, a) in enumerate(regions, 1)]
    return "\n".join(out) + "\n"


def node(points=SQUARE, head: str | None = None) -> str:
    rows = [f"{i} {x} {y}" for i, (x, y) in enumerate(points, 1)]
    return "\n".join([head or f"{len(points)} 2 0 0", *rows])


def cgshop(points=SQUARE, boundary=(0, 1, 2, 3), constraints=(), **override) -> str:
    d = {"instance_uid": "t", "points_x": [p[0] for p in points], "points_y": [p[1] for p in points],
         "region_boundary": list(boundary), "additional_constraints": [list(c) for c in constraints]}
    return json.dumps({**d, **override})


def domain(**keys) -> str:
    return json.dumps({"points": [list(p) for p in SQUARE], "segments": [list(s) for s in LOOP4], **keys})


def mesh(**override) -> str:
    """The square with its centre: 4 counter-clockwise triangles, every boundary angle 90 degrees."""
    pts = [*map(list, SQUARE), [2, 2]]
    loop = [list(s) for s in LOOP4]
    d = {"points": pts, "triangles": [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]], "segments": loop,
         "input_points": pts, "input_segments": loop}
    return json.dumps({**d, **override})


def twice_winding_mesh() -> str:
    """Counter-clockwise triangles (0, k, k+1) around the centre over ring points at 72 k degrees, radius
    1 + 0.05 k (k = 0..9): every triangle is positive and every inner edge has two triangles, yet the mesh
    winds twice around the centre (triangles overlap)."""
    import math

    pts = [[0.0, 0.0]] + [[(1 + 0.05 * k) * math.cos(math.radians(72 * k)),
                           (1 + 0.05 * k) * math.sin(math.radians(72 * k))] for k in range(10)]
    tri = [[0, k, k + 1] for k in range(1, 10)] + [[0, 10, 1]]
    seg = [[k, k + 1] for k in range(1, 10)] + [[10, 1]]
    return json.dumps({"points": pts, "triangles": tri, "segments": seg, "input_points": pts,
                       "input_segments": seg})


def off(points=TET, faces=TET_FACES, head: str = "OFF") -> str:
    out = [head, f"{len(points)} {len(faces)} 0"] + [" ".join(map(str, p)) for p in points]
    return "\n".join(out + [" ".join(map(str, [len(f), *f])) for f in faces]) + "\n"


def scaled_tet(scale: str) -> str:
    """The corner tetrahedron with its unit coordinates written as ``1{scale}`` (e.g. ``1e-300``)."""
    return off([tuple(f"{c}{scale}" if c else "0" for c in p) for p in TET])


def uv_sphere(rings: int = 30, sectors: int = 40) -> str:
    """A UV sphere: the poles and rings - 1 circles of ``sectors`` points, outward triangles."""
    import math

    pts = [(0.0, 0.0, 1.0)]
    for i in range(1, rings):
        t = math.pi * i / rings
        phi = [2 * math.pi * j / sectors for j in range(sectors)]
        pts += [(math.sin(t) * math.cos(f), math.sin(t) * math.sin(f), math.cos(t)) for f in phi]
    pts.append((0.0, 0.0, -1.0))

    def at(i, j):
        return 1 + (i - 1) * sectors + j % sectors

    faces = [(0, at(1, j), at(1, j + 1)) for j in range(sectors)]
    for i in range(1, rings - 1):
        for j in range(sectors):
            faces += [(at(i, j), at(i + 1, j), at(i + 1, j + 1)), (at(i, j), at(i + 1, j + 1), at(i, j + 1))]
    faces += [(len(pts) - 1, at(rings - 1, j + 1), at(rings - 1, j)) for j in range(sectors)]
    return off([tuple(map(repr, p)) for p in pts], faces)


def obj(points=TET, faces=TET_FACES, base: int = 1) -> str:
    out = ["v " + " ".join(map(str, p)) for p in points]
    return "\n".join(out + ["f " + " ".join(str(v + base) for v in f) for f in faces]) + "\n"


def ply(points=TET, faces=TET_FACES) -> str:
    head = ["ply", "format ascii 1.0", f"element vertex {len(points)}",
            *(f"property float {c}" for c in "xyz"), f"element face {len(faces)}",
            "property list uchar int vertex_indices",
            "end_header"]
    rows = [" ".join(map(str, p)) for p in points] + [" ".join(map(str, [len(f), *f])) for f in faces]
    return "\n".join(head + rows) + "\n"


def stl(points=TET, faces=TET_FACES, vertices_per_facet: int = 3) -> str:
    out = ["solid t"]
    for f in faces:
        out += ["facet normal 0 0 0", "outer loop"]
        out += ["vertex " + " ".join(map(str, points[v])) for v in f[:vertices_per_facet]]
        out += ["endloop", "endfacet"]
    return "\n".join(out + ["endsolid t"]) + "\n"


def smesh(points=TET, faces=TET_FACES, head: str | None = None) -> str:
    out = [head or f"{len(points)} 3 0 0"] + [f"{i} {' '.join(map(str, p))}" for i, p in enumerate(points, 1)]
    out += [f"{len(faces)} 0"] + [" ".join(map(str, [len(f), *(v + 1 for v in f)])) for f in faces]
    return "\n".join(out + ["0", "0"]) + "\n"


BOWTIE = [(0, 0), (4, 4), (4, 0), (0, 4)]
L_SHAPE = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)]
L_OPEN = [(i, i + 1) for i in range(5)]  # the closing segment (5, 0) is missing
SQUARE_AND_CENTRE = [*SQUARE, (2, 2)]
OUT = "out.json"

# ---- the catalogue -----------------------------------------------------------------------------------------

CASES = [
    # files that cannot be read at all, whatever the reader
    K("missing-domain", "check nope.poly", ("nope.poly", "cannot read")),
    K("missing-3d", "check3d nope.off", ("nope.off", "no such file")),
    K("empty-poly", "check a.poly", ("a.poly", "empty"), {"a.poly": ""}),
    K("blank-node", "check a.node", ("a.node", "empty"), {"a.node": "\n  \n\t\n"}),
    K("comments-only-poly", "check a.poly", ("a.poly", "ends early", "vertex count"), {"a.poly": "# x\n"}),
    K("binary-poly", "check a.poly", ("a.poly", "cannot read"), {"a.poly": b"\xff\xfe\x00\x81garbage"}),
    K("unknown-domain-suffix", "check a.txt", ("a.txt", "unknown domain format"), {"a.txt": "1 2 3\n"}),
    K("unknown-3d-suffix", "check3d a.xyz", ("a.xyz", "unknown 3D format"), {"a.xyz": "1 2 3\n"}),
    K("empty-off", "check3d a.off", ("a.off", "empty"), {"a.off": ""}),
    K("empty-stl", "check3d a.stl", ("a.stl", "empty"), {"a.stl": ""}),
    K("empty-json", "check a.json", ("a.json", "empty"), {"a.json": ""}),
    # Triangle .poly
    K("poly-count-not-integer", "check a.poly", ("a.poly:1", "vertex count must be an integer"),
      {"a.poly": poly(head="four 2 0 0")}),
    K("poly-count-negative", "check a.poly", ("a.poly:1", "must not be negative"),
      {"a.poly": poly(head="-4 2 0 0")}),
    K("poly-dimension-3", "check a.poly", ("a.poly:1", "dimension must be 2"),
      {"a.poly": poly(head="4 3 0 0")}),
    K("poly-markers-2", "check a.poly", ("a.poly:1", "markers must be 0 or 1"),
      {"a.poly": poly(head="4 2 0 2")}),
    K("poly-first-id-5", "check a.poly", ("a.poly:2", "first vertex id must be 0 or 1"),
      {"a.poly": poly().replace("\n1 0 0\n", "\n5 0 0\n")}),
    K("poly-ids-not-consecutive", "check a.poly", ("a.poly:4", "consecutive", "expected 3, found 7"),
      {"a.poly": poly().replace("\n3 4 4\n", "\n7 4 4\n")}),
    K("poly-x-not-number", "check a.poly", ("a.poly:3", "x must be a number", "'abc'"),
      {"a.poly": poly().replace("\n2 4 0\n", "\n2 abc 0\n")}),
    K("poly-underscore-number", "check a.poly", ("a.poly:3", "must be a number", "'4_0'"),
      {"a.poly": poly().replace("\n2 4 0\n", "\n2 4_0 0\n")}),
    K("poly-nan", "check a.poly", ("point 1", "not finite", "line 3"),
      {"a.poly": poly().replace("\n2 4 0\n", "\n2 nan 0\n")}),
    K("poly-inf", "check a.poly", ("point 2", "not finite", "line 4"),
      {"a.poly": poly().replace("\n3 4 4\n", "\n3 4 -inf\n")}),
    K("poly-vertex-line-short", "check a.poly", ("a.poly:3", "expected id, x, y"),
      {"a.poly": poly().replace("\n2 4 0\n", "\n2 4\n")}),
    K("poly-truncated-vertices", "check a.poly", ("a.poly:", "ends early", "vertex 4 of 4"),
      {"a.poly": "4 2 0 0\n1 0 0\n2 4 0\n3 4 4\n"}),
    K("poly-endpoint-missing", "check a.poly", ("a.poly:10", "endpoint 9 does not exist", "1 to 4"),
      {"a.poly": poly(segments=[(0, 1), (1, 2), (2, 3), (3, 8)])}),
    K("poly-endpoint-not-integer", "check a.poly", ("a.poly:7", "endpoint must be an integer", "'1.5'"),
      {"a.poly": poly().replace("\n1 1 2\n", "\n1 1.5 2\n")}),
    K("poly-no-hole-section", "check a.poly", ("a.poly:", "ends early", "hole count"),
      {"a.poly": poly().rsplit("0\n", 1)[0]}),
    K("poly-trailing-content", "check a.poly", ("a.poly:13", "unexpected content"),
      {"a.poly": poly(regions=[]) + "9 9\n"}),
    K("poly-hole-not-number", "check a.poly", ("a.poly:12", "y must be a number"),
      {"a.poly": poly().rsplit("0\n", 1)[0] + "1\n1 2 two\n"}),
    K("poly-region-short", "check a.poly", ("a.poly:13", "expected id, x, y, attribute"),
      {"a.poly": poly(regions=[(1, 1, 7)]).replace("1 1 1 7", "1 1 1")}),
    K("poly-duplicate-points", "check a.poly", ("duplicate points", "point 1", "point 4", "line 6"),
      {"a.poly": poly(points=[*SQUARE, (4, 0)])}),
    K("poly-zero-length-segment", "check a.poly", ("segment 4", "zero length", "line 11"),
      {"a.poly": poly(segments=[*LOOP4, (2, 2)])}),
    K("poly-crossing-segments", "check a.poly", ("segment 0", "segment 2", "cross away from their endpoints"),
      {"a.poly": poly(points=BOWTIE)}, subprocess=True),
    K("poly-open-boundary", "check a.poly", ("not closed", "dangling ends", "convex_hull"),
      {"a.poly": poly(points=L_SHAPE, segments=L_OPEN + [(1, 3)])}, subprocess=True),
    K("poly-hole-outside", "check a.poly", ("hole seed 0 at (9.0, 9.0)", "line 12", "not inside"),
      {"a.poly": poly(holes=[(9, 9)])}),
    K("poly-hole-on-segment", "check a.poly", ("hole seed 0 at (2.0, 0.0)", "exactly on a point or a"),
      {"a.poly": poly(holes=[(2, 0)])}),
    K("poly-region-outside", "check a.poly", ("region seed 0", "attribute 7.0", "not inside the domain"),
      {"a.poly": poly(regions=[(5, 5, 7)])}),
    K("poly-hole-fills-domain", "check a.poly", ("no domain triangle", "not closed"),
      {"a.poly": poly(holes=[(1, 1)])}),
    K("poly-zero-vertices-no-node", "check a.poly", ("a.poly", "vertices come from", "a.node", "cannot read"),
      {"a.poly": poly(points=[], segments=[])}),
    K("poly-huge-vertex-count", "check a.poly", ("a.poly:1", "1000000000000"),
      {"a.poly": poly(head="1000000000000 2 0 0")}),
    # Triangle .node
    K("node-no-vertices", "check a.node", ("a.node", "lists no vertices"), {"a.node": "0 2 0 0\n"}),
    K("node-collinear", "check a.node", ("a.node", "no triangle", "collinear"),
      {"a.node": node([(0, 0), (1, 1), (2, 2)])}),
    K("node-single-point", "check a.node", ("a.node", "no triangle"), {"a.node": node([(1, 1)])}),
    K("node-attribute-not-number", "check a.node", ("a.node:2", "vertex attribute 1 must be a number"),
      {"a.node": node(head="4 2 1 0").replace("1 0 0", "1 0 0 red")}),
    K("node-marker-not-integer", "check a.node", ("a.node:2", "boundary marker must be an integer"),
      {"a.node": node(head="4 2 0 1").replace("1 0 0", "1 0 0 0.5")}),
    K("node-duplicate", "check a.node", ("duplicate points", "line 2", "line 6"),
      {"a.node": node([*SQUARE, (0, 0)])}),
    # CG:SHOP 2025 instance .json
    K("json-syntax", "check a.json", ("a.json:2", "not valid JSON"), {"a.json": '{"points_x": [0, 1],\n ]'}),
    K("json-top-level-list", "check a.json", ("a.json", "expected a JSON object", "list"),
      {"a.json": "[1, 2]"}),
    K("cgshop-no-boundary", "check a.json", ("a.json", "needs the list 'region_boundary'"),
      {"a.json": cgshop(region_boundary=None)}),
    K("cgshop-length-mismatch", "check a.json", ("points_x has 4 values but points_y has 3",),
      {"a.json": cgshop(points_y=[0, 0, 4])}),
    K("cgshop-string-coordinate", "check a.json", ("points_x[1] must be a number", "'4'"),
      {"a.json": cgshop(points_x=[0, "4", 4, 0])}),
    K("cgshop-boolean-coordinate", "check a.json", ("points_y[2] must be a number", "True"),
      {"a.json": cgshop(points_y=[0, 0, True, 4])}),
    K("cgshop-short-boundary", "check a.json", ("region_boundary must list at least 3 points, found 2",),
      {"a.json": cgshop(boundary=(0, 1))}),
    K("cgshop-boundary-index-missing", "check a.json", ("segment 1", "refers to a point that does not exist"),
      {"a.json": cgshop(boundary=(0, 1, 7, 3))}),
    K("cgshop-boundary-float-index", "check a.json", ("region_boundary[1] must be an integer", "1.5"),
      {"a.json": cgshop(boundary=(0, 1.5, 2, 3))}),
    K("cgshop-ragged-constraint", "check a.json", ("additional_constraints[0] must be a list of 2 integers",),
      {"a.json": cgshop(points=SQUARE_AND_CENTRE, constraints=[(0, 4, 2)])}),
    K("cgshop-integer-not-a-float64", "check a.json", ("points_x[2]", "not exactly representable"),
      {"a.json": cgshop(points_x=[0, 4, 2**53 + 1, 0])}),
    K("cgshop-crossing-boundary", "check a.json", ("cross away from their endpoints",),
      {"a.json": cgshop(BOWTIE)}),
    K("cgshop-overflowing-literal", "check a.json", ("point 2", "not finite"),
      {"a.json": cgshop().replace('"points_x": [0, 4, 4, 0]', '"points_x": [0, 4, 1e400, 0]')}),
    K("cgshop-nan-literal", "check a.json", ("point 3", "not finite"),
      {"a.json": cgshop().replace('"points_y": [0, 0, 4, 4]', '"points_y": [0, 0, 4, NaN]')},
      subprocess=True),
    K("json-nested-deep", "check a.json", ("a.json",),
      {"a.json": '{"points": ' + "[" * 100_000 + "]" * 100_000 + "}"}),
    # nonobtuse domain .json
    K("domain-unknown-key", "check a.json", ("a.json", "unknown key(s) ['colour']"),
      {"a.json": domain(colour=1)}),
    K("domain-hull-not-boolean", "check a.json", ("'convex_hull' must be true or false", "'yes'"),
      {"a.json": domain(convex_hull="yes")}),
    K("domain-no-points", "check a.json", ("a.json", "needs 'points'"), {"a.json": '{"segments": []}'}),
    K("domain-points-not-list", "check a.json", ("points must be a list", "dict"),
      {"a.json": domain(points={})}),
    K("domain-point-3d", "check a.json", ("points[1] must be a list of 2 numbers", "[4, 0, 1]"),
      {"a.json": domain(points=[[0, 0], [4, 0, 1], [4, 4], [0, 4]])}),
    K("domain-empty-points", "check a.json", ("a.json", "no points"),
      {"a.json": domain(points=[], segments=[])}),
    K("domain-negative-index", "check a.json", ("segment 3", "refers to a point that does not exist"),
      {"a.json": domain(segments=[[0, 1], [1, 2], [2, 3], [3, -1]])}),
    K("domain-hole-string", "check a.json", ("holes[0] must be a number", "'1'"),
      {"a.json": domain(holes=[["1", 1]])}),
    K("domain-region-short", "check a.json", ("regions[0] must be a list of 3 numbers",),
      {"a.json": domain(regions=[[1, 1]])}),
    K("domain-is-a-mesh", "refine a.json -o b.json", ("a.json", "this is a mesh", "not a domain"),
      {"a.json": mesh(input_segments=[[0, 1]])}, code=2),
    K("domain-l-open", "check a.json", ("a.json", "not closed"),
      {"a.json": json.dumps({"points": L_SHAPE, "segments": L_OPEN})}),
    # nonobtuse mesh .json (check reads a file with 'triangles' as a mesh)
    K("mesh-missing-key", "check a.json", ("mesh keys missing ['input_segments']",),
      {"a.json": json.dumps({k: v for k, v in json.loads(mesh()).items() if k != "input_segments"})}),
    K("mesh-triangle-index", "check a.json", ("triangles[1] = [1, 2, 9]", "refers to a missing point"),
      {"a.json": mesh(triangles=[[0, 1, 4], [1, 2, 9]])}),
    K("mesh-input-points-differ", "check a.json", ("the first 5 points must be the input points",),
      {"a.json": mesh(input_points=[[0, 0], [4, 0], [4, 4], [0, 4], [2, 3]])}),
    K("mesh-regions-count", "check a.json", ("2 regions for 4 triangles",), {"a.json": mesh(regions=[1, 2])}),
    K("mesh-stats-not-object", "check a.json", ("'stats' must be an object",), {"a.json": mesh(stats=[1])}),
    K("mesh-twice-winding", "check a.json", ("a.json",), {"a.json": twice_winding_mesh()}),
    K("mesh-overflowing-literal", "check a.json", ("a.json", "not finite"),
      {"a.json": mesh().replace("[2, 2]", "[2, 1e400]")}, subprocess=True),
    # .vtu and .msh meshes (meshio)
    K("vtu-garbage", "check a.vtu", ("a.vtu", "cannot read the mesh"), {"a.vtu": "<VTKFile><nonsense"}),
    K("vtu-empty", "check a.vtu", ("a.vtu", "empty"), {"a.vtu": ""}),
    K("msh-garbage", "check a.msh", ("a.msh", "cannot read the mesh"), {"a.msh": "$MeshFormat\n9 9 9\n"}),
    K("msh-lines-only", "check a.msh", ("a.msh", "no triangle cells"),
      {"a.msh": "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n2 1 0 0\n$EndNodes\n"
                "$Elements\n1\n1 1 2 0 0 1 2\n$EndElements\n"}),
    K("msh-not-planar", "check a.msh", ("a.msh", "not planar"),
      {"a.msh": "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 5\n$EndNodes\n"
                "$Elements\n1\n1 2 2 0 0 1 2 3\n$EndElements\n"}),
    # output paths
    K("out-unknown-suffix", "refine a.poly -o out.txt", ("out.txt", "unknown mesh format"),
      {"a.poly": poly()}),
    K("out-missing-folder", "refine a.poly -o nodir/out.json", ("nodir",), {"a.poly": poly()}),
    K("out-is-a-directory", "refine a.poly -o d.json", ("d.json",), {"a.poly": poly(), "d.json/keep": ""}),
    K("out-is-the-input", "refine a.json -o a.json", ("a.json",), {"a.json": domain()}),
    K("out-sibling-overwrites-node", "refine a.node -o a.poly", ("a.node",), {"a.node": node()}),
    K("out-sibling-overwrites-poly", "refine A.poly -o A.ele", ("A.poly",), {"A.poly": poly()}),
    K("triangulate-out-unknown", "triangulate a.poly -o out.off", ("out.off", "unknown mesh format"),
      {"a.poly": poly()}),
    K("refine3d-out-unknown", "refine3d a.off -o out.txt", ("out.txt",), {"a.off": off()}),
    # options
    K("no-command", "", ("required",)),
    K("unknown-command", "mesh a.poly", ("invalid choice", "'mesh'")),
    K("unknown-option", "check a.poly --fast", ("unrecognized arguments", "--fast"), {"a.poly": poly()},
      subprocess=True),
    K("refine-no-output", "refine a.poly", ("the following arguments are required", "-o"),
      {"a.poly": poly()}),
    K("strategy-unknown", "refine a.poly -o o.json --strategy best", ("--strategy", "invalid choice: 'best'"),
      {"a.poly": poly()}),
    K("max-steiner-negative", "refine a.poly -o out.json --max-steiner -1",
      ("--max-steiner", "non-negative integer", "-1"), {"a.poly": poly()}, subprocess=True),
    K("max-steiner-not-integer", "refine a.poly -o o.json --max-steiner 2.5",
      ("--max-steiner", "non-negative integer", "'2.5'"), {"a.poly": poly()}),
    K("max-steiner-huge", "refine a.poly -o out.json --max-steiner 99999999999999999999",
      ("max", "99999999999999999999"), {"a.poly": poly()}),
    K("threads-zero", "refine a.poly -o out.json --threads 0", ("threads must be a positive integer", "0"),
      {"a.poly": poly()}),
    K("threads-negative", "refine a.poly -o out.json --threads -2", ("threads must be a positive integer",),
      {"a.poly": poly()}),
    K("threads-word", "refine a.poly -o out.json --threads two", ("--threads", "invalid int", "'two'"),
      {"a.poly": poly()}),
    K("backend-unknown", "check3d a.off --backend gmsh", ("--backend", "invalid choice", "'gmsh'"),
      {"a.off": off()}),
    K("split-unknown", "refine3d a.off -o out.json --split thirds", ("--split", "invalid choice"),
      {"a.off": off()}),
    K("min-length-word", "refine3d a.off -o out.json --min-length tiny",
      ("--min-length", "expected a number", "'tiny'"), {"a.off": off()}),
    K("refine3d-max-steiner-negative", "refine3d a.off -o out.json --max-steiner -5",
      ("--max-steiner", "non-negative integer", "-5"), {"a.off": off()}),
    K("refine3d-min-length-nan", "refine3d a.off -o out.json --min-length nan",
      ("--min-length", "finite number", "nan"), {"a.off": off()}),
    K("refine3d-time-limit-negative", "refine3d a.off -o out.json --time-limit -1",
      ("--time-limit", "finite number >= 0", "-1"), {"a.off": off()}),
    K("refine3d-time-limit-nan", "refine3d a.off -o out.json --time-limit nan",
      ("--time-limit", "finite number", "nan"), {"a.off": off()}),
    # OFF
    K("off-bad-header", "check3d a.off", ("a.off:1", "not an OFF file", "'PLY'"), {"a.off": off(head="PLY")}),
    K("off-counts-not-integer", "check3d a.off", ("a.off:2", "OFF counts must be an integer"),
      {"a.off": off().replace("4 4 0", "4 four 0")}),
    K("off-truncated", "check3d a.off", ("a.off:", "ends early", "face 3"),
      {"a.off": off().rsplit("3 ", 1)[0]}),
    K("off-coordinate-word", "check3d a.off", ("a.off:4", "vertex 1 must be a number", "'one'"),
      {"a.off": off([(0, 0, 0), ("one", 0, 0), *TET[2:]])}),
    K("off-face-index-missing", "check3d a.off", ("facet 3", "a.off:10", "refers to vertex", "7"),
      {"a.off": off(faces=[*TET_FACES[:3], (1, 2, 7)])}),
    K("off-nan-vertex", "check3d a.off", ("vertex 2", "NaN or infinite"),
      {"a.off": off([*TET[:2], (0, "nan", 0), TET[3]])}, subprocess=True),
    K("off-repeated-vertex-face", "check3d a.off", ("degenerate face", "repeated"),
      {"a.off": off(faces=[*TET_FACES[:3], (1, 2, 2)])}),
    K("off-collinear-face", "check3d a.off", ("degenerate face", "collinear"),
      {"a.off": off([*TET, (2, 0, 0)], [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3), (0, 1, 4)])}),
    K("off-duplicate-face", "check3d a.off", ("duplicate face",),
      {"a.off": off(faces=[*TET_FACES, (1, 2, 3)])}),
    K("off-open-surface", "check3d a.off", ("a.off", "edge"), {"a.off": off(faces=TET_FACES[:3])}),
    # OBJ
    K("obj-coordinate-word", "check3d a.obj", ("a.obj:2", "must be a number", "'zero'"),
      {"a.obj": obj().replace("v 1 0 0", "v 1 zero 0")}),
    K("obj-face-index-missing", "check3d a.obj", ("a.obj:8", "refers to vertex"),
      {"a.obj": obj(faces=[*TET_FACES[:3], (1, 2, 8)])}),
    K("obj-face-word", "check3d a.obj", ("a.obj:5", "must be an integer"),
      {"a.obj": obj().replace("f 1 3 2", "f 1 x 2")}),
    K("obj-index-zero", "check3d a.obj", ("a.obj:5", "index 0"),
      {"a.obj": obj(faces=TET_FACES, base=0)}),
    K("obj-no-faces", "check3d a.obj", ("empty input",), {"a.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\n"}),
    # PLY
    K("ply-not-ply", "check3d a.ply", ("a.ply", "not a PLY file"), {"a.ply": off()}),
    K("ply-bad-header", "check3d a.ply", ("a.ply", "malformed PLY"),
      {"a.ply": ply().replace("property float y\n", "property flot y\n")}),
    K("ply-truncated", "check3d a.ply", ("a.ply", "malformed PLY"), {"a.ply": ply().rsplit("\n3 ", 1)[0]}),
    # STL
    K("stl-not-stl", "check3d a.stl", ("a.stl", "not an STL file"), {"a.stl": "hello world\n"}),
    K("stl-vertex-word", "check3d a.stl", ("a.stl", "malformed ASCII STL vertex"),
      {"a.stl": stl().replace("vertex 1 0 0", "vertex 1 O 0", 1)}),
    K("stl-two-vertices", "check3d a.stl", ("a.stl", "not a multiple of 3"),
      {"a.stl": stl(vertices_per_facet=2)}),
    K("stl-binary-wrong-size", "check3d a.stl", ("a.stl", "not an STL file"),
      {"a.stl": b"\0" * 80 + (4).to_bytes(4, "little") + b"\0" * 100}),
    # TetGen .poly / .smesh
    K("smesh-dimension-2", "check3d a.smesh", ("a.smesh:1", "dimension 2", "only 3D"),
      {"a.smesh": smesh(head="4 2 0 0")}),
    K("poly2d-as-3d", "check3d a.poly", ("a.poly:1", "dimension 2"), {"a.poly": poly()}),
    K("smesh-node-short", "check3d a.smesh", ("a.smesh:3", "an index and 3 coordinates"),
      {"a.smesh": smesh().replace("\n2 1 0 0\n", "\n2 1 0\n")}),
    K("smesh-facet-index-missing", "check3d a.smesh", ("facet 3", "a.smesh:", "refers to vertex"),
      {"a.smesh": smesh(faces=[*TET_FACES[:3], (1, 2, 8)])}),
    K("smesh-truncated", "check3d a.smesh", ("a.smesh:", "ends early", "facet 3"),
      {"a.smesh": smesh().split("\n3 2 3 4")[0] + "\n"}),
    K("smesh-no-nodes-no-node-file", "check3d a.smesh", ("a.node", "cannot read"),
      {"a.smesh": smesh(head="0 3 0 0").replace("\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1", "")}),
    K("tetgen-poly-not-planar", "check3d a.poly", ("facet 0", "not planar"),
      {"a.poly": "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 1\n5 0 0 2\n1 0\n1\n4 1 2 3 4\n0\n0\n"}),
]


def _checksums(folder: Path) -> dict[str, str]:
    return {str(p.relative_to(folder)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(folder.rglob("*")) if p.is_file()}


def _write(folder: Path, files: dict[str, str | bytes]) -> None:
    for name, content in files.items():
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content)


def _run_in_process(argv: list[str], capsys) -> tuple[int, str]:
    try:
        code = main(argv)
    except SystemExit as e:  # argparse refuses options with SystemExit(2)
        code = e.code if isinstance(e.code, int) else 2
    return code, capsys.readouterr().err


def _run_subprocess(argv: list[str], cwd: Path) -> tuple[int, str]:
    code = "import sys; from nonobtuse.cli import main; sys.exit(main())"
    run = subprocess.run([sys.executable, "-c", code, *argv], cwd=cwd, capture_output=True, text=True,
                         timeout=120, env={**_env(), "PYTHONWARNINGS": "default"})
    return run.returncode, run.stderr


def _env() -> dict[str, str]:

    src = str(Path(nonobtuse.__file__).resolve().parents[1])
    return {**os.environ, "PYTHONPATH": os.pathsep.join([src, os.environ.get("PYTHONPATH", "")])}


def _params():
    for case in CASES:
        marks = [pytest.mark.xfail(strict=True, reason=DEFECT)] if case.defect else []
        yield pytest.param(case, id=case.id, marks=marks)


def test_the_catalogue_is_large_and_its_ids_unique():
    ids = [c.id for c in CASES]
    assert len(set(ids)) == len(ids) >= 80


@pytest.mark.parametrize("case", list(_params()))
def test_bad_input(case: K, tmp_path, monkeypatch, capsys):
    _write(tmp_path, case.files)
    before = _checksums(tmp_path)
    argv = shlex.split(case.argv)
    monkeypatch.chdir(tmp_path)
    code, err = _run_subprocess(argv, tmp_path) if case.subprocess else _run_in_process(argv, capsys)
    assert "Traceback" not in err and "Warning" not in err, err
    assert code == case.code, f"exit {code}, expected {case.code}; stderr: {err[-500:]}"
    missing = [w for w in case.words if w not in err]
    assert not missing, f"stderr lacks {missing}: {err[-500:]}"
    after = _checksums(tmp_path)
    assert {k: after.get(k) for k in before} == before, "an input file changed"
    if case.code == 2:
        assert set(after) == set(before), f"a refused run wrote {sorted(set(after) - set(before))}"


# ---- defects whose right answer is computed from a run on a clean input ------------------------------------


def _subprocess_json(argv: list[str], cwd: Path) -> tuple[int, dict | None, str]:
    code = "import sys; from nonobtuse.cli import main; sys.exit(main())"
    run = subprocess.run([sys.executable, "-c", code, *argv, "--json"], cwd=cwd, capture_output=True,
                         text=True, timeout=120, env={**_env(), "PYTHONWARNINGS": "default"})
    try:
        out = json.loads(run.stdout, parse_constant=lambda c: pytest.fail(f"{c} in the JSON output"))
    except json.JSONDecodeError:
        out = None
    return run.returncode, out, run.stderr


SCALES = [pytest.param(s, id=f"1{s}") for s in ("e-300", "e-150", "e-100", "e-20", "e20", "e100", "e150",
                                                 "e160", "e300")]


@pytest.fixture(scope="module")
def unit_tet_refined(tmp_path_factory) -> tuple[int, int]:
    """(exit code, Steiner points) of refine3d on the unit corner tetrahedron."""
    folder = tmp_path_factory.mktemp("unit")
    (folder / "unit.off").write_text(off())
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        code = main(["refine3d", str(folder / "unit.off"), "-o", str(folder / "unit.json"), "--json"])
    return code, json.loads(out.getvalue())["steiner_points"]


@pytest.mark.parametrize("scale", SCALES)
def test_refine3d_is_scale_free(scale, tmp_path, unit_tet_refined):
    # Exact predicates do not depend on the scale: the corner tetrahedron scaled by 1e-300 .. 1e300 (every
    # coordinate 0 or the scale, exactly as written) refines like the unit one: same exit code and Steiner
    # count, no signal (a floating-point trap is exit -8), no warning.
    (tmp_path / "scaled.off").write_text(scaled_tet(scale))
    code, got, err = _subprocess_json(["refine3d", "scaled.off", "-o", "scaled.json"], tmp_path)
    assert (code, got and got["steiner_points"]) == unit_tet_refined, err[-300:]
    assert "Traceback" not in err and "Warning" not in err, err


def test_a_utf8_bom_does_not_lose_a_vertex(tmp_path, capsys):
    # An OBJ file starting with a byte-order mark is read as the same file without it (or refused naming
    # the mark), never as a surface missing its first vertex.
    (tmp_path / "plain.obj").write_text(obj())
    (tmp_path / "bom.obj").write_text("\ufeff" + obj(), encoding="utf-8")
    want = main(["check3d", str(tmp_path / "plain.obj"), "--json"]), json.loads(capsys.readouterr().out)
    code = main(["check3d", str(tmp_path / "bom.obj"), "--json"])
    out, err = capsys.readouterr()
    if code == 2:
        assert "BOM" in err or "byte-order mark" in err, err
    else:
        got = json.loads(out)
        assert (code, got["points"], got["tets"]) == (want[0], want[1]["points"], want[1]["tets"])


def test_check3d_reports_finite_volumes_on_a_uv_sphere(tmp_path):
    # A UV sphere 30 x 40 is a valid closed surface whose tetrahedralization has tets of positive exact volume
    # that are flat in floating point (cocircular ring points): their circumcenters are computed exactly. The
    # control volumes then add up to the volume of the tetrahedralization, summed here exactly in rationals,
    # within rounding; the JSON output is strict JSON (no NaN) and nothing is printed as a warning.
    (tmp_path / "uv.off").write_text(uv_sphere())
    code, out, err = _subprocess_json(["check3d", "uv.off"], tmp_path)
    assert "Warning" not in err, err[-500:]
    assert code in (0, 1) and out is not None
    assert out["control_volumes"]["flat_in_floating_point"] > 0
    mesh = tetrahedralize(load_plc(str(tmp_path / "uv.off")), out["backend"])
    assert len(mesh.tets) == out["tets"]
    exact = sum(_exact_volume(mesh.points[t]) for t in mesh.tets)
    assert 4.0 < exact < 4 * Fraction(31415927, 10**7) / 3
    assert out["control_volumes"]["total_volume"] == pytest.approx(float(exact), rel=1e-13)


def _exact_volume(corners) -> Fraction:
    a, b, c, d = ([Fraction(float(x)) for x in q] for q in corners)
    u, v, w = ([q[i] - a[i] for i in range(3)] for q in (b, c, d))
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2])
            + u[2] * (v[0] * w[1] - v[1] * w[0])) / 6


def test_a_flipped_face_is_reoriented_not_refused(tmp_path, capsys):
    # Orientation is never refused (the plc3d work): a closed surface with one face reversed is checked as
    # the consistently oriented one (same exit code and report), with a warning naming the face it turned.
    (tmp_path / "good.off").write_text(off())
    (tmp_path / "flipped.off").write_text(off(faces=[*TET_FACES[:3], (3, 2, 1)]))
    want = main(["check3d", str(tmp_path / "good.off"), "--json"]), json.loads(capsys.readouterr().out)
    code = main(["check3d", str(tmp_path / "flipped.off"), "--json"])
    out, err = capsys.readouterr()
    got = json.loads(out)
    assert "Traceback" not in err and "Warning" not in err, err
    assert code == want[0]
    assert {k: v for k, v in got.items() if k not in ("input", "warnings")} == \
        {k: v for k, v in want[1].items() if k not in ("input", "warnings")}
    assert want[1]["warnings"] == []
    assert len(got["warnings"]) == 1 and "orientation" in got["warnings"][0]
    assert "face 3" in got["warnings"][0] and "reoriented" in got["warnings"][0]


def test_a_fractional_region_survives_a_msh_output(tmp_path, capsys):
    # No longer bad input (the markers work): .msh physical tags are integers, so a region attribute 1.5 gets
    # tag 1 and the map NAME.msh.regions.json beside the mesh; reading the .msh back gives 1.5 again.
    from nonobtuse.io.meshio_formats import read_meshio

    (tmp_path / "a.poly").write_text(poly(regions=[(1, 1, 1.5)]))
    out = tmp_path / "out.msh"
    assert main(["refine", str(tmp_path / "a.poly"), "-o", str(out)]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.poly", "out.msh", "out.msh.regions.json"]
    assert json.loads((tmp_path / "out.msh.regions.json").read_text()) == {"tag_to_region": {"1": 1.5}}
    m = read_meshio(out)
    assert m.regions is not None and len(m.regions) == len(m.triangles) > 0
    assert set(m.regions.tolist()) == {1.5}


def test_a_point_outside_the_domain_is_refused_or_dropped(tmp_path, capsys):
    # (9, 9) lies outside the closed square: refine either refuses it (exit 2, naming point 4) or leaves it
    # out of the mesh; it never stays in the output as a point no triangle uses.
    (tmp_path / "a.poly").write_text(poly(points=[*SQUARE, (9, 9)]))
    out = tmp_path / "out.json"
    code = main(["refine", str(tmp_path / "a.poly"), "-o", str(out)])
    if code == 2:
        assert "point 4" in capsys.readouterr().err
    else:
        m = json.loads(out.read_text())
        used = {v for t in m["triangles"] for v in t}
        assert used == set(range(len(m["points"])))


def test_refine3d_never_reports_unchecked_facets_as_zero(tmp_path, capsys):
    # With --time-limit 0 the certificate checks nothing (unchecked_faces > 0), and the corner tet has an
    # encroached facet (the origin is inside the diametral sphere of (1,0,0), (0,1,0), (0,0,1)): the output
    # must not say encroached_facets 0.
    (tmp_path / "tet.off").write_text(off())
    code = main(["refine3d", str(tmp_path / "tet.off"), "-o", str(tmp_path / "o.json"), "--time-limit", "0",
                 "--json"])
    stats = json.loads(capsys.readouterr().out)
    assert code == 3 and stats["unchecked_faces"] > 0
    assert stats["encroached_facets"] != 0


def test_a_closed_stdout_is_not_a_traceback(tmp_path):
    # `nonobtuse check ... | head`: the reader has gone before the report is written. The read end is closed
    # before the child starts writing, so its write fails with EPIPE every time; that ends the run quietly.
    (tmp_path / "a.json").write_text(cgshop([(0, 0), (4, 0), (2, 1)], (0, 1, 2)))
    code = "import sys; from nonobtuse.cli import main; sys.exit(main())"
    child = subprocess.Popen([sys.executable, "-c", code, "check", "a.json", "--json"], cwd=tmp_path,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=_env())
    child.stdout.close()
    err = child.stderr.read().decode()
    child.wait(timeout=120)
    child.stderr.close()
    assert "Traceback" not in err and "BrokenPipeError" not in err, err[-500:]


def test_outputs_follow_the_umask(tmp_path):
    # A file written by refine gets the permissions any new file gets (0666 minus the umask), not 0600.
    (tmp_path / "a.poly").write_text(poly())
    old = os.umask(0o022)
    try:
        assert main(["refine", str(tmp_path / "a.poly"), "-o", str(tmp_path / "out.json")]) == 0
    finally:
        os.umask(old)
    assert (tmp_path / "out.json").stat().st_mode & 0o777 == 0o644


@pytest.mark.parametrize("suffix", [
    ".json", ".vtu", ".poly"])
def test_identical_runs_write_identical_files(tmp_path, suffix, capsys):
    # The same input and options give byte-identical output (no timings in the mesh file).
    (tmp_path / "a.poly").write_text(poly(points=[(0, 0), (4, 0), (2, 1)], segments=[(0, 1), (1, 2), (2, 0)]))
    outputs = []
    for k in range(2):
        out = tmp_path / f"run{k}{suffix}"
        assert main(["refine", str(tmp_path / "a.poly"), "-o", str(out)]) == 0
        outputs.append(out.read_bytes().replace(out.stem.encode(), b""))  # .poly names its .node
    assert outputs[0] == outputs[1]
