#include "hodt/objectives.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "objectives/objective_terms.hpp"

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

// Every objective's value comes from its terms (objective_terms.hpp): one
// description read by evaluate, the region engine and the local searches.
double evaluate(Objective o, const Mesh& m, const Progress& progress) { return evaluate_terms(o, m, progress); }

std::array<double, kNumObjectives> evaluate_all(const Mesh& m) {
  std::array<double, kNumObjectives> v{};
  for (const auto& i : objectives()) v[static_cast<size_t>(i.objective)] = evaluate(i.objective, m);
  return v;
}

}  // namespace hodt
