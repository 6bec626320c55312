// The dynamic program over partial fills (fill_dp.hpp) against plain
// enumeration of each region's triangulations: the same signatures, each with
// the same best value; and the neighbour-class summaries against the terms.
#include <doctest/doctest.h>

#include <cmath>
#include <map>

#include "hodt/delaunay.hpp"
#include "hodt/measures.hpp"
#include "hodt/points.hpp"
#include "generators.hpp"
#include "higher_order/regions/fill_dp.hpp"
#include "higher_order/fills/fill_enumerator.hpp"
#include "higher_order/regions/region_terms.hpp"
#include "higher_order/regions/regions.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

bool close(double a, double b) { return a == b || std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)); }

}  // namespace

TEST_CASE("fill DP: the best triangulation of every signature, as enumeration finds it") {
  uint64_t regions_checked = 0;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    const Mesh dt = first_order(delaunay(validate_points(mixed_instance(seed, 2)).xyz)).base;
    for (uint32_t k : {2u, 3u, 4u}) {
      const Regions R = k_order_skeleton(dt, k);
      const Candidates cand = k_order_candidates(dt, k, R.useful);
      for (const auto& oi : objectives()) {
        const RegionTerms T(dt, R, oi.objective, &cand);  // (apex kinds, harmless triangles)
        for (uint32_t r = 0; r < R.regions.size(); ++r) {
          if (R.regions[r].delaunay_triangles.size() < 2) continue;
          std::map<std::vector<SignatureEntry>, double> listed;
          const bool complete = enumerate_fills(dt, cand, R.regions[r].boundary, 200'000, [&](const std::vector<Tri>& tris) {
            const StateKey key = T.key(r, tris);
            auto [it, fresh] = listed.try_emplace(key.signature, key.value);
            if (!fresh && T.better(key.value, it->second)) it->second = key.value;
          });
          if (!complete) continue;
          const auto fills = best_fills(dt, cand, T, r, 2'000'000);
          REQUIRE(fills);
          CAPTURE(seed);
          CAPTURE(k);
          CAPTURE(std::string(oi.id));
          CAPTURE(r);
          std::map<std::vector<SignatureEntry>, double> found;
          for (const BestFill& f : *fills) {
            const StateKey key = T.key(r, f.triangles);
            CHECK(close(key.value, f.value));  // the DP's running value is the triangulation's
            CHECK(found.emplace(key.signature, key.value).second);  // one fill per signature
          }
          REQUIRE(found.size() == listed.size());
          for (const auto& [signature, value] : listed) {
            const auto it = found.find(signature);
            REQUIRE(it != found.end());
            CHECK(close(it->second, value));
          }
          ++regions_checked;
        }
      }
    }
  }
  CHECK(regions_checked > 1000);
}

TEST_CASE("fill DP: a budget too small is reported, not answered") {
  const Mesh dt = first_order(delaunay(validate_points(uniform_points(60, 7)).xyz)).base;
  const Regions R = k_order_skeleton(dt, 4);
  const Candidates cand = k_order_candidates(dt, 4, R.useful);
  const RegionTerms T(dt, R, Objective::MinmaxEdgeAreaRatio);
  bool refused = false;
  for (uint32_t r = 0; r < R.regions.size(); ++r) {
    if (R.regions[r].delaunay_triangles.size() <= 6) continue;
    // How far the sweep got: a share of the triangles, 1 only when it fits.
    double tight = -1, wide = -1;
    const bool fits = best_fills(dt, cand, T, r, 10, {}, nullptr, nullptr, &tight).has_value();
    refused = refused || !fits;
    CHECK((fits ? tight == 1 : tight >= 0 && tight < 1));
    if (!fits && best_fills(dt, cand, T, r, 2'000'000, {}, nullptr, nullptr, &wide)) CHECK(wide == 1);
  }
  CHECK(refused);
}

TEST_CASE("neighbour classes give the same vertex terms as the stars they summarise") {
  for (uint64_t seed = 1; seed <= 30; ++seed) {
    const Mesh m = delaunay(validate_points(seed % 2 ? dem_points(80, seed) : grid_points(7, 7, seed, true)).xyz);
    const Stars st = build_stars(m);
    for (const auto& oi : objectives()) {
      const ObjectiveTerms& d = objective_terms(oi.objective, m);
      if (!d.neighbor_class) continue;
      for (uint32_t v = 0; v < m.num_vertices(); ++v) {
        std::vector<uint32_t> nb(st.neighbor.begin() + st.offset[v], st.neighbor.begin() + st.offset[v + 1]);
        const std::vector<Tri> none;
        CHECK(d.term_of_classes(neighbor_classes(d, m, v, nb)) == vertex_term(d, m, Star(v, nb, none)));
      }
    }
  }
}

TEST_CASE("regions: a second pass with larger budgets lists the incomplete regions as one pass with those budgets does") {
  int passes = 0, whole = 0;
  for (uint64_t seed = 1; seed <= 24; ++seed) {
    const Mesh dt = first_order(delaunay(validate_points(uniform_points(150, seed)).xyz)).base;
    for (uint32_t k : {3u, 4u}) {
      for (Objective o : {Objective::MaxConvexEdges, Objective::MinMixedVertices, Objective::MaxConvexVertices}) {
        Regions R = k_order_skeleton(dt, k);
        const Candidates cand = k_order_candidates(dt, k, R.useful);
        const RegionTerms T(dt, R, o, &cand);
        RegionLimits small;
        small.terms = &T;
        small.candidates = &cand;
        small.first_pass_states = small.max_states_per_region_dp = 40;
        small.max_total_states = 200;
        small.max_states_per_region = 4;
        small.first_pass_nodes = 20, small.max_nodes_per_region = 50, small.max_total_nodes = 300;
        enumerate_regions(dt, R, small);
        if (!R.incomplete) continue;
        const std::vector<Region> before = R.regions;
        RegionLimits wide = small;
        wide.only_incomplete = true;
        wide.max_states_per_region = 100'000;
        wide.max_states_per_region_dp = 1'000'000;
        wide.max_total_states = 4'000'000;
        enumerate_regions(dt, R, wide);
        ++passes;
        CAPTURE(seed);
        CAPTURE(k);
        CAPTURE(static_cast<int>(o));
        for (size_t r = 0; r < R.regions.size(); ++r)
          if (before[r].complete) CHECK(R.regions[r].states == before[r].states);  // (kept as they were)
        if (R.incomplete) continue;  // (a region over even these budgets: the caller keeps its first listing)
        ++whole;
        // One pass with the larger budgets lists the same signatures with the same best values.
        Regions one = k_order_skeleton(dt, k);
        const RegionTerms T1(dt, one, o, &cand);
        RegionLimits big = wide;
        big.only_incomplete = false;
        big.terms = &T1;
        enumerate_regions(dt, one, big);
        REQUIRE(!one.incomplete);
        for (size_t r = 0; r < R.regions.size(); ++r) {
          std::map<std::vector<SignatureEntry>, double> a, b;
          for (const auto& s : R.regions[r].states) a.emplace(T.key(static_cast<uint32_t>(r), s).signature, T.key(static_cast<uint32_t>(r), s).value);
          for (const auto& s : one.regions[r].states) b.emplace(T1.key(static_cast<uint32_t>(r), s).signature, T1.key(static_cast<uint32_t>(r), s).value);
          CHECK(a == b);
        }
      }
    }
  }
  MESSAGE(passes << " second passes, " << whole << " listing every region whole");
  CHECK(whole > 10);
}
