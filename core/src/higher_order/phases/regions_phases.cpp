#include "hodt/error.hpp"
#include "engines/dual_bound.hpp"
#include "higher_order/phases/phases.hpp"
#include "higher_order/regions/region_model.hpp"
#include "higher_order/regions/regions.hpp"

namespace hodt {

void find_regions(KOrderRun& run) {
  // (The ladder's rungs read their useful edges from the top order's.)
  if (!run.above) run.by_order = useful_edges_by_order(run.dt, run.k, run.finding);
  run.useful = run.orders().at(run.k);
  run.skeleton = k_order_skeleton(run.dt, run.k, run.useful, run.finding);
}

void build_engine(KOrderRun& run) {
  run.engine = std::make_unique<RegionEngine>(run.dt, run.o, run.built_structure(), std::move(run.skeleton), run.shared.region_limits,
                                              run.finding, run.shared.memo);
  run.refused = run.engine->exact_refusal().value_or("");
  const StateGraph& graph = run.engine->model.graph;
  run.counts = !graph.relaxed_terms && integral_sum(graph);
  run.provable = run.bounded && run.counts;
  // (Counts unless approx is asked: the dual's proof needs no other bound, so
  // the relaxation's is read only if the proof did not come.)
  run.dual_first = run.provable && run.options.method != Method::Approx;
}

// Not when a region is over the size the first pass enumerates at all (those
// have astronomically many signatures), nor when the first pass ran out of
// budget on one before it had placed most of its triangles (its frontier still
// widening, it will not fit a budget many times larger either).
void list_whole(KOrderRun& run) {
  RegionEngine& engine = *run.engine;
  Regions& R = engine.R;
  const bool listable = std::none_of(R.regions.begin(), R.regions.end(), [&](const Region& g) {
    return !g.complete && (g.delaunay_triangles.size() > engine.limits.max_region_triangles ||
                           g.swept < run.budgets.list_whole_min_swept);
  });
  if (!listable) return;
  Regions listed = R;
  std::vector<uint8_t> changed(R.regions.size(), 0);
  for (size_t r = 0; r < R.regions.size(); ++r) changed[r] = !R.regions[r].complete;
  RegionLimits wide = engine.limits;
  wide.only_incomplete = true;
  wide.max_states_per_region = run.budgets.list_whole_states_per_region;
  wide.max_states_per_region_dp = run.budgets.list_whole_states_per_region_dp;
  wide.max_total_states = run.budgets.list_whole_total_states;
  enumerate_regions(run.dt, R, wide);
  if (R.incomplete) {
    R = std::move(listed);
    return;
  }
  engine.model = update_region_model(std::move(engine.model), run.dt, R, run.o, changed, engine.model_limits, run.finding);
  run.refused = engine.exact_refusal().value_or("");
}

void solve_exactly(KOrderRun& run) {
  if (run.refused.empty() && run.options.method != Method::Approx) {
    uint32_t width = 0;
    if (auto x = run.engine->exact(run.exactly, run.refused, &width)) {
      Mesh m = run.R().triangulation(run.dt, *x);
      const double v = evaluate(run.o, m);
      run.answer.prove_with(std::move(m), v, "the DP over a tree decomposition of width " + std::to_string(width),
                            "every region is listed whole and the DP over them is exact");
      return;
    }
  }
  if (run.options.method == Method::Exact && !run.provable)
    throw LimitError("exact at order " + std::to_string(run.k) + ": " + run.refused);
}

}  // namespace hodt
