#include "hodt/higher_order.hpp"

#include <algorithm>
#include <array>

#include "hodt/error.hpp"
#include "hodt/measures.hpp"
#include "hodt/predicates.hpp"
#include "mesh/circle_count.hpp"

namespace hodt {

namespace {

// The point among `side` whose circle with a, b (a, b, s counterclockwise) is the
// smallest cap: no other point of `side` inside it.
uint32_t smallest_cap(const Mesh& m, uint32_t a, uint32_t b, const std::vector<uint32_t>& side) {
  uint32_t best = side[0];
  for (uint32_t s : side)
    if (s != best && in_circle(m.point(a), m.point(b), m.point(best), m.point(s))) best = s;
  return best;
}

struct Walker {
  const Mesh& m;
  uint32_t u;
  uint32_t max_crossings;
  std::vector<uint32_t> left, right;  // ends of the crossed edges, along the path
  // Each candidate w > u that crosses edges, with the smallest cap on each side
  // (Lemma 1 reads only those: the crossed edges' ends are not kept).
  struct Found {
    uint32_t w, left_cap, right_cap;
  };
  std::vector<Found> found;

  const double* p(uint32_t v) const { return m.point(v); }

  // Rays from u inside the open wedge (right of ray u->wl, left of ray u->wr) cross
  // halfedge h, which runs from its right end to its left end seen from u.
  void cross(uint32_t h, uint32_t wr, uint32_t wl) {
    const int32_t f = m.halfedges[h];
    if (f < 0 || left.size() >= max_crossings) return;
    const uint32_t r = m.origin(h), l = m.target(h);
    left.push_back(l);
    right.push_back(r);
    const uint32_t ff = static_cast<uint32_t>(f);
    const uint32_t w = m.apex(ff);  // triangle l, r, w beyond the edge
    const bool inside_right = orient2d(p(u), p(wr), p(w)) > 0;  // w left of ray u->wr
    const bool inside_left = orient2d(p(u), p(wl), p(w)) < 0;   // w right of ray u->wl
    // Edges of the far triangle: r -> w (next of ff) and w -> l (prev of ff), with
    // their right and left ends as seen from u.
    const uint32_t rw = next_halfedge(ff), wl_edge = prev_halfedge(ff);
    // Halfedge ff runs l -> r; next(ff) runs r -> w; prev(ff) runs w -> l. Seen from
    // u, crossing r -> w goes from right end r to left end w: we need the twin
    // orientation "right end first", which is the halfedge itself (u is on the
    // other side of it), and likewise w -> l.
    if (inside_right && inside_left) {
      if (w > u) found.push_back({w, smallest_cap(m, u, w, left), smallest_cap(m, w, u, right)});
      cross(rw, wr, w);
      cross(wl_edge, w, wl);
    } else if (!inside_left) {  // w on or beyond the left ray: rays leave through r -> w
      cross(rw, wr, wl);
    } else {  // w on or beyond the right ray: rays leave through w -> l
      cross(wl_edge, wr, wl);
    }
    left.pop_back();
    right.pop_back();
  }
};

// The points in the circle through a, b and the smallest cap on s's side of ab
// (a, b, s counterclockwise), or k + 1 if over k: walks the points inside the
// circle through s; a point inside on s's side of ab means s was not the smallest
// cap: move to it and look again. (Within k the walk sees every point inside.)
uint32_t cap_order(const Mesh& m, CircleCounter& circles, uint32_t a, uint32_t b, uint32_t s, uint32_t k) {
  for (;;) {
    const uint32_t count = circles.count(a, b, s, k);
    uint32_t better = s;
    for (uint32_t w : circles.inside())
      if (orient2d(m.point(a), m.point(b), m.point(w)) > 0 &&
          (better == s || in_circle(m.point(a), m.point(b), m.point(better), m.point(w))))
        better = w;
    if (better == s) return std::min(count, k + 1);
    s = better;
  }
}

}  // namespace

UsefulEdges useful_edges_by_order(const Mesh& m, uint32_t k, const Progress& progress) {
  const uint32_t n = m.num_vertices();
  const std::vector<int32_t> start = vertex_halfedges(m);
  CircleCounter circles(m);
  std::vector<std::pair<std::pair<uint32_t, uint32_t>, uint32_t>> out;  // (edge, order)
  for (uint32_t u = 0; u < n; ++u) {
    if (progress && (u & 255) == 0 && !progress(u, n)) throw Cancelled();
    Walker walk{m, u, k == 0 ? 0 : 2 * k - 1, {}, {}, {}};
    uint32_t e = static_cast<uint32_t>(start[u]);
    for (;;) {  // every triangle around u: u, a, b counterclockwise
      const uint32_t a = m.target(e), b = m.apex(e);
      if (a > u) out.push_back({{u, a}, 0});  // a Delaunay edge: useful for every k >= 0 (found from the smaller end)
      walk.cross(next_halfedge(e), a, b);
      const int32_t t = m.halfedges[prev_halfedge(e)];
      if (t < 0) {
        if (b > u) out.push_back({{u, b}, 0});
        break;
      }
      e = static_cast<uint32_t>(t);
      if (e == static_cast<uint32_t>(start[u])) break;
    }
    // Lemma 1 on each side (both sides have points: uw crosses edges).
    for (const Walker::Found& f : walk.found) {
      const uint32_t left = cap_order(m, circles, u, f.w, f.left_cap, k);
      const uint32_t order = left > k ? left : std::max(left, cap_order(m, circles, f.w, u, f.right_cap, k));
      if (order <= k) out.push_back({{u, f.w}, order});
    }
  }
  std::sort(out.begin(), out.end());  // (an edge found twice: its order once, the least first)
  UsefulEdges r;
  for (const auto& [edge, order] : out)
    if (r.edges.empty() || r.edges.back() != edge) r.edges.push_back(edge), r.order.push_back(static_cast<uint8_t>(order));
  return r;
}

std::vector<std::pair<uint32_t, uint32_t>> UsefulEdges::at(uint32_t j) const {
  std::vector<std::pair<uint32_t, uint32_t>> r;
  for (size_t i = 0; i < edges.size(); ++i)
    if (order[i] <= j) r.push_back(edges[i]);
  return r;
}

std::vector<std::pair<uint32_t, uint32_t>> useful_edges(const Mesh& m, uint32_t k, const Progress& progress) {
  return useful_edges_by_order(m, k, progress).edges;
}

std::vector<std::array<uint32_t, 3>> useful_triangles(const Mesh& m, uint32_t k,
                                                      const std::vector<std::pair<uint32_t, uint32_t>>& edges,
                                                      const Progress& progress) {
  const uint32_t n = m.num_vertices();
  std::vector<std::vector<uint32_t>> adj(n);
  for (auto [u, v] : edges) adj[u].push_back(v), adj[v].push_back(u);
  for (auto& a : adj) std::sort(a.begin(), a.end());
  CircleCounter circles(m);
  std::vector<std::array<uint32_t, 3>> out;
  for (size_t i = 0; i < edges.size(); ++i) {
    const auto [u, v] = edges[i];
    if (progress && (i & 1023) == 0 && !progress(static_cast<double>(i), static_cast<double>(edges.size()))) throw Cancelled();
    for (uint32_t w : adj[v]) {
      if (w <= v || !std::binary_search(adj[u].begin(), adj[u].end(), w)) continue;
      const int o = orient2d(m.point(u), m.point(v), m.point(w));
      if (o == 0) continue;
      const uint32_t count = o > 0 ? circles.count(u, v, w, k) : circles.count(u, w, v, k);
      if (count <= k) out.push_back({u, v, w});
    }
  }
  return out;
}

bool is_k_order(const Mesh& t, const Mesh& delaunay, uint32_t k, const Progress& progress) {
  CircleCounter circles(delaunay);
  for (uint32_t i = 0; i < t.num_triangles(); ++i) {
    if (progress && (i & 2047) == 0 && !progress(i, t.num_triangles())) throw Cancelled();
    if (circles.count(t.triangles[3 * i], t.triangles[3 * i + 1], t.triangles[3 * i + 2], k) > k) return false;
  }
  return true;
}

}  // namespace hodt
