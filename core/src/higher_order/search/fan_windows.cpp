#include "higher_order/search/fan_windows.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hodt/error.hpp"
#include "higher_order/bounds/fan_terms.hpp"
#include "higher_order/bounds/fan_trees.hpp"
#include "objectives/objective_terms.hpp"

namespace hodt {

namespace {

// Where the tiles lie, call by call (WindowLimits::placement), in tile sides
// along x and y: as they are, shifted half a tile along x, then y, then by
// quarters and eighths (each call's four offsets shift along the diagonal).
constexpr double kPlacements[8][2] = {{0, 0},       {0.5, 0},       {0, 0.5},       {0.25, 0.5},
                                      {0.5, 0.25},  {0.125, 0.375}, {0.375, 0.125}, {0.625, 0.875}};

// One window's members, their candidate fans (rings) and values, and a branch
// and bound over them: forward checking (a choice removes the later members'
// fans that disagree), a branch ending when its value plus each later member's
// best live fan cannot beat the best found.
struct Window {
  std::vector<uint32_t> member;
  std::vector<uint8_t> cyclic;
  std::vector<std::vector<std::vector<uint32_t>>> rings;  // per member, its fans, best first
  std::vector<std::vector<double>> value;                 // the same order
  std::vector<uint32_t> found;                            // per member, the fan index of the best found
  double found_value = 0;                                 // its value (the sum of the members')

