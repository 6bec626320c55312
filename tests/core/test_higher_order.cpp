// Useful k-OD edges and triangles against a brute force over all pairs (Lemma 1
// with points scanned, no walking) on random small instances.
#include <doctest/doctest.h>

#include <set>

#include "hodt/delaunay.hpp"
#include "hodt/first_order.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/points.hpp"
#include "hodt/predicates.hpp"
#include "generators.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

uint32_t inside(const Mesh& m, uint32_t a, uint32_t b, uint32_t c) {  // a, b, c counterclockwise
  uint32_t k = 0;
  for (uint32_t v = 0; v < m.num_vertices(); ++v)
    k += v != a && v != b && v != c && in_circle(m.point(a), m.point(b), m.point(c), m.point(v));
  return k;
}

std::set<std::pair<uint32_t, uint32_t>> brute_useful_edges(const Mesh& m, uint32_t k) {
  std::set<std::pair<uint32_t, uint32_t>> out;
  const uint32_t n = m.num_vertices();
  for (uint32_t u = 0; u < n; ++u)
    for (uint32_t v = u + 1; v < n; ++v) {
      bool blocked = false;  // a point inside the segment uv
      for (uint32_t w = 0; w < n && !blocked; ++w)
        if (w != u && w != v && orient2d(m.point(u), m.point(v), m.point(w)) == 0) {
          const double* a = m.point(u);
          const double* b = m.point(v);
          const double* c = m.point(w);
          blocked = std::min(a[0], b[0]) <= c[0] && c[0] <= std::max(a[0], b[0]) &&
                    std::min(a[1], b[1]) <= c[1] && c[1] <= std::max(a[1], b[1]);
        }
      if (blocked) continue;
      bool ok = true;
      for (int side = 0; side < 2 && ok; ++side) {
        const uint32_t a = side ? v : u, b = side ? u : v;  // points left of a -> b
        int32_t s = -1;
        for (uint32_t w = 0; w < n; ++w)
          if (orient2d(m.point(a), m.point(b), m.point(w)) > 0 &&
              (s < 0 || in_circle(m.point(a), m.point(b), m.point(uint32_t(s)), m.point(w))))
            s = static_cast<int32_t>(w);
        if (s >= 0) ok = inside(m, a, b, static_cast<uint32_t>(s)) <= k;
      }
      if (ok) out.insert({u, v});
    }
  return out;
}

}  // namespace

TEST_CASE("useful k-OD edges and triangles equal a brute force on 500 instances for k = 1..4") {
  int instances = 0;
  for (uint64_t seed = 1; instances < 500; ++seed) {
    Rng r(seed);
    const int n = 6 + r.below(14);
    std::vector<double> p = seed % 4 == 0 ? dem_points(n, seed) : seed % 4 == 1 ? grid_points(3 + r.below(3), 3, seed) : uniform_points(n, seed);
    Mesh dt;
    try {
      dt = delaunay(validate_points(p, Dedupe::KeepFirst).xyz);
    } catch (const std::exception&) {
      continue;
    }
    ++instances;
    for (uint32_t k = 1; k <= 4; ++k) {
      const auto edges = useful_edges(dt, k);
      const auto brute = brute_useful_edges(dt, k);
      CHECK(std::set<std::pair<uint32_t, uint32_t>>(edges.begin(), edges.end()) == brute);
      // Triangles: all triples, every edge useful, at most k points in the circle.
      size_t expect = 0;
      const uint32_t nv = dt.num_vertices();
      for (uint32_t a = 0; a < nv; ++a)
        for (uint32_t b = a + 1; b < nv; ++b)
          for (uint32_t c = b + 1; c < nv; ++c) {
            if (!brute.count({a, b}) || !brute.count({b, c}) || !brute.count({a, c})) continue;
            const int o = orient2d(dt.point(a), dt.point(b), dt.point(c));
            if (o == 0) continue;
            expect += (o > 0 ? inside(dt, a, b, c) : inside(dt, a, c, b)) <= k;
          }
      CHECK(useful_triangles(dt, k, edges).size() == expect);
    }
    // The orders at which edges become useful give every lower order's edges.
    const UsefulEdges by_order = useful_edges_by_order(dt, 6);
    for (uint32_t j = 0; j <= 6; ++j) {
      const auto at = by_order.at(j);
      const auto brute = brute_useful_edges(dt, j);
      CHECK(std::set<std::pair<uint32_t, uint32_t>>(at.begin(), at.end()) == brute);
      CHECK(at.size() == brute.size());
    }
    // k = 1: the Delaunay edges and the flipped diagonals.
    const FirstOrder fo = first_order(dt);
    CHECK(useful_edges(dt, 1).size() == (dt.triangles.size() + dt.hull.size()) / 2 + fo.num_quads());
  }
}
