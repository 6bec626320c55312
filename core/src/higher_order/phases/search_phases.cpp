#include "higher_order/phases/phases.hpp"
#include "higher_order/regions/region_model.hpp"
#include "higher_order/search/branch_and_bound.hpp"
#include "higher_order/search/flip_search.hpp"
#include "higher_order/search/k_order_baker.hpp"
#include "higher_order/search/threshold_sat.hpp"

namespace hodt {

// The start's triangulation is among the listed ones, so the answer is never
// worse than the start; the start is kept when better (relaxed terms can
// mislead the search).
void best_listed(KOrderRun& run) {
  RegionEngine& engine = *run.engine;
  Regions& R = engine.R;
  if (run.added)
    engine.model = update_region_model(std::move(engine.model), run.dt, R, run.o, run.changed, engine.model_limits, run.searching);
  const ListedBest listed = engine.best_listed(listed_states(R, run.start), run.searching);
  if (run.bounded && listed.bound_only && !R.incomplete && !engine.model.graph.relaxed_terms &&
      !better(run.sense, listed.listed_value, run.start_value)) {
    // The model is the whole problem, so its mini-bucket value bounds the
    // optimum, and the start already meets it.
    run.answer.offer(std::move(run.start), run.start_value, "the " + run.start_name);
    run.answer.tighten(listed.listed_value, "the mini-bucket bound over the whole model");
    return;
  }
  Mesh m = R.triangulation(run.dt, listed.regions);
  const double v = evaluate(run.o, m);
  run.answer.offer(std::move(m), v, listed.how);
  run.answer.offer(run.start, run.start_value, "the " + run.start_name);
  const std::string proof = run.min_max_proof(run.answer.value());
  if (!proof.empty()) run.answer.prove(proof);
}

// Bands of Delaunay triangles kept every lambda layers cut the regions too
// large for the engine (about lambda runs of it, so only when asked).
void shift_bands(KOrderRun& run) {
  KOrderBaker b = k_order_baker(run.dt, run.o, *run.structure, run.k, run.options.epsilon,
                                run.shared.region_limits.max_nodes_per_region, in_phase(run.options.progress, Phase::Approximating));
  if (b.triangulation && better(run.sense, b.value, run.answer.value()))
    run.answer.restart(std::move(*b.triangulation), b.value, b.summary());
  else if (b.shifts)
    run.answer.note(" (" + b.summary() + ": no better)");
}

void flip(KOrderRun& run) {
  Mesh flipped = run.answer.triangulation();
  if (improve_by_flips(flipped, run.dt, run.k, run.o, run.searching, run.shared.memo)) {
    const double v = evaluate(run.o, flipped);
    run.answer.offer(std::move(flipped), v, "k-OD flips");
  }
}

void descend_fill_graphs(KOrderRun& run) {
  read_fill_graphs(run, run.answer, run.searching, 0,
                   run.k >= run.budgets.early_rung_order ? run.budgets.rung_dual_sweeps : run.budgets.dual_sweeps);
}

// From the first order optimum: its value is the first cut, and each better
// fill found cuts deeper.
void branch_and_bound_small(KOrderRun& run) {
  const Mesh& start = run.shared.first_order.get();
  const double known = run.shared.first_order.value;
  const BranchAndBound b = branch_and_bound(run.dt, run.o, run.built_structure().candidates, known,
                                            run.budgets.branch_and_bound_nodes, run.budgets.branch_and_bound_memo_words,
                                            run.exactly);
  if (b.found) run.answer.offer(*b.found, b.value, "branch and bound over every fill");
  else run.answer.offer(start, known, "the first order optimum");
  if (b.complete)
    run.answer.prove("branch and bound over every k-OD triangulation (" + std::to_string(b.nodes) +
                     " search nodes) found none better");
}

namespace {

// From the best value in hand (the first order optimum when none): each better
// triangulation the solver finds lowers the threshold, and its "no" proves the
// last one optimal. The solver's decisions start from the answer's triangles.
void ask_sat(KOrderRun& run, uint64_t max_work) {
  if (!run.answer.has()) {
    const Mesh& start = run.shared.first_order.get();  // (computes the value too)
    run.answer.offer(start, run.shared.first_order.value, "the first order optimum");
  }
  const ThresholdSat s = threshold_sat(run.dt, run.o, run.built_structure().candidates, run.answer.value(),
                                       run.budgets.threshold_sat_conflicts, max_work, run.exactly,
                                       &run.answer.triangulation());
  if (s.found) run.answer.offer(*s.found, s.value, "the threshold SAT search");
  const std::string asked = std::to_string(s.questions) + (s.questions == 1 ? " question, " : " questions, ") +
                            std::to_string(s.conflicts) + " conflicts";
  if (s.complete)
    run.answer.prove("no k-OD triangulation has every term below its value (CDCL over every candidate triangle: " +
                     asked + ")");
  else
    run.answer.note(" (threshold SAT: " + asked + ", no answer within its budget)");
}

}  // namespace

void refute_by_sat(KOrderRun& run) { ask_sat(run, run.budgets.threshold_sat_work); }
void refute_gap_by_sat(KOrderRun& run) { ask_sat(run, run.budgets.threshold_sat_gap_work); }

}  // namespace hodt
