#include "higher_order/regions/fill_graph.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "containers/words_hash.hpp"

namespace hodt {

namespace {

// The triangles of the path through `arcs` (in any order), canonical and sorted.
std::vector<Tri> fill_of(const FillGraph& g, const std::vector<uint32_t>& arcs) {
  std::vector<Tri> tris;
  for (uint32_t a : arcs) tris.push_back(canonical_triangle(g.arcs[a].triangle));
  std::sort(tris.begin(), tris.end());
  return tris;
}

// Per node, an arc into it and an arc out of it on a path to a complete fill
// (UINT32_MAX: none, at the start and at complete fills).
struct Links {
  std::vector<uint32_t> in, out;
  explicit Links(const FillGraph& g) : in(g.nodes, UINT32_MAX), out(g.nodes, UINT32_MAX) {
    for (uint32_t a = 0; a < g.arcs.size(); ++a) {
      if (in[g.arcs[a].child] == UINT32_MAX) in[g.arcs[a].child] = a;
      if (out[g.arcs[a].parent] == UINT32_MAX) out[g.arcs[a].parent] = a;
    }
  }
  // The arcs of a complete fill through arc a.
  std::vector<uint32_t> through(const FillGraph& g, uint32_t a) const {
    std::vector<uint32_t> path{a};
    for (uint32_t n = g.arcs[a].parent; in[n] != UINT32_MAX; n = g.arcs[in[n]].parent) path.push_back(in[n]);
    for (uint32_t n = g.arcs[a].child; out[n] != UINT32_MAX; n = g.arcs[out[n]].child) path.push_back(out[n]);
    return path;
  }
};

}  // namespace

namespace {

std::vector<double> arc_costs(const FillGraph& g, const std::vector<std::vector<double>>& costs) {
  std::vector<double> c(g.arcs.size());
  for (size_t a = 0; a < g.arcs.size(); ++a) {
    double v = g.arcs[a].cost;
    for (uint32_t t = g.arcs[a].first_take; t < g.arcs[a].first_take + g.arcs[a].takes; ++t)
      v += costs[g.taken[t].first][g.taken[t].second];
    c[a] = v;
  }
  return c;
}

// Per node, the least cost from it to a complete fill.
std::vector<double> backward(const FillGraph& g, const std::vector<double>& c) {
  std::vector<double> b(g.nodes, INFINITY);
  for (uint32_t n : g.complete) b[n] = 0;
  for (size_t a = g.arcs.size(); a-- > 0;) b[g.arcs[a].parent] = std::min(b[g.arcs[a].parent], c[a] + b[g.arcs[a].child]);
  return b;
}

}  // namespace

double FillGraph::least(const std::vector<std::vector<double>>& costs, std::vector<std::vector<double>>* marginals,
                        std::vector<Tri>* best, std::vector<uint32_t>* best_entries) const {
  if (best_entries && !best) {
    std::vector<Tri> tris;
    return least(costs, marginals, &tris, best_entries);
  }
  const std::vector<double> c = arc_costs(*this, costs);
  std::vector<double> forward(nodes, INFINITY);
  std::vector<uint32_t> via(best ? nodes : 0, UINT32_MAX);
  forward[0] = 0;
  for (size_t a = 0; a < arcs.size(); ++a) {
    const double v = forward[arcs[a].parent] + c[a];
    if (v < forward[arcs[a].child]) {
      forward[arcs[a].child] = v;
      if (best) via[arcs[a].child] = static_cast<uint32_t>(a);
    }
  }
  uint32_t end = complete.empty() ? 0 : complete[0];
  for (uint32_t n : complete)
    if (forward[n] < forward[end]) end = n;
  if (best) {
    std::vector<uint32_t> path;
    for (uint32_t n = end; via[n] != UINT32_MAX; n = arcs[via[n]].parent) path.push_back(via[n]);
    *best = fill_of(*this, path);
    if (best_entries) {
      best_entries->assign(entries.size(), 0);
      for (uint32_t a : path)
        for (uint32_t t = arcs[a].first_take; t < arcs[a].first_take + arcs[a].takes; ++t)
          (*best_entries)[taken[t].first] = taken[t].second;
    }
  }
  if (marginals) {
    const std::vector<double> back = backward(*this, c);
    marginals->resize(entries.size());
    for (size_t i = 0; i < entries.size(); ++i) (*marginals)[i].assign(entries[i].size(), INFINITY);
    for (size_t a = 0; a < arcs.size(); ++a) {
      const double v = forward[arcs[a].parent] + c[a] + back[arcs[a].child];
      for (uint32_t t = arcs[a].first_take; t < arcs[a].first_take + arcs[a].takes; ++t) {
        double& m = (*marginals)[taken[t].first][taken[t].second];
        m = std::min(m, v);
      }
    }
  }
  return forward[end];
}

std::optional<std::vector<double>> FillGraph::through(const std::vector<std::vector<double>>& costs) const {
  const std::vector<double> c = arc_costs(*this, costs);
  std::vector<double> forward(nodes, INFINITY);
  forward[0] = 0;
  for (size_t a = 0; a < arcs.size(); ++a)
    forward[arcs[a].child] = std::min(forward[arcs[a].child], forward[arcs[a].parent] + c[a]);
  const std::vector<double> back = backward(*this, c);
  auto small = [](double v) { return std::fabs(v) < 0x1p31; };
  std::vector<double> out(arcs.size());
  for (size_t a = 0; a < arcs.size(); ++a) {
    if (!small(c[a]) || !small(forward[arcs[a].parent]) || !small(back[arcs[a].child])) return std::nullopt;
    out[a] = forward[arcs[a].parent] + c[a] + back[arcs[a].child];
  }
  return out;
}

namespace {

// Per node, its paths to a complete fill over kept arcs (counted up to 1e18).
std::vector<double> kept_paths(const FillGraph& g, const std::vector<uint8_t>& kept) {
  std::vector<double> paths(g.nodes, 0);
  for (uint32_t n : g.complete) paths[n] = 1;
  for (size_t a = g.arcs.size(); a-- > 0;)
    if (kept[a]) paths[g.arcs[a].parent] = std::min(paths[g.arcs[a].parent] + paths[g.arcs[a].child], 1e18);
  return paths;
}

}  // namespace

std::optional<std::vector<std::vector<Tri>>> FillGraph::fills(const std::vector<uint8_t>& kept, uint64_t max_fills) const {
  const std::vector<double> paths = kept_paths(*this, kept);
  if (paths[0] > static_cast<double>(max_fills)) return std::nullopt;
  // Arcs out of each node (arcs are sorted by parent).
  std::vector<uint32_t> first(nodes + 1, 0);
  for (const Arc& arc : arcs) ++first[arc.parent + 1];
  for (uint32_t n = 0; n < nodes; ++n) first[n + 1] += first[n];
  std::vector<std::vector<Tri>> out;
  std::vector<uint32_t> path;
  auto walk = [&](auto&& self, uint32_t n) -> void {
    if (first[n] == first[n + 1]) {
      if (paths[n] > 0) out.push_back(fill_of(*this, path));
      return;
    }
    for (uint32_t a = first[n]; a < first[n + 1]; ++a) {
      if (!kept[a] || paths[arcs[a].child] == 0) continue;
      path.push_back(a);
      self(self, arcs[a].child);
      path.pop_back();
    }
  };
  walk(walk, 0);
  return out;
}

std::optional<std::vector<std::vector<Tri>>> FillGraph::best_by_entries(const std::vector<uint8_t>& kept,
                                                                        uint64_t max_fills, uint64_t max_labels) const {
  // Labels: a path to a node with the entries it took, the least per (node,
  // entries). Arcs are sorted by parent and lead to later nodes, so a node's
  // labels are final when its arcs out are read. A label's key: its node, then
  // its (item, entry) pairs sorted by item.
  struct Label {
    uint32_t prev, arc;  // the label it extends (UINT32_MAX: the empty fill), the arc taken
    double cost;
    const std::vector<uint32_t>* key;  // (held by `index`: its elements stay put)
  };
  // (Only arcs on a kept path to a complete fill.)
  const std::vector<double> ends = kept_paths(*this, kept);
  std::unordered_map<std::vector<uint32_t>, uint32_t, WordsHash> index{{{0u}, 0u}};
  std::vector<Label> labels{{UINT32_MAX, UINT32_MAX, 0.0, &index.begin()->first}};
  std::vector<std::vector<uint32_t>> at(nodes);
  at[0].push_back(0);
  std::vector<uint32_t> key;
  std::vector<std::pair<uint32_t, uint32_t>> pairs;
  for (uint32_t a = 0; a < arcs.size(); ++a) {
    const Arc& arc = arcs[a];
    for (size_t i = 0; kept[a] && ends[arc.child] > 0 && i < at[arc.parent].size(); ++i) {
      const uint32_t l = at[arc.parent][i];
      const std::vector<uint32_t>& from = *labels[l].key;
      pairs.clear();
      for (size_t w = 1; w < from.size(); w += 2) pairs.push_back({from[w], from[w + 1]});
      pairs.insert(pairs.end(), taken.begin() + arc.first_take, taken.begin() + arc.first_take + arc.takes);
      std::sort(pairs.begin(), pairs.end());
      key.assign(1, arc.child);
      for (auto [item, entry] : pairs) key.push_back(item), key.push_back(entry);
      const double cost = labels[l].cost + arc.cost;
      const auto [it, fresh] = index.try_emplace(key, static_cast<uint32_t>(labels.size()));
      if (fresh) {
        if (labels.size() >= max_labels) return std::nullopt;
        labels.push_back({l, a, cost, &it->first});
        at[arc.child].push_back(it->second);
      } else if (cost < labels[it->second].cost) {
        labels[it->second].prev = l, labels[it->second].arc = a, labels[it->second].cost = cost;
      }
    }
    // (The node's last arc out: its labels are read no more.)
    if (a + 1 == arcs.size() || arcs[a + 1].parent != arc.parent) std::vector<uint32_t>().swap(at[arc.parent]);
  }
  // The least per combination over every complete node.
  std::unordered_map<std::vector<uint32_t>, uint32_t, WordsHash> best;
  for (uint32_t n : complete)
    for (uint32_t l : at[n]) {
      key.assign(labels[l].key->begin() + 1, labels[l].key->end());
      const auto [it, fresh] = best.try_emplace(key, l);
      if (!fresh && labels[l].cost < labels[it->second].cost) it->second = l;
    }
  if (best.size() > max_fills) return std::nullopt;
  std::vector<std::vector<Tri>> out;
  std::vector<uint32_t> path;
  for (const auto& [k, last] : best) {
    path.clear();
    for (uint32_t l = last; labels[l].prev != UINT32_MAX; l = labels[l].prev) path.push_back(labels[l].arc);
    out.push_back(fill_of(*this, path));
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::vector<std::vector<Tri>>> FillGraph::representatives() const {
  const Links links(*this);
  std::vector<std::vector<std::vector<Tri>>> out(entries.size());
  for (size_t i = 0; i < entries.size(); ++i) out[i].resize(entries[i].size());
  for (uint32_t a = 0; a < arcs.size(); ++a)
    for (uint32_t t = arcs[a].first_take; t < arcs[a].first_take + arcs[a].takes; ++t) {
      auto& rep = out[taken[t].first][taken[t].second];
      if (rep.empty()) rep = fill_of(*this, links.through(*this, a));
    }
  return out;
}

}  // namespace hodt
