#include "hodt/domain.hpp"

#include <cmath>
#include <string>

#include "hodt/error.hpp"
#include "hodt/format.hpp"
#include "hodt/predicates.hpp"

namespace hodt {

std::vector<uint8_t> inside_triangles(const Mesh& m) {
  std::vector<uint8_t> inside(m.num_triangles(), 1);
  if (!has_domain(m)) return inside;
  for (uint32_t t = 0; t < m.num_triangles(); ++t)
    inside[t] = triangle_inside(m, {m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]});
  return inside;
}

std::vector<uint8_t> quads_touching_outside(const FirstOrder& fo) {
  std::vector<uint8_t> touching(fo.num_quads(), 0);
  if (!has_domain(fo.base)) return touching;
  const Mesh& m = fo.base;
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    const Quad& k = fo.quads[q];
    touching[q] = !edge_inside(m, k.a, k.b) || !edge_inside(m, k.c, k.d) || !edge_inside(m, k.a, k.c) ||
                  !edge_inside(m, k.c, k.b) || !edge_inside(m, k.b, k.d) || !edge_inside(m, k.d, k.a);
  }
  return touching;
}

void check_max_edge(double max_edge) {
  if (!(max_edge > 0))
    throw InputError("maxEdge must be a positive length (or none), got " + format_number(max_edge));
}

}  // namespace hodt
