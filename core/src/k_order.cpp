#include "hodt/k_order.hpp"

#include <algorithm>
#include <chrono>
#include <unordered_map>
#include <unordered_set>

#include "hodt/circle_count.hpp"
#include "hodt/error.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/measures.hpp"
#include "hodt/pair_measures.hpp"
#include "hodt/predicates.hpp"
#include "hodt/solve_options.hpp"

namespace hodt {

namespace {

constexpr uint32_t kMaxEnumeratedPoints = 30;

uint64_t key(uint32_t a, uint32_t b) { return (uint64_t(a) << 32) | b; }

// Candidate triangles: k-OD, every edge useful, no point inside; by directed edge
// (u -> v) the apexes w of the counterclockwise triangles u, v, w.
std::unordered_map<uint64_t, std::vector<uint32_t>> candidates(const Mesh& dt, uint32_t k) {
  const auto edges = useful_edges(dt, k);
  CircleCounter circles(dt);
  std::unordered_map<uint64_t, std::vector<uint32_t>> out;
  for (auto t : useful_triangles(dt, k, edges)) {
    if (orient2d(dt.point(t[0]), dt.point(t[1]), dt.point(t[2])) < 0) std::swap(t[1], t[2]);
    circles.count(t[0], t[1], t[2], k);  // the at most k points in its circle
    bool empty = true;
    for (uint32_t p : circles.inside())
      empty = empty && !(orient2d(dt.point(t[0]), dt.point(t[1]), dt.point(p)) >= 0 &&
                         orient2d(dt.point(t[1]), dt.point(t[2]), dt.point(p)) >= 0 &&
                         orient2d(dt.point(t[2]), dt.point(t[0]), dt.point(p)) >= 0);
    if (!empty) continue;
    for (int i = 0; i < 3; ++i) out[key(t[i], t[(i + 1) % 3])].push_back(t[(i + 2) % 3]);
  }
  return out;
}

bool crosses(const Mesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  if (a == c || a == d || b == c || b == d) return false;
  const int o1 = orient2d(m.point(a), m.point(b), m.point(c)), o2 = orient2d(m.point(a), m.point(b), m.point(d));
  const int o3 = orient2d(m.point(c), m.point(d), m.point(a)), o4 = orient2d(m.point(c), m.point(d), m.point(b));
  return o1 * o2 < 0 && o3 * o4 < 0;
}

struct Enumerator {
  const Mesh& dt;
  const std::unordered_map<uint64_t, std::vector<uint32_t>>& cand;
  uint64_t budget;
  const std::function<void(const std::vector<Tri>&)>& visit;
  const Progress& progress;
  std::unordered_set<uint64_t> open;  // directed edges with the uncovered side on their left
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  std::vector<Tri> tris;
  uint64_t nodes = 0;
  bool complete = true;

  const std::vector<uint32_t>* options(uint64_t e) const {
    const auto it = cand.find(e);
    return it == cand.end() ? nullptr : &it->second;
  }

