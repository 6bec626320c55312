// Turning fuzzer bytes into terrains: small point sets that are mostly
// degenerate (integer grids with equal heights, cocircular and collinear points,
// georeferenced offsets, extreme magnitudes), where slow paths and wrong answers hide.
#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace hodt::fuzz {

// Reads the fuzzer's bytes front to back; zeros once they run out.
struct Bytes {
  const uint8_t* data;
  size_t size;
  size_t at = 0;
  uint8_t byte() { return at < size ? data[at++] : 0; }
  double raw_double() {
    uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= static_cast<uint64_t>(byte()) << (8 * i);
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
};

// n points (x, y, z) in one of a few styles picked by the input.
inline std::vector<double> points(Bytes& in, uint32_t n) {
  const uint8_t style = in.byte() % 5;
  std::vector<double> xyz;
  for (uint32_t i = 0; i < n; ++i) {
    const uint8_t a = in.byte(), b = in.byte(), c = in.byte();
    double x = a % 6, y = b % 6, z = c % 4;  // a small grid, few heights: ties everywhere
    switch (style) {
      case 1:  // reprojected raster: an offset and a cell size that are not round in binary
        x = 731012.3456789 + 74.98765 * (a % 8), y = 4100000.25 + 74.98765 * (b % 8), z = 100 + 0.5 * (c % 8);
        break;
      case 2:  // quantised LiDAR-like coordinates
        x = 500000 + 0.01 * (a | (b << 8)) , y = 4100000 + 0.01 * ((b << 3) ^ c), z = 0.01 * c;
        break;
      case 3:  // any doubles (the core refuses what it cannot handle)
        x = in.raw_double(), y = in.raw_double(), z = in.raw_double();
        break;
      case 4:  // points on a circle (cocircular) and its centre, scaled
        x = std::cos(a * 0.7853981633974483) * (1 + (c & 1)), y = std::sin(a * 0.7853981633974483) * (1 + (c & 1)), z = b % 3;
        break;
      default:
        break;
    }
    xyz.insert(xyz.end(), {x, y, z});
  }
  return xyz;
}

}  // namespace hodt::fuzz
