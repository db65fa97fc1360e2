// The labelled cells of the interior quality refinement's tetrahedralization (see quality3d_cells.h).
#include "quality3d_cells.h"

#include <algorithm>
#include <map>

#include "quality3d_rows.h"

namespace nonobtuse::quality3d {

std::array<int, 4> corners(Cell c) {
  return sorted_corners({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
}

void flood_labels(DT& dt, const std::vector<Triangle>& faces, std::vector<Cell> stack) {
  std::vector<std::array<int, 3>> subfacet;  // each with its corners sorted; sorted, for binary searches
  subfacet.reserve(faces.size());
  for (std::array<int, 3> k : faces) {
    std::sort(k.begin(), k.end());
    subfacet.push_back(k);
  }
  std::sort(subfacet.begin(), subfacet.end());
  while (!stack.empty()) {
    Cell c = stack.back();
    stack.pop_back();
    for (int i = 0; i < 4; ++i) {
      Cell n = c->neighbor(i);
      if (n->info() >= 0 || dt.is_infinite(n)) continue;
      std::array<int, 3> k;
      for (int j = 0, m = 0; j < 4; ++j)
        if (j != i) k[m++] = c->vertex(j)->info();
      std::sort(k.begin(), k.end());
      if (std::binary_search(subfacet.begin(), subfacet.end(), k)) continue;
      n->info() = c->info();
      stack.push_back(n);
    }
  }
}

void label_cells(DT& dt, const std::vector<std::array<int, 4>>& tets, const std::vector<int>& tet_labels,
                 const std::vector<Triangle>& faces) {
  std::map<std::array<int, 4>, int> label_of;
  for (std::size_t t = 0; t < tets.size(); ++t) label_of.emplace(sorted_corners(tets[t]), tet_labels[t]);
  std::vector<Cell> stack;
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) {
    c->info() = -1;
    if (dt.is_infinite(c)) continue;
    auto it = label_of.find(corners(c));
    if (it != label_of.end()) {
      c->info() = it->second;
      stack.push_back(c);
    }
  }
  flood_labels(dt, faces, std::move(stack));
}

}  // namespace nonobtuse::quality3d
