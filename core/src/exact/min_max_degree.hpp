// Minimum maximum degree (NP-hard, paper Theorem 5). Exact: binary search on the
// degree bound D; "is max degree <= D possible?" is a factor graph with a 0/1
// violation term per vertex that could exceed D, whose optimum is 0 iff feasible.
// Terms of vertices that cannot exceed D vanish, so the decompositions stay narrow
// far more often than a single min-max factor graph would.
#pragma once
#include "hodt/first_order.hpp"
#include "engines/factor_graph.hpp"

namespace hodt {

struct DegreeBounds {
  uint32_t lower;  // max of the largest fixed degree and the average degree (rounded up)
  uint32_t upper;  // max degree of the Delaunay (base) triangulation
};
DegreeBounds degree_bounds(const FirstOrder& fo);

// The optimal choice; throws LimitError if a feasibility test is over the
// budget of limits (a vertex term or a decomposition too large).
Choice min_max_degree_exact(const FirstOrder& fo, const DpLimits& limits);

// The feasibility model for bound D (exposed for tests and the teaching view);
// throws LimitError naming the vertex if a term is over the budget of limits.
FactorGraph degree_feasibility_model(const FirstOrder& fo, uint32_t bound, const DpLimits& limits = {});

}  // namespace hodt
