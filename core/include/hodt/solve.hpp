// One entry point for every objective and method.
#pragma once
#include <string>

#include "hodt/progress.hpp"
#include "hodt/solution.hpp"

namespace hodt {

enum class Method : uint8_t { BruteForce, Exact, Approx, Auto };

struct Explanation;  // explain.hpp

struct SolveOptions {
  uint32_t order = 1;     // k: optimise over the k-th order Delaunay triangulations
  Method method = Method::Auto;
  double epsilon = 0.25;  // approximation schemes: value within (1 - epsilon) of optimal
  bool trace = false;     // record the bottleneck search (min-max pair objectives)
  uint32_t max_width = 20;  // exact engine: widest tree decomposition allowed (memory cap; Budgets::dp_max_width)
  // Long runs: phased(callback) to receive each phase by name, its fraction and
  // the time left (progress.hpp); a plain (done, total) function receives each
  // phase's fraction as (fraction, 1). false cancels.
  Progress progress;
  // A plain progress is called at every new phase and at most every this often
  // (0: at every progress point of the solvers, for tests); phased() has its own.
  double progress_interval_ms = kProgressIntervalMs;
  // explain(): where the solvers that run record what they built (not owned).
  Explanation* explanation = nullptr;
};

const char* method_id(Method m);
std::optional<Method> parse_method(std::string_view id);
std::string method_ids();  // "brute-force, exact, approx, auto"

// Solves objective over the first order triangulations of fo (order k: the k-th
// order ones, k_order.hpp). Throws LimitError when the method cannot handle the
// instance (with the reason), InputError for bad options (check_options) and
// Cancelled when progress says stop. The delaunay_value of the result is filled in.
Solution solve(const FirstOrder& fo, Objective objective, const SolveOptions& options);

}  // namespace hodt
