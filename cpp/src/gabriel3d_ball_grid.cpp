// The subsegments' diametral spheres in power-of-two grids (gabriel3d_ball_grid.h).
#include "gabriel3d_ball_grid.h"

#include <algorithm>

namespace nonobtuse::gabriel3d {

// The division by a power of two is exact unless it underflows, and an underflow keeps the sign (a nonzero
// subnormal floors correctly) except when it rounds to zero.
std::int64_t SubsegmentBalls::cell_index(double x, int level) {
  const double q = std::ldexp(x, -level);
  if (q == 0.0) return x < 0.0 ? -1 : 0;
  return static_cast<std::int64_t>(std::floor(q));
}

std::size_t SubsegmentBalls::CellHash::operator()(const Cell& c) const {
  std::size_t h = std::hash<int>()(c.level);
  for (std::int64_t v : {c.x, c.y, c.z}) h = h * 1000003u ^ std::hash<std::int64_t>()(v);
  return h;
}

std::optional<SubsegmentBalls::Cells> SubsegmentBalls::cells_of(const Key& sub) const {
  const SearchBall ball = search_ball(points_[sub.first], points_[sub.second]);
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
  Cells out;
  const std::int64_t x1 = cell_index(c[0] + r, level), y1 = cell_index(c[1] + r, level);
  const std::int64_t z1 = cell_index(c[2] + r, level);
  for (std::int64_t x = cell_index(c[0] - r, level); x <= x1; ++x)
    for (std::int64_t y = cell_index(c[1] - r, level); y <= y1; ++y)
      for (std::int64_t z = cell_index(c[2] - r, level); z <= z1; ++z) out.cell[out.size++] = {level, x, y, z};
  return out;
}

void SubsegmentBalls::add(const Key& sub) {
  const auto cells = cells_of(sub);
  if (!cells) {
    everywhere_.insert(sub);
    return;
  }
  for (const Cell& cell : *cells) {
    std::vector<Key>& filed = cells_[cell];
    if (filed.empty()) filed.reserve(4);  // a cell holds a handful: one allocation, not one per doubling
    filed.push_back(sub);
  }
  ++levels_[cells->cell[0].level];
}

void SubsegmentBalls::remove(const Key& sub) {
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
  if (--levels_[cells->cell[0].level] == 0) levels_.erase(cells->cell[0].level);
}

}  // namespace nonobtuse::gabriel3d
