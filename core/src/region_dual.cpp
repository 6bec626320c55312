#include "hodt/region_dual.hpp"

#include "hodt/fill_graph.hpp"
#include "hodt/region_model.hpp"

namespace hodt {

namespace {

// A region's fills as an implicit factor over its items' variables (min form).
// Items with one entry have no variable: their costs stay 0.
struct RegionFactor final : ImplicitFactor {
  FillGraph graph;                 // its arc costs in min form
  double offset = 0;               // less the Delaunay fill's own terms (the model counts those)
  std::vector<uint32_t> item_of;   // per scope position, its item in the graph
  mutable std::vector<std::vector<double>> costs, marginals;

  double least(const std::vector<std::vector<double>>& scope_costs,
               std::vector<std::vector<double>>* scope_marginals) const override {
    costs.resize(graph.entries.size());
    for (size_t i = 0; i < costs.size(); ++i) costs[i].assign(graph.entries[i].size(), 0.0);
    for (size_t j = 0; j < item_of.size(); ++j) costs[item_of[j]] = scope_costs[j];
    const double v = graph.least(costs, scope_marginals ? &marginals : nullptr) + offset;
    if (scope_marginals) {
      scope_marginals->resize(item_of.size());
      for (size_t j = 0; j < item_of.size(); ++j) {
        (*scope_marginals)[j] = marginals[item_of[j]];
        for (double& m : (*scope_marginals)[j]) m += offset;
      }
    }
    return v;
  }
};

}  // namespace

RegionDual region_dual(const Mesh& dt, const Regions& R, Objective o, const Candidates& cand, const RegionTerms& terms,
                       std::optional<double> stop_at, const RegionDualLimits& limits) {
  RegionDual out;
  out.fills.resize(R.regions.size());
  const double sign = info(o).sense == Sense::Min ? 1.0 : -1.0;
  // The regions not listed whole, each through its graph if it fits.
  std::vector<std::optional<FillGraph>> graphs(R.regions.size());
  std::vector<std::vector<RegionView>> views(R.regions.size());
  uint64_t used = 0;
  for (uint32_t r = 0; r < R.regions.size(); ++r) {
    if (R.regions[r].complete) continue;
    uint64_t states = 0;
    if (used < limits.max_total)
      graphs[r] = fill_graph(dt, cand, terms, r, std::min(limits.max_states, limits.max_total - used),
                             limits.dual.progress, &states);
    used += states;
    if (!graphs[r]) {
      ++out.relaxed;
      continue;
    }
    ++out.graphs;
    // Its own terms from the implicit factor: the model reads the Delaunay fill
    // for them (a constant), each item from the fills that stand for its entries.
    views[r].push_back({{}, {R.regions[r].states[0]}});
    const auto reps = graphs[r]->representatives();
    for (size_t i = 0; i < reps.size(); ++i) views[r].push_back({{graphs[r]->items[i]}, reps[i]});
  }
  if (!out.graphs) return out;
  RegionModel model = region_model(dt, R, o, {}, limits.dual.progress, &views);
  std::vector<RegionFactor> factors(R.regions.size());
  std::vector<const ImplicitFactor*> implicit;
  std::vector<uint32_t> region_of_factor;
  for (uint32_t r = 0; r < R.regions.size(); ++r) {
    if (!graphs[r]) continue;
    RegionFactor& f = factors[r];
    f.graph = std::move(*graphs[r]);
    for (FillGraph::Arc& a : f.graph.arcs) a.cost *= sign;
    f.offset = -sign * terms.key(r, R.regions[r].states[0]).value;
    region_of_factor.push_back(r);
  }
  for (uint32_t x = 0; x < model.region_of_variable.size(); ++x) {
    const uint32_t r = model.region_of_variable[x], view = model.view_of_variable[x];
    if (!graphs[r] || view == 0) continue;
    factors[r].scope.push_back(x);
    factors[r].item_of.push_back(view - 1);
  }
  for (uint32_t r : region_of_factor) implicit.push_back(&factors[r]);
  const DualProof proof(relaxation(model.graph), limits.dual, stop_at, implicit);
  out.bound = proof.bound();
  if (!proof.applies()) return out;
  for (size_t i = 0; i < region_of_factor.size(); ++i) {
    const RegionFactor& f = factors[region_of_factor[i]];
    const std::vector<std::vector<double>> scope_costs = proof.implicit_costs(i);
    std::vector<std::vector<double>> costs(f.graph.entries.size());
    for (size_t j = 0; j < costs.size(); ++j) costs[j].assign(f.graph.entries[j].size(), 0.0);
    for (size_t j = 0; j < f.item_of.size(); ++j) costs[f.item_of[j]] = scope_costs[j];
    f.graph.least(costs, nullptr, &out.fills[region_of_factor[i]]);
  }
  return out;
}

}  // namespace hodt
