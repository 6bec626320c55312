// Every objective as a factor graph over the quads: a term per vertex (class,
// extremum, degree), per edge (convexity) or per pair of quads (min-max pairs),
// each depending only on the quads around it. The exact engine (factor_graph.hpp)
// solves any of them; the NP-hard objectives have no better exact method.
#pragma once
#include "hodt/factor_graph.hpp"
#include "hodt/first_order.hpp"
#include "hodt/objectives.hpp"

namespace hodt {

FactorGraph factor_model(const FirstOrder& fo, Objective o);

}  // namespace hodt
