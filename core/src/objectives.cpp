#include "hodt/objectives.hpp"

#include <algorithm>
#include <cmath>

#include "hodt/measures.hpp"

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

std::array<double, kNumObjectives> evaluate_all(const Mesh& m) {
  std::array<double, kNumObjectives> v{};
  auto at = [&](Objective o) -> double& { return v[static_cast<size_t>(o)]; };
  const Measures ms = measure(m);
  const uint32_t n = m.num_vertices(), nt = m.num_triangles();
  std::vector<double> area(nt);
  double max_area = 0;
  for (uint32_t t = 0; t < nt; ++t) {
    area[t] = triangle_area(m.point(m.triangles[3 * t]), m.point(m.triangles[3 * t + 1]),
                            m.point(m.triangles[3 * t + 2]));
    max_area = std::max(max_area, area[t]);
  }
  at(Objective::MinmaxTriangleArea) = max_area;
  auto corners = [&](uint32_t t, const double* out[3]) {
    for (int k = 0; k < 3; ++k) out[k] = m.point(m.triangles[3 * t + k]);
  };
  std::vector<double> lengths;
  lengths.reserve(m.triangles.size() / 2 + m.hull.size());
  double edge_ratio = 0, edge_angle = 0, edge_circle = 0, convex_edges = 0;
  for (uint32_t e = 0; e < m.triangles.size(); ++e) {
    const int32_t f = m.halfedges[e];
    if (f >= 0 && static_cast<uint32_t>(f) < e) continue;
    lengths.push_back(edge_length(m.point(m.origin(e)), m.point(m.target(e))));
    if (f < 0) continue;
    const uint32_t t1 = e / 3, t2 = static_cast<uint32_t>(f) / 3;
    if (ms.edge_shape[e] == kConvexEdge) ++convex_edges;
    edge_ratio = std::max(edge_ratio, area_ratio(area[t1], area[t2]));
    const double *c1[3], *c2[3];
    corners(t1, c1);
    corners(t2, c2);
    edge_angle = std::max(edge_angle, normal_angle(c1, c2));
    edge_circle = std::max(edge_circle, enclosing_circle(m.point(m.origin(e)), m.point(m.target(e)),
                                                         m.point(m.apex(e)), m.point(m.apex(static_cast<uint32_t>(f)))));
  }
  at(Objective::MinTotalEdgeLength) = order_free_sum(std::move(lengths));
  at(Objective::MinmaxEdgeAreaRatio) = edge_ratio;
  at(Objective::MinmaxEdgeNormalAngle) = edge_angle;
  at(Objective::MinmaxEdgeEnclosingCircle) = edge_circle;
  at(Objective::MaxConvexEdges) = convex_edges;

  const Stars s = build_stars(m);
  double vertex_ratio = 0, vertex_angle = 0, convex = 0, mixed = 0, minima = 0, maxima = 0, degree = 0;
  for (uint32_t v = 0; v < n; ++v) {
    degree = std::max<double>(degree, ms.degree[v]);
    convex += ms.vertex_class[v] == kConvex;
    mixed += ms.vertex_class[v] == kMixed;
    minima += ms.extremum[v] == kLocalMinimum;
    maxima += ms.extremum[v] == kLocalMaximum;
    const uint32_t b = s.tri_offset[v], e = s.tri_offset[v + 1];
    double lo = INFINITY, hi = 0;
    for (uint32_t i = b; i < e; ++i) {
      lo = std::min(lo, area[s.triangle[i]]);
      hi = std::max(hi, area[s.triangle[i]]);
      const double* ci[3];
      corners(s.triangle[i], ci);
      for (uint32_t j = i + 1; j < e; ++j) {
        const double* cj[3];
        corners(s.triangle[j], cj);
        vertex_angle = std::max(vertex_angle, normal_angle(ci, cj));
      }
    }
    if (e - b >= 2) vertex_ratio = std::max(vertex_ratio, hi / lo);
  }
  at(Objective::MaxConvexVertices) = convex;
  at(Objective::MinMixedVertices) = mixed;
  at(Objective::MinLocalMinima) = minima;
  at(Objective::MinLocalExtrema) = minima + maxima;
  at(Objective::MinmaxDegree) = degree;
  at(Objective::MinmaxVertexAreaRatio) = vertex_ratio;
  at(Objective::MinmaxVertexNormalAngle) = vertex_angle;
  return v;
}

double evaluate(Objective o, const Mesh& m) { return evaluate_all(m)[static_cast<size_t>(o)]; }

}  // namespace hodt
