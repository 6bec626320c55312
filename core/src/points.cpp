#include "hodt/points.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "hodt/error.hpp"
#include "hodt/format.hpp"
#include "hodt/predicates.hpp"

namespace hodt {

std::string PointLabels::describe(size_t i) const {
  std::string s = "point " + std::to_string(i);
  if (i < lines.size()) s += " (line " + std::to_string(lines[i]) + ")";
  return s;
}

TerrainPoints validate_points(std::vector<double> xyz, Dedupe dedupe, const PointLabels& labels) {
  if (xyz.size() % 3 != 0)
    throw InputError("expected x, y, z per point: " + std::to_string(xyz.size()) +
                     " numbers is not a multiple of 3");
  const size_t n = xyz.size() / 3;
  static const char* const axis[3] = {"x", "y", "z"};
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(xyz[3 * i + k]))
        throw InputError(labels.describe(i) + ": " + axis[k] + " is " +
                         format_number(xyz[3 * i + k]) + ", expected a finite number");

  // Sort by (x, y), ties by index, to find duplicates: equal points become
  // neighbours, the earliest input index first. (Comparisons of doubles are exact.)
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  const double* c = xyz.data();
  std::sort(order.begin(), order.end(), [c](uint32_t a, uint32_t b) {
    const double ax = c[3 * size_t(a)], bx = c[3 * size_t(b)];
    if (ax != bx) return ax < bx;
    const double ay = c[3 * size_t(a) + 1], by = c[3 * size_t(b) + 1];
    return ay != by ? ay < by : a < b;
  });
  std::vector<char> keep(n, 1);
  for (size_t k = 1; k < n; ++k) {
    const uint32_t a = order[k - 1], b = order[k];
    if (compare_xy(&xyz[3 * a], &xyz[3 * b]) != 0) continue;
    if (dedupe == Dedupe::Error) {
      throw InputError(labels.describe(a) + " and " + labels.describe(b) +
                       " have the same (x, y) = (" +
                       format_number(xyz[3 * a]) + ", " + format_number(xyz[3 * a + 1]) +
                       "); remove one or ask for dedupe \"first\"");
    }
    keep[b] = 0;   // the stable sort put the earliest input index of a run first
    order[k] = a;  // so later duplicates are compared with it
  }

  order = {};
  TerrainPoints out;
  out.input_index.reserve(n);
  for (size_t i = 0; i < n; ++i)
    if (keep[i]) out.input_index.push_back(static_cast<uint32_t>(i));
  if (out.input_index.size() == n) {
    out.xyz = std::move(xyz);  // nothing dropped: no copy
  } else {
    for (uint32_t i : out.input_index) out.xyz.insert(out.xyz.end(), &xyz[3 * i], &xyz[3 * i + 3]);
  }
  const size_t m = out.input_index.size();
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
