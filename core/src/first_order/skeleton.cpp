#include "hodt/skeleton.hpp"

#include <algorithm>

#include "hodt/measures.hpp"

namespace hodt {

namespace {
bool has_directed_edge(const Tri& t, uint32_t u, uint32_t v) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == u && t[(k + 1) % 3] == v) return true;
  return false;
}
bool contains(const Tri& t, uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }
}  // namespace

Side side_of(const FirstOrder& fo, uint32_t e) {
  const Mesh& m = fo.base;
  const uint32_t t = e / 3;
  Side s;
  s.quad = fo.quad_of_triangle[t];
  if (s.quad < 0) {
    s.tri[0] = s.tri[1] = base_triangle(m, t);
    return s;
  }
  const uint32_t u = m.origin(e), v = m.target(e);
  for (int x = 0; x < 2; ++x) {
    uint32_t six[6];
    fo.triangles_of(static_cast<uint32_t>(s.quad), x, six);
    const Tri t0 = {six[0], six[1], six[2]}, t1 = {six[3], six[4], six[5]};
    s.tri[x] = has_directed_edge(t0, u, v) ? t0 : t1;
  }
  return s;
}

uint32_t quad_triangles_at(const FirstOrder& fo, uint32_t q, uint32_t v, bool flipped, Tri out[2]) {
  uint32_t six[6];
  fo.triangles_of(q, flipped, six);
  uint32_t n = 0;
  for (int k = 0; k < 2; ++k) {
    const Tri t = {six[3 * k], six[3 * k + 1], six[3 * k + 2]};
    if (contains(t, v)) out[n++] = t;
  }
  return n;
}

double largest_triangle(const FirstOrder& fo, uint32_t q, bool flipped) {
  const Mesh& m = fo.base;
  uint32_t t[6];
  fo.triangles_of(q, flipped, t);
  return std::max(triangle_area(m.point(t[0]), m.point(t[1]), m.point(t[2])),
                  triangle_area(m.point(t[3]), m.point(t[4]), m.point(t[5])));
}

VertexIncidence vertex_incidence(const FirstOrder& fo) {
  const Mesh& m = fo.base;
  const uint32_t n = m.num_vertices();
  VertexIncidence vi;
  vi.quad_offset.assign(n + 1, 0);
  vi.fixed_offset.assign(n + 1, 0);
  for (const Quad& q : fo.quads)
    for (uint32_t v : {q.a, q.b, q.c, q.d}) ++vi.quad_offset[v + 1];
  for (uint32_t t = 0; t < m.num_triangles(); ++t)
    if (fo.quad_of_triangle[t] < 0)
      for (int k = 0; k < 3; ++k) ++vi.fixed_offset[m.triangles[3 * t + k] + 1];
  for (uint32_t v = 0; v < n; ++v) {
    vi.quad_offset[v + 1] += vi.quad_offset[v];
    vi.fixed_offset[v + 1] += vi.fixed_offset[v];
  }
  vi.quads.resize(vi.quad_offset[n]);
  vi.fixed.resize(vi.fixed_offset[n]);
  std::vector<uint32_t> qf(vi.quad_offset.begin(), vi.quad_offset.end() - 1);
  std::vector<uint32_t> ff(vi.fixed_offset.begin(), vi.fixed_offset.end() - 1);
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    const Quad& k = fo.quads[q];
    for (uint32_t v : {k.a, k.b, k.c, k.d}) vi.quads[qf[v]++] = q;
  }
  for (uint32_t t = 0; t < m.num_triangles(); ++t)
    if (fo.quad_of_triangle[t] < 0)
      for (int k = 0; k < 3; ++k) vi.fixed[ff[m.triangles[3 * t + k]]++] = t;
  return vi;
}

}  // namespace hodt
