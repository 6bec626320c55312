// Approximation schemes: the guarantee and the certified bound, against the optimum
// (brute force on small instances, the exact engine on jittered grids).
#include <doctest/doctest.h>

#include "hodt/brute_force.hpp"
#include "hodt/delaunay.hpp"
#include "hodt/error.hpp"
#include "hodt/points.hpp"
#include "hodt/solve.hpp"
#include "approx/approx.hpp"
#include "approx/baker.hpp"
#include "engines/roof_dual.hpp"
#include "generators.hpp"
#include "exact/factor_models.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

uint32_t interior(const FirstOrder& fo) { return fo.base.num_vertices() - static_cast<uint32_t>(fo.base.hull.size()); }

void check_approx(const FirstOrder& fo, Objective o, double opt, double eps) {
  SolveOptions options;
  options.method = Method::Approx;
  options.epsilon = eps;
  const Solution s = solve(fo, o, options);
  REQUIRE(s.bound);
  CHECK(s.value == evaluate(o, triangulate(fo, s.choice)));
  switch (o) {
    case Objective::MaxConvexEdges:
      CHECK(s.value >= (1 - eps) * opt - 1e-9);
      CHECK(s.value <= opt);
      CHECK(*s.bound >= opt);
      break;
    case Objective::MinMixedVertices: {
      const double n = interior(fo);
      CHECK(n - s.value >= (1 - eps) * (n - opt) - 1e-9);  // non-mixed within (1 - eps)
      CHECK(s.value >= opt);
      CHECK(*s.bound <= opt);
      break;
    }
    case Objective::MinmaxDegree:
      CHECK(s.value >= opt);
      CHECK(*s.bound <= opt);
      CHECK(s.value <= 2 * *s.bound);
      break;
    default:
      break;
  }
}

}  // namespace

TEST_CASE("approximations on small instances: guarantee and bound against brute force") {
  int done = 0;
  for (uint64_t seed = 1; done < 1000; ++seed) {
    Rng r(seed);
    const int n = 8 + r.below(10);
    const std::vector<double> p = seed % 3 == 0 ? uniform_points(n, seed) : seed % 3 == 1 ? dem_points(n, seed) : jittered_grid(4, 3 + r.below(2), 0.3, seed);
    const FirstOrder fo = first_order(delaunay(validate_points(p).xyz));
    if (fo.num_quads() > 10) continue;
    ++done;
    for (Objective o : {Objective::MaxConvexEdges, Objective::MinMixedVertices, Objective::MinmaxDegree}) {
      const double opt = brute_force(fo, o).value;
      for (double eps : {0.5, 0.34, 0.25}) check_approx(fo, o, opt, eps);
    }
  }
}

TEST_CASE("approximations on jittered grids against the exact engine") {
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    const FirstOrder fo = first_order(delaunay(jittered_grid(14, 12, 0.35, seed)));
    for (Objective o : {Objective::MaxConvexEdges, Objective::MinMixedVertices, Objective::MinmaxDegree}) {
      SolveOptions exact;
      exact.method = Method::Exact;
      const double opt = solve(fo, o, exact).value;
      for (double eps : {0.5, 0.34, 0.25}) check_approx(fo, o, opt, eps);
    }
  }
}

TEST_CASE("auto runs exact when it fits, else approx, and says which") {
  const FirstOrder fo = first_order(delaunay(uniform_points(2000, 3)));
  SolveOptions options;
  options.method = Method::Auto;
  const Solution s = solve(fo, Objective::MaxConvexEdges, options);
  CHECK(s.method == "exact");
  CHECK(s.optimal);
  // A component too wide for exact, approximated. (The paper's hardness surface,
  // the saddle grid, is exact now: the roof dual fixes every quad of it.)
  CHECK(solve(first_order(delaunay(saddle_grid(24))), Objective::MaxConvexEdges, SolveOptions{}).optimal);
  const FirstOrder grid = first_order(delaunay(frustrated_raster()));
  SolveOptions exact;
  exact.method = Method::Exact;
  CHECK_THROWS_WITH_AS(solve(grid, Objective::MaxConvexEdges, exact), doctest::Contains("tree decomposition of width"), LimitError);
  const Solution a = solve(grid, Objective::MaxConvexEdges, options);
  CHECK(a.method == "approx");
  CHECK(a.details.find("exact refused") != std::string::npos);
  REQUIRE(a.bound);
  CHECK(a.value <= *a.bound);
  CHECK(a.value >= (1 - options.epsilon) * *a.bound);  // the bound is within the guarantee
  // The scheme ran on the quads the roof dual left free: its bound is at most
  // the roof dual's.
  const FactorGraph g = factor_model(grid, Objective::MaxConvexEdges);
  const RoofDual rd = roof_dual(g);
  CHECK(*a.bound <= rd.bound);
  CHECK(a.details.find("the roof dual fixed " + std::to_string(rd.num_fixed) + " of ") != std::string::npos);
}

TEST_CASE("long runs report progress and can be cancelled") {
  const FirstOrder grid = first_order(delaunay(saddle_grid(30)));
  SolveOptions options;
  options.method = Method::Approx;
  int calls = 0;
  options.progress = [&](double done, double total) {
    ++calls;
    CHECK(done <= total);
    return true;
  };
  solve(grid, Objective::MaxConvexEdges, options);
  CHECK(calls > 0);
  options.progress = [](double, double) { return false; };
  CHECK_THROWS_AS(solve(grid, Objective::MaxConvexEdges, options), Cancelled);
  options.method = Method::Exact;
  const FirstOrder random = first_order(delaunay(uniform_points(3000, 5)));
  CHECK_THROWS_AS(solve(random, Objective::MinMixedVertices, options), Cancelled);
}

TEST_CASE("baker lends its graph's factors to each shift and returns them, also when a shift throws") {
  const FirstOrder fo = first_order(delaunay(jittered_grid(12, 12, 0.35, 5)));
  FactorGraph g = factor_model(fo, Objective::MaxConvexEdges);
  const FactorGraph before = g;
  auto same = [&] {
    REQUIRE(g.factors.size() == before.factors.size());
    for (size_t k = 0; k < g.factors.size(); ++k) {
      CHECK(g.factors[k].scope == before.factors[k].scope);
      CHECK(g.factors[k].table == before.factors[k].table);
    }
  };
  const std::vector<uint32_t> layer = quad_layers(fo);
  const BakerResult r = baker(g, layer, 0.5, DpLimits{});
  CHECK(r.shifts.size() == r.lambda);
  same();
  DpLimits narrow;
  narrow.max_width = 0;  // every thick layer is wider: the first shift throws
  CHECK_THROWS_AS(baker(g, layer, 0.5, narrow), LimitError);
  same();
}
