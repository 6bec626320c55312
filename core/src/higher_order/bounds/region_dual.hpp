// A proven bound for counts over k-OD models whose regions are too large to
// list: a Lagrangian dual in which each such region is one factor, read
// through its fill graph (fill_graph.hpp), and never listed.
//
// A region too large to list gets one variable per item (a shared vertex or
// edge): its states are the item's entries, each stood for by one fill that
// takes it (a view of that item alone, region_views.hpp). The shared terms read
// these variables as they read any region's states. The region itself becomes
// an implicit factor over them: a set of entries costs the region's own terms
// of the best fill that takes them all, +infinity if none does. Every k-OD
// triangulation is an assignment of the same value, so the dual bound
// (dual_bound.hpp) over this model bounds the optimum, however large the
// region. Regions whose fill graph is itself too large are left to the
// relaxation (their terms at their best).
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "engines/dual_bound.hpp"
#include "higher_order/fills/fill_enumerator.hpp"
#include "higher_order/regions/region_model.hpp"
#include "higher_order/regions/region_terms.hpp"
#include "higher_order/regions/regions.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

// (Defaults and reasons: tuning/budgets.hpp, fill_graph_*.)
struct RegionDualLimits {
  // Partial fills of one region's graph: every region first gets first_states,
  // then those left max_states each (smallest first; when more than max_second
  // are left, until max_second_failures in a row do not fit); max_total over
  // all, those that did not fit included, or max_total_per_point per point
  // when that is more.
  uint64_t first_states = kBudgets.fill_graph_first_states;
  uint64_t max_states = kBudgets.fill_graph_max_states;
  uint32_t max_second = kBudgets.fill_graph_max_second;
  uint32_t max_second_failures = kBudgets.fill_graph_max_second_failures;
  uint64_t max_total = kBudgets.fill_graph_max_total;
  uint64_t max_total_per_point = kBudgets.fill_graph_max_total_per_point;
  uint32_t restarts = kBudgets.fill_graph_restarts;  // descents from the dual's states, regions shuffled
  // The proof lists, per region, the fills that could beat the incumbent.
  uint64_t max_listed = kBudgets.fill_graph_max_listed;  // per region
  uint64_t max_listed_total = kBudgets.fill_graph_max_listed_total;
  uint32_t short_rounds = kBudgets.fill_graph_short_rounds;  // proving rounds before the last
  DualLimits dual;
  StateDpLimits dp;                    // for the DP over what the proof lists
  RegionModelLimits model;             // the models over the regions listed whole
};

struct RegionDual {
  std::optional<double> bound;  // no k-OD triangulation is better (nothing: the dual does not apply)
  // k-OD triangulations (their triangles) found by block coordinate descent,
  // each region read through its graph taking its best fill for the others'
  // entries: from the dual's decoded states (the regions in their order, then
  // shuffled until one meets the bound), and from `start`.
  std::vector<std::vector<Tri>> found;
  std::vector<double> values;  // of each found, evaluated
  // The proof, with a start and every region read through a graph: each
  // graph pruned to the fills whose bound allows a better value than the best
  // triangulation at hand (the start's or one found), those listed, and the
  // dual proof (its pruning and exact DP) over the model, now whole.
  bool proven = false;           // no k-OD triangulation beats the best at hand ...
  std::optional<Mesh> optimum;   // ... or this one, which does (then optimal)
  double optimum_value = 0;      // (its value in the model: the caller checks it against the mesh)
  uint64_t listed = 0;           // fills the proof listed
  uint32_t tightened = 0;        // units its targets short of the ascent's bound took off it
  uint32_t graphs = 0;    // regions read through their fill graph
  std::vector<uint32_t> graph_nodes;  // ... per region, its graph's partial fills (0: none)
  uint32_t relaxed = 0;   // regions not listed whole left to the relaxation
};

// start: a k-OD triangulation whose part in every region is listed (add_states_of),
// its value the ascent's stop (it stops once that is proven optimal).
// model_of_R (when given): a model of these regions, or of the same ones but for
// some not listed whole (region_model.hpp): the proof's models are its updates.
RegionDual region_dual(const Mesh& delaunay, const Regions& regions, Objective o, const Candidates& candidates,
                       const RegionTerms& terms, const Mesh* start = nullptr, const RegionDualLimits& limits = {},
                       const RegionModel* model_of_R = nullptr);

// Min-max objectives (terms combined by max, minimised) by thresholds: at a
// threshold t, how many terms exceed t is a count over the same model (each
// table entry, state and arc 1 if its value exceeds t), and a dual bound above 0
// proves that every triangulation has a term above t, so the optimum is at
// least the next value a term can take. A binary search over those values,
// from `known` (a bound already proven, at least RegionTerms::floor) up to
// `incumbent` (the value of a triangulation at hand), keeps the largest t so
// refuted. Returns the bound (`incumbent` itself when it is optimal), nothing
// when no threshold is refuted or no region has a graph.
std::optional<double> region_threshold_bound(const Mesh& delaunay, const Regions& regions, Objective o,
                                             const Candidates& candidates, const RegionTerms& terms, double known,
                                             double incumbent, const RegionDualLimits& limits = {});

}  // namespace hodt
