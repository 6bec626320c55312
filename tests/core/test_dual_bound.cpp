// The dual bound and its proofs (dual_bound.hpp) against enumeration and the
// exact DP: the bound is never past the optimum, a proof is never wrong, and
// an optimum found is the optimum.
#include <doctest/doctest.h>

#include <random>

#include "hodt/delaunay.hpp"
#include "hodt/error.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/measures.hpp"
#include "hodt/points.hpp"
#include "engines/dual_bound.hpp"
#include "generators.hpp"
#include "higher_order/k_order.hpp"
#include "higher_order/regions/region_engine.hpp"
#include "k_order_reference.hpp"
#include "random_state_graph.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

bool not_past(Sense sense, double bound, double optimum) { return sense == Sense::Min ? bound <= optimum : bound >= optimum; }

std::vector<uint32_t> random_assignment(std::mt19937& rng, const StateGraph& g) {
  std::vector<uint32_t> x(g.domain.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = static_cast<uint32_t>(rng() % g.domain[i]);
  return x;
}

// Checks a proof of `incumbent` against the optimum.
void check_proof(const StateGraph& g, const DualProof::Proof& p, double incumbent, double optimum) {
  if (!p.proven) return;
  if (p.better) {
    CHECK(p.better_value == optimum);
    CHECK(evaluate_states(g, *p.better) == optimum);
  } else {
    CHECK(incumbent == optimum);
  }
}

// A w x h grid of variables with a factor on each grid edge and diagonal
// (treewidth about min(w, h)): frustrated cycles everywhere.
StateGraph grid_graph(std::mt19937& rng, uint32_t w, uint32_t h, Sense sense) {
  auto below = [&](uint32_t n) { return static_cast<uint32_t>(rng() % n); };
  StateGraph g;
  g.sense = sense;
  for (uint32_t x = 0; x < w * h; ++x) {
    g.domain.push_back(2 + below(4));
    g.unary.emplace_back();
    for (uint32_t s = 0; s < g.domain[x]; ++s) g.unary[x].push_back(below(3));
  }
  g.unary_terms.assign(g.domain.size(), 1);
  g.partial.assign(g.domain.size(), 0);
  auto factor = [&](uint32_t a, uint32_t b) {
    StateFactor f;
    f.scope = {a, b};
    for (uint32_t x : f.scope) {
      const uint32_t classes = 2 + below(2);
      std::vector<uint32_t> p(g.domain[x]);
      for (auto& c : p) c = below(classes);
      f.project.push_back(p);
      f.dims.push_back(classes);
    }
    for (uint32_t e = 0; e < f.dims[0] * f.dims[1]; ++e) f.table.push_back(below(4));
    g.factors.push_back(std::move(f));
  };
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      if (x + 1 < w) factor(y * w + x, y * w + x + 1);
      if (y + 1 < h) factor(y * w + x, (y + 1) * w + x);
      if (x + 1 < w && y + 1 < h) factor(y * w + x, (y + 1) * w + x + 1);
    }
  return g;
}

}  // namespace

TEST_CASE("dual bound: never past the optimum, tight on most small graphs, clustered or not") {
  std::mt19937 rng(20261126);
  int tight = 0, graphs = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Sense sense = trial % 2 ? Sense::Max : Sense::Min;
    const StateGraph g = trial % 4 < 2 ? random_state_graph(rng, Combine::Sum, sense)
                                       : random_state_graph(rng, Combine::Sum, sense, 10, 3);
    const double best = enumerate_best(g);
    for (double cluster : {1.0, 16.0, 1024.0}) {
      DualLimits limits;
      limits.cluster_entries = cluster;
      const DualProof d(g, limits);
      CAPTURE(trial);
      CAPTURE(cluster);
      REQUIRE(d.applies());
      CHECK(not_past(sense, *d.bound(), best));
      tight += *d.bound() == best;
      ++graphs;
      const std::vector<uint32_t> x = d.decoded();
      REQUIRE(x.size() == g.domain.size());
      for (size_t i = 0; i < x.size(); ++i) CHECK(x[i] < g.domain[i]);
    }
  }
  MESSAGE(tight << " of " << graphs << " bounds tight");
  CHECK(tight > graphs / 2);
}

