#include "higher_order/search/flip_search.hpp"

#include <algorithm>
#include <cmath>

#include "hodt/error.hpp"
#include "hodt/predicates.hpp"
#include "containers/flat_index.hpp"
#include "higher_order/fills/fill_enumerator.hpp"
#include "mesh/circle_count.hpp"
#include "objectives/objective_terms.hpp"

namespace hodt {

namespace {

// Calls visit(h) for every halfedge h leaving v, counterclockwise from the
// boundary (if v is on one), given one of them; returns the last (its
// previous halfedge has no twin when v's star is open).
template <class Visit>
uint32_t for_star(const Mesh& m, uint32_t h, Visit visit) {
  const uint32_t start = h;
  while (m.halfedges[h] >= 0) {  // clockwise to the boundary, if any
    const uint32_t g = next_halfedge(static_cast<uint32_t>(m.halfedges[h]));
    if (g == start) break;
    h = g;
  }
  for (const uint32_t first = h;;) {
    visit(h);
    const int32_t t = m.halfedges[prev_halfedge(h)];
    if (t < 0 || static_cast<uint32_t>(t) == first) return h;
    h = static_cast<uint32_t>(t);
  }
}

struct Local {
  const Mesh& m;
  const ObjectiveTerms& d;
  const std::vector<uint8_t>& on_hull;
  VertexTermMemo* memo;
  std::vector<uint32_t> nb, sorted;
  std::vector<Tri> tris;

  double add(double a, double b) const { return combine(d.combine, a, b); }

  // The vertex term of v, from an outgoing halfedge h.
  double vertex(uint32_t v, uint32_t h) {
    if (interior_only(d.site) && on_hull[v]) return 0;
    nb.clear();
    tris.clear();
    const uint32_t last = for_star(m, h, [&](uint32_t g) {
      nb.push_back(m.target(g));
      tris.push_back({m.origin(g), m.target(g), m.apex(g)});
    });
    if (m.halfedges[prev_halfedge(last)] < 0) nb.push_back(m.apex(last));  // (an open star's last neighbour)
    auto eval = [&] { return vertex_term(d, m, Star(v, nb, tris)); };
    if (!memo) return eval();
    sorted = nb;
    std::sort(sorted.begin(), sorted.end());
    return (*memo)(v, sorted, eval);
  }

  double edge(uint32_t h) const {
    const int32_t t = m.halfedges[h];
    if (t < 0 && interior_only(d.site)) return 0;
    return edge_term(d, m, m.origin(h), m.target(h), m.apex(h), t < 0 ? kNoApex : m.apex(static_cast<uint32_t>(t)));
  }

  // The terms that flipping the diagonal of halfedge e can change.
  double around(uint32_t e) {
    const uint32_t f = static_cast<uint32_t>(m.halfedges[e]);
    double v = 0;
    if (vertex_site(d.site)) {
      v = add(v, vertex(m.origin(e), e));
      v = add(v, vertex(m.target(e), next_halfedge(e)));
      v = add(v, vertex(m.apex(e), prev_halfedge(e)));
      v = add(v, vertex(m.apex(f), prev_halfedge(f)));
    } else if (edge_site(d.site)) {
      for (uint32_t h : {e, next_halfedge(e), prev_halfedge(e), next_halfedge(f), prev_halfedge(f)}) v = add(v, edge(h));
    } else {
      for (uint32_t t : {e / 3, f / 3}) v = add(v, triangle_term(d, m, {m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]}));
    }
    return v;
  }
};

}  // namespace

uint32_t improve_by_flips(Mesh& m, const Mesh& delaunay, uint32_t k, Objective o, const Progress& progress,
                          VertexTermMemo* memo) {
  const ObjectiveTerms& d = objective_terms(o, m);
  const Sense sense = info(o).sense;
  std::vector<uint8_t> on_hull(m.num_vertices(), 0);
  for (uint32_t v : m.hull) on_hull[v] = 1;
  CircleCounter circles(delaunay);
  Local local{m, d, on_hull, memo, {}, {}, {}};
  uint32_t flips = 0;
  // An edge is tried again only when a kept flip touched its quad's corners (the
  // terms it reads are theirs, its circles its quad's: untouched, it would not
  // flip now either), at a fraction of the tests of passes over every edge.
  // Edges are known by their ends (a flip, even undone, moves edges between
  // halfedge slots). A clock orders tries and touches (a set of settled edges,
  // each touch erasing the edges around a corner, reads nodes scattered in
  // memory at every touch; a clock is one store per vertex touched).
  uint32_t clock = 0;
  std::vector<uint32_t> touched(m.num_vertices(), 0);  // per vertex, when its star last changed
  FlatIndex tried;                                     // per edge, when it was last tried
  tried.reserve(m.halfedges.size());
  auto key = [&](uint32_t h) { return edge_key(std::min(m.origin(h), m.target(h)), std::max(m.origin(h), m.target(h))); };
  // (h has a twin: its quad's corners are its ends and their two apexes.)
  auto settled = [&](uint32_t h) {
    const uint32_t at = tried.find(key(h));
    const uint32_t g = static_cast<uint32_t>(m.halfedges[h]);
    return at != FlatIndex::kNone && at > std::max({touched[m.origin(h)], touched[m.target(h)], touched[m.apex(h)], touched[m.apex(g)]});
  };
  for (int pass = 0; pass < 30; ++pass) {
    if (progress && !progress(pass, 30)) throw Cancelled();
    bool changed = false;
    for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
      if (progress && (e & 4095) == 0 && !progress(pass * double(m.halfedges.size()) + e, 30.0 * m.halfedges.size()))
        throw Cancelled();
      const int32_t f = m.halfedges[e];
      if (f < static_cast<int32_t>(e) || settled(e)) continue;
      tried.assign(key(e), ++clock);
      const uint32_t a = m.origin(e), b = m.target(e), c = m.apex(e), x = m.apex(static_cast<uint32_t>(f));
      const int sa = orient2d(m.point(c), m.point(x), m.point(a)), sb = orient2d(m.point(c), m.point(x), m.point(b));
      if (sa == 0 || sb == 0 || sa == sb) continue;  // not strictly convex
      if (circles.count(a, x, c, k) > k || circles.count(x, b, c, k) > k) continue;
      const double before = local.around(e);
      flip_edge(m, e);
      const double after = local.around(e);
      // Strictly better, beyond rounding (sums of lengths are not exact).
      const double margin = d.combine == Combine::Sum ? 1e-12 * std::abs(before) : 0;
      if (sense == Sense::Min ? after < before - margin : after > before + margin) {
        changed = true, ++flips;
        // (The quad's corners: the new diagonal's ends and its two apexes.)
        ++clock;
        for (uint32_t h : {e, next_halfedge(e), prev_halfedge(e), prev_halfedge(static_cast<uint32_t>(m.halfedges[e]))})
          touched[m.origin(h)] = clock;
      } else {
        flip_edge(m, e);  // undo
      }
    }
    // (Done when every edge was tried since its corners last changed: an undone
    // flip moves its quad's edges between slots, so a pass can miss one.)
    bool all_tried = !changed;
    for (uint32_t e = 0; all_tried && e < m.halfedges.size(); ++e)
      all_tried = m.halfedges[e] < static_cast<int32_t>(e) || settled(e);
    if (all_tried) break;
  }
  canonicalize(m);
  return flips;
}

}  // namespace hodt
