#include "geometry/spatial_order.hpp"

#include <algorithm>
#include <cmath>

#include "containers/out_of_line.hpp"

namespace hodt {

namespace {
constexpr int kBits = 21;  // per axis: 42-bit keys, sorted in three 14-bit passes
constexpr int kDigit = 14;

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
  // (Each loop over the points per chunk, out of line: containers/out_of_line.hpp.)
  for_each_chunk(n, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i)
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], xyz[3 * i + k]), hi[k] = std::max(hi[k], xyz[3 * i + k]);
  });
  std::vector<uint64_t> key(n);
  for_each_chunk(n, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      uint32_t q[2];
      for (int k = 0; k < 2; ++k) {
        const double span = hi[k] - lo[k], top = double((1u << kBits) - 1);
        const double t = span > 0 ? (xyz[3 * i + k] - lo[k]) / span : 0.0;
        q[k] = static_cast<uint32_t>(std::min(t * top, top));
      }
      key[i] = spread(q[0]) | (spread(q[1]) << 1);
    }
  });
  // LSD radix sort of the indices by key (stable: equal keys stay by index).
  std::vector<uint32_t> order(n), next(n);
  for (size_t i = 0; i < n; ++i) order[i] = static_cast<uint32_t>(i);
  std::vector<uint32_t> count(size_t(1) << kDigit);
  for (int shift = 0; shift < 2 * kBits; shift += kDigit) {
    std::fill(count.begin(), count.end(), 0);
    const uint64_t mask = (uint64_t(1) << kDigit) - 1;
    for_each_chunk(n, [&](size_t begin, size_t end) {
      for (size_t j = begin; j < end; ++j) ++count[(key[order[j]] >> shift) & mask];
    });
    uint32_t sum = 0;
    for (uint32_t& c : count) sum += c, c = sum - c;
    for_each_chunk(n, [&](size_t begin, size_t end) {
      for (size_t j = begin; j < end; ++j) next[count[(key[order[j]] >> shift) & mask]++] = order[j];
    });
    order.swap(next);
  }
  // Equal keys (points closer than the quantum; rare) are ordered by x, y, then
  // index, so that equal points end up next to each other (validate_points relies on it).
  const double* c = xyz.data();
  size_t k = 0;  // (the runs that start in a chunk, each whole)
  for_each_chunk(n, [&](size_t, size_t chunk_end) {
    while (k < chunk_end) {
      size_t end = k + 1;
      while (end < n && key[order[end]] == key[order[k]]) ++end;
      if (end - k > 1)
        std::sort(order.begin() + k, order.begin() + end, [c](uint32_t a, uint32_t b) {
          const double *p = c + 3 * size_t(a), *q = c + 3 * size_t(b);
          if (p[0] != q[0]) return p[0] < q[0];
          if (p[1] != q[1]) return p[1] < q[1];
          return a < b;
        });
      k = end;
    }
  });
  return order;
}

}  // namespace hodt
