#include "higher_order/search/threshold_sat.hpp"

#include <algorithm>
#include <cmath>

#include "engines/cdcl.hpp"
#include "higher_order/search/branch_and_bound.hpp"
#include "mesh/mesh_of.hpp"
#include "objectives/objective_terms.hpp"

namespace hodt {

bool threshold_sat_applies(Objective o, const Mesh& dt) { return branch_and_bound_applies(o, dt); }

namespace {

// A triangle packed with its corners counterclockwise, the smallest first, so
// that each candidate has one key (the corners fit 21 bits: callers keep the
// input small).
uint64_t pack(uint32_t a, uint32_t b, uint32_t c) { return uint64_t(a) << 42 | uint64_t(b) << 21 | c; }
Tri unpack(uint64_t k) {
  constexpr uint64_t m = (uint64_t{1} << 21) - 1;
  return {static_cast<uint32_t>(k >> 42), static_cast<uint32_t>(k >> 21 & m), static_cast<uint32_t>(k & m)};
}
uint64_t canonical(uint32_t a, uint32_t b, uint32_t c) {
  if (b < a && b < c) return pack(b, c, a);
  if (c < a && c < b) return pack(c, a, b);
  return pack(a, b, c);
}

template <class T>
uint32_t index_of(const std::vector<T>& sorted, T key) {
  return static_cast<uint32_t>(std::lower_bound(sorted.begin(), sorted.end(), key) - sorted.begin());
}

class Encoding {
 public:
  Encoding(const Mesh& dt, const ObjectiveTerms& d, const Candidates& cand, const Progress& progress)
      : dt_(dt), d_(d), progress_(progress) {
    for (const auto& [key, apexes] : cand)
      for (uint32_t w : apexes) keys_.push_back(canonical(static_cast<uint32_t>(key >> 32), static_cast<uint32_t>(key), w));
    std::sort(keys_.begin(), keys_.end());
    keys_.erase(std::unique(keys_.begin(), keys_.end()), keys_.end());
    for (uint64_t k : keys_) tris_.push_back(unpack(k));
    for (const Tri& t : tris_)
      for (uint32_t i = 0; i < 3; ++i) edges_.push_back(undirected(t[i], t[(i + 1) % 3]));
    std::sort(edges_.begin(), edges_.end());
    edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
    for (size_t i = 0; i < tris_.size() + edges_.size(); ++i) sat_.add_var();
    sides_.resize(2 * edges_.size());
    for (uint32_t t = 0; t < tris_.size(); ++t)
      for (uint32_t i = 0; i < 3; ++i) {
        const uint32_t a = tris_[t][i], b = tris_[t][(i + 1) % 3];
        const uint32_t e = index_of(edges_, undirected(a, b));
        sides_[2 * e + (a < b ? 0 : 1)].push_back(t);  // (0: the triangle is left of lo -> hi)
        sat_.add_clause({Cdcl::lit(t, false), edge_lit(e, true)});
      }
    cover();
    forbid_crossings();
    if (d_.site == TermSite::EdgePair)
      for (uint32_t e = 0; e < edges_.size(); ++e)
        for (uint32_t s : sides_[2 * e])
          for (uint32_t t : sides_[2 * e + 1]) pending_pairs_.push_back({s, t});
    if (d_.site == TermSite::VertexPair) list_vertex_pairs();
    if (d_.site == TermSite::Triangle)
      for (uint32_t t = 0; t < tris_.size(); ++t) pending_tris_.push_back(t);
    if (d_.site == TermSite::Vertex) {
      at_vertex_.resize(dt.num_vertices());
      for (uint32_t e = 0; e < edges_.size(); ++e)
        at_vertex_[edges_[e] >> 32].push_back(e), at_vertex_[static_cast<uint32_t>(edges_[e])].push_back(e);
    }
  }

  bool valid() const { return valid_; }

  // The solver's decisions try m's triangles and edges first (those of m
  // that are not candidates are not variables).
  void prefer(const Mesh& m) {
    for (uint32_t t = 0; t < m.num_triangles(); ++t) {
      const uint32_t* c = &m.triangles[3 * size_t(t)];
      const uint64_t key = canonical(c[0], c[1], c[2]);
      const uint32_t i = index_of(keys_, key);
      if (i == keys_.size() || keys_[i] != key) continue;
      sat_.prefer(i, true);
      for (uint32_t j = 0; j < 3; ++j) {
        const uint64_t e = undirected(c[j], c[(j + 1) % 3]);
        sat_.prefer(static_cast<uint32_t>(tris_.size()) + index_of(edges_, e), true);
      }
    }
  }

