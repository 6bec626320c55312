// Every objective as a factor graph over the quads: a term per vertex (class,
// extremum, degree), per edge (convexity) or per pair of quads (min-max pairs),
// each depending only on the quads around it. The exact engine (factor_graph.hpp)
// solves any of them; the NP-hard objectives have no better exact method.
#pragma once
#include "hodt/first_order.hpp"
#include "hodt/objectives.hpp"
#include "engines/factor_graph.hpp"
#include "engines/term_budget.hpp"

namespace hodt {

// A vertex term has 2^(quads at the vertex) entries: terms over the budget of
// limits (max_term_scope, max_term_work) are refused with a LimitError naming the
// vertex, or with OverBudget::Relax left out (counted in FactorGraph::relaxed).
// limits.progress is called while the tables are filled.
// Without constants, the vertex terms of vertices in no quad and the length terms
// of edges beside no quad are left out (total edge length and the vertex sums):
// the optimal choice is the same, its value is not.
FactorGraph factor_model(const FirstOrder& fo, Objective o, const DpLimits& limits = {},
                         OverBudget over = OverBudget::Refuse, bool constants = true);

}  // namespace hodt
