// Optimising over k-th order Delaunay triangulations (k >= 1; paper Section 4.3).
//
// The fixed edges cut the hull into regions (regions.hpp); each region's k-OD
// triangulations are listed, and the objective's terms become a state graph
// over the regions (region_model.hpp). The solve is a table of phases
// (phases/phase_table.hpp) over one answer (phases/incumbent.hpp): the exact DP over a
// tree decomposition when every region is listed whole; else searches from the
// first order optimum and the order below, and proven bounds, until the bound
// meets the value (`optimal`) or the phases run out (the gap is known).
// Brute force (every k-OD triangulation of the whole instance, small inputs) is
// the reference the engine is tested against. Every returned triangulation is
// verified k-OD.
#pragma once
#include <functional>

#include "hodt/first_order.hpp"
#include "hodt/objectives.hpp"
#include "hodt/skeleton.hpp"
#include "hodt/solution.hpp"
#include "hodt/solve.hpp"
#include "higher_order/phases/k_order_result.hpp"
#include "higher_order/regions/regions.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

// Brute force at order k enumerates the whole instance: at most
// kBudgets.brute_force_max_points points.

// Calls visit for every k-OD triangulation of the points of `delaunay` (as a list
// of triangles); returns false if it stopped because `max_nodes` was reached.
// progress (if given) is called every few thousand nodes; returning false cancels.
bool enumerate_k_order(const Mesh& delaunay, uint32_t k, uint64_t max_nodes,
                       const std::function<void(const std::vector<Tri>&)>& visit, const Progress& progress = {});

// max_nodes: the enumeration budget of one region (brute force: of the instance).
KOrderResult solve_k_order(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options,
                           uint64_t max_nodes = kBudgets.region_max_nodes);
// The same with every budget of the regions' listing given (brute force:
// max_nodes_per_region for the instance). Tests shrink them so that small
// instances take the paths of large terrains, where regions stay incomplete.
KOrderResult solve_k_order(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options,
                           const RegionLimits& budgets);

// The same as a Solution (for the CLI and the bindings).
Solution k_order_solution(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options);

}  // namespace hodt
