#include "higher_order/search/branch_and_bound.hpp"

#include <algorithm>
#include <cmath>

#include "hodt/domain.hpp"
#include "mesh/mesh_of.hpp"
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
  TermPruning(const Mesh& dt, const ObjectiveTerms& d, double known, uint64_t memo)
      : dt_(dt), d_(d), around_(dt.num_vertices()) {
    set_best(known);
    // (The context packs a triangle's corners in one word.)
    memo_words = dt.num_vertices() <= 1024 ? memo : 0;
  }
  // A term is no better than the best known when it is >= it: pair measures
  // answer exactly above `below_` (the largest double under the best), and
  // anything <= below_ when they are at most that.
  void set_best(double value) { below_ = std::nextafter(value, -INFINITY); }

  bool accept(const Tri& t) override { return !(largest_term(t, below_, nullptr) > below_); }
  // The largest term placed so far, exact: place() measures with that as the cut.
  void place(const Tri& t) override {
    const double before = largest_.empty() ? 0 : largest_.back();
    largest_.push_back(std::max(before, largest_term(t, before, nullptr, false)));
    for (uint32_t v : t) around_[v].push_back({t, static_cast<uint32_t>(largest_.size() - 1)});
  }
  void remove(const Tri& t) override {
    for (uint32_t v : t) around_[v].pop_back();  // (stack order)
    largest_.pop_back();
  }
  // Every completion keeps the largest placed term (a degree only grows): the
  // triangles up to the first that reached the best known.
  uint32_t dead() const override {
    if (largest_.empty() || !(largest_.back() > below_)) return 0;
    return static_cast<uint32_t>(std::upper_bound(largest_.begin(), largest_.end(), below_) - largest_.begin()) + 1;
  }
  // The placed triangles that make a term with t at least the best known (a
  // triangle's own term: none; a degree: every placed triangle at the vertex).
  bool reasons(const Tri& t, std::vector<uint32_t>& positions) const override {
    return largest_term(t, below_, &positions) > below_;
  }

  // What a completion's terms read of the placed triangles, the frontier
  // given (fill_search.hpp). A completion's triangles lie in the uncovered
  // part, so a term they share with placed ones sits on the frontier:
  // - a triangle's own term reads nothing placed;
  // - an edge pair across a placed triangle and a completion's shares an open
  //   edge: the key names the triangle behind each open edge (the apex, none
  //   on the hull), the whole of what such pairs read;
  // - a vertex pair shares a corner in both parts, a vertex of the frontier:
  //   the key holds every placed triangle at a frontier vertex;
  // - a vertex's degree at the end counts its neighbours placed and those the
  //   completion adds, less those in both: the edges in both parts, which are
  //   the open edges at the vertex that a placed triangle opened (those not on
  //   the hull, which the frontier tells). The key holds each frontier vertex's
  //   degree so far; the other vertices touched by a completion are inside the
  //   uncovered part and have no placed neighbour.
  // So two partial fills with the same frontier and key give each completion
  // the same terms beyond those among their placed triangles alone.
  void context(const std::vector<uint64_t>& open, std::vector<uint32_t>& key) const override {
    if (d_.site == TermSite::Triangle) return;
    if (d_.site == TermSite::EdgePair) {
      for (uint64_t e : open) {
        const uint32_t u = static_cast<uint32_t>(e >> 32), v = static_cast<uint32_t>(e);
        uint32_t apex = UINT32_MAX;
        for (const Placed& s : around_[u])
          if (has_corner(s.t, v)) apex = s.t[0] + s.t[1] + s.t[2] - u - v;
        key.push_back(apex);
      }
      return;
    }
    frontier_.clear();
    for (uint64_t e : open) frontier_.push_back(static_cast<uint32_t>(e >> 32));
    std::sort(frontier_.begin(), frontier_.end());
    frontier_.erase(std::unique(frontier_.begin(), frontier_.end()), frontier_.end());
    if (d_.site == TermSite::VertexPair) {
      packed_.clear();
      for (uint32_t v : frontier_)
        for (const Placed& p : around_[v]) {
          const Tri& s = p.t;
          const uint32_t m = s[0] < s[1] ? (s[0] < s[2] ? 0 : 2) : (s[1] < s[2] ? 1 : 2);  // (smallest corner first)
          packed_.push_back(s[m] << 20 | s[(m + 1) % 3] << 10 | s[(m + 2) % 3]);
        }
      std::sort(packed_.begin(), packed_.end());
      packed_.erase(std::unique(packed_.begin(), packed_.end()), packed_.end());
      key.insert(key.end(), packed_.begin(), packed_.end());
      return;
    }
    for (uint32_t v : frontier_) key.push_back(degree(v, nullptr));
  }
  // The placed triangles' own terms (a degree's floor among them) are below the
  // best known: a failed search of their completions is the completions'.
  bool explored() const override { return dead() == 0; }

 private:
  struct Placed {
    Tri t;
    uint32_t position;
  };

  // The largest term t makes with the placed triangles: exact above `cut`,
  // else anything <= cut. test: any one term above cut will do, as soon as it
  // is found; culprits (when given, with test): the placed triangles it was made with.
  double largest_term(const Tri& t, double cut, std::vector<uint32_t>* culprits, bool test = true) const {
    double worst = -INFINITY;
    const auto with = [&](const Placed& s) {
      worst = std::max(worst, d_.pair(dt_, s.t, t, std::max(cut, worst)));
      if (!(test && worst > cut)) return false;
      if (culprits) culprits->push_back(s.position);
      return true;
    };
    switch (d_.site) {
      case TermSite::Triangle:
        return d_.triangle(dt_, t);
      case TermSite::EdgePair:  // the placed triangle across each of t's edges
        for (uint32_t i = 0; i < 3; ++i)
          for (const Placed& s : around_[t[i]])
            if (has_corner(s.t, t[(i + 1) % 3]) && with(s)) return worst;
        return worst;
      case TermSite::VertexPair:  // each placed triangle at a corner, once (at its first shared corner)
        for (uint32_t i = 0; i < 3; ++i)
          for (const Placed& s : around_[t[i]])
            if ((i == 0 || !has_corner(s.t, t[0])) && (i < 2 || !has_corner(s.t, t[1])) && with(s)) return worst;
        return worst;
      default:  // a vertex's degree so far: its neighbours only grow
        for (uint32_t i = 0; i < 3; ++i) {
          worst = std::max(worst, d_.term_of_degree(degree(t[i], &t)));
          if (test && worst > cut) {
            if (culprits)
              for (const Placed& s : around_[t[i]]) culprits->push_back(s.position);
            return worst;
          }
        }
        return worst;
    }
  }
  // v's neighbours among the placed triangles, and t's corners when given.
  uint32_t degree(uint32_t v, const Tri* t) const {
    neighbours_.clear();
    if (t)
      for (uint32_t w : *t)
        if (w != v) neighbours_.push_back(w);
    for (const Placed& s : around_[v])
      for (uint32_t w : s.t)
        if (w != v) neighbours_.push_back(w);
    std::sort(neighbours_.begin(), neighbours_.end());
    return static_cast<uint32_t>(std::unique(neighbours_.begin(), neighbours_.end()) - neighbours_.begin());
  }

  const Mesh& dt_;
  const ObjectiveTerms& d_;
  std::vector<std::vector<Placed>> around_;  // per vertex, its placed triangles
  std::vector<double> largest_;              // per placed triangle, the largest term so far
  mutable std::vector<uint32_t> neighbours_, frontier_, packed_;
  double below_ = 0;
};

}  // namespace

BranchAndBound branch_and_bound(const Mesh& dt, Objective o, const Candidates& cand, double known, uint64_t max_nodes,
                                uint64_t memo_words, const Progress& progress) {
  BranchAndBound r;
  r.value = known;
  TermPruning pruning(dt, objective_terms(o, dt), known, memo_words);
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
  r.complete = search_fills(dt, cand, hull, max_nodes, pruning, visit, progress, &r.nodes);
  return r;
}

}  // namespace hodt
