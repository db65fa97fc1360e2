"""JSON formats: CG:SHOP 2025 instances and nonobtuse domains (read), nonobtuse meshes (read and write).
The schemas are documented in :mod:`nonobtuse.io`."""

from __future__ import annotations

import json
from collections.abc import Sequence
from pathlib import Path
from typing import IO, Any, NoReturn

import numpy as np

from nonobtuse.domain import Domain, SourceMap
from nonobtuse.errors import InvalidInputError
from nonobtuse.io._files import atomic_text, exact_float, read_text
from nonobtuse.mesh import Mesh

DOMAIN_KEYS = {"points", "segments", "holes", "regions", "convex_hull", "point_markers", "segment_markers"}
MESH_KEYS = {
    "points", "triangles", "segments", "input_points", "input_segments", "regions", "point_markers",
    "segment_markers", "stats",
}  # fmt: skip


def read_json(path: Path) -> Any:
    try:
        return json.loads(read_text(path))
    except json.JSONDecodeError as e:
        raise InvalidInputError(f"{path}:{e.lineno}: not valid JSON: {e.msg}") from None
    except RecursionError:
        raise InvalidInputError(f"{path}: not a domain or mesh: JSON nested too deeply") from None


def domain_from_json(path: Path, data: Any) -> tuple[Domain, bool | None]:
    """A CG:SHOP 2025 instance or a nonobtuse domain, by their keys. Returns the domain and the file's
    ``convex_hull`` (None when the file does not say)."""
    if not isinstance(data, dict):
        raise InvalidInputError(f"{path}: expected a JSON object, found {type(data).__name__}")
    if "points_x" in data:
        return _cgshop_instance(path, data), False
    if "triangles" in data:
        raise InvalidInputError(f"{path}: this is a mesh (it has 'triangles'), not a domain; use read_mesh")
    if "points" not in data:
        raise InvalidInputError(
            f"{path}: a JSON domain needs 'points' (nonobtuse domain) or 'points_x' (CG:SHOP instance)"
        )
    unknown = sorted(set(data) - DOMAIN_KEYS)
    if unknown:
        raise InvalidInputError(f"{path}: unknown key(s) {unknown} (a domain has {sorted(DOMAIN_KEYS)})")
    hull = data.get("convex_hull")
    if hull is not None and not isinstance(hull, bool):
        raise InvalidInputError(f"{path}: 'convex_hull' must be true or false, found {hull!r}")
    points = rows(data["points"], 2, float, f"{path}: points")
    segments = rows(data.get("segments", []), 2, int, f"{path}: segments")
    markers: dict[str, Any] = _markers(path, data, len(points), len(segments))
    domain = Domain(
        points,
        segments,
        rows(data.get("holes", []), 2, float, f"{path}: holes"),
        rows(data.get("regions", []), 3, float, f"{path}: regions"),
        source=str(path),
        origin=SourceMap(file=str(path)),
        **markers,
    )
    return domain, hull


def _markers(path: Path, data: dict, n_points: int, n_segments: int) -> dict[str, np.ndarray]:
    """The optional ``point_markers`` / ``segment_markers`` lists (integers, one per point / segment)."""
    markers = {}
    for key, n in (("point_markers", n_points), ("segment_markers", n_segments)):
        if data.get(key) is not None:
            markers[key] = rows(data[key], 0, int, f"{path}: {key}")
            if len(markers[key]) != n:
                raise InvalidInputError(f"{path}: {len(markers[key])} {key} for {n} {key.split('_')[0]}s")
    return markers


