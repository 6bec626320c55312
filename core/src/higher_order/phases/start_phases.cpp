#include "higher_order/phases/phases.hpp"
#include "higher_order/regions/region_model.hpp"

namespace hodt {

void take_start(KOrderRun& run) {
  // (At order 1 the engine is the first order solver within a domain: Delaunay starts.)
  const bool first = run.k == 1;
  run.start = first ? run.dt : run.shared.first_order.get();
  run.start_value = first ? evaluate(run.o, run.dt) : run.shared.first_order.value;
  run.start_name = first ? "Delaunay triangulation" : "first order optimum";
}

void prove_start(KOrderRun& run) { run.prove_start(); }

void list_start(KOrderRun& run) {
  run.changed.assign(run.R().regions.size(), 0);
  run.added = add_states_of(run.R(), run.dt, run.start, &run.changed);
}

// Up to order rung_step_max_order the rung is k - 1 (a rung too far below
// gives fewer of this order's moves); above, half of k. A rung stops before
// the bounds, so an answer can still trail the lower order's own.
void solve_lower_order(KOrderRun& run) {
  SolveOptions lower = run.options;
  lower.method = Method::Auto;
  lower.progress = hold_in_phase(run.options.progress, Phase::Searching);  // (a start for this order's search)
  run.lower = solve_at_order(run.shared, run.lower_order(), lower, false, &run.orders());
}

void start_from_lower_order(KOrderRun& run) {
  KOrderResult& lower = *run.lower;
  run.added = add_states_of(run.R(), run.dt, lower.triangulation, &run.changed) || run.added;
  if (better(run.sense, lower.value, run.start_value)) {
    run.start = std::move(lower.triangulation), run.start_value = lower.value;
    run.start_name = "answer at order " + std::to_string(run.lower_order());
  }
  run.prove_start();
}

// What its descents find can be a worse start for the rest, so it keeps only a
// proof.
void quick_fill_graph_proof(KOrderRun& run) {
  RegionEngine& engine = *run.engine;
  Regions& R = engine.R;
  if (run.added)
    engine.model = update_region_model(std::move(engine.model), run.dt, R, run.o, run.changed, engine.model_limits, run.searching);
  run.changed.assign(R.regions.size(), 0), run.added = false;
  std::vector<size_t> counts(R.regions.size());
  for (size_t i = 0; i < R.regions.size(); ++i) counts[i] = R.regions[i].states.size();
  Incumbent trial = run.answer;
  const ListedBest listed = engine.best_listed(listed_states(R, run.start), run.searching);
  Mesh m = R.triangulation(run.dt, listed.regions);
  const double v = evaluate(run.o, m);
  trial.offer(std::move(m), v, listed.how);
  trial.offer(run.start, run.start_value, "the " + run.start_name);
  read_fill_graphs(run, trial, run.proving, 0, run.budgets.quick_sweeps);
  if (trial.optimal()) {
    run.answer = std::move(trial);
    return;
  }
  for (size_t i = 0; i < R.regions.size(); ++i) R.regions[i].states.resize(counts[i]);
}

}  // namespace hodt
