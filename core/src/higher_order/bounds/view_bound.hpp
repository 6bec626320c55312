// The bound of a k-OD model whose largest regions are read through views
// (region_views.hpp), refined where the views disagree.
//
// The relaxation's optimum picks one state per view. Where the first view's state
// of a region agrees with every other view's state on that view's items, the
// first view alone realises what the relaxation counted for the region. If it does
// so in every region (and none is left unlisted), the states form a k-OD
// triangulation whose value is the bound: it is optimal. Otherwise the regions
// whose views disagree get larger groups (fewer, more exact views) and the model is
// solved again, within a budget of rounds and of partial fills.
#pragma once
#include <optional>

#include "higher_order/bounds/region_views.hpp"
#include "higher_order/regions/region_model.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

struct ViewBound {
  double bound;               // proven: no k-OD triangulation is better
  std::optional<Mesh> realised;  // a triangulation of value `bound`, when the views agreed
  uint32_t rounds = 0;
  uint32_t split_regions = 0;  // regions read through views in the last round
};

struct ViewBoundLimits {
  RegionViewLimits views;
  uint32_t max_rounds = kBudgets.view_max_rounds;  // (tuning/budgets.hpp)
  uint64_t max_total_states = kBudgets.view_max_total_states;  // partial fills over all views' DPs
  StateDpLimits dp;
  RegionModelLimits model;  // the models over the views
};

// Nothing when no region can be read through views (or the DP does not fit).
// known: the value of a triangulation in hand; the rounds stop once the bound meets it.
// at_hand: a bound proven otherwise; the rounds stop once one's bound trails it,
// as each refines with more partial fills than the last: the rounds left cost
// more than those run, for a bound that may still not pass the one at hand.
std::optional<ViewBound> view_bound(const Mesh& delaunay, const Regions& regions, Objective o,
                                    const Candidates& candidates, const RegionTerms& terms,
                                    uint32_t max_region_triangles, std::optional<double> known = {},
                                    std::optional<double> at_hand = {}, const ViewBoundLimits& limits = {});

}  // namespace hodt
