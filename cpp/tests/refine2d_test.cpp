// nonobtuse::refine: budget and status, and the shared corpus refined with its exact certificate.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "nonobtuse/check2d.h"
#include "refine2d_fixtures.h"

namespace nonobtuse {
namespace {

using testing::half_disk;

TEST(Refine2d, BudgetExhaustedReturnsPartialMesh) {
  Domain2 d = half_disk({{17, 15}, {39, 30.7}});
  Refine2DOptions options;
  options.max_steiner = 0;
  options.check_every_split = true;
  Refine2DResult r = refine(d, options);
  EXPECT_EQ(r.status, RefineStatus::BudgetExhausted);
  EXPECT_EQ(r.steiner_points, 0);
  EXPECT_EQ(r.max_steiner, 0);
  EXPECT_EQ(r.obtuse_boundary_sides, 1);  // the triangle on e, obtuse at q1
  EXPECT_EQ(r.mesh.points.size(), d.points.size());
  EXPECT_EQ(default_steiner_budget(7), 1070);
  EXPECT_EQ(refine(d).max_steiner, default_steiner_budget(d.points.size()));
  EXPECT_STREQ(to_string(r.status), "budget_exhausted");
  EXPECT_STREQ(to_string(RefineStrategy::ProjectFlip), "project-flip");
}

// Points, triangles, constrained subsegments and regions of two meshes are the same, in the same order.
void expect_same_mesh(const Mesh2& a, const Mesh2& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    EXPECT_EQ(a.points[i].x, b.points[i].x);
    EXPECT_EQ(a.points[i].y, b.points[i].y);
  }
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.segments, b.segments);
  EXPECT_EQ(a.triangle_region, b.triangle_region);
}

TEST(Refine2d, TakesOverTheTriangulationInspectDomainKept) {
  // A half disk with obtuse apexes, a triangular hole and region seeds: refine on the kept triangulation gives
  // the mesh refine makes alone, and empties it.
  Domain2 d = half_disk({{17, 15}, {39, 30.7}, {22, 8}, {28, 8}, {25, 12}});
  const int n = static_cast<int>(d.points.size());
  d.segments.insert(d.segments.end(), {{n - 3, n - 2}, {n - 2, n - 1}, {n - 1, n - 3}});
  d.holes = {{25, 9}};
  d.regions = {{{10, 5}, 1.0}, {{40, 5}, 2.0}};
  DomainCoverage cov = inspect_domain(d, true);
  ASSERT_NE(cov.triangulation, nullptr);
  EXPECT_EQ(inspect_domain(d).triangulation, nullptr);  // kept only when asked
  const Refine2DResult alone = refine(d);
  const Refine2DResult taken = refine(d, {}, cov.triangulation.get());
  EXPECT_TRUE(cov.triangulation->empty());
  EXPECT_GT(alone.steiner_points, 0);
  EXPECT_EQ(taken.steiner_points, alone.steiner_points);
  expect_same_mesh(taken.mesh, alone.mesh);

  // Kept for another domain (a point moved): refine triangulates the one it is given.
  Domain2 moved = d;
  moved.points[n - 4] = {17, 16};
  cov = inspect_domain(d, true);
  expect_same_mesh(refine(moved, {}, cov.triangulation.get()).mesh, refine(moved).mesh);
  EXPECT_TRUE(cov.triangulation->empty());
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// The numbers of the JSON array `key` holds (nested arrays flattened), in order.
std::vector<double> json_numbers(const std::string& text, const std::string& key) {
  const auto at = text.find("\"" + key + "\"");
  if (at == std::string::npos) throw std::runtime_error("no key " + key);
  const auto open = text.find('[', at);
  int depth = 0;
  std::size_t end = open;
  do depth += text[end] == '[' ? 1 : text[end] == ']' ? -1 : 0;
  while (depth > 0 && ++end < text.size());
  std::vector<double> out;
  const std::regex number(R"(-?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?)");
  const std::string body = text.substr(open, end - open);
  for (std::sregex_iterator it(body.begin(), body.end(), number), stop; it != stop; ++it)
    out.push_back(std::stod(it->str()));
  return out;
}

// A CG:SHOP 2025 instance: the region_boundary polygon (closed), additional constraints, interior points (as
// tests/refine_helpers.py reads it).
Domain2 cgshop_domain(const std::string& text) {
  Domain2 d;
  const auto xs = json_numbers(text, "points_x"), ys = json_numbers(text, "points_y");
  for (std::size_t i = 0; i < xs.size(); ++i) d.points.push_back({xs[i], ys[i]});
  const auto rb = json_numbers(text, "region_boundary"), extra = json_numbers(text, "additional_constraints");
  for (std::size_t i = 0; i < rb.size(); ++i)
    d.segments.push_back({static_cast<int>(rb[i]), static_cast<int>(rb[(i + 1) % rb.size()])});
  for (std::size_t i = 0; i + 1 < extra.size(); i += 2)
    d.segments.push_back({static_cast<int>(extra[i]), static_cast<int>(extra[i + 1])});
  return d;
}

// Every CG:SHOP instance pinned in tests/data/refine_corpus.json, refined by each strategy with the per-split
// invariants on: converged, the exact certificate of the returned mesh recomputed here (count_obtuse_boundary_sides)
// is 0, and the Steiner counts and lower bound equal the pins the Python corpus test holds too.
TEST(Refine2d, SharedCorpusConvergesWithAnExactCertificate) {
  const std::string shared = NONOBTUSE_SHARED_DATA;
  if (!std::ifstream(shared + "/cgshop25/SOURCE.md")) GTEST_SKIP() << "../shared/data not present: " << shared;
  const std::string pins = read_text(NONOBTUSE_TEST_DATA "/refine_corpus.json");
  const std::regex entry(R"re("(cgshop25/[^"]+)":\s*\{\s*"greedy":\s*(\d+),\s*"project-flip":\s*(\d+),)re"
                         R"re(\s*"projection":\s*(\d+),\s*"lower_bound":\s*(\d+))re");
  int files = 0;
  for (std::sregex_iterator it(pins.begin(), pins.end(), entry), stop; it != stop; ++it, ++files) {
    const std::smatch& m = *it;
    const Domain2 d = cgshop_domain(read_text(shared + "/" + m[1].str()));
    const RefineStrategy strategies[] = {RefineStrategy::Greedy, RefineStrategy::ProjectFlip,
                                         RefineStrategy::Projection};
    for (int k = 0; k < 3; ++k) {
      Refine2DResult r = testing::run(d, strategies[k]);
      EXPECT_EQ(r.status, RefineStatus::Converged) << m[1] << " " << to_string(strategies[k]);
      EXPECT_EQ(count_obtuse_boundary_sides(r.mesh), 0) << m[1] << " " << to_string(strategies[k]);
      EXPECT_EQ(r.steiner_points, std::stoll(m[2 + k].str())) << m[1] << " " << to_string(strategies[k]);
      EXPECT_EQ(r.lower_bound, std::stoll(m[5].str())) << m[1];
    }
  }
  EXPECT_GE(files, 50);  // the corpus holds 52 CG:SHOP instances
}

}  // namespace
}  // namespace nonobtuse