  // Better than `current` by more than min_gain (slot: a vertex's place among
  // the members, or -1).
  bool best(double current, double min_gain, uint64_t max_steps, const std::vector<int32_t>& slot) {
    const size_t m = member.size();
    std::vector<std::vector<uint8_t>> alive(m);
    for (size_t a = 0; a < m; ++a) alive[a].assign(rings[a].size(), 1);
    std::vector<std::pair<size_t, size_t>> trail;
    std::vector<uint32_t> pick(m);
    // Per member, the later members that a fan of either names: a choice says
    // nothing of the others (they and it stay out of each other's fans).
    std::vector<std::vector<size_t>> named(m);
    {
      std::vector<uint8_t> linked(m * m, 0);
      for (size_t a = 0; a < m; ++a)
        for (const std::vector<uint32_t>& fan : rings[a])
          for (uint32_t u : fan)
            if (const int32_t b = slot[u]; b >= 0)
              linked[std::min(a, size_t(b)) * m + std::max(a, size_t(b))] = 1;
      for (size_t a = 0; a < m; ++a)
        for (size_t b = a + 1; b < m; ++b)
          if (linked[a * m + b]) named[a].push_back(b);
    }
    double best = current + min_gain;
    bool improved = false;
    uint64_t steps = 0;
    auto top = [&](size_t a) {
      for (size_t x = 0; x < rings[a].size(); ++x)
        if (alive[a][x]) return value[a][x];
      return -std::numeric_limits<double>::infinity();
    };
    auto dfs = [&](auto& self, size_t a, double sum) -> void {
      if (a == m) {
        if (sum > best) best = found_value = sum, found = pick, improved = true;
        return;
      }
      double rest = 0;
      for (size_t b = a; b < m; ++b) rest += top(b);
      if (!(sum + rest > best)) return;  // (also when a member has no fan left: -infinity)
      const double others = rest - top(a);
      for (size_t x = 0; x < rings[a].size() && steps < max_steps; ++x) {
        if (!alive[a][x]) continue;
        if (!(sum + value[a][x] + others > best)) break;
        ++steps;
        const size_t mark = trail.size();
        bool ok = true;
        for (size_t i = 0; i < named[a].size() && ok; ++i) {
          const size_t b = named[a][i];
          const FanSide want = mirrored(side_in_ring(rings[a][x], cyclic[a], member[b]));
          ok = false;
          for (size_t y = 0; y < rings[b].size(); ++y)
            if (alive[b][y]) {
              if (side_in_ring(rings[b][y], cyclic[b], member[a]) == want) ok = true;
              else alive[b][y] = 0, trail.emplace_back(b, y);
            }
        }
        pick[a] = static_cast<uint32_t>(x);
        if (ok) self(self, a + 1, sum + value[a][x]);
        for (; trail.size() > mark; trail.pop_back()) alive[trail.back().first][trail.back().second] = 1;
      }
    };
    dfs(dfs, 0, 0.0);
    return improved;
  }
};

}  // namespace

std::optional<std::vector<Tri>> improve_by_windows(const Mesh& dt, Objective o, const Candidates& cand,
                                                   const Mesh& start, const WindowLimits& limits) {
  const ObjectiveTerms& d = objective_terms(o, dt);
  // (Within a domain fan_terms reads the domain's terms, but a hull edge's
  // length counts there only beside a triangle inside, which no fan holds.)
  if (d.combine != Combine::Sum || !fan_holds_terms(d) || (d.domain && d.site == TermSite::Edge)) return std::nullopt;
  const double sign = info(o).sense == Sense::Max ? 1 : -1;  // (windows maximise sign * value)
  const bool integral = d.term_max < 1e6 && d.term_max == std::floor(d.term_max);  // (counts)
  const uint32_t n = dt.num_vertices();
  if (n == 0 || start.num_vertices() != n) return std::nullopt;

  // The rings at hand (updated as windows improve), and the tiles.
  std::vector<uint8_t> interior(n, 1);
  for (uint32_t h : dt.hull) interior[h] = 0;
  std::vector<std::vector<uint32_t>> ring = rings_of(start);
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (uint32_t v = 0; v < n; ++v)
    for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], dt.point(v)[a]), hi[a] = std::max(hi[a], dt.point(v)[a]);
  const double side = std::sqrt(limits.per_window * (hi[0] - lo[0]) * (hi[1] - lo[1]) / n);
  if (!(side > 0) || !std::isfinite(side)) return std::nullopt;

  FanTrees t;
  FanLister lister(dt, cand, t, false);
  uint64_t listed_nodes = 0;
  const uint64_t budget = std::max(limits.max_nodes, limits.max_nodes_per_point * n);
  double gained = 0;  // (sign form)
  std::vector<int32_t> slot(n, -1);  // a vertex's place in the window
  std::vector<uint32_t> scratch, fan;
  std::vector<double> own;
  // What the current rings say: v's fan must say this of u (u outside the window).
  auto wanted = [&](uint32_t v, uint32_t u) { return mirrored(side_in_ring(ring[u], interior[u], v)); };
  bool improved = false;
  std::vector<std::pair<uint64_t, uint32_t>> keyed(n);
  const double offsets[4] = {0.0, 0.5, 0.25, 0.75};
  const double* shift = kPlacements[limits.placement % 8];
  for (int pass = 0; pass < 4; ++pass) {
    for (uint32_t v = 0; v < n; ++v) {
      const auto cell = [&](int a) {  // (clamped: a sliver of a hull has more cells than that)
        return static_cast<uint64_t>(std::min(std::floor((dt.point(v)[a] - lo[a]) / side + offsets[pass] + shift[a]), 2147483647.0));
      };
      keyed[v] = {cell(1) << 32 | cell(0), v};
    }
    std::sort(keyed.begin(), keyed.end());
    for (size_t i = 0; i < n && listed_nodes < budget && gained < limits.enough;) {
      Window w;
      size_t j = i;
      for (; j < n && keyed[j].first == keyed[i].first; ++j) w.member.push_back(keyed[j].second);
      i = j;
      if (limits.progress && !limits.progress(pass * double(n) + double(i), 4.0 * n)) throw Cancelled();
      for (size_t a = 0; a < w.member.size(); ++a) slot[w.member[a]] = static_cast<int32_t>(a);
      // Each member's fans that agree with its outside neighbours, valued; a
      // member whose fans are over the budget keeps its ring (one fan).
      const size_t m = w.member.size();
      w.cyclic.resize(m), w.rings.resize(m), w.value.resize(m);
      auto owns = [&](uint32_t v) { return [&, v](uint32_t u) { return slot[u] < 0 || v < u; }; };
      own.assign(m, 0.0);  // (per member, its terms at hand)
      double current = 0;
      for (size_t a = 0; a < m; ++a) {
        fan_terms(dt, d, w.member[a], ring[w.member[a]], interior[w.member[a]], owns(w.member[a]), scratch,
                  [&](double x) { own[a] += sign * x; });
        current += own[a];
      }
      // Terms are never below 0: a minimised sum at 0 is at its best, and its
      // fans need no listing.
      const bool at_best = sign < 0 && current == 0;
      bool choice = false;
      for (size_t a = 0; a < m && !at_best; ++a) {
        const uint32_t v = w.member[a];
        w.cyclic[a] = interior[v];
        std::vector<std::pair<double, std::vector<uint32_t>>> listed;
        t.truncate(0, 0);
        const bool all_listed = lister.list(v, limits.max_nodes_per_vertex);
        listed_nodes += all_listed ? t.corner.size() : limits.max_nodes_per_vertex;  // (the work either way)
        if (all_listed)
          for (uint64_t f = 0; f < t.leaf.size(); ++f) {
            t.ring(f, interior[v], fan);
            auto agrees = [&](uint32_t u) { return slot[u] >= 0 || side_in_ring(fan, interior[v], u) == wanted(v, u); };
            // (outside neighbours in the fan, then those at hand)
            if (!std::all_of(fan.begin(), fan.end(), agrees) || !std::all_of(ring[v].begin(), ring[v].end(), agrees)) continue;
            double x = 0;
            fan_terms(dt, d, v, fan, interior[v], owns(v), scratch, [&](double y) { x += sign * y; });
            listed.emplace_back(x, fan);
          }
        if (listed.empty()) listed.emplace_back(own[a], ring[v]);  // (over the budget: v keeps its ring)
        std::stable_sort(listed.begin(), listed.end(), [](const auto& p, const auto& q) { return p.first > q.first; });
        w.rings[a].clear(), w.value[a].clear();
        for (auto& [x, r] : listed) w.value[a].push_back(x), w.rings[a].push_back(std::move(r));
        choice = choice || listed.size() > 1;
      }
      // (counts: a gain of 1 at least; lengths: beyond the rounding of their sums)
      const double min_gain = integral ? 0.5 : 1e-9 * std::fabs(current);
      if (choice && w.best(current, min_gain, limits.max_steps, slot)) {
        for (size_t a = 0; a < m; ++a) ring[w.member[a]] = w.rings[a][w.found[a]];
        gained += w.found_value - current;
        improved = true;
      }
      for (uint32_t v : w.member) slot[v] = -1;
    }
  }
  if (!improved) return std::nullopt;
  std::vector<Tri> out;
  for (uint32_t v = 0; v < n; ++v) append_fan_triangles(v, ring[v], interior[v], out);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace hodt