  void run() {
    if (++nodes > budget) {
      complete = false;
      return;
    }
    if (progress && (nodes & 4095) == 0 && !progress(static_cast<double>(nodes), static_cast<double>(budget)))
      throw Cancelled();
    if (open.empty()) {
      visit(tris);
      return;
    }
    // The open edge with the fewest candidate triangles (ties: smallest key).
    uint64_t best = 0;
    size_t fewest = SIZE_MAX;
    for (uint64_t e : open) {
      const auto* o = options(e);
      const size_t c = o ? o->size() : 0;
      if (c < fewest || (c == fewest && e < best)) fewest = c, best = e;
    }
    if (fewest == 0) return;  // a dead end: nothing can cover this edge
    const uint32_t u = static_cast<uint32_t>(best >> 32), v = static_cast<uint32_t>(best);
    for (uint32_t w : *options(best)) {
      if (!complete) return;
      // The triangle's other sides v -> w and w -> u: each closes the open edge in
      // the same direction (that region is this triangle), or leaves the region
      // beyond it uncovered: the reversed edge opens, if it crosses nothing placed.
      bool ok = true;
      bool close[2];
      const uint32_t side[2][2] = {{v, w}, {w, u}};
      for (int s = 0; s < 2 && ok; ++s) {
        const uint32_t a = side[s][0], b = side[s][1];
        close[s] = open.count(key(a, b)) > 0;
        if (close[s]) continue;
        if (open.count(key(b, a))) { ok = false; break; }  // its far side is covered already
        for (auto [c, d] : edges)
          if ((c == a && d == b) || (c == b && d == a) || crosses(dt, a, b, c, d)) { ok = false; break; }
      }
      if (!ok) continue;
      open.erase(best);
      size_t added = 0;
      for (int s = 0; s < 2; ++s) {
        const uint32_t a = side[s][0], b = side[s][1];
        if (close[s]) open.erase(key(a, b));
        else open.insert(key(b, a)), edges.push_back({a, b}), ++added;
      }
      tris.push_back({u, v, w});
      run();
      tris.pop_back();
      for (int s = 1; s >= 0; --s) {
        const uint32_t a = side[s][0], b = side[s][1];
        if (close[s]) open.insert(key(a, b));
        else open.erase(key(b, a));
      }
      edges.resize(edges.size() - added);
      open.insert(best);
    }
  }
};

// The objective's terms touched by flipping the diagonal at halfedge e: the four
// corners (vertex objectives) or the five edges of the quad (edge objectives).
double local_value(Objective o, const Mesh& m, uint32_t e, const std::vector<uint8_t>& on_hull) {
  const uint32_t f = static_cast<uint32_t>(m.halfedges[e]);
  double v = 0;
  if (o == Objective::MaxConvexEdges) {
    for (uint32_t h : {e, next_halfedge(e), prev_halfedge(e), next_halfedge(f), prev_halfedge(f)}) {
      const int32_t t = m.halfedges[h];
      if (t < 0) continue;
      v += edge_shape(m.point(m.origin(h)), m.point(m.target(h)), m.point(m.apex(h)),
                      m.point(m.apex(static_cast<uint32_t>(t)))) == kConvexEdge;
    }
    return v;
  }
  std::vector<const double*> nb;
  for (uint32_t c : {m.origin(e), m.target(e), m.apex(e), m.apex(f)}) {
    if (on_hull[c]) continue;
    // Neighbours of c: walk its star from any outgoing halfedge (interior vertex).
    nb.clear();
    uint32_t h = c == m.origin(e) ? e : c == m.target(e) ? next_halfedge(e) : c == m.apex(e) ? prev_halfedge(e) : prev_halfedge(f);
    const uint32_t start = h;
    do {
      nb.push_back(m.point(m.target(h)));
      h = static_cast<uint32_t>(m.halfedges[prev_halfedge(h)]);
    } while (h != start);
    const Extremum x = extremum(m.point(c), nb.data(), static_cast<uint32_t>(nb.size()));
    v += o == Objective::MinLocalMinima ? x == kLocalMinimum : x != kNotExtremum;
  }
  return v;
}

}  // namespace

Mesh mesh_of(const Coords& coords, const std::vector<Tri>& triangles) {
  Mesh m;
  m.coords = coords;
  for (const Tri& t : triangles) m.triangles.insert(m.triangles.end(), t.begin(), t.end());
  canonicalize(m);
  return m;
}

bool enumerate_k_order(const Mesh& dt, uint32_t k, uint64_t max_nodes,
                       const std::function<void(const std::vector<Tri>&)>& visit, const Progress& progress) {
  const auto cand = candidates(dt, k);
  Enumerator en{dt, cand, max_nodes, visit, progress, {}, {}, {}};
  for (size_t i = 0; i < dt.hull.size(); ++i) en.open.insert(key(dt.hull[i], dt.hull[(i + 1) % dt.hull.size()]));
  en.run();
  return en.complete;
}

KOrderResult solve_k_order(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options, uint64_t max_nodes) {
  if (!fo.is_delaunay) throw InputError("higher order needs the Delaunay triangulation: not for user triangulations");
  const Mesh& dt = fo.base;
  const Sense sense = info(o).sense;
  KOrderResult r;
  r.delaunay_value = evaluate(o, dt);
  // Exact: enumerate when the instance is small enough (beyond a few dozen points
  // the k-OD triangulations are far too many to list).
  bool have = false;
  std::vector<Tri> best;
  const bool small = dt.num_vertices() <= kMaxEnumeratedPoints;
  const bool enumerate = small && options.method != Method::Approx;  // approx: the heuristic alone
  const bool complete = enumerate && enumerate_k_order(dt, k, max_nodes, [&](const std::vector<Tri>& tris) {
    ++r.enumerated;
    const double v = evaluate(o, mesh_of(dt.coords, tris));
    if (!have || better(sense, v, r.value)) r.value = v, best = tris, have = true;
  }, options.progress);
  if (complete && have) {
    r.triangulation = mesh_of(dt.coords, best);
    r.optimal = true;
    r.method = options.method == Method::BruteForce ? "brute-force" : "exact";
    return r;
  }
  if (options.method == Method::BruteForce || options.method == Method::Exact)  // enumeration or nothing
    throw LimitError(std::string(options.method == Method::Exact ? "exact" : "brute force") + " at order " +
                     std::to_string(k) + " enumerates every k-OD triangulation and " +
                     (small ? "stopped at its budget of " + std::to_string(max_nodes) + " search nodes"
                            : "refuses " + std::to_string(dt.num_vertices()) + " points (at most " +
                                  std::to_string(kMaxEnumeratedPoints) + ")") +
                     "; use --method auto or approx");
  if (o != Objective::MinLocalMinima && o != Objective::MaxConvexEdges && o != Objective::MinLocalExtrema)
    throw LimitError(std::string("order ") + std::to_string(k) + ": " + info(o).id +
                     " is solved only by enumeration, and this instance has too many k-OD triangulations; "
                     "max-convex-edges, min-local-minima and min-local-extrema have a heuristic");
  // Heuristic: from the first order optimum, k-OD-preserving improving flips.
  SolveOptions first = options;
  first.method = Method::Auto;
  first.order = 1;
  Mesh m = triangulate(fo, solve(fo, o, first).choice);
  std::vector<uint8_t> on_hull(m.num_vertices(), 0);
  for (uint32_t v : m.hull) on_hull[v] = 1;
  CircleCounter circles(dt);
  const double sign = sense == Sense::Max ? 1 : -1;
  for (int pass = 0; pass < 30; ++pass) {
    if (options.progress && !options.progress(pass, 30)) throw Cancelled();
    bool changed = false;
    for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
      const int32_t f = m.halfedges[e];
      if (f < static_cast<int32_t>(e)) continue;
      const uint32_t a = m.origin(e), b = m.target(e), c = m.apex(e), d = m.apex(static_cast<uint32_t>(f));
      const int sa = orient2d(m.point(c), m.point(d), m.point(a)), sb = orient2d(m.point(c), m.point(d), m.point(b));
      if (sa == 0 || sb == 0 || sa == sb) continue;  // not strictly convex
      if (circles.count(a, d, c, k) > k || circles.count(d, b, c, k) > k) continue;
      const double before = local_value(o, m, e, on_hull);
      flip_edge(m, e);
      const double after = local_value(o, m, e, on_hull);
      if (sign * (after - before) > 0) changed = true;
      else flip_edge(m, e);  // undo
    }
    if (!changed) break;
  }
  canonicalize(m);
  r.triangulation = std::move(m);
  r.value = evaluate(o, r.triangulation);
  r.method = "heuristic";
  // Bounds: a vertex whose every possible neighbour (useful edge) is higher is a
  // minimum in every k-OD triangulation; convex edges are at most the interior edges.
  if (o == Objective::MinLocalMinima) {
    std::vector<uint8_t> always(dt.num_vertices(), 1);
    for (uint32_t v : dt.hull) always[v] = 0;
    for (auto [u, v] : useful_edges(dt, k)) {
      if (!(dt.point(v)[2] > dt.point(u)[2])) always[u] = 0;
      if (!(dt.point(u)[2] > dt.point(v)[2])) always[v] = 0;
    }
    r.bound = static_cast<double>(std::count(always.begin(), always.end(), 1));
  } else if (o == Objective::MaxConvexEdges) {
    r.bound = static_cast<double>((dt.triangles.size() - dt.hull.size()) / 2);
  }
  r.optimal = r.bound && *r.bound == r.value;
  return r;
}

