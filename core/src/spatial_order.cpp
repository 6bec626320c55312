#include "hodt/spatial_order.hpp"

#include <algorithm>
#include <cmath>

namespace hodt {

namespace {
uint64_t spread(uint32_t v) {  // bits of v at the even positions
  uint64_t x = v;
  x = (x | (x << 16)) & 0x0000FFFF0000FFFFull;
  x = (x | (x << 8)) & 0x00FF00FF00FF00FFull;
  x = (x | (x << 4)) & 0x0F0F0F0F0F0F0F0Full;
  x = (x | (x << 2)) & 0x3333333333333333ull;
  x = (x | (x << 1)) & 0x5555555555555555ull;
  return x;
}
}  // namespace

std::vector<uint32_t> spatial_order(const std::vector<double>& xyz) {
  const size_t n = xyz.size() / 3;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], xyz[3 * i + k]), hi[k] = std::max(hi[k], xyz[3 * i + k]);
  std::vector<std::pair<uint64_t, uint32_t>> keys(n);
  for (size_t i = 0; i < n; ++i) {
    uint32_t q[2];
    for (int k = 0; k < 2; ++k) {
      const double span = hi[k] - lo[k];
      const double t = span > 0 ? (xyz[3 * i + k] - lo[k]) / span : 0.0;
      q[k] = static_cast<uint32_t>(std::min(t * 4294967295.0, 4294967295.0));
    }
    keys[i] = {spread(q[0]) | (spread(q[1]) << 1), static_cast<uint32_t>(i)};
  }
  // Equal keys (rare: closer than the quantum) are ordered by x, y, then index, so
  // that equal points end up next to each other (validate_points relies on it).
  const double* c = xyz.data();
  std::sort(keys.begin(), keys.end(), [c](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first < b.first;
    const double *p = c + 3 * size_t(a.second), *q = c + 3 * size_t(b.second);
    if (p[0] != q[0]) return p[0] < q[0];
    if (p[1] != q[1]) return p[1] < q[1];
    return a.second < b.second;
  });
  std::vector<uint32_t> order(n);
  for (size_t k = 0; k < n; ++k) order[k] = keys[k].second;
  return order;
}

}  // namespace hodt
