// One order's solve over the k-OD triangulations: what its phases share (the
// instance, the regions' engine, the start, the answer), and the ladder that
// lower orders run on (KOrderShared). The phases are listed in phase_table.hpp.
#pragma once
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hodt/higher_order.hpp"
#include "hodt/progress.hpp"
#include "hodt/solution.hpp"
#include "hodt/solve.hpp"
#include "higher_order/bounds/region_dual.hpp"
#include "higher_order/phases/incumbent.hpp"
#include "higher_order/phases/k_order_result.hpp"
#include "higher_order/regions/region_engine.hpp"
#include "higher_order/regions/vertex_term_memo.hpp"
#include "objectives/objective_terms.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

// The first order optimum, the start at every order of the ladder: solved once.
struct FirstOrderStart {
  const FirstOrder& fo;
  Objective o;
  const SolveOptions& options;
  std::optional<Mesh> mesh;
  double value = 0;
  std::optional<Solution> solution;  // (method auto)
  const Mesh& get();
};

// What every order of one solve shares: the ladder's rungs solve the same
// instance at lower orders.
struct KOrderShared {
  const FirstOrder& fo;
  Objective o;
  const SolveOptions& options;
  const RegionLimits& region_limits;
  FirstOrderStart& first_order;
  VertexTermMemo* memo;  // (the ladder's orders meet the same stars too)
  Budgets budgets;
};

struct KOrderRun {
  // bounded: whether the answer needs its bound (a ladder's rung serves only as
  // a start, so it proves nothing). above: the useful edges of the order above
  // (a rung reads its own from them).
  // options: this order's (a rung's are its own: method auto, progress held).
  KOrderRun(const KOrderShared& shared, uint32_t k, const SolveOptions& options, bool bounded, const UsefulEdges* above);
  KOrderRun(const KOrderRun&) = delete;

  const KOrderShared& shared;
  const Mesh& dt;
  const Objective o;
  const uint32_t k;
  const bool bounded;
  const SolveOptions options;
  const Budgets& budgets;
  const ObjectiveTerms& description;
  const Sense sense;
  // The progress of each kind of step (progress.hpp).
  const Progress finding, exactly, searching, proving;

  // The useful edges of every order up to k (a rung's are the top order's).
  const UsefulEdges* above;
  UsefulEdges by_order;
  const UsefulEdges& orders() const { return above ? *above : by_order; }
  std::vector<std::pair<uint32_t, uint32_t>> useful;  // (moved into the structure)
  Regions skeleton;                                   // (moved into the engine)
  std::optional<KOrderStructure> structure;
  // The structure (the useful edges moved into it), built by the first phase that needs it.
  KOrderStructure& built_structure() {
    if (!structure) structure.emplace(dt, k, std::move(useful), finding);
    return *structure;
  }
  std::unique_ptr<RegionEngine> engine;
  std::optional<KOrderResult> lower;  // the ladder's rung below
  uint32_t lower_order() const { return k <= budgets.rung_step_max_order ? k - 1 : k / 2; }

  std::string refused;     // why the exact DP refused
  bool counts = false;     // integer terms summed: the dual bound applies
  bool provable = false;   // counts, and bounded
  bool dual_first = false; // the dual's proof comes before the relaxation's bound

  // The start of the search: the first order optimum (at order 1 Delaunay), or
  // the rung's answer when better.
  Mesh start;
  double start_value = 0;
  std::string start_name;
  double not_shown = NAN;        // a min-max value no proof showed optimal
  std::vector<uint8_t> changed;  // the regions given a triangulation since the model was built
  bool added = false;
  std::optional<RegionDual> unglued;  // the fill graphs' first reading, when glue might tighten it

  Incumbent answer;
  // The answer is another solver's, final as it is (its method and details).
  std::optional<std::string> method, details;

  Regions& R() { return engine->R; }
  // The bound so far, or none (infinite) before any.
  double bound() const {
    const std::optional<double> b = answer.bound();
    return b ? *b : sense == Sense::Min ? -INFINITY : INFINITY;
  }
  // Why `value` is optimal for a min-max objective, when the terms' floor or
  // arc consistency over the model's relaxation shows it; empty otherwise.
  std::string min_max_proof(double value);
  // Offers the start (to a fresh answer) when a min-max proof shows it optimal.
  bool prove_start();
};

// The answer at order k (a rung: bounded false).
KOrderResult solve_at_order(const KOrderShared& shared, uint32_t k, const SolveOptions& options, bool bounded,
                            const UsefulEdges* above);

// Adds to each incomplete region the part of a k-OD triangulation that lies in
// it; marks the regions it added to in `changed` (when given). Returns whether
// any was added.
bool add_states_of(Regions& R, const Mesh& delaunay, const Mesh& m, std::vector<uint8_t>* changed = nullptr);

// Reads the regions not listed whole through their fill graphs (region_dual.hpp):
// the best triangulation its descents find is offered to `answer`, its proof
// makes the answer optimal. Returns the bound. max_glue: while a gap is left,
// the regions read through graphs are glued in pairs and read again, up to
// max_glue times. unglued (when given): with max_glue 0, the first reading,
// kept when glue might close its gap; given back with max_glue > 0, the levels
// start from it.
std::optional<double> read_fill_graphs(KOrderRun& run, Incumbent& answer, const Progress& progress, uint32_t max_glue,
                                       uint32_t max_sweeps, std::optional<RegionDual>* unglued = nullptr);

}  // namespace hodt
