// The state-graph engine (state_graph.hpp) against enumeration of every
// assignment, on random graphs whose factors read their variables through
// coarse projections (the case the projected elimination is built for) and whose
// tables hold small integers (ties everywhere).
#include <doctest/doctest.h>

#include <functional>
#include <random>

#include "hodt/state_graph.hpp"

using namespace hodt;

namespace {

StateGraph random_graph(std::mt19937& rng, TermCombine combine, Sense sense) {
  auto below = [&](uint32_t n) { return static_cast<uint32_t>(rng() % n); };
  StateGraph g;
  g.combine = combine;
  g.sense = sense;
  const uint32_t n = 1 + below(7);
  for (uint32_t x = 0; x < n; ++x) {
    g.domain.push_back(1 + below(5));
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
double enumerate_best(const StateGraph& g) {
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

// 3000 random graphs, in turn sum/min, sum/max and max/min (the three kinds the
// objectives make).
void for_random_graphs(uint32_t seed, const std::function<void(int, std::mt19937&, const StateGraph&)>& check) {
  std::mt19937 rng(seed);
  const std::pair<TermCombine, Sense> kinds[] = {
      {TermCombine::Sum, Sense::Min}, {TermCombine::Sum, Sense::Max}, {TermCombine::Max, Sense::Min}};
  for (int trial = 0; trial < 3000; ++trial) {
    const StateGraph g = random_graph(rng, kinds[trial % 3].first, kinds[trial % 3].second);
    CAPTURE(trial);
    check(trial, rng, g);
  }
}

}  // namespace

TEST_CASE("state graph: the engine equals enumeration on random graphs with coarse projections") {
  int checked = 0;
  for_random_graphs(20261123, [&](int, std::mt19937&, const StateGraph& g) {
    const StateDpResult r = solve_states(g);
    CHECK(r.value == enumerate_best(g));
    CHECK(evaluate_states(g, r.state) == r.value);
    ++checked;
  });
  CHECK(checked == 3000);
}

TEST_CASE("state graph: mini-buckets bound the optimum from the right side, and equal it when no bag is split") {
  int split = 0, strict = 0;
  for_random_graphs(7, [&](int trial, std::mt19937&, const StateGraph& g) {
    StateDpLimits limits;
    limits.max_table = 1 + trial % 6;
    limits.mini_buckets = true;
    const StateDpResult r = solve_states(g, limits);
    const double best = enumerate_best(g);
    if (!r.bound_only) {
      CHECK(r.value == best);
      return;
    }
    ++split;
    CHECK((g.sense == Sense::Min ? r.value <= best : r.value >= best));
    strict += r.value != best;
  });
  MESSAGE(split << " graphs split into mini-buckets, " << strict << " bounds strictly weaker");
  CHECK(split > 500);
  CHECK(strict > 0);
}

TEST_CASE("state graph: windows solved exactly never worsen an assignment, and a window over every variable finds the optimum") {
  int improved = 0;
  for_random_graphs(11, [&](int, std::mt19937& rng, const StateGraph& g) {
    std::vector<uint32_t> start(g.domain.size());
    for (size_t x = 0; x < start.size(); ++x) start[x] = static_cast<uint32_t>(rng() % g.domain[x]);
    const double before = evaluate_states(g, start);
    const std::vector<uint32_t> small = improve_by_windows(g, start, {}, 2);
    const double after = evaluate_states(g, small);
    CHECK((g.sense == Sense::Min ? after <= before : after >= before));
    improved += after != before;
    const std::vector<uint32_t> whole = improve_by_windows(g, start, {}, 64);
    // (a ball reaches only the variables connected to its seed: one window per component)
    CHECK(evaluate_states(g, whole) == enumerate_best(g));
  });
  CHECK(improved > 300);
}
