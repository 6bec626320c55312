// A sum objective over some of the quads, the others' diagonals fixed: where a
// rule proves the best diagonal of most quads whatever the rest choose (the
// shorter one for total edge length, the reflex one for convex vertices), only
// the quads it cannot decide go to the factor graph, which sees them alone.
#pragma once
#include <cstdint>
#include <vector>

#include "hodt/first_order.hpp"
#include "hodt/objectives.hpp"
#include "engines/factor_graph.hpp"

namespace hodt {

// The best choice of the quads marked free, the others keeping their diagonal in
// `choice` (whose free entries are overwritten). Exact for sum objectives; throws
// LimitError if the free quads' decomposition is over the budget of limits.
void solve_free_quads(const FirstOrder& fo, Objective o, const std::vector<uint8_t>& free, Choice& choice,
                      const DpLimits& limits);

}  // namespace hodt
