// Tree decompositions from elimination orders (min-degree, min-fill): every
// factor inside a bag, every bag's separator inside its parent's bag (what the DP
// relies on), and min-fill where min-degree is too wide.
#include <doctest/doctest.h>

#include <algorithm>

#include "hodt/delaunay.hpp"
#include "hodt/solve.hpp"
#include "engines/roof_dual.hpp"
#include "generators.hpp"
#include "exact/factor_models.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

// The properties of a complete decomposition of g.
void check_decomposition(const FactorGraph& g, const Decomposition& d) {
  REQUIRE(d.complete);
  REQUIRE(d.order.size() == g.num_vars);
  std::vector<uint32_t> position(g.num_vars, UINT32_MAX);
  for (uint32_t i = 0; i < d.order.size(); ++i) position[d.order[i]] = i;
  for (uint32_t v = 0; v < g.num_vars; ++v) REQUIRE(position[v] != UINT32_MAX);
  auto in = [](const std::vector<uint32_t>& bag, uint32_t v) { return std::find(bag.begin(), bag.end(), v) != bag.end(); };
  uint32_t width = 0;
  for (uint32_t i = 0; i < d.bags.size(); ++i) {
    const std::vector<uint32_t>& bag = d.bags[i];
    CHECK(bag[0] == d.order[i]);
    width = std::max(width, static_cast<uint32_t>(bag.size() - 1));
    uint32_t parent = UINT32_MAX;
    for (size_t j = 1; j < bag.size(); ++j) {
      CHECK(position[bag[j]] > i);  // later neighbours only
      parent = std::min(parent, position[bag[j]]);
    }
    if (parent == UINT32_MAX) continue;
    for (size_t j = 1; j < bag.size(); ++j) CHECK(in(d.bags[parent], bag[j]));
  }
  CHECK(d.width == width);
  for (const Factor& f : g.factors) {
    if (f.scope.empty()) continue;
    uint32_t first = f.scope[0];
    for (uint32_t v : f.scope)
      if (position[v] < position[first]) first = v;
    for (uint32_t v : f.scope) CHECK(in(d.bags[position[first]], v));
  }
}

}  // namespace

TEST_CASE("decompose: min-degree and min-fill orders are tree decompositions") {
  for (uint64_t seed = 1; seed <= 300; ++seed) {
    Rng r(seed);
    FactorGraph g;
    g.num_vars = 1 + static_cast<uint32_t>(r.below(40));
    const int terms = r.below(3 * static_cast<int>(g.num_vars));
    for (int k = 0; k < terms; ++k) {
      Factor f;
      const int scope = 1 + r.below(4);
      for (int j = 0; j < scope; ++j) {
        const uint32_t v = static_cast<uint32_t>(r.below(static_cast<int>(g.num_vars)));
        if (std::find(f.scope.begin(), f.scope.end(), v) == f.scope.end()) f.scope.push_back(v);
      }
      f.table.assign(size_t(1) << f.scope.size(), 0.0);
      g.factors.push_back(std::move(f));
    }
    INFO("seed " << seed);
    for (Elimination e : {Elimination::MinDegree, Elimination::MinFill, Elimination::Auto})
      check_decomposition(g, decompose(g, UINT32_MAX, {}, e));
  }
}

TEST_CASE("decompose: min-fill where min-degree is too wide, and exact then answers") {
  // A smooth raster's window whose free quads (after the roof dual) have
  // min-degree width 22 and min-fill width 17.
  const FirstOrder fo = first_order(delaunay(frustrated_raster(61, 90, 255, 316)));
  ReducedModel m = reduce_by_roof_dual(factor_model(fo, Objective::MaxConvexEdges));
  const FactorGraph& g = m.graph();
  CHECK_FALSE(decompose(g, 20, {}, Elimination::MinDegree).complete);
  const Decomposition d = decompose(g, 20);
  check_decomposition(g, d);
  CHECK(d.width <= 20);
  SolveOptions exact;
  exact.method = Method::Exact;
  const Solution s = solve(fo, Objective::MaxConvexEdges, exact);
  CHECK(s.optimal);
  CHECK(s.value <= m.roof->bound);
  SolveOptions approx;
  approx.method = Method::Approx;
  const Solution a = solve(fo, Objective::MaxConvexEdges, approx);
  CHECK(s.value >= a.value);
  CHECK(s.value <= *a.bound);
}
