// An objective over the k-OD triangulations as a state graph: one variable per
// region with a choice, its states the region's triangulations, and the
// objective's terms (objective_terms.hpp) as factors over the regions each term
// can see: a vertex term over the regions around the vertex (through the fan each
// state puts at the vertex), an edge term on a fixed edge over the regions on its
// two sides (through the apex), everything inside one region as its unary.
//
// A relaxation may read some regions through views (region_views.hpp): one
// variable per view, each item's terms read from the view that speaks for it, the
// region's own terms from its first view. Its optimum bounds the true one; its
// assignments are not triangulations (region_states reads first views only).
#pragma once
#include "hodt/objectives.hpp"
#include "engines/state_graph.hpp"
#include "higher_order/regions/regions.hpp"
#include "higher_order/regions/vertex_term_memo.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

// A view of a region (bounds/region_views.hpp): the items of its signature it
// speaks for, and its best triangulations, one per signature restricted to them.
struct RegionView {
  std::vector<Tri> items;                // sorted
  std::vector<std::vector<Tri>> states;
};

struct RegionModel {
  StateGraph graph;
  std::vector<uint32_t> region_of_variable;
  std::vector<int32_t> variable_of_region;  // -1 for a region with one state
  std::vector<uint32_t> view_of_variable;   // with views: which of its region's views (else 0)
  // Per region, its state for an assignment of the variables.
  std::vector<uint32_t> region_states(const std::vector<uint32_t>& variable_state) const;
  // The variables' states for per-region states.
  std::vector<uint32_t> variable_states(const std::vector<uint32_t>& region_state) const;
};

struct RegionModelLimits {
  double max_factor = kBudgets.region_model_max_factor;  // entries of one vertex factor (larger: relaxed)
  // Vertex terms remembered across the models of one solve (one objective, one
  // Delaunay triangulation; none within a domain: vertex_term_memo.hpp).
  VertexTermMemo* memo = nullptr;
};

// views: per region, nothing or its views (a relaxation, as above).
RegionModel region_model(const Mesh& delaunay, const Regions& regions, Objective o,
                         const RegionModelLimits& limits = {}, const Progress& progress = {},
                         const std::vector<std::vector<RegionView>>* views = nullptr);

// The model of `regions` from M, the model of the same regions before the
// ones marked `changed` (per region) changed their triangulations: only the
// terms that read a changed region are built again (a few incomplete regions
// of many given more triangulations: most of the model is kept). views (as
// region_model's, for changed regions only): those read through views from
// now on, their first view through the region's variable, the others'
// variables after all the others (as the fill graphs' model is built from
// the engine's).
// The same model as region_model's, its variables and factors in another order,
// except that a changed region left with one triangulation (or a first view of
// one) keeps its variable (of one state); built whole where M has relaxed terms
// or views, or a region gains its variable.
RegionModel update_region_model(RegionModel M, const Mesh& delaunay, const Regions& regions, Objective o,
                                const std::vector<uint8_t>& changed, const RegionModelLimits& limits = {},
                                const Progress& progress = {},
                                const std::vector<std::vector<RegionView>>* views = nullptr);

}  // namespace hodt
