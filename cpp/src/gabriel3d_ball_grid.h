// Internal: the diametral spheres of a set of subsegments, filed in grids of power-of-two cells so that the
// subsegments whose spheres may hold a point are found without scanning them all (EncroachedSubsegments,
// quality3d's BoundarySplitter). Each sphere's search ball (gabriel3d_index.h) is filed in every cell it touches
// of the grid of cell side 2^level, with level the smallest at which a ball spans at most two cells per axis: a
// point strictly inside a sphere lies in one of its cells at its level, so a query visits one cell per populated
// level (and the balls without finite bound). Candidates only: the caller decides exactly.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>
#include <vector>

#include "gabriel3d_plc.h"

namespace nonobtuse::gabriel3d {

class SubsegmentBalls {
 public:
  // Keeps a reference to points, which must hold both ends of every subsegment filed.
  explicit SubsegmentBalls(const std::vector<P3>& points) : points_(points) {}
  void add(const Key& sub);
  void remove(const Key& sub);  // a filed one (its ends have not moved since)
  // Calls visit(sub) for every filed subsegment whose diametral sphere may hold p strictly inside (among others).
  template <class Visit>
  void for_each_near(const P3& p, Visit&& visit) const;

 private:
  struct Cell {
    int level;  // cell side 2^level
    std::int64_t x, y, z;
    bool operator==(const Cell& o) const { return level == o.level && x == o.x && y == o.y && z == o.z; }
  };
  struct CellHash {
    std::size_t operator()(const Cell& c) const;
  };
  // floor(x / 2^level) for |x / 2^level| < 2^62 (exact but for underflow, which keeps the sign).
  static std::int64_t cell_index(double x, int level);
  // The cells a subsegment's search ball touches: at most 8 almost always, 27 at most (three per axis); in place,
  // not on the heap (one allocation per add or remove was a tenth of their time on fandisk).
  struct Cells {
    std::array<Cell, 27> cell;
    int size = 0;
    const Cell* begin() const { return cell.data(); }
    const Cell* end() const { return cell.data() + size; }
  };
  // nullopt without finite bound.
  std::optional<Cells> cells_of(const Key& sub) const;

  const std::vector<P3>& points_;
  std::unordered_map<Cell, std::vector<Key>, CellHash> cells_;
  std::map<int, long> levels_;  // populated level -> number of balls filed there
  std::set<Key> everywhere_;    // balls without finite bound: candidates for every point
};

template <class Visit>
void SubsegmentBalls::for_each_near(const P3& p, Visit&& visit) const {
  for (const auto& [level, balls] : levels_) {
    const double limit = 0x1p62;
    if (std::abs(std::ldexp(p.x(), -level)) >= limit || std::abs(std::ldexp(p.y(), -level)) >= limit ||
        std::abs(std::ldexp(p.z(), -level)) >= limit)
      continue;  // beyond every cell of this level (their indices stay below 2^53)
    auto it = cells_.find({level, cell_index(p.x(), level), cell_index(p.y(), level), cell_index(p.z(), level)});
    if (it != cells_.end())
      for (const Key& sub : it->second) visit(sub);
  }
  for (const Key& sub : everywhere_) visit(sub);
}

}  // namespace nonobtuse::gabriel3d
