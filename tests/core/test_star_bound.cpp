// The bound from the vertices' stars (star_bound.hpp) against brute force:
// never past the optimum, at every order, with every fan listed or some left
// out, and tight where the stars see enough.
#include <doctest/doctest.h>

#include <fstream>
#include <string>

#include "hodt/delaunay.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/points.hpp"
#include "generators.hpp"
#include "higher_order/bounds/star_bound.hpp"
#include "higher_order/bounds/star_decode.hpp"
#include "higher_order/k_order.hpp"
#include "mesh/mesh_of.hpp"
#include "higher_order/regions/region_engine.hpp"
#include "k_order_reference.hpp"
#include "objectives/objective_terms.hpp"

using namespace hodt;
using namespace hodt::test;


TEST_CASE("star bound: never past the brute-force optimum (k = 1 to 4), with fans left out too, and in tiles") {
  int runs = 0, tight = 0, partial = 0, tiled = 0;
  for_small_k_instances({1u, 2u, 3u, 4u}, 100, 19, [&](uint32_t k, uint64_t seed, const FirstOrder& fo, const KOrderStructure& structure) {
    const Mesh& dt = fo.base;
    for (const auto& oi : objectives()) {
      const double delaunay_value = evaluate(oi.objective, dt);
      StarBoundLimits limits;
      limits.iterations = 1 + static_cast<uint32_t>(seed % 3) * 100;
      if (seed % 4 == 0) limits.max_nodes_per_vertex = 1 + seed % 7, limits.max_left_out = 1;  // (some vertices left out)
      if (seed % 4 == 1) limits.max_nodes = 20 + seed % 90, limits.max_left_out = 1;  // (tiles)
      if (seed % 8 == 2) limits.max_visits = seed * 50;  // (sweeps stopped part way)
      const auto b = star_bound(dt, oi.objective, structure.candidates, delaunay_value, limits);
      if (!b) continue;
      const double want = k_order_brute_force(fo, oi.objective, k, 20'000'000).value;
      CAPTURE(k);
      CAPTURE(seed);
      CAPTURE(std::string(oi.id));
      ++runs;
      partial += b->left_out > 0;
      tiled += b->tiles > 1;
      if (oi.objective != Objective::MinTotalEdgeLength) CHECK(b->bound == std::floor(b->bound));
      if (oi.sense == Sense::Max) CHECK(b->bound >= want);
      else CHECK(b->bound <= want);
      tight += b->bound == want;
    }
  });
  MESSAGE(runs << " star bounds, " << tight << " equal to the optimum, " << partial << " with vertices left out, "
               << tiled << " in tiles");
  CHECK(runs > 1000);
  CHECK(tight > runs / 2);
  CHECK(partial > 50);
  CHECK(tiled > 100);
}

// The volcano sampled on a jittered 60 x 60 grid (tests/fixtures/make.mjs) at
// k = 5: its least number of mixed vertices is 443 (`hodt solve
// volcano-jittered-60x60.txt --objective min-mixed-vertices --order 5`, proven).
// The stars agreeing on diamonds bound it at 443; agreeing on triangles alone
// they stopped at 439.
TEST_CASE("star bound: diamonds meet the optimum of min-mixed-vertices on the jittered volcano at k = 5 (443)") {
  std::ifstream in(std::string(HODT_FIXTURES) + "/volcano-jittered-60x60.txt");
  std::string header;
  REQUIRE(std::getline(in, header));
  std::vector<double> xyz;
  for (double a; in >> a;) xyz.push_back(a);
  REQUIRE(xyz.size() == 3 * 3600);
  const FirstOrder fo = first_order(delaunay(validate_points(xyz, Dedupe::KeepFirst, {}, PointOrder::Spatial).xyz));
  const KOrderStructure structure(fo.base, 5, {});
  const auto b = star_bound(fo.base, Objective::MinMixedVertices, structure.candidates, 443);
  REQUIRE(b);
  CHECK(b->tiles == 1);
  CHECK(b->bound == 443);
  // In tiles, the vertices at a tile's border carried into the next keep
  // most of the agreement across it (tiles alone: 436 in 5, 427 in 13).
  for (const uint32_t parts : {4u, 12u}) {
    StarBoundLimits limits;
    limits.max_nodes = b->nodes / parts;
    const auto tiled = star_bound(fo.base, Objective::MinMixedVertices, structure.candidates, 443, limits);
    REQUIRE(tiled);
    CAPTURE(parts);
    MESSAGE(tiled->tiles << " tiles: " << tiled->bound);
    CHECK(tiled->tiles >= parts);
    CHECK(tiled->bound >= 440);
  }
}

TEST_CASE("star bound: sums only (counts, lengths); a triangulation's value is never past it on a large instance") {
  const FirstOrder fo = first_order(delaunay(validate_points(dem_points(300, 5)).xyz));
  const KOrderStructure structure(fo.base, 6, {});
  int applied = 0;
  for (const auto& oi : objectives()) {
    CAPTURE(std::string(oi.id));
    if (objective_terms(oi.objective, fo.base).combine == Combine::Max) {
      CHECK(!star_bound(fo.base, oi.objective, structure.candidates, evaluate(oi.objective, fo.base)));
      continue;
    }
    const KOrderResult r = solve_k_order(fo, oi.objective, 6, {});
    const auto b = star_bound(fo.base, oi.objective, structure.candidates, r.value);
    REQUIRE(b);
    ++applied;
    if (oi.sense == Sense::Max) CHECK(b->bound >= r.value);
    else CHECK(b->bound <= r.value);
    if (r.bound) CHECK(!better(oi.sense, *r.bound, b->bound));  // (the solver keeps the tighter)
  }
  CHECK(applied == 6);  // convex vertices and edges, minima, extrema, mixed vertices, total length
}