Solution k_order_solution(const FirstOrder& fo, Objective o, uint32_t k, const SolveOptions& options) {
  SolveOptions checked = options;
  checked.order = k;
  check_options(checked);
  const auto t0 = std::chrono::steady_clock::now();
  KOrderResult r = solve_k_order(fo, o, k, options);
  Solution s;
  s.objective = o;
  s.method = r.method;
  s.order = k;
  s.value = r.value;
  s.delaunay_value = r.delaunay_value;
  s.optimal = r.optimal;
  s.bound = r.bound;  // heuristics: the bound that certifies (or not) the value
  s.details = r.method != "heuristic" ? std::to_string(r.enumerated) + " k-OD triangulations enumerated"
                                  : "first order optimum improved by k-OD flips";
  // Edges of the result that are not Delaunay edges.
  std::unordered_set<uint64_t> delaunay_edges;
  const Mesh& dt = fo.base;
  for (uint32_t e = 0; e < dt.triangles.size(); ++e)
    delaunay_edges.insert(key(std::min(dt.origin(e), dt.target(e)), std::max(dt.origin(e), dt.target(e))));
  const Mesh& m = r.triangulation;
  for (uint32_t e = 0; e < m.triangles.size(); ++e)
    if (m.halfedges[e] < static_cast<int32_t>(e))
      s.non_delaunay_edges += !delaunay_edges.count(key(std::min(m.origin(e), m.target(e)), std::max(m.origin(e), m.target(e))));
  s.critical = critical_pair(o, m);
  s.mesh = std::move(r.triangulation);
  s.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return s;
}

}  // namespace hodt
