#include "engines/dual_bound.hpp"
#include "engines/state_graph.hpp"
#include "higher_order/bounds/region_dual.hpp"
#include "higher_order/bounds/star_bound.hpp"
#include "higher_order/bounds/view_bound.hpp"
#include "higher_order/phases/phases.hpp"
#include "higher_order/regions/region_model.hpp"
#include "higher_order/search/fan_windows.hpp"

namespace hodt {

// Each term that sees a region not listed whole takes its best value, so every
// k-OD triangulation is at least as bad as the relaxation's optimum.
void relax(KOrderRun& run) {
  StateDpLimits dl;
  dl.progress = run.proving;
  run.answer.tighten(relaxation_bound(run.engine->model.graph, dl), "the relaxation over the regions' states");
}

void floor_terms(KOrderRun& run) {
  run.answer.tighten(run.engine->terms.floor(), "the worst term that no region changes");
}

// Over a whole model the dual gives local search one more start, then proves
// the best triangulation found optimal or finds the optimum, by pruning and the
// DP over what is left; over regions not listed whole it reads them through
// their fill graphs, unglued (kept in run.unglued when gluing might tighten it).
void prove_by_dual(KOrderRun& run) {
  RegionEngine& engine = *run.engine;
  Regions& R = engine.R;
  RegionModel& model = engine.model;
  Incumbent& answer = run.answer;
  if (R.incomplete) {
    if (const auto b = read_fill_graphs(run, answer, run.proving, 0, run.budgets.dual_sweeps, &run.unglued))
      answer.tighten(*b, "the dual over the regions' fill graphs");
    return;
  }
  DualLimits dual;
  dual.progress = run.proving;
  dual.max_rounds = run.budgets.dual_proof_rounds;
  StateDpLimits dl;
  dl.progress = run.proving;
  for (const double clusters : run.budgets.dual_clusters) {
    dual.cluster_entries = clusters;
    const DualProof proof(model.graph, dual, answer.value());
    if (!proof.applies()) return;
    answer.tighten(*proof.bound(), "the dual bound");
    StateDpLimits window = dl;
    window.max_table = run.budgets.window_table;
    const std::vector<uint32_t> x = improve_by_windows(
        model.graph, improve_states(model.graph, proof.decoded(), run.proving), window, run.budgets.window_variables);
    Mesh m = R.triangulation(run.dt, model.region_states(x));
    const double v = evaluate(run.o, m);
    answer.offer(std::move(m), v, "local search from the dual");
    StateDpLimits pruned = dl;
    pruned.max_table = run.budgets.pruned_dp_table;
    const DualProof::Proof p = proof.prove(answer.value(), pruned);
    if (!p.proven) continue;
    const std::string why = "the dual bound (clusters of " + std::to_string(static_cast<int>(clusters)) + " entries) kept " +
                            std::to_string(p.kept_states) + " of " + std::to_string(p.states) +
                            " states and the DP over them proved " +
                            (p.better ? std::string("its optimum") : std::string("the answer")) +
                            " optimal (the DP alone refused: " + run.refused + ")";
    if (p.better) {
      Mesh best = R.triangulation(run.dt, model.region_states(*p.better));
      const double bv = evaluate(run.o, best);
      if (bv != p.better_value) throw std::logic_error("order k: the model's value differs from the triangulation's");
      answer.prove_with(std::move(best), bv, "the pruned DP's optimum", why);
    } else {
      answer.prove(why);
    }
    return;
  }
}

// When the views agree, a triangulation meets their bound.
void view_regions(KOrderRun& run) {
  RegionEngine& engine = *run.engine;
  ViewBoundLimits vl;
  vl.views.progress = vl.dp.progress = run.proving;
  vl.model = engine.model_limits;
  const double bound = run.bound();
  auto vb = view_bound(run.dt, engine.R, run.o, engine.cand, engine.terms, engine.limits.max_region_triangles,
                             run.answer.value(), bound, vl);
  if (!vb) return;
  run.answer.tighten(vb->bound, "the regions' views");
  if (vb->realised && !better(run.sense, run.answer.value(), vb->bound))
    run.answer.offer(std::move(*vb->realised), vb->bound,  // (its value, evaluated)
                     "the regions' views (" + std::to_string(vb->split_regions) + " regions, " +
                         std::to_string(vb->rounds) + " rounds)",
                     true);
}

void refute_thresholds(KOrderRun& run) {
  RegionEngine& engine = *run.engine;
  RegionDualLimits limits;
  limits.dual.progress = run.proving;
  limits.dual.max_sweeps = run.budgets.threshold_sweeps;
  limits.model = engine.model_limits;
  if (const auto t = region_threshold_bound(run.dt, engine.R, run.o, engine.cand, engine.terms, run.bound(),
                                            run.answer.value(), limits))
    run.answer.tighten(*t, "thresholds over the regions' fill graphs");
}

void floor_fans(KOrderRun& run) {
  StarBoundLimits stars;
  stars.progress = run.proving;
  if (const auto f = star_floor(run.dt, run.o, run.engine->cand, stars)) run.answer.tighten(*f, "the vertices' fans");
}

void glue_fill_graphs(KOrderRun& run) {
  if (const auto b = read_fill_graphs(run, run.answer, run.proving, run.budgets.max_glue, run.budgets.dual_sweeps, &run.unglued))
    run.answer.tighten(*b, "the dual over the regions' fill graphs, glued");
}

}  // namespace hodt
