// Baker's shifting at order k: the engine with forced bands against brute force
// over the k-OD triangulations that keep the bands, and the scheme's answers
// against the true optimum.
#include <doctest/doctest.h>

#include <algorithm>
#include <set>

#include "hodt/delaunay.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/points.hpp"
#include "approx/baker.hpp"
#include "generators.hpp"
#include "higher_order/k_order.hpp"
#include "mesh/mesh_of.hpp"
#include "higher_order/regions/region_engine.hpp"
#include "higher_order/search/k_order_baker.hpp"
#include "tuning/budgets.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

std::set<std::pair<uint32_t, uint32_t>> edges_of(const std::vector<Tri>& tris) {
  std::set<std::pair<uint32_t, uint32_t>> out;
  for (const Tri& t : tris)
    for (int i = 0; i < 3; ++i) out.insert({std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3])});
  return out;
}

std::vector<Tri> triangles_of(const Mesh& m) {
  std::vector<Tri> out;
  for (uint32_t t = 0; t < m.num_triangles(); ++t) out.push_back(base_triangle(m, t));
  return out;
}

}  // namespace

TEST_CASE("baker bands: every triangle at a banded depth, both halves of its edges") {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    const Mesh dt = delaunay(validate_points(uniform_points(300, seed)).xyz);
    const std::vector<uint32_t> depth = hull_depth(dt);
    for (uint32_t e = 0; e < dt.triangles.size(); ++e)
      if (dt.halfedges[e] >= 0) {
        const uint32_t a = depth[dt.origin(e)], b = depth[dt.target(e)];
        CHECK((a > b ? a - b : b - a) <= 1);
      }
    for (uint32_t s = 0; s < 3; ++s) {
      const std::vector<uint8_t> forced = baker_bands(dt, depth, 3, s);
      for (uint32_t e = 0; e < dt.triangles.size(); ++e) {
        const uint32_t t = e / 3;
        bool band = false;
        for (uint32_t f = 3 * t; f < 3 * t + 3; ++f) band = band || depth[dt.triangles[f]] % 3 == s;
        if (band) CHECK(forced[e] == 1);
        if (dt.halfedges[e] >= 0) CHECK(forced[e] == forced[static_cast<uint32_t>(dt.halfedges[e])]);
      }
    }
  }
}

TEST_CASE("forced edges: the engine's optimum equals brute force over the k-OD triangulations keeping them") {
  // Small instances are shallow: every depth is banded in turn (lambda 2), and
  // the engine must find the best triangulation that keeps the band's edges.
  uint32_t compared = 0;
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    const auto pts = seed % 4 == 0 ? grid_points(5, 5, seed, true) : mixed_instance(seed, 1);
    const Mesh dt = delaunay(validate_points(pts).xyz);
    if (dt.num_vertices() > kBudgets.brute_force_max_points) continue;
    const std::vector<uint32_t> depth = hull_depth(dt);
    for (uint32_t k : {2u, 3u}) {
      const KOrderStructure structure(dt, k, {});
      for (uint32_t s = 0; s < 2; ++s) {
        const std::vector<uint8_t> forced = baker_bands(dt, depth, 2, s);
        std::set<std::pair<uint32_t, uint32_t>> kept;
        for (uint32_t e = 0; e < dt.triangles.size(); ++e)
          if (forced[e]) kept.insert({std::min(dt.origin(e), dt.target(e)), std::max(dt.origin(e), dt.target(e))});
        const Objective objectives[] = {Objective::MaxConvexEdges, Objective::MinMixedVertices, Objective::MinLocalMinima,
                                        Objective::MinmaxEdgeAreaRatio, Objective::MaxConvexVertices};
        std::vector<double> best(std::size(objectives));
        bool have = false;
        enumerate_k_order(dt, k, 1'000'000, [&](const std::vector<Tri>& tris) {
          const auto e = edges_of(tris);
          if (!std::includes(e.begin(), e.end(), kept.begin(), kept.end())) return;
          const Mesh m = mesh_of(dt.coords, tris);
          for (size_t i = 0; i < best.size(); ++i) {
            const double v = evaluate(objectives[i], m);
            if (!have || better(info(objectives[i]).sense, v, best[i])) best[i] = v;
          }
          have = true;
        });
        REQUIRE(have);  // (Delaunay keeps every band)
        for (size_t i = 0; i < best.size(); ++i) {
          const Objective o = objectives[i];
          RegionEngine engine(dt, o, structure, k, RegionLimits{}, {}, forced);
          std::string refused;
          const auto x = engine.exact({}, refused);
          REQUIRE_MESSAGE(x, refused);
          const Mesh m = engine.R.triangulation(dt, *x);
          CHECK(is_k_order(m, dt, k));
          const auto e = edges_of(triangles_of(m));
          CHECK(std::includes(e.begin(), e.end(), kept.begin(), kept.end()));
          CHECK_MESSAGE(evaluate(o, m) == best[i], "seed ", seed, " k ", k, " shift ", s, " ", info(o).id);
          ++compared;
        }
      }
    }
  }
  CHECK(compared >= 300);
}

TEST_CASE("baker at order k: a k-OD answer between the bound and the optimum") {
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const FirstOrder fo = first_order(delaunay(validate_points(dem_points(400, seed)).xyz));
    for (Objective o : {Objective::MaxConvexEdges, Objective::MinMixedVertices}) {
      const Sense sense = info(o).sense;
      const KOrderBaker b = k_order_baker(fo.base, o, KOrderStructure(fo.base, 4, {}), 4, 0.9, 300'000);
      REQUIRE(b.triangulation);
      CHECK(b.shifts == b.lambda);
      CHECK(is_k_order(*b.triangulation, fo.base, 4));
      CHECK(evaluate(o, *b.triangulation) == b.value);
      SolveOptions approx;
      approx.method = Method::Approx;
      approx.epsilon = 0.9;
      const KOrderResult r = solve_k_order(fo, o, 4, approx);
      const double bound = r.bound.value_or(r.value);
      CHECK(!better(sense, b.value, bound));  // never past the proven bound
      CHECK(!better(sense, b.value, r.value));  // the approx answer takes the better one
    }
  }
}
