#include "objectives/mean_area.hpp"

#include <CGAL/MP_Float.h>

#include <cmath>

namespace hodt {

double mean_triangle_area_below(const Mesh& m) {
  const uint32_t triangles = m.num_triangles();
  if (triangles == 0 || m.hull.size() < 3) return 0;
  using F = CGAL::MP_Float;  // exact sums and products of doubles
  // Twice the hull's area: the shoelace sum about its first vertex.
  const double* o = m.point(m.hull[0]);
  F twice = 0;
  for (size_t i = 1; i + 1 < m.hull.size(); ++i) {
    const double* a = m.point(m.hull[i]);
    const double* b = m.point(m.hull[i + 1]);
    const F ax = F(a[0]) - F(o[0]), ay = F(a[1]) - F(o[1]), bx = F(b[0]) - F(o[0]), by = F(b[1]) - F(o[1]);
    twice = twice + (ax * by - ay * bx);
  }
  // The mean is twice / (2 T): the largest double q with 2 T q <= twice
  // exactly, found from the nearest estimate (to_interval is a few ulps wide).
  const F divisor = F(2.0 * triangles);
  const auto [lo, hi] = CGAL::to_interval(twice);
  double q = (lo / 2 + hi / 2) / (2.0 * triangles);
  auto above = [&](double x) { return CGAL::compare(F(x) * divisor, twice) == CGAL::LARGER; };
  while (q > 0 && above(q)) q = std::nextafter(q, 0.0);
  for (int step = 0; step < 8 && !above(std::nextafter(q, INFINITY)); ++step) q = std::nextafter(q, INFINITY);
  return std::max(q, 0.0);
}

}  // namespace hodt
