// A factor graph over variables with any number of states (a region's k-OD
// triangulations), solved exactly by variable elimination over a tree
// decomposition, or heuristically with a relaxation bound. A factor reads each of
// its variables through a projection of the states to classes (what the factor
// sees of a state: a fan around a vertex, an apex beside an edge), so its table
// stays small; the elimination reads each variable of a bag through the classes
// its tables can tell apart.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "hodt/objectives.hpp"
#include "hodt/progress.hpp"
#include "engines/factor_graph.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

struct StateFactor {
  std::vector<uint32_t> scope;                 // distinct variables
  std::vector<std::vector<uint32_t>> project;  // per scope variable: state -> class
  std::vector<uint32_t> dims;                  // classes per scope variable
  std::vector<double> table;                   // over the classes, first variable fastest
  uint32_t num_terms = 1;                      // objective terms combined in it
};

struct StateGraph {
  Combine combine = Combine::Sum;
  Sense sense = Sense::Min;
  double term_max = INFINITY;  // a term's largest possible value (relaxations)
  double constant = 0;
  std::vector<uint32_t> domain;              // states per variable
  std::vector<std::vector<double>> unary;    // per variable and state (combined)
  std::vector<uint32_t> unary_terms;         // terms in each variable's unary
  std::vector<StateFactor> factors;
  // Terms left out of the factors (too large to tabulate, or over a variable
  // whose states are not all known): the solution is then not exact, and a bound
  // must assume the best of them.
  uint64_t relaxed_terms = 0;
  std::vector<uint8_t> partial;  // per variable: its states are not all known
};

struct StateDpLimits {
  double max_table = kBudgets.state_dp_max_table;  // entries of the largest table (tuning/budgets.hpp)
  // A bag over max_table is split into mini-buckets, each optimising the
  // eliminated variable on its own: the value is then a bound on the optimum
  // (StateDpResult::bound_only), not the value of the state returned.
  bool mini_buckets = false;
  Progress progress;
};

struct StateDpResult {
  std::vector<uint32_t> state;  // per variable
  double value;                 // the model's value of it
  uint32_t width = 0;           // largest bag minus one
  double largest_table = 0;     // entries
  bool bound_only = false;      // mini-buckets were used: `value` bounds the optimum
};

// Merges the classes of a factor's variable that its table cannot tell apart,
// drops the variables it does not depend on, and folds factors of one variable
// into the unary terms (same values for every assignment).
void simplify(StateGraph& g, const Progress& progress = {});

// The exact optimum (ignoring relaxed terms: exact only if there are none):
// variable elimination for sums; for min-max, a binary search over the tables'
// values with a feasibility DP per threshold. Throws LimitError before building a
// table over limits.max_table entries.
StateDpResult solve_states(const StateGraph& g, const StateDpLimits& limits = {});

// The model's value of an assignment.
double evaluate_states(const StateGraph& g, const std::vector<uint32_t>& state);

// Coordinate descent from `start`: each variable in turn takes its best state for
// the others' current states, until no variable improves.
std::vector<uint32_t> improve_states(const StateGraph& g, std::vector<uint32_t> start, const Progress& progress = {});

// Large-neighbourhood search: windows of up to `window` variables (breadth-first
// balls in the factor graph), each solved exactly by the DP with the others fixed
// at their current states; windows whose tables exceed the limits are skipped.
std::vector<uint32_t> improve_by_windows(const StateGraph& g, std::vector<uint32_t> start, const StateDpLimits& limits = {},
                                         uint32_t window = 64);

// The relaxation: every relaxed term, and every term that sees a partial
// variable, replaced by the best value a term can take. Its optimum is a proven
// bound on the optimum over all assignments, including the states not listed.
StateGraph relaxation(const StateGraph& g);
// That optimum, by the DP (where its tables are too large, over mini-buckets,
// and then no weaker than each factor at its best on its own).
double relaxation_bound(const StateGraph& g, StateDpLimits limits = {});

// Min-max (terms combined by max, minimised): whether no assignment has every
// term below t, shown by arc consistency (states whose unary is t or more go,
// then every class no table entry below t supports with live classes, until
// nothing changes): true when some variable loses every state. Sound, not
// complete: false says nothing. Over the relaxation, true proves the optimum at
// least t, often at once where the DP's threshold search takes seconds.
bool none_below(const StateGraph& g, double t, const Progress& progress = {});

}  // namespace hodt
