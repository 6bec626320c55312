// The budgets of the order-k solve's phases, each with its default and why.
// (The regions' listing budgets are RegionLimits, regions.hpp; the exact DP's,
// the duals' and the views' own defaults are their engines' limits, which the
// phases override only through the fields below.)
#pragma once
#include <cstdint>

namespace hodt {

struct PhaseBudgets {
  // Branch and bound over every fill of the instance (min-max): on inputs of at
  // most this many points, within this many search nodes. Small inputs at high
  // order have one region of astronomically many triangulations, which the
  // regions' engine can only bound, while the terms' pruning proves them. It
  // runs where the exact DP refused.
  // (A node tests every candidate of the frontier, so its cost grows with the
  // input: the budget keeps a search that cannot finish short beside the rest.)
  uint32_t branch_and_bound_points = 80;
  uint64_t branch_and_bound_nodes = 60'000;
  // Its memo of partial fills searched to the end (fill_search.hpp), in 32-bit
  // words: a key is a frontier and what the terms read of the triangles
  // behind it, a few dozen words, so this holds one for most of the nodes.
  // (Once full, the search goes on without storing more.)
  uint64_t branch_and_bound_memo_words = uint64_t{1} << 22;
  // The dual over the regions' fill graphs: sweeps of its ascent. Strips side by
  // side couple along whole boundaries and the ascent climbs slowly, so the
  // bound keeps tightening long after the first hundred sweeps.
  uint32_t dual_sweeps = 1500;
  // A ladder's rung from order 5 on wants the dual's descents (a better start
  // for the order above), not its bound: a short ascent gives most of them.
  uint32_t rung_dual_sweeps = 150;
  // The quick reading of the fill graphs before a ladder's lower order (counts,
  // k < 5): long enough to prove what a proof is near for, short enough that a
  // reading that proves nothing costs little beside the lower order.
  uint32_t quick_sweeps = 150;
  // Levels of gluing the regions' fill graphs in pairs: each level costs a dual
  // as large as the first.
  uint32_t max_glue = 2;
  // At most this many regions read through their graphs are glued: each level
  // over hundreds of strips costs as much as the whole solve before it.
  uint32_t max_glued = 128;
  // The second, wider listing of the regions over the first budgets is tried
  // only when each such region had placed at least this share of its triangles
  // when its first pass ran out: a frontier still widening will not fit a
  // budget many times larger, and the pass that fails costs as much as the rest.
  double list_whole_min_swept = 0.7;
  // That listing's budgets: several times the first pass's, for regions whose
  // signatures are many but whose frontier stays narrow.
  uint64_t list_whole_states_per_region = 100'000;
  uint64_t list_whole_states_per_region_dp = 500'000;
  uint64_t list_whole_total_states = 1'500'000;
  // The dual proof over a whole model: clusterings of these many table entries,
  // tried in turn (the larger, the tighter relaxation). Each ascent stops at a
  // fixed point of its own, and a proof turns on the bound passing an integer,
  // so either may prove what the other cannot.
  double dual_clusters[2] = {4096, 1024};
  // Min-max thresholds refuted over the regions' fill graphs: sweeps per threshold.
  uint32_t threshold_sweeps = 100;
  // The last order whose ladder rung is k - 1; above, the rung is k / 2 (each
  // rung costs about as much as its order, and halving keeps the ladder short).
  uint32_t rung_step_max_order = 8;
  // From this order on the rung is solved before this order's structures are
  // built (one order's regions in memory at a time), and the quick fill-graph
  // reading is skipped: the exact engine rarely answers there on large inputs.
  uint32_t early_rung_order = 5;
  // The dual proof's rounds per clustering (each prunes by the bound, tries the
  // DP over what is left, else raises the bound and prunes again): the next
  // clustering is a tighter relaxation, worth more than a third round.
  uint32_t dual_proof_rounds = 2;
  // Local search from the dual's decoded states: windows of this many
  // variables, each solved by a DP within this table (many small windows move
  // further than a few large ones in the same time).
  uint32_t dual_window_variables = 24;
  double dual_window_table = 1 << 16;
  // What a proof's pruning leaves is far smaller than the model: its DP (and
  // the DP over the fill graphs' listed states) may use a table this large.
  double pruned_dp_table = 1 << 24;
  // Descents by windows of fans around the stars' decoding: at most this many
  // placements of the tiles in all, and these window sizes in turn after the
  // decoding (a move that no window of one size holds may fit one of the next).
  uint32_t fan_window_placements = 16;
  uint32_t fan_window_sizes[4] = {25, 40, 64, 102};
};

}  // namespace hodt
