// Solves of other terrains from inside a solve's progress callback (the JS API
// allows it: only the terrain being solved is busy) give the answers they give
// alone, and leave the outer solve's answer unchanged: no solver keeps state
// between calls that a nested solve could overwrite.
#include <doctest/doctest.h>

#include <memory>
#include <vector>

#include "hodt/objectives.hpp"
#include "hodt/progress.hpp"
#include "hodt/solve.hpp"
#include "hodt/terrain.hpp"
#include "generators.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

Terrain terrain(int n, uint64_t seed, double max_edge) {
  Terrain t = Terrain::from_points(uniform_points(n, seed));
  if (max_edge < INFINITY) t.set_max_edge(max_edge);
  return t;
}

Solution solved(const Terrain& t, Objective o, uint32_t order, const Progress& progress = {}) {
  SolveOptions options;
  options.order = order;
  options.progress = progress;
  options.progress_interval_ms = 0;
  return solve(t.structure(), o, options);
}

}  // namespace

TEST_CASE("solves nested in another solve's progress callback answer as they do alone") {
  for (uint32_t order : {1u, 2u})
    for (double max_edge : {static_cast<double>(INFINITY), 0.08}) {
      const Terrain outer = terrain(120, 7, max_edge);
      const Terrain inner = terrain(60, 11, max_edge);
      std::vector<double> alone;
      for (const auto& info : objectives()) alone.push_back(solved(inner, info.objective, order).value);
      for (const auto& info : objectives()) {
        CAPTURE(order);
        CAPTURE(max_edge);
        CAPTURE(info.id);
        const double expected = solved(outer, info.objective, order).value;
        int calls = 0;
        const Solution s = solved(outer, info.objective, order, [&](double, double) {
          if (++calls > 3) return true;
          for (const auto& other : objectives())
            CHECK(solved(inner, other.objective, order).value == alone[static_cast<size_t>(other.objective)]);
          return true;
        });
        CHECK(s.value == expected);
      }
    }
}

TEST_CASE("terrains made, measured, solved and freed inside a solve's progress callback, as the JS API does") {
  auto points = [](int n, uint64_t seed) {
    std::vector<double> p = uniform_points(n, seed);
    for (double& c : p) c *= 100;
    return p;
  };
  for (const auto& a : objectives()) {
    CAPTURE(a.id);
    const Terrain outer = Terrain::from_points(points(400, 7));
    int calls = 0;
    SolveOptions options;
    options.progress = phased([&](const ProgressPoint&) {
      if (++calls > 5) return true;
      for (const auto& b : objectives()) {
        const auto inner = std::make_unique<Terrain>(Terrain::from_points(points(300, 11 + calls)));
        SolveOptions o;
        o.progress = phased([](const ProgressPoint&) { return true; });
        inner->delaunay_value(b.objective, o.progress);
        solve(inner->structure(), b.objective, o);
      }
      return true;
    });
    outer.delaunay_value(a.objective, options.progress);
    const Solution s = solve(outer.structure(), a.objective, options);
    SolveOptions plain;
    CHECK(s.value == solve(Terrain::from_points(points(400, 7)).structure(), a.objective, plain).value);
  }
}
