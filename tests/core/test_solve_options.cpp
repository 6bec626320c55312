// Solve options are checked in one place (check_options) for every order and every
// front end: epsilon, order, method; and every method means something at order k.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>

#include "hodt/delaunay.hpp"
#include "hodt/error.hpp"
#include "hodt/points.hpp"
#include "hodt/solve.hpp"
#include "hodt/solve_options.hpp"
#include "generators.hpp"
#include "engines/factor_graph.hpp"
#include "higher_order/k_order.hpp"
#include "higher_order/regions/regions.hpp"
#include "tuning/budgets.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

std::string error_of(const SolveOptions& options) {
  try {
    check_options(options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("epsilon must be a number in (0, 1), at every order") {
  const double inf = std::numeric_limits<double>::infinity();
  for (uint32_t order : {1u, 2u, 16u})
    for (auto [epsilon, shown] : {std::pair{2.0, "2"}, {-1.0, "-1"}, {0.0, "0"}, {1.0, "1"}, {inf, "Infinity"},
                                  {-inf, "-Infinity"}, {std::nan(""), "NaN"}, {std::strtod("1e309", nullptr), "Infinity"}}) {
      SolveOptions options;
      options.order = order;
      options.epsilon = epsilon;
      CAPTURE(order);
      CHECK(error_of(options) == std::string("epsilon is ") + shown + ", expected a number in (0, 1)");
    }
  SolveOptions fine;
  fine.epsilon = 0.5;
  fine.order = 3;
  CHECK(error_of(fine) == "");
}

TEST_CASE("orders from kMinOrder to kMaxOrder, every method at every order") {
  SolveOptions options;
  options.order = 0;
  CHECK(error_of(options) == "order is 0, expected an integer from 1 to 16");
  options.order = kMaxOrder + 1;
  CHECK(error_of(options) == "order is 17, expected an integer from 1 to 16");
  for (Method m : {Method::BruteForce, Method::Exact, Method::Approx, Method::Auto})
    for (uint32_t order : {kMinOrder, 2u, kMaxOrder}) {
      options.method = m;
      options.order = order;
      CHECK(error_of(options) == "");
    }
  options.method = static_cast<Method>(7);
  CHECK(error_of(options) == "method is 7, expected brute-force, exact, approx, auto");
  CHECK(order_from_number(3) == 3);
  for (double k : {0.0, 17.0, 1.5, std::nan(""), -1.0})
    CHECK_THROWS_WITH_AS(order_from_number(k), doctest::Contains("expected an integer from 1 to 16"), InputError);
}

TEST_CASE("every solver checks the options: solve() and k_order_solution()") {
  const FirstOrder fo = first_order(delaunay(uniform_points(12, 3)));
  SolveOptions options;
  options.epsilon = std::nan("");
  CHECK_THROWS_WITH_AS(solve(fo, Objective::MinLocalMinima, options), "epsilon is NaN, expected a number in (0, 1)",
                       InputError);
  CHECK_THROWS_WITH_AS(k_order_solution(fo, Objective::MinLocalMinima, 2, options),
                       "epsilon is NaN, expected a number in (0, 1)", InputError);
  options.order = 2;
  CHECK_THROWS_AS(solve(fo, Objective::MinLocalMinima, options), InputError);
  CHECK_THROWS_WITH_AS(k_order_solution(fo, Objective::MinLocalMinima, 0, SolveOptions{}),
                       "order is 0, expected an integer from 1 to 16", InputError);
}

TEST_CASE("solve() at order k is the k-th order solver") {
  const FirstOrder fo = first_order(delaunay(uniform_points(12, 3)));
  SolveOptions options;
  options.order = 2;
  const Solution s = solve(fo, Objective::MinLocalMinima, options);
  const Solution k = k_order_solution(fo, Objective::MinLocalMinima, 2, SolveOptions{});
  CHECK(s.order == 2);
  CHECK(s.method == k.method);
  CHECK(s.value == k.value);
  REQUIRE(s.mesh);
  CHECK(s.mesh->triangles == k.mesh->triangles);
}

TEST_CASE("every method at order k: brute force enumerates or refuses, exact runs the region DP, approx is the heuristic (exact when its bound proves it)") {
  const FirstOrder small = first_order(delaunay(uniform_points(12, 3)));
  SolveOptions options;
  for (uint32_t k : {2u, 3u}) {
    options.order = k;
    options.method = Method::Auto;
    const Solution a = solve(small, Objective::MaxConvexEdges, options);
    REQUIRE(a.method == "exact");
    for (Method m : {Method::BruteForce, Method::Exact}) {
      options.method = m;
      const Solution s = solve(small, Objective::MaxConvexEdges, options);
      CHECK(s.method == (m == Method::BruteForce ? "brute-force" : "exact"));
      CHECK(s.optimal);
      if (m == Method::BruteForce) CHECK(s.details.find("triangulations enumerated") != std::string::npos);
      CHECK(s.value == a.value);
    }
    options.method = Method::Approx;
    const Solution h = solve(small, Objective::MaxConvexEdges, options);
    CHECK(h.method == (h.optimal ? "exact" : "heuristic"));
    CHECK(h.value <= a.value);
  }
  const FirstOrder large = first_order(delaunay(uniform_points(200, 3)));
  options.order = 2;
  options.method = Method::BruteForce;
  CHECK_THROWS_WITH_AS(solve(large, Objective::MinLocalMinima, options),
                       doctest::Contains("brute force at order 2 enumerates every k-OD triangulation and refuses 200 "
                                         "points (at most 30)"),
                       LimitError);
  // Exact and auto: the DP over the regions; approx: the heuristic, never better.
  options.method = Method::Exact;
  const Solution e = solve(large, Objective::MinLocalMinima, options);
  CHECK(e.method == "exact");
  CHECK(e.optimal);
  options.method = Method::Auto;
  CHECK(solve(large, Objective::MinLocalMinima, options).method == "exact");
  options.method = Method::Approx;
  const Solution h = solve(large, Objective::MinLocalMinima, options);
  CHECK(h.method == (h.optimal ? "exact" : "heuristic"));
  CHECK(h.value >= e.value);
}

// The public options' default width is the engine's budget, and the engines'
// limits start from the budgets (tuning/budgets.hpp): one place to change them.
TEST_CASE("the options and the engines' limits take their defaults from the budgets") {
  CHECK(SolveOptions{}.max_width == kBudgets.dp_max_width);
  CHECK(DpLimits{}.max_width == kBudgets.dp_max_width);
  CHECK(DpLimits{}.max_term_scope == kBudgets.dp_max_term_scope);
  CHECK(RegionLimits{}.max_nodes_per_region == kBudgets.region_max_nodes);
  CHECK(RegionLimits{}.first_pass_states == kBudgets.region_first_pass_states);
}