def _cgshop_instance(path: Path, data: dict) -> Domain:
    """CG:SHOP 2025: ``points_x``, ``points_y`` (numbers), ``region_boundary`` (a closed loop of point
    indices, counter-clockwise), ``additional_constraints`` (index pairs). Other keys (instance_uid,
    num_points, num_constraints) are ignored."""
    for key in ("points_x", "points_y", "region_boundary"):
        if not isinstance(data.get(key), list):
            raise InvalidInputError(f"{path}: a CG:SHOP instance needs the list '{key}'")
    xs, ys = data["points_x"], data["points_y"]
    if len(xs) != len(ys):
        raise InvalidInputError(f"{path}: points_x has {len(xs)} values but points_y has {len(ys)}")
    points = np.column_stack(
        [rows(xs, 0, float, f"{path}: points_x"), rows(ys, 0, float, f"{path}: points_y")]
    ).reshape(-1, 2)
    loop = rows(data["region_boundary"], 0, int, f"{path}: region_boundary")
    if len(loop) < 3:
        raise InvalidInputError(f"{path}: region_boundary must list at least 3 points, found {len(loop)}")
    boundary = np.column_stack([loop, np.roll(loop, -1)])
    extra = rows(data.get("additional_constraints", []), 2, int, f"{path}: additional_constraints")
    return Domain(
        points, np.concatenate([boundary, extra]), source=str(path), origin=SourceMap(file=str(path))
    )


def rows(value: Any, width: int, kind: type, where: str) -> np.ndarray:
    """A JSON list of ``width``-number lists (or of numbers when width is 0) as a float64 or int64 array.
    Refuses booleans, strings, ragged rows, non-integers where integers are expected, and integers float64
    cannot hold exactly; the message names ``where`` and the offending index."""
    dtype = np.int64 if kind is int else np.float64
    if isinstance(value, list) and len(value) == 0:
        return np.zeros((0,) if width == 0 else (0, width), dtype=dtype)
    try:
        arr = np.asarray(value) if isinstance(value, list) else None
    except ValueError:  # ragged rows
        arr = None
    row_shape = (width,) if width else ()
    if arr is None or arr.dtype.kind not in ("iu" if kind is int else "iuf") or arr.shape[1:] != row_shape:
        _explain(value, width, kind, where)
    if any(isinstance(x, bool) for x in (value if width == 0 else (x for row in value for x in row))):
        _explain(value, width, kind, where)  # numpy took true/false for 1/0
    if kind is float and arr.dtype.kind in "iu" and np.abs(arr).max() > 2**53:
        _exact_floats(value, width, where)
    return np.ascontiguousarray(arr, dtype=dtype)


def _exact_floats(value: list, width: int, where: str) -> None:
    for i, row in enumerate(value):
        for j, x in enumerate([row] if width == 0 else row):
            exact_float(x, f"{where}[{i}]" + ("" if width == 0 else f"[{j}]"))


def _explain(value: Any, width: int, kind: type, where: str) -> NoReturn:
    """Raise InvalidInputError naming the first malformed entry of ``value``."""
    if not isinstance(value, list):
        raise InvalidInputError(f"{where} must be a list, found {type(value).__name__}")
    what = (
        ("an integer" if kind is int else "a number")
        if width == 0
        else f"a list of {width} " + ("integers" if kind is int else "numbers")
    )
    for i, row in enumerate(value):
        entries = [row] if width == 0 else row
        if not isinstance(entries, list) or len(entries) != max(width, 1):
            raise InvalidInputError(f"{where}[{i}] must be {what}, found {row!r}")
        for x in entries:
            if kind is int and (isinstance(x, bool) or not isinstance(x, int)):
                raise InvalidInputError(f"{where}[{i}] must be {what}, found {row!r}")
            if kind is float:
                exact_float(x, f"{where}[{i}]")
    raise InvalidInputError(f"{where}: malformed (mixed types?)")


