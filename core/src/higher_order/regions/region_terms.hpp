// What one objective's terms (objective_terms.hpp) see of one region's
// triangulation. The terms the region alone decides (its triangles, the edges
// inside it or to fixed triangles, the vertices it shares with no other region
// that has a choice) combine into its value; what the regions beside it see (its
// fan at a shared vertex, its apex on an edge to another region with a choice)
// is its signature. Triangulations of a region with equal signatures are
// interchangeable for every other term, so only the best of each needs keeping:
// this keeps regions with millions of triangulations down to their interfaces.
//
// The same pieces serve a whole triangulation (key) and a fill built triangle by
// triangle (fill_dp.hpp), which meets each vertex and edge as it completes.
#pragma once
#include <array>
#include <unordered_map>
#include <vector>

#include "hodt/measures.hpp"
#include "containers/words_memo.hpp"
#include "higher_order/fills/fill_enumerator.hpp"
#include "higher_order/regions/neighbor_filter.hpp"
#include "higher_order/regions/regions.hpp"
#include "objectives/objective_terms.hpp"

namespace hodt {

// The terms the region engine reads at each vertex. Within a domain, a vertex
// none of whose k-OD triangles can be outside (Regions::near_outside) has its
// whole star inside in every k-OD triangulation, so its term is the one without
// a domain: it reads those terms, and with them the summaries that see only its
// neighbours (their classes, their count, the neighbours that can change the
// term). Only the vertices beside a triangle that may be outside read the
// domain's terms, over their triangles; but interior-vertex terms over
// neighbour classes read classes there too, with one more: a triangle outside,
// which leaves the vertex uncounted whatever its neighbours. (Without a domain:
// the same terms everywhere.)
class TermsAtVertex {
 public:
  TermsAtVertex(const Mesh& delaunay, const Regions& regions, Objective o);  // (regions must outlive this)
  const ObjectiveTerms& at(uint32_t v) const {
    return !domain_.domain || (!near_.empty() && !near_[v]) ? inside_ : domain_;
  }
  const ObjectiveTerms& domain() const { return domain_; }  // (the domain's: every vertex may read them)
  const ObjectiveTerms& inside() const { return inside_; }  // (what at() gives where nothing can be outside)
  // Is v's fan read as a mask of classes (ObjectiveTerms::neighbor_class)?
  bool by_classes(uint32_t v) const {
    return inside_.neighbor_class && (&at(v) == &inside_ || inside_.site == TermSite::InteriorVertex);
  }
  // The mask of a fan at v: its neighbours' classes, and the class outside_class()
  // when one of its triangles is outside.
  uint32_t classes(uint32_t v, const std::vector<uint32_t>& nb, const std::vector<Tri>& triangles) const;
  uint32_t outside_class() const { return 1u << inside_.classes; }
  uint32_t masks() const { return outside_class() << (domain_.domain ? 1 : 0); }  // (masks are below this)
  // The term of a whole star's mask (0 with a triangle outside).
  double term_of_classes(uint32_t mask) const { return mask & outside_class() ? 0 : inside_.term_of_classes(mask); }

 private:
  const Mesh& dt_;
  const ObjectiveTerms& domain_;
  const ObjectiveTerms& inside_;
  const std::vector<uint8_t>& near_;
};

// A signature is a sorted list of entries, each a header (what it is about)
// followed by what the neighbours see.
using SignatureEntry = std::vector<Tri>;

struct StateKey {
  std::vector<SignatureEntry> signature;  // sorted
  double value = 0;
};

class RegionTerms {
 public:
  // `regions` and `candidates` (k_order_candidates, for apex kinds) must outlive this.
  RegionTerms(const Mesh& delaunay, const Regions& regions, Objective o, const Candidates* candidates = nullptr);

  const ObjectiveTerms& terms() const { return d_; }
  const Regions& regions() const { return R_; }
  bool better(double a, double b) const { return hodt::better(sense_, a, b); }
  double add(double value, double term) const { return combine(d_.combine, value, term); }
  // Which pieces of a triangulation the terms read.
  bool reads_vertices() const { return vertex_site(d_.site); }
  // At vertex v (TermsAtVertex): its fan's triangles, else its neighbours suffice.
  bool reads_fans(uint32_t v) const { return reads_star_triangles(at_.at(v)); }
  bool reads_edges() const { return edge_site(d_.site); }
  bool reads_apexes() const { return reads_edges() && d_.edge_reads_apexes; }
  bool reads_triangles() const { return d_.site == TermSite::Triangle; }
  // Vertex terms at v that read only the classes of the neighbours: a fan is its mask.
  bool reads_classes(uint32_t v) const { return at_.by_classes(v); }
  // The classes triangle t adds to v's fan (TermsAtVertex::classes).
  uint32_t triangle_classes(uint32_t v, const Tri& t) const;
  // The smallest class mask that no neighbours can tell from `mask` at v: with
  // the classes of v's fixed neighbours (present in every triangulation), masks
  // that give the same term whatever classes join them are one state. (A vertex
  // that already has a lower neighbour over a fixed edge is no minimum, whatever
  // a region does: its fans are all alike.)
  uint32_t canonical_classes(uint32_t v, uint32_t mask) const;
  // Vertex terms at v that read only the degree: a fan is its number of
  // neighbours over edges that are not fixed.
  bool reads_degree(uint32_t v) const { return at_.at(v).term_of_degree != nullptr; }
  // ... and whether v's term can exceed the floor at all (else its count is not kept).
  bool degree_matters(uint32_t v) const {
    return useful_degree_.empty() || at_.inside().term_of_degree(useful_degree_[v]) > floor_;
  }