// Every triangulation read off the stars (star_decode.hpp) is a k-OD
// triangulation of the points, so never past the brute-force optimum; on these
// small instances, whose relaxations are mostly tight, most reach it. Tiny step
// budgets stop the search part way (then nothing, never a partial answer).
// In tiles (each a half to a quarter of the instance's nodes), each tile's
// decoder holds the vertices of the others at their fans in the start.
TEST_CASE("star decode: k-OD triangulations, never past the optimum, mostly at it; in tiles too") {
  int decoded = 0, optimal = 0, runs = 0, tiled = 0, tiled_decoded = 0;
  for_small_k_instances({2u, 3u, 4u}, 60, 23, [&](uint32_t k, uint64_t seed, const FirstOrder& fo, const KOrderStructure& structure) {
    const Mesh& dt = fo.base;
    for (const auto& oi : objectives()) {
      if (objective_terms(oi.objective, dt).combine != Combine::Sum) continue;
      StarBoundLimits limits;
      limits.decode = true;
      if (seed % 5 == 0) limits.decode_steps_per_vertex = 1;
      std::vector<std::vector<Tri>> found;
      auto decode = [&](const StarDecoder& d) {
        for (std::vector<Tri>& tris : d.sweeps()) found.push_back(std::move(tris));
        if (auto tris = d.repair(dt)) found.push_back(std::move(*tris));
      };
      if (seed % 3 == 1) {  // (tiles)
        StarBoundLimits whole;
        whole.iterations = 0;
        const auto all = star_bound(dt, oi.objective, structure.candidates, evaluate(oi.objective, dt), whole);
        if (!all) continue;
        limits.max_nodes = limits.max_nodes_per_vertex = std::max<uint64_t>(1, all->nodes / (2 + seed % 3));
        limits.max_left_out = 1;  // (a vertex over a tile's budget: left out, held in its tile's decoder)
        limits.start = &dt;
        limits.decoded_tile = decode;
      }
      const double delaunay_value = evaluate(oi.objective, dt);
      const auto b = star_bound(dt, oi.objective, structure.candidates, delaunay_value, limits);
      if (!b) continue;
      ++runs;
      tiled += b->tiles > 1;
      CHECK((b->tiles == 1 || !b->decoder));
      tiled_decoded += static_cast<int>(found.size());
      if (b->decoder) decode(*b->decoder);
      if (found.empty()) continue;
      const double want = k_order_brute_force(fo, oi.objective, k, 20'000'000).value;
      CAPTURE(k);
      CAPTURE(seed);
      CAPTURE(std::string(oi.id));
      for (const std::vector<Tri>& tris : found) {
        ++decoded;
        REQUIRE(tris.size() == dt.num_triangles());
        const Mesh m = mesh_of(dt.coords, tris);
        CHECK(is_k_order(m, dt, k));
        const double v = evaluate(oi.objective, m);
        CHECK(!better(oi.sense, v, want));
        CHECK(!better(oi.sense, v, b->bound));
        optimal += v == want;
      }
    }
  });
  MESSAGE(runs << " star bounds with a gap to Delaunay, " << decoded << " triangulations decoded, " << optimal << " optimal; "
               << tiled << " in tiles, " << tiled_decoded << " of those decoded");
  CHECK(decoded > 200);
  CHECK(optimal > decoded / 2);
  CHECK(tiled > 200);
  CHECK(tiled_decoded > 100);
}

TEST_CASE("star decode: a DEM at k = 8, every sweep a k-OD triangulation") {
  const FirstOrder fo = first_order(delaunay(validate_points(grid_points(12, 11, 3)).xyz));
  const KOrderStructure structure(fo.base, 8, {});
  for (const Objective o : {Objective::MaxConvexEdges, Objective::MaxConvexVertices}) {
    StarBoundLimits limits;
    limits.decode = true;
    const auto b = star_bound(fo.base, o, structure.candidates, evaluate(o, fo.base), limits);
    REQUIRE(b);
    REQUIRE(b->decoder);
    const std::vector<std::vector<Tri>> found = b->decoder->sweeps();
    CHECK(!found.empty());
    for (const std::vector<Tri>& tris : found) {
      const Mesh m = mesh_of(fo.base.coords, tris);
      CHECK(is_k_order(m, fo.base, 8));
      CHECK(evaluate(o, m) <= b->bound);
    }
  }
}

// The min-max floor from the fans: every vertex takes one of its fans, so no
// triangulation's max is below the worst vertex's best fan.
TEST_CASE("star floor: min-max objectives, never past the brute-force optimum (k = 1 to 4)") {
  int runs = 0, tight = 0;
  for_small_k_instances({1u, 2u, 3u, 4u}, 40, 29, [&](uint32_t k, uint64_t seed, const FirstOrder& fo, const KOrderStructure& structure) {
    for (const auto& oi : objectives()) {
      StarBoundLimits limits;
      if (seed % 4 == 0) limits.max_nodes_per_vertex = 1 + seed % 5;  // (some vertices say nothing)
      const auto f = star_floor(fo.base, oi.objective, structure.candidates, limits);
      if (objective_terms(oi.objective, fo.base).combine != Combine::Max) {
        CHECK(!f);
        continue;
      }
      REQUIRE(f);
      const double want = k_order_brute_force(fo, oi.objective, k, 20'000'000).value;
      CAPTURE(k);
      CAPTURE(seed);
      CAPTURE(std::string(oi.id));
      CHECK(*f <= want);
      ++runs;
      tight += *f == want;
    }
  });
  MESSAGE(runs << " floors, " << tight << " equal to the optimum");
  CHECK(runs > 800);
  CHECK(tight > runs / 10);
}
