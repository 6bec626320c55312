// What every solver returns.
#pragma once
#include <optional>
#include <string>

#include "hodt/first_order.hpp"
#include "hodt/objectives.hpp"
#include "hodt/skeleton.hpp"

namespace hodt {

// Each threshold the bottleneck search tested, in the order tested (for the CLI's --trace and the demo).
struct ThresholdStep {
  double threshold;
  bool satisfiable;
  uint32_t clauses;     // 2-SAT clauses built (forced choices count one each)
  uint32_t forced;      // quads whose choice the eliminations fixed
  bool immediate_no;    // a fixed pair or a quad with both diagonals over the threshold
};

// One phase of an order-k solve, as it ran (SolveOptions::trace): its name,
// its time, and the answer after it.
struct PhaseStep {
  std::string name;
  double ms = 0;
  std::optional<double> value;  // the answer's value after it (none yet)
  std::optional<double> bound;  // the proven bound after it (none yet)
  bool improved = false;        // it found a better triangulation
  bool tightened = false;       // it tightened the bound
  bool proved = false;          // the answer is optimal after it
};

// The two triangles that attain a min-max value.
struct CriticalPair {
  Tri first, second;
  double value;
};

struct Solution {
  Objective objective;
  std::string method;            // the method that ran: "brute-force", "exact", ...
  Choice choice;                 // one byte per quad
  double value = 0;              // objective value of the returned triangulation
  double delaunay_value = 0;     // value of the base (Delaunay) triangulation
  bool optimal = false;          // value is proven optimal
  std::optional<double> bound;   // proven bound on the optimum, when not optimal
  double time_ms = 0;
  bool local_search_improved = false;    // approximations: did the local search help?
  std::string details;                   // what ran, in a few words (for reports)
  std::optional<CriticalPair> critical;  // min-max pair objectives
  std::vector<ThresholdStep> trace;      // bottleneck search, when asked for
  std::vector<PhaseStep> phases;         // order k >= 2, when a trace is asked for
  // Higher order (k > 1): the triangulation itself (not a choice of diagonals), and
  // the number of its edges that are not Delaunay edges.
  uint32_t order = 1;
  std::optional<Mesh> mesh;
  uint32_t non_delaunay_edges = 0;
};

}  // namespace hodt
