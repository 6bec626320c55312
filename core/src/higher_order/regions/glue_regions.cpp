#include "higher_order/regions/glue_regions.hpp"

#include <algorithm>
#include <map>
#include <tuple>

namespace hodt {

Regions glue_pairs(const Mesh& dt, const Regions& R, const std::function<bool(uint32_t, uint32_t)>& may_glue,
                   std::vector<std::pair<uint32_t, uint32_t>>* glued) {
  const uint32_t n = static_cast<uint32_t>(R.regions.size());
  // Fixed edges shared by two regions, per pair.
  std::map<std::pair<uint32_t, uint32_t>, uint32_t> shared;
  for (uint32_t e = 0; e < dt.halfedges.size(); ++e) {
    const int32_t twin = dt.halfedges[e];
    if (twin <= static_cast<int32_t>(e) || !R.fixed[e]) continue;
    const uint32_t a = R.region_of_triangle[e / 3], b = R.region_of_triangle[static_cast<uint32_t>(twin) / 3];
    if (a != b) ++shared[{std::min(a, b), std::max(a, b)}];
  }
  std::vector<std::tuple<uint32_t, uint32_t, uint32_t>> pairs;  // (edges shared, a, b)
  for (const auto& [ab, count] : shared)
    if (may_glue(ab.first, ab.second)) pairs.emplace_back(count, ab.first, ab.second);
  std::stable_sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) { return std::get<0>(x) > std::get<0>(y); });
  std::vector<uint32_t> mate(n, UINT32_MAX);
  for (const auto& [count, a, b] : pairs)
    if (mate[a] == UINT32_MAX && mate[b] == UINT32_MAX) {
      mate[a] = b, mate[b] = a;
      if (glued) glued->push_back({a, b});
    }

  // The edges between mates are no longer fixed; regions not glued keep what they listed.
  Regions out;
  out.order = R.order;
  out.useful = R.useful;
  out.near_outside = R.near_outside;
  out.fixed = R.fixed;
  for (uint32_t e = 0; e < dt.halfedges.size(); ++e) {
    const int32_t twin = dt.halfedges[e];
    if (twin >= 0 && mate[R.region_of_triangle[e / 3]] == R.region_of_triangle[static_cast<uint32_t>(twin) / 3])
      out.fixed[e] = 0;
  }
  cut_into_regions(dt, out);
  for (Region& region : out.regions) {
    const uint32_t was = R.region_of_triangle[region.delaunay_triangles[0]];
    if (mate[was] == UINT32_MAX) region.states = R.regions[was].states, region.complete = R.regions[was].complete;
    else region.complete = false;
    out.incomplete += !region.complete;
  }
  return out;
}

}  // namespace hodt
