#include "hodt/drainage.hpp"

#include <algorithm>
#include <stdexcept>

#include "hodt/domain.hpp"
#include "hodt/predicates.hpp"

namespace hodt {
namespace {

// Per vertex, the steepest strictly lower neighbour, ties to the smaller index.
// That is the largest neighbour in one total order (slope descending, then index
// ascending) among those below, so it does not depend on the order neighbours are
// offered in: each halfedge offers its origin its target, and a hull halfedge,
// which has no twin to offer the other direction, also offers its target its
// origin. So every ordered pair of neighbours is offered exactly once.
std::vector<int32_t> downstream_points(const Mesh& m, const std::vector<uint32_t>& index) {
  std::vector<int32_t> down(m.num_vertices(), -1);
  const auto rank = [&](uint32_t v) { return index.empty() ? v : index[v]; };
  const auto offer = [&](uint32_t v, uint32_t w) {
    const double *pv = m.point(v), *pw = m.point(w);
    if (!(pw[2] < pv[2])) return;  // (heights are finite: exact comparison)
    const int32_t best = down[v];
    if (best >= 0) {
      const auto b = static_cast<uint32_t>(best);
      const int c = compare_descents(pv, pw, m.point(b));
      if (c < 0 || (c == 0 && rank(w) > rank(b))) return;
    }
    down[v] = static_cast<int32_t>(w);
  };
  for (uint32_t e = 0; e < m.triangles.size(); ++e) {
    offer(m.origin(e), m.target(e));
    if (m.halfedges[e] < 0) offer(m.target(e), m.origin(e));
  }
  return down;
}

// 1 for the vertices that are not interior in the domain's sense: on the hull, or
// (within a domain) a corner of a triangle outside it.
std::vector<uint8_t> boundary_vertices(const Mesh& m) {
  std::vector<uint8_t> boundary(m.num_vertices(), 0);
  for (uint32_t v : m.hull) boundary[v] = 1;
  if (has_domain(m)) {
    const std::vector<uint8_t> inside = inside_triangles(m);
    for (uint32_t t = 0; t < inside.size(); ++t)
      if (!inside[t])
        for (uint32_t k = 0; k < 3; ++k) boundary[m.triangles[3 * t + k]] = 1;
  }
  return boundary;
}

}  // namespace

Drainage drainage(const Mesh& m, const std::vector<uint32_t>& index) {
  const uint32_t n = m.num_vertices();
  if (!index.empty() && index.size() != n) throw std::logic_error("drainage: one index per vertex expected");
  Drainage d;
  d.downstream = downstream_points(m, index);
  const std::vector<uint8_t> boundary = boundary_vertices(m);
  for (uint32_t v = 0; v < n; ++v)
    if (d.downstream[v] < 0) (boundary[v] ? d.outlets : d.pits).push_back(v);

  // The network is a forest: each vertex has at most one downstream point, and
  // heights strictly fall along it, so no path returns. Peeling it from its
  // sources (vertices no one drains to) lists every vertex after all of its
  // upstream ones, a topological order, in time linear in n: a vertex is
  // listed when its last upstream neighbour is, and by then its accumulation,
  // 1 + the sum over its upstream neighbours, is complete.
  std::vector<uint32_t> upstream(n, 0);
  for (uint32_t v = 0; v < n; ++v)
    if (d.downstream[v] >= 0) ++upstream[static_cast<uint32_t>(d.downstream[v])];
  std::vector<uint32_t> order;
  order.reserve(n);
  for (uint32_t v = 0; v < n; ++v)
    if (upstream[v] == 0) order.push_back(v);
  d.accumulation.assign(n, 1);
  for (size_t i = 0; i < order.size(); ++i) {
    const int32_t w = d.downstream[order[i]];
    if (w < 0) continue;
    d.accumulation[static_cast<uint32_t>(w)] += d.accumulation[order[i]];
    if (--upstream[static_cast<uint32_t>(w)] == 0) order.push_back(static_cast<uint32_t>(w));
  }
  if (order.size() != n) throw std::logic_error("drainage: the network has a cycle");  // (heights fall: never)
  // Backwards, each vertex comes after its downstream point, whose basin is known.
  d.basin.resize(n);
  for (size_t i = n; i-- > 0;) {
    const uint32_t v = order[i];
    const int32_t w = d.downstream[v];
    d.basin[v] = w < 0 ? static_cast<int32_t>(v) : d.basin[static_cast<uint32_t>(w)];
  }
  return d;
}

Drainage drainage(const Terrain& terrain, const Mesh& mesh) {
  if (mesh.num_vertices() != terrain.structure().base.num_vertices())
    throw std::logic_error("drainage: the mesh is not a triangulation of the terrain's vertices");
  const Drainage k = drainage(mesh, terrain.input_index());
  const auto input = [&](int32_t v) { return v < 0 ? -1 : static_cast<int32_t>(terrain.to_input(static_cast<uint32_t>(v))); };
  const uint32_t n = terrain.num_input_points();
  Drainage d;
  d.downstream.assign(n, -1);
  d.basin.assign(n, -1);
  d.accumulation.assign(n, 0);
  for (uint32_t v = 0; v < mesh.num_vertices(); ++v) {
    const uint32_t i = terrain.to_input(v);
    d.downstream[i] = input(k.downstream[v]);
    d.basin[i] = input(k.basin[v]);
    d.accumulation[i] = k.accumulation[v];
  }
  d.pits = terrain.to_input(k.pits);
  d.outlets = terrain.to_input(k.outlets);
  std::sort(d.pits.begin(), d.pits.end());
  std::sort(d.outlets.begin(), d.outlets.end());
  return d;
}

}  // namespace hodt
