#include "higher_order/search/k_order_baker.hpp"

#include <algorithm>
#include <cmath>

#include "approx/baker.hpp"

namespace hodt {

std::string KOrderBaker::summary() const {
  return "Baker's shifting at order k: lambda " + std::to_string(lambda) +
         (reduced ? " (reduced to cut three times)" : "") + ", " + std::to_string(exact_shifts) + " of " +
         std::to_string(shifts) + " shifts solved exactly";
}

std::vector<uint8_t> baker_bands(const Mesh& dt, const std::vector<uint32_t>& depth, uint32_t lambda, uint32_t shift) {
  std::vector<uint8_t> forced(dt.triangles.size(), 0);
  for (uint32_t t = 0; t < dt.num_triangles(); ++t) {
    bool band = false;
    for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
      const uint32_t d = depth[dt.triangles[e]];
      band = band || (d != UINT32_MAX && d % lambda == shift);
    }
    if (!band) continue;
    for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) {
      forced[e] = 1;
      if (dt.halfedges[e] >= 0) forced[static_cast<uint32_t>(dt.halfedges[e])] = 1;
    }
  }
  return forced;
}

KOrderBaker k_order_baker(const Mesh& dt, Objective o, const KOrderStructure& structure, uint32_t k,
                          double epsilon, uint64_t max_nodes, const Progress& progress) {
  KOrderBaker out;
  const std::vector<uint32_t> depth = hull_depth(dt, progress);
  uint32_t deepest = 0;
  for (uint32_t d : depth)
    if (d != UINT32_MAX) deepest = std::max(deepest, d);
  // The paper's lambda, unless fewer than three bands would cut the instance:
  // then as many layers as give three, so that a ring lies between two bands
  // (the guarantee is lost; the bound still holds).
  uint32_t lambda = static_cast<uint32_t>(std::min(std::ceil(2.0 * k / epsilon), 1e6));
  out.reduced = lambda > deepest / 3;
  if (out.reduced) lambda = deepest / 3;
  if (lambda < 2) return out;  // (too shallow to cut)
  out.lambda = lambda;
  const Sense sense = info(o).sense;
  // Each shift gets a share of the enumeration budgets: all shifts together cost
  // about what one run of the engine on the whole instance may.
  RegionLimits budgets;
  budgets.max_nodes_per_region = max_nodes;
  budgets.max_total_states /= lambda;
  budgets.max_states_per_region_dp = std::min(budgets.max_states_per_region_dp, budgets.max_total_states);
  budgets.max_total_nodes /= lambda;
  budgets.first_pass_states = std::min(budgets.first_pass_states, budgets.max_total_states / 8);
  budgets.large_region_states = std::min(budgets.large_region_states, budgets.max_total_states / 8);
  for (uint32_t s = 0; s < lambda; ++s) {
    const Progress step = progress ? Progress([&](double done, double total) {
      return progress(s + (total > 0 ? done / total : 0), lambda);
    }) : Progress();
    RegionEngine engine(dt, o, structure, k, budgets, step, baker_bands(dt, depth, lambda, s));
    std::string refused;
    std::vector<uint32_t> x;
    if (auto exact = engine.exact(step, refused)) x = std::move(*exact), ++out.exact_shifts;
    else x = engine.best_listed({}, step).regions;
    Mesh m = engine.R.triangulation(dt, x);
    const double v = evaluate(o, m);
    ++out.shifts;
    if (!out.triangulation || better(sense, v, out.value)) out.triangulation = std::move(m), out.value = v;
  }
  return out;
}

}  // namespace hodt
