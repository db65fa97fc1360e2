// The encroached subsegments, kept up to date as points are added (gabriel3d_encroached.h).
#include "gabriel3d_encroached.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace nonobtuse::gabriel3d {
namespace {

// floor(x / 2^level) for |x / 2^level| < 2^62. The division by a power of two is exact unless it underflows, and an
// underflow keeps the sign (a nonzero subnormal floors correctly) except when it rounds to zero.
std::int64_t cell_index(double x, int level) {
  const double q = std::ldexp(x, -level);
  if (q == 0.0) return x < 0.0 ? -1 : 0;
  return static_cast<std::int64_t>(std::floor(q));
}

}  // namespace

std::size_t EncroachedSubsegments::CellHash::operator()(const Cell& c) const {
  std::size_t h = std::hash<int>()(c.level);
  for (std::int64_t v : {c.x, c.y, c.z}) h = h * 1000003u ^ std::hash<std::int64_t>()(v);
  return h;
}

EncroachedSubsegments::EncroachedSubsegments(const PlcState& s, const PointIndex& index) : s_(s), index_(index) {
  for (const auto& [sub, parent] : s.subsegments) track(sub);
}

bool EncroachedSubsegments::encroached_by_query(const Key& sub) const {
  return deepest_encroacher(s_.points, index_, sub.first, sub.second, -1).vertex >= 0;
}

std::optional<std::vector<EncroachedSubsegments::Cell>> EncroachedSubsegments::cells_of(const Key& sub) const {
  const SearchBall ball = search_ball(s_.points[sub.first], s_.points[sub.second]);
  if (ball.everything) return std::nullopt;
  const auto& c = ball.center;
  const double reach = std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])}) + ball.radius;
  // The ball contains the exact diametral sphere; the margin (about 9 units of 2^-53 of reach) covers the rounding
  // of radius + margin and of center -/+ radius below, so the cells hold every point strictly inside the sphere.
  const double r = ball.radius + 1e-15 * reach;
  int level = 0;
  std::frexp(2.0 * r, &level);  // 2^level > 2 r: at most two cells per axis (three where rounding shifts an end)
  // Not below 2^-1000 (no overflow in cell_index's scaling), nor so fine that indices pass 2^53.
  level = std::max({level, -1000, std::ilogb(reach + r) - 52});
  std::vector<Cell> out;
  const std::int64_t x1 = cell_index(c[0] + r, level), y1 = cell_index(c[1] + r, level);
  const std::int64_t z1 = cell_index(c[2] + r, level);
  for (std::int64_t x = cell_index(c[0] - r, level); x <= x1; ++x)
    for (std::int64_t y = cell_index(c[1] - r, level); y <= y1; ++y)
      for (std::int64_t z = cell_index(c[2] - r, level); z <= z1; ++z) out.push_back({level, x, y, z});
  return out;
}

void EncroachedSubsegments::track(const Key& sub) {
  if (encroached_by_query(sub)) encroached_.insert(sub);
  const auto cells = cells_of(sub);
  if (!cells) {
    everywhere_.insert(sub);
    return;
  }
  for (const Cell& cell : *cells) cells_[cell].push_back(sub);
  ++levels_[cells->front().level];
}

void EncroachedSubsegments::untrack(const Key& sub) {
  encroached_.erase(sub);
  const auto cells = cells_of(sub);  // the same cells as when it was filed: its ends have not moved
  if (!cells) {
    everywhere_.erase(sub);
    return;
  }
  for (const Cell& cell : *cells) {
    auto it = cells_.find(cell);
    std::vector<Key>& filed = it->second;
    filed.erase(std::find(filed.begin(), filed.end(), sub));
    if (filed.empty()) cells_.erase(it);
  }
  if (--levels_[cells->front().level] == 0) levels_.erase(cells->front().level);
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
  for (const auto& [level, balls] : levels_) {
    const double limit = 0x1p62;
    if (std::abs(std::ldexp(p.x(), -level)) >= limit || std::abs(std::ldexp(p.y(), -level)) >= limit ||
        std::abs(std::ldexp(p.z(), -level)) >= limit)
      continue;  // beyond every cell of this level (their indices stay below 2^53)
    auto it = cells_.find({level, cell_index(p.x(), level), cell_index(p.y(), level), cell_index(p.z(), level)});
    if (it != cells_.end())
      for (const Key& sub : it->second) test(sub);
  }
  for (const Key& sub : everywhere_) test(sub);
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
