#include "hodt/star_bound.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "hodt/domain.hpp"
#include "hodt/error.hpp"
#include "hodt/fan_terms.hpp"
#include "hodt/fan_trees.hpp"
#include "hodt/objective_terms.hpp"
#include "hodt/star_decode.hpp"

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
  if (d.combine != TermCombine::Sum || has_domain(dt) || !std::isfinite(incumbent) ||
      !(integral ? at_vertices || d.site == TermSite::InteriorEdge : lengths))
    return std::nullopt;
  const uint32_t n = dt.num_vertices();

  // The fans.
  FanTrees t;
  FanLister lister(dt, cand, t);
  std::vector<uint8_t> in(n, 0);  // its fans listed (else its terms at their best)
  StarBound out;
  for (uint32_t v = 0; v < n; ++v) {
    t.first_node.push_back(t.corner.size()), t.first_leaf.push_back(t.leaf.size());
    const uint64_t room = std::min(limits.max_nodes_per_vertex, limits.max_nodes - std::min<uint64_t>(limits.max_nodes, t.corner.size()));
    in[v] = lister.list(v, room);
    if (!in[v]) t.truncate(t.first_node.back(), t.first_leaf.back());
    out.left_out += !in[v];
    if (limits.progress && v % 4096 == 0 && !limits.progress(v, 2.0 * n)) throw Cancelled();
  }
  t.first_node.push_back(t.corner.size()), t.first_leaf.push_back(t.leaf.size());
  out.nodes = t.corner.size();
  if (out.left_out > limits.max_left_out * n) return std::nullopt;

  // Each fan's terms. An interior edge's belongs to its smaller end with fans
  // listed; terms no listed fan holds are at their best.
  const int64_t best_term = sign > 0 ? static_cast<int64_t>(d.term_max) : 0;
  int64_t constant = 0;  // (in units)
  auto owner = [&](uint32_t a, uint32_t b) { return in[a] && (!in[b] || a < b) ? a : in[b] ? b : kNoFanNode; };
  // The terms of fan f of v (an edge's, of the edges v owns).
  std::vector<uint32_t> seq, scratch;
  auto terms_of = [&](uint32_t v, uint64_t f, const auto& take) {
    const bool cyclic = lister.interior(v);
    t.ring(f, cyclic, seq);
    fan_terms(dt, d, v, seq, cyclic, [&](uint32_t u) { return owner(v, u) == v; }, scratch, take);
  };
  // Lengths in units of 2^-e, the longest term near 2^20 units: each rounded
  // down, less one unit (the length is accurate, not exact), so every sum is
  // exact and never above the true one. Counts: units of 1.
  double scale = 1;
  if (!integral) {
    double longest = 0;
    for (uint32_t v = 0; v < n; ++v)
      for (uint64_t f = t.first_leaf[v]; f < t.first_leaf[v + 1]; ++f)
        terms_of(v, f, [&](double w) { longest = std::max(longest, std::fabs(w)); });
    for (size_t i = 0; i < dt.hull.size(); ++i)
      longest = std::max(longest, edge_term(d, dt, dt.hull[i], dt.hull[(i + 1) % dt.hull.size()], kNoApex, kNoApex));
    if (longest > 0) scale = std::ldexp(1.0, 20 - std::ilogb(longest));
  }
  auto units = [&](double w) {  // (sign form, at least sign * w * scale)
    if (integral) return sign * static_cast<int64_t>(w);
    return -(static_cast<int64_t>(std::floor(w * scale)) - 1);
  };
  if (lengths)  // (hull edges: in every triangulation)
    for (size_t i = 0; i < dt.hull.size(); ++i)
      constant += units(edge_term(d, dt, dt.hull[i], dt.hull[(i + 1) % dt.hull.size()], kNoApex, kNoApex)) * kUnit;
  if (at_vertices) {
    for (uint32_t v = 0; v < n; ++v)
      if (!in[v] && (d.site == TermSite::Vertex || lister.interior(v))) constant += best_term * kUnit;
  } else {
    for (uint32_t v = 0; v < n; ++v)
      for (const uint32_t u : lister.around(v))
        if (v < u && owner(v, u) == kNoFanNode) constant += best_term * kUnit;
  }
  std::vector<int64_t> weight(t.leaf.size());
  bool counts = true;
  for (uint32_t v = 0; v < n; ++v)
    for (uint64_t f = t.first_leaf[v]; f < t.first_leaf[v + 1]; ++f)
      terms_of(v, f, [&](double w) {
        if (integral && !(w == std::floor(w) && std::fabs(w) < 1e6)) counts = false;
        else weight[f] += units(w) * kUnit;
      });
  if (!counts) return std::nullopt;

  // Block coordinate descent on the multipliers (MPLP, Globerson and Jaakkola
  // 2007, with a triangle's corners as the block): each live corner's best fan
  // with the triangle and without it, then multipliers that make every corner
  // indifferent by the same margin. Each update lowers the bound or keeps it;
  // the sums stay exact (rounded to units, the last corner takes the rest).
  const std::vector<Tri>& tris = lister.triangles();
  const size_t corners = 3 * tris.size();
  std::vector<int64_t> lambda(corners, 0);
  std::vector<uint8_t> live(corners, 0);
  for (const uint32_t c : t.corner)
    if (c != kNoFanNode) live[c] = 1;
  // Per node of one vertex's trees (indexed from its first node: the scratch is
  // as large as the largest vertex's trees, not all of them).
  uint64_t widest = 0;
  for (uint32_t v = 0; v < n; ++v) widest = std::max(widest, t.first_node[v + 1] - t.first_node[v]);
  std::vector<int64_t> acc(widest);
  std::vector<uint8_t> has(widest);
  // The best fan of v with corner c and the best without (c's own multiplier
  // left out; INT64_MIN: none).
  auto split = [&](uint32_t v, uint32_t c) {
    int64_t with = INT64_MIN, without = INT64_MIN;
    const uint64_t base = t.first_node[v];
    for (uint64_t x = base; x < t.first_node[v + 1]; ++x) {
      const bool root = t.parent[x] == kNoFanNode, own = c != kNoFanNode && t.corner[x] == c;
      has[x - base] = own || (!root && has[t.parent[x] - base]);
      acc[x - base] = (root ? 0 : acc[t.parent[x] - base]) + (t.corner[x] == kNoFanNode || own ? 0 : lambda[t.corner[x]]);
    }
    for (uint64_t f = t.first_leaf[v]; f < t.first_leaf[v + 1]; ++f) {
      int64_t& side = has[t.leaf[f] - base] ? with : without;
      side = std::max(side, weight[f] + acc[t.leaf[f] - base]);
    }
    return std::pair{with, without};
  };
  // The bound: per vertex its best fan (with no corner set apart, all fans are "without").
  auto bound_now = [&] {
    int64_t total = constant;
    for (uint32_t v = 0; v < n; ++v)
      if (in[v]) total += split(v, kNoFanNode).second;
    return total;
  };
  const double target = static_cast<double>(sign) * incumbent;
  // What the relaxation proves of sign * value: counts are integers (the
  // floor), lengths the ceiling in their units.
  auto relaxed = [&](int64_t total) {
    return integral ? static_cast<double>(floor_div(total, kUnit)) : static_cast<double>(-floor_div(-total, kUnit)) / scale;
  };
  int64_t best = bound_now();
  std::vector<int64_t> best_lambda = limits.decode ? lambda : std::vector<int64_t>();  // (the multipliers of `best`)
  constexpr double kCap = double(int64_t{1} << 32);  // (a corner every fan takes: its margin is capped)
  std::vector<std::pair<uint32_t, double>> block;  // (corner, margin)
  for (uint32_t sweep = 0; sweep < limits.iterations && relaxed(best) > target; ++sweep) {
    for (size_t tri = 0; tri < tris.size(); ++tri) {
      block.clear();
      for (uint32_t c = static_cast<uint32_t>(3 * tri); c < 3 * tri + 3; ++c)
        if (live[c]) {
          const auto [with, without] = split(tris[tri][c - 3 * tri], c);
          const double margin = without == INT64_MIN ? kCap : static_cast<double>(with) - static_cast<double>(without);
          block.push_back({c, std::clamp(margin, -kCap, kCap)});
        }
      if (block.size() < 2) continue;
      double mean = 0;
      for (const auto& [c, m] : block) mean += m;
      mean /= static_cast<double>(block.size());
      int64_t sum = 0;
      for (size_t i = 0; i + 1 < block.size(); ++i) {
        lambda[block[i].first] = std::llround(mean - block[i].second);
        sum += lambda[block[i].first];
      }
      lambda[block.back().first] = -sum;  // (exactly 0 over the triangle)
    }
    const int64_t now = bound_now();
    if (limits.progress && !limits.progress(n + static_cast<double>(sweep + 1) * n / limits.iterations, 2.0 * n)) throw Cancelled();
    const int64_t gained = best - now;
    if (now < best && limits.decode) best_lambda = lambda;
    best = std::min(best, now);
    // Stop once the last sweep's gain, kept up for every sweep left, would not
    // reach the next value the bound can prove (the next integer for counts, or
    // past the known bound; half a unit for lengths). The gains shrink slowly:
    // on the volcano at k = 4, min-mixed-vertices, 74.27 after 8 sweeps (each
    // gaining less than half a unit), 75.0 after 24, proving the 76 found.
    int64_t next = integral ? best - floor_div(best, kUnit) * kUnit + 1 : kUnit / 2;
    if (integral && std::isfinite(limits.known_bound) && std::fabs(limits.known_bound) < 1e12)
      next = std::max(next, best - static_cast<int64_t>(std::floor(sign * limits.known_bound)) * kUnit + 1);
    if (gained * static_cast<int64_t>(limits.iterations - sweep - 1) < next) break;
  }
  out.bound = static_cast<double>(sign) * relaxed(best);
  // A gap left: a triangulation from the fans best under the multipliers.
  if (limits.decode && out.left_out == 0 && relaxed(best) > target) {
    std::vector<int64_t> value(t.leaf.size());
    for (uint64_t f = 0; f < t.leaf.size(); ++f) {
      value[f] = weight[f];
      for (uint64_t x = t.leaf[f]; x != kNoFanNode; x = t.parent[x])
        if (t.corner[x] != kNoFanNode) value[f] += best_lambda[t.corner[x]];
    }
    out.decoder = std::make_shared<const StarDecoder>(dt, std::move(t), tris, std::move(value),
                                                      limits.decode_steps_per_vertex * n);
  }
  return out;
}


std::optional<double> star_floor(const Mesh& dt, Objective o, const Candidates& cand, const StarBoundLimits& limits) {
  const ObjectiveTerms& d = objective_terms(o, dt);
  if (d.combine != TermCombine::Max || info(o).sense != Sense::Min || has_domain(dt)) return std::nullopt;
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
