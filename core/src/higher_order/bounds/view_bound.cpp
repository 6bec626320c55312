#include "higher_order/bounds/view_bound.hpp"

#include <algorithm>

#include "engines/dual_bound.hpp"
#include "mesh/mesh_of.hpp"

namespace hodt {

namespace {

// The entries of a triangulation's signature about the given (sorted) items.
std::vector<SignatureEntry> entries_about(const RegionTerms& T, uint32_t r, const std::vector<Tri>& tris,
                                          const std::vector<Tri>& items) {
  std::vector<SignatureEntry> out;
  for (SignatureEntry& e : T.key(r, tris).signature)
    if (std::binary_search(items.begin(), items.end(), RegionTerms::item_of(e))) out.push_back(std::move(e));
  return out;
}

size_t largest_group(const std::vector<RegionView>& views) {
  size_t g = 1;
  for (const RegionView& v : views) g = std::max(g, v.items.size());
  return g;
}

}  // namespace

std::optional<ViewBound> view_bound(const Mesh& dt, const Regions& R, Objective o, const Candidates& cand,
                                    const RegionTerms& T, uint32_t max_region_triangles, std::optional<double> known,
                                    std::optional<double> at_hand, const ViewBoundLimits& limits) {
  const size_t n = R.regions.size();
  std::vector<std::vector<RegionView>> views(n);
  std::vector<RegionViewLimits> per(n, limits.views);  // each region's current limits
  std::vector<uint8_t> refine(n, 0), retry(n, 0);  // retry: its views did not fit, try again with more
  for (uint32_t r = 0; r < n; ++r) {
    refine[r] = !R.regions[r].complete && R.regions[r].delaunay_triangles.size() <= max_region_triangles;
    // (its whole signature did not fit: start from halves)
    if (refine[r]) per[r].max_items = std::min<uint64_t>(per[r].max_items, (T.items(r).size() + 1) / 2);
  }
  uint64_t used = 0;
  for (auto& p : per) p.states_used = &used;
  std::optional<ViewBound> out;
  for (uint32_t round = 0; round < limits.max_rounds && used < limits.max_total_states; ++round) {
    bool any = false;
    for (uint32_t r = 0; r < n; ++r) {
      if ((!refine[r] && !retry[r]) || used >= limits.max_total_states) continue;  // (over budget: left as they are)
      retry[r] = 0;
      if (auto v = region_views(dt, cand, T, r, per[r])) views[r] = std::move(*v), any = true;
      else retry[r] = 1, per[r].max_states *= 4, any = true;
    }
    if (!any) break;
    const RegionModel M = region_model(dt, R, o, limits.model, limits.views.progress, &views);
    // Where the tables are too large, mini-buckets: still a bound, but their
    // assignment is no optimum to refine the views by, so the rounds stop.
    StateDpLimits dp = limits.dp;
    dp.mini_buckets = true;
    const StateGraph relaxed = relaxation(M.graph);
    const StateDpResult sol = solve_states(relaxed, dp);
    ViewBound b;
    b.bound = out ? tighter(info(o).sense, out->bound, sol.value) : sol.value;  // (every round's is a bound)
    b.rounds = round + 1;
    if (sol.bound_only) {
      // (counts: the dual bound is usually far tighter than mini-buckets)
      DualLimits dual;
      dual.progress = limits.dp.progress;
      if (const std::optional<double> d = DualProof(relaxed, dual).bound()) b.bound = tighter(info(o).sense, b.bound, *d);
      b.split_regions = out ? out->split_regions : 0;
      out = std::move(b);
      break;
    }
    // The solution's state of each region's list, or of each of its views (0
    // where a list or view has no variable: one state).
    bool realised = true;
    std::vector<std::vector<uint32_t>> pick(n);
    for (uint32_t r = 0; r < n; ++r) pick[r].assign(std::max<size_t>(1, views[r].size()), 0);
    for (size_t x = 0; x < M.region_of_variable.size(); ++x) {
      if (M.graph.partial[x]) realised = false;  // (a region neither listed nor read through views)
      else pick[M.region_of_variable[x]][M.view_of_variable[x]] = sol.state[x];
    }
    auto state = [&](uint32_t r, size_t j) -> const std::vector<Tri>& {
      return views[r].empty() ? R.regions[r].states[pick[r][0]] : views[r][j].states[pick[r][j]];
    };
    // Regions whose first view disagrees with another view on that view's items.
    std::fill(refine.begin(), refine.end(), 0);
    for (uint32_t r = 0; r < n; ++r) {
      if (views[r].empty()) continue;
      ++b.split_regions;
      for (size_t j = 1; j < views[r].size() && !refine[r]; ++j)
        refine[r] = entries_about(T, r, state(r, 0), views[r][j].items) !=
                    entries_about(T, r, state(r, j), views[r][j].items);
      if (refine[r]) {
        realised = false;
        per[r].max_items = 2 * largest_group(views[r]);
        per[r].max_states *= 2;
        per[r].max_listed *= 2;
      }
    }
    if (realised) {  // the first views' triangulations: kept if (evaluated exactly) they meet the bound
      std::vector<Tri> tris;
      for (uint32_t r = 0; r < n; ++r) tris.insert(tris.end(), state(r, 0).begin(), state(r, 0).end());
      Mesh m = mesh_of(dt.coords, tris);
      const double v = evaluate(o, m);
      if (!better(info(o).sense, b.bound, v)) b.bound = v, b.realised = std::move(m);
    }
    const bool trails = at_hand && better(info(o).sense, b.bound, *at_hand);
    out = std::move(b);
    // Nothing left to prove, or the views trail the bound at hand.
    if (out->realised || (known && !better(info(o).sense, out->bound, *known)) || trails) break;
  }
  return out;
}

}  // namespace hodt
