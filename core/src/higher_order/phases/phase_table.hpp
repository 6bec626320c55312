// The order-k solve as a table: each row a phase (phases.hpp) with its name and
// the condition it runs under; one driver reads the rows in order, while the
// answer is not proven optimal (incumbent.hpp) and no phase gave a final one.
#pragma once
#include <vector>

#include "higher_order/phases/k_order_run.hpp"

namespace hodt {

struct KOrderPhase {
  const char* name;                    // what it does, in a few words
  bool (*applies)(const KOrderRun&);   // when it runs (besides: a gap is left)
  void (*run)(KOrderRun&);
};

// The rows, in the order they run.
const std::vector<KOrderPhase>& k_order_phases();

// Runs the rows over `run`; returns those that ran, each with its time and
// what it changed.
std::vector<PhaseStep> run_phases(KOrderRun& run);

}  // namespace hodt
