#include "hodt/explain.hpp"

#include <algorithm>

#include "higher_order/regions/regions.hpp"

namespace hodt {

namespace {

// The regions of order k with their triangulations counted by plain enumeration
// (no objective: each region's own k-OD triangulations, up to the budget).
RegionExplanation region_explanation(const Mesh& dt, uint32_t k, const Progress& progress) {
  RegionLimits limits;
  limits.progress = progress;
  const Regions r = k_order_regions(dt, k, limits);
  RegionExplanation e;
  e.order = k;
  for (auto [u, v] : r.useful) e.useful.insert(e.useful.end(), {u, v});
  for (uint32_t h = 0; h < dt.halfedges.size(); ++h)
    if (r.fixed[h] && dt.halfedges[h] < static_cast<int32_t>(h)) e.fixed.insert(e.fixed.end(), {dt.origin(h), dt.target(h)});
  e.triangles = dt.triangles;
  e.region_of_triangle.assign(r.region_of_triangle.begin(), r.region_of_triangle.end());
  for (const Region& region : r.regions) {
    // A region over the budgets keeps the triangulations listed so far, and one
    // too large to enumerate only its Delaunay one; yet a region of two or more
    // triangles has at least two: its triangles meet across a free edge, which a
    // useful edge crosses (else it would be fixed), and a useful edge is in some
    // k-OD triangulation, which differs from Delaunay inside this region (it
    // cannot cross the fixed edges around it). So an unfinished count is at
    // least two, never one.
    const size_t listed = region.states.size();
    const size_t at_least = !region.complete && region.delaunay_triangles.size() > 1 ? std::max<size_t>(listed, 2) : listed;
    e.triangulations.push_back(static_cast<uint32_t>(at_least));
    e.complete.push_back(region.complete);
  }
  return e;
}

}  // namespace

Explanation explain(const FirstOrder& fo, Objective objective, SolveOptions options) {
  Explanation e;
  options.explanation = &e;
  options.progress = as_phased(options.progress, options.progress_interval_ms);  // (one run: the solve and the regions)
  e.solution = solve(fo, objective, options);
  if (fo.is_delaunay) e.regions = region_explanation(fo.base, options.order, in_phase(options.progress, Phase::FindingRegions));
  return e;
}

}  // namespace hodt
