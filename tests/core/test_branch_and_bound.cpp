// Branch and bound over every fill (min-max objectives) against the k-OD
// enumerator's exhaustive optimum: a complete search proves exactly that value,
// from any value in hand; what it finds is a k-OD triangulation of that value.
#include <doctest/doctest.h>

#include "hodt/delaunay.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/points.hpp"
#include "generators.hpp"
#include "k_order_reference.hpp"
#include "higher_order/k_order.hpp"
#include "mesh/mesh_of.hpp"
#include "higher_order/regions/region_engine.hpp"
#include "higher_order/search/branch_and_bound.hpp"

using namespace hodt;
using namespace hodt::test;

// The search's backjumping and memo (fill_search.hpp) skip branches for reasons
// and twins: a reason that misses a triangle, or a memo key that misses what a
// term reads, loses the optimum on some instance. So: many small instances
// where exhaustive enumeration is cheap, with ties (integer heights on grids,
// cocircular points) and near-degenerate ones, each searched with the memo and
// without, from no value at all (the best improves all along, between a twin's
// store and its lookup), from the Delaunay value, from just above the optimum
// (only the optimum is better) and from the optimum itself (nothing is).
TEST_CASE("branch and bound over every fill equals exhaustive enumeration (min-max, orders 2 to 5, ties included)") {
  const int searched = for_fill_search_cases([](const Mesh& dt, uint32_t k, const KOrderStructure& structure,
                                                  Objective o, double best, double known) {
    REQUIRE(branch_and_bound_applies(o, dt));
    for (const uint64_t memo : {uint64_t{0}, uint64_t{1} << 20}) {
      CAPTURE(memo);
      const BranchAndBound b = branch_and_bound(dt, o, structure.candidates, known, 5'000'000, memo);
      REQUIRE(b.complete);
      CHECK(b.value == best);
      REQUIRE(b.found.has_value() == (best < known));
      if (b.found) {
        CHECK(is_k_order(*b.found, dt, k));
        CHECK(evaluate(o, *b.found) == b.value);
      }
    }
  });
  CHECK(searched == 30 * 4 * 7 * 4);
  // Out of budget: nothing proven.
  const Mesh dt = delaunay(validate_points(uniform_points(40, 7)).xyz);
  const KOrderStructure structure(dt, 6, {});
  const BranchAndBound b = branch_and_bound(dt, Objective::MinmaxVertexNormalAngle, structure.candidates, INFINITY, 50, 1 << 20);
  CHECK(!b.complete);
}
