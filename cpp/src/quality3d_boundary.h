// Internal: the boundary of an interior refinement (quality3d_interior.cpp) as the facets' triangulations
// (gabriel3d_plc.h), split where circumcenters encroach it and then until it is Gabriel again (Ruppert's and
// Shewchuk's rule: subsegments before subfacets, a subfacet's circumcenter that encroaches a subsegment splits the
// subsegment instead).
#pragma once
#include <functional>
#include <map>
#include <tuple>
#include <vector>

#include "gabriel3d_ball_grid.h"
#include "gabriel3d_plc.h"
#include "quality3d_small_angle.h"

namespace nonobtuse::quality3d {

using gabriel3d::P3;

class BoundarySplitter {
 public:
  // points: every point of the mesh (boundary and interior, in the caller's order); faces with the input facet id of
  // each (face_facets), segments: the subfacets and subsegments. min_length: no split point closer than this to a
  // point (0: none); max_points: boundary points to add at most; sharp_dihedral, small_apex: the small-angle rule's
  // angles in degrees, at most volume_sharp for a tet over the volume bound (near_small_angle; 0: none). Throws
  // InvalidInput as build_plc_state does.
  BoundarySplitter(const std::vector<Point3>& points, const std::vector<Triangle>& faces,
                   const std::vector<int>& face_facets, const std::vector<Segment>& segments, double min_length,
                   long long max_points, double sharp_dihedral, double small_apex, double volume_sharp);

  const std::vector<P3>& points() const { return s_.points; }
  // Appends an interior point (on no facet), so that indices stay the caller's.
  void add_interior_point(const P3& p);
  int facet_id(int f) const { return s_.facets[f]->id; }
  // The facet (index into the state's facets) holding points a, b, c, or -1.
  int common_facet(int a, int b, int c) const;
  // Do the four points lie on one facet?
  bool on_one_facet(const std::array<int, 4>& p) const;
  // Is the triangle (a, b, c) of facet f's points inside the facet (gabriel3d::triangle_on_facet)?
  bool on_facet(int f, int a, int b, int c) const { return gabriel3d::triangle_on_facet(s_, f, a, b, c); }
  std::size_t facet_count() const { return s_.facets.size(); }
  // The subfacets (rows of the facets' triangulations, sorted) with their facet indices; the subsegments (sorted).
  void subfacets(std::vector<Triangle>& faces, std::vector<int>& facets) const;
  std::vector<Segment> subsegments() const;
  bool is_subsegment(int a, int b) const { return s_.subsegments.count(gabriel3d::key(a, b)) > 0; }
  // Is a point strictly inside the diametral sphere of segment ab (c == -1) or triangle abc? (exact)
  bool encroached(int a, int b, int c) const;

  // The small-angle rule (its termination argument is at refine_interior's boundary split rule): is the split that
  // a point in the closed diametral sphere of subsegment ab (f == -1) or of subfacet abc of facet f asks for, i.e.
  // the subsegment, or the subsegments of f that abc's circumcenter encroaches, or else abc itself, (i) at a small
  // input angle and near it: a subsegment on a sharp segment or with an end near a sharp apex whose midpoint is in
  // the protecting region, or a subfacet with a corner on a sharp segment or near a sharp apex whose circumcenter is
  // (SharpFeatures); or (ii) shorter than `shortest`: halves of a subsegment shorter than it, or a subfacet
  // circumcenter closer than it to the corners (Shewchuk's terminator: the split would make a feature smaller than
  // the tet it is made for)? Lengths compared exactly against the double `shortest`.
  // over_volume: for a tet over the volume bound, whose sharp features are those below volume_sharp degrees.
  bool near_small_angle(int f, int a, int b, int c, double shortest, bool over_volume) const;
  // The rule for a point in the closed diametral sphere at `row` of faces (a subfacet; -1 - row: of segments).
  bool leaves_alone(int row, const std::vector<Triangle>& faces, const std::vector<Segment>& segments,
                    double shortest, bool over_volume) const;

  // The split for a point in the closed diametral sphere of subsegment ab: its midpoint. False when refused.
  bool split_subsegment(int a, int b);
  // The split for a point in the closed diametral sphere of subfacet abc of facet f (a face of its triangulation):
  // its circumcenter, or the subsegments of the facet that point encroaches. False when nothing was added.
  bool split_subfacet(int f, int a, int b, int c);
  // Flips edges of the facets' triangulations towards the faces for which is_face holds (the choice of the 3D
  // Delaunay tetrahedralization between the diagonals of nearly cocircular points, which the facet's 2D Delaunay
  // criterion in its frame can decide the other way): an unconstrained edge between a subfacet that is no such
  // face and its neighbour is flipped when both new triangles are. Returns how many subfacets are still no such face.
  long follow(const std::function<bool(int, int, int)>& is_face);
  // Splits every subsegment, then every subfacet, with a point strictly inside its diametral sphere, and again,
  // until none has (true) or a split is refused or stop() (false).
  bool restore_gabriel(const std::function<bool()>& stop);

  // The next splits may add this many points at most (a step's own budget, within max_points); < 0: no bound.
  void limit_step(long long points) { step_end_ = points < 0 ? -1 : added + points; }

  long long added = 0;    // boundary points
  long long refused = 0;  // splits refused: min_length, an existing point, the budget, outside the facet

 private:
  bool may_add(const P3& p);
  void added_point(int i, char sharp, char volume_sharp);
  // The constrained edges of facet f whose diametral spheres hold z strictly inside, sorted: the subsegments
  // balls_ proposes for z whose input segment lies on f, decided exactly (a scan of f's edges took 22% of
  // anchor.off's time). Remembered per facet and point until the next split (the rule asks for the same subfacet's
  // circumcenter for every tet whose circumcenter lies in its sphere: anchor.off spent 37% of its pass rescanning).
  const std::vector<gabriel3d::Key>& encroached_subsegments(int f, const P3& z) const;
  mutable std::map<std::tuple<int, double, double, double>, std::vector<gabriel3d::Key>> hits_;
  // The subsegments and subfacets (facet, sorted corners) that restore_gabriel's last scan of each level found
  // free, sorted, and the number of points then: points are only added (interior ones too, between calls), so a free
  // one is encroached now exactly when one of the points added since is strictly inside its sphere; the others are
  // checked against all points. The scans find what full scans would.
  std::vector<gabriel3d::Key> free_subs_;
  std::vector<std::array<int, 4>> free_faces_;
  std::size_t subs_from_ = 0, faces_from_ = 0;

  gabriel3d::PlcState s_;
  gabriel3d::PointIndex index_;
  gabriel3d::SubsegmentBalls balls_;  // of s_.subsegments
  double min_length_;
  long long max_points_;
  long long step_end_ = -1;  // limit_step: added may not reach it; -1: no bound
  SharpFeatures features_;
  SharpFeatures volume_features_;  // below volume_sharp degrees, for tets over the volume bound
};

}  // namespace nonobtuse::quality3d
