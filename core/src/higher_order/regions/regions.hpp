// The regions of order k. A useful k-OD edge that crosses no other useful k-OD
// edge is in every k-OD triangulation (a triangulation is a maximal plane graph
// and uses only useful edges). Such fixed edges are Delaunay edges (any other
// useful edge crosses a Delaunay edge), and they cut the hull into regions: unions
// of Delaunay triangles glued across the free Delaunay edges. The k-OD
// triangulations are exactly the products of one k-OD triangulation per region.
// At order 1 the regions with a choice are the flippable quads.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/skeleton.hpp"
#include "engines/factor_graph.hpp"
#include "higher_order/fills/fill_enumerator.hpp"
#include "tuning/budgets.hpp"

namespace hodt {

struct Region {
  std::vector<uint32_t> delaunay_triangles;             // its triangles in the Delaunay mesh
  std::vector<std::pair<uint32_t, uint32_t>> boundary;  // directed edges, the region on their left
  // Its k-OD triangulations; states[0] is the Delaunay one. Each lists the
  // triangles counterclockwise, starting at their smallest vertex, sorted.
  std::vector<std::vector<Tri>> states;
  bool complete = true;  // every k-OD triangulation of the region is in states
  // How far the DP by signature (fill_dp.hpp) got when its budget ran out: the
  // share of the region's triangles placed (1: it did not run out).
  double swept = 1;
};

struct Regions {
  uint32_t order = 1;
  std::vector<std::pair<uint32_t, uint32_t>> useful;  // useful k-OD edges (u < v)
  // Within a domain, per vertex: 1 if a k-OD triangle at it may be outside
  // (vertices_near_outside, domain.hpp); the terms at the others are the ones
  // without a domain (region_terms.hpp). Empty: every vertex may be.
  std::vector<uint8_t> near_outside;
  std::vector<uint8_t> fixed;                 // per Delaunay halfedge: in every k-OD triangulation
  std::vector<uint32_t> region_of_triangle;   // per Delaunay triangle
  std::vector<Region> regions;
  uint64_t incomplete = 0;                    // regions whose enumeration hit the budget

  // The triangles of one state per region, as a mesh (canonical order).
  Mesh triangulation(const Mesh& delaunay, const std::vector<uint32_t>& state) const;
};

class RegionTerms;  // region_terms.hpp

struct RegionLimits {
  // With an objective's terms, each region keeps only the best triangulation per
  // signature (region_terms.hpp), found by dynamic programming over partial fills
  // (fill_dp.hpp) within these many kept partial fills; a region over them is
  // enumerated instead, within the node budgets below.
  const RegionTerms* terms = nullptr;
  const Candidates* candidates = nullptr;  // k_order_candidates (computed when not given)
  // (Defaults and reasons: tuning/budgets.hpp, region_*.)
  uint64_t first_pass_states = kBudgets.region_first_pass_states;
  uint64_t max_states_per_region_dp = kBudgets.region_max_states_dp;
  uint64_t max_total_states = kBudgets.region_max_total_states;
  // Enumeration search nodes: every region first gets a small budget, then the
  // regions that need more get up to max_nodes_per_region each while the total
  // stays within max_total_nodes.
  uint64_t first_pass_nodes = kBudgets.region_first_pass_nodes;
  uint64_t max_nodes_per_region = kBudgets.region_max_nodes;
  uint64_t max_total_nodes = kBudgets.region_max_total_nodes;
  uint64_t max_states_per_region = kBudgets.region_max_listed;  // triangulations kept per region
  // Regions of more Delaunay triangles are not enumerated; with terms the DP
  // still tries them, within large_region_states kept fills each.
  uint32_t max_region_triangles = kBudgets.region_max_triangles;
  uint64_t large_region_states = kBudgets.large_region_states;
  // A second pass with larger budgets, of use only if it lists every region
  // whole (with terms): the regions already whole are kept, the others get the
  // DP, the largest first, until one does not fit.
  bool only_incomplete = false;
  Progress progress;
};

// Fixed edges and regions, each with its Delaunay triangulation only. forced: per
// Delaunay halfedge (both halves set), edges every triangulation must keep
// (Baker's bands, k_order_baker.hpp); empty: none.
Regions k_order_skeleton(const Mesh& delaunay, uint32_t k, const Progress& progress = {},
                         const std::vector<uint8_t>& forced = {});
// The same from the useful k-OD edges (useful_edges), computed once.
Regions k_order_skeleton(const Mesh& delaunay, uint32_t k, const std::vector<std::pair<uint32_t, uint32_t>>& useful,
                         const Progress& progress, const std::vector<uint8_t>& forced = {});
// The regions of out.fixed (Delaunay triangles glued across the edges not
// fixed), each with its Delaunay triangulation only: replaces out.regions and
// out.region_of_triangle.
void cut_into_regions(const Mesh& delaunay, Regions& out);
// Each region's k-OD triangulations (within the limits: a region over them keeps
// the ones found and is marked incomplete).
void enumerate_regions(const Mesh& delaunay, Regions& regions, const RegionLimits& limits = {});
// Both.
Regions k_order_regions(const Mesh& delaunay, uint32_t k, const RegionLimits& limits = {});

// Per region, the state whose triangles all belong to `m` (0 if none does: a
// region whose enumeration stopped early may lack it).
std::vector<uint32_t> listed_states(const Regions& regions, const Mesh& m);

// The Delaunay halfedges crossed by the segment u v (u, v vertices, uv not a
// Delaunay edge and through no other point).
std::vector<uint32_t> crossed_edges(const Mesh& delaunay, const std::vector<int32_t>& vertex_halfedge, uint32_t u,
                                    uint32_t v);

}  // namespace hodt
