#include "higher_order/phases/phase_table.hpp"

#include <chrono>

#include "hodt/error.hpp"
#include "higher_order/phases/phases.hpp"
#include "higher_order/search/branch_and_bound.hpp"
#include "higher_order/search/threshold_sat.hpp"

namespace hodt {

namespace {

bool always(const KOrderRun&) { return true; }
bool max_terms(const KOrderRun& run) { return run.description.combine == Combine::Max; }
bool incomplete(const KOrderRun& run) { return run.engine->R.incomplete; }
// A small input and a min-max objective: the branch and bound's.
bool small_min_max(const KOrderRun& r) {
  return r.bounded && r.k >= 2 && r.dt.num_vertices() <= r.budgets.branch_and_bound_points &&
         branch_and_bound_applies(r.o, r.dt);
}
// A small input and a min-max objective: the threshold SAT search's.
bool small_sat(const KOrderRun& r) {
  return r.bounded && r.k >= 2 && r.dt.num_vertices() <= r.budgets.threshold_sat_points &&
         threshold_sat_applies(r.o, r.dt);
}
// A larger input (up to Budgets::threshold_sat_gap_points), min-max: the
// threshold SAT search's where the cheap bounds left a gap.
bool larger_sat(const KOrderRun& r) {
  return r.bounded && r.k >= 2 && r.dt.num_vertices() > r.budgets.threshold_sat_points &&
         r.dt.num_vertices() <= r.budgets.threshold_sat_gap_points && threshold_sat_applies(r.o, r.dt);
}
// The high orders (from Budgets::early_rung_order on), where listing the
// regions costs the most and the exact engine rarely answers: the searches
// that need no listing come before it, the quick reading of the fill graphs
// is left out.
bool high_order(const KOrderRun& r) { return r.k >= r.budgets.early_rung_order; }
// Sums whose stars come before the dual proof (a small input).
bool stars_first(const KOrderRun& r) {
  return r.bounded && !max_terms(r) && r.dt.num_vertices() <= r.budgets.stars_first_points;
}
// Whether a rung of the ladder (the order below) gives this order its start.
bool ladder(const KOrderRun& r) {
  return r.k >= 3 && (max_terms(r) || r.dt.num_vertices() > r.budgets.sum_ladder_points);
}

}  // namespace

// Cheap proofs first, then the exact engine, then the search and its starts,
// then the bounds from the cheapest up. Counts read the dual first (it proves
// most of them on its own); the regions' views, which cost the most and which
// the other bounds almost always make redundant, come after the fans and the
// stars; the glued fill graphs last, where all else left a gap.
const std::vector<KOrderPhase>& k_order_phases() {
  static const std::vector<KOrderPhase> rows = {
      {"the first order optimum meets the global bound",
       [](const KOrderRun& r) { return r.bounded && r.k >= 2 && r.description.global_bound != nullptr; }, meet_global_bound},
      {"finding the regions", always, find_regions},
      // (Order 1 stays on the region engine: solve() takes the first order paths itself.)
      {"a diagonal per quad", [](const KOrderRun& r) { return r.k >= 2; }, solve_as_quads},
      // (Before everything that lists: its questions need only the candidates,
      // and on a small input it answers in milliseconds what the rest takes
      // seconds to prove, or never does.)
      {"the threshold SAT search", small_sat, refute_by_sat},
      // (From the early rung's order on, before the regions are listed: there
      // the listing takes far longer than the search; below, the exact DP
      // answers first.)
      {"branch and bound over every fill, first",
       [](const KOrderRun& r) { return small_min_max(r) && high_order(r); }, branch_and_bound_small},
      // (One order's regions in memory at a time.)
      // (Not before the branch and bound, which needs no rung.)
      {"the lower order, first", [](const KOrderRun& r) { return ladder(r) && high_order(r) && !small_min_max(r); },
       solve_lower_order},
      {"listing the regions", always, build_engine},
      {"listing the regions whole",
       [](const KOrderRun& r) {
         return r.provable && incomplete(r) &&
                !(high_order(r) && r.dt.num_vertices() <= r.budgets.list_whole_high_order_points);
       },
       list_whole},
      {"the exact DP", always, solve_exactly},
      {"the start", always, take_start},
      {"a min-max proof of the start", always, prove_start},
      {"branch and bound over every fill",
       [](const KOrderRun& r) { return small_min_max(r) && !high_order(r); }, branch_and_bound_small},
      {"the start listed", always, list_start},
      {"a quick reading of the fill graphs",
       [](const KOrderRun& r) {
         return r.provable && !high_order(r) && incomplete(r) && r.options.method != Method::Approx;
       },
       quick_fill_graph_proof},
      {"the lower order", [](const KOrderRun& r) { return ladder(r) && !r.lower; }, solve_lower_order},
      {"the lower order's answer as a start", [](const KOrderRun& r) { return r.lower.has_value(); }, start_from_lower_order},
      {"the best listed combination", always, best_listed},
      {"Baker's shifting at order k",
       [](const KOrderRun& r) { return r.bounded && r.k >= 2 && r.options.method == Method::Approx; }, shift_bands},
      {"k-OD flips", always, flip},
      // A rung ends here: its answer is a start, its bound of no use.
      {"descents over the fill graphs (a rung)", [](const KOrderRun& r) { return !r.bounded && r.counts && incomplete(r); },
       descend_fill_graphs},
      {"the relaxation", [](const KOrderRun& r) { return r.bounded && !r.dual_first; }, relax},
      {"the terms' floor", [](const KOrderRun& r) { return r.bounded && max_terms(r); }, floor_terms},
      {"the vertices' stars, first", stars_first, search_stars},
      {"the dual proof", [](const KOrderRun& r) { return r.provable; }, prove_by_dual},
      {"the relaxation, after the dual", [](const KOrderRun& r) { return r.dual_first; }, relax},
      {"thresholds over the fill graphs", [](const KOrderRun& r) { return r.bounded && max_terms(r) && incomplete(r); },
       refute_thresholds},
      {"the vertices' fans", [](const KOrderRun& r) { return r.bounded && max_terms(r); }, floor_fans},
      {"the vertices' stars", [](const KOrderRun& r) { return r.bounded && !max_terms(r) && !stars_first(r); },
       search_stars},
      {"the threshold SAT search, for the gap", larger_sat, refute_gap_by_sat},
      {"the regions' views", [](const KOrderRun& r) { return r.bounded; }, view_regions},
      {"the fill graphs glued", [](const KOrderRun& r) { return r.bounded && r.unglued.has_value(); }, glue_fill_graphs},
  };
  return rows;
}

std::vector<PhaseStep> run_phases(KOrderRun& run) {
  std::vector<PhaseStep> ran;
  const Incumbent& answer = run.answer;
  for (const KOrderPhase& phase : k_order_phases()) {
    if (answer.optimal() || run.method) break;
    if (!phase.applies(run)) continue;
    const bool had = answer.has();
    const double value = answer.value();
    const std::optional<double> bound = answer.bound();
    const auto t0 = std::chrono::steady_clock::now();
    phase.run(run);
    PhaseStep step;
    step.name = phase.name;
    step.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (answer.has()) step.value = answer.value();
    step.bound = answer.bound();
    step.improved = answer.has() && (!had || better(run.sense, answer.value(), value));
    step.tightened = step.bound && (!bound || better(run.sense, *bound, *step.bound));
    step.proved = answer.optimal();
    ran.push_back(std::move(step));
  }
  return ran;
}

// The answer as the phases left it: `optimal` is the incumbent's (the bound
// meets the value), the method what produced it.
KOrderResult solve_at_order(const KOrderShared& shared, uint32_t k, const SolveOptions& options, bool bounded,
                            const UsefulEdges* above) {
  KOrderRun run(shared, k, options, bounded, above);
  KOrderResult r;
  r.phases = run_phases(run);
  const Incumbent& answer = run.answer;
  r.optimal = answer.optimal();
  if (bounded && !run.method && options.method == Method::Exact && !r.optimal)
    throw LimitError("exact at order " + std::to_string(k) + ": " + run.refused + "; the dual bound left a gap");
  r.value = answer.value();
  if (!r.optimal) r.bound = answer.bound();
  r.method = run.method ? *run.method : r.optimal ? "exact" : "heuristic";
  if (run.details) {
    r.details = *run.details;
  } else {
    r.details = run.engine ? region_summary(run.engine->R) + "; " : "";
    r.details += answer.found_by();
    if (r.optimal)
      r.details += "; optimal: " + (answer.proof().empty() ? "its value meets " + answer.bound_by() : answer.proof());
    else if (r.bound)
      r.details += "; bound from " + answer.bound_by();
    r.details += answer.notes();
    if (!run.refused.empty()) r.details += " (exact refused: " + run.refused + ")";
    else if (options.method == Method::Approx) r.details += " (approx asked)";
  }
  r.triangulation = run.answer.take_triangulation();
  return r;
}

}  // namespace hodt
