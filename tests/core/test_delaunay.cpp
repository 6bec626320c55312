// hodt's triangulator (core/src/mesh/delaunay.cpp) against CGAL's Delaunay_triangulation_2:
// the same triangles on random, clustered and degenerate input (grids, cocircular
// points, collinear runs on the hull, points on edges), in any input order.
#include <doctest/doctest.h>

#include <algorithm>

#include "hodt/delaunay.hpp"
#include "hodt/error.hpp"
#include "hodt/points.hpp"
#include "cgal_delaunay.hpp"
#include "generators.hpp"
#include "mesh/raster_delaunay.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

void same_as_cgal(const std::vector<double>& input) {
  std::vector<double> xyz;
  try {
    xyz = validate_points(input, Dedupe::KeepFirst).xyz;
  } catch (const InputError&) {
    return;  // a random draw with all points collinear: not a terrain
  }
  const Mesh m = delaunay(xyz);
  REQUIRE(validate(m) == "");
  CHECK(m.num_triangles() == 2 * m.num_vertices() - 2 - m.hull.size());
  CHECK(triangle_set(m) == cgal_delaunay(xyz));
}

// Small integer coordinates: many collinear triples and cocircular quadruples.
std::vector<double> integer_points(int n, int range, uint64_t seed) {
  Rng r(seed);
  std::vector<double> p;
  for (int i = 0; i < n; ++i) p.insert(p.end(), {double(r.below(range)), double(r.below(range)), r.uniform()});
  return p;
}

bool is_raster(const std::vector<double>& xyz) {
  Mesh m;
  m.coords = validate_points(xyz, Dedupe::KeepFirst).xyz;
  return raster_delaunay(m);
}

}  // namespace

TEST_CASE("triangulator equals CGAL on random and DEM-like points") {
  for (uint64_t seed = 1; seed <= 200; ++seed) {
    same_as_cgal(uniform_points(3 + int(seed % 40), seed));
    same_as_cgal(dem_points(20 + int(seed), seed));
  }
  same_as_cgal(uniform_points(20000, 1));
}

TEST_CASE("triangulator equals CGAL on degenerate input") {
  for (uint64_t seed = 1; seed <= 300; ++seed) {
    same_as_cgal(integer_points(4 + int(seed % 30), 3 + int(seed % 6), seed));  // collinear and cocircular
    same_as_cgal(shuffled(grid_points(2 + int(seed % 9), 2 + int(seed % 7), seed), seed));
    same_as_cgal(shuffled(cocircular_points(3 + int(seed % 10), seed), seed));
  }
  same_as_cgal(grid_points(100, 100, 1));
  // Collinear points first: the seed triangle comes late, and the first points lie
  // on its edges or on their extensions.
  std::vector<double> line;
  for (int i = 0; i < 30; ++i) line.insert(line.end(), {double(i), double(i), 0.0});
  line.insert(line.end(), {5.0, 0.0, 0.0, 0.0, 5.0, 0.0, 40.0, 3.0, 0.0});
  same_as_cgal(line);
  // Points on a hull edge and on its extensions.
  std::vector<double> box = {0, 0, 0, 10, 0, 0, 10, 10, 0, 0, 10, 0};
  for (int i = -5; i <= 15; i += 2) box.insert(box.end(), {double(i), 0.0, 0.0});
  same_as_cgal(box);
  same_as_cgal(shuffled(box, 3));
}

// Rasters take the closed form (raster_delaunay.hpp): the same triangles as CGAL
// at any offset, cell size and spacing (uneven columns and rows too), in any input
// order; and input that is almost a raster (a node missing, moved or added) takes
// the general construction, with the same result.
TEST_CASE("rasters: the closed form equals CGAL, and near-rasters fall back") {
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    Rng r(seed);
    const int w = 2 + r.below(12), h = 2 + r.below(12);
    std::vector<double> xs(w), ys(h);
    const double x0 = seed % 3 == 0 ? 731012.3456789 : seed % 3 == 1 ? -3.5 : 1e-20, cell = seed % 2 ? 74.98765 : 0.25;
    for (int i = 0; i < w; ++i) xs[i] = x0 + cell * i * (seed % 5 == 0 ? 1 + r.uniform() : 1.0);
    for (int j = 0; j < h; ++j) ys[j] = 4100000.25 * (seed % 4 == 0) + cell * j * (seed % 7 == 0 ? 1 + 3 * r.uniform() : 1.0);
    std::sort(xs.begin(), xs.end()), std::sort(ys.begin(), ys.end());
    std::vector<double> p;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) p.insert(p.end(), {xs[i], ys[j], r.uniform()});
    const std::vector<double> raster = seed % 2 ? shuffled(p, seed) : p;
    CHECK(is_raster(raster));
    same_as_cgal(raster);
    // A node missing, a node moved off its column, a point added inside a cell.
    if (w * h > 4) {
      std::vector<double> missing(raster.begin() + 3, raster.end());
      CHECK(!is_raster(missing));
      same_as_cgal(missing);
    }
    std::vector<double> moved = raster;
    moved[0] = std::nextafter(moved[0], INFINITY);
    CHECK(!is_raster(moved));
    same_as_cgal(moved);
    std::vector<double> added = raster;
    added.insert(added.end(), {xs[0] + (xs[1] - xs[0]) / 3, ys[0] + (ys[1] - ys[0]) / 3, 0.5});
    CHECK(!is_raster(added));
    same_as_cgal(added);
  }
  same_as_cgal(shuffled(grid_points(300, 200, 2), 2));
}