  // A vertex's fan as a growing fill keeps it (fill_dp.hpp), in words: its
  // neighbours' class mask, its count of new neighbours, the neighbours or the
  // triangles that can change its term. t joins v's fan, drawing `fresh` of v's
  // two sides in t first (the others closed a side already drawn).
  void extend_fan(uint32_t v, const Tri& t, uint32_t fresh, std::vector<uint32_t>& fan) const;
  // v's fan (as extend_fan keeps it) in region r is complete: its term, or its
  // signature entry, as vertex_done below.
  double fan_done(uint32_t r, uint32_t v, const std::vector<uint32_t>& fan, SignatureEntry& entry) const;

  // Vertex v's fan in region r is complete: nb its neighbours there (sorted),
  // fan its triangles there (read only when reads_fans(v)). Returns its term (0 if
  // none), or sets `entry` (else left empty) when other regions see the fan.
  double vertex_done(uint32_t r, uint32_t v, const std::vector<uint32_t>& nb, const std::vector<Tri>& fan,
                     SignatureEntry& entry) const;
  // The same for a fan summarised by one number: the classes of its neighbours
  // (reads_classes(v)) or how many of them are not fixed (reads_degree(v)).
  double vertex_done(uint32_t r, uint32_t v, uint32_t summary, SignatureEntry& entry) const;
  // Is u -> v a boundary edge of region r (r on its left)? (Edge terms only.)
  bool on_boundary(uint32_t r, uint32_t u, uint32_t v) const;
  // Boundary edge u -> v of region r (r on its left) is covered by triangle u v w.
  double boundary_edge(uint32_t r, uint32_t u, uint32_t v, uint32_t w, SignatureEntry& entry) const;
  // Edge u -> v inside a region: w the apex on its left, x on its right.
  double inside_edge(uint32_t u, uint32_t v, uint32_t w, uint32_t x) const;
  double triangle(const Tri& t) const { return clip(triangle_term(d_, dt_, t)); }
  // With apexes: the apex that stands for w behind edge a -> b (on its right).
  // Apexes whose edge terms agree for every candidate apex in front of a -> b
  // are interchangeable; each kind is named by its smallest apex.
  uint32_t apex_kind(uint32_t a, uint32_t b, uint32_t w) const;
  // Vertex-pair terms: does every pair of t (at v) with another k-OD triangle at
  // v measure at most floor()? Then no term reads t above the floor, and fans
  // need not keep it (in fills, signatures and vertex_done alike).
  bool harmless(uint32_t v, const Tri& t) const;
  // Min-max objectives: a bound on the optimum from what every triangulation
  // has: the largest term that no region can change, each fixed edge's smallest
  // possible term, and the objective's global bound. Every term is read as at
  // least this (clip): the same optima, and far fewer apexes and signatures to
  // tell apart.
  double floor() const { return floor_; }

  // A whole triangulation of region r (counterclockwise triangles).
  StateKey key(uint32_t r, const std::vector<Tri>& triangulation) const;

  // The items a signature speaks of: a shared vertex, or a boundary edge (region
  // on its left) whose apex the region beside sees. Each entry is about one item.
  static Tri vertex_item(uint32_t v);
  static Tri edge_item(uint32_t u, uint32_t v);
  static Tri item_of(const SignatureEntry& entry);
  // The items region r's signatures may have entries for, in boundary order
  // (neighbours along the boundary stay close), sorted by nothing else.
  std::vector<Tri> items(uint32_t r) const;

 private:
  double clip(double term) const { return d_.combine == Combine::Max && term < floor_ ? floor_ : term; }
  double fixed_terms_max() const;
  // Edge terms: every fixed edge is in every triangulation, with one candidate
  // triangle on each side: the largest over fixed edges of the smallest term its
  // candidates allow, or at_least if that is larger.
  double fixed_edges_least(double at_least) const;
  // Appends v's Delaunay triangles outside region r (fixed, when v is not shared).
  void add_outside(uint32_t r, uint32_t v, std::vector<Tri>& star) const;

  const Mesh& dt_;
  const Regions& R_;
  const Candidates* cand_;
  double floor_ = 0;
  mutable std::unordered_map<uint64_t, std::vector<std::pair<uint32_t, uint32_t>>> kinds_;  // edge -> (apex, kind)
  const TermsAtVertex at_;
  const ObjectiveTerms& d_;  // (the domain's, or the plain ones without a domain)
  Sense sense_;
  std::vector<uint8_t> shared_;  // per vertex: in two regions that may have a choice
  std::vector<uint8_t> on_hull_;
  Stars stars_;
  std::unordered_map<uint64_t, uint32_t> boundary_;  // fixed or hull halfedges by (origin, target)
  NeighborFilter filter_;
  std::vector<uint8_t> fixed_classes_;   // per vertex: its fixed neighbours' class mask (small class counts)
  std::vector<uint8_t> canonical_;       // [fixed mask][mask] -> canonical mask, class counts up to 4
  std::vector<uint32_t> useful_degree_;  // per vertex: its useful edges, the most neighbours it can have
  std::vector<std::vector<Tri>> candidate_fan_;  // per vertex: its k-OD triangles (vertex pairs, with a floor)
  mutable WordsMemo harmless_;  // (v, triangle) -> harmless (1 word)
  mutable std::vector<Tri> star_, fan_;
  mutable std::vector<uint32_t> nb_, fan_nb_;
};

}  // namespace hodt
