// Branch and bound over every fill (min-max objectives) against the k-OD
// enumerator's exhaustive optimum: a complete search proves exactly that value,
// from any value in hand; what it finds is a k-OD triangulation of that value.
#include <doctest/doctest.h>

#include "hodt/delaunay.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/points.hpp"
#include "generators.hpp"
#include "higher_order/k_order.hpp"
#include "higher_order/regions/region_engine.hpp"
#include "higher_order/search/branch_and_bound.hpp"

using namespace hodt;
using namespace hodt::test;

TEST_CASE("branch and bound over every fill equals exhaustive enumeration (min-max, orders 2 to 4, ties included)") {
  const Objective minmax[] = {Objective::MinmaxEdgeAreaRatio,     Objective::MinmaxEdgeNormalAngle,
                              Objective::MinmaxEdgeEnclosingCircle, Objective::MinmaxVertexAreaRatio,
                              Objective::MinmaxVertexNormalAngle, Objective::MinmaxTriangleArea,
                              Objective::MinmaxDegree};
  int proven = 0;
  for (uint64_t seed = 1; seed <= 12; ++seed) {
    const std::vector<double> xyz = seed % 3 == 0   ? grid_points(3, 4, seed, true)
                                    : seed % 3 == 1 ? uniform_points(10 + static_cast<int>(seed % 4), seed)
                                                    : cocircular_points(10, seed);
    const Mesh dt = delaunay(validate_points(xyz).xyz);
    for (uint32_t k = 2; k <= 4; ++k) {
      const KOrderStructure structure(dt, k, {});
      for (Objective o : minmax) {
        const std::string id = info(o).id;
        CAPTURE(seed);
        CAPTURE(k);
        CAPTURE(id);
        REQUIRE(branch_and_bound_applies(o, dt));
        double best = INFINITY;
        REQUIRE(enumerate_k_order(dt, k, 5'000'000, [&](const std::vector<Tri>& tris) {
          best = std::min(best, evaluate(o, mesh_of(dt.coords, tris)));
        }));
        // From the Delaunay value, and from the optimum itself (nothing better
        // to find); without the memo of searched partial fills and with it.
        for (const double known : {evaluate(o, dt), best})
          for (const uint64_t memo : {uint64_t{0}, uint64_t{1} << 20}) {
            CAPTURE(memo);
            const BranchAndBound b = branch_and_bound(dt, o, structure.candidates, known, 5'000'000, memo);
            REQUIRE(b.complete);
            CHECK(b.value == best);
            CHECK(b.found.has_value() == (best < known));
            if (b.found) {
              CHECK(is_k_order(*b.found, dt, k));
              CHECK(evaluate(o, *b.found) == b.value);
            }
            ++proven;
          }
      }
    }
  }
  CHECK(proven == 12 * 3 * 7 * 4);
  // Out of budget: nothing proven.
  const Mesh dt = delaunay(validate_points(uniform_points(40, 7)).xyz);
  const KOrderStructure structure(dt, 6, {});
  const BranchAndBound b = branch_and_bound(dt, Objective::MinmaxVertexNormalAngle, structure.candidates, INFINITY, 50, 1 << 20);
  CHECK(!b.complete);
}

// The search's backjumping and memo (fill_search.hpp) skip branches for reasons
// and twins: a reason that misses a triangle, or a memo key that misses what a
// term reads, loses the optimum on some instance. Many small ones where
// exhaustive enumeration is cheap, with ties (integer heights on grids,
// cocircular points) and near-degenerate ones, each searched from no value at
// all (the best improves all along, between a twin's store and its lookup),
// from the Delaunay value, and from just above the optimum (only the optimum
// is better).
TEST_CASE("the fill search's backjumping and memo keep the optimum (random, grids with ties, cocircular)") {
  const Objective minmax[] = {Objective::MinmaxEdgeAreaRatio,     Objective::MinmaxEdgeNormalAngle,
                              Objective::MinmaxEdgeEnclosingCircle, Objective::MinmaxVertexAreaRatio,
                              Objective::MinmaxVertexNormalAngle, Objective::MinmaxTriangleArea,
                              Objective::MinmaxDegree};
  int searched = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    std::vector<double> xyz;
    switch (seed % 5) {
      case 0: xyz = grid_points(4, 4, seed, true); break;
      case 1: xyz = uniform_points(11 + static_cast<int>(seed % 3), seed); break;
      case 2: xyz = cocircular_points(12, seed); break;
      case 3: xyz = grid_points(3, 5, seed, true); break;
      default: xyz = near_collinear_points(12, seed); break;
    }
    const Mesh dt = delaunay(validate_points(xyz).xyz);
    for (uint32_t k = 2; k <= 5; ++k) {
      const KOrderStructure structure(dt, k, {});
      for (Objective o : minmax) {
        const std::string id = info(o).id;
        CAPTURE(seed);
        CAPTURE(k);
        CAPTURE(id);
        if (!branch_and_bound_applies(o, dt)) continue;
        double best = INFINITY;
        REQUIRE(enumerate_k_order(dt, k, 5'000'000, [&](const std::vector<Tri>& tris) {
          best = std::min(best, evaluate(o, mesh_of(dt.coords, tris)));
        }));
        for (const double known : {double{INFINITY}, evaluate(o, dt), std::nextafter(best, double{INFINITY})})
          for (const uint64_t memo : {uint64_t{0}, uint64_t{1} << 20}) {
            CAPTURE(known);
            CAPTURE(memo);
            const BranchAndBound b = branch_and_bound(dt, o, structure.candidates, known, 5'000'000, memo);
            REQUIRE(b.complete);
            CHECK(b.value == best);
            REQUIRE(b.found.has_value() == (best < known));
            if (b.found) CHECK(evaluate(o, *b.found) == best);
            ++searched;
          }
      }
    }
  }
  CHECK(searched == 20 * 4 * 7 * 6);
}
