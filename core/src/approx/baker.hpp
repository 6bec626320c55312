// Baker's approximation scheme over a factor graph (paper, Section 4): the quads
// get layers (peeling depth from the hull); for each shift i a cut every lambda
// layers drops the factors that straddle it, the remaining thick layers are
// independent and solved exactly by the factor graph DP, and the best shift wins.
//
// Guarantee (maximising a sum of non-negative factors): a factor whose scope spans
// s layers is dropped in at most s of the lambda shifts, so some shift drops at
// most s/lambda of the optimum; with lambda = ceil(s_max / epsilon) the best shift
// keeps at least (1 - epsilon) OPT. Bound: the optimum is at most any shift's
// relaxed optimum plus the largest values of the factors it dropped; the run
// reports the smallest such bound, so value <= OPT <= bound is certified.
#pragma once
#include <cstdint>
#include <vector>

#include "hodt/first_order.hpp"
#include "engines/factor_graph.hpp"

namespace hodt {

// Depth of each vertex: the number of edges of `m` from the hull (vertex BFS),
// an outerplanarity peeling; adjacent vertices differ by at most one.
std::vector<uint32_t> hull_depth(const Mesh& m, const Progress& progress = {});
// Layer of each quad: the smallest depth of its corners.
std::vector<uint32_t> quad_layers(const FirstOrder& fo, const Progress& progress = {});

struct BakerShift {
  uint32_t shift;
  double relaxed;   // sum of the thick layers' optima (dropped factors count 0)
  double value;     // true objective of the union of their choices
  double bound;     // relaxed + max of each dropped factor: >= OPT
  uint32_t dropped; // factors dropped by the cut
};

struct BakerResult {
  Choice choice;
  double value;          // the model's value of choice
  double bound;          // certified upper bound on the optimum
  uint32_t lambda;       // layers per period
  std::vector<BakerShift> shifts;
  uint32_t width;        // widest thick-layer decomposition solved
  bool local_search_improved = false;
  std::vector<Choice> shift_choices;  // per shift its choice, when asked for (explain)
};

// g: Sense::Max, Combine::Sum, non-negative tables (throws std::logic_error else);
// each shift borrows its factors and returns them, so g is as given on return
// (also when it throws). Factors with a scope of more than max_scope variables
// are always dropped (the paper's degree cap for non-mixed vertices). Throws
// LimitError if a thick layer is wider than limits.max_width.
BakerResult baker(FactorGraph& g, const std::vector<uint32_t>& layer, double epsilon,
                  const DpLimits& limits, uint32_t max_scope = UINT32_MAX, bool keep_shift_choices = false);

// Local search that only improves: single flips, then pairs of quads sharing a
// factor, until no move helps. Returns true if it improved the value.
bool improve_locally(const FactorGraph& g, Choice& choice, const Progress& progress = {});

// Reverts flipped quads to their Delaunay diagonal, one by one, whenever that does
// not make the value worse (sum graphs): the same value with fewer flips.
void prefer_delaunay(const FactorGraph& g, Choice& choice, const Progress& progress = {});

}  // namespace hodt
