// The encroached subsegments, kept up to date as points are added (gabriel3d_encroached.h).
#include "gabriel3d_encroached.h"

#include <algorithm>
#include <string>

namespace nonobtuse::gabriel3d {

EncroachedSubsegments::EncroachedSubsegments(const PlcState& s, const PointIndex& index)
    : s_(s), index_(index), balls_(s.points) {
  for (const auto& [sub, parent] : s.subsegments) track(sub);
}

bool EncroachedSubsegments::encroached_by_query(const Key& sub) const {
  return deepest_encroacher(s_.points, index_, sub.first, sub.second, -1).vertex >= 0;
}

void EncroachedSubsegments::track(const Key& sub) {
  if (encroached_by_query(sub)) encroached_.insert(sub);
  balls_.add(sub);
}

void EncroachedSubsegments::untrack(const Key& sub) {
  encroached_.erase(sub);
  balls_.remove(sub);
}

void EncroachedSubsegments::added(int m, const std::optional<Key>& split) {
  if (split) {
    untrack(*split);
    track(key(split->first, m));
    track(key(m, split->second));
  }
  const P3& p = s_.points[m];
  auto test = [&](const Key& sub) {
    if (sub.first == m || sub.second == m || encroached_.count(sub)) return;
    if (CGAL::side_of_bounded_sphere(s_.points[sub.first], s_.points[sub.second], p) == CGAL::ON_BOUNDED_SIDE)
      encroached_.insert(sub);
  };
  balls_.for_each_near(p, test);
}

std::vector<Key> EncroachedSubsegments::holding(const P3& p) const {
  std::vector<Key> out;
  balls_.for_each_near(p, [&](const Key& sub) {
    if (CGAL::side_of_bounded_sphere(s_.points[sub.first], s_.points[sub.second], p) == CGAL::ON_BOUNDED_SIDE)
      out.push_back(sub);
  });
  std::sort(out.begin(), out.end());
  return out;
}

void EncroachedSubsegments::check_against_full_scan() const {
  std::size_t found = 0;
  for (const auto& [sub, parent] : s_.subsegments) {
    const bool query = encroached_by_query(sub);
    found += query;
    if (query != contains(sub))
      throw InternalError("subsegment (" + std::to_string(sub.first) + ", " + std::to_string(sub.second) + ") is " +
                          (query ? "" : "not ") + "encroached, but the incremental set says otherwise");
  }
  if (found != encroached_.size()) throw InternalError("the incremental encroached set holds split subsegments");
}

}  // namespace nonobtuse::gabriel3d
