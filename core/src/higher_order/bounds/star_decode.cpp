#include "higher_order/bounds/star_decode.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_set>
#include "tuning/budgets.hpp"

namespace hodt {

namespace {

class Fans {
 public:
  Fans(const Mesh& dt, const FanTrees& t) : t_(t), hull_(dt.num_vertices(), 0) {
    for (uint32_t h : dt.hull) hull_[h] = 1;
  }
  // The neighbours of fan f of v in counterclockwise order (a cycle at an
  // interior vertex: the first is not repeated).
  const std::vector<uint32_t>& ring(uint32_t v, uint64_t f) {
    t_.ring(f, !hull_[v], ring_);
    return ring_;
  }
  FanSide edge(uint32_t v, uint64_t f, uint32_t u) { return side_in_ring(ring(v, f), !hull_[v], u); }
  bool cyclic(uint32_t v) const { return !hull_[v]; }

 private:
  const FanTrees& t_;
  std::vector<uint8_t> hull_;
  std::vector<uint32_t> ring_;
};

// Neighbours: any two vertices one's fans pass through the other. Read off the
// trees' nodes (every node is on a fan's ring), each once per vertex, not off
// every fan's ring (a node is on the rings of all the fans through it, so the
// rings read it many times over).
std::vector<std::vector<uint32_t>> neighbours(const FanTrees& t, uint32_t n) {
  std::vector<std::vector<uint32_t>> near(n);
  std::vector<uint32_t> seen(n, UINT32_MAX);
  for (uint32_t v = 0; v < n; ++v)
    for (uint64_t x = t.first_node[v]; x < t.first_node[v + 1]; ++x)
      if (const uint32_t u = t.neighbor[x]; seen[u] != v) seen[u] = v, near[v].push_back(u), near[u].push_back(v);
  for (auto& a : near) std::sort(a.begin(), a.end()), a.erase(std::unique(a.begin(), a.end()), a.end());
  return near;
}

// The triangles of one fan per vertex.
std::vector<Tri> triangles_of(Fans& fans, const std::vector<uint64_t>& chosen) {
  std::vector<Tri> out;
  for (uint32_t v = 0; v < chosen.size(); ++v) append_fan_triangles(v, fans.ring(v, chosen[v]), fans.cyclic(v), out);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

constexpr uint64_t kNoFan = UINT64_MAX;

// The sweeps' directions (off the axes a little: rows and columns of a grid
// are then visited in one order).
constexpr double kAxes[4][2] = {{1, 0.001}, {-1, -0.001}, {0.001, 1}, {-0.001, -1}};

}  // namespace

StarDecoder::StarDecoder(const Mesh& dt, FanTrees trees, std::vector<Tri> triangles, std::vector<int64_t> value,
                         uint64_t max_steps)
    : dt_(dt),
      t_(std::move(trees)),
      tris_(std::move(triangles)),
      value_(std::move(value)),
      near_(neighbours(t_, dt.num_vertices())),
      max_steps_(max_steps) {}

std::vector<std::vector<Tri>> StarDecoder::sweeps() const {
  std::vector<std::vector<Tri>> out;
  for (const auto& axis : kAxes)
    if (auto tris = search(value_, axis)) out.push_back(std::move(*tris));
  return out;
}

std::optional<std::vector<Tri>> StarDecoder::repair(const Mesh& start) const {
  std::unordered_set<Tri, WordsHash> kept;
  for (uint32_t i = 0; i < start.num_triangles(); ++i) kept.insert(canonical_triangle(base_triangle(start, i)));
  std::vector<uint8_t> in_start(tris_.size());
  for (size_t i = 0; i < tris_.size(); ++i) in_start[i] = kept.count(tris_[i]) > 0;
  std::vector<int64_t> value(value_.size());
  for (uint64_t f = 0; f < t_.leaf.size(); ++f) {
    bool all = true;  // (every triangle of f in start)
    for (uint64_t x = t_.leaf[f]; x != kNoFanNode && all; x = t_.parent[x])
      all = t_.corner[x] == kNoFanNode || in_start[t_.corner[x] / 3];
    value[f] = 2 * value_[f] + all;  // (exact: values are far below 2^62)
  }
  return search(value, kAxes[0]);
}

std::optional<std::vector<Tri>> StarDecoder::search(const std::vector<int64_t>& value, const double axis[2]) const {
  const Mesh& dt = dt_;
  const FanTrees& t = t_;
  const uint64_t max_steps = max_steps_;
  const uint32_t n = dt.num_vertices();
  Fans fans(dt, t);
  std::vector<uint32_t> owner(t.leaf.size());
  std::vector<std::vector<uint64_t>> domain(n);
  for (uint32_t v = 0; v < n; ++v) {
    if (t.first_leaf[v] == t.first_leaf[v + 1]) return std::nullopt;
    for (uint64_t f = t.first_leaf[v]; f < t.first_leaf[v + 1]; ++f) owner[f] = v, domain[v].push_back(f);
    std::stable_sort(domain[v].begin(), domain[v].end(), [&](uint64_t a, uint64_t b) { return value[a] > value[b]; });
  }
  const std::vector<std::vector<uint32_t>>& near = near_;
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::vector<double> along(n);
  for (uint32_t v = 0; v < n; ++v) along[v] = axis[0] * dt.point(v)[0] + axis[1] * dt.point(v)[1];
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return along[a] < along[b]; });
  // Vertices with one fan first (those a tile's decoder holds): their
  // neighbours then meet what they force before choosing, not after.
  std::stable_partition(order.begin(), order.end(), [&](uint32_t v) { return domain[v].size() == 1; });

