// The reference solver: every one of the 2^m first order triangulations,
// measured directly on the triangulation (not through any solver's model).
#pragma once
#include <functional>
#include <vector>

#include "hodt/progress.hpp"
#include "hodt/solution.hpp"

namespace hodt {

// Optimum over all 2^m choices (Gray code order: one flip per step). Among optimal
// choices it returns one with the fewest flips, the first in Gray code order.
// Throws LimitError if m is over the brute force's budget (24 quads).
// progress (if given) is called for every triangulation (pace it: phased(), progress.hpp);
// returning false cancels.
Solution brute_force(const FirstOrder& fo, Objective objective, const Progress& progress = {});

// The value of every objective for every choice (index = choice bits, quad 0 the
// lowest bit): the teaching view's "all 2^m triangulations".
std::vector<std::array<double, kNumObjectives>> enumerate_all(const FirstOrder& fo);

}  // namespace hodt
