#include "higher_order/search/branch_and_bound.hpp"

#include <algorithm>
#include <cmath>

#include "hodt/domain.hpp"
#include "higher_order/k_order.hpp"
#include "objectives/objective_terms.hpp"

namespace hodt {

bool branch_and_bound_applies(Objective o, const Mesh& dt) {
  if (has_domain(dt) || info(o).sense != Sense::Min) return false;
  const ObjectiveTerms& d = objective_terms(o, dt);
  if (d.combine != TermCombine::Max) return false;
  return d.site == TermSite::Triangle || d.site == TermSite::EdgePair || d.site == TermSite::VertexPair ||
         (d.site == TermSite::Vertex && d.term_of_degree);
}

namespace {

uint32_t shared_corners(const Tri& s, const Tri& t) {
  uint32_t n = 0;
  for (uint32_t a : s) n += a == t[0] || a == t[1] || a == t[2];
  return n;
}

}  // namespace

BranchAndBound branch_and_bound(const Mesh& dt, Objective o, const Candidates& cand, double known, uint64_t max_nodes,
                                const Progress& progress) {
  const ObjectiveTerms& d = objective_terms(o, dt);
  BranchAndBound r;
  r.value = known;
  // A term is no better than the best known when it is >= it: pair measures
  // answer exactly above `below` (the largest double under the best), and
  // anything <= below when they are at most that.
  double below = std::nextafter(r.value, -INFINITY);
  std::vector<uint32_t> neighbours;
  const AcceptTriangle accept = [&](const std::vector<Tri>& placed, const Tri& t) {
    switch (d.site) {
      case TermSite::Triangle:
        return d.triangle(dt, t) <= below;
      case TermSite::EdgePair:
      case TermSite::VertexPair: {
        const uint32_t shared = d.site == TermSite::EdgePair ? 2 : 1;
        for (const Tri& s : placed)
          if (shared_corners(s, t) >= shared && d.pair(dt, s, t, below) > below) return false;
        return true;
      }
      default: {  // a vertex's degree so far: its neighbours only grow
        for (uint32_t v : t) {
          neighbours.clear();
          for (const Tri& s : placed)
            if (s[0] == v || s[1] == v || s[2] == v)
              for (uint32_t w : s)
                if (w != v) neighbours.push_back(w);
          for (uint32_t w : t)
            if (w != v) neighbours.push_back(w);
          std::sort(neighbours.begin(), neighbours.end());
          const auto degree = static_cast<uint32_t>(std::unique(neighbours.begin(), neighbours.end()) - neighbours.begin());
          if (d.term_of_degree(degree) > below) return false;
        }
        return true;
      }
    }
  };
  // Every fill that reaches here has each term below the best known: it is better.
  const auto visit = [&](const std::vector<Tri>& tris) {
    Mesh m = mesh_of(dt.coords, tris);
    const double v = evaluate(o, m);
    if (!(v < r.value)) return;  // (never, the terms being the value's)
    r.found = std::move(m), r.value = v;
    below = std::nextafter(v, -INFINITY);
  };
  std::vector<std::pair<uint32_t, uint32_t>> hull;
  for (size_t i = 0; i < dt.hull.size(); ++i) hull.push_back({dt.hull[i], dt.hull[(i + 1) % dt.hull.size()]});
  r.complete = enumerate_fills(dt, cand, hull, max_nodes, visit, progress, &r.nodes, accept);
  return r;
}

}  // namespace hodt