  std::vector<uint64_t> chosen(n, kNoFan), trail;
  std::vector<uint8_t> alive(t.leaf.size(), 1);
  std::vector<uint64_t> left(n), mark(n), next(n, 0);
  for (uint32_t v = 0; v < n; ++v) left[v] = domain[v].size();
  auto undo = [&](uint64_t to) {
    for (; trail.size() > to; trail.pop_back()) alive[trail.back()] = 1, ++left[owner[trail.back()]];
  };
  // Fan f of v chosen: each neighbour not yet decided keeps the fans that say
  // of v what f says of it (the same triangles on their edge). False when one
  // has none left.
  auto choose = [&](uint32_t v, uint64_t f) {
    chosen[v] = f;
    for (uint32_t u : near[v]) {
      if (chosen[u] != kNoFan) continue;
      const FanSide wanted = mirrored(fans.edge(v, f, u));
      for (uint64_t g : domain[u])
        if (alive[g] && !(fans.edge(u, g, v) == wanted)) alive[g] = 0, --left[u], trail.push_back(g);
      if (left[u] == 0) return false;
    }
    return true;
  };
  // v's fans in the order tried: the first few alive ones by their
  // value plus, per undecided neighbour, the best value it keeps with them (a
  // fan that leaves its neighbours poor choices goes later: the search keeps
  // the first fans that agree, so a greedy first choice costs its neighbours),
  // then the rest by value.
  std::vector<std::vector<uint64_t>> ranked(n);
  auto rank = [&](uint32_t v) {
    std::vector<std::pair<int64_t, uint64_t>> top;
    for (size_t j = 0; j < domain[v].size() && top.size() < kBudgets.star_decode_lookahead; ++j) {
      const uint64_t f = domain[v][j];
      if (!alive[f]) continue;
      int64_t score = value[f];
      for (uint32_t u : near[v]) {
        if (chosen[u] != kNoFan) continue;
        const FanSide wanted = mirrored(fans.edge(v, f, u));
        int64_t best = -(int64_t{1} << 50);  // (none: far below any value; sums of them stay in range)
        for (uint64_t g : domain[u])  // (best first: the first that agrees)
          if (alive[g] && fans.edge(u, g, v) == wanted) {
            best = value[g];
            break;
          }
        score += best;
      }
      top.push_back({score, f});
    }
    std::stable_sort(top.begin(), top.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    ranked[v].clear();
    for (const auto& [score, f] : top) ranked[v].push_back(f);
    for (uint64_t f : domain[v])
      if (std::none_of(top.begin(), top.end(), [&](const auto& p) { return p.second == f; })) ranked[v].push_back(f);
  };
  uint64_t steps = 0;
  for (int64_t i = 0; i < static_cast<int64_t>(n);) {
    const uint32_t v = order[static_cast<size_t>(i)];
    if (chosen[v] != kNoFan) undo(mark[v]), chosen[v] = kNoFan;  // (back here: its next fan)
    if (next[v] == 0) rank(v);  // (a fresh visit: its fans ranked anew)
    bool placed = false;
    while (!placed && next[v] < ranked[v].size()) {
      const uint64_t f = ranked[v][next[v]++];
      if (!alive[f]) continue;
      if (++steps > max_steps) return std::nullopt;
      mark[v] = trail.size();
      placed = choose(v, f);
      if (!placed) undo(mark[v]), chosen[v] = kNoFan;
    }
    if (placed) {
      if (++i < static_cast<int64_t>(n)) next[order[static_cast<size_t>(i)]] = 0;
    } else {
      next[v] = 0;
      if (--i < 0) return std::nullopt;
    }
  }
  return triangles_of(fans, chosen);
}

}  // namespace hodt
