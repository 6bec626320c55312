// Min-max ("bottleneck") objectives over first order triangulations (paper,
// Section 2.1-2.2): the objective is the largest value of a measure over pairs of
// triangles, each pair depending on at most two quads. The sorted candidate values
// are binary searched; each step decides "is there a triangulation with every pair
// at most t?" by the paper's eliminations and a linear-time 2-SAT.
#pragma once
#include <cstdint>
#include <vector>

#include "hodt/first_order.hpp"
#include "hodt/progress.hpp"
#include "hodt/skeleton.hpp"
#include "hodt/solution.hpp"
#include "containers/flat_index.hpp"

namespace hodt {

// A term of the objective: the worst pair value as a function of the choices of
// at most two quads. v[x_q + 2 * x_r]; a unary term (r < 0) uses v[0], v[1].
struct PairTerm {
  int32_t q = -1, r = -1;
  double v[4] = {0, 0, 0, 0};
};

struct BottleneckModel {
  uint32_t num_quads = 0;
  double floor = 0;              // a lower bound of the optimum: the worst pair between fixed
                                 // triangles (pruned models: or a term's least value)
  std::vector<PairTerm> terms;   // one per quad (unary) or pair of quads (binary)
};

struct BottleneckResult {
  Choice choice;
  double value;  // the optimal max
  std::vector<ThresholdStep> trace;
};

// Builds a model: a pair measure evaluated on triangles (vertex triples).
template <class Measure>
BottleneckModel edge_pair_model(const FirstOrder& fo, Measure measure, const Progress& progress = {});
// (star_below: see bottleneck_models.ipp; none by default)
constexpr auto kNoStarFilter = [](const Tri*, size_t, double) { return false; };
template <class Measure, class StarBelow = decltype(kNoStarFilter)>
BottleneckModel vertex_pair_model(const FirstOrder& fo, Measure measure, const Progress& progress = {},
                                  StarBelow star_below = kNoStarFilter);

struct SearchExplanation;  // explain.hpp
// record (optional): the candidates and every test in full (clauses, components).
BottleneckResult solve_bottleneck(const BottleneckModel& model, const Progress& progress = {},
                                  SearchExplanation* record = nullptr);

// Models are assembled term by term; terms over the same quads are merged (max).
// Pruned, a model keeps only values above its floor: every candidate threshold is
// at least the floor, so other values never make a clause, a bound or a candidate
// (constants should come first). Kept terms stay in the order the full model
// would list them (the 2-SAT answer depends on the clause order).
class BottleneckBuilder {
 public:
  // repeated_pairs: binary terms over the same quads may come more than once
  // (and are merged). Not so for edge pairs: two convex quads share at most
  // one edge.
  BottleneckBuilder(uint32_t num_quads, bool prune, bool repeated_pairs);
  double floor() const { return model_.floor; }
  void constant(double v);
  void unary(uint32_t q, double v0, double v1);
  // v[x_q + 2 * x_r], q != r
  void binary(uint32_t q, uint32_t r, const double v[4]);
  BottleneckModel finish(const Progress& progress = {});

 private:
  bool below_floor(const double* v, int n) const;
  // The kept term over (q, r), r = kUnary for a unary one; a new one at position seq.
  PairTerm* find(uint32_t q, uint32_t r);
  void add(const PairTerm& t, uint32_t seq);

  static constexpr uint32_t kUnary = UINT32_MAX, kNone = FlatIndex::kNone;
  BottleneckModel model_;
  bool prune_, repeated_pairs_;
  uint32_t next_seq_ = 0;               // positions in the full model: a unary term at
  std::vector<uint32_t> unary_seq_;     // its first part (per quad), a binary one at its last
  std::vector<uint32_t> seq_;           // per kept term
  std::vector<uint32_t> unary_term_;    // per quad: its kept unary term
  std::vector<uint8_t> in_binary_;      // per quad: in a kept binary term
  FlatIndex index_;  // (q, r) -> kept binary term (repeated pairs only)
};

}  // namespace hodt

#include "exact/bottleneck_models.ipp"
