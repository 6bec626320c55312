// Exact polynomial algorithms (paper, Section 2, and Gudmundsson, Hammar and van Kreveld, "Higher order Delaunay triangulations", 2002).
#pragma once
#include "hodt/solution.hpp"
#include "engines/factor_graph.hpp"

namespace hodt {

struct Explanation;  // explain.hpp

struct ExactOptions {
  bool trace = false;  // record the bottleneck search's thresholds
  DpLimits limits;     // progress, and the budget of the exact engine where one runs
  Explanation* explanation = nullptr;  // explain(): where the search records its tests
};

// True for the objectives with a polynomial exact algorithm here.
bool has_polynomial_exact(Objective o);

// A proven optimum. Throws LimitError for objectives without a polynomial
// algorithm (the NP-hard ones go through the factor graph engine instead).
Solution solve_polynomial(const FirstOrder& fo, Objective o, const ExactOptions& options);

}  // namespace hodt
