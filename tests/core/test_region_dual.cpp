// Regions read through their fill graphs (fill_graph.hpp) and the Lagrangian
// dual over them (region_dual.hpp), against the regions' listed
// triangulations and brute force: the graph holds exactly the region's
// triangulations, its min-marginals are the listed ones, and the bound never
// passes the optimum.
#include <doctest/doctest.h>

#include <map>

#include "hodt/delaunay.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/points.hpp"
#include "generators.hpp"
#include "higher_order/bounds/region_dual.hpp"
#include "higher_order/regions/fill_graph.hpp"
#include "higher_order/k_order.hpp"
#include "mesh/mesh_of.hpp"
#include "higher_order/regions/glue_regions.hpp"
#include "higher_order/regions/region_engine.hpp"
#include "k_order_reference.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

bool not_past(Sense sense, double bound, double optimum) { return sense == Sense::Min ? bound <= optimum : bound >= optimum; }

// Every region with a choice is marked as not listed (only its Delaunay fill kept).
uint64_t forget_lists(Regions& R) {
  for (Region& g : R.regions)
    if (g.states.size() > 1) g.states.resize(1), g.complete = false, ++R.incomplete;
  return R.incomplete;
}

}  // namespace

TEST_CASE("fill graph: the region's triangulations, their best by entry and by combination of entries, and a fill for each entry") {
  int graphs = 0, entries = 0;
  for (uint32_t k : {2u, 3u, 4u})
    for (uint64_t seed = 1; seed <= 30; ++seed) {
      const Mesh dt = delaunay(validate_points(mixed_instance(seed * 7 + k, 1)).xyz);
      const KOrderStructure structure(dt, k, {});
      for (const auto& oi : objectives()) {
        const RegionEngine engine(dt, oi.objective, structure, k, RegionLimits{}, {});
        if (engine.R.incomplete || engine.terms.terms().combine != Combine::Sum) continue;
        // Every listed triangulation of each region (the enumeration, not the DP).
        RegionLimits all;
        all.max_states_per_region = 1'000'000;
        all.first_pass_states = all.max_states_per_region_dp = 0;
        Regions listed = k_order_regions(dt, k, all);
        for (uint32_t r = 0; r < engine.R.regions.size(); ++r) {
          const auto& states = listed.regions[r].states;
          if (states.size() < 2 || !listed.regions[r].complete) continue;
          const auto g = fill_graph(dt, engine.cand, engine.terms, r, 1'000'000);
          REQUIRE(g);
          ++graphs;
          CAPTURE(k);
          CAPTURE(seed);
          CAPTURE(oi.id);
          CAPTURE(r);
          // Per (item, entry), the least own value over the listed triangulations that take it.
          std::map<SignatureEntry, double> want;
          double least = INFINITY;
          for (const auto& s : states) {
            const StateKey key = engine.terms.key(r, s);
            least = std::min(least, key.value);
            for (const SignatureEntry& e : key.signature) {
              const auto [it, fresh] = want.try_emplace(e, key.value);
              if (!fresh) it->second = std::min(it->second, key.value);
            }
          }
          std::vector<std::vector<double>> zero(g->entries.size()), marginals;
          for (size_t i = 0; i < zero.size(); ++i) zero[i].assign(g->entries[i].size(), 0.0);
          std::vector<Tri> best;
          // (Lengths and areas: the graph adds the same terms in another order.)
          const auto near = [](double v) { return doctest::Approx(v).epsilon(1e-12); };
          CHECK(g->least(zero, &marginals, &best) == near(least));
          CHECK(engine.terms.key(r, best).value == near(least));
          CHECK(std::find(states.begin(), states.end(), best) != states.end());
          size_t count = 0;
          const auto reps = g->representatives();
          for (size_t i = 0; i < g->entries.size(); ++i)
            for (size_t e = 0; e < g->entries[i].size(); ++e, ++count) {
              const SignatureEntry& entry = g->entries[i][e];
              CHECK(RegionTerms::item_of(entry) == g->items[i]);
              REQUIRE(want.count(entry));
              CHECK(marginals[i][e] == near(want.at(entry)));
              const auto sig = engine.terms.key(r, reps[i][e]).signature;
              CHECK(std::find(sig.begin(), sig.end(), entry) != sig.end());
              CHECK(std::find(states.begin(), states.end(), reps[i][e]) != states.end());
            }
          CHECK(count == want.size());  // (no entry missing, none that no fill takes)
          entries += static_cast<int>(count);
          // The least fill per combination of entries, over every arc and over
          // some: against the fills over those arcs, grouped by signature.
          for (int pass = 0; pass < 2; ++pass) {
            std::vector<uint8_t> kept(g->arcs.size(), 1);
            for (size_t a = 0; pass && a < kept.size(); ++a) kept[a] = (a * 2654435761u + seed) % 7 != 0;
            auto every = g->fills(kept, 1'000'000);
            REQUIRE(every);
            std::sort(every->begin(), every->end());
            std::map<std::vector<SignatureEntry>, double> least_of;
            for (const auto& fill : *every) {
              const StateKey key = engine.terms.key(r, fill);
              const auto [it, fresh] = least_of.try_emplace(key.signature, key.value);
              if (!fresh) it->second = std::min(it->second, key.value);
            }
            const auto by_entries = g->best_by_entries(kept, 1'000'000, 1'000'000);
            REQUIRE(by_entries);
            CHECK(by_entries->size() == least_of.size());
            for (const auto& fill : *by_entries) {
              CHECK(std::binary_search(every->begin(), every->end(), fill));
              const StateKey key = engine.terms.key(r, fill);
              REQUIRE(least_of.count(key.signature));
              CHECK(key.value == near(least_of.at(key.signature)));
            }
            if (!least_of.empty()) CHECK_FALSE(g->best_by_entries(kept, least_of.size() - 1, 1'000'000));
          }
        }
      }
    }
  MESSAGE(graphs << " fill graphs, " << entries << " entries checked");
  CHECK(graphs > 500);
}

