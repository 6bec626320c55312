#include "hodt/pair_measures.hpp"

#include "hodt/measures.hpp"

namespace hodt {

namespace {
double area(const Mesh& m, const Tri& t) { return triangle_area(m.point(t[0]), m.point(t[1]), m.point(t[2])); }
}  // namespace

double pair_area_ratio(const Mesh& m, const Tri& s, const Tri& t) { return area_ratio(area(m, s), area(m, t)); }

double pair_normal_angle(const Mesh& m, const Tri& s, const Tri& t) {
  const double* a[3] = {m.point(s[0]), m.point(s[1]), m.point(s[2])};
  const double* b[3] = {m.point(t[0]), m.point(t[1]), m.point(t[2])};
  return normal_angle(a, b);
}

double pair_enclosing_circle(const Mesh& m, const Tri& s, const Tri& t) {
  // The vertex of t that is not in s.
  uint32_t d = t[0];
  for (uint32_t v : t)
    if (v != s[0] && v != s[1] && v != s[2]) d = v;
  return enclosing_circle(m.point(s[0]), m.point(s[1]), m.point(s[2]), m.point(d));
}

bool is_pair_objective(Objective o) {
  switch (o) {
    case Objective::MinmaxEdgeAreaRatio:
    case Objective::MinmaxEdgeNormalAngle:
    case Objective::MinmaxEdgeEnclosingCircle:
    case Objective::MinmaxVertexAreaRatio:
    case Objective::MinmaxVertexNormalAngle:
      return true;
    default:
      return false;
  }
}

std::optional<CriticalPair> critical_pair(Objective o, const Mesh& m) {
  double (*measure)(const Mesh&, const Tri&, const Tri&) = nullptr;
  bool edge = true;
  switch (o) {
    case Objective::MinmaxEdgeAreaRatio: measure = pair_area_ratio; break;
    case Objective::MinmaxEdgeNormalAngle: measure = pair_normal_angle; break;
    case Objective::MinmaxEdgeEnclosingCircle: measure = pair_enclosing_circle; break;
    case Objective::MinmaxVertexAreaRatio: measure = pair_area_ratio, edge = false; break;
    case Objective::MinmaxVertexNormalAngle: measure = pair_normal_angle, edge = false; break;
    default: return std::nullopt;
  }
  std::optional<CriticalPair> best;
  auto consider = [&](uint32_t s, uint32_t t) {
    const Tri a = base_triangle(m, s), b = base_triangle(m, t);
    const double v = measure(m, a, b);
    if (!best || v > best->value) best = CriticalPair{a, b, v};
  };
  if (edge) {
    for (uint32_t e = 0; e < m.halfedges.size(); ++e)
      if (m.halfedges[e] > static_cast<int32_t>(e)) consider(e / 3, static_cast<uint32_t>(m.halfedges[e]) / 3);
  } else {
    const Stars st = build_stars(m);
    for (uint32_t v = 0; v < m.num_vertices(); ++v)
      for (uint32_t i = st.tri_offset[v]; i < st.tri_offset[v + 1]; ++i)
        for (uint32_t j = i + 1; j < st.tri_offset[v + 1]; ++j) consider(st.triangle[i], st.triangle[j]);
  }
  return best;
}

}  // namespace hodt
