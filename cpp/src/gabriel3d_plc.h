// Internal: the state of a PLC under Gabriel refinement. Each facet keeps its subfacets as a 2D constrained
// Delaunay triangulation in an (approximately) orthonormal frame of its plane; its constraints are the facet's
// boundary edges and the PLC segments inside it. The 2D triangulation uses exact constructions so that a point
// splitting a subsegment lies exactly on it in 2D (a + t (b - a) with t the double split parameter); the 3D point
// is the same interpolation rounded to doubles, and every 3D decision is made on the rounded coordinates.
#pragma once
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "gabriel3d_index.h"
#include "gabriel3d_scan_memo.h"

namespace nonobtuse::gabriel3d {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using Q2 = EK::Point_2;

struct FacetFaceInfo {
  bool in_domain = false;
  int nesting = -1;  // number of constraints crossed from the outside (domain: odd)
  ScanMemo scan;     // Refiner::encroached_subfacets' last answer for this face
};
using Vb2 = CGAL::Triangulation_vertex_base_with_info_2<int, EK>;  // info: global point index
using Fbb2 = CGAL::Triangulation_face_base_with_info_2<FacetFaceInfo, EK>;
using Fb2 = CGAL::Constrained_triangulation_face_base_2<EK, Fbb2>;
using Tds2 = CGAL::Triangulation_data_structure_2<Vb2, Fb2>;
// Facet edges crossing each other are refused (an exception); one through a vertex is caught by build_plc_state.
// (No_constraint_intersection_tag would also refuse inserting a point on a constraint, which splits use.)
using FacetCDT = CGAL::Constrained_Delaunay_triangulation_2<EK, Tds2,
                                                            CGAL::No_constraint_intersection_requiring_constructions_tag>;

struct Facet {
  int id = 0;  // the input facet id
  std::array<double, 3> origin{}, u{}, v{};
  FacetCDT cdt;
  std::unordered_map<int, FacetCDT::Vertex_handle> vertex;  // global point index -> vertex
  Q2 project(const P3& p) const;
  std::array<double, 3> normal() const;  // u x v (rounded; unit to rounding)
};

// An input segment: a PLC segment or a facet boundary edge. Subsegments remember it as their parent.
struct InputSegment {
  int a = 0, b = 0;
  std::vector<int> facets;  // indices into PlcState::facets whose triangulation has it as a constraint
  long steiner = 0;
};

using Key = std::pair<int, int>;  // (min, max) point indices
inline Key key(int a, int b) { return a < b ? Key{a, b} : Key{b, a}; }

// The distance between p and q in doubles (rounded: for sizes and search bounds, never for a geometric decision).
inline double distance(const P3& p, const P3& q) { return std::sqrt(CGAL::to_double(CGAL::squared_distance(p, q))); }

struct PlcState {
  int n_input = 0;
  std::vector<P3> points;
  std::vector<std::unique_ptr<Facet>> facets;
  std::vector<InputSegment> segments;
  std::map<Key, int> subsegments;              // subsegment -> parent input segment
  std::vector<std::vector<int>> point_facets;  // facets each point lies on
  std::map<std::array<double, 3>, int> at;     // coordinates -> point index (no duplicates allowed)
};

// Validates the PLC and builds the facets' triangulations and the input segments. Throws InvalidInput.
PlcState build_plc_state(const PLC3& plc);

// Marks in_domain by nesting parity, flooding from the infinite faces across edges (constraints add one).
void mark_facet_domain(FacetCDT& cdt);

// Splits subsegment ab of `parent` at a + t (b - a): a new point (index returned), the facets' triangulations and
// the subsegment map are updated.
int split_subsegment(PlcState& s, int a, int b, double t, const P3& rounded);

// Inserts a point strictly inside facet f's domain (located at (lt, loc, li) in its triangulation).
int insert_in_facet(PlcState& s, int f, const P3& point, FacetCDT::Locate_type lt, FacetCDT::Face_handle loc,
                    int li);

// Is the direction from `from` to `to` rounding noise for a point placed at distance `radius` along it: |to - from|
// within 2^-26 radius, or within 2^20 units in the last place of the larger coordinates (the two points' own
// rounding, a few of those units, then tilts it by more than 2^-20)? The ray rules (collar points, points moved
// onto a protecting sphere) refuse such a direction: a point placed along it can leave the facet's plane by up to
// `radius`.
bool noisy_direction(const P3& from, const P3& to, double radius);

// Is a located point strictly inside the facet's domain: in a domain face, or on an unconstrained edge between two?
bool strictly_in_domain(const FacetCDT& cdt, FacetCDT::Locate_type lt, FacetCDT::Face_handle loc, int li);

// The subsegment of the facet crossed first by the segment from g to q (2D, in its frame), if any; ties by Key.
std::optional<Key> first_crossed_subsegment(const Facet& facet, const Q2& g, const Q2& q);

// Is the triangle (a, b, c) of points on facet f inside the facet's domain (its 2D centroid in domain faces)?
bool triangle_on_facet(const PlcState& s, int f, int a, int b, int c);

void check_invariants(const PlcState& s);  // throws InternalError

// Output of the restriction of the Delaunay tetrahedralization of all points to the PLC's interior.
struct Restricted {
  std::vector<Tetrahedron> tets;
  std::vector<Triangle> boundary_faces;
  std::vector<int> face_markers;
  std::vector<int> face_facets;  // index into PlcState::facets of each boundary face
  // Per tet: the attribute of the region seed in its component, 0 for none; without seeds at all, its
  // component's number 1, 2, ... (components in the order of their smallest cells).
  std::vector<double> tet_regions;
};
// Components of cells connected across faces on no facet; the unbounded one and those of hole seeds are outside.
// Rows are canonical (a tet's least even permutation, a face from its smallest corner) and sorted.
Restricted restrict_delaunay(const PlcState& s, const PLC3& plc);
// The Delaunay tetrahedralization of a PLC state's points kept across the rounds of a refinement pass: restrict()
// inserts the points added since its last call and restricts it, with the result of restrict_delaunay on the same
// points (CGAL's symbolic perturbation makes the tetrahedralization of cospherical points independent of the
// insertion order, and the rows are canonical). The state's points may only grow.
class DelaunayRounds {
 public:
  DelaunayRounds();
  ~DelaunayRounds();
  // Runs work() while a second thread inserts the points feed() hands it (the points of the state's list from the
  // tetrahedralization's size on, as work() appends them), so that the insertion overlaps the refinement that makes
  // the points instead of following it in restrict() (a seventh of refine_gabriel on fandisk.off). One thread where
  // `parallel` is false or no thread can be started. An exception of work() or of the insertion is rethrown after
  // both ended, work()'s first.
  void insert_while(bool parallel, const std::function<void()>& work);
  // Copies the points [those handed before, points.size()) to the inserting thread, if insert_while runs one.
  void feed(const std::vector<P3>& points);
  Restricted restrict(const PlcState& s, const PLC3& plc);
  // The edges (point index pairs, of points restrict() has inserted) that are no edges of the tetrahedralization,
  // in the given order.
  std::vector<Key> missing_edges(const std::vector<Key>& edges) const;

 private:
  struct Kept;
  std::unique_ptr<Kept> kept_;
};
// The subfacets (the facets' triangulations) as boundary faces, oriented like the input triangles of their facet;
// no tets. Subfacets whose corners became collinear through the rounding of Steiner points (no diametral sphere)
// are left out and counted in *collinear.
Restricted subfacet_boundary(const PlcState& s, long* collinear);

// The few smallest input angles of each kind; call before refinement (it reads the unsplit input segments).
std::vector<InputAngle> smallest_input_angles(const PlcState& s);
// Every angle between an input segment and a facet through one of its ends where the segment leans over the facet
// (its projection points into the facet): kind "segment-facet", vertices {apex, segment end}. Floating point.
std::vector<InputAngle> segment_facet_angles(const PlcState& s);
// Steiner points per input segment and per nearest input vertex, top few; and the subsegments `check` found
// encroached (its segment rows in the order of s.subsegments) by input segment and encroacher.
void count_steiner(const PlcState& s, const GabrielReport& check, Refine3DDiagnosis& d);
// The length of the shortest subsegment (floating point), 0 without subsegments.
double smallest_subsegment(const PlcState& s);

}  // namespace nonobtuse::gabriel3d
