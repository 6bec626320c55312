// Every fan a vertex can have at order k, as prefix trees (star_bound.hpp):
// shared by the bound and by the decoding of a triangulation from it.
#pragma once
#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/predicates.hpp"
#include "hodt/skeleton.hpp"
#include "containers/words_hash.hpp"
#include "higher_order/fills/fill_enumerator.hpp"

namespace hodt {

constexpr uint32_t kNoFanNode = UINT32_MAX;

// Every vertex's fans as prefix trees, in preorder: a root per first neighbour
// (no triangle), then a node per triangle (v, the parent's neighbour, its own).
struct FanTrees {
  std::vector<uint32_t> corner, neighbor, parent;  // per node (corner: its triangle's at v, 3 id + position; parent, corner: kNoFanNode at a root)
  std::vector<uint64_t> leaf;              // per fan: its last node
  std::vector<uint64_t> first_node, first_leaf;  // per vertex, and one past the last
  void truncate(uint64_t nodes, uint64_t leaves) {
    corner.resize(nodes), neighbor.resize(nodes), parent.resize(nodes), leaf.resize(leaves);
  }
  // Fan f's neighbours in counterclockwise order (cyclic: round an interior
  // vertex, the first not repeated).
  void ring(uint64_t f, bool cyclic, std::vector<uint32_t>& out) const {
    out.clear();
    for (uint64_t x = leaf[f]; x != kNoFanNode; x = parent[x]) out.push_back(neighbor[x]);
    std::reverse(out.begin(), out.end());
    if (cyclic) out.pop_back();
  }
};

// What a fan (its ring of neighbours, counterclockwise; cyclic round an interior
// vertex) says of one neighbour u: whether the edge is in it, and if so the
// apexes before and after u (none at a hull end).
struct FanSide {
  bool present = false;
  uint32_t before = kNoFanNode, after = kNoFanNode;
  bool operator==(const FanSide&) const = default;
};
inline FanSide side_in_ring(const std::vector<uint32_t>& ring, bool cyclic, uint32_t u) {
  const auto it = std::find(ring.begin(), ring.end(), u);
  if (it == ring.end()) return {};
  const size_t j = static_cast<size_t>(it - ring.begin()), m = ring.size();
  return {true, cyclic || j > 0 ? ring[(j + m - 1) % m] : kNoFanNode, cyclic || j + 1 < m ? ring[(j + 1) % m] : kNoFanNode};
}
// What u's fan must say of v when v's says `said` of u: the same triangles,
// seen from the other end. Fans that all agree so are a triangulation.
inline FanSide mirrored(const FanSide& said) { return said.present ? FanSide{true, said.after, said.before} : FanSide{}; }

// Each vertex's fan in a triangulation m, as its ring: its neighbours
// counterclockwise (at a hull vertex, from the next hull vertex round to the
// previous: as the fans are listed).
inline std::vector<std::vector<uint32_t>> rings_of(const Mesh& m) {
  const std::vector<int32_t> out = vertex_halfedges(m);
  std::vector<std::vector<uint32_t>> ring(m.num_vertices());
  for (uint32_t v = 0; v < m.num_vertices(); ++v) {
    if (out[v] < 0) continue;
    for (int32_t e = out[v];;) {
      ring[v].push_back(m.target(static_cast<uint32_t>(e)));
      const uint32_t p = prev_halfedge(static_cast<uint32_t>(e));
      e = m.halfedges[p];
      if (e < 0) ring[v].push_back(m.origin(p));  // (round to the hull edge before v)
      if (e < 0 || e == out[v]) break;
    }
  }
  return ring;
}

// The triangles of v's fan (canonical), appended.
inline void append_fan_triangles(uint32_t v, const std::vector<uint32_t>& ring, bool cyclic, std::vector<Tri>& out) {
  const size_t m = ring.size(), last = cyclic ? m : m - 1;
  for (size_t j = 0; j < last; ++j) out.push_back(canonical_triangle(Tri{v, ring[j], ring[(j + 1) % m]}));
}

// Lists fans by depth-first search over the candidate triangles at v, in
// counterclockwise order.
class FanLister {
 public:
  // numbered: give each node its triangle's corner (a number per triangle, kept
  // for the lister's life); else every corner is kNoFanNode (rings only).
  FanLister(const Mesh& dt, const Candidates& cand, FanTrees& t, bool numbered = true)
      : dt_(dt), cand_(cand), t_(t), numbered_(numbered), around_(dt.num_vertices()), hull_at_(dt.num_vertices(), -1) {
    for (const auto& [key, apexes] : cand)
      if (!apexes.empty()) around_[static_cast<uint32_t>(key >> 32)].push_back(static_cast<uint32_t>(key));
    for (auto& a : around_) std::sort(a.begin(), a.end()), a.erase(std::unique(a.begin(), a.end()), a.end());
    for (size_t i = 0; i < dt.hull.size(); ++i) hull_at_[dt.hull[i]] = static_cast<int64_t>(i);
  }

