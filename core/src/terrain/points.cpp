#include "hodt/points.hpp"

#include <algorithm>
#include <cmath>

#include "hodt/error.hpp"
#include "hodt/format.hpp"
#include "hodt/predicates.hpp"
#include "containers/out_of_line.hpp"
#include "geometry/spatial_order.hpp"

namespace hodt {

std::string PointLabels::describe(size_t i) const {
  std::string s = "point " + std::to_string(i);
  if (i < lines.size()) s += " (line " + std::to_string(lines[i]) + ")";
  return s;
}

void check_coordinate(double v, int axis, const std::string& who) {
  static const char* const name[3] = {"x", "y", "z"};
  if (!std::isfinite(v))
    throw InputError(who + ": " + name[axis] + " is " + format_number(v) + ", expected a finite number");
  if (v != 0 && !(std::abs(v) >= kMinCoordinate && std::abs(v) <= kMaxCoordinate))
    throw InputError(who + ": " + name[axis] + " is " + format_number(v) +
                     ", outside the supported range: every coordinate must be 0 or of magnitude from " +
                     format_number(kMinCoordinate) + " to " + format_number(kMaxCoordinate));
}

TerrainPoints validate_points(std::vector<double> xyz, Dedupe dedupe, const PointLabels& labels,
                              PointOrder point_order) {
  if (xyz.size() % 3 != 0)
    throw InputError("expected x, y, z per point: " + std::to_string(xyz.size()) +
                     " numbers is not a multiple of 3");
  const size_t n = xyz.size() / 3;
  // (The long loops out of line per chunk: containers/out_of_line.hpp.)
  for_each_index(n, [&](size_t i) {
    for (int k = 0; k < 3; ++k) {
      const double v = xyz[3 * i + k];
      if (!(v == 0 || (std::abs(v) >= kMinCoordinate && std::abs(v) <= kMaxCoordinate)))  // (false for NaN)
        check_coordinate(v, k, labels.describe(i));
    }
  });

  // Along the spatial order equal points are consecutive, the earliest input index
  // first; the first of each run is kept. The error names the run with the
  // smallest (x, y) and its two earliest points, whatever the order.
  std::vector<uint32_t> order = spatial_order(xyz);
  std::vector<char> keep(n, 1);
  size_t dropped = 0;
  const double* worst = nullptr;
  uint32_t worst_a = 0, worst_b = 0;
  size_t first = 0;
  for_each_index(n, [&](size_t k) {
    if (k == 0) return;
    const uint32_t a = order[first], b = order[k];
    if (compare_xy(&xyz[3 * size_t(a)], &xyz[3 * size_t(b)]) != 0) {
      first = k;
      return;
    }
    if (keep[a] && dedupe == Dedupe::Error && (!worst || compare_xy(&xyz[3 * size_t(a)], worst) < 0))
      worst = &xyz[3 * size_t(a)], worst_a = a, worst_b = b;
    keep[b] = 0;
    ++dropped;
  });
  if (worst)
    throw InputError(labels.describe(worst_a) + " and " + labels.describe(worst_b) + " have the same (x, y) = (" +
                     format_number(worst[0]) + ", " + format_number(worst[1]) +
                     "); remove one or ask for dedupe \"first\"");

  TerrainPoints out;
  const size_t m = n - dropped;
  out.input_index.reserve(m);
  if (point_order == PointOrder::Spatial) {
    out.xyz.resize(3 * m);
    for_each_index(n, [&](size_t k) {
      const uint32_t i = order[k];
      if (keep[i]) {
        std::copy_n(&xyz[3 * size_t(i)], 3, &out.xyz[3 * out.input_index.size()]);
        out.input_index.push_back(i);
      }
    });
  } else {
    for (uint32_t i = 0; i < n; ++i)
      if (keep[i]) out.input_index.push_back(i);
    if (m == n) {
      out.xyz = std::move(xyz);  // nothing dropped: no copy
    } else {
      for (uint32_t i : out.input_index) out.xyz.insert(out.xyz.end(), &xyz[3 * i], &xyz[3 * i + 3]);
    }
  }
  if (m < 3)
    throw InputError("need at least 3 distinct points, got " + std::to_string(m));
  const double* p = &out.xyz[0];
  const double* q = &out.xyz[3];
  bool collinear = true;
  for (size_t i = 2; i < m && collinear; ++i) collinear = orient2d(p, q, &out.xyz[3 * i]) == 0;
  if (collinear)
    throw InputError("all " + std::to_string(m) +
                     " points are collinear: a terrain needs points spanning an area");
  return out;
}

}  // namespace hodt
