// Roof duality (Hammer, Hansen and Simeone 1984) through the QPBO graph of
// Kolmogorov and Rother (2007), for factor graphs that are sums of terms over at
// most two binary variables with integer values (convex edges at order 1): one
// minimum cut gives a proven bound on the optimum and a partial assignment that
// some optimal assignment extends (weak persistency). The exact engine then
// needs only the variables left free, which on a raster's single wide component
// are few and scattered.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "engines/factor_graph.hpp"

namespace hodt {

struct RoofDual {
  double bound = 0;           // on the optimum, in the graph's sense (an upper bound when maximising)
  std::vector<int8_t> fixed;  // per variable: 0 or 1 (persistent), or -1 (free)
  uint32_t num_fixed = 0;
};

// Sum of terms over at most two variables, every value an integer of magnitude
// at most 2^40 (the cut is then computed exactly in 64-bit integers).
bool roof_dual_applies(const FactorGraph& g);

// Throws std::logic_error if !roof_dual_applies(g).
RoofDual roof_dual(const FactorGraph& g, const Progress& progress = {});

// The same graph with the variables of `fixed` (0 or 1; -1 free) set: their
// factors are restricted to the free variables, and those left with none are
// folded into the constant.
FactorGraph condition(const FactorGraph& g, const std::vector<int8_t>& fixed);

// A model and, when the roof dual applies, the same model over its free
// variables (renumbered 0, 1, ...: a raster keeps about 1 % of its quads): what
// the exact engine and Baker's scheme solve. An optimum of graph(), expanded, is
// an optimum of the model.
struct ReducedModel {
  FactorGraph model;
  std::optional<RoofDual> roof;
  FactorGraph free;                // with a roof: the model on the free variables
  std::vector<uint32_t> original;  // with a roof: per variable of free, the model's variable

  FactorGraph& graph() { return roof ? free : model; }
  const FactorGraph& graph() const { return roof ? free : model; }
  // An assignment of the model's variables: the fixed ones, and x on the free.
  Choice expand(const Choice& x) const;
  // Per variable of graph(), from values per variable of the model.
  std::vector<uint32_t> restrict(const std::vector<uint32_t>& per_variable) const;
};
ReducedModel reduce_by_roof_dual(FactorGraph model, const Progress& progress = {});

}  // namespace hodt
