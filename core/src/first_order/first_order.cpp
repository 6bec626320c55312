#include "hodt/first_order.hpp"

#include <algorithm>
#include <stdexcept>

#include "hodt/delaunay.hpp"
#include "hodt/error.hpp"
#include "hodt/predicates.hpp"

namespace hodt {

void FirstOrder::triangles_of(uint32_t q, bool flipped, uint32_t out[6]) const {
  const Quad& k = quads[q];
  const uint32_t t[6] = {k.a, k.b, k.c, k.b, k.a, k.d};  // abc, bad
  const uint32_t f[6] = {k.d, k.c, k.a, k.c, k.d, k.b};  // dca, cdb
  std::copy_n(flipped ? f : t, 6, out);
}

std::vector<uint8_t> FirstOrder::diagonal_mask() const {
  std::vector<uint8_t> mask(base.triangles.size(), 0);
  for (const Quad& q : quads) mask[q.edge] = mask[static_cast<uint32_t>(base.halfedges[q.edge])] = 1;
  return mask;
}

namespace {

bool strictly_convex(const Mesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  // a, b on opposite sides of cd (c, d are on opposite sides of ab by construction).
  const int sa = orient2d(m.point(c), m.point(d), m.point(a));
  const int sb = orient2d(m.point(c), m.point(d), m.point(b));
  return sa != 0 && sb != 0 && sa != sb;
}

Quad quad_at(const Mesh& m, uint32_t e) {
  const uint32_t f = static_cast<uint32_t>(m.halfedges[e]);
  return Quad{m.origin(e), m.target(e), m.apex(e), m.apex(f), e};
}

FirstOrder assemble(Mesh base, std::vector<Quad> quads, bool is_delaunay) {
  FirstOrder fo;
  fo.quad_of_triangle.assign(base.num_triangles(), -1);
  for (uint32_t q = 0; q < quads.size(); ++q) {
    const uint32_t e = quads[q].edge, f = static_cast<uint32_t>(base.halfedges[e]);
    for (uint32_t t : {e / 3, f / 3}) {
      if (fo.quad_of_triangle[t] >= 0)
        throw InputError("triangle " + std::to_string(t) + " (" + std::to_string(base.triangles[3 * t]) +
                         ", " + std::to_string(base.triangles[3 * t + 1]) + ", " +
                         std::to_string(base.triangles[3 * t + 2]) + ") touches two flippable edges");
      fo.quad_of_triangle[t] = static_cast<int32_t>(q);
    }
  }
  fo.base = std::move(base);
  fo.quads = std::move(quads);
  fo.is_delaunay = is_delaunay;
  return fo;
}

// Is a neighbour of v, other than the skipped three, strictly inside the circle
// of (p, q, r)? out[v] is an outgoing halfedge of v (the hull one on the hull).
bool neighbour_inside(const Mesh& m, const std::vector<int32_t>& out, uint32_t v, const double* p,
                      const double* q, const double* r, const uint32_t skip[3]) {
  const uint32_t start = static_cast<uint32_t>(out[v]);
  uint32_t e = start;
  for (;;) {
    const uint32_t w = m.target(e);
    if (w != skip[0] && w != skip[1] && w != skip[2] && in_circle(p, q, r, m.point(w))) return true;
    const int32_t t = m.halfedges[prev_halfedge(e)];
    if (t < 0) {  // v on the hull: the last neighbour is this triangle's apex
      const uint32_t x = m.apex(e);
      return x != skip[0] && x != skip[1] && x != skip[2] && in_circle(p, q, r, m.point(x));
    }
    e = static_cast<uint32_t>(t);
    if (e == start) return false;
  }
}

}  // namespace

// Quad (a, b, c, d) with Delaunay diagonal ab is flippable iff it is strictly
// convex and b is the only point inside circle(a, d, c) and a the only point inside
// circle(d, b, c). b is inside the first (it is the other diagonal's end), and the
// points strictly inside a circle through three vertices induce a connected
// subgraph of the Delaunay triangulation (lifted to the paraboloid they are the
// vertices below a plane, and a linear function on the lower hull decreases along
// edges to its minimum; circle_count.hpp). So a second point inside would make a
// neighbour of b inside: checking b's star (and a's for the other circle) decides.
bool flippable(const Mesh& dt, const std::vector<int32_t>& out, uint32_t e) {
  if (dt.halfedges[e] < 0) return false;
  const Quad q = quad_at(dt, e);
  if (!strictly_convex(dt, q.a, q.b, q.c, q.d)) return false;
  const double *a = dt.point(q.a), *b = dt.point(q.b), *c = dt.point(q.c), *d = dt.point(q.d);
  const uint32_t skip_a[3] = {q.a, q.c, q.d}, skip_b[3] = {q.b, q.c, q.d};
  return !neighbour_inside(dt, out, q.b, a, d, c, skip_a) && !neighbour_inside(dt, out, q.a, d, b, c, skip_b);
}

FirstOrder first_order(Mesh dt) {
  std::vector<uint8_t> marked(dt.halfedges.size(), 0);
  const std::vector<int32_t> out = vertex_halfedges(dt);
  for (uint32_t e = 0; e < dt.halfedges.size(); ++e)
    marked[e] = dt.halfedges[e] > static_cast<int32_t>(e) && flippable(dt, out, e);
  return first_order_of_marked(std::move(dt), marked);
}

FirstOrder first_order_of_marked(Mesh dt, const std::vector<uint8_t>& marked) {
  std::vector<Quad> quads;
  for (uint32_t e = 0; e < dt.halfedges.size(); ++e)
    if (marked[e]) quads.push_back(quad_at(dt, e));
  // No triangle is in two flippable quads (Gudmundsson, Hammar and van Kreveld, "Higher order Delaunay triangulations", 2002; the paper, Section 2): a violation
  // would be a bug in the predicates, reported rather than silently mis-modelled.
  try {
    return assemble(std::move(dt), std::move(quads), true);
  } catch (const InputError& e) {
    throw std::logic_error(std::string("first order structure: ") + e.what());
  }
}

FirstOrder singly_flippable(std::vector<double> coords, const std::vector<uint32_t>& tris,
                            const std::vector<uint32_t>& flip) {
  Mesh m;
  const uint32_t n = static_cast<uint32_t>(coords.size() / 3);
  m.coords = coords;
  if (tris.size() % 3 != 0)
    throw InputError("triangles: " + std::to_string(tris.size()) + " indices is not a multiple of 3");
  if (flip.size() % 2 != 0)
    throw InputError("flippable edges: " + std::to_string(flip.size()) + " indices is not a multiple of 2");
  m.triangles = tris;
  std::vector<uint32_t> used(n, 0);
  for (uint32_t t = 0; t < m.num_triangles(); ++t) {
    uint32_t* v = &m.triangles[3 * t];
    for (int k = 0; k < 3; ++k)
      if (v[k] >= n)
        throw InputError("triangle " + std::to_string(t) + ": vertex " + std::to_string(v[k]) +
                         " is out of range (" + std::to_string(n) + " points)");
    const int o = orient2d(m.point(v[0]), m.point(v[1]), m.point(v[2]));
    if (o == 0)
      throw InputError("triangle " + std::to_string(t) + " (" + std::to_string(v[0]) + ", " +
                       std::to_string(v[1]) + ", " + std::to_string(v[2]) + ") is degenerate (collinear)");
    if (o < 0) std::swap(v[1], v[2]);
    for (int k = 0; k < 3; ++k) ++used[v[k]];
  }
  for (uint32_t v = 0; v < n; ++v)
    if (!used[v]) throw InputError("point " + std::to_string(v) + " is not a vertex of any triangle");
  const std::string err = link_halfedges(m);
  if (!err.empty()) throw InputError("triangles: " + err);
  // The boundary must be the convex hull (with its collinear points), as in the
  // Delaunay triangulation of the same points.
  const Mesh dt = delaunay(coords);
  if (m.hull != dt.hull)
    throw InputError("triangles: the boundary is not the convex hull of the points");
  // A disk (Euler characteristic 1) whose every vertex star is one fan; with all
  // triangles counterclockwise and the boundary the hull, it covers the hull once.
  if (m.num_triangles() != dt.num_triangles())
    throw InputError("triangles: expected " + std::to_string(dt.num_triangles()) +
                     " triangles for these points, got " + std::to_string(m.num_triangles()) +
                     " (overlapping or missing triangles)");
  const std::vector<int32_t> start = vertex_halfedges(m);
  for (uint32_t v = 0; v < n; ++v) {
    uint32_t e = static_cast<uint32_t>(start[v]), fan = 0;
    do {
      ++fan;
      const int32_t t = m.halfedges[prev_halfedge(e)];
      if (t < 0) break;
      e = static_cast<uint32_t>(t);
    } while (e != static_cast<uint32_t>(start[v]) && fan <= used[v]);
    if (fan != used[v])
      throw InputError("triangles around point " + std::to_string(v) + " do not form a single fan");
  }
  // Designated edges.
  std::vector<Quad> quads;
  for (size_t k = 0; k < flip.size(); k += 2) {
    const uint32_t u = flip[k], v = flip[k + 1];
    const std::string name = "flippable edge " + std::to_string(k / 2) + " (" + std::to_string(u) + ", " +
                             std::to_string(v) + ")";
    if (u >= n || v >= n) throw InputError(name + ": vertex out of range");
    int32_t found = -1;
    uint32_t e = static_cast<uint32_t>(start[u]);
    do {
      if (m.target(e) == v) { found = static_cast<int32_t>(e); break; }
      if (m.apex(e) == v) { found = static_cast<int32_t>(prev_halfedge(e)); break; }
      const int32_t t = m.halfedges[prev_halfedge(e)];
      if (t < 0) break;
      e = static_cast<uint32_t>(t);
    } while (e != static_cast<uint32_t>(start[u]));
    if (found < 0) throw InputError(name + " is not an edge of the triangulation");
    uint32_t h = static_cast<uint32_t>(found);
    if (m.halfedges[h] < 0) throw InputError(name + " is on the convex hull, not flippable");
    h = std::min(h, static_cast<uint32_t>(m.halfedges[h]));
    for (const Quad& q : quads)
      if (q.edge == h) throw InputError(name + " is listed twice");
    const Quad q = quad_at(m, h);
    if (!strictly_convex(m, q.a, q.b, q.c, q.d))
      throw InputError(name + ": its quadrilateral is not strictly convex");
    quads.push_back(q);
  }
  std::sort(quads.begin(), quads.end(), [](const Quad& x, const Quad& y) { return x.edge < y.edge; });
  return assemble(std::move(m), std::move(quads), false);
}

Mesh triangulate(const FirstOrder& fo, const Choice& choice) {
  Mesh m = fo.base;
  for (uint32_t q = 0; q < fo.quads.size(); ++q)
    if (choice[q]) flip_edge(m, fo.quads[q].edge);
  return m;
}

uint32_t count_flipped(const Choice& choice) {
  return static_cast<uint32_t>(std::count_if(choice.begin(), choice.end(), [](uint8_t c) { return c != 0; }));
}

}  // namespace hodt
