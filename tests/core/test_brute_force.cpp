#include <doctest/doctest.h>

#include "hodt/brute_force.hpp"
#include "hodt/delaunay.hpp"
#include "hodt/error.hpp"
#include "hodt/points.hpp"
#include "generators.hpp"

using namespace hodt;
using namespace hodt::test;

TEST_CASE("brute force: optimum over a plain enumeration, for every objective") {
  int instances = 0;
  for (uint64_t seed = 1; instances < 40; ++seed) {
    const std::vector<double> p = seed % 3 == 0 ? dem_points(14, seed) : seed % 3 == 1 ? uniform_points(14, seed) : jittered_grid(4, 4, 0.2, seed);
    const FirstOrder fo = first_order(delaunay(validate_points(p).xyz));
    if (fo.num_quads() > 10) continue;
    ++instances;
    // Plain enumeration: rebuild each triangulation from the base (not Gray flips).
    const uint32_t m = fo.num_quads();
    std::vector<std::array<double, kNumObjectives>> values;
    for (uint64_t bits = 0; bits < (uint64_t(1) << m); ++bits) {
      Choice c(m);
      for (uint32_t q = 0; q < m; ++q) c[q] = (bits >> q) & 1;
      values.push_back(evaluate_all(triangulate(fo, c)));
    }
    CHECK(enumerate_all(fo) == values);
    for (const auto& oi : objectives()) {
      const size_t k = static_cast<size_t>(oi.objective);
      double best = values[0][k];
      for (const auto& v : values) best = oi.sense == Sense::Min ? std::min(best, v[k]) : std::max(best, v[k]);
      const Solution s = brute_force(fo, oi.objective);
      CHECK(s.value == best);
      CHECK(s.optimal);
      CHECK(s.delaunay_value == values[0][k]);
      CHECK(evaluate(oi.objective, triangulate(fo, s.choice)) == s.value);
    }
  }
}

TEST_CASE("brute force refuses more than 24 quads") {
  const FirstOrder fo = first_order(delaunay(grid_points(8, 8, 1)));
  REQUIRE(fo.num_quads() > 24);
  CHECK_THROWS_AS(brute_force(fo, Objective::MaxConvexEdges), LimitError);
}
