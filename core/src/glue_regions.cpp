#include "hodt/glue_regions.hpp"

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

  Regions out;
  out.order = R.order;
  out.useful = R.useful;
  out.fixed = R.fixed;
  std::vector<uint32_t> id(n, UINT32_MAX);
  for (uint32_t r = 0; r < n; ++r) {
    if (id[r] != UINT32_MAX) continue;
    id[r] = static_cast<uint32_t>(out.regions.size());
    if (mate[r] == UINT32_MAX) {
      out.regions.push_back(R.regions[r]);
      continue;
    }
    id[mate[r]] = id[r];
    const Region &a = R.regions[r], &b = R.regions[mate[r]];
    Region g;
    g.delaunay_triangles = a.delaunay_triangles;
    g.delaunay_triangles.insert(g.delaunay_triangles.end(), b.delaunay_triangles.begin(), b.delaunay_triangles.end());
    // The boundary less the edges between the two (each is on both, reversed).
    auto inner = [](const Region& x, std::pair<uint32_t, uint32_t> e) {
      return std::find(x.boundary.begin(), x.boundary.end(), std::pair{e.second, e.first}) != x.boundary.end();
    };
    for (const auto& e : a.boundary)
      if (!inner(b, e)) g.boundary.push_back(e);
    for (const auto& e : b.boundary)
      if (!inner(a, e)) g.boundary.push_back(e);
    std::vector<Tri> fill;
    std::merge(a.states[0].begin(), a.states[0].end(), b.states[0].begin(), b.states[0].end(), std::back_inserter(fill));
    g.states.push_back(std::move(fill));
    g.complete = false;
    out.regions.push_back(std::move(g));
  }
  for (uint32_t e = 0; e < dt.halfedges.size(); ++e) {
    const int32_t twin = dt.halfedges[e];
    if (twin < 0) continue;
    const uint32_t a = R.region_of_triangle[e / 3], b = R.region_of_triangle[static_cast<uint32_t>(twin) / 3];
    if (a != b && id[a] == id[b]) out.fixed[e] = 0;
  }
  out.region_of_triangle.resize(R.region_of_triangle.size());
  for (size_t t = 0; t < out.region_of_triangle.size(); ++t) out.region_of_triangle[t] = id[R.region_of_triangle[t]];
  for (const Region& region : out.regions) out.incomplete += !region.complete;
  return out;
}

}  // namespace hodt
