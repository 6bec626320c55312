// The maximum flow against the minimum cut over every subset, and the roof
// dual's bound and persistent assignment against exhaustive search.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "hodt/delaunay.hpp"
#include "hodt/solve.hpp"
#include "engines/max_flow.hpp"
#include "engines/roof_dual.hpp"
#include "generators.hpp"
#include "exact/factor_models.hpp"

using namespace hodt;
using namespace hodt::test;

TEST_CASE("max flow: the minimum cut over every subset, and a feasible flow") {
  for (uint64_t seed = 1; seed <= 2000; ++seed) {
    Rng r(seed);
    const uint32_t n = 1 + static_cast<uint32_t>(r.below(10));
    std::vector<int64_t> from_source(n), to_sink(n);
    struct E { uint32_t u, v; int64_t cap; };
    std::vector<E> edges;
    MaxFlow f(n);
    for (uint32_t v = 0; v < n; ++v) {
      from_source[v] = r.below(3) ? 0 : r.below(6);
      to_sink[v] = r.below(3) ? 0 : r.below(6);
      f.add_terminal(v, from_source[v], to_sink[v]);
    }
    // Paths (long augmenting paths, orphans re-adopted) and random arcs.
    const bool chain = seed % 4 == 0;
    const uint32_t m = static_cast<uint32_t>(r.below(3 * static_cast<int>(n) + 1));
    for (uint32_t k = 0; k < (chain ? n - 1 : m); ++k) {
      const uint32_t u = chain ? k : static_cast<uint32_t>(r.below(static_cast<int>(n)));
      const uint32_t v = chain ? k + 1 : static_cast<uint32_t>(r.below(static_cast<int>(n)));
      if (u == v) continue;
      edges.push_back({u, v, r.below(7)});
      f.add_edge(u, v, edges.back().cap);
    }
    const int64_t flow = f.solve();
    int64_t cut = INT64_MAX;
    for (uint32_t side = 0; side < (1u << n); ++side) {  // bit v: v on the sink side
      int64_t c = 0;
      for (uint32_t v = 0; v < n; ++v) c += (side >> v) & 1 ? from_source[v] : to_sink[v];
      for (const E& e : edges) c += !((side >> e.u) & 1) && ((side >> e.v) & 1) ? e.cap : 0;
      cut = std::min(cut, c);
    }
    REQUIRE_MESSAGE(flow == cut, "seed " << seed);
    // Conservation and capacities (terminal flows are net of s -> v -> t).
    std::vector<int64_t> net(n, 0);
    int64_t out_of_source = 0;
    for (uint32_t v = 0; v < n; ++v) {
      const int64_t t = f.terminal_flow(v);
      CHECK(t <= from_source[v]);
      CHECK(-t <= to_sink[v]);
      net[v] += t;
      out_of_source += std::min(from_source[v], to_sink[v]) + std::max<int64_t>(t, 0);
    }
    for (uint32_t k = 0; k < edges.size(); ++k) {
      const int64_t x = f.edge_flow(k);
      CHECK(x >= 0);
      CHECK(x <= edges[k].cap);
      net[edges[k].u] -= x, net[edges[k].v] += x;
    }
    for (uint32_t v = 0; v < n; ++v) CHECK(net[v] == 0);
    CHECK(out_of_source == flow);
  }
}

// Edmonds and Karp's shortest augmenting paths on a dense matrix: the reference
// for graphs too large to enumerate their cuts.
int64_t reference_max_flow(std::vector<std::vector<int64_t>> cap, uint32_t s, uint32_t t) {
  const size_t n = cap.size();
  int64_t flow = 0;
  for (;;) {
    std::vector<int64_t> from(n, -1);
    std::vector<size_t> queue{s};
    from[s] = s;
    for (size_t h = 0; h < queue.size() && from[t] < 0; ++h)
      for (size_t v = 0; v < n; ++v)
        if (from[v] < 0 && cap[queue[h]][v] > 0) from[v] = static_cast<int64_t>(queue[h]), queue.push_back(v);
    if (from[t] < 0) return flow;
    int64_t push = INT64_MAX;
    for (size_t v = t; v != s; v = static_cast<size_t>(from[v])) push = std::min(push, cap[static_cast<size_t>(from[v])][v]);
    for (size_t v = t; v != s; v = static_cast<size_t>(from[v]))
      cap[static_cast<size_t>(from[v])][v] -= push, cap[v][static_cast<size_t>(from[v])] += push;
    flow += push;
  }
}

TEST_CASE("max flow: grids of up to 144 nodes, against shortest augmenting paths") {
  for (uint64_t seed = 1; seed <= 400; ++seed) {
    Rng r(seed);
    const uint32_t w = 2 + static_cast<uint32_t>(r.below(11)), h = 2 + static_cast<uint32_t>(r.below(11)), n = w * h;
    std::vector<std::vector<int64_t>> cap(n + 2, std::vector<int64_t>(n + 2, 0));  // n: source, n + 1: sink
    MaxFlow f(n);
    for (uint32_t v = 0; v < n; ++v) {
      const int64_t a = r.below(4) ? 0 : r.below(9), b = r.below(4) ? 0 : r.below(9);
      f.add_terminal(v, a, b);
      cap[n][v] += a, cap[v][n + 1] += b;
      for (uint32_t u : {v + 1, v + w}) {
        if ((u == v + 1 && (v + 1) % w == 0) || u >= n) continue;
        const int64_t c = r.below(5), d = r.below(5);
        f.add_edge(v, u, c), f.add_edge(u, v, d);
        cap[v][u] += c, cap[u][v] += d;
      }
    }
    REQUIRE_MESSAGE(f.solve() == reference_max_flow(cap, n, n + 1), "seed " << seed);
  }
}

