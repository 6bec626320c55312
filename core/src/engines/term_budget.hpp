// Which local terms of a model are small enough to tabulate. A term over s quads
// has a table of 2^s entries, each costing some work to compute (a vertex with many
// flippable quads around it, such as the centre of a wheel, has an exponential
// table): the budget (DpLimits) is checked before any table is allocated.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "engines/factor_graph.hpp"

namespace hodt {

struct TermSize {
  uint32_t scope;         // quads the term depends on
  double work_per_entry;  // elementary steps (predicate tests) to compute one entry
};

// What to do with the terms over the budget.
enum class OverBudget : uint8_t {
  Refuse,  // throw LimitError naming the term (exact methods)
  Relax,   // leave them out (approximations: the model becomes a relaxation)
};

// keep[k] = 1 for the terms to tabulate: those over limits.max_term_scope quads
// or limits.max_term_work steps are over the budget. name(k) describes term k for
// a message, such as "the vertex at (0, 0) has 22 flippable quads around it".
std::vector<uint8_t> plan_terms(const std::vector<TermSize>& terms, const DpLimits& limits, OverBudget over,
                                const std::function<std::string(size_t)>& name);

}  // namespace hodt
