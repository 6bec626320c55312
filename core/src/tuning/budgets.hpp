// Every budget and threshold of the engine, each with its default and why.
// The engines' limits structs (DpLimits, StateDpLimits, DualLimits,
// RegionLimits, RegionModelLimits, RegionDualLimits, RegionViewLimits,
// ViewBoundLimits, StarBoundLimits, WindowLimits) take their defaults from
// kBudgets; the order-k phases read a Budgets of their own (KOrderShared) and
// override those defaults only from its fields. A budget bounds time or memory;
// running out of one never makes an answer wrong, only unproven (or, for the
// brute-force reference, refused).
#pragma once
#include <cstddef>
#include <cstdint>

namespace hodt {

struct Budgets {
  // ---- The factor graph's DP (first order: a variable per quad) -------------
  // Largest bag minus one: a bag's table has 2^(width+1) entries.
  uint32_t dp_max_width = 20;
  // All tables of one run together (messages and back-pointers).
  double dp_max_table_bytes = 512.0 * 1024 * 1024;
  // A local term is tabulated over at most this many quads (2^20 entries).
  uint32_t dp_max_term_scope = 20;
  // Tabulating one term: at most about this many predicate tests (a second or two).
  double dp_max_term_work = 268435456.0;
  // Min-fill (which counts fill-ins: slower, often narrower) is tried after a
  // min-degree order too wide only on graphs of at most this many variables.
  uint32_t min_fill_variables = 50'000;
  // ... and within this many pair tests counting fill-ins (about a second).
  double min_fill_work = 268435456.0;

  // ---- The state graph's DP (order k: a variable per region) ----------------
  // Entries of the largest table the DP may build.
  double state_dp_max_table = 1 << 22;
  // Local search by windows of a few variables, each solved by the DP within
  // this table: many small windows move further than a few large ones in the
  // same time.
  uint32_t window_variables = 24;
  double window_table = 1 << 16;

  // ---- The brute-force references -------------------------------------------
  // Every choice of diagonals (order 1: 2^m of them) or every k-OD
  // triangulation: larger inputs are refused, not left running.
  uint32_t brute_force_max_quads = 24;
  uint32_t brute_force_max_points = 30;

  // ---- Measures --------------------------------------------------------------
  // Enclosing circles remembered by shape (512 KB): a reprojected raster's
  // rounding makes a few thousand distinct ones, and a cache with room for
  // fewer misses them in turn.
  size_t recent_circles = 8192;

  // ---- The dual bound (Lagrangian, over any state graph) --------------------
  // Factors sharing variables are joined into clusters of up to this many table
  // entries first (a tighter relaxation; 1: none).
  double dual_cluster_entries = 4096;
  uint32_t dual_max_sweeps = 400;  // passes over every factor
  // Rounds of proving: each prunes by the bound, tries the DP over what is
  // left, else raises the bound over what is left and prunes again.
  uint32_t dual_max_rounds = 4;
  // Stop when a pass raises the bound by less than this (the objective's units).
  double dual_min_gain = 1e-3;

  // ---- The regions' listing (order k) ----------------------------------------
  // With an objective's terms each region keeps only its best triangulation per
  // signature, found by the fill DP within these many kept partial fills (each
  // costs about a microsecond or ten and a few hundred bytes): a small first
  // pass for every region, then more for those that need it.
  uint64_t region_first_pass_states = 20'000;
  uint64_t region_max_states_dp = 200'000;
  uint64_t region_max_total_states = 500'000;
  // Enumeration (regions the DP could not list): a small budget for every
  // region, then up to max_nodes_per_region each within the total (about a
  // microsecond per node).
  uint64_t region_first_pass_nodes = 5'000;
  uint64_t region_max_nodes = 300'000;
  uint64_t region_max_total_nodes = 1'500'000;
  uint64_t region_max_listed = 2'000;  // triangulations kept per enumerated region
  // Regions of more Delaunay triangles are not enumerated (each fill costs its
  // size, and their triangulations are astronomically many); with terms the DP
  // still tries them within large_region_states kept fills each (a long strip
  // with few signatures needs a few hundred; most others fail fast).
  uint32_t region_max_triangles = 64;
  uint64_t large_region_states = 5'000;
  // Entries of one vertex factor of a regions' model: larger ones are relaxed
  // (the model then ignores that term, and its value is a bound).
  double region_model_max_factor = 1 << 20;
  // The DP over partial fills scans at most this many open edges per kept
  // state, on average, before it gives up (frontiers are rarely longer than a
  // few dozen edges: one that costs more will not fit).
  uint64_t fill_dp_work_per_state = 64;