def mesh_from_json(path: Path, data: Any) -> Mesh:
    """A mesh in the nonobtuse mesh schema; checks keys, shapes, index ranges and that the first points are
    the input points. Geometry (orientation, Delaunay) is not checked here."""
    if not isinstance(data, dict) or "triangles" not in data:
        raise InvalidInputError(f"{path}: not a nonobtuse mesh (a JSON object with 'triangles')")
    missing = sorted({"points", "triangles", "segments", "input_points", "input_segments"} - set(data))
    unknown = sorted(set(data) - MESH_KEYS)
    if missing or unknown:
        raise InvalidInputError(f"{path}: mesh keys missing {missing}, unknown {unknown}")
    points = rows(data["points"], 2, float, f"{path}: points")
    not_finite = np.flatnonzero(~np.isfinite(points).all(axis=1))
    if len(not_finite):
        i = int(not_finite[0])
        raise InvalidInputError(f"{path}: points[{i}] = {points[i].tolist()} is not finite (a number too "
                                "large for float64, such as 1e400, reads as infinity)")
    input_points = rows(data["input_points"], 2, float, f"{path}: input_points")
    triangles = rows(data["triangles"], 3, int, f"{path}: triangles")
    segments = rows(data["segments"], 2, int, f"{path}: segments")
    input_segments = rows(data["input_segments"], 2, int, f"{path}: input_segments")
    for name, idx, n in (
        ("triangles", triangles, len(points)), ("segments", segments, len(points)),
        ("input_segments", input_segments, len(input_points)),
    ):  # fmt: skip
        bad = np.flatnonzero(((idx < 0) | (idx >= n)).any(axis=1)) if len(idx) else np.zeros(0, np.int64)
        if len(bad):
            raise InvalidInputError(
                f"{path}: {name}[{bad[0]}] = {idx[bad[0]].tolist()} refers to a missing point"
            )
    n0 = len(input_points)
    if n0 > len(points) or not np.array_equal(points[:n0], input_points):
        raise InvalidInputError(f"{path}: the first {n0} points must be the input points, in input order")
    regions = None
    if data.get("regions") is not None:
        regions = rows(data["regions"], 0, float, f"{path}: regions")
        if len(regions) != len(triangles):
            raise InvalidInputError(f"{path}: {len(regions)} regions for {len(triangles)} triangles")
    markers = _markers(path, data, len(points), len(segments))
    stats = data.get("stats", {})
    if not isinstance(stats, dict):
        raise InvalidInputError(f"{path}: 'stats' must be an object")
    return Mesh(points, triangles, segments, input_points, input_segments, regions, stats, **markers)


MESH_ARRAYS = (
    "points", "triangles", "segments", "input_points", "input_segments", "regions", "point_markers",
    "segment_markers",
)  # fmt: skip
_CHUNK_ROWS = 1 << 16
_COMPACT: dict[str, Any] = {"allow_nan": False, "separators": (",", ":")}


def write_mesh_json(mesh: Mesh, path: Path) -> None:
    """The mesh schema of :mod:`nonobtuse.io`, atomically: the arrays in the order of ``MESH_ARRAYS`` (the
    optional ones when the mesh has them), then ``stats``. Floats are written in shortest round-trip form, so
    reading gives the same float64 values. The text is what ``json.dump`` of the arrays' lists with
    ``separators=(",", ":")`` gives, byte for byte, but written in chunks of rows so the lists of the whole
    mesh are never built. NaN or infinity (never produced by nonobtuse) raise ValueError and leave ``path``
    untouched. Cost: O(size of the file), memory O(chunk)."""
    stats = json.dumps(mesh.stats, default=_plain, **_COMPACT)
    dtypes = {"regions": np.float64, "point_markers": np.int64, "segment_markers": np.int64}
    arrays = {
        key: np.asarray(getattr(mesh, key), dtype=dtypes.get(key))
        for key in MESH_ARRAYS
        if getattr(mesh, key) is not None
    }
    with atomic_text(path) as f:
        for i, (key, values) in enumerate(arrays.items()):
            f.write(("{" if i == 0 else ",") + json.dumps(key) + ":")
            _write_list(f, values)
        f.write(f',"stats":{stats}}}\n')


def _write_list(f: IO[str], values: np.ndarray) -> None:
    """``values`` as a JSON list: each chunk of rows through json's own encoder (the same text as the whole
    list's, floats by ``float.__repr__``), its brackets dropped and the chunks joined by commas."""
    f.write("[")
    for start in range(0, len(values), _CHUNK_ROWS):
        if start:
            f.write(",")
        f.write(json.dumps(values[start : start + _CHUNK_ROWS].tolist(), **_COMPACT)[1:-1])
    f.write("]")


def _plain(value: Any) -> Any:
    """JSON form of numpy scalars and arrays and of other sequences (``stats["edges"]``) in ``stats``."""
    if isinstance(value, Sequence):
        return list(value)
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    raise TypeError(f"stats value {value!r} of type {type(value).__name__} is not JSON serializable")
