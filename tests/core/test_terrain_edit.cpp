// Live edits (Terrain::add_point / move_point / remove_point) against terrains
// built from scratch from the edited points: the same triangles, the same
// flippable edges, the same optimum; bad edits leave the terrain unchanged.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <set>

#include "hodt/error.hpp"
#include "hodt/solve.hpp"
#include "hodt/terrain.hpp"
#include "generators.hpp"
#include "input_triangles.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

using Edge = std::pair<uint32_t, uint32_t>;

std::set<Edge> flippable_in_input(const Terrain& t) {
  std::set<Edge> out;
  for (const Quad& q : t.structure().quads) {
    const uint32_t a = t.to_input(q.a), b = t.to_input(q.b);
    out.insert({std::min(a, b), std::max(a, b)});
  }
  return out;
}

// The edited terrain equals one built from its points (in input order).
void same_as_fresh(const Terrain& t, const std::vector<double>& xyz) {
  REQUIRE(validate(t.structure().base) == "");
  const Terrain fresh = Terrain::from_points(xyz);
  REQUIRE(t.num_input_points() == fresh.num_input_points());
  CHECK(triangles_in_input(t) == triangles_in_input(fresh));
  CHECK(flippable_in_input(t) == flippable_in_input(fresh));
  CHECK(t.structure().base.hull.size() == fresh.structure().base.hull.size());
  for (Objective o : {Objective::MinLocalMinima, Objective::MinmaxEdgeAreaRatio}) {
    CHECK(solve(t.structure(), o, {}).value == solve(fresh.structure(), o, {}).value);
    CHECK(t.delaunay_value(o) == fresh.delaunay_value(o));
  }
}

void random_edits(std::vector<double> xyz, uint64_t seed, int edits, double step, bool integer) {
  Rng r(seed);
  Terrain t = Terrain::from_points(xyz);
  for (int k = 0; k < edits; ++k) {
    const uint32_t n = static_cast<uint32_t>(xyz.size() / 3);
    const uint32_t i = static_cast<uint32_t>(r.below(static_cast<int>(n)));
    double x = xyz[3 * i] + step * (2 * r.uniform() - 1), y = xyz[3 * i + 1] + step * (2 * r.uniform() - 1);
    if (integer) x = std::round(x), y = std::round(y);
    const double z = r.uniform();
    const int kind = r.below(3);
    const auto before = triangles_in_input(t);
    try {
      if (kind == 0) {
        const uint32_t added = t.add_point(x, y, z);
        CHECK(added == n);
        xyz.insert(xyz.end(), {x, y, z});
      } else if (kind == 1) {
        t.move_point(i, x, y, z);
        xyz[3 * i] = x, xyz[3 * i + 1] = y, xyz[3 * i + 2] = z;
      } else {
        t.remove_point(i);
        xyz.erase(xyz.begin() + 3 * i, xyz.begin() + 3 * i + 3);
      }
    } catch (const InputError&) {
      CHECK(triangles_in_input(t) == before);  // refused: unchanged
      continue;
    }
    same_as_fresh(t, xyz);
  }
}

}  // namespace

TEST_CASE("live edits equal a fresh build: random points") {
  for (uint64_t seed = 1; seed <= 12; ++seed) random_edits(uniform_points(30 + 10 * int(seed), seed), seed, 40, 0.2, false);
  random_edits(uniform_points(2000, 7), 7, 60, 0.01, false);
}

TEST_CASE("live edits equal a fresh build: grids (cocircular, collinear, duplicates refused)") {
  for (uint64_t seed = 1; seed <= 8; ++seed) random_edits(grid_points(6 + int(seed), 5 + int(seed), seed), seed, 40, 1.5, true);
}

TEST_CASE("live edits: errors name what is wrong and change nothing") {
  Terrain t = Terrain::from_points(grid_points(4, 4, 1));
  auto error_of = [&](auto edit) -> std::string {
    try {
      edit();
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  CHECK(error_of([&] { t.add_point(1, 1, 0); }) == "point 16 has the same (x, y) = (1, 1) as point 5");
  CHECK(error_of([&] { t.move_point(0, 2, 2, 0); }) == "point 0 cannot move to (2, 2): point 10 is there");
  CHECK(error_of([&] { t.move_point(16, 0.5, 0.5, 0); }) == "point 16 is out of range (16 points)");
  CHECK(error_of([&] { t.add_point(0.5, NAN, 0); }) == "point 16: y is NaN, expected a finite number");
  Terrain three = Terrain::from_points({0, 0, 0, 1, 0, 0, 0, 1, 0});
  CHECK(error_of([&] { three.remove_point(1); }) == "need at least 3 distinct points, got 2");
  CHECK(three.num_input_points() == 3);
  CHECK(error_of([&] { three.move_point(2, 2, 0, 0); }).find("collinear") != std::string::npos);
  CHECK(validate(three.structure().base) == "");
  CHECK(three.structure().base.point(three.structure().base.num_vertices() - 1)[0] != 2);
}

TEST_CASE("live edits: a point dropped as a duplicate can be removed, and later indices shift") {
  // Points 1 and 3 are at the same (x, y): dedupe keeps point 1.
  Terrain t = Terrain::from_points({0, 0, 0, 1, 0, 1, 0, 1, 2, 1, 0, 3, 1, 1, 4}, Dedupe::KeepFirst);
  REQUIRE(t.num_input_points() == 5);
  REQUIRE(t.structure().base.num_vertices() == 4);
  const auto before = triangles_in_input(t);
  t.remove_point(3);
  CHECK(t.num_input_points() == 4);
  CHECK(t.structure().base.num_vertices() == 4);
  // The same triangles, with point 4 now point 3.
  std::set<std::array<uint32_t, 3>> shifted;
  for (auto tri : before) {
    for (uint32_t& v : tri) v = v > 3 ? v - 1 : v;
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    shifted.insert(tri);
  }
  CHECK(triangles_in_input(t) == shifted);
  // The terrain is the one built from the remaining points.
  Terrain fresh = Terrain::from_points({0, 0, 0, 1, 0, 1, 0, 1, 2, 1, 1, 4});
  CHECK(triangles_in_input(t) == triangles_in_input(fresh));
  t.remove_point(0);  // and a real vertex after it
  CHECK(t.num_input_points() == 3);
}