  // ---- The dual over the regions' fill graphs --------------------------------
  // Partial fills of one region's graph: every region first gets first_states,
  // then those left max_states each (smallest first; when more than max_second
  // are left, until max_second_failures in a row do not fit); max_total over
  // all, those that did not fit included, or max_total_per_point per point when
  // that is more (a large terrain at high order is many strips of thousands of
  // partial fills each, and a total fixed for all sizes would leave most unread).
  uint64_t fill_graph_first_states = 20'000;
  uint64_t fill_graph_max_states = 200'000;
  uint32_t fill_graph_max_second = 256;
  uint32_t fill_graph_max_second_failures = 8;
  uint64_t fill_graph_max_total = 2'000'000;
  uint64_t fill_graph_max_total_per_point = 32;
  uint32_t fill_graph_restarts = 6;  // descents from the dual's states with the regions shuffled
  // The proof lists, per region, the fills that could beat the incumbent.
  uint64_t fill_graph_max_listed = 20'000;
  uint64_t fill_graph_max_listed_total = 200'000;
  // Its short rounds (prune, list, DP) before one that lists all that is left:
  // each round's bound prunes the next.
  uint32_t fill_graph_short_rounds = 3;

  // ---- The regions' views (a bound from overlapping windows of regions) -----
  uint64_t view_max_states = 100'000;  // partial fills of one view's DP
  uint64_t view_max_listed = 2'000;    // triangulations kept per view
  uint32_t view_max_rounds = 4;
  uint64_t view_max_total_states = 3'000'000;  // partial fills over all views' DPs (a few microseconds each)

  // ---- The vertices' stars (a bound from every vertex's fans) ---------------
  // Fans as prefix trees (a node per triangle, 24 bytes with its diamond end
  // and the interval of fans under it; 28 more per fan, 24 per end, and with
  // decoding 37 more per fan): per vertex (vertices beyond are left out, their
  // terms at their best; when more than max_left_out of them are, the bound is
  // not worth its steps), and per tile (more in all: tiles taken in turn, each
  // border's vertices carried into the next, a bound a little weaker in the
  // memory of one).
  uint64_t star_max_nodes_per_vertex = 50'000;
  uint64_t star_max_nodes = 16'000'000;
  double star_max_left_out = 0.05;
  // Sweeps over every diamond: at most this many, and none once the last
  // sweep's gain, kept up for every sweep left, would not prove a better value.
  uint32_t star_iterations = 50;
  // Fans the sweeps read, in all (each end's update reads the values of its
  // vertex's fans: several hundred million a second natively), shared among
  // the tiles by their vertices: the bound's time.
  uint64_t star_max_visits = 120'000'000'000;
  // Decoding triangulations off the fans under the multipliers: fans tried per
  // vertex, and those looked ahead at each step.
  uint64_t star_decode_steps_per_vertex = 64;
  uint32_t star_decode_lookahead = 4;
  // On inputs of at most this many points the stars come before the dual
  // proof: there they take milliseconds, and prove the counts the dual's
  // ascent leaves with a gap after most of a second.
  uint32_t stars_first_points = 200;

  // ---- Windows of fans (local search over tiles of vertices) ----------------
  uint32_t fan_window_vertices = 25;
  uint64_t fan_window_steps = 2'000;               // fans tried per window (the best found by then is kept)
  uint64_t fan_window_nodes_per_vertex = 50'000;  // a vertex with more fans keeps its star
  // Fans' tree nodes listed in all (a window's members listed anew at each of
  // the four offsets), the larger of the two: no window starts past it. The
  // windows run in rows from one side, so a budget short of the whole leaves
  // the far side as it was: per point, enough for the four offsets at k = 8 on
  // DEMs (a few thousand nodes per point at that order), so that a large
  // terrain is searched whole; max_nodes is the floor for small inputs.
  uint64_t fan_window_max_nodes = 16'000'000;
  uint64_t fan_window_nodes_per_point = 8'192;

