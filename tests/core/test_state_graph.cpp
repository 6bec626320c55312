// The state-graph engine (state_graph.hpp) against enumeration of every
// assignment, on random graphs whose factors read their variables through
// coarse projections (the case the projected elimination is built for) and whose
// tables hold small integers (ties everywhere).
#include <doctest/doctest.h>

#include <functional>
#include <random>

#include "engines/state_graph.hpp"
#include "random_state_graph.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

// 3000 random graphs, in turn sum/min, sum/max and max/min (the three kinds the
// objectives make).
void for_random_graphs(uint32_t seed, const std::function<void(int, std::mt19937&, const StateGraph&)>& check) {
  std::mt19937 rng(seed);
  const std::pair<Combine, Sense> kinds[] = {
      {Combine::Sum, Sense::Min}, {Combine::Sum, Sense::Max}, {Combine::Max, Sense::Min}};
  for (int trial = 0; trial < 3000; ++trial) {
    const StateGraph g = random_state_graph(rng, kinds[trial % 3].first, kinds[trial % 3].second);
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

TEST_CASE("state graph: min-max over independent components is the largest of their optima") {
  std::mt19937 rng(20261126);
  int split = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    // Up to 4 random graphs side by side (variables renumbered), with a constant.
    StateGraph g;
    g.combine = Combine::Max;
    g.sense = Sense::Min;
    g.constant = static_cast<double>(rng() % 3);
    double want = g.constant;
    const uint32_t parts = 1 + rng() % 4;
    for (uint32_t p = 0; p < parts; ++p) {
      const StateGraph h = random_state_graph(rng, Combine::Max, Sense::Min, 5, 4);
      const uint32_t base = static_cast<uint32_t>(g.domain.size());
      g.domain.insert(g.domain.end(), h.domain.begin(), h.domain.end());
      g.unary.insert(g.unary.end(), h.unary.begin(), h.unary.end());
      g.unary_terms.insert(g.unary_terms.end(), h.unary_terms.begin(), h.unary_terms.end());
      g.partial.insert(g.partial.end(), h.partial.begin(), h.partial.end());
      for (StateFactor f : h.factors) {
        for (uint32_t& x : f.scope) x += base;
        g.factors.push_back(std::move(f));
      }
      want = std::max(want, enumerate_best(h));
    }
    split += parts > 1;
    CAPTURE(trial);
    const StateDpResult r = solve_states(g);
    CHECK(r.value == want);
    CHECK(evaluate_states(g, r.state) == r.value);
    // Windows over whole components from any start: each component's worst
    // term is lowered in turn, as the whole's worst moves from one to the next.
    std::vector<uint32_t> start(g.domain.size());
    for (size_t x = 0; x < start.size(); ++x) start[x] = static_cast<uint32_t>(rng() % g.domain[x]);
    CHECK(evaluate_states(g, improve_by_windows(g, start, {}, 64)) == want);
  }
  CHECK(split > 1000);
}

TEST_CASE("state graph: min-max windows follow the worst term from component to component") {
  // Three variables alone, each at its worse state: the worst term is lowered in
  // turn at the third, the second, then the first (windows before the worst term
  // cannot lower it, so a pass skips them; another pass comes back).
  StateGraph g;
  g.combine = Combine::Max;
  g.sense = Sense::Min;
  g.domain = {2, 2, 2};
  g.unary = {{8, 1}, {9, 2}, {10, 3}};
  g.unary_terms.assign(3, 1);
  g.partial.assign(3, 0);
  CHECK(evaluate_states(g, improve_by_windows(g, {0, 0, 0}, {}, 1)) == 3);
}

TEST_CASE("state graph: arc consistency refutes a min-max threshold only at or below the optimum") {
  std::mt19937 rng(23);
  int refuted = 0, kept_above = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const StateGraph g = random_state_graph(rng, Combine::Max, Sense::Min);
    const double best = enumerate_best(g);
    CAPTURE(trial);
    // (Tables hold 0 to 4: every threshold between them.)
    for (double t = -0.5; t <= 5.5; t += 0.5) {
      const bool none = none_below(g, t);
      if (t > best) CHECK(!none);  // the optimum has every term below t
      if (t <= best) refuted += none;
      kept_above += t > best && !none;
    }
  }
  CHECK(refuted > 3000);  // (thresholds at or below the optimum, refuted: most of them)
  CHECK(kept_above > 0);
  CHECK(!none_below(random_state_graph(rng, Combine::Sum, Sense::Min), 1e9));  // (min-max only)
}
