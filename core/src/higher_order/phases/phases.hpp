// The phases of an order-k solve, each a step over one KOrderRun that offers
// triangulations to its answer or tightens its bound. When each runs is the
// table's (phase_table.cpp); each says here what it does and why it is sound.
#pragma once
#include "higher_order/phases/k_order_run.hpp"

namespace hodt {

// --- Shortcuts (shortcuts.cpp) ---
// The first order optimum, when it meets a bound that every triangulation of
// the points meets (ObjectiveTerms::global_bound).
void meet_global_bound(KOrderRun& run);
// When every region is a quad or a triangle, the k-OD triangulations are the
// choices of a diagonal per quad: a singly flippable structure, which the first
// order solvers take as it is; their answer is final.
void solve_as_quads(KOrderRun& run);

// Min-max on small inputs: branch and bound over every k-OD triangulation of
// the instance, within a node budget (branch_and_bound.hpp).
void branch_and_bound_small(KOrderRun& run);
// Min-max: "is any k-OD triangulation better than the answer?" as SAT, asked
// until the answer is no (threshold_sat.hpp), within budgets of conflicts and work.
void refute_by_sat(KOrderRun& run);
// The same on a larger input, where a gap is left, within its own work budget.
void refute_gap_by_sat(KOrderRun& run);

// --- The regions and their engine (regions_phases.cpp) ---
// The useful edges of every order up to k, and the regions the fixed ones cut.
void find_regions(KOrderRun& run);
// The regions' triangulations listed, their terms and state-graph model.
void build_engine(KOrderRun& run);
// A second, larger listing of the regions over the first budgets, kept only if
// it lists every region whole (then the exact DP may run).
void list_whole(KOrderRun& run);
// The DP over a tree decomposition of the regions' model: exact.
void solve_exactly(KOrderRun& run);

// --- The start and the ladder (start_phases.cpp) ---
// The search's start: the first order optimum (at order 1, Delaunay).
void take_start(KOrderRun& run);
// A min-max proof of the start (the terms' floor, or arc consistency).
void prove_start(KOrderRun& run);
// The start's parts listed in the regions not listed whole.
void list_start(KOrderRun& run);
// The ladder's rung below: every j-OD triangulation (j < k) is k-OD, so the
// answer at order j is one more listed triangulation per region and a start
// no worse.
void solve_lower_order(KOrderRun& run);
// The rung's answer listed in the regions, and the start when better.
void start_from_lower_order(KOrderRun& run);
// Counts with regions not listed whole: a short reading of their fill graphs
// from the best listed combination, before the ladder's rung. Proof or nothing:
// else the regions are left as they were.
void quick_fill_graph_proof(KOrderRun& run);

// --- Search (search_phases.cpp) ---
// The best combination of the regions' listed triangulations (the start's among
// them): by the DP when its tables fit, else over mini-buckets and local search.
void best_listed(KOrderRun& run);
// Baker's shifting at order k (the paper's Theorem 10).
void shift_bands(KOrderRun& run);
// k-OD flips that improve the terms around them (they reach into the regions
// too large to list).
void flip(KOrderRun& run);
// A rung's answer improved by the descents of a reading of the fill graphs.
void descend_fill_graphs(KOrderRun& run);
// The vertices' stars: their bound, the triangulations read off their
// multipliers, and descents by windows of fans (star_search.cpp).
void search_stars(KOrderRun& run);

// --- Bounds (bound_phases.cpp) ---
// The model's relaxation: every term that sees a region not listed whole at its best.
void relax(KOrderRun& run);
// Min-max: the largest term that no region can change.
void floor_terms(KOrderRun& run);
// Counts: the Lagrangian dual, which prunes what cannot beat the answer and
// proves it optimal by the DP over the rest, or tightens the bound.
void prove_by_dual(KOrderRun& run);
// The regions too large to list read through their views.
void view_regions(KOrderRun& run);
// Min-max over regions not listed whole: thresholds refuted by the dual over
// their fill graphs.
void refute_thresholds(KOrderRun& run);
// Min-max: every vertex takes one of its fans; each fan's worst term bounds.
void floor_fans(KOrderRun& run);
// The regions' fill graphs glued in pairs and read again.
void glue_fill_graphs(KOrderRun& run);

}  // namespace hodt
