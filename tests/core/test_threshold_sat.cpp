// The threshold SAT search (min-max objectives) against the k-OD enumerator's
// exhaustive optimum: a search that ends with "no" proves exactly that value,
// from any value in hand; each triangulation it answers with is a k-OD
// triangulation of its value.
#include <doctest/doctest.h>

#include "hodt/delaunay.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/points.hpp"
#include "generators.hpp"
#include "k_order_reference.hpp"
#include "higher_order/k_order.hpp"
#include "higher_order/search/threshold_sat.hpp"
#include "mesh/mesh_of.hpp"
#include "higher_order/regions/region_engine.hpp"

using namespace hodt;
using namespace hodt::test;

// The clauses must admit every triangulation (else "no" is a false proof) and
// admit nothing else (else a model is no triangulation): instances with ties
// (integer heights on grids, cocircular points, near-collinear points) where
// enumeration is cheap, asked from no value at all (every question of the
// descent), from the Delaunay value, from just above the optimum (only the
// optimum is better) and from the optimum itself (nothing is).
TEST_CASE("threshold SAT equals exhaustive enumeration (min-max, orders 2 to 5, ties included)") {
  const int searched = for_fill_search_cases([](const Mesh& dt, uint32_t k, const KOrderStructure& structure,
                                                  Objective o, double best, double known) {
    REQUIRE(threshold_sat_applies(o, dt));
    const ThresholdSat s = threshold_sat(dt, o, structure.candidates, known, 10'000'000, UINT64_MAX);
    REQUIRE(s.complete);
    CHECK(s.value == best);
    REQUIRE(s.found.has_value() == (best < known));
    if (s.found) {
      CHECK(is_k_order(*s.found, dt, k));
      CHECK(evaluate(o, *s.found) == s.value);
    }
  });
  CHECK(searched == 30 * 4 * 7 * 4);
}

// Out of either budget: nothing proven, and what was found is still a k-OD
// triangulation of its value.
TEST_CASE("threshold SAT out of its conflicts or its work proves nothing") {
  const Mesh dt = delaunay(validate_points(uniform_points(60, 7)).xyz);
  const KOrderStructure structure(dt, 6, {});
  const ThresholdSat s = threshold_sat(dt, Objective::MinmaxVertexNormalAngle, structure.candidates, INFINITY, 1, UINT64_MAX);
  CHECK(!s.complete);
  const ThresholdSat w = threshold_sat(dt, Objective::MinmaxVertexNormalAngle, structure.candidates, INFINITY, UINT64_MAX, 100);
  if (s.found) CHECK(is_k_order(*s.found, dt, 6));
  CHECK(!w.complete);
  if (w.found) CHECK(is_k_order(*w.found, dt, 6));
}

// The work budget holds over every question: the clauses a question adds
// propagate too, and the next question gets only what is left (a budget that
// wrapped around would run it unbounded). So: budgets just above where each
// question starts (found by bisection on how many questions a budget asks),
// where the new clauses' propagation alone reaches the budget.
TEST_CASE("threshold SAT keeps to its work budget across questions") {
  const Mesh dt = delaunay(validate_points(uniform_points(300, 7)).xyz);
  const KOrderStructure structure(dt, 5, {});
  const auto search = [&](uint64_t max_work) {
    return threshold_sat(dt, Objective::MinmaxTriangleArea, structure.candidates, INFINITY, UINT64_MAX, max_work);
  };
  const ThresholdSat whole = search(UINT64_MAX);
  REQUIRE(whole.complete);
  REQUIRE(whole.questions > 2);
  uint64_t worst = 0;
  for (uint32_t j = 2; j <= whole.questions; ++j) {
    uint64_t lo = 1, hi = whole.work;  // the least budget with question j attempted
    while (lo < hi) {
      const uint64_t mid = lo + (hi - lo) / 2;
      if (search(mid).questions >= j) hi = mid;
      else lo = mid + 1;
    }
    for (uint64_t budget = lo > 16 ? lo - 16 : 1; budget <= lo + 16; ++budget) {
      const ThresholdSat s = search(budget);
      worst = std::max(worst, s.work > budget ? s.work - budget : 0);
    }
  }
  MESSAGE("worst overrun " << worst << " of a whole search's " << whole.work);
  CHECK(worst < whole.work / 32);
}
