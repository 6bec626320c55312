// Approximations with certified bounds for the NP-hard objectives.
//  - max-convex-edges: Baker's scheme (Theorem 7), value >= (1 - epsilon) OPT.
//  - min-mixed-vertices: Baker's scheme on the non-mixed count (Theorem 8):
//    non-mixed(value) >= (1 - epsilon) non-mixed(OPT).
//  - minmax-degree: local search from the degree-balanced choice; every first order
//    triangulation is within a factor 2 of optimal (a vertex in k quads has at least
//    k fixed edges, so its degree is at most twice its fixed degree, and the largest
//    fixed degree is a lower bound), and the result reports that lower bound.
// Each is followed by a local search that can only improve the value.
// Within budget (DpLimits), always: vertex terms too large to tabulate are relaxed
// (counted at their best in the bound), a thick layer too wide for the DP falls
// back to the local search from Delaunay with every term at its best as the bound,
// and a degree test too large keeps the last proven lower bound. The value is
// always measured on the returned triangulation, the bound always certified.
#pragma once
#include "hodt/solution.hpp"
#include "hodt/solve.hpp"
#include "engines/roof_dual.hpp"

namespace hodt {

// built: the model exact built and refused (method auto), reused when it is the
// one Baker's scheme reads (a maximised sum: convex edges), so that the model
// and its roof dual are not computed twice.
Solution approximate(const FirstOrder& fo, Objective o, const SolveOptions& options, ReducedModel* built = nullptr);

}  // namespace hodt
