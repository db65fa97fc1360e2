"""
nonobtuse C++ core (CGAL, exact predicates)
"""
from __future__ import annotations
import collections.abc
import numpy
import numpy.typing
import typing
__all__: list[str] = ['DomainCoverage', 'EdgeClassification', 'GabrielCertificate', 'InputAngle2D', 'InputAngle3D', 'InteriorRefinement', 'Junction', 'Mesh2D', 'Quality2DOptions', 'Quality2DStats', 'Refine2DDiagnosis', 'Refine2DResult', 'Refine3DDiagnosis', 'Refine3DResult', 'SegmentIntersections', 'SteinerCount', 'Triangulation2', 'check_gabriel', 'classify_edges', 'closed_diametral_sphere_hits', 'conforming_gabriel_steiner_points', 'control_volumes3d', 'coupling_signs', 'default_interior_budget', 'default_steiner_budget', 'delaunay_cells_inside_surface', 'delaunay_restricted_to_plc', 'delaunay_tetrahedra', 'dual_area_signs', 'exact_tet_circumspheres', 'find_segment_intersections', 'inspect_domain', 'parse_numeric_rows', 'plc_collinear', 'plc_orient3d', 'plc_self_intersections', 'plc_unbalanced_edge', 'refine', 'refine_gabriel', 'refine_interior', 'surface_winding_numbers', 'triangulate']
class Mesh2D:
    """
    A triangulated 2D domain (read-only; each array attribute is a new array on each access).
    """
    def __repr__(self) -> str:
        ...
    @property
    def points(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, 2) float64: the domain's points in input order, then Steiner points.
        """
    @property
    def segments(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (k, 2) int64: every constrained subsegment (boundary, interface, dangling).
        """
    @property
    def triangle_region(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (m,) float64 region attribute per triangle (0 where no region seed reached).
        """
    @property
    def triangles(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (m, 3) int64, counter-clockwise, domain triangles only.
        """
class EdgeClassification:
    """
    Every edge of a mesh classified exactly, sorted by (a, b), a < b (read-only).
    """
    def __repr__(self) -> str:
        ...
    @property
    def angle(self) -> numpy.typing.NDArray[numpy.int8]:
        """
        (E, 2) int8: 0 acute, 1 right, 2 obtuse (meaningless where triangle is -1)
        """
    @property
    def apex(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (E, 2) int64 [left, right], -1 where no triangle
        """
    @property
    def edges(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (E, 2) int64 (a, b), a < b
        """
    @property
    def kind(self) -> numpy.typing.NDArray[numpy.int8]:
        """
        (E,) int8: 0 boundary, 1 interface, 2 interior
        """
    @property
    def locally_delaunay(self) -> numpy.typing.NDArray[numpy.int8]:
        """
        (E,) int8
        """
    @property
    def sign(self) -> numpy.typing.NDArray[numpy.int8]:
        """
        (E,) int8 exact sign of each coupling coefficient (coupling_signs; empty otherwise)
        """
    @property
    def triangle(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (E, 2) int64 [left, right], -1 where none
        """
class SegmentIntersections:
    """
    Exact segment intersections, sorted int64 (k, 2) arrays (read-only; a new array on each access).
    """
    def __repr__(self) -> str:
        ...
    @property
    def crossings(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (s, t): proper crossings
        """
    @property
    def overlaps(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (s, t): collinear with a common piece
        """
    @property
    def points_on_segments(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (p, s): point p strictly inside segment s
        """
class Triangulation2:
    """
    Opaque: the constrained Delaunay triangulation inspect_domain built, for refine to take over (once).
    """
    @property
    def empty(self) -> bool:
        """
        True once refine took it
        """
class DomainCoverage:
    """
    What a domain's constrained Delaunay triangulation covers.
    """
    def __repr__(self) -> str:
        ...
    @property
    def domain_triangles(self) -> int:
        ...
    @property
    def encloses_area(self) -> bool:
        """
        some triangle is enclosed by segments (holes ignored)
        """
    @property
    def holes(self) -> numpy.typing.NDArray[numpy.int8]:
        """
        int8 per hole seed: 0 inside, 1 outside, 2 on a point or segment
        """
    @property
    def regions(self) -> numpy.typing.NDArray[numpy.int8]:
        """
        int8 per region seed, likewise
        """
    @property
    def segments_outside(self) -> numpy.typing.NDArray[numpy.int32]:
        """
        int32: segments with no domain triangle on either side
        """
    @property
    def triangulation(self) -> Triangulation2:
        """
        the triangulation when kept (keep_triangulation=True and a triangle), else None
        """
class Quality2DOptions:
    """
    What makes a triangle bad for refine (see nonobtuse.refine).
    """
    def __init__(self) -> None:
        ...
    def enabled(self) -> bool:
        """
        whether any criterion is set
        """
    def set_max_area_at(self, size: collections.abc.Callable[[float, float], typing.SupportsFloat | typing.SupportsIndex]) -> None:
        """
        size(x, y) -> the largest area of a triangle whose centroid is (x, y)
        """
    @property
    def max_area(self) -> float:
        """
        <= 0: none
        """
    @max_area.setter
    def max_area(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def max_interior(self) -> int:
        """
        < 0: default_interior_budget
        """
    @max_interior.setter
    def max_interior(self, arg0: typing.SupportsInt | typing.SupportsIndex) -> None:
        ...
    @property
    def min_angle_degrees(self) -> float:
        ...
    @min_angle_degrees.setter
    def min_angle_degrees(self, arg0: typing.SupportsFloat | typing.SupportsIndex) -> None:
        ...
    @property
    def minimal_boundary_first(self) -> bool:
        """
        greedy strategy: the minimal boundary before the quality refinement (default False: Triangle's midpoints and shells by the quality refinement)
        """
    @minimal_boundary_first.setter
    def minimal_boundary_first(self, arg0: bool) -> None:
        ...
    @property
    def region_max_area(self) -> list[tuple[float, float]]:
        """
        [(attribute, area), ...]
        """
    @region_max_area.setter
    def region_max_area(self, arg0: collections.abc.Sequence[tuple[typing.SupportsFloat | typing.SupportsIndex, typing.SupportsFloat | typing.SupportsIndex]]) -> None:
        ...
class Quality2DStats:
    """
    What the interior refinement did and left (read-only).
    """
    @property
    def bad_triangles(self) -> int:
        ...
    @property
    def boundary_points_removed(self) -> int:
        ...
    @property
    def boundary_splits(self) -> int:
        ...
    @property
    def interior_budget(self) -> int:
        ...
    @property
    def interior_points(self) -> int:
        ...
    @property
    def max_area(self) -> float:
        ...
    @property
    def min_angle_degrees(self) -> float:
        ...
    @property
    def min_angle_outside_small_angles_degrees(self) -> float:
        ...
    @property
    def small_angle_triangles(self) -> int:
        ...
    @property
    def triangles(self) -> int:
        ...
class Junction:
    """
    An input vertex where at least two input constraints meet.
    """
    def __repr__(self) -> str:
        ...
    @property
    def constraints(self) -> int:
        """
        input constraints meeting there
        """
    @property
    def min_angle_degrees(self) -> float:
        """
        smallest angle between two of them (float, for reporting only)
        """
    @property
    def steiner_points(self) -> int:
        """
        Steiner points whose nearest end on their input edge is this vertex
        """
    @property
    def vertex(self) -> int:
        """
        input point index
        """
class InputAngle2D:
    """
    The angle at vertex between input constraints (vertex, a) and (vertex, b).
    """
    def __repr__(self) -> str:
        ...
    @property
    def a(self) -> int:
        ...
    @property
    def b(self) -> int:
        """
        the constraint closest in angle to (vertex, a)
        """
    @property
    def degrees(self) -> float:
        ...
    @property
    def steiner_points(self) -> int:
        """
        Steiner points on (vertex, a) nearest to vertex
        """
    @property
    def vertex(self) -> int:
        ...
class Refine2DDiagnosis:
    """
    Where the Steiner points of a 2D refinement went.
    """
    def __repr__(self) -> str:
        ...
    @property
    def angles(self) -> list[InputAngle2D]:
        """
        at most 10, likewise
        """
    @property
    def initial_violations(self) -> int:
        ...
    @property
    def junctions(self) -> list[Junction]:
        """
        at most 10, by decreasing Steiner count
        """
    @property
    def propagation_depth(self) -> int:
        ...
    @property
    def propagation_splits(self) -> int:
        ...
    @property
    def stop_reason(self) -> str:
        """
        why the refinement stopped, in refine_gabriel's words (a budget by its option's name)
        """
class Refine2DResult:
    """
    What refine returns (read-only; see nonobtuse.refine).
    """
    def __repr__(self) -> str:
        ...
    @property
    def diagnosis(self) -> Refine2DDiagnosis:
        ...
    @property
    def edges(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (k, 4) int64 rows a, b, steiner_points, lower_bound per input boundary edge (a new array on each access)
        """
    @property
    def lower_bound(self) -> int:
        ...
    @property
    def max_steiner(self) -> int:
        """
        the Steiner budget used (its default resolved)
        """
    @property
    def max_steiner_offset(self) -> float:
        """
        largest distance of a Steiner point off its input segment over the segment's length
        """
    @property
    def mesh(self) -> Mesh2D:
        """
        the constrained Delaunay triangulation of the refined domain
        """
    @property
    def obtuse_boundary_sides(self) -> int:
        """
        exact certificate of mesh: obtuse boundary sides (0 when converged)
        """
    @property
    def optimal(self) -> bool | None:
        """
        True when certainly optimal, None when unknown
        """
    @property
    def quality(self) -> Quality2DStats:
        """
        the interior refinement (Quality2DStats)
        """
    @property
    def seconds(self) -> float:
        ...
    @property
    def status(self) -> str:
        """
        'converged', 'budget_exhausted' or 'stalled'
        """
    @property
    def steiner_points(self) -> int:
        ...
class GabrielCertificate:
    """
    Encroached boundary faces and segments (read-only; a new array on each access).
    """
    def __repr__(self) -> str:
        ...
    @property
    def candidates(self) -> int:
        """
        (simplex, vertex) pairs passed to the exact predicate
        """
    @property
    def face_depths(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (a,) float64 1 - |vertex - center| / radius (floating point, for display)
        """
    @property
    def face_vertices(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (a,) int64 the deepest encroaching vertex of each
        """
    @property
    def faces(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (a,) int64 rows of the faces checked that are encroached
        """
    @property
    def segment_depths(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def segment_vertices(self) -> numpy.typing.NDArray[numpy.int64]:
        ...
    @property
    def segments(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (b,) int64 rows of the segments checked that are encroached
        """
    @property
    def unchecked_faces(self) -> int:
        """
        rows refine_gabriel's time_limit left unchecked
        """
    @property
    def unchecked_segments(self) -> int:
        ...
class InputAngle3D:
    """
    One small angle of the input (degrees, floating point).
    """
    def __repr__(self) -> str:
        ...
    @property
    def degrees(self) -> float:
        ...
    @property
    def facets(self) -> list[int]:
        ...
    @property
    def kind(self) -> str:
        """
        'segment-segment', 'segment-facet' or 'dihedral'
        """
    @property
    def vertices(self) -> list[int]:
        ...
class SteinerCount:
    """
    Steiner points near an input vertex or on an input segment.
    """
    def __repr__(self) -> str:
        ...
    @property
    def count(self) -> int:
        ...
    @property
    def where(self) -> list[int]:
        """
        an input vertex, or the two ends of an input segment
        """
class Refine3DDiagnosis:
    """
    What drove a 3D refinement and why it stopped.
    """
    def __repr__(self) -> str:
        ...
    @property
    def encroached_per_segment(self) -> list[SteinerCount]:
        ...
    @property
    def smallest_angles(self) -> list[InputAngle3D]:
        ...
    @property
    def steiner_per_segment(self) -> list[SteinerCount]:
        ...
    @property
    def steiner_per_vertex(self) -> list[SteinerCount]:
        ...
    @property
    def stop_reason(self) -> str:
        ...
class Refine3DResult:
    """
    What refine_gabriel returns (read-only; a new array on each access of an array attribute).
    """
    def __repr__(self) -> str:
        ...
    @property
    def boundary_faces(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (f, 3) int64
        """
    @property
    def certificate(self) -> GabrielCertificate:
        """
        check_gabriel of the mesh as returned
        """
    @property
    def diagnosis(self) -> Refine3DDiagnosis:
        ...
    @property
    def face_markers(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (f,) int64 input facet id of each boundary face
        """
    @property
    def greedy_splits(self) -> int:
        ...
    @property
    def max_steiner(self) -> int:
        """
        the Steiner budget used (its default resolved)
        """
    @property
    def max_work(self) -> int:
        """
        the work budget of each strategy pass (its default resolved)
        """
    @property
    def min_length(self) -> float:
        """
        the minimum length used (its default resolved)
        """
    @property
    def other_attempt(self) -> str:
        """
        status and stop reason of the attempts not returned
        """
    @property
    def points(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (n, 3) float64
        """
    @property
    def protecting_balls(self) -> int:
        """
        apex vertices protected
        """
    @property
    def seconds(self) -> float:
        ...
    @property
    def segments(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (k, 2) int64
        """
    @property
    def smallest_subsegment(self) -> float:
        ...
    @property
    def status(self) -> str:
        """
        'converged', 'budget_exhausted', 'min_length_reached' or 'stalled'
        """
    @property
    def steiner_on_facets(self) -> int:
        ...
    @property
    def steiner_on_segments(self) -> int:
        ...
    @property
    def strategy(self) -> str:
        """
        'shells', 'greedy', 'midpoint', 'protected', 'mirrored', or '<rule>+protected' / '<rule>+mirrored' after a fallback
        """
    @property
    def tet_regions(self) -> numpy.typing.NDArray[numpy.float64]:
        """
        (t,) float64
        """
    @property
    def tets(self) -> numpy.typing.NDArray[numpy.int64]:
        """
        (t, 4) int64
        """
    @property
    def volume_mesh(self) -> str:
        """
        'built', or why tets is empty
        """
    @property
    def work(self) -> int:
        """
        the work units spent by every attempt together
        """
class InteriorRefinement:
    """
    What refine_interior returns (read-only).
    """
    @property
    def blocked_centers(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def blocked_rows(self) -> numpy.typing.NDArray[numpy.int32]:
        ...
    @property
    def boundary_points(self) -> int:
        ...
    @property
    def boundary_rounds(self) -> int:
        ...
    @property
    def certified_points(self) -> int:
        ...
    @property
    def face_facets(self) -> numpy.typing.NDArray[numpy.int32]:
        ...
    @property
    def faces(self) -> numpy.typing.NDArray[numpy.int64]:
        ...
    @property
    def inserted(self) -> int:
        ...
    @property
    def placed(self) -> int:
        ...
    @property
    def points(self) -> numpy.typing.NDArray[numpy.float64]:
        ...
    @property
    def refused_splits(self) -> int:
        ...
    @property
    def segments(self) -> numpy.typing.NDArray[numpy.int64]:
        ...
    @property
    def small_angle_rows(self) -> numpy.typing.NDArray[numpy.int32]:
        ...
    @property
    def split_face_facets(self) -> numpy.typing.NDArray[numpy.int32]:
        ...
    @property
    def split_faces(self) -> numpy.typing.NDArray[numpy.int64]:
        ...
    @property
    def split_segments(self) -> numpy.typing.NDArray[numpy.int64]:
        ...
    @property
    def status(self) -> str:
        ...
    @property
    def step_centers(self) -> int:
        ...
    @property
    def step_elements(self) -> numpy.typing.NDArray[numpy.int64]:
        ...
    @property
    def tet_labels(self) -> numpy.typing.NDArray[numpy.int32]:
        ...
    @property
    def tets(self) -> numpy.typing.NDArray[numpy.int64]:
        ...
def check_gabriel(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], faces: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], segments: typing.Annotated[numpy.typing.ArrayLike, numpy.int64]) -> GabrielCertificate:
    """
    Exact diametral-sphere test of every face (f,3) and segment (k,2) against all points (n,3).
    Returns a GabrielCertificate.
    """
def classify_edges(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], triangles: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], segments: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], triangle_region: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> EdgeClassification:
    """
    Exact classification of every edge of a ccw triangle mesh (an EdgeClassification).
    triangle_region: (m,) float64 or empty.
    """
def closed_diametral_sphere_hits(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], faces: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], segments: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], candidates: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> tuple[numpy.typing.NDArray[numpy.int32], numpy.typing.NDArray[numpy.int32]]:
    """
    For each candidate (c,3): the first face (f,3) and the first segment (k,2) of points (n,3) whose closed
    diametral sphere holds it (exact), -1 where none. Returns (face (c,) int32, segment (c,) int32).
    """
def conforming_gabriel_steiner_points(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], segments: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], holes: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], regions: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], convex_hull_boundary: bool) -> int:
    """
    Benchmark peer: Steiner points added by CGAL::make_conforming_Gabriel_2 to the domain's CDT.
    """
def control_volumes3d(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], tets: typing.Annotated[numpy.typing.ArrayLike, numpy.int64]) -> dict:
    """
    The Voronoi face area dual to every edge of a tet mesh (per-tet decomposition, clipped to the mesh), its
    exact sign, and the cell volumes. points (n,3) float64, tets (t,4) int64 positively oriented
    (InvalidInputError otherwise). Returns a dict: edges (E,2) int64 (a < b, sorted), sign (E,) int8
    (-1, 0, +1), dual_areas (E,) float64 (exact sign times the float magnitude), lengths (E,) float64,
    volumes (n,) float64, exact_evaluations (int: edges the interval filter left to exact arithmetic),
    flat_in_floating_point (int: tets flat in doubles, whose circumcenters are exact, rounded).
    """
def coupling_signs(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], triangles: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], segments: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], triangle_region: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], conductivity: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> EdgeClassification:
    """
    classify_edges with sign (E,) int8: the exact sign (-1, 0, +1) of each edge's control-volume coupling
    coefficient sum_t k_t cot(apex_t) / 2. conductivity: (m,) float64 > 0 per triangle, or empty for k = 1.
    """
def default_interior_budget(n_points: typing.SupportsInt | typing.SupportsIndex, domain_area: typing.SupportsFloat | typing.SupportsIndex, smallest_area_limit: typing.SupportsFloat | typing.SupportsIndex) -> int:
    """
    The interior budget refine uses when max_interior < 0 (quality2d.h).
    """
def default_steiner_budget(n_points: typing.SupportsInt | typing.SupportsIndex) -> int:
    """
    The Steiner budget refine uses for n input points when max_steiner < 0 (refine2d.h).
    """
def delaunay_cells_inside_surface(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], triangles: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], cells: typing.Annotated[numpy.typing.ArrayLike, numpy.int64] | None = None) -> numpy.typing.NDArray[numpy.int64]:
    """
    Cells (t, 4) int64 of delaunay_tetrahedra(points) (or of the given cells (c, 4), e.g. the
    delaunay_cells of delaunay_restricted_to_plc) whose centroid has a non-zero exact winding number with
    respect to the closed oriented surface triangles (m, 3); sorted.
    """
def delaunay_restricted_to_plc(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], triangles: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], facet_ids: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], segments: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], holes: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], regions: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> dict:
    """
    The Delaunay tetrahedralization of a PLC's vertices restricted to its regions (exact flood fill across
    faces on no facet). Returns a dict: tets (t, 4), tet_regions (t,), boundary_faces (f, 3), face_markers
    (f,), uncovered_facets (facet ids the faces do not cover; empty iff it conforms to every facet),
    delaunay_cells (c, 4): for a triangle surface that does not conform, every Delaunay cell (tets etc.
    then empty); else (0, 4).
    """
def delaunay_tetrahedra(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> numpy.typing.NDArray[numpy.int64]:
    """
    Finite cells (t, 4) int64 of the Delaunay tetrahedralization of points (n, 3), positively oriented.
    Raises InvalidInputError when two points coincide.
    """
def dual_area_signs(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], tets: typing.Annotated[numpy.typing.ArrayLike, numpy.int64]) -> dict:
    """
    control_volumes3d's edges, sign and exact_evaluations alone (no floating-point magnitudes, lengths or
    volumes): for counting wrong-signed couplings. The same arguments and errors.
    """
def exact_tet_circumspheres(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], tets: typing.Annotated[numpy.typing.ArrayLike, numpy.int64]) -> tuple[numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64], numpy.typing.NDArray[numpy.float64]]:
    """
    Circumcenters (t,3), squared circumradii (t,) and signed volumes (t,) of tets (t,4) int64 over points
    (n,3) float64, each computed exactly and rounded to nearest (ties to even); +-inf beyond the double range;
    a coplanar tet: center and squared radius inf, volume 0.
    """
def find_segment_intersections(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], segments: typing.Annotated[numpy.typing.ArrayLike, numpy.int64]) -> SegmentIntersections:
    """
    Exact segment intersections. points (n,2) float64 finite and pairwise distinct; segments (m,2) int64 of
    distinct points. Returns a SegmentIntersections.
    """
def inspect_domain(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], segments: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], holes: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], regions: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], convex_hull_boundary: bool, keep_triangulation: bool = False) -> DomainCoverage:
    """
    What the domain covers (its constrained Delaunay triangulation). Inputs as for triangulate, validated
    (no crossings, no points inside segments). Returns a DomainCoverage; with keep_triangulation its
    triangulation is kept for refine.
    """
def parse_numeric_rows(text: bytes, rows: typing.SupportsInt | typing.SupportsIndex, width: typing.SupportsInt | typing.SupportsIndex, integer_columns: collections.abc.Sequence[typing.SupportsInt | typing.SupportsIndex]) -> numpy.typing.NDArray[numpy.float64] | None:
    """
    ASCII text of `rows` lines of exactly `width` plain decimal numbers as a (rows, width) float64 array
    (integer_columns: integer literals, |x| < 2^53), or None for anything else (numeric_rows.h).
    """
def plc_collinear(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], triples: typing.Annotated[numpy.typing.ArrayLike, numpy.int64]) -> numpy.typing.NDArray[numpy.int8]:
    """
    Exact collinearity (int8 1/0) of every row (a, b, c) of triples (m, 3).
    """
def plc_orient3d(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], quads: typing.Annotated[numpy.typing.ArrayLike, numpy.int64]) -> numpy.typing.NDArray[numpy.int8]:
    """
    Exact orient3d sign (int8: +1, 0 coplanar, -1) of every row (a, b, c, d) of quads (m, 4).
    """
def plc_self_intersections(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], triangles: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], max_pairs: typing.SupportsInt | typing.SupportsIndex = 1) -> numpy.typing.NDArray[numpy.int64]:
    """
    Pairs (k, 2) int64 (i < j) of triangles intersecting beyond shared vertices/edges (exact);
    triangles must be non-degenerate and distinct. At most max_pairs rows.
    """
def plc_unbalanced_edge(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], triangles: typing.Annotated[numpy.typing.ArrayLike, numpy.int64]) -> typing.Any:
    """
    The smallest edge (a, b), a < b, that the triangles (m, 3) traverse more often one way than the other,
    or None when they form a closed oriented surface.
    """
def refine(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], segments: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], holes: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], regions: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], convex_hull_boundary: bool, strategy: str = 'greedy', max_steiner: typing.SupportsInt | typing.SupportsIndex = -1, threads: typing.SupportsInt | typing.SupportsIndex = 2, quality: Quality2DOptions = ..., triangulation: Triangulation2 | None = None) -> Refine2DResult:
    """
    Nonobtuse boundary refinement of a validated domain (see nonobtuse.refine). max_steiner < 0:
    default_steiner_budget(n); quality: interior refinement (off by default). triangulation: inspect_domain's
    (DomainCoverage.triangulation), taken over when it triangulates this domain, empty afterwards. Returns a
    Refine2DResult.
    """
def refine_gabriel(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], triangles: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], facet_ids: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], segments: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], holes: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], regions: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], max_steiner: typing.SupportsInt | typing.SupportsIndex, min_length: typing.SupportsFloat | typing.SupportsIndex, max_work: typing.SupportsInt | typing.SupportsIndex, time_limit: typing.SupportsFloat | typing.SupportsIndex, split: str, protected_fallback: bool, fallback_own_limits: bool, progress_every: typing.SupportsInt | typing.SupportsIndex, progress: collections.abc.Callable[[int, int, int, float], None] | None) -> Refine3DResult:
    """
    Gabriel refinement of a PLC. max_steiner < 0, min_length < 0, max_work < 0: the defaults of Refine3DOptions (gabriel3d.h).
    progress: None or f(steiner, encroached_segments, encroached_facets, seconds).
    Returns a Refine3DResult.
    """
def refine_interior(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], tets: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], tet_labels: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], faces: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], segments: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], radius_edge: typing.SupportsFloat | typing.SupportsIndex, volume_bounds: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], max_points: typing.SupportsInt | typing.SupportsIndex, time_limit: typing.SupportsFloat | typing.SupportsIndex, insert: typing.Annotated[numpy.typing.ArrayLike, numpy.float64] = ..., face_facets: typing.Annotated[numpy.typing.ArrayLike, numpy.int64] = ..., max_boundary_points: typing.SupportsInt | typing.SupportsIndex = 1000000, min_length: typing.SupportsFloat | typing.SupportsIndex = 0.0, sharp_dihedral_degrees: typing.SupportsFloat | typing.SupportsIndex = 85.0, small_apex_degrees: typing.SupportsFloat | typing.SupportsIndex = 60.0, left_alone: typing.Annotated[numpy.typing.ArrayLike, numpy.int64] = ..., max_step_centers: typing.SupportsInt | typing.SupportsIndex = 0) -> InteriorRefinement:
    """
    Delaunay refinement of the interior of a mesh (n,3) points, (t,4) tets, (t,) labels with a Gabriel
    boundary (f,3) faces, (k,2) segments: circumcenters of tets over radius_edge (<= 0: none) or
    volume_bounds[label] inserted outside every closed diametral sphere, after inserting the points
    insert (p,3) outside them; with face_facets (f,) the facet id of each face, a center in a closed
    sphere splits the boundary instead, but near small input angles (sharp_dihedral_degrees,
    small_apex_degrees: small_angle_rows; see quality3d.h), or in that of a subfacet (a,b,c) or
    subsegment (a,b,-1) of left_alone (e,3);
    max_step_centers: blocked centers a boundary step splits for at most (0: all).
    """
def surface_winding_numbers(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], triangles: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], queries: typing.Annotated[numpy.typing.ArrayLike, numpy.float64]) -> numpy.typing.NDArray[numpy.int64]:
    """
    Exact winding number (q,) int64 of the oriented triangles (m, 3) around each query (q, 3): vertical ray
    casting from the query symbolically perturbed off the surface; +1 inside an outward closed surface.
    """
def triangulate(points: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], segments: typing.Annotated[numpy.typing.ArrayLike, numpy.int64], holes: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], regions: typing.Annotated[numpy.typing.ArrayLike, numpy.float64], convex_hull_boundary: bool) -> Mesh2D:
    """
    Constrained Delaunay triangulation of a validated domain. regions: (r, 3) rows x, y, attribute.
    Returns a Mesh2D.
    """
