#include "hodt/delaunay.hpp"

#include <stdexcept>

#include "hodt/predicates.hpp"
#include "geometry/spatial_order.hpp"
#include "mesh/delaunay_builder.hpp"
#include "mesh/raster_delaunay.hpp"

namespace hodt {

Mesh delaunay(std::vector<double> xyz, bool spatially_ordered) {
  const uint32_t n = static_cast<uint32_t>(xyz.size() / 3);
  Mesh m;
  m.coords = std::move(xyz);
  if (raster_delaunay(m)) {  // a raster: in closed form
    canonicalize(m);
    return m;
  }
  std::vector<uint32_t> order;
  if (!spatially_ordered) order = spatial_order(m.coords.vector());
  auto at = [&](uint32_t k) { return spatially_ordered ? k : order[k]; };
  const uint32_t nt = n > 2 ? 2 * n - 5 : 1;  // at most 2n - 2 - h triangles, h >= 3
  m.triangles.reserve(3 * size_t(nt));
  m.halfedges.reserve(3 * size_t(nt));
  // The first two points and the first point off their line make the seed triangle.
  uint32_t third = 2;
  while (third < n && orient2d(m.point(at(0)), m.point(at(1)), m.point(at(third))) == 0) ++third;
  if (third >= n) throw std::logic_error("delaunay: all points are collinear (validate_points rejects that)");
  Builder b(m);
  b.seed(at(0), at(1), at(third));
  for (uint32_t k = 2; k < n; ++k)
    if (k != third) b.insert(at(k));
  b.finish();
  canonicalize(m);  // sorted by vertex: stars are contiguous, later passes cache-friendly
  return m;
}

}  // namespace hodt
