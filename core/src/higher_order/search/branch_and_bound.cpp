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
  if (d.combine != Combine::Max) return false;
  return d.site == TermSite::Triangle || d.site == TermSite::EdgePair || d.site == TermSite::VertexPair ||
         (d.site == TermSite::Vertex && d.term_of_degree);
}

namespace {

bool has_corner(const Tri& s, uint32_t v) { return s[0] == v || s[1] == v || s[2] == v; }

// The terms a triangle makes with the placed ones, read through each vertex's
// placed triangles (a star holds a few, so a test costs a few pair measures).
class TermPruning final : public FillPruning {
 public:
  TermPruning(const Mesh& dt, const ObjectiveTerms& d, double known)
      : dt_(dt), d_(d), around_(dt.num_vertices()) {
    set_best(known);
  }
  // A term is no better than the best known when it is >= it: pair measures
  // answer exactly above `below_` (the largest double under the best), and
  // anything <= below_ when they are at most that.
  void set_best(double value) { below_ = std::nextafter(value, -INFINITY); }

  bool accept(const Tri& t) override {
    switch (d_.site) {
      case TermSite::Triangle:
        return d_.triangle(dt_, t) <= below_;
      case TermSite::EdgePair:  // the placed triangle across each of t's edges
        for (uint32_t i = 0; i < 3; ++i)
          for (const Tri& s : around_[t[i]])
            if (has_corner(s, t[(i + 1) % 3]) && d_.pair(dt_, s, t, below_) > below_) return false;
        return true;
      case TermSite::VertexPair:  // each placed triangle at a corner, once (at its first shared corner)
        for (uint32_t i = 0; i < 3; ++i)
          for (const Tri& s : around_[t[i]])
            if ((i == 0 || !has_corner(s, t[0])) && (i < 2 || !has_corner(s, t[1])) &&
                d_.pair(dt_, s, t, below_) > below_)
              return false;
        return true;
      default:  // a vertex's degree so far: its neighbours only grow
        for (uint32_t i = 0; i < 3; ++i) {
          const uint32_t v = t[i];
          neighbours_.assign({t[(i + 1) % 3], t[(i + 2) % 3]});
          for (const Tri& s : around_[v])
            for (uint32_t w : s)
              if (w != v) neighbours_.push_back(w);
          std::sort(neighbours_.begin(), neighbours_.end());
          const auto degree = static_cast<uint32_t>(std::unique(neighbours_.begin(), neighbours_.end()) - neighbours_.begin());
          if (d_.term_of_degree(degree) > below_) return false;
        }
        return true;
    }
  }
  void place(const Tri& t) override {
    for (uint32_t v : t) around_[v].push_back(t);
  }
  void remove(const Tri& t) override {
    for (uint32_t v : t) around_[v].pop_back();  // (stack order)
  }

 private:
  const Mesh& dt_;
  const ObjectiveTerms& d_;
  std::vector<std::vector<Tri>> around_;  // per vertex, its placed triangles
  std::vector<uint32_t> neighbours_;
  double below_ = 0;
};

}  // namespace

BranchAndBound branch_and_bound(const Mesh& dt, Objective o, const Candidates& cand, double known, uint64_t max_nodes,
                                const Progress& progress) {
  BranchAndBound r;
  r.value = known;
  TermPruning pruning(dt, objective_terms(o, dt), known);
  // Every fill that reaches here has each term below the best known: it is better.
  const auto visit = [&](const std::vector<Tri>& tris) {
    Mesh m = mesh_of(dt.coords, tris);
    const double v = evaluate(o, m);
    if (!(v < r.value)) return;  // (never, the terms being the value's)
    r.found = std::move(m), r.value = v;
    pruning.set_best(v);
  };
  std::vector<std::pair<uint32_t, uint32_t>> hull;
  for (size_t i = 0; i < dt.hull.size(); ++i) hull.push_back({dt.hull[i], dt.hull[(i + 1) % dt.hull.size()]});
  r.complete = enumerate_fills(dt, cand, hull, max_nodes, visit, progress, &r.nodes, &pruning);
  return r;
}

}  // namespace hodt
