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

#include "hodt/factor_graph.hpp"

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

// A graph reduced to its free variables when the roof dual applies (else the
// graph itself): what the exact engine and Baker's scheme solve. An optimum of
// the reduced graph, completed by fill(), is an optimum of the original.
struct PersistentReduction {
  FactorGraph graph;
  std::optional<RoofDual> roof;
  void fill(Choice& x) const {
    if (roof)
      for (size_t v = 0; v < x.size(); ++v)
        if (roof->fixed[v] >= 0) x[v] = static_cast<uint8_t>(roof->fixed[v]);
  }
};
PersistentReduction reduce_by_roof_dual(const FactorGraph& g, const Progress& progress = {});

}  // namespace hodt
