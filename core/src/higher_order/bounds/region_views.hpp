// Views of a region too large to list by signature, for a relaxation bound.
//
// A region's signature (region_terms.hpp) speaks of items: its shared vertices
// and the boundary edges whose apex the region beside sees. Split the items into
// groups; each group's view lists the best triangulation per signature restricted
// to that group (fill_dp.hpp with keep_items), so each view stays small. For any
// triangulation T of the region, every view has a state that agrees with T on its
// group, and the first view's state decides the region's own terms at least as
// well as T does. A model that reads each item from its group's view, and the
// region's own terms from the first view only, therefore has an optimum at least
// as good as the true one: a proven bound, tight when the views happen to agree.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "higher_order/fills/fill_enumerator.hpp"
#include "higher_order/regions/region_model.hpp"
#include "higher_order/regions/region_terms.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

struct RegionViewLimits {
  uint64_t max_states = kBudgets.view_max_states;  // partial fills of one view's DP (tuning/budgets.hpp)
  uint64_t max_listed = kBudgets.view_max_listed;  // triangulations kept per view
  uint64_t max_items = UINT64_MAX;  // items per group (tests force small groups)
  uint64_t* states_used = nullptr;  // adds the partial fills of every DP tried
  Progress progress;
};

// The views of region r: groups of consecutive items (boundary order), halved
// until each view's DP fits the limits. Nothing if a single item does not fit.
// The first view holds the region's own terms (it exists even without items).
std::optional<std::vector<RegionView>> region_views(const Mesh& delaunay, const Candidates& candidates,
                                                    const RegionTerms& terms, uint32_t r,
                                                    const RegionViewLimits& limits = {});

}  // namespace hodt