  // Adds the clauses of every term above `below` (the largest double under the
  // threshold): each pending triangle, pair or degree is measured once more,
  // and stays pending while below it (thresholds only go down).
  void tighten(double below) {
    WorkCounter work;
    size_t kept = 0;
    for (uint32_t t : pending_tris_) {
      if (work.tick()) report(progress_, 0, 1);
      if (d_.triangle(dt_, tris_[t]) > below) sat_.add_clause({Cdcl::lit(t, false)});
      else pending_tris_[kept++] = t;
    }
    pending_tris_.resize(kept);
    kept = 0;
    for (const auto& [s, t] : pending_pairs_) {
      if (work.tick(4)) report(progress_, 0, 1);
      if (d_.pair(dt_, tris_[s], tris_[t], below) > below) sat_.add_clause({Cdcl::lit(s, false), Cdcl::lit(t, false)});
      else pending_pairs_[kept++] = {s, t};
    }
    pending_pairs_.resize(kept);
    if (d_.site == TermSite::Vertex) limit_degrees(below);
  }

  SatAnswer ask(uint64_t max_conflicts, uint64_t max_work) { return sat_.solve(max_conflicts, progress_, max_work); }
  uint64_t conflicts() const { return sat_.conflicts(); }
  uint64_t work() const { return sat_.work(); }
  size_t clauses() const { return sat_.num_clauses(); }

  // The model's triangles.
  std::vector<Tri> model() const {
    std::vector<Tri> used;
    for (uint32_t t = 0; t < tris_.size(); ++t)
      if (sat_.value(t)) used.push_back(tris_[t]);
    return used;
  }

 private:
  static uint64_t undirected(uint32_t a, uint32_t b) { return a < b ? uint64_t(a) << 32 | b : uint64_t(b) << 32 | a; }
  uint32_t edge_lit(uint32_t e, bool b) const { return Cdcl::lit(static_cast<uint32_t>(tris_.size()) + e, b); }

  // Hull edges are used; a used edge has one triangle on each side (one on the
  // hull: nothing lies outside it, so its outer side has no candidate).
  void cover() {
    std::vector<uint8_t> on_hull(edges_.size(), 0);
    for (size_t i = 0; i < dt_.hull.size(); ++i) {
      const uint64_t h = undirected(dt_.hull[i], dt_.hull[(i + 1) % dt_.hull.size()]);
      const uint32_t e = index_of(edges_, h);
      if (e == edges_.size() || edges_[e] != h) {
        valid_ = false;  // (no candidate has a hull edge: the candidates are not all)
        return;
      }
      on_hull[e] = 1;
      sat_.add_clause({edge_lit(e, true)});
    }
    std::vector<uint32_t> clause;
    for (uint32_t e = 0; e < edges_.size(); ++e)
      for (uint32_t side = 0; side < 2; ++side) {
        const std::vector<uint32_t>& ts = sides_[2 * e + side];
        if (on_hull[e] && ts.empty()) continue;
        clause.assign(1, edge_lit(e, false));
        for (uint32_t t : ts) clause.push_back(Cdcl::lit(t, true));
        sat_.add_clause(clause);
        for (size_t i = 0; i < ts.size(); ++i)
          for (size_t j = i + 1; j < ts.size(); ++j) sat_.add_clause({Cdcl::lit(ts[i], false), Cdcl::lit(ts[j], false)});
      }
  }

  // A sweep in x: edges sorted by their left end, each tested against those
  // that start before it ends.
  void forbid_crossings() {
    std::vector<std::pair<double, uint32_t>> by_x;
    std::vector<double> right(edges_.size());
    for (uint32_t e = 0; e < edges_.size(); ++e) {
      const double xa = dt_.point(static_cast<uint32_t>(edges_[e] >> 32))[0];
      const double xb = dt_.point(static_cast<uint32_t>(edges_[e]))[0];
      by_x.push_back({std::min(xa, xb), e});
      right[e] = std::max(xa, xb);
    }
    std::sort(by_x.begin(), by_x.end());
    WorkCounter work;
    for (size_t i = 0; i < by_x.size(); ++i) {
      const uint32_t e = by_x[i].second;
      const uint32_t a = static_cast<uint32_t>(edges_[e] >> 32), b = static_cast<uint32_t>(edges_[e]);
      for (size_t j = i + 1; j < by_x.size() && by_x[j].first <= right[e]; ++j) {
        if (work.tick()) report(progress_, static_cast<double>(i), static_cast<double>(by_x.size()));
        const uint32_t f = by_x[j].second;
        if (segments_cross(dt_, a, b, static_cast<uint32_t>(edges_[f] >> 32), static_cast<uint32_t>(edges_[f])))
          sat_.add_clause({edge_lit(e, false), edge_lit(f, false)});
      }
    }
  }

  // Each pair of candidates sharing a vertex, once (at the smallest corner
  // they share), but those on one side of an edge: they cannot both be used.
  void list_vertex_pairs() {
    std::vector<std::vector<uint32_t>> around(dt_.num_vertices());
    for (uint32_t t = 0; t < tris_.size(); ++t)
      for (uint32_t v : tris_[t]) around[v].push_back(t);
    const auto has = [](const Tri& t, uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; };
    for (uint32_t v = 0; v < around.size(); ++v)
      for (size_t i = 0; i < around[v].size(); ++i)
        for (size_t j = i + 1; j < around[v].size(); ++j) {
          const Tri &s = tris_[around[v][i]], &t = tris_[around[v][j]];
          bool first = true, same_side = false;
          for (uint32_t c = 0; c < 3; ++c) {
            const uint32_t w = s[c], x = s[(c + 1) % 3];
            if (w < v && has(t, w)) first = false;
            // (Both counterclockwise: sharing w -> x in the same direction puts them on one side.)
            for (uint32_t r = 0; r < 3; ++r)
              if (t[r] == w && t[(r + 1) % 3] == x) same_side = true;
          }
          if (first && !same_side) pending_pairs_.push_back({around[v][i], around[v][j]});
        }
  }

