// Random state graphs for the engine's tests: factors read their variables
// through coarse projections (the case the projected elimination is built
// for) and tables hold small integers (ties everywhere).
#pragma once
#include <algorithm>
#include <random>

#include "engines/state_graph.hpp"

namespace hodt::test {

// Up to max_vars variables of up to max_states states.
inline StateGraph random_state_graph(std::mt19937& rng, Combine combine, Sense sense, uint32_t max_vars = 7,
                                     uint32_t max_states = 5) {
  auto below = [&](uint32_t n) { return static_cast<uint32_t>(rng() % n); };
  StateGraph g;
  g.combine = combine;
  g.sense = sense;
  const uint32_t n = 1 + below(max_vars);
  for (uint32_t x = 0; x < n; ++x) {
    g.domain.push_back(1 + below(max_states));
    g.unary.emplace_back();
    for (uint32_t s = 0; s < g.domain[x]; ++s) g.unary[x].push_back(below(3) == 0 ? below(4) : 0);
    g.unary_terms.push_back(1);
    g.partial.push_back(0);
  }
  const uint32_t m = below(2 * n + 1);
  for (uint32_t i = 0; i < m; ++i) {
    StateFactor f;
    const uint32_t size = 1 + below(std::min<uint32_t>(n, 3));
    while (f.scope.size() < size) {
      const uint32_t x = below(n);
      if (std::find(f.scope.begin(), f.scope.end(), x) == f.scope.end()) f.scope.push_back(x);
    }
    size_t entries = 1;
    for (uint32_t x : f.scope) {
      const uint32_t classes = 1 + below(std::max<uint32_t>(1, g.domain[x] - 1));
      std::vector<uint32_t> p(g.domain[x]);
      for (auto& c : p) c = below(classes);
      f.project.push_back(p);
      f.dims.push_back(classes);
      entries *= classes;
    }
    for (size_t e = 0; e < entries; ++e) f.table.push_back(below(5));
    g.factors.push_back(std::move(f));
  }
  return g;
}

// The best value over every assignment.
inline double enumerate_best(const StateGraph& g) {
  std::vector<uint32_t> x(g.domain.size(), 0);
  double best = evaluate_states(g, x);
  for (;;) {
    size_t i = 0;
    for (; i < x.size(); ++i) {
      if (++x[i] < g.domain[i]) break;
      x[i] = 0;
    }
    if (i == x.size()) return best;
    const double v = evaluate_states(g, x);
    if (g.sense == Sense::Min ? v < best : v > best) best = v;
  }
}

}  // namespace hodt::test