namespace {

// f with its positions reordered: new position i is old position order[i]
// (the table's first position fastest, as always).
StateFactor reordered(const StateFactor& f, const std::vector<size_t>& order) {
  StateFactor t;
  t.num_terms = f.num_terms;
  for (size_t j : order) t.scope.push_back(f.scope[j]), t.dims.push_back(f.dims[j]), t.project.push_back(f.project[j]);
  t.table.resize(f.table.size());
  std::vector<uint32_t> c(f.dims.size(), 0);  // the entry's classes, old positions
  for (size_t e = 0; e < f.table.size(); ++e) {
    size_t at = 0, stride = 1;
    for (size_t i = 0; i < order.size(); ++i) at += c[order[i]] * stride, stride *= t.dims[i];
    t.table[at] = f.table[e];
    for (size_t j = 0; j < c.size() && ++c[j] == f.dims[j]; ++j) c[j] = 0;
  }
  return t;
}

}  // namespace

TEST_CASE("dual bound: the same bound and states whatever the order of each factor's positions") {
  // (The ascent lays each table out widest position first, and simplify
  // merges the same classes in any order: the same messages, exactly. Not
  // clustered: clusters grow along each scope in its order.)
  std::mt19937 rng(20261128);
  int loose = 0;
  for (int trial = 0; trial < 900; ++trial) {
    const Sense sense = trial % 2 ? Sense::Max : Sense::Min;
    StateGraph g = trial % 4 ? grid_graph(rng, 4 + trial % 3, 5, sense) : random_state_graph(rng, Combine::Sum, sense, 12, 6);
    if (trial % 3 == 0)  // (wider values: relaxations that are not tight; else ties, classes to merge)
      for (StateFactor& f : g.factors)
        for (double& t : f.table) t = static_cast<double>(rng() % 40);
    StateGraph h = g;
    for (StateFactor& f : h.factors) {
      std::vector<size_t> order(f.dims.size());
      for (size_t j = 0; j < order.size(); ++j) order[j] = j;
      std::shuffle(order.begin(), order.end(), rng);
      f = reordered(f, order);
    }
    for (int i = 0; i < 20; ++i) {  // (the same function, reordered)
      const std::vector<uint32_t> x = random_assignment(rng, g);
      CHECK(evaluate_states(h, x) == evaluate_states(g, x));
    }
    const double optimum = solve_states(g).value;
    DualLimits limits;
    limits.cluster_entries = 1;
    const DualProof a(g, limits), b(h, limits);
    CAPTURE(trial);
    REQUIRE(a.applies() == b.applies());
    if (!a.applies()) continue;
    CHECK(*a.bound() == *b.bound());
    CHECK(a.decoded() == b.decoded());
    loose += *a.bound() != optimum;
  }
  MESSAGE(loose << " of the bounds compared were not tight");
  CHECK(loose > 10);
}

TEST_CASE("dual proof: proves the optimum, finds it from a worse incumbent, and never claims a wrong one") {
  std::mt19937 rng(7);
  int proven = 0, found = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Sense sense = trial % 2 ? Sense::Max : Sense::Min;
    const StateGraph g = random_state_graph(rng, Combine::Sum, sense, 9, 4);
    const double best = enumerate_best(g);
    DualLimits limits;
    limits.cluster_entries = trial % 3 == 0 ? 1.0 : 64.0;
    limits.max_sweeps = 1 + trial % 50;  // (short ascents leave work to the pruning)
    StateDpLimits dp;
    dp.max_table = trial % 5 == 0 ? 2 : 1 << 22;  // (a DP refused: the rounds go on, or nothing is proven)
    dp.mini_buckets = trial % 7 == 0;             // (ignored: a mini-bucket value is no assignment's)
    const DualProof d(g, limits);
    for (double incumbent : {best, evaluate_states(g, random_assignment(rng, g))}) {
      CAPTURE(trial);
      CAPTURE(incumbent);
      const DualProof::Proof p = d.prove(incumbent, dp);
      check_proof(g, p, incumbent, best);
      proven += p.proven;
      found += p.better.has_value();
      CHECK(p.kept_states <= p.states);
      CHECK(p.kept_entries <= p.entries);
    }
  }
  MESSAGE(proven << " proofs, " << found << " better optima found");
  CHECK(proven > 2000);
  CHECK(found > 300);
}

