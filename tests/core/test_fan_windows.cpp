// Descent by windows (fan_windows.hpp) against brute force: one window over
// every vertex is a branch and bound over all agreeing fans, so it reaches the
// optimum; small windows with tiny step budgets give k-OD triangulations no
// worse than their start.
#include <doctest/doctest.h>

#include <cmath>

#include "hodt/delaunay.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/points.hpp"
#include "generators.hpp"
#include "higher_order/k_order.hpp"
#include "mesh/mesh_of.hpp"
#include "higher_order/regions/region_engine.hpp"
#include "higher_order/search/fan_windows.hpp"
#include "k_order_reference.hpp"
#include "objectives/objective_terms.hpp"

using namespace hodt;
using namespace hodt::test;

TEST_CASE("fan windows: one window over everything equals brute force, small ones never worse (k = 2 to 4)") {
  int whole = 0, small = 0, moved = 0, stopped = 0;
  for_small_k_instances({2u, 3u, 4u}, 150, 29, [&](uint32_t k, uint64_t seed, const FirstOrder& fo, const KOrderStructure& structure) {
    const Mesh& dt = fo.base;
    for (const auto& oi : objectives()) {
      if (objective_terms(oi.objective, dt).combine != Combine::Sum) continue;
      const double delaunay_value = evaluate(oi.objective, dt);
      const double want = k_order_brute_force(fo, oi.objective, k, 20'000'000).value;
      CAPTURE(k);
      CAPTURE(seed);
      CAPTURE(std::string(oi.id));
      // Small windows first: each result is a start for the next.
      Mesh start = dt;
      double at = delaunay_value;
      for (const auto [per_window, steps] : {std::pair{4u, 1'000u}, std::pair{9u, 3u}}) {
        WindowLimits limits;
        limits.per_window = per_window, limits.max_steps = steps;
        const auto part = improve_by_windows(dt, oi.objective, structure.candidates, start, limits);
        if (!part) continue;
        ++small;
        REQUIRE(part->size() == dt.num_triangles());
        Mesh m = mesh_of(dt.coords, *part);
        CHECK(is_k_order(m, dt, k));
        const double v = evaluate(oi.objective, m);
        CHECK(better(oi.sense, v, at));
        CHECK(!better(oi.sense, v, want));
        // Asked for a gain of one unit only, the same windows stop at the first
        // that gains it: part of the way.
        limits.enough = 1;
        if (oi.objective != Objective::MinTotalEdgeLength) {
          const auto first = improve_by_windows(dt, oi.objective, structure.candidates, start, limits);
          REQUIRE(first);
          const double u = evaluate(oi.objective, mesh_of(dt.coords, *first));
          CHECK(std::fabs(u - at) >= 1);
          CHECK(std::fabs(u - at) <= std::fabs(v - at));
          stopped += u != v;
        }
        start = std::move(m), at = v;
      }
      moved += at != delaunay_value;
      WindowLimits all;
      all.per_window = 1u << 30, all.max_steps = 100'000'000;
      const auto best = improve_by_windows(dt, oi.objective, structure.candidates, start, all);
      const double got = best ? evaluate(oi.objective, mesh_of(dt.coords, *best)) : at;
      if (best) CHECK(is_k_order(mesh_of(dt.coords, *best), dt, k));
      if (oi.objective == Objective::MinTotalEdgeLength) CHECK(std::fabs(got - want) <= 1e-9 * want);
      else CHECK(got == want);
      ++whole;
    }
  });
  MESSAGE(whole << " windows over everything, " << small << " small descents that improved, " << moved
                << " starts not Delaunay, " << stopped << " stopped short by `enough`");
  CHECK(whole > 1000);
  CHECK(small > 200);
  CHECK(stopped > 10);  // (17 when written)
}
