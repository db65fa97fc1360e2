// Internal: the encroached subsegments of a PLC under refinement, kept up to date point by point instead of
// rescanning every subsegment. Points are only ever added, so a subsegment stays encroached until it is split, and
// an unencroached one becomes encroached only by a new point inside its diametral sphere: after each new point
// only the subsegments whose balls (gabriel3d_ball_grid.h) may hold it are tested, and the two halves of a split
// subsegment get a full query. Decisions are exact (side_of_bounded_sphere); the set always equals what a full
// scan with deepest_encroacher would find.
#pragma once
#include <optional>
#include <set>
#include <vector>

#include "gabriel3d_ball_grid.h"
#include "gabriel3d_plc.h"

namespace nonobtuse::gabriel3d {

class EncroachedSubsegments {
 public:
  // Queries every subsegment of s now (one deepest_encroacher each). Keeps references to s and index, which must
  // hold every point of s whenever added() is called.
  EncroachedSubsegments(const PlcState& s, const PointIndex& index);
  // Point m was appended to s (and to the index); `split`: the subsegment it split into (a, m) and (m, b), if any.
  void added(int m, const std::optional<Key>& split);
  bool contains(const Key& sub) const { return encroached_.count(sub) > 0; }
  // In the order of PlcState::subsegments (Key order), as a scan of that map would list them.
  std::vector<Key> sorted() const { return {encroached_.begin(), encroached_.end()}; }
  // The subsegments whose diametral spheres hold p strictly inside (exact), in Key order. Cost: the candidates of
  // one grid query (gabriel3d_ball_grid.h), not every subsegment.
  std::vector<Key> holding(const P3& p) const;
  // Throws InternalError unless the set is what a full scan finds (debug builds' invariant check).
  void check_against_full_scan() const;

 private:
  bool encroached_by_query(const Key& sub) const;
  void track(const Key& sub);    // a new subsegment: query it, file its ball
  void untrack(const Key& sub);  // a split one

  const PlcState& s_;
  const PointIndex& index_;
  std::set<Key> encroached_;
  SubsegmentBalls balls_;  // of the tracked subsegments
};

}  // namespace nonobtuse::gabriel3d