TEST_CASE("dual proof: grids wider than the DP allows, against the DP without limits") {
  std::mt19937 rng(2026);
  int proven = 0, found = 0;
  const int trials = 120;
  for (int trial = 0; trial < trials; ++trial) {
    const Sense sense = trial % 2 ? Sense::Max : Sense::Min;
    const StateGraph g = grid_graph(rng, 6 + trial % 3, 6, sense);
    const StateDpResult exact = solve_states(g);
    StateDpLimits narrow;
    narrow.max_table = 16;
    REQUIRE_THROWS_AS(solve_states(g, narrow), LimitError);
    const std::vector<uint32_t> start = improve_states(g, random_assignment(rng, g));
    const double incumbent = evaluate_states(g, start);
    DualLimits limits;
    limits.cluster_entries = trial % 2 ? 1.0 : 256.0;
    const DualProof d(g, limits, incumbent);
    CAPTURE(trial);
    CHECK(not_past(sense, *d.bound(), exact.value));
    const DualProof::Proof p = d.prove(incumbent, narrow);
    check_proof(g, p, incumbent, exact.value);
    proven += p.proven;
    found += p.better.has_value();
  }
  MESSAGE(proven << " of " << trials << " grids too wide for the DP proven by pruning, " << found << " with a better optimum");
  CHECK(proven > trials / 8);
}

TEST_CASE("dual bound: only sums of moderate integers over whole graphs") {
  std::mt19937 rng(3);
  StateGraph g;
  do g = random_state_graph(rng, Combine::Sum, Sense::Min);
  while (g.factors.empty());
  CHECK(DualProof(g).applies());
  StateGraph max = g;
  max.combine = Combine::Max;
  CHECK(!DualProof(max).applies());
  StateGraph fraction = g;
  fraction.factors[0].table[0] = 0.5;
  CHECK(!DualProof(fraction).applies());
  StateGraph huge = g;
  huge.factors[0].table[0] = 1e300;
  CHECK(!DualProof(huge).applies());
  StateGraph partial = g;
  partial.partial[0] = 1;
  CHECK(!DualProof(partial).applies());
  StateGraph relaxed = g;
  relaxed.relaxed_terms = 1;
  CHECK(!DualProof(relaxed).applies());
  const DualProof d(g);
  CHECK(!d.prove(0.5).proven);  // (an incumbent that is no count proves nothing)
}

TEST_CASE("dual proof over the order-k model: what it proves is the brute-force optimum (k = 2, 3, 4)") {
  int proven = 0, found = 0, runs = 0;
  for_small_k_instances({2u, 3u, 4u}, 100, 13, [&](uint32_t k, uint64_t seed, const FirstOrder& fo, const KOrderStructure& structure) {
    const Mesh& dt = fo.base;
    for (const auto& oi : objectives()) {
      const RegionEngine engine(dt, oi.objective, structure, k, RegionLimits{}, {});
      if (engine.R.incomplete || !integral_sum(engine.model.graph)) continue;
      const double want = k_order_brute_force(fo, oi.objective, k).value;
      // The incumbent: Delaunay's regions; short ascents and a DP allowed
      // almost nothing, so the pruning and the rounds do the work.
      const RegionModel& model = engine.model;
      const double incumbent = evaluate(oi.objective, engine.R.triangulation(dt, std::vector<uint32_t>(engine.R.regions.size(), 0)));
      DualLimits limits;
      limits.max_sweeps = 1 + seed % 20;
      limits.cluster_entries = seed % 2 ? 1.0 : 4096.0;
      const DualProof d(model.graph, limits, incumbent);
      CAPTURE(k);
      CAPTURE(seed);
      CAPTURE(oi.id);
      REQUIRE(d.applies());
      CHECK(not_past(oi.sense, *d.bound(), want));
      StateDpLimits dp;
      dp.max_table = 1 + seed % 8;
      const DualProof::Proof p = d.prove(incumbent, dp);
      ++runs;
      if (!p.proven) continue;
      ++proven;
      if (p.better) {
        ++found;
        const Mesh m = engine.R.triangulation(dt, model.region_states(*p.better));
        CHECK(evaluate(oi.objective, m) == want);
        CHECK(p.better_value == want);
        CHECK(is_k_order(m, dt, k));
      } else {
        CHECK(incumbent == want);
      }
    }
  });
  MESSAGE(proven << " of " << runs << " proofs over order-k models, " << found << " finding a better optimum");
  CHECK(proven > runs / 2);
  CHECK(found > 50);
}
