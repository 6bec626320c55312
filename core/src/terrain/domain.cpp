#include "hodt/domain.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "hodt/error.hpp"
#include "hodt/format.hpp"
#include "hodt/measures.hpp"
#include "hodt/predicates.hpp"

namespace hodt {

std::vector<uint8_t> inside_triangles(const Mesh& m) {
  std::vector<uint8_t> inside(m.num_triangles(), 1);
  if (!has_domain(m)) return inside;
  // Each edge decided once, from its first halfedge, for both its triangles.
  const double max_edge = m.coords.max_edge();
  for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
    const int32_t f = m.halfedges[e];
    if (f >= 0 && static_cast<uint32_t>(f) < e) continue;
    if (compare_length(m.point(m.origin(e)), m.point(m.target(e)), max_edge) > 0) {
      inside[e / 3] = 0;
      if (f >= 0) inside[static_cast<uint32_t>(f) / 3] = 0;
    }
  }
  return inside;
}

std::vector<uint8_t> quads_touching_outside(const FirstOrder& fo) {
  std::vector<uint8_t> touching(fo.num_quads(), 0);
  if (!has_domain(fo.base)) return touching;
  const Mesh& m = fo.base;
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    const Quad& k = fo.quads[q];
    touching[q] = !edge_inside(m, k.a, k.b) || !edge_inside(m, k.c, k.d) || !edge_inside(m, k.a, k.c) ||
                  !edge_inside(m, k.c, k.b) || !edge_inside(m, k.b, k.d) || !edge_inside(m, k.d, k.a);
  }
  return touching;
}

std::vector<uint8_t> vertices_near_outside(const Mesh& dt, const std::vector<std::pair<uint32_t, uint32_t>>& useful) {
  std::vector<uint8_t> near(dt.num_vertices(), 0);
  if (!has_domain(dt)) return near;
  std::vector<std::vector<uint32_t>> adj(dt.num_vertices());
  auto join = [&](uint32_t u, uint32_t v) { adj[u].push_back(v), adj[v].push_back(u); };
  for (const auto& [u, v] : useful) join(u, v);
  for (uint32_t e = 0; e < dt.halfedges.size(); ++e)
    if (dt.halfedges[e] < static_cast<int32_t>(e)) join(dt.origin(e), dt.target(e));
  for (auto& a : adj) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
  }
  // A triangle uvw with a long edge uv: u, v and every common neighbour w.
  std::vector<uint32_t> common;
  for (uint32_t u = 0; u < adj.size(); ++u)
    for (uint32_t v : adj[u]) {
      if (v < u || edge_inside(dt, u, v)) continue;
      near[u] = near[v] = 1;
      common.clear();
      std::set_intersection(adj[u].begin(), adj[u].end(), adj[v].begin(), adj[v].end(), std::back_inserter(common));
      for (uint32_t w : common) near[w] = 1;
    }
  return near;
}

std::optional<std::string> empty_domain_warning(const Mesh& dt) {
  if (!has_domain(dt) || dt.num_triangles() == 0) return std::nullopt;
  const std::vector<uint8_t> inside = inside_triangles(dt);
  const size_t in = static_cast<size_t>(std::count(inside.begin(), inside.end(), 1)), all = inside.size();
  if (100 * in > all) return std::nullopt;
  std::vector<double> lengths;  // each edge once
  for (uint32_t e = 0; e < dt.halfedges.size(); ++e)
    if (dt.halfedges[e] < static_cast<int32_t>(e)) lengths.push_back(edge_length(dt.point(dt.origin(e)), dt.point(dt.target(e))));
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double median = lengths[lengths.size() / 2];
  return "the domain (maxEdge " + format_number(dt.coords.max_edge()) + ") leaves " + std::to_string(in) + " of " +
         std::to_string(all) + " triangles inside to be measured; the points' typical spacing (median Delaunay edge length) is " +
         format_number(median) + ": a larger maxEdge, or none, measures the terrain";
}

void check_max_edge(double max_edge) {
  if (!(max_edge > 0))
    throw InputError("maxEdge must be a positive length (or none), got " + format_number(max_edge));
}

}  // namespace hodt