  // Every fan of v, appended to the trees: around an interior vertex each from
  // its smallest neighbour, once round; at a hull vertex from the next hull
  // vertex round to the previous (the other way is outside). False when over
  // the budget of nodes, or when v has no fan (nothing is kept of v then).
  bool list(uint32_t v, uint64_t budget) {
    const uint64_t leaves = t_.leaf.size();
    if (interior(v)) return list(v, around_[v], true, 0, budget) && t_.leaf.size() > leaves;
    const size_t h = dt_.hull.size(), i = static_cast<size_t>(hull_at_[v]);
    return list(v, {dt_.hull[(i + 1) % h]}, false, dt_.hull[(i + h - 1) % h], budget) && t_.leaf.size() > leaves;
  }
  bool interior(uint32_t v) const { return hull_at_[v] < 0; }
  // The useful neighbours of v (the candidates' edges), sorted.
  const std::vector<uint32_t>& around(uint32_t v) const { return around_[v]; }
  const std::vector<Tri>& triangles() const { return tris_; }
  // Numbers triangles afresh (for trees listed anew: a tile of star_bound).
  void renumber() { ids_.clear(), tris_.clear(); }

 private:
  const Mesh& dt_;
  const Candidates& cand_;
  FanTrees& t_;
  bool numbered_;
  std::vector<std::vector<uint32_t>> around_;
  std::vector<int64_t> hull_at_;
  std::unordered_map<Tri, uint32_t, WordsHash> ids_;
  std::vector<Tri> tris_;  // by id
  uint64_t limit_ = 0;
  uint32_t v_ = 0, start_ = 0, end_ = 0;
  bool cyclic_ = true;

  // Each fan from one of `starts`, once round (cyclic), else from the one start
  // round to `to`.
  bool list(uint32_t v, const std::vector<uint32_t>& starts, bool cyclic, uint32_t to, uint64_t budget) {
    const uint64_t nodes = t_.corner.size(), leaves = t_.leaf.size();
    limit_ = nodes + budget, v_ = v, cyclic_ = cyclic;
    for (const uint32_t s : starts) {
      start_ = s, end_ = cyclic ? s : to;
      const uint64_t root = push(kNoFanNode, kNoFanNode, s), before = t_.leaf.size();
      if (!grow(root, s)) {
        t_.truncate(nodes, leaves);
        return false;
      }
      if (t_.leaf.size() == before) t_.truncate(root, before);  // (no fan from s)
    }
    return true;
  }
  uint64_t push(uint32_t corner, uint64_t parent, uint32_t w) {
    t_.corner.push_back(corner), t_.parent.push_back(static_cast<uint32_t>(parent)), t_.neighbor.push_back(w);
    return t_.corner.size() - 1;
  }
  uint32_t corner(uint32_t u, uint32_t w) {
    if (!numbered_) return kNoFanNode;
    const Tri c = canonical_triangle(Tri{v_, u, w});
    const auto [it, fresh] = ids_.try_emplace(c, static_cast<uint32_t>(ids_.size()));
    if (fresh) tris_.push_back(c);
    const uint32_t id = it->second;
    return 3 * id + static_cast<uint32_t>(std::find(c.begin(), c.end(), v_) - c.begin());
  }
  // The fans going on from node `at`, whose neighbour is cur (the candidates
  // on the left of v -> cur are the next triangles counterclockwise).
  bool grow(uint64_t at, uint32_t cur) {
    const auto it = cand_.find(edge_key(v_, cur));
    if (it == cand_.end()) return true;
    const double* pv = dt_.point(v_);
    for (const uint32_t w : it->second) {
      if (t_.corner.size() >= limit_) return false;
      if (w == end_) {
        t_.leaf.push_back(push(corner(cur, w), at, w));
        continue;
      }
      // Once round only: no step over the first neighbour's direction.
      if (cyclic_ && (w < start_ || (orient2d(pv, dt_.point(cur), dt_.point(start_)) > 0 &&
                                     orient2d(pv, dt_.point(start_), dt_.point(w)) > 0)))
        continue;
      const uint64_t node = push(corner(cur, w), at, w), before = t_.leaf.size();
      if (!grow(node, w)) return false;
      if (t_.leaf.size() == before) t_.truncate(node, before);  // (a dead end)
    }
    return true;
  }
};


}  // namespace hodt
