// What an order-k solve returns: the triangulation, its value, whether it is
// proven optimal (else a proven bound), what found and proved it, and the
// phases that ran.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/solution.hpp"

namespace hodt {

struct KOrderResult {
  Mesh triangulation;
  double value = 0;
  double delaunay_value = 0;
  bool optimal = false;
  std::optional<double> bound;
  uint64_t enumerated = 0;  // triangulations enumerated (brute force)
  std::string method;       // "brute-force", "exact" or "heuristic"
  std::string details;      // what ran, in a few words
  std::vector<PhaseStep> phases;  // the phases that ran (the top order's)
};

}  // namespace hodt