TEST_CASE("region dual: regions read through their graphs never take the bound past the brute-force optimum, and prove only the optimum") {
  int runs = 0, tight = 0, relaxed = 0, found_optimum = 0, proven = 0, better_found = 0, by_pruning = 0, tightened = 0;
  for_small_k_instances({2u, 3u, 4u}, 60, 11, [&](uint32_t k, uint64_t seed, const FirstOrder& fo, const KOrderStructure& structure) {
    const Mesh& dt = fo.base;
    for (const auto& oi : objectives()) {
      RegionEngine engine(dt, oi.objective, structure, k, RegionLimits{}, {});
      if (!integral_sum(engine.model.graph) || engine.R.incomplete || engine.model.graph.relaxed_terms) continue;
      if (!forget_lists(engine.R)) continue;
      const double want = k_order_brute_force(fo, oi.objective, k).value;
      RegionDualLimits limits;
      // (Short ascents: the pruning and the DP do the work; none at all: the
      // proof's targets short of the bound take it down.)
      limits.dual.max_sweeps = seed % 7 == 3 ? 0 : seed % 3 ? 1 + seed % 50 : 1;
      limits.dual.cluster_entries = seed % 2 ? 1.0 : 4096.0;
      if (seed % 5 == 0) limits.first_states = limits.max_states = 20;  // (some graphs too large: left to the relaxation)
      const RegionDual d = region_dual(dt, engine.R, oi.objective, engine.cand, engine.terms, &dt, limits);
      CAPTURE(k);
      CAPTURE(seed);
      CAPTURE(oi.id);
      if (!d.graphs) continue;
      REQUIRE(d.bound);
      ++runs;
      relaxed += d.relaxed > 0;
      CHECK(not_past(oi.sense, *d.bound, want));
      tight += *d.bound == want;
      // What the descent found (from the dual, and from Delaunay): k-OD triangulations no better than the bound.
      CHECK(d.found.size() >= 2);
      bool optimum = false;
      REQUIRE(d.values.size() == d.found.size());
      for (size_t i = 0; i < d.found.size(); ++i) {
        const Mesh m = mesh_of(dt.coords, d.found[i]);
        CHECK(is_k_order(m, dt, k));
        const double v = evaluate(oi.objective, m);
        CHECK(d.values[i] == v);
        CHECK(not_past(oi.sense, *d.bound, v));
        CHECK(not_past(oi.sense, want, v));
        optimum = optimum || v == want;
      }
      found_optimum += optimum;
      tightened += d.tightened > 0;
      // The proof: what it proves optimal is the optimum.
      if (d.proven) {
        ++proven;
        by_pruning += *d.bound != want;
        double best = evaluate(oi.objective, dt);
        for (const auto& tris : d.found) {
          const double v = evaluate(oi.objective, mesh_of(dt.coords, tris));
          if (better(oi.sense, v, best)) best = v;
        }
        if (d.optimum) {
          CHECK(is_k_order(*d.optimum, dt, k));
          CHECK(better(oi.sense, evaluate(oi.objective, *d.optimum), best));
          best = evaluate(oi.objective, *d.optimum);
          ++better_found;
        }
        CHECK(best == want);
      }
    }
  });
  MESSAGE(runs << " bounds over regions read through their graphs, " << tight << " equal to the optimum, " << relaxed
                << " with some regions relaxed, " << found_optimum << " with the optimum found by the descent, " << proven
                << " proven (" << better_found << " by a better optimum, " << by_pruning
                << " where the bound alone did not meet it), " << tightened << " bounds tightened by the proof's targets");
  CHECK(runs > 300);
  CHECK(tightened >= 2);
  CHECK(tight > runs / 2);
  CHECK(relaxed >= 10);
  CHECK(found_optimum > runs / 2);
  CHECK(proven > runs / 2);
  CHECK(by_pruning > 5);
}

