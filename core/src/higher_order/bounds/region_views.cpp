#include "higher_order/bounds/region_views.hpp"

#include <algorithm>

#include "higher_order/regions/fill_dp.hpp"

namespace hodt {

std::optional<std::vector<RegionView>> region_views(const Mesh& dt, const Candidates& cand, const RegionTerms& terms,
                                                    uint32_t r, const RegionViewLimits& limits) {
  const std::vector<Tri> items = terms.items(r);
  std::vector<RegionView> views;
  // Lists the view of items [a, b); halves the range when it does not fit.
  auto list = [&](auto&& self, size_t a, size_t b) -> bool {
    RegionView view;
    view.items.assign(items.begin() + static_cast<std::ptrdiff_t>(a), items.begin() + static_cast<std::ptrdiff_t>(b));
    std::sort(view.items.begin(), view.items.end());
    std::optional<std::vector<BestFill>> fills;
    if (b - a <= limits.max_items) fills = best_fills(dt, cand, terms, r, limits.max_states, limits.progress, limits.states_used, &view.items);
    if (fills && fills->size() <= limits.max_listed) {
      for (BestFill& f : *fills) view.states.push_back(std::move(f.triangles));
      views.push_back(std::move(view));
      return true;
    }
    if (b - a <= 1) return false;
    const size_t m = a + (b - a) / 2;
    return self(self, a, m) && self(self, m, b);
  };
  if (!list(list, 0, items.size())) return std::nullopt;
  return views;
}

}  // namespace hodt
