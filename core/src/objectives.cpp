#include "hodt/objectives.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "hodt/measures.hpp"
#include "hodt/pair_measures.hpp"
#include "hodt/skeleton.hpp"

namespace hodt {

const std::array<ObjectiveInfo, kNumObjectives>& objectives() {
  static const std::array<ObjectiveInfo, kNumObjectives> table = {{
      {Objective::MaxConvexVertices, "max-convex-vertices", Sense::Max, true,
       "Most convex interior vertices (all neighbours on or below a plane through the vertex)."},
      {Objective::MinmaxEdgeAreaRatio, "minmax-edge-area-ratio", Sense::Min, false,
       "Smallest worst area ratio (larger over smaller) of two triangles sharing an edge."},
      {Objective::MinmaxEdgeNormalAngle, "minmax-edge-normal-angle", Sense::Min, false,
       "Smallest worst angle between the normals of two triangles sharing an edge."},
      {Objective::MinmaxEdgeEnclosingCircle, "minmax-edge-enclosing-circle", Sense::Min, false,
       "Smallest worst radius of the smallest circle around two triangles sharing an edge."},
      {Objective::MinmaxVertexAreaRatio, "minmax-vertex-area-ratio", Sense::Min, false,
       "Smallest worst area ratio of two triangles sharing a vertex."},
      {Objective::MinmaxVertexNormalAngle, "minmax-vertex-normal-angle", Sense::Min, false,
       "Smallest worst angle between the normals of two triangles sharing a vertex."},
      {Objective::MinLocalMinima, "min-local-minima", Sense::Min, true,
       "Fewest local minima (interior vertices whose neighbours are all higher): pits that trap water."},
      {Objective::MinLocalExtrema, "min-local-extrema", Sense::Min, true,
       "Fewest local minima plus local maxima."},
      {Objective::MinTotalEdgeLength, "min-total-edge-length", Sense::Min, false,
       "Shortest total plane length of all edges."},
      {Objective::MinmaxTriangleArea, "minmax-triangle-area", Sense::Min, false,
       "Smallest largest triangle (plane area)."},
      {Objective::MaxConvexEdges, "max-convex-edges", Sense::Max, true,
       "Most convex (ridge) interior edges. NP-hard."},
      {Objective::MinMixedVertices, "min-mixed-vertices", Sense::Min, true,
       "Fewest mixed interior vertices (neither convex, concave nor flat). NP-hard."},
      {Objective::MinmaxDegree, "minmax-degree", Sense::Min, true,
       "Smallest maximum vertex degree. NP-hard."},
  }};
  return table;
}

const ObjectiveInfo& info(Objective o) { return objectives()[static_cast<size_t>(o)]; }

std::optional<Objective> parse_objective(std::string_view id) {
  for (const auto& i : objectives())
    if (id == i.id) return i.objective;
  return std::nullopt;
}

std::string objective_ids() {
  std::string s;
  for (const auto& i : objectives()) s += (s.empty() ? "" : ", ") + std::string(i.id);
  return s;
}

namespace {

// Each family of objectives computes only what it needs: evaluate() of one
// objective must stay linear and light (it runs after every solve).
double tri_area(const Mesh& m, uint32_t t) {
  return triangle_area(m.point(m.triangles[3 * t]), m.point(m.triangles[3 * t + 1]), m.point(m.triangles[3 * t + 2]));
}

std::vector<double> areas(const Mesh& m) {
  std::vector<double> a(m.num_triangles());
  for (uint32_t t = 0; t < m.num_triangles(); ++t) a[t] = tri_area(m, t);
  return a;
}

double max_triangle_area(const Mesh& m) {
  double best = 0;
  for (uint32_t t = 0; t < m.num_triangles(); ++t) best = std::max(best, tri_area(m, t));
  return best;
}

double total_edge_length(const Mesh& m) {
  std::vector<double> lengths;
  lengths.reserve(m.triangles.size() / 2 + m.hull.size());
  for (uint32_t e = 0; e < m.triangles.size(); ++e)
    if (m.halfedges[e] < static_cast<int32_t>(e))
      lengths.push_back(edge_length(m.point(m.origin(e)), m.point(m.target(e))));
  return order_free_sum(std::move(lengths));
}

// Max over interior edges of a measure of the edge's two triangles.
template <class F>
double edge_pair_max(const Mesh& m, F f) {
  double best = 0;
  for (uint32_t e = 0; e < m.halfedges.size(); ++e)
    if (m.halfedges[e] > static_cast<int32_t>(e)) best = std::max(best, f(e, static_cast<uint32_t>(m.halfedges[e])));
  return best;
}

double convex_edges(const Mesh& m) {
  double n = 0;
  for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
    const int32_t f = m.halfedges[e];
    if (f > static_cast<int32_t>(e))
      n += edge_shape(m.point(m.origin(e)), m.point(m.target(e)), m.point(m.apex(e)),
                      m.point(m.apex(static_cast<uint32_t>(f)))) == kConvexEdge;
  }
  return n;
}

// Counts interior vertices by a predicate of the vertex and its neighbours.
template <class F>
double count_vertices(const Mesh& m, const Stars& s, F f) {
  double n = 0;
  std::vector<const double*> nb;
  for (uint32_t v = 0; v < m.num_vertices(); ++v) {
    if (s.on_hull[v]) continue;
    nb.resize(s.degree(v));
    for (uint32_t k = 0; k < nb.size(); ++k) nb[k] = m.point(s.neighbor[s.offset[v] + k]);
    n += f(m.point(v), nb.data(), static_cast<uint32_t>(nb.size()));
  }
  return n;
}

double vertex_area_ratio(const Mesh& m, const Stars& s, const std::vector<double>& area) {
  double best = 0;
  for (uint32_t v = 0; v < m.num_vertices(); ++v) {
    const uint32_t b = s.tri_offset[v], e = s.tri_offset[v + 1];
    if (e - b < 2) continue;
    double lo = INFINITY, hi = 0;
    for (uint32_t i = b; i < e; ++i) lo = std::min(lo, area[s.triangle[i]]), hi = std::max(hi, area[s.triangle[i]]);
    best = std::max(best, hi / lo);  // = the largest pairwise ratio: division is monotone
  }
  return best;
}

// The largest normal angle over the pairs of triangles at a vertex. The best so
// far is the cut: float estimates show most pairs below it, and only pairs that
// raise it get accurate normals (pair_measures.hpp); the max is the same.
double vertex_normal_angle(const Mesh& m, const Stars& s) {
  double best = 0;
  for (uint32_t v = 0; v < m.num_vertices(); ++v)
    for (uint32_t i = s.tri_offset[v]; i < s.tri_offset[v + 1]; ++i)
      for (uint32_t j = i + 1; j < s.tri_offset[v + 1]; ++j)
        best = std::max(best, pair_normal_angle(m, base_triangle(m, s.triangle[i]), base_triangle(m, s.triangle[j]), best));
  return best;
}

double max_degree(const Stars& s) {
  uint32_t d = 0;
  for (uint32_t v = 0; v + 1 < s.offset.size(); ++v) d = std::max(d, s.degree(v));
  return d;
}

}  // namespace

