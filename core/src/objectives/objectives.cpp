#include "hodt/objectives.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "objectives/objective_terms.hpp"

namespace hodt {

namespace {

// objective, id, sense, combine, integral, polynomial, unit, reference, summary
using S = Sense;
using C = Combine;
using O = Objective;
constexpr std::array<ObjectiveInfo, kNumObjectives> kTable = {{
    {O::MaxConvexVertices, "max-convex-vertices", S::Max, C::Sum, true, true, "count", "Thm 1, O(n log n)",
     "Most convex interior vertices (all neighbours on or below a plane through the vertex)."},
    {O::MinmaxEdgeAreaRatio, "minmax-edge-area-ratio", S::Min, C::Max, false, true, "ratio, >= 1", "Thm 2, 2-SAT",
     "Smallest worst area ratio (larger over smaller) of two triangles sharing an edge."},
    {O::MinmaxEdgeNormalAngle, "minmax-edge-normal-angle", S::Min, C::Max, false, true, "radians, 0 to pi", "Thm 2, 2-SAT",
     "Smallest worst angle between the normals of two triangles sharing an edge."},
    {O::MinmaxEdgeEnclosingCircle, "minmax-edge-enclosing-circle", S::Min, C::Max, false, true, "plane units (a radius)", "Sec 1 remark, 2-SAT",
     "Smallest worst radius of the smallest circle around two triangles sharing an edge."},
    {O::MinmaxVertexAreaRatio, "minmax-vertex-area-ratio", S::Min, C::Max, false, true, "ratio, >= 1", "Thm 3, 2-SAT",
     "Smallest worst area ratio of two triangles sharing a vertex."},
    {O::MinmaxVertexNormalAngle, "minmax-vertex-normal-angle", S::Min, C::Max, false, true, "radians, 0 to pi", "Thm 3, 2-SAT",
     "Smallest worst angle between the normals of two triangles sharing a vertex."},
    {O::MinLocalMinima, "min-local-minima", S::Min, C::Sum, true, true, "count", "[10], O(n log n)",
     "Fewest local minima (interior vertices whose neighbours are all higher): pits that trap water."},
    {O::MinLocalExtrema, "min-local-extrema", S::Min, C::Sum, true, true, "count", "[10]",
     "Fewest local minima plus local maxima."},
    {O::MinTotalEdgeLength, "min-total-edge-length", S::Min, C::Sum, false, true, "plane units", "[10]",
     "Shortest total plane length of all edges."},
    {O::MinmaxTriangleArea, "minmax-triangle-area", S::Min, C::Max, false, true, "squared plane units", "[10]",
     "Smallest largest triangle (plane area)."},
    {O::MaxConvexEdges, "max-convex-edges", S::Max, C::Sum, true, false, "count", "NP-hard (Thm 6); PTAS Thm 7; k-OD Thm 10",
     "Most convex (ridge) interior edges. NP-hard."},
    {O::MinMixedVertices, "min-mixed-vertices", S::Min, C::Sum, true, false, "count", "NP-hard (Thm 4); PTAS Thm 8",
     "Fewest mixed interior vertices (neither convex, concave nor flat). NP-hard."},
    {O::MinmaxDegree, "minmax-degree", S::Min, C::Max, true, false, "count (neighbours)", "NP-hard (Thm 5); 3/2-approx [10]",
     "Smallest maximum vertex degree. NP-hard."},
}};

// info(o) reads row o: the rows are in the enum's order.
constexpr bool in_enum_order() {
  for (size_t i = 0; i < kNumObjectives; ++i)
    if (static_cast<size_t>(kTable[i].objective) != i) return false;
  return true;
}
static_assert(in_enum_order(), "the objective table is out of order");

}  // namespace

const std::array<ObjectiveInfo, kNumObjectives>& objectives() { return kTable; }

const ObjectiveInfo& info(Objective o) { return kTable[static_cast<size_t>(o)]; }

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
