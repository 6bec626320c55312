#include <doctest/doctest.h>

#include <array>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "hodt/predicates.hpp"

using namespace hodt;

TEST_CASE("orient2d is exact on nearly collinear points") {
  const double a[3] = {0.5, 0.5, 0}, b[3] = {12, 12, 0}, c[3] = {24, 24, 0};
  CHECK(orient2d(a, b, c) == 0);
  const double d[3] = {0.5 + 0x1p-52, 0.5, 0};  // a tiny step off the line
  CHECK(orient2d(d, b, c) != 0);
  CHECK(orient2d(d, b, c) == -orient2d(b, d, c));
}

TEST_CASE("orient3d: above is +1 for a counterclockwise base") {
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0};
  const double up[3] = {0.3, 0.3, 1}, down[3] = {0.3, 0.3, -1}, on[3] = {5, 7, 0};
  CHECK(orient3d(a, b, c, up) == 1);
  CHECK(orient3d(a, b, c, down) == -1);
  CHECK(orient3d(a, b, c, on) == 0);
}

TEST_CASE("in_circle: strict cases and the perturbation of cocircular points") {
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {1, 1, 0}, d[3] = {0, 1, 0};
  const double in[3] = {0.5, 0.5, 0}, out[3] = {2, 2, 0};
  CHECK(in_circle(a, b, c, in));
  CHECK_FALSE(in_circle(a, b, c, out));
  // d is on the circle of a, b, c: the perturbation decides, and consistently: of
  // the two triangulations of the square exactly one is Delaunay.
  const bool d_in_abc = in_circle(a, b, c, d);
  const bool b_in_acd = in_circle(a, c, d, b);
  const bool c_in_abd = in_circle(a, b, d, c);
  const bool a_in_bcd = in_circle(b, c, d, a);
  CHECK(d_in_abc == b_in_acd);  // diagonal ac is illegal iff ... both sides agree
  CHECK(c_in_abd == a_in_bcd);
  CHECK(d_in_abc != c_in_abd);  // exactly one diagonal is legal
  // Rotating the triangle's vertices does not change the answer.
  CHECK(in_circle(b, c, a, d) == d_in_abc);
  CHECK(in_circle(c, a, b, d) == d_in_abc);
}

TEST_CASE("compare_xy is lexicographic") {
  const double a[3] = {0, 1, 0}, b[3] = {0, 2, 0}, c[3] = {-1, 5, 0};
  CHECK(compare_xy(a, b) < 0);
  CHECK(compare_xy(c, a) < 0);
  CHECK(compare_xy(a, a) == 0);
}

TEST_CASE("exact integer paths agree with CGAL on grid-like coordinates") {
  // Cocircular and collinear points with coordinates on a 0.5 grid, far from 0.
  const double base = 4096.5;
  for (int i = 0; i < 200; ++i) {
    const double a[3] = {base + (i % 7), base + (i % 5), 0}, b[3] = {base + (i % 7) + 2, base + (i % 5), 0};
    const double c[3] = {base + (i % 7) + 2, base + (i % 5) + 1.5, 0}, d[3] = {base + (i % 7), base + (i % 5) + 1.5, 0};
    CHECK(in_circle_sign(a, b, c, d) == 0);  // a rectangle: cocircular
    const double m[3] = {base + (i % 7) + 1, base + (i % 5), 0};
    CHECK(orient2d(a, m, b) == 0);
    const double e[3] = {base + (i % 7) + 1, base + (i % 5) + 0.5, 0};
    CHECK(in_circle_sign(a, b, c, e) == 1);
    CHECK(orient2d(a, b, e) == 1);
  }
}

TEST_CASE("exact paths on georeferenced grids and quantised clouds equal CGAL's exact kernel") {
  // Differences to the last point are exact there (Sterbenz), so the predicates
  // decide in scaled 128/256-bit integers; CGAL's exact kernel is the reference.
  using K = CGAL::Exact_predicates_exact_constructions_kernel;
  uint64_t state = 12345;
  auto next = [&]() { return (state = state * 6364136223846793005ULL + 1442695040888963407ULL) >> 33; };
  int zeros_2d = 0, zeros_circle = 0, zeros_3d = 0, checked = 0;
  for (const auto& [x0, y0, cell] : {std::array<double, 3>{731012.3456789, 4100000.25, 74.98765},
                                     std::array<double, 3>{500000.0, 4100000.0, 0.01},  // LiDAR, 1 cm quanta
                                     std::array<double, 3>{2667400.0, 6478700.0, 10.0},
                                     std::array<double, 3>{1e-20, 3e-20, 1e-23}}) {
    for (int trial = 0; trial < 3000; ++trial) {
      double p[4][3];
      for (auto& q : p) {
        // Small grid offsets: many ties (collinear, cocircular, coplanar).
        q[0] = x0 + cell * static_cast<double>(next() % 5);
        q[1] = y0 + cell * static_cast<double>(next() % 5);
        q[2] = 100.0 + 0.25 * static_cast<double>(next() % 3);
      }
      const K::Point_2 a(p[0][0], p[0][1]), b(p[1][0], p[1][1]), c(p[2][0], p[2][1]), d(p[3][0], p[3][1]);
      const int o2 = orient2d(p[0], p[1], p[2]);
      CHECK(o2 == static_cast<int>(CGAL::orientation(a, b, c)));
      zeros_2d += o2 == 0;
      if (o2 > 0) {
        const int s = in_circle_sign(p[0], p[1], p[2], p[3]);
        CHECK(s == static_cast<int>(CGAL::side_of_oriented_circle(a, b, c, d)));
        zeros_circle += s == 0;
        const K::Point_3 A(p[0][0], p[0][1], p[0][2]), B(p[1][0], p[1][1], p[1][2]), C(p[2][0], p[2][1], p[2][2]),
            D(p[3][0], p[3][1], p[3][2]);
        const int s3 = orient3d(p[0], p[1], p[2], p[3]);
        CHECK(s3 == static_cast<int>(CGAL::orientation(A, B, C, D)));  // (the same convention: +1 above)
        zeros_3d += s3 == 0;
      }
      ++checked;
    }
  }
  // The ties are what the exact paths are for.
  CHECK(zeros_2d > 1000);
  CHECK(zeros_circle > 200);
  CHECK(zeros_3d > 100);
  MESSAGE(checked << " configurations; ties: " << zeros_2d << " collinear, " << zeros_circle << " cocircular, " << zeros_3d
                  << " coplanar");
}
