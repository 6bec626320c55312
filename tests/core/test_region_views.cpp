// Region views (region_views.hpp): a model that reads regions through views
// bounds the optimum from the right side for every grouping of the items, and
// equals it when each region has a single view (the whole signature).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "hodt/delaunay.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/mesh.hpp"
#include "hodt/points.hpp"
#include "generators.hpp"
#include "higher_order/bounds/region_views.hpp"
#include "higher_order/bounds/view_bound.hpp"
#include "higher_order/k_order.hpp"
#include "higher_order/regions/region_model.hpp"
#include "higher_order/regions/regions.hpp"
#include "k_order_reference.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

bool close(double a, double b) { return a == b || std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

// The optimum of the model reading every region with a choice through views of
// at most `group` items each.
double views_optimum(const Mesh& dt, const Regions& R, const Candidates& cand, const RegionTerms& T, Objective o,
                     uint64_t group) {
  std::vector<std::vector<RegionView>> views(R.regions.size());
  RegionViewLimits vl;
  vl.max_items = group;
  vl.max_states = 2'000'000;
  vl.max_listed = 1'000'000;
  for (uint32_t r = 0; r < R.regions.size(); ++r) {
    if (R.regions[r].delaunay_triangles.size() < 2) continue;
    auto v = region_views(dt, cand, T, r, vl);
    REQUIRE(v);
    views[r] = std::move(*v);
  }
  return solve_states(region_model(dt, R, o, {}, {}, &views).graph).value;
}

// Mixed instances at k = 3 and 4, every objective, the regions listed within
// tiny budgets (most with a choice stay incomplete): visit(seed, fo, k, cand, R,
// T, objective) wherever some region is incomplete.
template <class Visit>
void with_incomplete_regions(uint64_t seeds, Visit visit) {
  for (uint64_t seed = 1; seed <= seeds; ++seed) {
    const FirstOrder fo = first_order(delaunay(validate_points(mixed_instance(seed * 11 + 3, 1)).xyz));
    const Mesh& dt = fo.base;
    for (uint32_t k : {3u, 4u}) {
      const Regions skeleton = k_order_skeleton(dt, k);
      const Candidates cand = k_order_candidates(dt, k, skeleton.useful);
      for (const auto& oi : objectives()) {
        Regions R = skeleton;
        const RegionTerms T(dt, R, oi.objective, &cand);
        RegionLimits rl;
        rl.terms = &T;
        rl.candidates = &cand;
        rl.first_pass_states = rl.max_states_per_region_dp = 3;
        rl.max_states_per_region = 2;
        rl.max_nodes_per_region = rl.first_pass_nodes = 3;
        enumerate_regions(dt, R, rl);
        if (R.incomplete) visit(seed, fo, k, cand, R, T, oi);
      }
    }
  }
}

}  // namespace

TEST_CASE("region views: one view per region is exact, smaller groups bound the optimum") {
  uint64_t checked = 0, strict = 0;
  for (uint64_t seed = 1; seed <= 150; ++seed) {
    const FirstOrder fo = first_order(delaunay(validate_points(mixed_instance(seed * 5 + 2, 1)).xyz));
    const Mesh& dt = fo.base;
    for (uint32_t k : {2u, 3u, 4u}) {
      const Regions R = k_order_skeleton(dt, k);
      const Candidates cand = k_order_candidates(dt, k, R.useful);
      for (const auto& oi : objectives()) {
        const double opt = k_order_brute_force(fo, oi.objective, k).value;
        const RegionTerms T(dt, R, oi.objective, &cand);
        CAPTURE(seed);
        CAPTURE(k);
        CAPTURE(std::string(oi.id));
        CHECK(close(views_optimum(dt, R, cand, T, oi.objective, UINT64_MAX), opt));
        for (uint64_t group : {1u, 2u, 3u}) {
          const double bound = views_optimum(dt, R, cand, T, oi.objective, group);
          CHECK((close(bound, opt) || better(oi.sense, bound, opt)));
          strict += !close(bound, opt);
          ++checked;
        }
      }
    }
  }
  MESSAGE(checked << " bounds, " << strict << " strictly weaker than the optimum");
  CHECK(strict > 0);  // (smaller groups do relax: the test sees both sides)
}

