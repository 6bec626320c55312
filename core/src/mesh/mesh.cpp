#include "hodt/mesh.hpp"

#include <algorithm>

#include "hodt/predicates.hpp"
#include "containers/out_of_line.hpp"
#include "mesh/mesh_of.hpp"

namespace hodt {
namespace {
void link(Mesh& m, uint32_t x, int32_t y) {
  m.halfedges[x] = y;
  if (y >= 0) m.halfedges[static_cast<uint32_t>(y)] = static_cast<int32_t>(x);
}
}  // namespace

// Triangle (A, B, C) holds a: A -> B; triangle (B, A, D) holds b: B -> A. The quad
// is A, D, B, C counterclockwise; the new triangles are (D, C, A) and (C, D, B) with
// the new diagonal D -> C in a's slot and C -> D in b's slot.
void flip_edge(Mesh& m, uint32_t a) {
  const uint32_t b = static_cast<uint32_t>(m.halfedges[a]);
  const uint32_t an = next_halfedge(a), ap = prev_halfedge(a);
  const uint32_t bn = next_halfedge(b), bp = prev_halfedge(b);
  const uint32_t A = m.triangles[a], B = m.triangles[an], C = m.triangles[ap], D = m.triangles[bp];
  const int32_t h_an = m.halfedges[an], h_ap = m.halfedges[ap];
  const int32_t h_bn = m.halfedges[bn], h_bp = m.halfedges[bp];
  m.triangles[a] = D, m.triangles[an] = C, m.triangles[ap] = A;
  m.triangles[b] = C, m.triangles[bn] = D, m.triangles[bp] = B;
  link(m, a, static_cast<int32_t>(b));
  link(m, an, h_ap);  // C -> A
  link(m, ap, h_bn);  // A -> D
  link(m, bn, h_bp);  // D -> B
  link(m, bp, h_an);  // B -> C
}

std::string link_halfedges(Mesh& m) {
  const uint32_t nv = m.num_vertices();
  const size_t ne = m.triangles.size();
  m.halfedges.assign(ne, -1);
  // Bucket halfedges by origin (counting sort), then find each twin among the
  // halfedges leaving its target: O(sum of degrees squared) = O(n) for bounded stars.
  std::vector<uint32_t> start(nv + 1, 0), out(ne);
  for (size_t e = 0; e < ne; ++e) ++start[m.triangles[e] + 1];
  for (uint32_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<uint32_t> fill(start.begin(), start.end() - 1);
  for (size_t e = 0; e < ne; ++e) out[fill[m.triangles[e]]++] = static_cast<uint32_t>(e);
  for (size_t e = 0; e < ne; ++e) {
    const uint32_t u = m.triangles[e], v = m.triangles[next_halfedge(static_cast<uint32_t>(e))];
    for (uint32_t k = start[v]; k < start[v + 1]; ++k) {
      const uint32_t f = out[k];
      if (m.triangles[next_halfedge(f)] != u) continue;
      if (f < e) continue;  // linked when f was visited
      if (m.halfedges[e] >= 0 || m.halfedges[f] >= 0)
        return "edge " + std::to_string(u) + "-" + std::to_string(v) + " is shared by more than two triangles";
      m.halfedges[e] = static_cast<int32_t>(f);
      m.halfedges[f] = static_cast<int32_t>(e);
    }
    for (uint32_t k = start[u]; k < start[u + 1]; ++k) {
      const uint32_t f = out[k];
      if (f != e && m.triangles[next_halfedge(f)] == v)
        return "two triangles use edge " + std::to_string(u) + "->" + std::to_string(v) +
               " in the same direction (triangles " + std::to_string(e / 3) + " and " +
               std::to_string(f / 3) + ": overlapping or inconsistently oriented)";
    }
  }
  // Hull: the twinless halfedges form the boundary; follow them from the smallest vertex.
  m.hull.clear();
  std::vector<int32_t> hull_next(nv, -1);
  uint32_t first = nv;
  size_t count = 0;
  for (size_t e = 0; e < ne; ++e) {
    if (m.halfedges[e] >= 0) continue;
    const uint32_t u = m.triangles[e];
    if (hull_next[u] >= 0) return "vertex " + std::to_string(u) + " is on the boundary twice";
    hull_next[u] = static_cast<int32_t>(m.triangles[next_halfedge(static_cast<uint32_t>(e))]);
    first = std::min(first, u);
    ++count;
  }
  if (count == 0) return "the triangulation has no boundary";
  uint32_t v = first;
  do {
    m.hull.push_back(v);
    v = static_cast<uint32_t>(hull_next[v]);
  } while (v != first && m.hull.size() <= count);
  if (m.hull.size() != count) return "the boundary is not a single cycle";
  return {};
}

void canonicalize(Mesh& m) {
  const uint32_t nt = m.num_triangles(), nv = m.num_vertices();
  // Rotate each triangle to start at its smallest vertex; remember by how much.
  std::vector<uint8_t> rotation(nt);
  // (Each long loop out of line: containers/out_of_line.hpp.)
  for_each_index(nt, [&](uint32_t t) {
    uint32_t* v = &m.triangles[3 * t];
    const uint8_t r = v[1] < v[0] && v[1] < v[2] ? 1 : v[2] < v[0] && v[2] < v[1] ? 2 : 0;
    std::rotate(v, v + r, v + 3);
    rotation[t] = r;
  });
  // Counting sort by first vertex, then by second within each bucket.
  std::vector<uint32_t> start(nv + 1, 0);
  for_each_index(nt, [&](uint32_t t) { ++start[m.triangles[3 * t] + 1]; });
  for (uint32_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<uint32_t> order(nt);
  for_each_index(nt, [&](uint32_t t) { order[start[m.triangles[3 * t]]++] = t; });  // start[v] ends at v + 1's
  for (uint32_t v = nv; v-- > 0;) start[v + 1] = start[v];
  start[0] = 0;
  for_each_index(nv, [&](uint32_t v) {
    std::sort(order.begin() + start[v], order.begin() + start[v + 1],
              [&](uint32_t s, uint32_t t) { return m.triangles[3 * s + 1] < m.triangles[3 * t + 1]; });
  });
  start = {};
  std::vector<uint32_t> position(nt);  // new slot of each old triangle
  for_each_index(nt, [&](uint32_t k) { position[order[k]] = k; });
  order = {};
  const bool linked = m.halfedges.size() == m.triangles.size();
  if (linked) {
    // Halfedge 3t + k of old triangle t becomes 3 * position(t) + (k - rotation) mod 3:
    // renumber the twins, rotate each triangle's entries like its vertices.
    auto renumber = [&](uint32_t e) { return 3 * position[e / 3] + (e % 3 + 3 - rotation[e / 3]) % 3; };
    for_each_index(m.halfedges.size(), [&](size_t e) {
      int32_t& f = m.halfedges[e];
      if (f >= 0) f = static_cast<int32_t>(renumber(static_cast<uint32_t>(f)));
    });
    for_each_index(nt, [&](uint32_t t) { std::rotate(&m.halfedges[3 * t], &m.halfedges[3 * t + rotation[t]], &m.halfedges[3 * t + 3]); });
  }
  // Gather into new arrays, one at a time (triangles, then halfedges): faster than
  // permuting in place, and at most one array's worth of extra memory.
  {
    std::vector<uint32_t> sorted(m.triangles.size());
    for_each_index(nt, [&](uint32_t t) { std::copy_n(&m.triangles[3 * t], 3, &sorted[3 * position[t]]); });
    m.triangles.swap(sorted);
  }
  if (linked) {
    std::vector<int32_t> sorted(m.halfedges.size());
    for_each_index(nt, [&](uint32_t t) { std::copy_n(&m.halfedges[3 * t], 3, &sorted[3 * position[t]]); });
    m.halfedges.swap(sorted);
  }
  if (!linked) link_halfedges(m);
}

std::vector<int32_t> vertex_halfedges(const Mesh& m) {
  std::vector<int32_t> out(m.num_vertices(), -1);
  for_each_index(static_cast<uint32_t>(m.triangles.size()), [&](uint32_t e) {
    const uint32_t v = m.triangles[e];
    if (out[v] < 0 || m.halfedges[e] < 0) out[v] = static_cast<int32_t>(e);
  });
  return out;
}

std::string validate(const Mesh& m) {
  const uint32_t nv = m.num_vertices();
  if (m.triangles.size() % 3 != 0) return "triangle array length is not a multiple of 3";
  if (m.halfedges.size() != m.triangles.size()) return "halfedges and triangles differ in length";
  for (uint32_t e = 0; e < m.triangles.size(); ++e)
    if (m.triangles[e] >= nv) return "triangle " + std::to_string(e / 3) + " has a vertex out of range";
  for (uint32_t t = 0; t < m.num_triangles(); ++t) {
    const uint32_t* v = &m.triangles[3 * t];
    if (orient2d(m.point(v[0]), m.point(v[1]), m.point(v[2])) <= 0)
      return "triangle " + std::to_string(t) + " is not counterclockwise";
  }
  size_t boundary = 0;
  for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
    const int32_t f = m.halfedges[e];
    if (f < 0) { ++boundary; continue; }
    if (static_cast<size_t>(f) >= m.halfedges.size() || m.halfedges[f] != static_cast<int32_t>(e))
      return "halfedge " + std::to_string(e) + " and its twin do not point at each other";
    if (m.origin(e) != m.target(f) || m.target(e) != m.origin(f))
      return "halfedge " + std::to_string(e) + " and its twin do not join the same vertices";
  }
  if (m.hull.size() != boundary) return "hull length differs from the number of boundary halfedges";
  for (size_t k = 0; k < m.hull.size(); ++k) {
    const double* a = m.point(m.hull[k]);
    const double* b = m.point(m.hull[(k + 1) % m.hull.size()]);
    const double* c = m.point(m.hull[(k + 2) % m.hull.size()]);
    if (orient2d(a, b, c) < 0) return "hull is not convex and counterclockwise";
  }
  return {};
}

Mesh mesh_of(const Coords& coords, const std::vector<Tri>& triangles) {
  Mesh m;
  m.coords = coords;
  m.triangles.reserve(3 * triangles.size());
  for (const Tri& t : triangles) m.triangles.insert(m.triangles.end(), t.begin(), t.end());
  canonicalize(m);
  return m;
}

}  // namespace hodt