TEST_CASE("roof dual: a bound on the optimum, and an assignment some optimum extends") {
  uint32_t labelled = 0, variables = 0, strict = 0, whole = 0;
  for (uint64_t seed = 1; seed <= 4000; ++seed) {
    Rng r(seed);
    FactorGraph g;
    g.num_vars = 1 + static_cast<uint32_t>(r.below(9));
    g.sense = r.below(2) ? Sense::Max : Sense::Min;
    g.constant = r.below(5) - 2;
    // Every fourth instance only submodular pairs (for the sense): then the cut
    // is exact and labels every variable.
    const bool submodular = seed % 4 == 0;
    const int terms = r.below(4 * static_cast<int>(g.num_vars) + 1);
    for (int k = 0; k < terms; ++k) {
      Factor f;
      const int scope = r.below(6) == 0 ? 0 : r.below(3) ? 2 : 1;
      for (int j = 0; j < scope; ++j) {
        const uint32_t v = static_cast<uint32_t>(r.below(static_cast<int>(g.num_vars)));
        if (std::find(f.scope.begin(), f.scope.end(), v) == f.scope.end()) f.scope.push_back(v);
      }
      for (size_t i = 0; i < (size_t(1) << f.scope.size()); ++i) f.table.push_back(r.below(7) - 3);
      if (submodular && f.scope.size() == 2) {
        // min: e01 + e10 >= e00 + e11 (max: <=), made so by raising (lowering) e01.
        const double need = f.table[0] + f.table[3] - f.table[1];
        f.table[2] = g.sense == Sense::Min ? std::max(f.table[2], need) : std::min(f.table[2], need);
      }
      g.factors.push_back(std::move(f));
    }
    REQUIRE(roof_dual_applies(g));
    const RoofDual rd = roof_dual(g);
    const bool max = g.sense == Sense::Max;
    double best = max ? -INFINITY : INFINITY, best_extending = best;
    for (uint32_t bits = 0; bits < (1u << g.num_vars); ++bits) {
      Choice x(g.num_vars);
      bool extends = true;
      for (uint32_t v = 0; v < g.num_vars; ++v) {
        x[v] = (bits >> v) & 1;
        extends = extends && (rd.fixed[v] < 0 || rd.fixed[v] == x[v]);
      }
      const double value = g.evaluate(x);
      best = max ? std::max(best, value) : std::min(best, value);
      if (extends) best_extending = max ? std::max(best_extending, value) : std::min(best_extending, value);
    }
    INFO("seed " << seed);
    REQUIRE(best_extending == best);
    REQUIRE((max ? rd.bound >= best : rd.bound <= best));
    // Conditioning keeps the value of every assignment that extends the fixed one.
    const FactorGraph c = condition(g, rd.fixed);
    Choice x(g.num_vars);
    for (uint32_t v = 0; v < g.num_vars; ++v) x[v] = rd.fixed[v] >= 0 ? rd.fixed[v] : r.below(2);
    CHECK(c.evaluate(x) == g.evaluate(x));
    for (const Factor& f : c.factors)
      for (uint32_t v : f.scope) CHECK(rd.fixed[v] < 0);
    if (submodular) {
      CHECK(rd.num_fixed == g.num_vars);
      CHECK(rd.bound == best);
    }
    labelled += rd.num_fixed, variables += g.num_vars;
    strict += rd.bound != best, whole += rd.num_fixed == g.num_vars;
  }
  MESSAGE(labelled << " of " << variables << " variables labelled; " << whole << " instances whole, bound above the optimum in " << strict);
  CHECK(strict > 40);                 // the bound is not the optimum computed some other way
  CHECK(labelled < variables);        // nor is every variable labelled
  CHECK(labelled > variables / 2);
}

TEST_CASE("convex edges: the roof dual and the DP on the quads it leaves free equal the DP alone") {
  uint32_t instances = 0, fixed = 0, quads = 0, partly = 0;
  for (uint64_t seed = 1; seed <= 70; ++seed) {
    std::vector<double> p;
    switch (seed % 7) {
      case 5: p = frustrated_raster(15, 100 + static_cast<int>(seed % 5) * 4, 260 + static_cast<int>(seed % 3) * 10, 316); break;
      case 6: p = grid_points(30, 30, seed, true); break;
      case 0: p = uniform_points(400, seed); break;
      case 1: p = dem_points(400, seed); break;
      case 2: p = grid_points(16, 16, seed, true); break;  // equal heights, cocircular cells
      case 3: p = jittered_grid(16, 16, 0.35, seed); break;
      default: p = grid_points(16, 16, seed); break;
    }
    const FirstOrder fo = first_order(delaunay(p));
    const FactorGraph g = factor_model(fo, Objective::MaxConvexEdges);
    const DpResult alone = solve_exact(g);
    SolveOptions exact;
    exact.method = Method::Exact;
    const Solution s = solve(fo, Objective::MaxConvexEdges, exact);
    INFO("seed " << seed);
    CHECK(s.value == alone.value);
    CHECK(g.evaluate(s.choice) == alone.value);
    const RoofDual rd = roof_dual(g);
    CHECK(rd.bound >= alone.value);
    ++instances, fixed += rd.num_fixed, quads += g.num_vars, partly += rd.num_fixed < g.num_vars;
  }
  MESSAGE(instances << " instances, the roof dual fixed " << fixed << " of " << quads << " quads");
  CHECK(partly >= 10);  // the DP on the free quads ran
}