double evaluate(Objective o, const Mesh& m) {
  switch (o) {
    case Objective::MinmaxTriangleArea: return max_triangle_area(m);
    case Objective::MinTotalEdgeLength: return total_edge_length(m);
    case Objective::MaxConvexEdges: return convex_edges(m);
    case Objective::MinmaxEdgeAreaRatio: {
      const std::vector<double> a = areas(m);
      return edge_pair_max(m, [&](uint32_t e, uint32_t f) { return area_ratio(a[e / 3], a[f / 3]); });
    }
    case Objective::MinmaxEdgeNormalAngle: {
      double best = 0;  // the cut, as in vertex_normal_angle
      return edge_pair_max(m, [&](uint32_t e, uint32_t f) {
        return best = std::max(best, pair_normal_angle(m, base_triangle(m, e / 3), base_triangle(m, f / 3), best));
      });
    }
    case Objective::MinmaxEdgeEnclosingCircle:
      return edge_pair_max(m, [&](uint32_t e, uint32_t f) {
        return enclosing_circle(m.point(m.origin(e)), m.point(m.target(e)), m.point(m.apex(e)), m.point(m.apex(f)));
      });
    default: break;
  }
  const Stars s = build_stars(m);
  switch (o) {
    case Objective::MaxConvexVertices:
      return count_vertices(m, s, [](const double* p, const double* const* nb, uint32_t d) { return vertex_class(p, nb, d) == kConvex; });
    case Objective::MinMixedVertices:
      return count_vertices(m, s, [](const double* p, const double* const* nb, uint32_t d) { return vertex_class(p, nb, d) == kMixed; });
    case Objective::MinLocalMinima:
      return count_vertices(m, s, [](const double* p, const double* const* nb, uint32_t d) { return extremum(p, nb, d) == kLocalMinimum; });
    case Objective::MinLocalExtrema:
      return count_vertices(m, s, [](const double* p, const double* const* nb, uint32_t d) { return extremum(p, nb, d) != kNotExtremum; });
    case Objective::MinmaxDegree: return max_degree(s);
    case Objective::MinmaxVertexAreaRatio: return vertex_area_ratio(m, s, areas(m));
    case Objective::MinmaxVertexNormalAngle: return vertex_normal_angle(m, s);
    default: break;
  }
  throw std::logic_error("unknown objective");
}

std::array<double, kNumObjectives> evaluate_all(const Mesh& m) {
  std::array<double, kNumObjectives> v{};
  for (const auto& i : objectives()) v[static_cast<size_t>(i.objective)] = evaluate(i.objective, m);
  return v;
}

}  // namespace hodt
