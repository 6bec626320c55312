// What the solvers really did, for teaching views and for checking them: the
// structures a solve built and decided on, recorded while it runs (never
// recomputed beside it). Flat arrays of indices, as everywhere else: quads by
// their index, the literal "quad q takes state x" as 2 q + x (0 keeps the
// Delaunay diagonal), vertices by their index in the terrain.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "hodt/solution.hpp"
#include "hodt/solve.hpp"

namespace hodt {

// One test of the bottleneck search (paper, Section 2.1): "is there a first
// order triangulation with every pair of triangles at most threshold?"
struct ThresholdTest {
  double threshold = 0;
  bool satisfiable = false;
  bool immediate_no = false;         // the floor is over it, or a quad is blocked
  std::vector<uint32_t> forced;      // (quad, the state it must take) pairs
  std::vector<uint32_t> blocked;     // a quad with both states over the threshold (the search stops at it)
  std::vector<uint32_t> clauses;     // (literal, literal) pairs, at least one holds; a forced quad's is a unit clause (a, a)
  std::vector<int32_t> component;    // per literal: its strongly connected component of the implication graph
                                     // (Tarjan's numbering, a reverse topological order), -1 if in no clause
  std::vector<uint32_t> conflicts;   // quads with both literals in one component: the reason for "no"
  std::vector<uint8_t> assignment;   // when satisfiable: a state per quad
};

// The min-max objectives at order 1: the values that can be the optimum and each
// test of the binary search over them.
struct SearchExplanation {
  double floor = 0;                  // the largest value no choice can avoid (fixed pairs)
  std::vector<double> candidates;    // ascending; the first is a lower bound, the last the Delaunay value
  std::vector<ThresholdTest> tests;  // in the order tested
};

// Baker's shifting (paper, Section 4), in the objective's own units.
struct BakerShiftExplanation {
  uint32_t shift = 0;
  double relaxed = 0;  // the optimum of what the shift keeps (dropped terms at their worst)
  double value = 0;    // the objective of the triangulation that optimum gives
  double bound = 0;    // relaxed with every dropped term at its best: the optimum is on this side of it
  uint32_t dropped = 0;              // terms the shift's cuts dropped
  std::vector<uint8_t> choice;       // its state per quad
};
struct BakerExplanation {
  uint32_t lambda = 0;               // layers per period: ceil(span / epsilon)
  uint32_t width = 0;                // widest thick layer's tree decomposition
  std::vector<uint32_t> layer;       // per quad: its peeling depth from the hull
  std::vector<BakerShiftExplanation> shifts;
};

// The exact engine (factor graph DP over a tree decomposition).
struct ExactExplanation {
  uint32_t width = 0;                // max bag size - 1
  uint32_t num_components = 0;       // independent parts of the quad graph
  std::vector<uint32_t> order;       // elimination order of the quads
  std::vector<uint32_t> component;   // per quad
};

// Order k (paper, Section 4.3): the useful edges, the fixed ones (in every k-OD
// triangulation) and the regions they cut the hull into.
struct RegionExplanation {
  uint32_t order = 1;
  std::vector<uint32_t> useful;            // useful k-OD edges, (u, v) pairs
  std::vector<uint32_t> fixed;             // the useful edges no other crosses, (u, v) pairs
  std::vector<uint32_t> triangles;         // the Delaunay triangles, vertex triples
  std::vector<int32_t> region_of_triangle; // per Delaunay triangle
  std::vector<uint32_t> triangulations;    // per region: its k-OD triangulations (counted up to a budget; 2 or more for a region of 2 or more triangles)
  std::vector<uint8_t> complete;           // per region: the count is exact (else at least that many)
};

struct Explanation {
  Solution solution;
  std::optional<SearchExplanation> search;
  std::optional<BakerExplanation> baker;
  std::optional<ExactExplanation> exact;
  std::optional<RegionExplanation> regions;
};

// Solves as solve() does, recording the structures of the solvers that ran, and
// the regions of options.order (at order 1: the flippable quads).
Explanation explain(const FirstOrder& fo, Objective objective, SolveOptions options);

}  // namespace hodt
