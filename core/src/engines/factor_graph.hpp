// One exact engine for every objective that decomposes into local terms: a factor
// graph over the binary quad variables, solved by dynamic programming over a tree
// decomposition (paper, Section 4). The decomposition comes from a min-degree
// elimination order: eliminating a variable forms the bag {v} + its neighbours, the
// table DP combines the factors of the bag and optimises v out, keeping a
// back-pointer table to rebuild the optimal choice.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "hodt/first_order.hpp"
#include "hodt/objectives.hpp"
#include "hodt/progress.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

struct Factor {
  std::vector<uint32_t> scope;  // variables (quads), distinct
  std::vector<double> table;    // 2^|scope| values; bit k of the index is scope[k]
};

struct FactorGraph {
  uint32_t num_vars = 0;
  Sense sense = Sense::Min;
  Combine combine = Combine::Sum;  // constant (+) or (max) the factors' values
  double constant = 0;
  std::vector<Factor> factors;
  // Terms left out because they were too large to tabulate (DpLimits): the graph
  // is then a relaxation, and a bound must count each of them at its best value.
  uint32_t relaxed = 0;

  double evaluate(const Choice& x) const;
  // Drops from each factor the variables its table does not depend on, and folds
  // constant factors into `constant`: fewer interactions, narrower decompositions.
  void simplify(const Progress& progress = {});
};

// The exact engine's budgets, all checked before the memory or time is spent.
// (Defaults and reasons: tuning/budgets.hpp.)
struct DpLimits {
  uint32_t max_width = kBudgets.dp_max_width;  // largest bag minus one
  double max_table_bytes = kBudgets.dp_max_table_bytes;
  uint32_t max_term_scope = kBudgets.dp_max_term_scope;  // quads a term is tabulated over
  double max_term_work = kBudgets.dp_max_term_work;      // predicate tests per term
  Progress progress;
};

// A tree decomposition, as the elimination order's bags.
struct Decomposition {
  std::vector<uint32_t> order;               // elimination order
  std::vector<std::vector<uint32_t>> bags;   // bag of order[i]: order[i] and its later neighbours
  std::vector<uint32_t> component;           // per variable
  uint32_t num_components = 0;
  uint32_t width = 0;                        // max bag size - 1 (0 if no variables)
  std::vector<uint32_t> component_width;
  bool complete = true;                      // false: stopped at a bag wider than asked
};
// Elimination orders: min-degree, min-fill, or (Auto) min-degree and, when that
// is wider than max_width, min-fill on graphs of at most
// kBudgets.min_fill_variables variables (min-fill counts fill-ins: slower, often
// narrower).
enum class Elimination : uint8_t { Auto, MinDegree, MinFill };
// Stops early (complete = false) once a bag is wider than max_width: the fill-in
// of a wide component would cost far more memory and time than the answer needs.
Decomposition decompose(const FactorGraph& g, uint32_t max_width = UINT32_MAX, const Progress& progress = {},
                        Elimination elimination = Elimination::Auto);

struct DpResult {
  Choice choice;
  double value;
  Decomposition decomposition;
};

// The exact optimum. Throws LimitError naming the width if a component's
// decomposition is wider than limits.max_width, or the tables would need more
// than limits.max_table_bytes (before using the memory), and Cancelled if
// progress returns false.
DpResult solve_exact(const FactorGraph& g, const DpLimits& limits = {});

}  // namespace hodt
