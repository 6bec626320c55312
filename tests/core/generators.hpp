// Point sets for tests and benchmarks, seeded and platform independent.
#pragma once
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace hodt::test {

// splitmix64: the same sequence on every platform.
struct Rng {
  uint64_t s;
  explicit Rng(uint64_t seed) : s(seed * 0x9E3779B97F4A7C15ull + 1) {}
  uint64_t next() {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform() { return (next() >> 11) * (1.0 / 9007199254740992.0); }
  int below(int n) { return static_cast<int>(next() % static_cast<uint64_t>(n)); }
};

inline std::vector<double> uniform_points(int n, uint64_t seed) {
  Rng r(seed);
  std::vector<double> p;
  for (int i = 0; i < n; ++i) p.insert(p.end(), {r.uniform(), r.uniform(), r.uniform()});
  return p;
}

// Smooth hills with noise: heights correlated in space, like a DEM sample.
inline double dem_height(double x, double y, uint64_t seed) {
  const double a = 1 + (seed % 7) * 0.3;
  return std::sin(3 * a * x) * std::cos(2.3 * y + a) + 0.5 * std::sin(7.1 * x + 5.3 * y) +
         0.2 * std::cos(13 * x * y + a);
}
inline std::vector<double> dem_points(int n, uint64_t seed) {
  Rng r(seed);
  std::vector<double> p;
  for (int i = 0; i < n; ++i) {
    const double x = r.uniform(), y = r.uniform();
    p.insert(p.end(), {x, y, dem_height(x, y, seed) + 0.05 * r.uniform()});
  }
  return p;
}

// The same points in a random order (Fisher-Yates, seeded).
inline std::vector<double> shuffled(std::vector<double> p, uint64_t seed) {
  Rng r(seed);
  const int n = static_cast<int>(p.size() / 3);
  for (int i = n - 1; i > 0; --i) {
    const int j = r.below(i + 1);
    for (int k = 0; k < 3; ++k) std::swap(p[3 * i + k], p[3 * j + k]);
  }
  return p;
}

// A w x h grid with integer coordinates: cocircular everywhere (degenerate).
inline std::vector<double> grid_points(int w, int h, uint64_t seed, bool integer_heights = false) {
  Rng r(seed);
  std::vector<double> p;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      p.insert(p.end(), {double(i), double(j), integer_heights ? double(r.below(4)) : dem_height(i / 7.0, j / 7.0, seed)});
  return p;
}

// A grid with each point moved by up to `jitter` of the spacing.
inline std::vector<double> jittered_grid(int w, int h, double jitter, uint64_t seed) {
  Rng r(seed);
  std::vector<double> p;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const double x = i + jitter * (2 * r.uniform() - 1), y = j + jitter * (2 * r.uniform() - 1);
      p.insert(p.end(), {x, y, dem_height(x / 7.0, y / 7.0, seed) * 3});
    }
  return p;
}

// The paper's hardness surface (Section 3.3) on a unit grid: f(x, y) = xy - (x^2 +
// y^2) / 10 makes every edge between two cells depend on both cells' diagonals,
// so the quads form one component of treewidth about the grid side.
inline std::vector<double> saddle_grid(int w) {
  std::vector<double> p;
  for (int j = 0; j < w; ++j)
    for (int i = 0; i < w; ++i) {
      const double x = i - w / 2.0, y = j - w / 2.0;
      p.insert(p.end(), {double(i), double(j), x * y - (x * x + y * y) / 10});
    }
  return p;
}

// A 60 x 60 window of a smooth raster (the benchmark's hill function sampled on
// a 1000 x 1000 lattice, as its 1M raster is): after the roof dual, most of its
// convex-edge quads stay free in a frustrated component of treewidth above 20,
// for min-degree and min-fill alike. Windows of a coarser lattice (316) keep
// smaller free components.
inline std::vector<double> frustrated_raster(int w = 60, int x0 = 340, int y0 = 860, double lattice = 1000) {
  auto hill = [](double x, double y) {
    return std::sin(3 * x) * std::cos(2.3 * y) + 0.5 * std::sin(7.1 * x + 5.3 * y) + 0.2 * std::cos(13 * x * y);
  };
  std::vector<double> p;
  for (int j = y0; j < y0 + w; ++j)
    for (int i = x0; i < x0 + w; ++i) p.insert(p.end(), {double(i), double(j), 300 + 200 * hill(i / lattice, j / lattice)});
  return p;
}

// n points on a circle (all cocircular) plus its centre.
inline std::vector<double> cocircular_points(int n, uint64_t seed) {
  Rng r(seed);
  std::vector<double> p;
  // Pythagorean-triple points on the circle of radius 5 and 25 are exactly cocircular.
  const int pts[][2] = {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3},
                        {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  for (int k = 0; k < 12 && k < n; ++k) p.insert(p.end(), {double(pts[k][0]), double(pts[k][1]), r.uniform()});
  p.insert(p.end(), {0.0, 0.0, r.uniform()});
  return p;
}

// A wheel: a centre and n - 1 points on a circle around it. The centre sees every
// spoke, so about a third of the points' quads meet at one vertex (its terms grow as
// 2^quads). Heights alternate up and down around the circle (the centre is mixed
// whatever the choice) or, with cone, fall away from the centre (it is convex, and
// classifying it takes every triple of neighbours).
inline std::vector<double> wheel_points(int n, bool cone = false) {
  std::vector<double> p = {0, 0, cone ? 1.0 : 0.0};
  for (int i = 0; i < n - 1; ++i) {
    const double a = 6.283185307179586 * i / (n - 1);
    p.insert(p.end(), {std::cos(a), std::sin(a), cone ? 0.0 : i % 2 ? 1.0 : -1.0});
  }
  return p;
}

// Near-degenerate point sets: points within rounding of a segment, computed as
// t a + (1 - t) b in doubles (the rounded point is just off the segment, or on it).
inline void push_on_segment(std::vector<double>& p, const double* a, const double* b, double t, double z) {
  p.insert(p.end(), {t * a[0] + (1 - t) * b[0], t * a[1] + (1 - t) * b[1], z});
}

// n - 1 random points and one within rounding of the segment between two of them:
// its triangle with the segment's ends is a sliver.
inline std::vector<double> sliver_points(int n, uint64_t seed) {
  Rng r(seed);
  std::vector<double> p = uniform_points(n - 1, seed + 1000);
  const int i = r.below(n - 1), j = (i + 1 + r.below(n - 2)) % (n - 1);
  const double a[2] = {p[3 * i], p[3 * i + 1]}, b[2] = {p[3 * j], p[3 * j + 1]};
  push_on_segment(p, a, b, 0.05 + 0.9 * r.uniform(), r.uniform());
  return p;
}

// The corners of a square rotated by a random angle, `inside` random points in it,
// and `on_edges` points computed on its edges (each within rounding of a hull edge:
// a sliver with the edge's ends, or a hull vertex a rounding error out).
inline std::vector<double> rotated_hull_points(int inside, int on_edges, uint64_t seed) {
  Rng r(seed);
  const double angle = 6.283185307179586 * r.uniform(), scale = 1 + 9 * r.uniform();
  const double ox = 100 * r.uniform() - 50, oy = 100 * r.uniform() - 50;
  double corner[4][2];
  for (int k = 0; k < 4; ++k) {
    const double x = (k == 1 || k == 2) ? 1 : -1, y = k >= 2 ? 1 : -1;
    corner[k][0] = ox + scale * (x * std::cos(angle) - y * std::sin(angle));
    corner[k][1] = oy + scale * (x * std::sin(angle) + y * std::cos(angle));
  }
  std::vector<double> p;
  for (auto& c : corner) p.insert(p.end(), {c[0], c[1], r.uniform()});
  for (int i = 0; i < inside; ++i) {
    const double s = 0.9 * (2 * r.uniform() - 1), t = 0.9 * (2 * r.uniform() - 1);
    p.insert(p.end(), {ox + scale * (s * std::cos(angle) - t * std::sin(angle)),
                       oy + scale * (s * std::sin(angle) + t * std::cos(angle)), r.uniform()});
  }
  for (int i = 0; i < on_edges; ++i) {
    const int k = r.below(4);
    push_on_segment(p, corner[k], corner[(k + 1) % 4], 0.05 + 0.9 * r.uniform(), r.uniform());
  }
  return p;
}

// n points, all within rounding of one segment (nearly, but rarely exactly, collinear).
inline std::vector<double> near_collinear_points(int n, uint64_t seed) {
  Rng r(seed);
  const double a[2] = {r.uniform(), r.uniform()}, b[2] = {1 + r.uniform(), 1 + r.uniform()};
  std::vector<double> p;
  for (int i = 0; i < n; ++i) push_on_segment(p, a, b, r.uniform(), r.uniform());
  return p;
}

// Instances of every kind the order-k engine must handle: random, DEM-like,
// integer grids with equal heights (cocircular, flat), cocircular rings. Scale 1
// stays small enough for whole-instance brute force; scale 2 gives regions of a
// few dozen triangulations and more at k = 3, 4.
inline std::vector<double> mixed_instance(uint64_t seed, int scale) {
  Rng r(seed);
  switch (seed % 4) {
    case 0: return uniform_points(6 * scale + r.below(4 * scale), seed);
    case 1: return dem_points(6 * scale + r.below(4 * scale), seed);
    case 2: return grid_points(2 + scale + r.below(2), 2 + scale, seed, true);
    default: return cocircular_points(2 + 3 * scale + r.below(6), seed);
  }
}

}  // namespace hodt::test