TEST_CASE("region threshold bound: min-max objectives over regions read through their graphs, never past the optimum") {
  int runs = 0, tight = 0;
  for_small_k_instances({2u, 3u, 4u}, 40, 17, [&](uint32_t k, uint64_t seed, const FirstOrder& fo, const KOrderStructure& structure) {
    const Mesh& dt = fo.base;
    for (const auto& oi : objectives()) {
      RegionEngine engine(dt, oi.objective, structure, k, RegionLimits{}, {});
      if (engine.terms.terms().combine != Combine::Max || engine.R.incomplete) continue;
      if (!forget_lists(engine.R)) continue;
      const double want = k_order_brute_force(fo, oi.objective, k).value;
      const double delaunay_value = evaluate(oi.objective, dt);
      RegionDualLimits limits;
      limits.dual.max_sweeps = 1 + seed % 100;
      if (seed % 5 == 0) limits.first_states = limits.max_states = 20;
      CAPTURE(k);
      CAPTURE(seed);
      CAPTURE(oi.id);
      const auto b = region_threshold_bound(dt, engine.R, oi.objective, engine.cand, engine.terms,
                                            engine.terms.floor(), delaunay_value, limits);
      if (!b) continue;
      ++runs;
      CHECK(*b <= want);
      CHECK(*b > engine.terms.floor());
      tight += *b == want;
    }
  });
  MESSAGE(runs << " threshold bounds, " << tight << " equal to the optimum");
  CHECK(runs > 100);
  CHECK(tight > runs / 2);
}

TEST_CASE("glued regions: the same k-OD triangulations, and a dual over them never past the optimum") {
  int runs = 0, tight = 0, glued_runs = 0, proven = 0;
  for_small_k_instances({2u, 3u, 4u}, 120, 13, [&](uint32_t k, uint64_t seed, const FirstOrder& fo, const KOrderStructure& structure) {
    const Mesh& dt = fo.base;
    CAPTURE(k);
    CAPTURE(seed);
    // Glued once and twice, every pair allowed: each region is a union of the
    // first ones, and the product of the regions' triangulations is the same.
    Regions R = k_order_skeleton(dt, k, structure.useful, {});
    RegionLimits all;
    all.max_states_per_region = 1'000'000;
    all.first_pass_states = all.max_states_per_region_dp = 0;
    all.max_region_triangles = 1'000;
    const auto product = [&](const Regions& g) {
      double p = 1;
      for (const Region& region : g.regions) {
        REQUIRE(region.complete);
        p *= static_cast<double>(region.states.size());
      }
      return p;
    };
    enumerate_regions(dt, R, all);
    const double want_count = product(R);
    for (int level = 1; level <= 2; ++level) {
      const Regions next = glue_pairs(dt, R, [](uint32_t, uint32_t) { return true; });
      CHECK(next.regions.size() <= R.regions.size());
      glued_runs += next.regions.size() < R.regions.size();
      for (uint32_t t = 0; t < dt.num_triangles(); ++t)
        for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
          const int32_t twin = dt.halfedges[e];
          if (twin < 0) continue;
          const bool apart = next.region_of_triangle[t] != next.region_of_triangle[static_cast<uint32_t>(twin) / 3];
          if (apart) CHECK(next.fixed[e]);  // (regions meet only at fixed edges)
          if (!next.fixed[e]) CHECK(!apart);
        }
      R = next;
      enumerate_regions(dt, R, all);
      CHECK(product(R) == want_count);
    }
    // The dual over the glued regions, each read through its graph.
    for (const auto& oi : objectives()) {
      if (objective_terms(oi.objective, dt).combine != Combine::Sum) continue;
      Regions forgotten = R;
      if (!forget_lists(forgotten)) continue;
      const RegionTerms forgotten_terms(dt, forgotten, oi.objective, &structure.candidates);
      const double want = k_order_brute_force(fo, oi.objective, k, 20'000'000).value;
      RegionDualLimits limits;
      limits.dual.max_sweeps = 1 + seed % 60;
      const RegionDual d = region_dual(dt, forgotten, oi.objective, structure.candidates, forgotten_terms, &dt, limits);
      const std::string name(oi.id);
      CAPTURE(name);
      if (!d.graphs || !d.bound) continue;
      ++runs;
      CHECK(not_past(oi.sense, *d.bound, want));
      tight += *d.bound == want;
      for (size_t i = 0; i < d.found.size(); ++i) {
        const Mesh m = mesh_of(dt.coords, d.found[i]);
        CHECK(is_k_order(m, dt, k));
        CHECK(not_past(oi.sense, want, evaluate(oi.objective, m)));
      }
      if (d.proven) {
        ++proven;
        double best = evaluate(oi.objective, dt);
        for (const double v : d.values)
          if (better(oi.sense, v, best)) best = v;
        if (d.optimum) best = evaluate(oi.objective, *d.optimum);
        CHECK(best == want);
      }
    }
  });
  MESSAGE(runs << " bounds over glued regions, " << tight << " equal to the optimum, " << proven << " proven; "
                << glued_runs << " gluings");
  CHECK(glued_runs > 300);
  CHECK(runs > 1000);
  CHECK(tight > runs / 2);
  CHECK(proven > runs / 2);
}
