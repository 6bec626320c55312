#include "higher_order/regions/region_terms.hpp"

#include <algorithm>
#include <map>
#include <unordered_map>

#include "hodt/domain.hpp"
#include "higher_order/fills/fill_enumerator.hpp"

namespace hodt {

namespace {
// Entry headers: a vertex's fan (triangles or neighbours), an edge's apex.
constexpr uint32_t kVertexEntry = UINT32_MAX, kEdgeEntry = UINT32_MAX - 1;
constexpr uint32_t kMaxCanonicalClasses = 4;  // (a table of 2^4 x 2^4 masks)
}  // namespace

TermsAtVertex::TermsAtVertex(const Mesh& dt, const Regions& R, Objective o)
    : dt_(dt), domain_(objective_terms(o, dt)), inside_(domain_.domain ? objective_terms_inside(o) : domain_),
      near_(R.near_outside) {}

uint32_t TermsAtVertex::classes(uint32_t v, const std::vector<uint32_t>& nb, const std::vector<Tri>& triangles) const {
  uint32_t mask = neighbor_classes(inside_, dt_, v, nb);
  if (&at(v) != &inside_)
    for (const Tri& t : triangles)
      if (!triangle_inside(dt_, t)) return mask | outside_class();
  return mask;
}

uint32_t RegionTerms::triangle_classes(uint32_t v, const Tri& t) const {
  const ObjectiveTerms& plain = at_.inside();
  uint32_t mask = 0;
  for (uint32_t w : t)
    if (w != v) mask |= 1u << plain.neighbor_class(dt_, v, w);
  if (&at_.at(v) != &plain && !triangle_inside(dt_, t)) mask |= at_.outside_class();
  return mask;
}

uint32_t RegionTerms::canonical_classes(uint32_t v, uint32_t mask) const {
  if (canonical_.empty()) return mask;
  if (interior_only(d_.site) && on_hull_[v]) return fixed_classes_[v];  // (no term at all)
  return canonical_[fixed_classes_[v] * at_.masks() + mask];
}

// (The summaries below are of the terms without a domain: only the vertices
// that read those (TermsAtVertex) use them.)
RegionTerms::RegionTerms(const Mesh& dt, const Regions& R, Objective o, const Candidates* candidates)
    : dt_(dt), R_(R), cand_(candidates), at_(dt, R, o), d_(at_.domain()), sense_(info(o).sense),
      filter_(dt, R, at_.inside()) {
  const ObjectiveTerms& plain = at_.inside();
  const uint32_t n = dt.num_vertices();
  std::vector<uint32_t> count(n, 0), seen(n, UINT32_MAX);
  for (uint32_t r = 0; r < R.regions.size(); ++r) {
    if (R.regions[r].delaunay_triangles.size() < 2) continue;
    for (uint32_t t : R.regions[r].delaunay_triangles)
      for (uint32_t e = 3 * t; e < 3 * t + 3; ++e)
        if (seen[dt.triangles[e]] != r) seen[dt.triangles[e]] = r, ++count[dt.triangles[e]];
  }
  shared_.resize(n);
  for (uint32_t v = 0; v < n; ++v) shared_[v] = count[v] >= 2;
  on_hull_.assign(n, 0);
  for (uint32_t v : dt.hull) on_hull_[v] = 1;
  stars_ = build_stars(dt);
  if (reads_edges())
    for (uint32_t e = 0; e < dt.halfedges.size(); ++e)
      if (dt.halfedges[e] < 0 || R.fixed[e]) boundary_.emplace(edge_key(dt.origin(e), dt.target(e)), e);
  if (plain.neighbor_class && at_.masks() <= 1u << kMaxCanonicalClasses) {
    const uint32_t masks = at_.masks();
    fixed_classes_.resize(n);
    for (uint32_t v = 0; v < n; ++v)
      fixed_classes_[v] = static_cast<uint8_t>(neighbor_classes(plain, dt, v, filter_.fixed(v)));
    // (Within a domain: and the class outside, at the corners of a fixed
    // triangle outside, which is in every triangulation.)
    for (uint32_t t = 0; t < dt.num_triangles() && d_.domain; ++t)
      if (R.regions[R.region_of_triangle[t]].delaunay_triangles.size() == 1 && !triangle_inside(dt, base_triangle(dt, t)))
        for (uint32_t e = 3 * t; e < 3 * t + 3; ++e) fixed_classes_[dt.triangles[e]] |= static_cast<uint8_t>(at_.outside_class());
    // Masks a and b (both holding f) are alike when every m gives term(a | m) == term(b | m).
    auto alike = [&](uint32_t a, uint32_t b) {
      for (uint32_t m = 0; m < masks; ++m)
        if (at_.term_of_classes(a | m) != at_.term_of_classes(b | m)) return false;
      return true;
    };
    canonical_.resize(masks * masks);
    for (uint32_t f = 0; f < masks; ++f)
      for (uint32_t a = 0; a < masks; ++a) {
        uint32_t b = f;
        while ((b & f) != f || !alike(a | f, b)) ++b;  // (b = a | f ends it)
        canonical_[f * masks + a] = static_cast<uint8_t>(b);
      }
  }
  if (d_.combine == Combine::Max) {
    floor_ = fixed_edges_least(fixed_terms_max());
    if (d_.global_bound) floor_ = std::max(floor_, d_.global_bound(dt));
  }
  if (plain.term_of_degree && floor_ > 0) {
    useful_degree_.assign(n, 0);
    for (const auto& [a, b] : R.useful) ++useful_degree_[a], ++useful_degree_[b];
  }
  if (d_.site == TermSite::VertexPair && cand_ && floor_ > 0) {
    candidate_fan_.resize(n);
    for (const auto& [e, apexes] : *cand_)
      for (uint32_t x : apexes) {
        const Tri t = canonical_triangle({static_cast<uint32_t>(e >> 32), static_cast<uint32_t>(e), x});
        for (uint32_t c : t) candidate_fan_[c].push_back(t);
      }
    for (auto& f : candidate_fan_) {
      std::sort(f.begin(), f.end());
      f.erase(std::unique(f.begin(), f.end()), f.end());
    }
  }
}

bool RegionTerms::harmless(uint32_t v, const Tri& t) const {
  if (d_.site != TermSite::VertexPair) return false;
  const Tri c = canonical_triangle(t);
  if (d_.domain && !triangle_inside(dt_, c)) return true;  // (in no pair the domain measures)
  if (candidate_fan_.empty()) return false;
  const std::array<uint32_t, 4> key{v, c[0], c[1], c[2]};
  bool found = false;
  const std::span<const uint32_t> known = harmless_.find(key, found);
  if (found) return known[0] != 0;
  uint32_t ok = 1;
  for (const Tri& other : candidate_fan_[v])
    if (other != c && d_.pair(dt_, c, other, floor_) > floor_) {
      ok = 0;
      break;
    }
  harmless_.insert(key, {&ok, 1});
  return ok != 0;
}

double RegionTerms::fixed_edges_least(double at_least) const {
  double best = at_least;
  if (!reads_edges() || !cand_) return best;
  for (uint32_t e = 0; e < dt_.halfedges.size(); ++e) {
    const int32_t f = dt_.halfedges[e];
    if (!R_.fixed[e] || f < static_cast<int32_t>(e)) continue;  // (each interior fixed edge once)
    const uint32_t u = dt_.origin(e), v = dt_.target(e);
    const auto left = cand_->find(edge_key(u, v)), right = cand_->find(edge_key(v, u));
    if (left == cand_->end() || right == cand_->end()) continue;
    // The smallest term over the pairs of candidates; a term at most `best` (the
    // cut) cannot raise the bound, so the first one ends the search.
    double least = INFINITY;
    for (uint32_t w : left->second) {
      for (uint32_t x : right->second) {
        least = std::min(least, edge_term(d_, dt_, u, v, w, x, best));
        if (least <= best) break;
      }
      if (least <= best) break;
    }
    if (least > best) best = least;
  }
  return best;
}

double RegionTerms::fixed_terms_max() const {
  auto fixed = [&](uint32_t t) { return R_.regions[R_.region_of_triangle[t]].delaunay_triangles.size() == 1; };
  double m = 0;
  if (reads_triangles()) {
    for (uint32_t t = 0; t < dt_.num_triangles(); ++t)
      if (fixed(t)) m = std::max(m, triangle_term(d_, dt_, base_triangle(dt_, t)));
  } else if (reads_edges()) {
    for (uint32_t e = 0; e < dt_.halfedges.size(); ++e) {
      const int32_t f = dt_.halfedges[e];
      if (!fixed(e / 3) || (f >= 0 && (static_cast<uint32_t>(f) < e || !fixed(static_cast<uint32_t>(f) / 3)))) continue;
      if (f < 0 && interior_only(d_.site)) continue;
      m = std::max(m, edge_term(d_, dt_, dt_.origin(e), dt_.target(e), dt_.apex(e), f < 0 ? kNoApex : dt_.apex(static_cast<uint32_t>(f)), m));
    }
  } else {
    // Max vertex terms (degree, vertex pairs) never decrease as a star grows, and
    // every star has its vertex's fixed triangles and the ends of its fixed edges.
    for (uint32_t v = 0; v < dt_.num_vertices(); ++v) {
      if (interior_only(d_.site) && on_hull_[v]) continue;
      star_.clear();
      for (uint32_t j = stars_.tri_offset[v]; j < stars_.tri_offset[v + 1]; ++j)
        if (fixed(stars_.triangle[j])) star_.push_back(base_triangle(dt_, stars_.triangle[j]));
      m = std::max(m, vertex_term(d_, dt_, Star(v, filter_.fixed(v), star_), m));
    }
  }
  return m;
}

uint32_t RegionTerms::apex_kind(uint32_t a, uint32_t b, uint32_t w) const {
  if (!cand_) return w;
  auto [it, fresh] = kinds_.try_emplace(edge_key(a, b));
  auto& kinds = it->second;
  if (fresh) {
    const auto front = cand_->find(edge_key(a, b)), behind = cand_->find(edge_key(b, a));
    if (front != cand_->end() && behind != cand_->end()) {
      std::map<std::vector<double>, uint32_t> first;  // the terms for every front apex -> smallest apex
      std::vector<std::vector<double>> terms_of;
      for (uint32_t x : behind->second) {
        std::vector<double> terms;
        for (uint32_t f : front->second) terms.push_back(inside_edge(a, b, f, x));
        auto [k, fresh_kind] = first.try_emplace(terms, x);
        if (!fresh_kind) k->second = std::min(k->second, x);
        terms_of.push_back(std::move(terms));
      }
      for (size_t i = 0; i < behind->second.size(); ++i) kinds.push_back({behind->second[i], first[terms_of[i]]});
      std::sort(kinds.begin(), kinds.end());
    }
  }
  const auto k = std::lower_bound(kinds.begin(), kinds.end(), std::make_pair(w, 0u));
  return k != kinds.end() && k->first == w ? k->second : w;
}

void RegionTerms::extend_fan(uint32_t v, const Tri& t, uint32_t fresh, std::vector<uint32_t>& fan) const {
  const int i = t[0] == v ? 0 : t[1] == v ? 1 : 2;
  const uint32_t others[2] = {t[(i + 1) % 3], t[(i + 2) % 3]};
  if (reads_classes(v) || reads_degree(v)) {  // one word
    if (fan.empty()) fan.push_back(0);
    if (reads_classes(v))
      fan[0] = canonical_classes(v, fan[0] | triangle_classes(v, t));
    else if (degree_matters(v))
      fan[0] += fresh;
  } else if (reads_fans(v)) {  // triangles, three words each, sorted
    const Tri c = canonical_triangle(t);
    if (harmless(v, c)) return;
    size_t j = 0;
    while (j < fan.size() && Tri{fan[j], fan[j + 1], fan[j + 2]} < c) j += 3;
    fan.insert(fan.begin() + static_cast<std::ptrdiff_t>(j), c.begin(), c.end());
  } else {  // neighbours, sorted
    for (uint32_t w : others) {
      const auto it = std::lower_bound(fan.begin(), fan.end(), w);
      if (it == fan.end() || *it != w) fan.insert(it, w);
    }
    filter_.reduce(v, fan);
  }
}

double RegionTerms::fan_done(uint32_t r, uint32_t v, const std::vector<uint32_t>& fan, SignatureEntry& entry) const {
  if (reads_classes(v) || reads_degree(v)) return vertex_done(r, v, fan[0], entry);
  fan_.clear();
  if (!reads_fans(v)) return vertex_done(r, v, fan, fan_, entry);
  for (size_t j = 0; j < fan.size(); j += 3) fan_.push_back({fan[j], fan[j + 1], fan[j + 2]});
  star_neighbors(v, fan_, fan_nb_);
  return vertex_done(r, v, fan_nb_, fan_, entry);
}

double RegionTerms::vertex_done(uint32_t r, uint32_t v, const std::vector<uint32_t>& nb, const std::vector<Tri>& fan,
                                SignatureEntry& entry) const {
  entry.clear();
  if (!reads_vertices()) return 0;
  const ObjectiveTerms& d = at_.at(v);
  const bool fans = reads_fans(v);
  if (reads_classes(v)) return vertex_done(r, v, at_.classes(v, nb, fan), entry);
  if (reads_degree(v)) {
    const auto& f = filter_.fixed(v);
    const auto fixed = std::count_if(nb.begin(), nb.end(), [&](uint32_t w) { return std::binary_search(f.begin(), f.end(), w); });
    return vertex_done(r, v, degree_matters(v) ? static_cast<uint32_t>(nb.size() - static_cast<size_t>(fixed)) : 0, entry);
  }
  if (shared_[v]) {  // the regions beside see the triangles (vertex pairs) or the neighbours
    entry.push_back({kVertexEntry, v, fans ? 0u : 1u});
    if (fans) {  // canonical triangles, sorted
      for (const Tri& t : fan)
        if (!harmless(v, t)) entry.push_back(canonical_triangle(t));
      std::sort(entry.begin() + 1, entry.end());
    } else {
      nb_ = nb;
      filter_.reduce(v, nb_);
      for (uint32_t w : nb_) entry.push_back({w, 0, 0});
    }
    return 0;
  }
  if (interior_only(d_.site) && on_hull_[v]) return 0;
  // Its other triangles are fixed: the Delaunay ones outside this region.
  star_.clear();
  if (fans) star_ = fan;
  add_outside(r, v, star_);
  star_neighbors(v, star_, nb_);
  if (!fans) {  // add the region's neighbours (reduced: and the fixed ones, which they may leave out)
    nb_.insert(nb_.end(), nb.begin(), nb.end());
    if (filter_.active()) nb_.insert(nb_.end(), filter_.fixed(v).begin(), filter_.fixed(v).end());
    std::sort(nb_.begin(), nb_.end());
    nb_.erase(std::unique(nb_.begin(), nb_.end()), nb_.end());
  }
  return clip(vertex_term(d, dt_, Star(v, nb_, star_)));
}

double RegionTerms::vertex_done(uint32_t r, uint32_t v, uint32_t summary, SignatureEntry& entry) const {
  entry.clear();
  const ObjectiveTerms& plain = at_.inside();  // (summaries: only where nothing can be outside)
  if (reads_classes(v)) summary = canonical_classes(v, summary);
  if (shared_[v]) {  // the regions beside see the summary
    entry = {{kVertexEntry, v, 2}, {summary, 0, 0}};
    return 0;
  }
  if (interior_only(d_.site) && on_hull_[v]) return 0;
  star_.clear();
  add_outside(r, v, star_);
  star_neighbors(v, star_, nb_);
  if (reads_classes(v)) return clip(at_.term_of_classes(summary | at_.classes(v, nb_, star_)));
  // The fixed neighbours and those of the triangles outside, then the region's new ones.
  nb_.insert(nb_.end(), filter_.fixed(v).begin(), filter_.fixed(v).end());
  std::sort(nb_.begin(), nb_.end());
  nb_.erase(std::unique(nb_.begin(), nb_.end()), nb_.end());
  return clip(plain.term_of_degree(static_cast<uint32_t>(nb_.size()) + summary));
}

void RegionTerms::add_outside(uint32_t r, uint32_t v, std::vector<Tri>& star) const {
  for (uint32_t j = stars_.tri_offset[v]; j < stars_.tri_offset[v + 1]; ++j)
    if (R_.region_of_triangle[stars_.triangle[j]] != r) star.push_back(base_triangle(dt_, stars_.triangle[j]));
}

bool RegionTerms::on_boundary(uint32_t r, uint32_t u, uint32_t v) const {
  const auto it = boundary_.find(edge_key(u, v));
  return it != boundary_.end() && R_.region_of_triangle[it->second / 3] == r;
}

double RegionTerms::boundary_edge(uint32_t r, uint32_t u, uint32_t v, uint32_t w, SignatureEntry& entry) const {
  entry.clear();
  if (!reads_edges()) return 0;
  // The Delaunay halfedge u -> v on region r's boundary, and what lies beyond it.
  if (!on_boundary(r, u, v)) return 0;
  const int32_t f = dt_.halfedges[boundary_.at(edge_key(u, v))];
  if (f < 0) return interior_only(d_.site) ? 0 : clip(edge_term(d_, dt_, u, v, w, kNoApex));
  const uint32_t other = R_.region_of_triangle[static_cast<uint32_t>(f) / 3];
  if (R_.regions[other].delaunay_triangles.size() > 1 && reads_apexes()) {  // seen from the other side: the apex's kind
    entry = {{kEdgeEntry, u, v}, {apex_kind(v, u, w), 0, 0}};
    return 0;
  }
  return clip(edge_term(d_, dt_, u, v, w, dt_.apex(static_cast<uint32_t>(f))));
}

double RegionTerms::inside_edge(uint32_t u, uint32_t v, uint32_t w, uint32_t x) const {
  if (!reads_edges()) return 0;
  return clip(u < v ? edge_term(d_, dt_, u, v, w, x) : edge_term(d_, dt_, v, u, x, w));
}

Tri RegionTerms::vertex_item(uint32_t v) { return {kVertexEntry, v, 0}; }
Tri RegionTerms::edge_item(uint32_t u, uint32_t v) { return {kEdgeEntry, u, v}; }
Tri RegionTerms::item_of(const SignatureEntry& entry) {
  const Tri& h = entry[0];
  return h[0] == kVertexEntry ? vertex_item(h[1]) : h;
}

std::vector<Tri> RegionTerms::items(uint32_t r) const {
  std::vector<Tri> out;
  for (auto [u, v] : R_.regions[r].boundary) {
    if (reads_vertices() && shared_[u]) out.push_back(vertex_item(u));
    if (!reads_apexes()) continue;
    const int32_t f = dt_.halfedges[boundary_.at(edge_key(u, v))];
    if (f >= 0 && R_.regions[R_.region_of_triangle[static_cast<uint32_t>(f) / 3]].delaunay_triangles.size() > 1)
      out.push_back(edge_item(u, v));
  }
  // Shared vertices inside the region (touching a fixed edge that ends inside it).
  if (reads_vertices())
    for (const Tri& t : R_.regions[r].states[0])
      for (uint32_t v : t)
        if (shared_[v]) out.push_back(vertex_item(v));
  std::vector<Tri> seen;
  std::vector<Tri> unique;
  for (const Tri& i : out) {
    const auto it = std::lower_bound(seen.begin(), seen.end(), i);
    if (it != seen.end() && *it == i) continue;
    seen.insert(it, i);
    unique.push_back(i);
  }
  return unique;
}

StateKey RegionTerms::key(uint32_t r, const std::vector<Tri>& tris) const {
  StateKey key;
  SignatureEntry entry;
  auto take = [&](double term) {
    key.value = add(key.value, term);
    if (!entry.empty()) key.signature.push_back(std::move(entry)), entry.clear();
  };
  if (reads_vertices()) {
    std::vector<std::pair<uint32_t, uint32_t>> at;  // (vertex, triangle index)
    for (uint32_t i = 0; i < tris.size(); ++i)
      for (uint32_t v : tris[i]) at.push_back({v, i});
    std::sort(at.begin(), at.end());
    std::vector<Tri> fan;
    std::vector<uint32_t> nb;
    for (size_t i = 0; i < at.size();) {
      const uint32_t v = at[i].first;
      fan.clear();
      for (; i < at.size() && at[i].first == v; ++i) fan.push_back(tris[at[i].second]);
      star_neighbors(v, fan, nb);
      take(vertex_done(r, v, nb, fan, entry));
    }
  }
  if (reads_edges()) {
    std::unordered_map<uint64_t, uint32_t> apex;  // directed edge -> apex on its left
    for (const Tri& t : tris)
      for (int i = 0; i < 3; ++i) apex[edge_key(t[i], t[(i + 1) % 3])] = t[(i + 2) % 3];
    for (const Tri& t : tris)  // (in the triangles' order: sums come out the same everywhere)
      for (int i = 0; i < 3; ++i) {
        const uint32_t u = t[i], v = t[(i + 1) % 3], w = t[(i + 2) % 3];
        if (on_boundary(r, u, v)) take(boundary_edge(r, u, v, w, entry));  // (even with r beyond it)
        else if (u < v) take(inside_edge(u, v, w, apex.at(edge_key(v, u))));
      }
  }
  if (reads_triangles())
    for (const Tri& t : tris) take(triangle(t));
  std::sort(key.signature.begin(), key.signature.end());
  return key;
}

}  // namespace hodt
