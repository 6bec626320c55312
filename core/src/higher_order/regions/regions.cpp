#include "higher_order/regions/regions.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <stdexcept>

#include "hodt/domain.hpp"
#include "hodt/error.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/predicates.hpp"
#include "higher_order/regions/fill_dp.hpp"
#include "higher_order/fills/fill_enumerator.hpp"
#include "higher_order/regions/region_terms.hpp"
#include "mesh/mesh_of.hpp"

namespace hodt {

namespace {
// For collinear u, a, v: is a on the ray from u towards v? (Exact: coordinate comparisons.)
bool same_direction(const double* u, const double* a, const double* v) {
  const int axis = v[0] != u[0] ? 0 : 1;
  return (a[axis] > u[axis]) == (v[axis] > u[axis]) && a[axis] != u[axis];
}
}  // namespace

std::vector<uint32_t> crossed_edges(const Mesh& m, const std::vector<int32_t>& out, uint32_t u, uint32_t v) {
  auto orient = [&](uint32_t a, uint32_t b, uint32_t c) { return orient2d(m.point(a), m.point(b), m.point(c)); };
  auto through_point = [&](uint32_t w) {
    return std::logic_error("segment " + std::to_string(u) + " " + std::to_string(v) + " passes through point " +
                            std::to_string(w));
  };
  // The triangle u, a, b around u whose angle holds the direction of v.
  uint32_t e = static_cast<uint32_t>(out[u]);
  const uint32_t first = e;
  uint32_t h = UINT32_MAX;
  for (;;) {
    const uint32_t a = m.target(e), b = m.apex(e);
    if (a == v || b == v) return {};  // a Delaunay edge
    const int oa = orient(u, a, v), ob = orient(u, b, v);
    if (oa > 0 && ob < 0) {
      h = next_halfedge(e);
      break;
    }
    if (oa == 0 && same_direction(m.point(u), m.point(a), m.point(v))) throw through_point(a);
    const int32_t t = m.halfedges[prev_halfedge(e)];
    if (t < 0 || static_cast<uint32_t>(t) == first) throw std::logic_error("segment leaves the hull");
    e = static_cast<uint32_t>(t);
  }
  // Cross triangles until v: the crossed edge runs from a (right of u -> v) to b (left).
  std::vector<uint32_t> crossed;
  for (;;) {
    crossed.push_back(h);
    const int32_t t = m.halfedges[h];
    if (t < 0) throw std::logic_error("segment leaves the hull");
    const uint32_t c = m.apex(static_cast<uint32_t>(t));
    if (c == v) return crossed;
    const int o = orient(u, v, c);
    if (o == 0) throw through_point(c);
    h = o > 0 ? next_halfedge(static_cast<uint32_t>(t)) : prev_halfedge(static_cast<uint32_t>(t));
  }
}

namespace {

uint32_t find(std::vector<uint32_t>& parent, uint32_t x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

// Triangles rotated to start at their smallest vertex, sorted: equal
// triangulations of a region compare equal.
std::vector<Tri> canonical(std::vector<Tri> tris) {
  for (Tri& t : tris) t = canonical_triangle(t);
  std::sort(tris.begin(), tris.end());
  return tris;
}

struct StopFill {};

}  // namespace

Mesh Regions::triangulation(const Mesh& dt, const std::vector<uint32_t>& state) const {
  std::vector<Tri> tris;
  tris.reserve(dt.num_triangles());
  for (size_t r = 0; r < regions.size(); ++r) {
    const auto& s = regions[r].states[state.empty() ? 0 : state[r]];
    tris.insert(tris.end(), s.begin(), s.end());
  }
  return mesh_of(dt.coords, tris);
}

void cut_into_regions(const Mesh& dt, Regions& out) {
  // Delaunay triangles glued across free edges.
  const uint32_t nt = dt.num_triangles();
  std::vector<uint32_t> parent(nt);
  std::iota(parent.begin(), parent.end(), 0u);
  for (uint32_t e = 0; e < dt.halfedges.size(); ++e)
    if (!out.fixed[e]) parent[find(parent, e / 3)] = find(parent, static_cast<uint32_t>(dt.halfedges[e]) / 3);
  out.regions.clear();
  out.region_of_triangle.assign(nt, UINT32_MAX);
  std::vector<uint32_t> id(nt, UINT32_MAX);
  for (uint32_t t = 0; t < nt; ++t) {
    const uint32_t root = find(parent, t);
    if (id[root] == UINT32_MAX) id[root] = static_cast<uint32_t>(out.regions.size()), out.regions.emplace_back();
    out.region_of_triangle[t] = id[root];
    out.regions[id[root]].delaunay_triangles.push_back(t);
  }
  for (Region& region : out.regions) {
    std::vector<Tri> delaunay;
    for (uint32_t t : region.delaunay_triangles) {
      delaunay.push_back(base_triangle(dt, t));
      for (uint32_t e = 3 * t; e < 3 * t + 3; ++e)
        if (dt.halfedges[e] < 0 || out.fixed[e]) region.boundary.push_back({dt.origin(e), dt.target(e)});
    }
    region.states.push_back(canonical(std::move(delaunay)));
  }
  out.incomplete = 0;
}

Regions k_order_skeleton(const Mesh& dt, uint32_t k, const Progress& progress, const std::vector<uint8_t>& forced) {
  return k_order_skeleton(dt, k, useful_edges(dt, k, progress), progress, forced);
}

Regions k_order_skeleton(const Mesh& dt, uint32_t k, const std::vector<std::pair<uint32_t, uint32_t>>& useful,
                         const Progress& progress, const std::vector<uint8_t>& forced) {
  Regions out;
  out.order = k;
  const std::vector<int32_t> start = vertex_halfedges(dt);
  // A Delaunay edge is fixed unless a useful non-Delaunay edge crosses it (one
  // that crosses a forced edge is not useful here: no triangulation keeping the
  // forced edges has it).
  out.fixed.assign(dt.triangles.size(), 1);
  for (size_t i = 0; i < useful.size(); ++i) {
    if (progress && (i & 1023) == 0 && !progress(static_cast<double>(i), static_cast<double>(useful.size())))
      throw Cancelled();
    const std::vector<uint32_t> crossed = crossed_edges(dt, start, useful[i].first, useful[i].second);
    if (!forced.empty() && std::any_of(crossed.begin(), crossed.end(), [&](uint32_t h) { return forced[h] != 0; }))
      continue;
    out.useful.push_back(useful[i]);
    for (uint32_t h : crossed) {
      out.fixed[h] = 0;
      out.fixed[static_cast<uint32_t>(dt.halfedges[h])] = 0;
    }
  }
  out.near_outside = vertices_near_outside(dt, out.useful);
  cut_into_regions(dt, out);
  return out;
}

void enumerate_regions(const Mesh& dt, Regions& out, const RegionLimits& limits) {
  const bool any_free = std::find(out.fixed.begin(), out.fixed.end(), 0) != out.fixed.end();
  const Candidates cand = limits.candidates || !any_free ? Candidates{} : k_order_candidates(dt, out.order, out.useful, limits.progress);
  const Candidates& candidates = limits.candidates ? *limits.candidates : cand;
  const RegionTerms* terms = limits.terms;
  uint64_t used = 0, dp_used = 0;
  // The best triangulation per signature, by dynamic programming: false when
  // it needs more than `budget` partial fills.
  auto by_dp = [&](Region& region, uint32_t r, uint64_t budget) {
    auto fills = best_fills(dt, candidates, *terms, r, budget, limits.progress, &dp_used, nullptr, &region.swept);
    if (!fills) return false;
    std::stable_sort(fills->begin(), fills->end(),
                     [&](const BestFill& a, const BestFill& b) { return terms->better(a.value, b.value); });
    region.states.resize(1);
    region.complete = true;
    for (BestFill& f : *fills) {
      if (f.triangles == region.states[0]) continue;
      if (region.states.size() >= limits.max_states_per_region) {  // too many interfaces: the best ones
        region.complete = false;
        break;
      }
      region.states.push_back(std::move(f.triangles));
    }
    return true;
  };
  // Every triangulation, within `budget` search nodes; with terms, the best per signature.
  auto enumerate = [&](Region& region, uint32_t r, uint64_t budget) {
    region.states.resize(1);
    region.complete = true;
    std::map<std::vector<SignatureEntry>, std::pair<uint32_t, double>> best;  // the state kept per signature
    if (terms) {
      StateKey key = terms->key(r, region.states[0]);
      best.emplace(std::move(key.signature), std::make_pair(0u, key.value));
    }
    try {
      region.complete = enumerate_fills(dt, candidates, region.boundary, budget, [&](const std::vector<Tri>& tris) {
        std::vector<Tri> c = canonical(tris);
        if (c == region.states[0]) return;
        if (terms) {
          StateKey key = terms->key(r, c);
          auto it = best.find(key.signature);
          if (it != best.end()) {
            if (!terms->better(key.value, it->second.second)) return;
            if (it->second.first != 0) {  // replace (states[0] stays)
              region.states[it->second.first] = std::move(c);
              it->second.second = key.value;
              return;
            }
          }
          if (region.states.size() >= limits.max_states_per_region) throw StopFill{};
          best[std::move(key.signature)] = {static_cast<uint32_t>(region.states.size()), key.value};
        } else if (region.states.size() >= limits.max_states_per_region) {
          throw StopFill{};
        }
        region.states.push_back(std::move(c));
      }, limits.progress, &used);
    } catch (const StopFill&) {
      region.complete = false;
    }
  };
  if (limits.only_incomplete && terms) {
    // A second pass, of use only if every region ends up whole: the DP's larger
    // budget for each region left incomplete, the largest first, stopping at
    // the first that does not fit.
    std::vector<uint32_t> order;
    for (uint32_t r = 0; r < out.regions.size(); ++r)
      if (!out.regions[r].complete) order.push_back(r);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
      return out.regions[a].delaunay_triangles.size() > out.regions[b].delaunay_triangles.size();
    });
    for (uint32_t r : order)
      if (dp_used >= limits.max_total_states ||
          !by_dp(out.regions[r], r, std::min(limits.max_states_per_region_dp, limits.max_total_states - dp_used)) ||
          !out.regions[r].complete)
        break;
    out.incomplete = 0;
    for (const Region& region : out.regions) out.incomplete += !region.complete;
    return;
  }
  std::vector<uint8_t> done(out.regions.size(), 0);
  for (uint32_t pass = 0; pass < 2; ++pass) {
    for (size_t i = 0; i < out.regions.size(); ++i) {
      const uint32_t r = static_cast<uint32_t>(i);
      Region& region = out.regions[r];
      if (limits.progress && (r & 63) == 0 &&
          !limits.progress(static_cast<double>(pass * out.regions.size() + r), 2.0 * out.regions.size()))
        throw Cancelled();
      if (done[r] || region.delaunay_triangles.size() == 1) continue;
      if (region.delaunay_triangles.size() > limits.max_region_triangles) {
        // (A region nothing beside it sees has one signature: the DP keeps only
        // the frontiers, few even for a large region, so it gets the full budget.)
        const bool unseen = terms && terms->items(r).empty();
        if (pass == 0 && terms)
          done[r] = by_dp(region, r, unseen ? limits.max_states_per_region_dp : limits.large_region_states);
        if (!done[r]) region.complete = false;
        continue;
      }
      if (pass == 0) {
        done[r] = terms ? by_dp(region, r, std::min(limits.first_pass_states, limits.max_states_per_region_dp))
                        : (enumerate(region, r, std::min(limits.first_pass_nodes, limits.max_nodes_per_region)),
                           region.complete);
        continue;
      }
      if (terms) {
        if (dp_used < limits.max_total_states &&
            by_dp(region, r, std::min(limits.max_states_per_region_dp, limits.max_total_states - dp_used)))
          continue;
        // Over the DP's budgets: left to the fill graphs, views and stars, which
        // read such a region without listing it (listing its fills one by one,
        // each keyed, rarely completes a region the DP's budget did not hold,
        // and costs a large share of the solve).
        region.complete = false;
        continue;
      }
      // Too large for the budgets: some of its triangulations, for the heuristics
      // (unless pass 0 enumerated it with the whole budget already).
      if (limits.first_pass_nodes < limits.max_nodes_per_region && used < limits.max_total_nodes)
        enumerate(region, r, std::min(limits.max_nodes_per_region, limits.max_total_nodes - used));
    }
  }
  out.incomplete = 0;
  for (const Region& region : out.regions) out.incomplete += !region.complete;
}

Regions k_order_regions(const Mesh& dt, uint32_t k, const RegionLimits& limits) {
  Regions out = k_order_skeleton(dt, k, limits.progress);
  enumerate_regions(dt, out, limits);
  return out;
}

std::vector<uint32_t> listed_states(const Regions& R, const Mesh& m) {
  std::set<Tri> tris;
  for (uint32_t t = 0; t < m.num_triangles(); ++t) {
    tris.insert(canonical_triangle(base_triangle(m, t)));
  }
  std::vector<uint32_t> state(R.regions.size(), 0);
  for (size_t r = 0; r < R.regions.size(); ++r) {
    const auto& states = R.regions[r].states;
    for (uint32_t s = 0; s < states.size(); ++s)
      if (std::all_of(states[s].begin(), states[s].end(), [&](const Tri& t) { return tris.count(t) > 0; })) {
        state[r] = s;
        break;
      }
  }
  return state;
}


}  // namespace hodt
