#include "higher_order/regions/region_engine.hpp"

#include "hodt/error.hpp"
#include "hodt/higher_order.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

std::string region_summary(const Regions& R) {
  size_t choice = 0, largest = 0;
  for (const Region& g : R.regions)
    if (g.states.size() > 1) ++choice, largest = std::max(largest, g.states.size());
  return std::to_string(choice) + " regions with a choice (up to " + std::to_string(largest) + " triangulations each)";
}

KOrderStructure::KOrderStructure(const Mesh& dt, uint32_t k, const Progress& progress)
    : KOrderStructure(dt, k, useful_edges(dt, k, progress), progress) {}

KOrderStructure::KOrderStructure(const Mesh& dt, uint32_t k, std::vector<std::pair<uint32_t, uint32_t>> u,
                                 const Progress& progress)
    : useful(std::move(u)), candidates(k_order_candidates(dt, k, useful, progress)) {}

RegionEngine::RegionEngine(const Mesh& dt, Objective o, const KOrderStructure& structure, uint32_t k,
                           const RegionLimits& budgets, const Progress& progress, const std::vector<uint8_t>& forced)
    : RegionEngine(dt, o, structure, k_order_skeleton(dt, k, structure.useful, progress, forced), budgets, progress) {}

// (Forced edges drop the useful edges that cross them: the candidates follow.)
RegionEngine::RegionEngine(const Mesh& dt, Objective o, const KOrderStructure& structure, Regions skeleton,
                           const RegionLimits& budgets, const Progress& progress, VertexTermMemo* memo)
    : R(std::move(skeleton)),
      restricted_(R.useful.size() < structure.useful.size() ? restrict_candidates(structure.candidates, R.useful)
                                                             : Candidates{}),
      cand(R.useful.size() < structure.useful.size() ? restricted_ : structure.candidates),
      terms(dt, R, o, &cand),
      limits(budgets) {
  limits.candidates = &cand;
  limits.progress = progress;
  limits.terms = &terms;
  model_limits.memo = memo;
  enumerate_regions(dt, R, limits);
  model = region_model(dt, R, o, model_limits, progress);
}

std::optional<std::string> RegionEngine::exact_refusal() const {
  if (R.incomplete) return std::to_string(R.incomplete) + " regions have more k-OD triangulations than the budget";
  if (model.graph.relaxed_terms)
    return std::to_string(model.graph.relaxed_terms) + " terms see too many regions to tabulate";
  return std::nullopt;
}

std::optional<std::vector<uint32_t>> RegionEngine::exact(const Progress& progress, std::string& refused,
                                                         uint32_t* width) const {
  if (auto why = exact_refusal()) {
    refused = *why;
    return std::nullopt;
  }
  try {
    StateDpLimits dl;
    dl.progress = progress;
    const StateDpResult dp = solve_states(model.graph, dl);
    if (width) *width = dp.width;
    return model.region_states(dp.state);
  } catch (const LimitError& e) {
    refused = e.what();
    return std::nullopt;
  }
}

ListedBest RegionEngine::best_listed(const std::vector<uint32_t>& start_regions, const Progress& progress) const {
  StateDpLimits dl;
  dl.progress = progress;
  // The DP over the listed triangulations; where its tables are too large it runs
  // over mini-buckets, whose assignment is then one start of the local search.
  StateDpLimits mini = dl;
  mini.mini_buckets = true;
  // Small buckets: the mini-buckets' assignment is only a start for the local
  // search, and their time grows with the tables' size while the start hardly
  // improves past 2^18 entries. Min-max smaller still: its search is a DP per
  // threshold probed, each paying the tables' size. (Counts over smaller
  // tables start their local search further off and end slower.)
  mini.max_table = model.graph.combine == Combine::Max ? 1 << 14 : 1 << 18;
  const StateDpResult listed = solve_states(model.graph, mini);
  ListedBest out;
  out.bound_only = listed.bound_only;
  out.listed_value = listed.value;
  std::vector<uint32_t> x = listed.state;
  out.how = "the best combination of the regions' listed triangulations";
  if (listed.bound_only) {
    const Sense sense = model.graph.sense;
    x = improve_states(model.graph, x, progress);
    out.how = "local search from the mini-bucket DP";
    if (!start_regions.empty()) {
      const std::vector<uint32_t> y = improve_states(model.graph, model.variable_states(start_regions), progress);
      if (better(sense, evaluate_states(model.graph, y), evaluate_states(model.graph, x)))
        x = y, out.how = "local search from the first order optimum";
    }
    StateDpLimits window = dl;
    window.max_table = kBudgets.window_table;
    x = improve_by_windows(model.graph, x, window, kBudgets.window_variables);
    out.how += ", then windows solved exactly";
  }
  out.regions = model.region_states(x);
  return out;
}

}  // namespace hodt