  // ---- The order-k phases ---------------------------------------------------
  // Branch and bound over every fill of the instance (min-max): on inputs of at
  // most this many points, within this many search nodes. Small inputs at high
  // order have one region of astronomically many triangulations, which the
  // regions' engine can only bound, while the terms' pruning proves them.
  // From early_rung_order on it runs before the regions are listed (the
  // listing takes far longer than the search there); below, where the exact
  // DP refused.
  // (A node tests every candidate of the frontier, so its cost grows with the
  // input: the budget keeps a search that cannot finish short beside the rest.)
  uint32_t branch_and_bound_points = 80;
  uint64_t branch_and_bound_nodes = 60'000;
  // Its memo of partial fills searched to the end (fill_search.hpp), in 32-bit
  // words: a key is a frontier and what the terms read of the triangles
  // behind it, a few dozen words, so this holds one for most of the nodes.
  // (Once full, the search goes on without storing more.)
  uint64_t branch_and_bound_memo_words = uint64_t{1} << 22;
  // The threshold SAT search (min-max; threshold_sat.hpp): on inputs of at most
  // this many points (its clauses grow with the candidates' crossings and
  // pairs, which grow with the input and the order), within this many
  // conflicts over all its questions. Where the branch and bound's pruning
  // only reads the terms of placed triangles, the solver's learned clauses
  // carry what one part of the terrain forbids to every other part.
  uint32_t threshold_sat_points = 1000;
  uint64_t threshold_sat_conflicts = 200'000;
  // Its work (the solver's watches and implications visited, a few 10^7 a
  // second): a conflict's cost grows with the input, which the conflicts alone
  // do not bound. About two seconds: what it proves, it proves in milliseconds.
  uint64_t threshold_sat_work = 50'000'000;
  // On larger inputs it runs late, only where the answer still has a gap
  // after the cheap bounds (before the regions' views, the costliest): the
  // solver needs a full triangulation per answer, so a question costs more
  // the larger the input, and on most inputs the bounds prove the answer
  // first. Up to this many points, within this much work.
  uint32_t threshold_sat_gap_points = 20'000;
  uint64_t threshold_sat_gap_work = 125'000'000;
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
  // Not at high order (early_rung_order on) on inputs of at most this many
  // points: there a region over the first budgets is one region of most of the
  // input, which the wider listing does not make whole either, and the dual
  // proof and the stars prove the counts from the first listing.
  uint32_t list_whole_high_order_points = 200;
  // The dual proof over a whole model: clusterings of these many table entries,
  // tried in turn (the larger, the tighter relaxation). Each ascent stops at a
  // fixed point of its own, and a proof turns on the bound passing an integer,
  // so either may prove what the other cannot.
  double dual_clusters[2] = {4096, 1024};
  // Min-max thresholds refuted over the regions' fill graphs: sweeps per threshold.
  uint32_t threshold_sweeps = 100;
  // Sums on inputs of at most this many points take no start from the order
  // below: there this order's own searches (for counts, the dual proof's local
  // search from its decoded states) start as well, and the ladder's rungs
  // would cost more than the rest of the solve.
  uint32_t sum_ladder_points = 200;
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
  // What a proof's pruning leaves is far smaller than the model: its DP (and
  // the DP over the fill graphs' listed states) may use a table this large.
  double pruned_dp_table = 1 << 24;
  // Descents by windows of fans around the stars' decoding: at most this many
  // placements of the tiles in all, and these window sizes in turn after the
  // decoding (a move that no window of one size holds may fit one of the next).
  uint32_t fan_window_placements = 16;
  uint32_t fan_window_sizes[4] = {25, 40, 64, 102};
};

inline constexpr Budgets kBudgets{};

}  // namespace hodt
