// Every objective written once, as local terms and how they combine
// (docs/objectives.md): a term per vertex (over its star), per edge (over its two
// triangles), or per triangle, combined by sum or max. evaluate_terms() and the
// region engine (region_model.hpp) read only this description, at every order:
// adding an objective means adding its terms here, not touching a solver.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "hodt/measures.hpp"
#include "hodt/mesh.hpp"
#include "hodt/objectives.hpp"
#include "hodt/progress.hpp"
#include "hodt/skeleton.hpp"
#include "objectives/pair_measures.hpp"

namespace hodt {

// Where an objective's terms live.
enum class TermSite : uint8_t {
  InteriorVertex,  // every vertex not on the convex hull
  Vertex,          // every vertex
  InteriorEdge,    // every edge with a triangle on each side
  Edge,            // every edge (hull edges have no right apex)
  Triangle,        // every triangle
  EdgePair,        // every pair of triangles sharing an edge (a max over pairs)
  VertexPair,      // every pair of triangles sharing a vertex (a max over pairs)
};

constexpr uint32_t kNoApex = UINT32_MAX;

// A vertex's star in one triangulation: its neighbours and its triangles, in any
// order (the terms do not depend on it). Only vertex-pair terms read the
// triangles; callers may leave them out for the other sites.
struct Star {
  uint32_t center;
  const uint32_t* neighbors;
  uint32_t degree;
  const Tri* triangles;  // counterclockwise
  uint32_t num_triangles;
  Star(uint32_t v, const std::vector<uint32_t>& nb, const std::vector<Tri>& tris)
      : Star(v, nb.data(), static_cast<uint32_t>(nb.size()), tris.data(), static_cast<uint32_t>(tris.size())) {}
  Star(uint32_t v, const uint32_t* nb, uint32_t d, const Tri* tris, uint32_t nt)
      : center(v), neighbors(nb), degree(d), triangles(tris), num_triangles(nt) {}
};

// The neighbours of v in triangles around it: sorted, each once.
void star_neighbors(uint32_t v, const std::vector<Tri>& triangles, std::vector<uint32_t>& out);

struct ObjectiveTerms {
  TermSite site;
  // Each term's value lies in [0, term_max] (INFINITY when unbounded): what a
  // relaxation may assume of a term it cannot tabulate.
  double term_max;
  // Exactly one of these is set, matching the site.
  double (*vertex)(const Mesh& points, const Star& star) = nullptr;
  // Edge u -> v with w the apex on its left and x on its right (kNoApex on the hull).
  double (*edge)(const Mesh& points, uint32_t u, uint32_t v, uint32_t w, uint32_t x) = nullptr;
  double (*triangle)(const Mesh& points, const Tri& t) = nullptr;
  // Pair sites: the measure of two triangles (symmetric), or any value <= cut
  // when the measure is at most cut (a max that already holds cut loses nothing,
  // and most pairs then need no accurate measure). cut = -INFINITY: the measure.
  double (*pair)(const Mesh& points, const Tri& s, const Tri& t, double cut) = nullptr;
  // Pair sites: which measure `pair` is (set from it by the table).
  PairMeasure measure = PairMeasure::None;
  // Optional, for vertex terms that read only which classes the neighbours fall
  // in (above, below or level with the vertex): the class of neighbour w of v
  // (< 32), and the term from the set of classes present, as a bit mask. A fan is
  // then summarised by one mask, and fans with equal masks are interchangeable.
  uint32_t (*neighbor_class)(const Mesh& points, uint32_t v, uint32_t w) = nullptr;
  double (*term_of_classes)(uint32_t mask) = nullptr;
  uint32_t classes = 0;  // how many classes there are (neighbor_class < classes)
  // Optional, for vertex terms that read only the vertex's class (convex,
  // concave, flat, mixed): the term of the class. A star's class over the
  // choices of its quads is then found once per vertex (neighbourhood_classes.hpp).
  double (*term_of_vertex_class)(VertexClass c) = nullptr;
  // Optional, for vertex terms over neighbour sets: drops from nb (v's
  // neighbours so far, sorted) those that cannot change v's term, whatever
  // neighbours come next, as long as every vertex of `fixed` (the ends of v's
  // fixed edges, at order k) is among them. Region engines keep what is left.
  void (*drop_neighbors)(const Mesh& points, uint32_t v, const std::vector<uint32_t>& fixed,
                         std::vector<uint32_t>& nb) = nullptr;
  // Optional, for vertex terms that read only how many neighbours v has: the
  // term of that number. A region's fan is then its count of new neighbours
  // (regions share only fixed edges, so counts add up).
  double (*term_of_degree)(uint32_t degree) = nullptr;
  // Optional: a bound on the optimum that every triangulation of the points
  // meets, from counts alone (every triangulation has as many edges as the
  // Delaunay one; an area ratio is at least 1): a result that meets it is
  // optimal at every order.
  double (*global_bound)(const Mesh& delaunay) = nullptr;
  // How the terms combine: the objective table's (info(o).combine).
  Combine combine = Combine::Sum;
  // Edge terms: whether they read the apexes at all (a length does not).
  bool edge_reads_apexes = true;
  // Measured within a domain (domain.hpp): the terms below read only inside
  // triangles, so vertex terms need their star's triangles, edge terms their
  // apexes, and the summaries above (classes, degree, dropped neighbours) are off.
  bool domain = false;
  // The terms without a domain, read within one for pieces every triangle of
  // which is inside in every triangulation read (objective_terms_inside): they
  // measure there what the domain measures.
  bool all_inside = false;
};

// The classes of v's neighbours in nb, as a bit mask (neighbor_class set).
uint32_t neighbor_classes(const ObjectiveTerms& d, const Mesh& points, uint32_t v, const std::vector<uint32_t>& nb);

// The description for triangulations of m's points (with or without its domain).
const ObjectiveTerms& objective_terms(Objective o, const Mesh& m);

// The terms without a domain (with every summary above), for m's points within a
// domain where a term's triangles are all inside whatever the triangulation:
// a vertex whose k-OD triangles are all inside (vertices_near_outside,
// domain.hpp) has the same term either way.
const ObjectiveTerms& objective_terms_inside(Objective o);

// The site a term is attached to: a vertex-pair term is a vertex's max over the
// pairs of its star, an edge-pair term an interior edge's pair.
inline bool vertex_site(TermSite s) {
  return s == TermSite::InteriorVertex || s == TermSite::Vertex || s == TermSite::VertexPair;
}
inline bool edge_site(TermSite s) {
  return s == TermSite::InteriorEdge || s == TermSite::Edge || s == TermSite::EdgePair;
}
inline bool interior_only(TermSite s) {
  return s == TermSite::InteriorVertex || s == TermSite::InteriorEdge || s == TermSite::EdgePair;
}

// Do vertex terms read the triangles of the star (not only the neighbours)?
inline bool reads_star_triangles(const ObjectiveTerms& d) { return d.site == TermSite::VertexPair || d.domain; }

// One vertex term (vertex sites; hull vertices of an interior site are not asked).
// cut: pair terms may answer anything <= cut when they are at most cut. With a
// domain the star's triangles must all be given: only inside ones are read.
double vertex_term(const ObjectiveTerms& d, const Mesh& points, const Star& star, double cut = -INFINITY);
// One edge term; x = kNoApex on the hull (only asked for the Edge site).
double edge_term(const ObjectiveTerms& d, const Mesh& points, uint32_t u, uint32_t v, uint32_t w, uint32_t x,
                 double cut = -INFINITY);
// One triangle term (0 for a triangle outside the domain).
double triangle_term(const ObjectiveTerms& d, const Mesh& points, const Tri& t);


// The objective's value on a triangulation, from its terms alone (progress: now
// and then, with the elements done; false cancels).
double evaluate_terms(Objective o, const Mesh& mesh, const Progress& progress = {});

}  // namespace hodt