TEST_CASE("view bound: regions left incomplete are bounded through views, and a realised triangulation is optimal") {
  uint64_t bounded = 0, realised = 0, stopped = 0;
  with_incomplete_regions(80, [&](uint64_t seed, const FirstOrder& fo, uint32_t k, const Candidates& cand,
                                  const Regions& R, const RegionTerms& T, const auto& oi) {
    const Mesh& dt = fo.base;
    ViewBoundLimits vl;
    vl.views.max_states = 400;  // small views: several rounds
    vl.views.max_listed = 50;
    const auto vb = view_bound(dt, R, oi.objective, cand, T, 64, {}, {}, vl);
    if (!vb) return;
    const double opt = k_order_brute_force(fo, oi.objective, k).value;
    CAPTURE(seed);
    CAPTURE(k);
    CAPTURE(std::string(oi.id));
    CHECK((close(vb->bound, opt) || better(oi.sense, vb->bound, opt)));
    ++bounded;
    if (vb->realised) {
      ++realised;
      CHECK(is_k_order(*vb->realised, dt, k));
      CHECK(validate(*vb->realised) == "");
      CHECK(close(evaluate(oi.objective, *vb->realised), opt));
    }
    // With the optimum as the bound at hand, a round whose bound trails it is the last.
    const auto at_opt = view_bound(dt, R, oi.objective, cand, T, 64, {}, opt, vl);
    REQUIRE(at_opt);
    CHECK((close(at_opt->bound, opt) || better(oi.sense, at_opt->bound, opt)));
    CHECK(at_opt->rounds <= vb->rounds);
    if (at_opt->rounds < vb->rounds) {
      ++stopped;
      CHECK((!close(at_opt->bound, opt) && better(oi.sense, at_opt->bound, opt)));
    }
  });
  MESSAGE(bounded << " bounds, " << realised << " realised, " << stopped << " stopped by the bound at hand");
  CHECK(bounded > 100);
  CHECK(realised > 10);
  CHECK(stopped > 10);
}

TEST_CASE("region model: updated to read some regions through views, the same terms as built whole") {
  uint64_t compared = 0, split = 0, updates = 0;
  with_incomplete_regions(40, [&](uint64_t seed, const FirstOrder& fo, uint32_t k, const Candidates& cand,
                                  const Regions& R, const RegionTerms& T, const auto& oi) {
    const Mesh& dt = fo.base;
    // Every other incomplete region read through views (the rest keep their lists).
    std::vector<std::vector<RegionView>> views(R.regions.size());
    std::vector<uint8_t> changed(R.regions.size(), 0);
    RegionViewLimits vl;
    vl.max_states = 400;
    vl.max_listed = 50;
    vl.max_items = 1 + seed % 2;  // (several views per region)
    uint32_t incomplete = 0;
    for (uint32_t r = 0; r < R.regions.size(); ++r)
      if (!R.regions[r].complete && incomplete++ % 2 == 0)
        if (auto v = region_views(dt, cand, T, r, vl)) views[r] = std::move(*v), changed[r] = 1, ++split;
    if (std::find(changed.begin(), changed.end(), 1) == changed.end()) return;
    CAPTURE(seed);
    CAPTURE(k);
    CAPTURE(std::string(oi.id));
    const RegionModel whole = region_model(dt, R, oi.objective, {}, {}, &views);
    const RegionModel updated =
        update_region_model(region_model(dt, R, oi.objective), dt, R, oi.objective, changed, {}, {}, &views);
    CHECK(whole.graph.relaxed_terms == updated.graph.relaxed_terms);
    // (Updated, not built whole, where a region has views of two states or
    // more besides its first: their variables come after all the others.)
    updates += !std::is_sorted(updated.region_of_variable.begin(), updated.region_of_variable.end());
    // Variables by (region, view): the same domains (a first view of one
    // state: none, or the region's variable of one state), equal values on
    // every assignment tried.
    Rng rng(seed * 13 + k);
    for (int t = 0; t < 20; ++t) {
      std::map<std::pair<uint32_t, uint32_t>, uint32_t> pick;
      auto assign = [&](const RegionModel& M) {
        std::vector<uint32_t> state(M.region_of_variable.size());
        for (size_t x = 0; x < state.size(); ++x) {
          const std::pair<uint32_t, uint32_t> key{M.region_of_variable[x], M.view_of_variable[x]};
          auto it = pick.find(key);
          if (it == pick.end()) it = pick.emplace(key, static_cast<uint32_t>(rng.below(M.graph.domain[x]))).first;
          CHECK(it->second < M.graph.domain[x]);
          state[x] = it->second;
        }
        return state;
      };
      const std::vector<uint32_t> a = assign(whole), b = assign(updated);
      CHECK(close(evaluate_states(whole.graph, a), evaluate_states(updated.graph, b)));
    }
    ++compared;
  });
  MESSAGE(compared << " models compared (" << updates << " with views' variables after the others), " << split
                   << " regions read through views");
  CHECK(compared > 100);
  CHECK(updates > 50);
}
