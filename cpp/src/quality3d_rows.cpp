// refine_interior's input checks and canonical rows (see quality3d_rows.h).
#include "quality3d_rows.h"

#include <algorithm>
#include <string>
#include <utility>

namespace nonobtuse::quality3d {

std::array<int, 3> element(std::array<int, 3> e) {
  if (e[0] > e[1]) std::swap(e[0], e[1]);
  if (e[2] < 0) return e;
  if (e[1] > e[2]) std::swap(e[1], e[2]);
  if (e[0] > e[1]) std::swap(e[0], e[1]);
  return e;
}

std::array<int, 4> sorted_corners(std::array<int, 4> k) {
  std::sort(k.begin(), k.end());
  return k;
}

std::array<int, 4> canonical_tet(const std::array<int, 4>& t) {
  static constexpr int kEven[12][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 0, 3, 2}, {1, 2, 0, 3}, {1, 3, 2, 0},
                                       {2, 0, 1, 3}, {2, 1, 3, 0}, {2, 3, 0, 1}, {3, 0, 2, 1}, {3, 1, 0, 2}, {3, 2, 1, 0}};
  std::array<int, 4> best = t;
  for (const auto& p : kEven) best = std::min(best, std::array<int, 4>{t[p[0]], t[p[1]], t[p[2]], t[p[3]]});
  return best;
}

void check_input(const InteriorMesh& mesh, const InteriorBounds& bounds) {
  const auto n = static_cast<int>(mesh.points.size());
  auto in_range = [&](int v, const char* what, std::size_t row) {
    if (v < 0 || v >= n)
      throw InvalidInput(std::string(what) + " " + std::to_string(row) + " refers to point " + std::to_string(v) +
                         ", but there are " + std::to_string(n) + " points");
  };
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    for (int v : mesh.tets[t]) in_range(v, "tet", t);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
    for (int v : mesh.faces[f]) in_range(v, "face", f);
  for (std::size_t s = 0; s < mesh.segments.size(); ++s)
    for (int v : mesh.segments[s]) in_range(v, "segment", s);
  if (!mesh.face_facets.empty() && mesh.face_facets.size() != mesh.faces.size())
    throw InvalidInput("face_facets has " + std::to_string(mesh.face_facets.size()) + " entries for " +
                       std::to_string(mesh.faces.size()) + " faces");
  if (mesh.tet_labels.size() != mesh.tets.size())
    throw InvalidInput("tet_labels has " + std::to_string(mesh.tet_labels.size()) + " entries for " +
                       std::to_string(mesh.tets.size()) + " tets");
  for (std::size_t t = 0; t < mesh.tet_labels.size(); ++t)
    if (mesh.tet_labels[t] < 0 || static_cast<std::size_t>(mesh.tet_labels[t]) >= bounds.volume_bounds.size())
      throw InvalidInput("tet " + std::to_string(t) + " has label " + std::to_string(mesh.tet_labels[t]) +
                         ", but there are " + std::to_string(bounds.volume_bounds.size()) + " volume bounds");
}

}  // namespace nonobtuse::quality3d
