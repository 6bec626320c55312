#include "objectives/objective_terms.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "hodt/domain.hpp"
#include "hodt/measures.hpp"
#include "geometry/exact_sum.hpp"
#include "objectives/mean_area.hpp"
#include "objectives/pair_measures.hpp"
#include "objectives/star_cone.hpp"

namespace hodt {

namespace {

// Neighbour points of a star, for the exact vertex tests (one buffer per
// thread: the terms run once per vertex).
struct NeighborPoints {
  std::vector<const double*>& p;
  NeighborPoints(const Mesh& m, const Star& s) : p(buffer()) {
    p.clear();
    for (uint32_t i = 0; i < s.degree; ++i) p.push_back(m.point(s.neighbors[i]));
  }
  uint32_t size() const { return static_cast<uint32_t>(p.size()); }
  static std::vector<const double*>& buffer() {
    static thread_local std::vector<const double*> b;
    return b;
  }
};

double is_class(const Mesh& m, const Star& s, VertexClass c) {
  // A region engine's reduced star (drop_neighbors) ends with marks for sides known empty.
  uint32_t d = s.degree;
  bool no_plane_below = false, no_plane_above = false;
  for (; d > 0 && s.neighbors[d - 1] >= kNoPlaneAbove; --d)
    (s.neighbors[d - 1] == kNoPlaneBelow ? no_plane_below : no_plane_above) = true;
  const NeighborPoints nb(m, Star(s.center, s.neighbors, d, s.triangles, s.num_triangles));
  return vertex_class(m.point(s.center), nb.p.data(), nb.size(), no_plane_below, no_plane_above) == c;
}

double convex_vertex(const Mesh& m, const Star& s) { return is_class(m, s, kConvex); }
double mixed_vertex(const Mesh& m, const Star& s) { return is_class(m, s, kMixed); }
double convex_of_class(VertexClass c) { return c == kConvex; }
double mixed_of_class(VertexClass c) { return c == kMixed; }
// The class depends on the planes through v with every neighbour below, and
// with every neighbour above (star_cone.hpp): keep what defines them. A vertex
// with no plane below is not convex, whatever comes: its mark is all it keeps.
void convex_drop_neighbors(const Mesh& m, uint32_t v, const std::vector<uint32_t>& fixed, std::vector<uint32_t>& nb) {
  if (nb.empty() || nb.back() != kNoPlaneBelow) drop_implied_neighbors(m, v, fixed, nb, {StarSide::Below, StarSide::Above});
  if (!nb.empty() && nb.back() == kNoPlaneBelow) nb.assign(1, kNoPlaneBelow);
}
void mixed_drop_neighbors(const Mesh& m, uint32_t v, const std::vector<uint32_t>& fixed, std::vector<uint32_t>& nb) {
  drop_implied_neighbors(m, v, fixed, nb, {StarSide::Below, StarSide::Above});
}
double local_minimum(const Mesh& m, const Star& s) {
  const NeighborPoints nb(m, s);
  return extremum(m.point(s.center), nb.p.data(), nb.size()) == kLocalMinimum;
}
double local_extremum(const Mesh& m, const Star& s) {
  const NeighborPoints nb(m, s);
  return extremum(m.point(s.center), nb.p.data(), nb.size()) != kNotExtremum;
}
// Neighbour classes for the extremum terms: above, below, level (bits 1, 2, 4).
uint32_t height_class(const Mesh& m, uint32_t v, uint32_t w) {
  const double zv = m.point(v)[2], zw = m.point(w)[2];
  return zw > zv ? 0 : zw < zv ? 1 : 2;
}
double minimum_of_classes(uint32_t mask) { return mask == 1; }
double extremum_of_classes(uint32_t mask) { return mask == 1 || mask == 2; }

double degree(const Mesh&, const Star& s) { return static_cast<double>(s.degree); }
double degree_term(uint32_t d) { return static_cast<double>(d); }
// The largest triangle is at least the mean (mean_area.hpp), in the area's unit
// (triangle_area: squared plane units).
double area_bound(const Mesh& m) { return mean_triangle_area_below(m); }
// A ratio of two areas is at least 1, and there is a pair once there are two triangles.
double ratio_bound(const Mesh& m) { return m.num_triangles() >= 2 ? 1 : 0; }
// The largest degree is at least the mean, 2E / n (E: the edges, the same in
// every triangulation of the points).
double degree_bound(const Mesh& m) {
  uint64_t edges = 0;
  for (uint32_t e = 0; e < m.halfedges.size(); ++e) edges += m.halfedges[e] < static_cast<int32_t>(e);
  const uint64_t n = m.num_vertices();
  return n ? static_cast<double>((2 * edges + n - 1) / n) : 0;
}

double convex_edge(const Mesh& m, uint32_t u, uint32_t v, uint32_t w, uint32_t x) {
  return edge_shape(m.point(u), m.point(v), m.point(w), m.point(x)) == kConvexEdge;
}
double length(const Mesh& m, uint32_t u, uint32_t v, uint32_t, uint32_t) { return edge_length(m.point(u), m.point(v)); }
double area(const Mesh& m, const Tri& t) { return triangle_area(m.point(t[0]), m.point(t[1]), m.point(t[2])); }

constexpr double kCount = 1, kUnbounded = INFINITY;

// The cut-aware pair measures (pair_measures.hpp), as plain functions.
double pair_area_ratio_above(const Mesh& m, const Tri& s, const Tri& t, double cut) { return pair_area_ratio(m, s, t, cut); }
double pair_normal_angle_above(const Mesh& m, const Tri& s, const Tri& t, double cut) { return pair_normal_angle(m, s, t, cut); }
double pair_enclosing_circle_above(const Mesh& m, const Tri& s, const Tri& t, double cut) {
  return pair_enclosing_circle(m, s, t, cut);
}
using PairFunction = double (*)(const Mesh&, const Tri&, const Tri&, double);
PairFunction pair_function(PairMeasure p) {
  switch (p) {
    case PairMeasure::AreaRatio: return pair_area_ratio_above;
    case PairMeasure::NormalAngle: return pair_normal_angle_above;
    case PairMeasure::EnclosingCircle: return pair_enclosing_circle_above;
    case PairMeasure::None: break;
  }
  return nullptr;
}

std::array<ObjectiveTerms, kNumObjectives> make_table() {
  using S = TermSite;
  std::array<ObjectiveTerms, kNumObjectives> t{};
  auto set = [&](Objective o, ObjectiveTerms d) {
    d.combine = info(o).combine;
    d.pair = pair_function(d.measure);
    t[static_cast<size_t>(o)] = d;
  };
  auto pairs = [](TermSite site, PairMeasure measure) {
    ObjectiveTerms d{site, kUnbounded};
    d.measure = measure;
    return d;
  };
  ObjectiveTerms convex{S::InteriorVertex, kCount, convex_vertex};
  convex.term_of_vertex_class = convex_of_class, convex.drop_neighbors = convex_drop_neighbors;
  set(Objective::MaxConvexVertices, convex);
  ObjectiveTerms mixed{S::InteriorVertex, kCount, mixed_vertex};
  mixed.term_of_vertex_class = mixed_of_class, mixed.drop_neighbors = mixed_drop_neighbors;
  set(Objective::MinMixedVertices, mixed);
  ObjectiveTerms minima{S::InteriorVertex, kCount, local_minimum};
  minima.neighbor_class = height_class, minima.term_of_classes = minimum_of_classes, minima.classes = 3;
  set(Objective::MinLocalMinima, minima);
  ObjectiveTerms extrema{S::InteriorVertex, kCount, local_extremum};
  extrema.neighbor_class = height_class, extrema.term_of_classes = extremum_of_classes, extrema.classes = 3;
  set(Objective::MinLocalExtrema, extrema);
  ObjectiveTerms max_degree{S::Vertex, kUnbounded, degree};
  max_degree.term_of_degree = degree_term, max_degree.global_bound = degree_bound;
  set(Objective::MinmaxDegree, max_degree);
  set(Objective::MaxConvexEdges, {S::InteriorEdge, kCount, nullptr, convex_edge});
  ObjectiveTerms total_length{S::Edge, kUnbounded, nullptr, length};
  total_length.edge_reads_apexes = false;
  set(Objective::MinTotalEdgeLength, total_length);
  ObjectiveTerms largest_area{S::Triangle, kUnbounded, nullptr, nullptr, area};
  largest_area.global_bound = area_bound;
  set(Objective::MinmaxTriangleArea, largest_area);
  using P = PairMeasure;
  ObjectiveTerms edge_ratio = pairs(S::EdgePair, P::AreaRatio);
  edge_ratio.global_bound = ratio_bound;
  set(Objective::MinmaxEdgeAreaRatio, edge_ratio);
  set(Objective::MinmaxEdgeNormalAngle, pairs(S::EdgePair, P::NormalAngle));
  set(Objective::MinmaxEdgeEnclosingCircle, pairs(S::EdgePair, P::EnclosingCircle));
  ObjectiveTerms vertex_ratio = pairs(S::VertexPair, P::AreaRatio);
  vertex_ratio.global_bound = ratio_bound;
  set(Objective::MinmaxVertexAreaRatio, vertex_ratio);
  set(Objective::MinmaxVertexNormalAngle, pairs(S::VertexPair, P::NormalAngle));
  return t;
}

// Within a domain the shortcuts that summarise a star without its triangles
// cannot see which triangles are inside: they are off.
std::array<ObjectiveTerms, kNumObjectives> with_domain(std::array<ObjectiveTerms, kNumObjectives> t) {
  for (ObjectiveTerms& d : t) {
    d.neighbor_class = nullptr, d.term_of_classes = nullptr, d.drop_neighbors = nullptr, d.term_of_degree = nullptr;
    d.term_of_vertex_class = nullptr;
    d.global_bound = nullptr;  // (counts over all triangles; a domain may leave no pair)
    d.edge_reads_apexes = true;
    d.domain = true;
  }
  return t;
}

}  // namespace

void star_neighbors(uint32_t v, const std::vector<Tri>& triangles, std::vector<uint32_t>& out) {
  out.clear();
  for (const Tri& t : triangles)
    for (uint32_t w : t)
      if (w != v) out.push_back(w);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

uint32_t neighbor_classes(const ObjectiveTerms& d, const Mesh& m, uint32_t v, const std::vector<uint32_t>& nb) {
  uint32_t mask = 0;
  for (uint32_t w : nb) mask |= 1u << d.neighbor_class(m, v, w);
  return mask;
}

namespace {
const std::array<ObjectiveTerms, kNumObjectives>& plain_table() {
  static const std::array<ObjectiveTerms, kNumObjectives> table = make_table();
  return table;
}
// The plain terms, read by evaluate_terms where it has checked the domain itself.
const ObjectiveTerms& objective_terms_without_domain(Objective o) { return plain_table()[static_cast<size_t>(o)]; }
}  // namespace

const ObjectiveTerms& objective_terms_inside(Objective o) {
  static const std::array<ObjectiveTerms, kNumObjectives> table = [] {
    std::array<ObjectiveTerms, kNumObjectives> t = make_table();
    for (ObjectiveTerms& d : t) d.all_inside = true, d.global_bound = nullptr;  // (a bound on a whole triangulation: not a piece's)
    return t;
  }();
  return table[static_cast<size_t>(o)];
}

const ObjectiveTerms& objective_terms(Objective o, const Mesh& m) {
  static const std::array<ObjectiveTerms, kNumObjectives> domain_table = with_domain(make_table());
  return (has_domain(m) ? domain_table : plain_table())[static_cast<size_t>(o)];
}

namespace {

// The pairs of a star's triangles, the largest measure (0 if none).
double largest_pair(const ObjectiveTerms& d, const Mesh& m, const Tri* tris, uint32_t n, double cut) {
  double best = 0;
  for (uint32_t i = 0; i < n; ++i)
    for (uint32_t j = i + 1; j < n; ++j) best = std::max(best, d.pair(m, tris[i], tris[j], std::max(best, cut)));
  return best;
}

// A vertex term within a domain: the star's inside triangles only.
double vertex_term_in_domain(const ObjectiveTerms& d, const Mesh& m, const Star& s, double cut) {
  static thread_local std::vector<Tri> inside;
  static thread_local std::vector<uint32_t> nb;
  inside.clear();
  for (uint32_t i = 0; i < s.num_triangles; ++i)
    if (triangle_inside(m, s.triangles[i])) inside.push_back(s.triangles[i]);
  switch (d.site) {
    case TermSite::InteriorVertex:  // counted only when its whole star is inside
      return inside.size() == s.num_triangles ? d.vertex(m, s) : 0;
    case TermSite::VertexPair:
      return largest_pair(d, m, inside.data(), static_cast<uint32_t>(inside.size()), cut);
    default:  // the neighbours joined by an edge of an inside triangle
      star_neighbors(s.center, inside, nb);
      return d.vertex(m, Star(s.center, nb, inside));
  }
}

}  // namespace

double vertex_term(const ObjectiveTerms& d, const Mesh& m, const Star& s, double cut) {
  if (d.domain != has_domain(m) && !d.all_inside) throw std::logic_error("objective terms read with the wrong domain");
  if (d.domain) return vertex_term_in_domain(d, m, s, cut);
  if (d.site != TermSite::VertexPair) return d.vertex(m, s);
  return largest_pair(d, m, s.triangles, s.num_triangles, cut);
}

double edge_term(const ObjectiveTerms& d, const Mesh& m, uint32_t u, uint32_t v, uint32_t w, uint32_t x, double cut) {
  if (d.domain) {
    // An interior edge counts with an inside triangle on each side, a length
    // with one on either side.
    const bool left = w != kNoApex && triangle_inside(m, {u, v, w});
    const bool right = x != kNoApex && triangle_inside(m, {v, u, x});
    if (d.site == TermSite::Edge ? !left && !right : !left || !right) return 0;
  }
  if (d.site != TermSite::EdgePair) return d.edge(m, u, v, w, x);
  return d.pair(m, Tri{u, v, w}, Tri{v, u, x}, cut);
}

double triangle_term(const ObjectiveTerms& d, const Mesh& m, const Tri& t) {
  return d.domain && !triangle_inside(m, t) ? 0 : d.triangle(m, t);
}

double evaluate_terms(Objective o, const Mesh& m, const Progress& progress) {
  const ObjectiveTerms& d = objective_terms(o, m);
  // Sums are exact until one rounding (exact_sum.hpp), so that equal
  // triangulations listed differently have bit-identical totals.
  ExactSum sum;
  double max = 0;
  WorkCounter work;
  // A term's cost in elementary steps: a vertex's grows with its degree (cubic
  // for the vertex class), pairs with their count.
  auto step = [&](double done, double total, double units) {
    if (work.tick(units)) report(progress, done, total);
  };
  report(progress, 0, 1);  // (the phase begins, however few its terms)
  auto add = [&](double t) {
    if (d.combine == Combine::Sum) sum.add(t);
    else max = std::max(max, t);
  };
  // Within a domain each triangle is decided inside once; a term whose triangles
  // are all inside reads as without one, and a vertex, edge or triangle the
  // definitions leave out adds nothing (the degree and vertex pairs read their
  // stars' inside triangles in vertex_term).
  const std::vector<uint8_t> inside = d.domain ? inside_triangles(m) : std::vector<uint8_t>{};
  const ObjectiveTerms& plain = d.domain ? objective_terms_without_domain(o) : d;
  if (vertex_site(d.site)) {
    const Stars st = build_stars(m, progress);
    std::vector<Tri> tris;
    for (uint32_t v = 0; v < m.num_vertices(); ++v) {
      const double deg = st.degree(v);
      step(v, m.num_vertices(), 16 + deg * deg * (d.site == TermSite::VertexPair ? 4 : deg));
      if (interior_only(d.site) && st.on_hull[v]) continue;
      if (d.domain && d.site == TermSite::InteriorVertex) {  // counted only when its whole star is inside
        bool all = true;
        for (uint32_t i = st.tri_offset[v]; i < st.tri_offset[v + 1] && all; ++i) all = inside[st.triangle[i]] != 0;
        if (all) add(plain.vertex(m, Star(v, st.neighbor.data() + st.offset[v], st.degree(v), nullptr, 0)));
        continue;
      }
      tris.clear();  // (only pair terms and domains read the triangles)
      if (reads_star_triangles(d))
        for (uint32_t i = st.tri_offset[v]; i < st.tri_offset[v + 1]; ++i) tris.push_back(base_triangle(m, st.triangle[i]));
      add(vertex_term(d, m, Star(v, st.neighbor.data() + st.offset[v], st.degree(v), tris.data(), static_cast<uint32_t>(tris.size())),
                      max));
    }
  } else if (edge_site(d.site)) {
    for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
      step(e, static_cast<double>(m.halfedges.size()), 32);
      const int32_t f = m.halfedges[e];
      if (f < 0 ? interior_only(d.site) : f < static_cast<int32_t>(e)) continue;
      if (d.domain) {  // an interior edge with an inside triangle on each side, a length with one on either
        const bool left = inside[e / 3] != 0, right = f >= 0 && inside[static_cast<uint32_t>(f) / 3] != 0;
        if (d.site == TermSite::Edge ? !left && !right : !left || !right) continue;
      }
      add(edge_term(plain, m, m.origin(e), m.target(e), m.apex(e), f < 0 ? kNoApex : m.apex(static_cast<uint32_t>(f)), max));
    }
  } else {
    for (uint32_t t = 0; t < m.num_triangles(); ++t) {
      step(t, m.num_triangles(), 16);
      if (!d.domain || inside[t]) add(triangle_term(plain, m, base_triangle(m, t)));
    }
  }
  return d.combine == Combine::Sum ? sum.value() : max;
}

}  // namespace hodt
