// The threshold SAT search (min-max objectives) against the k-OD enumerator's
// exhaustive optimum: a search that ends with "no" proves exactly that value,
// from any value in hand; each triangulation it answers with is a k-OD
// triangulation of its value.
#include <doctest/doctest.h>

#include "hodt/delaunay.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/points.hpp"
#include "generators.hpp"
#include "higher_order/k_order.hpp"
#include "higher_order/search/threshold_sat.hpp"
#include "mesh/mesh_of.hpp"
#include "higher_order/regions/region_engine.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

const Objective kMinmax[] = {Objective::MinmaxEdgeAreaRatio,       Objective::MinmaxEdgeNormalAngle,
                             Objective::MinmaxEdgeEnclosingCircle, Objective::MinmaxVertexAreaRatio,
                             Objective::MinmaxVertexNormalAngle,   Objective::MinmaxTriangleArea,
                             Objective::MinmaxDegree};

double exhaustive_optimum(const Mesh& dt, uint32_t k, Objective o) {
  double best = INFINITY;
  REQUIRE(enumerate_k_order(dt, k, 5'000'000, [&](const std::vector<Tri>& tris) {
    best = std::min(best, evaluate(o, mesh_of(dt.coords, tris)));
  }));
  return best;
}

}  // namespace

// The clauses must admit every triangulation (else "no" is a false proof) and
// admit nothing else (else a model is no triangulation): instances with ties
// (integer heights on grids, cocircular points, near-collinear points) where
// enumeration is cheap, asked from no value at all (every question of the
// descent), from the Delaunay value, from just above the optimum (only the
// optimum is better) and from the optimum itself (nothing is).
TEST_CASE("threshold SAT equals exhaustive enumeration (min-max, orders 2 to 5, ties included)") {
  int searched = 0;
  for (uint64_t seed = 1; seed <= 30; ++seed) {
    std::vector<double> xyz;
    switch (seed % 6) {
      case 0: xyz = grid_points(seed % 4 ? 3 : 4, 4, seed, true); break;
      case 1: xyz = uniform_points(10 + static_cast<int>(seed % 4), seed); break;
      case 2: xyz = cocircular_points(10 + static_cast<int>(seed % 3), seed); break;
      case 3: xyz = grid_points(3, 5, seed, true); break;
      case 4: xyz = near_collinear_points(12, seed); break;
      default: xyz = uniform_points(12, seed); break;
    }
    const Mesh dt = delaunay(validate_points(xyz).xyz);
    for (uint32_t k = 2; k <= 5; ++k) {
      const KOrderStructure structure(dt, k, {});
      for (Objective o : kMinmax) {
        const std::string id = info(o).id;
        CAPTURE(seed);
        CAPTURE(k);
        CAPTURE(id);
        REQUIRE(threshold_sat_applies(o, dt));
        const double best = exhaustive_optimum(dt, k, o);
        for (const double known : {double{INFINITY}, evaluate(o, dt), std::nextafter(best, double{INFINITY}), best}) {
          CAPTURE(known);
          const ThresholdSat s = threshold_sat(dt, o, structure.candidates, known, 10'000'000, UINT64_MAX);
          REQUIRE(s.complete);
          CHECK(s.value == best);
          REQUIRE(s.found.has_value() == (best < known));
          if (s.found) {
            CHECK(is_k_order(*s.found, dt, k));
            CHECK(evaluate(o, *s.found) == s.value);
          }
          ++searched;
        }
      }
    }
  }
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
