#include "higher_order/bounds/star_bound.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <span>
#include <stdexcept>

#include "hodt/error.hpp"
#include "higher_order/bounds/diamond_ends.hpp"
#include "higher_order/bounds/fan_terms.hpp"
#include "higher_order/bounds/fan_trees.hpp"
#include "higher_order/bounds/star_decode.hpp"
#include "objectives/objective_terms.hpp"

namespace hodt {

namespace {

constexpr int64_t kUnit = 4096;  // multipliers in units of 2^-12: every sum exact

int64_t floor_div(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0))); }

}  // namespace

std::optional<StarBound> star_bound(const Mesh& dt, Objective o, const Candidates& cand, double incumbent,
                                    const StarBoundLimits& limits) {
  const ObjectiveTerms& d = objective_terms(o, dt);
  const bool at_vertices = d.site == TermSite::InteriorVertex || d.site == TermSite::Vertex;
  const int64_t sign = info(o).sense == Sense::Max ? 1 : -1;  // the relaxation maximises sign * value
  // Counts (integer terms), or minimised lengths over every edge (the hull's a
  // constant): nonnegative reals, each rounded down in fixed point.
  const bool integral = d.term_max < 1e6 && d.term_max == std::floor(d.term_max);
  const bool lengths = d.site == TermSite::Edge && !d.edge_reads_apexes && sign < 0;
  // (Within a domain a fan's terms are the domain's, fan_terms; lengths are not
  // read there: a hull edge counts only beside a triangle inside.)
  if (d.combine != Combine::Sum || !std::isfinite(incumbent) ||
      !(integral ? at_vertices || d.site == TermSite::InteriorEdge : lengths))
    return std::nullopt;
  const uint32_t n = dt.num_vertices();

  // Lengths in units of 2^-e, the longest useful edge near 2^20 units: each
  // rounded down, less one unit (the length is accurate, not exact), so every
  // sum is exact and never above the true one. Counts: units of 1.
  double scale = 1;
  if (!integral) {
    double longest = 0;
    for (const auto& [key, apexes] : cand)
      longest = std::max(longest, edge_term(d, dt, static_cast<uint32_t>(key >> 32), static_cast<uint32_t>(key), kNoApex, kNoApex));
    for (size_t i = 0; i < dt.hull.size(); ++i)
      longest = std::max(longest, edge_term(d, dt, dt.hull[i], dt.hull[(i + 1) % dt.hull.size()], kNoApex, kNoApex));
    if (longest > 0) scale = std::ldexp(1.0, 20 - std::ilogb(longest));
  }
  auto units = [&](double w) {  // (sign form, at least sign * w * scale)
    if (integral) return sign * static_cast<int64_t>(w);
    return -(static_cast<int64_t>(std::floor(w * scale)) - 1);
  };
  const int64_t best_term = sign > 0 ? static_cast<int64_t>(d.term_max) : 0;
  int64_t total = 0;  // (in units: the constants, then each tile's relaxation)
  if (lengths)  // (hull edges: in every triangulation)
    for (size_t i = 0; i < dt.hull.size(); ++i)
      total += units(edge_term(d, dt, dt.hull[i], dt.hull[(i + 1) % dt.hull.size()], kNoApex, kNoApex)) * kUnit;

  // The vertices in tiles of consecutive numbers (spatially coherent: the
  // terrain numbers them along a Morton curve), each as many as the budget of
  // nodes holds, so memory is one tile's (the fans of a large terrain at high
  // order run to far more nodes than one would hold at once). A tile's
  // vertices with a neighbour in a tile still to come are carried into the
  // next: listed again (the same fans in the same order), their values with
  // the multipliers so far folded in, so that their diamonds with the next
  // tile's vertices get multipliers too. Any multipliers keep the bound; a
  // vertex's best fan is counted once no multiplier at it changes again (its
  // tile's last, or once it is not carried). Agreement is dropped only where
  // the carried are over budget.
  FanTrees t;
  FanLister lister(dt, cand, t);
  std::vector<uint8_t> in(n, 0);                  // its fans listed (else its terms at their best)
  std::vector<uint32_t> tile_of(n, kNoFanNode);  // (set when its tile is closed)
  std::vector<uint32_t> members, carried;
  std::vector<std::vector<int64_t>> carried_value;  // (per carried vertex, per fan)
  std::vector<uint32_t> position(n, kNoFanNode);   // (a member's place in members)
  StarBound out;
  const double target = static_cast<double>(sign) * incumbent;
  // What a total proves of sign * value: counts are integers (the floor),
  // lengths the ceiling in their units.
  auto relaxed = [&](int64_t sum) {
    return integral ? static_cast<double>(floor_div(sum, kUnit)) : static_cast<double>(-floor_div(-sum, kUnit)) / scale;
  };
  uint32_t tiles = 0, done = 0;  // (done: the vertices of the tiles swept; progress: listed + swept)
  uint64_t visits = 0;  // (fans read by the sweeps: their work)
  std::vector<uint32_t> seq, scratch;
  std::vector<int64_t> lambda, best_lambda;
  uint32_t v = 0;  // (the next vertex to list)
  do {
    // List the next tile.
    members.clear();
    t.truncate(0, 0), t.first_node.clear(), t.first_leaf.clear();
    lister.renumber();
    // The carried first, in at most half the tile's nodes (beyond, counted
    // now at their best fans).
    std::vector<std::vector<int64_t>> kept_value;
    for (size_t c = 0; c < carried.size(); ++c) {
      const uint64_t used = t.corner.size(), leaves = t.leaf.size();
      if (used < limits.max_nodes / 2 && lister.list(carried[c], limits.max_nodes_per_vertex) &&
          t.leaf.size() - leaves == carried_value[c].size()) {
        t.first_node.push_back(used), t.first_leaf.push_back(leaves);
        members.push_back(carried[c]), kept_value.push_back(std::move(carried_value[c]));
        continue;
      }
      t.truncate(used, leaves);
      total += *std::max_element(carried_value[c].begin(), carried_value[c].end());
    }
    carried.clear(), carried_value.clear();
    const uint32_t kept = static_cast<uint32_t>(members.size());
    for (; v < n; ++v) {
      const uint64_t used = t.corner.size(), room = std::min(limits.max_nodes_per_vertex, limits.max_nodes - std::min(limits.max_nodes, used));
      t.first_node.push_back(used), t.first_leaf.push_back(t.leaf.size());
      const bool listed = lister.list(v, room);
      if (!listed) t.truncate(t.first_node.back(), t.first_leaf.back());
      if (!listed && room < limits.max_nodes_per_vertex && members.size() > kept) {  // (the tile is full)
        t.first_node.pop_back(), t.first_leaf.pop_back();
        break;
      }
      in[v] = listed;
      out.left_out += !listed;
      members.push_back(v);
      if (limits.progress && v % 4096 == 0 && !limits.progress(v + done, 2.0 * n)) throw Cancelled();
    }
    if (out.left_out > limits.max_left_out * n) return std::nullopt;
    const bool whole = tiles == 0 && v == n;  // (one tile: every vertex, numbered as the vertices)
    const uint32_t tile = tiles++, m = static_cast<uint32_t>(members.size()), fresh = m - kept;
    for (uint32_t i = 0; i < m; ++i) position[members[i]] = i;
    for (uint32_t i = kept; i < m; ++i) tile_of[members[i]] = tile;
    t.first_node.push_back(t.corner.size()), t.first_leaf.push_back(t.leaf.size());
    out.nodes = std::max<uint64_t>(out.nodes, t.corner.size());

    // Each fan's terms. An interior edge's belongs to its smaller end with fans
    // listed, or, between tiles, to its smaller end; terms no listed fan holds
    // are at their best (counted once: at the smaller end).
    auto owner = [&](uint32_t a, uint32_t b) {
      if (tile_of[a] != tile_of[b]) return a < b ? (in[a] ? a : kNoFanNode) : b;
      return in[a] && (!in[b] || a < b) ? a : in[b] ? b : kNoFanNode;
    };
    auto terms_of = [&](uint32_t i, uint64_t f, const auto& take) {
      const uint32_t u = members[i];
      const bool cyclic = lister.interior(u);
      t.ring(f, cyclic, seq);
      fan_terms(dt, d, u, seq, cyclic, [&](uint32_t w) { return owner(u, w) == u; }, scratch, take);
    };
    for (uint32_t i = kept; i < m; ++i) {
      const uint32_t u = members[i];
      if (at_vertices && !in[u] && (d.site == TermSite::Vertex || lister.interior(u))) total += best_term * kUnit;
      if (!at_vertices)
        for (const uint32_t w : lister.around(u))
          if (u < w && owner(u, w) == kNoFanNode) total += best_term * kUnit;
    }
    // Each fan's value under the multipliers (all 0 so far: its terms, or a
    // carried fan's value so far).
    std::vector<int64_t> current(t.leaf.size());
    for (uint32_t i = 0; i < kept; ++i) std::copy(kept_value[i].begin(), kept_value[i].end(), current.begin() + t.first_leaf[i]);
    kept_value.clear();
    bool counts = true;
    for (uint32_t i = kept; i < m; ++i)
      for (uint64_t f = t.first_leaf[i]; f < t.first_leaf[i + 1]; ++f)
        terms_of(i, f, [&](double w) {
          if (integral && !(w == std::floor(w) && std::fabs(w) < 1e6)) counts = false;
          else current[f] += units(w) * kUnit;
        });
    if (!counts) return std::nullopt;

    // One multiplier per diamond end (diamond_ends.hpp), a diamond's two
    // summing to 0: both fans hold it or neither does.
    const std::vector<Tri>& tris = lister.triangles();
    const DiamondEnds ends(t, members, position, lister);
    lambda.assign(ends.size(), 0);
    // Per node of one vertex's trees (indexed from its first node: the scratch
    // is as large as the largest vertex's trees, not all of them).
    uint64_t widest = 0;
    for (uint32_t i = 0; i < m; ++i) widest = std::max(widest, t.first_node[i + 1] - t.first_node[i]);
    // The fans holding each end: intervals of its vertex's leaves (a node's
    // subtree, or one leaf), disjoint (a fan holds an end once), in order.
    std::vector<uint32_t> first_span(ends.size() + 1, 0);
    std::vector<std::array<uint32_t, 2>> spans;
    {
      std::vector<std::array<uint32_t, 3>> found;  // (end, first leaf, one past the last)
      std::vector<std::array<uint32_t, 2>> below(widest);  // (per node: its subtree's leaves)
      for (uint32_t i = 0; i < m; ++i) {
        const uint64_t base = t.first_node[i], leaf0 = t.first_leaf[i];
        std::fill(below.begin(), below.begin() + static_cast<int64_t>(t.first_node[i + 1] - base), std::array<uint32_t, 2>{UINT32_MAX, 0});
        for (uint64_t f = leaf0; f < t.first_leaf[i + 1]; ++f) {
          const uint32_t at = static_cast<uint32_t>(f - leaf0);
          below[t.leaf[f] - base] = {at, at + 1};
          if (ends.at_leaf(f) != DiamondEnds::kNone) found.push_back({ends.at_leaf(f), at, at + 1});
        }
        for (uint64_t x = t.first_node[i + 1]; x-- > base;) {  // (children after their parents)
          if (t.parent[x] == kNoFanNode) continue;
          auto& up = below[t.parent[x] - base];
          up = {std::min(up[0], below[x - base][0]), std::max(up[1], below[x - base][1])};
        }
        for (uint64_t x = base; x < t.first_node[i + 1]; ++x)
          if (ends.at_node(x) != DiamondEnds::kNone) found.push_back({ends.at_node(x), below[x - base][0], below[x - base][1]});
      }
      std::sort(found.begin(), found.end());
      spans.reserve(found.size());
      for (const auto& [e, lo, hi] : found) {
        if (first_span[e + 1]++ && spans.back()[1] > lo) throw std::logic_error("star bound: a fan holds an end twice");
        spans.push_back({lo, hi});
      }
      for (size_t e = 0; e < ends.size(); ++e) first_span[e + 1] += first_span[e];
    }
    // The fans' values kept under the multipliers: a multiplier's change is an
    // add over its end's intervals, and the best fan with or without an end the
    // most over them or between them, in one pass over the vertex's fans'
    // values (contiguous), not a walk of its trees.
    constexpr double kCap = double(int64_t{1} << 32);  // (an end every fan holds: its margin capped)
    auto most = [&](uint64_t from, uint64_t to) {
      int64_t best = INT64_MIN;
      for (uint64_t f = from; f < to; ++f) best = std::max(best, current[f]);
      return best;
    };
    // How much more member i's best fan with end e is than its best without
    // (e's own multiplier left out).
    auto margin = [&](uint32_t i, uint32_t e) {
      const uint64_t base = t.first_leaf[i];
      int64_t with = INT64_MIN, without = INT64_MIN;
      uint64_t at = base;
      for (uint32_t s = first_span[e]; s < first_span[e + 1]; ++s) {
        without = std::max(without, most(at, base + spans[s][0]));
        with = std::max(with, most(base + spans[s][0], base + spans[s][1]));
        at = base + spans[s][1];
      }
      without = std::max(without, most(at, t.first_leaf[i + 1]));
      visits += t.first_leaf[i + 1] - base;
      return without == INT64_MIN ? kCap : std::clamp(static_cast<double>(with - lambda[e]) - static_cast<double>(without), -kCap, kCap);
    };
    auto set = [&](uint32_t i, uint32_t e, int64_t to) {
      const uint64_t base = t.first_leaf[i];
      for (uint32_t s = first_span[e]; s < first_span[e + 1]; ++s)
        for (uint64_t f = base + spans[s][0]; f < base + spans[s][1]; ++f) current[f] += to - lambda[e];
      lambda[e] = to;
    };
    // The tile's relaxation: per member its best fan.
    auto bound_now = [&] {
      int64_t sum = 0;
      for (uint32_t i = 0; i < m; ++i)
        if (in[members[i]]) sum += most(t.first_leaf[i], t.first_leaf[i + 1]);
      return sum;
    };
    // A diamond's update depends only on the multipliers at its two ends'
    // vertices other than its own: while neither changed since it was updated
    // last, updating it again changes nothing (late sweeps skip most).
    std::vector<uint32_t> changed(m, 0), seen(ends.pairs().size(), UINT32_MAX);
    uint32_t clock = 0;
    // The tile's share of the work left (by its vertices), then the sweeps stop.
    const uint64_t stop_at = visits + static_cast<uint64_t>(static_cast<double>(limits.max_visits - std::min(limits.max_visits, visits)) * fresh / (n - done));
    int64_t best = bound_now();
    best_lambda = lambda;  // (the multipliers of `best`)
    for (uint32_t sweep = 0; sweep < limits.iterations && (!whole || relaxed(total + best) > target); ++sweep) {
      for (size_t p = 0; p < ends.pairs().size() && visits < stop_at; ++p) {
        const std::array<uint32_t, 2>& pair = ends.pairs()[p];
        const uint32_t i = ends.member(pair[0]), j = ends.member(pair[1]);
        if (seen[p] != UINT32_MAX && changed[i] <= seen[p] && changed[j] <= seen[p]) continue;
        // MPLP over the two ends: each end's vertex then prefers its fans with
        // the diamond over those without by the same margin (their mean).
        const int64_t to = std::llround((margin(j, pair[1]) - margin(i, pair[0])) / 2);
        ++clock;
        if (lambda[pair[0]] != to) set(i, pair[0], to), set(j, pair[1], -to), changed[i] = changed[j] = clock;
        seen[p] = clock;
      }
      const int64_t now = bound_now();
      if (limits.progress && !limits.progress(v + done + static_cast<double>(sweep + 1) * fresh / limits.iterations, 2.0 * n))
        throw Cancelled();
      const int64_t gained = best - now;
      if (now < best) best_lambda = lambda;
      best = std::min(best, now);
      // Stop once the last sweep's gain, kept up for every sweep left, would not
      // reach the next value the bound can prove (the next integer for counts, or
      // past the known bound; half a unit for lengths): a tile of many aims at
      // its share of that. The gains shrink slowly: sweeps that each gain
      // less than a unit can still add up to the next provable value.
      const int64_t sum = total + best;
      int64_t next = integral ? sum - floor_div(sum, kUnit) * kUnit + 1 : kUnit / 2;
      if (integral && whole && std::isfinite(limits.known_bound) && std::fabs(limits.known_bound) < 1e12)
        next = std::max(next, sum - static_cast<int64_t>(std::floor(sign * limits.known_bound)) * kUnit + 1);
      if (!whole)  // (a tile of many: its share of that, or 2e-4 of its own relaxation)
        next = std::max<int64_t>(1, static_cast<int64_t>(std::max(double(integral ? kUnit : kUnit / 2) * fresh / n,
                                                                  2e-4 * std::fabs(static_cast<double>(best)))));
      if (gained * static_cast<int64_t>(limits.iterations - sweep - 1) < next || visits >= stop_at) break;
    }
    done += fresh;
    // Back to the best multipliers: the fans' values are then those of `best`.
    for (uint32_t e = 1; e < ends.size(); ++e)
      if (lambda[e] != best_lambda[e]) set(ends.member(e), e, best_lambda[e]);
    auto values_of = [&](uint32_t i) {
      return std::span<const int64_t>(current.data() + t.first_leaf[i], t.first_leaf[i + 1] - t.first_leaf[i]);
    };
    // Each member's best fan counted, but the carried's (a neighbour still to list).
    for (uint32_t i = 0; i < m; ++i) {
      const uint32_t u = members[i];
      if (!in[u]) continue;
      const std::span<const int64_t> value = values_of(i);
      const std::vector<uint32_t>& around = lister.around(u);  // (sorted)
      if (v < n && !around.empty() && around.back() >= v) carried.push_back(u), carried_value.emplace_back(value.begin(), value.end());
      else total += *std::max_element(value.begin(), value.end());
    }
    // A tile of many: its members' fans, every other vertex held at its fan in *start.
    if (!whole && limits.decode && limits.start && limits.decoded_tile) {
      const std::vector<std::vector<uint32_t>> held = rings_of(*limits.start);
      FanTrees d;
      std::vector<int64_t> value;
      for (uint32_t u = 0; u < n; ++u) {
        d.first_node.push_back(d.corner.size()), d.first_leaf.push_back(d.leaf.size());
        if (position[u] == kNoFanNode || !in[u]) {  // (held: one fan, a path round its ring, its corners unnumbered)
          uint32_t parent = kNoFanNode;
          auto push = [&](uint32_t w) {
            d.corner.push_back(kNoFanNode), d.neighbor.push_back(w), d.parent.push_back(parent);
            parent = static_cast<uint32_t>(d.corner.size() - 1);
          };
          for (const uint32_t w : held[u]) push(w);
          if (lister.interior(u) && !held[u].empty()) push(held[u][0]);  // (closed round an interior vertex)
          if (parent != kNoFanNode) d.leaf.push_back(parent), value.push_back(0);
          continue;
        }
        const uint32_t i = position[u];
        const uint64_t base = t.first_node[i], to = d.corner.size();
        for (uint64_t x = base; x < t.first_node[i + 1]; ++x) {
          d.corner.push_back(t.corner[x]), d.neighbor.push_back(t.neighbor[x]);
          d.parent.push_back(t.parent[x] == kNoFanNode ? kNoFanNode : static_cast<uint32_t>(t.parent[x] - base + to));
        }
        for (uint64_t f = t.first_leaf[i]; f < t.first_leaf[i + 1]; ++f) d.leaf.push_back(t.leaf[f] - base + to);
        value.insert(value.end(), values_of(i).begin(), values_of(i).end());
      }
      d.first_node.push_back(d.corner.size()), d.first_leaf.push_back(d.leaf.size());
      // (Its steps: the tile's share, and one per held vertex.)
      limits.decoded_tile(StarDecoder(dt, std::move(d), lister.triangles(), std::move(value), limits.decode_steps_per_vertex * m + n));
    }
    // A gap left: a triangulation from the fans best under the multipliers.
    if (whole && limits.decode && out.left_out == 0 && relaxed(total) > target) {
      // (Whole: the members are the vertices in order, their fans all of current.)
      out.decoder = std::make_shared<const StarDecoder>(dt, std::move(t), tris, std::move(current),
                                                        limits.decode_steps_per_vertex * n);
    }
    for (const uint32_t u : members) position[u] = kNoFanNode;
  } while (v < n);
  out.tiles = tiles;
  out.bound = static_cast<double>(sign) * relaxed(total);
  return out;
}