  // At each vertex, fewer used edges than the least degree whose term is above
  // `below`: Sinz's sequential counter over the vertex's edges, built at the
  // first limit, its registers saying "at least j of the first i edges are
  // used" (forced true when they are); each lower limit a few more clauses
  // over the same registers.
  void limit_degrees(double below) {
    size_t most = 0;  // (no vertex has more edges: a degree above it needs no clause)
    for (const std::vector<uint32_t>& es : at_vertex_) most = std::max(most, es.size());
    uint32_t degree = 0;  // the least degree whose term is above below
    while (degree <= most && !(d_.term_of_degree(degree) > below)) ++degree;
    if (degree > most || degree >= limit_) return;
    limit_ = degree;
    if (counters_.empty()) {
      counters_.resize(at_vertex_.size());
      width_ = degree > 0 ? degree - 1 : 0;
    }
    const uint32_t w = width_;
    for (uint32_t v = 0; v < at_vertex_.size(); ++v) {
      const std::vector<uint32_t>& es = at_vertex_[v];
      if (es.size() < degree) continue;
      if (degree <= 1) {  // (no edge at all)
        for (uint32_t e : es) sat_.add_clause({edge_lit(e, false)});
        continue;
      }
      std::vector<uint32_t>& s = counters_[v];  // s[i * w + j - 1]: at least j of edges 0 .. i
      if (s.empty()) {
        s.resize(es.size() * w);
        for (uint32_t& r : s) r = sat_.add_var();
        for (uint32_t i = 0; i < es.size(); ++i)
          for (uint32_t j = 1; j <= w; ++j) {
            const uint32_t out = Cdcl::lit(s[i * w + j - 1], true);
            if (j == 1) sat_.add_clause({edge_lit(es[i], false), out});
            if (i == 0) continue;
            sat_.add_clause({Cdcl::lit(s[(i - 1) * w + j - 1], false), out});
            if (j > 1) sat_.add_clause({edge_lit(es[i], false), Cdcl::lit(s[(i - 1) * w + j - 2], false), out});
          }
      }
      // Edge i is not used once degree - 1 of the edges before it are.
      for (uint32_t i = 1; i < es.size(); ++i)
        sat_.add_clause({edge_lit(es[i], false), Cdcl::lit(s[(i - 1) * w + degree - 2], false)});
    }
  }

  const Mesh& dt_;
  const ObjectiveTerms& d_;
  const Progress& progress_;
  Cdcl sat_;
  bool valid_ = true;
  std::vector<uint64_t> keys_, edges_;  // edges: lo << 32 | hi
  std::vector<Tri> tris_;
  std::vector<std::vector<uint32_t>> sides_;  // per edge, the triangles left of lo -> hi, then right
  std::vector<uint32_t> pending_tris_;
  std::vector<std::pair<uint32_t, uint32_t>> pending_pairs_;
  std::vector<std::vector<uint32_t>> at_vertex_, counters_;
  uint32_t limit_ = UINT32_MAX, width_ = 0;  // the least degree forbidden; the counters' registers per edge
};

}  // namespace

ThresholdSat threshold_sat(const Mesh& dt, Objective o, const Candidates& cand, double known, uint64_t max_conflicts,
                           uint64_t max_work, const Progress& progress, const Mesh* start) {
  ThresholdSat r;
  r.value = known;
  if (dt.num_vertices() > (uint32_t{1} << 21)) return r;  // (a triangle's key packs its corners)
  Encoding enc(dt, objective_terms(o, dt), cand, progress);
  if (!enc.valid()) return r;
  if (start) enc.prefer(*start);
  while (enc.conflicts() < max_conflicts && enc.work() < max_work) {
    enc.tighten(std::nextafter(r.value, -INFINITY));
    if (enc.work() >= max_work) break;  // (the new clauses' propagation spent it)
    ++r.questions;
    const SatAnswer a = enc.ask(max_conflicts - enc.conflicts(), max_work - enc.work());
    r.clauses = enc.clauses();
    if (a == SatAnswer::Unsatisfiable) r.complete = true;
    if (a != SatAnswer::Satisfiable) break;
    std::vector<Tri> tris = enc.model();
    if (tris.size() != dt.num_triangles()) break;  // (never: a model is a triangulation)
    Mesh m = mesh_of(dt.coords, tris);
    const double v = evaluate(o, m);
    if (!(v < r.value)) break;  // (never: its terms are below the threshold)
    r.found = std::move(m), r.value = v;
  }
  r.conflicts = enc.conflicts();
  r.work = enc.work();
  return r;
}

}  // namespace hodt
