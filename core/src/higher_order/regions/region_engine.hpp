// The engine on regions (order k): fixed edges and regions (regions.hpp), each
// region's best triangulations per signature (region_terms.hpp), and the state
// graph over them (region_model.hpp), solved exactly when everything is listed
// and the tables fit, else as the best combination of what the regions listed.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "higher_order/regions/region_model.hpp"
#include "higher_order/regions/region_terms.hpp"
#include "higher_order/regions/regions.hpp"

namespace hodt {

struct ListedBest {
  std::vector<uint32_t> regions;  // per region, its state
  double listed_value = 0;        // the listed DP's value (a bound when bound_only)
  bool bound_only = false;        // the DP ran over mini-buckets
  std::string how;
};

// What every engine on one instance at order k reads: its useful edges and
// candidate triangles (computed once; Baker's shifts restrict them).
struct KOrderStructure {
  KOrderStructure(const Mesh& delaunay, uint32_t k, const Progress& progress);
  // The same from the useful edges (useful_edges), computed once.
  KOrderStructure(const Mesh& delaunay, uint32_t k, std::vector<std::pair<uint32_t, uint32_t>> useful,
                  const Progress& progress);
  std::vector<std::pair<uint32_t, uint32_t>> useful;
  Candidates candidates;
};

struct RegionEngine {
  // forced: Delaunay edges every triangulation keeps (regions.hpp); the
  // structure must outlive the engine. budgets: the enumeration's (regions.hpp;
  // its candidates, terms and progress are set here).
  RegionEngine(const Mesh& delaunay, Objective o, const KOrderStructure& structure, uint32_t k,
               const RegionLimits& budgets, const Progress& progress, const std::vector<uint8_t>& forced = {});
  // The same from a skeleton of the structure's useful edges (k_order_skeleton),
  // computed once; memo (when given, it must outlive the engine): vertex terms
  // shared with the other engines of the solve.
  RegionEngine(const Mesh& delaunay, Objective o, const KOrderStructure& structure, Regions skeleton,
               const RegionLimits& budgets, const Progress& progress, VertexTermMemo* memo = nullptr);
  RegionEngine(const RegionEngine&) = delete;

  Regions R;
 private:
  const Candidates restricted_;  // (with forced edges: the structure's, restricted)
 public:
  const Candidates& cand;
  const RegionTerms terms;  // (reads R and cand)
  RegionLimits limits;
  RegionModelLimits model_limits;  // (every model of R: the engine's, rebuilt, the duals' and the views')
  RegionModel model;

  // Why the exact DP cannot run (a region not listed whole, a term not tabulated).
  std::optional<std::string> exact_refusal() const;
  // Per region, its state in an optimum; nothing (with the reason) when refused.
  std::optional<std::vector<uint32_t>> exact(const Progress& progress, std::string& refused,
                                             uint32_t* width = nullptr) const;
  // The best combination of the listed triangulations (by the DP, or over
  // mini-buckets then local search, also from start_regions when given).
  ListedBest best_listed(const std::vector<uint32_t>& start_regions, const Progress& progress) const;
};

// "n regions with a choice (up to m triangulations each)".
std::string region_summary(const Regions& R);

}  // namespace hodt