std::optional<double> star_floor(const Mesh& dt, Objective o, const Candidates& cand, const StarBoundLimits& limits) {
  const ObjectiveTerms& d = objective_terms(o, dt);
  // (Within a domain too: a fan decides which of its triangles are inside, and
  // the terms below read them.)
  if (d.combine != Combine::Max || info(o).sense != Sense::Min) return std::nullopt;
  const uint32_t n = dt.num_vertices();
  double floor = 0;
  std::vector<uint32_t> ring, nb;
  std::vector<Tri> tris;
  FanTrees t;
  FanLister lister(dt, cand, t);
  for (uint32_t v = 0; v < n; ++v) {
    // One vertex's fans at a time: the trees need not outlive it.
    t.truncate(0, 0);
    if (!lister.list(v, limits.max_nodes_per_vertex)) continue;  // (a vertex not listed says nothing)
    const bool cyclic = lister.interior(v);
    // Its least fan: the worst term each fan holds, the least over fans, with
    // terms at most the floor cut short (they cannot raise it).
    double least = INFINITY;
    for (uint64_t f = 0; f < t.leaf.size() && least > floor; ++f) {
      t.ring(f, cyclic, ring);
      const size_t m = ring.size(), last = cyclic ? m : m - 1;
      double worst = 0;
      tris.clear();
      for (size_t j = 0; j < last; ++j) tris.push_back(Tri{v, ring[j], ring[(j + 1) % m]});
      switch (d.site) {
        case TermSite::InteriorVertex:
          if (!cyclic) break;
          [[fallthrough]];
        case TermSite::Vertex:
        case TermSite::VertexPair:
          nb = ring;
          std::sort(nb.begin(), nb.end());
          worst = vertex_term(d, dt, Star(v, nb, tris), floor);
          break;
        case TermSite::Triangle:
          for (const Tri& tri : tris) worst = std::max(worst, triangle_term(d, dt, tri));
          break;
        default:  // (edge sites: the edges at v, with both apexes inside the fan)
          for (size_t j = 0; j < m; ++j) {
            const bool inner = cyclic || (j > 0 && j + 1 < m);
            if (!inner && d.site != TermSite::Edge) continue;
            const uint32_t left = cyclic || j + 1 < m ? ring[(j + 1) % m] : kNoApex;
            const uint32_t right = cyclic || j > 0 ? ring[(j + m - 1) % m] : kNoApex;
            worst = std::max(worst, left == kNoApex ? edge_term(d, dt, ring[j], v, right, kNoApex, floor)
                                                    : edge_term(d, dt, v, ring[j], left, right, floor));
          }
      }
      least = std::min(least, worst);
    }
    if (least > floor && std::isfinite(least)) floor = least;
    if (limits.progress && v % 4096 == 0 && !limits.progress(v, n)) throw Cancelled();
  }
  return floor;
}

}  // namespace hodt
