#include "hodt/domain.hpp"

#include <cmath>
#include <string>

#include "hodt/error.hpp"
#include "hodt/format.hpp"
#include "hodt/predicates.hpp"

namespace hodt {

bool edge_inside(const Mesh& m, uint32_t u, uint32_t v) {
  return !has_domain(m) || compare_length(m.point(u), m.point(v), m.coords.max_edge()) <= 0;
}

std::vector<uint8_t> inside_triangles(const Mesh& m) {
  std::vector<uint8_t> inside(m.num_triangles(), 1);
  if (!has_domain(m)) return inside;
  for (uint32_t t = 0; t < m.num_triangles(); ++t)
    inside[t] = triangle_inside(m, {m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]});
  return inside;
}

void check_max_edge(double max_edge) {
  if (!(max_edge > 0))
    throw InputError("maxEdge must be a positive length (or none), got " + format_number(max_edge));
}

}  // namespace hodt
