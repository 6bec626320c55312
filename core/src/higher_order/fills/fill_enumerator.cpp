#include "higher_order/fills/fill_enumerator.hpp"

#include <algorithm>
#include <unordered_set>

#include "hodt/error.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/predicates.hpp"
#include "mesh/circle_count.hpp"

namespace hodt {

Candidates k_order_candidates(const Mesh& dt, uint32_t k, const std::vector<std::pair<uint32_t, uint32_t>>& edges,
                              const Progress& progress) {
  CircleCounter circles(dt);
  Candidates out;
  uint64_t done = 0;
  for (auto t : useful_triangles(dt, k, edges, progress)) {
    if (progress && (++done & 4095) == 0 && !progress(static_cast<double>(done), 0)) throw Cancelled();
    if (orient2d(dt.point(t[0]), dt.point(t[1]), dt.point(t[2])) < 0) std::swap(t[1], t[2]);
    circles.count(t[0], t[1], t[2], k);  // the at most k points in its circle
    bool empty = true;
    for (uint32_t p : circles.inside())
      empty = empty && !(orient2d(dt.point(t[0]), dt.point(t[1]), dt.point(p)) >= 0 &&
                         orient2d(dt.point(t[1]), dt.point(t[2]), dt.point(p)) >= 0 &&
                         orient2d(dt.point(t[2]), dt.point(t[0]), dt.point(p)) >= 0);
    if (!empty) continue;
    for (int i = 0; i < 3; ++i) out[edge_key(t[i], t[(i + 1) % 3])].push_back(t[(i + 2) % 3]);
  }
  return out;
}

Candidates restrict_candidates(const Candidates& all, const std::vector<std::pair<uint32_t, uint32_t>>& edges) {
  std::unordered_set<uint64_t> kept;
  for (const auto& [u, v] : edges) kept.insert(edge_key(u, v));
  auto has = [&](uint32_t a, uint32_t b) { return kept.count(a < b ? edge_key(a, b) : edge_key(b, a)) > 0; };
  Candidates out;
  for (const auto& [key, apexes] : all) {
    const uint32_t a = static_cast<uint32_t>(key >> 32), b = static_cast<uint32_t>(key);
    if (!has(a, b)) continue;
    std::vector<uint32_t> left;
    for (uint32_t c : apexes)
      if (has(b, c) && has(c, a)) left.push_back(c);
    if (!left.empty()) out.emplace(key, std::move(left));
  }
  return out;
}

bool segments_cross(const Mesh& m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  if (a == c || a == d || b == c || b == d) return false;
  // Boxes apart: no crossing (exact comparisons; most pairs a frontier scan tests).
  const double *pa = m.point(a), *pb = m.point(b), *pc = m.point(c), *pd = m.point(d);
  for (int i = 0; i < 2; ++i)
    if (std::max(pa[i], pb[i]) < std::min(pc[i], pd[i]) || std::max(pc[i], pd[i]) < std::min(pa[i], pb[i])) return false;
  if (orient2d(m.point(a), m.point(b), m.point(c)) * orient2d(m.point(a), m.point(b), m.point(d)) >= 0) return false;
  return orient2d(m.point(c), m.point(d), m.point(a)) * orient2d(m.point(c), m.point(d), m.point(b)) < 0;
}

namespace {

struct Enumerator {
  const Mesh& dt;
  const Candidates& cand;
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

  // Whether triangle u v w may cover the open edge u -> v: each of its other
  // sides either closes an open edge in the same direction (the region beyond
  // is this triangle) or opens its reverse, which must cross nothing placed.
  bool fits(uint32_t u, uint32_t v, uint32_t w, bool close[2]) const {
    const uint32_t side[2][2] = {{v, w}, {w, u}};
    for (int s = 0; s < 2; ++s) {
      const uint32_t a = side[s][0], b = side[s][1];
      close[s] = open.count(edge_key(a, b)) > 0;
      if (close[s]) continue;
      if (open.count(edge_key(b, a))) return false;  // its far side is covered already
      for (auto [c, d] : edges)
        if ((c == a && d == b) || (c == b && d == a) || segments_cross(dt, a, b, c, d)) return false;
    }
    return true;
  }

  void place(uint64_t e, uint32_t w, const bool close[2]) {
    const uint32_t u = static_cast<uint32_t>(e >> 32), v = static_cast<uint32_t>(e);
    const uint32_t side[2][2] = {{v, w}, {w, u}};
    open.erase(e);
    size_t added = 0;
    for (int s = 0; s < 2; ++s) {
      const uint32_t a = side[s][0], b = side[s][1];
      if (close[s]) open.erase(edge_key(a, b));
      else open.insert(edge_key(b, a)), edges.push_back({a, b}), ++added;
    }
    tris.push_back({u, v, w});
    run();
    tris.pop_back();
    for (int s = 1; s >= 0; --s) {
      const uint32_t a = side[s][0], b = side[s][1];
      if (close[s]) open.insert(edge_key(a, b));
      else open.erase(edge_key(b, a));
    }
    edges.resize(edges.size() - added);
    open.insert(e);
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
      bool close[2];
      if (fits(u, v, w, close)) place(best, w, close);
    }
  }
};

}  // namespace

bool enumerate_fills(const Mesh& dt, const Candidates& candidates, const std::vector<std::pair<uint32_t, uint32_t>>& boundary,
                     uint64_t max_nodes, const std::function<void(const std::vector<Tri>&)>& visit,
                     const Progress& progress, uint64_t* nodes_used) {
  Enumerator en{dt, candidates, max_nodes, visit, progress, {}, {}, {}};
  for (auto [a, b] : boundary) en.open.insert(edge_key(a, b));
  try {
    en.run();
  } catch (...) {
    if (nodes_used) *nodes_used += en.nodes;
    throw;
  }
  if (nodes_used) *nodes_used += en.nodes;
  return en.complete;
}

}  // namespace hodt
