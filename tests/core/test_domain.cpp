// The domain (maxEdge): measures read inside triangles only, and every method
// at every order optimises what the domain measures. The reference measures are
// written here from the definitions, independently of the objective terms.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "hodt/brute_force.hpp"
#include "hodt/delaunay.hpp"
#include "hodt/domain.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/measures.hpp"
#include "hodt/points.hpp"
#include "hodt/predicates.hpp"
#include "hodt/solve.hpp"
#include "hodt/terrain.hpp"
#include "generators.hpp"
#include "higher_order/bounds/star_bound.hpp"
#include "higher_order/k_order.hpp"
#include "mesh/mesh_of.hpp"
#include "higher_order/regions/region_engine.hpp"
#include "higher_order/regions/regions.hpp"
#include "higher_order/search/fan_windows.hpp"
#include "k_order_reference.hpp"
#include "objectives/objective_terms.hpp"
#include "objectives/pair_measures.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

bool close(double a, double b) { return a == b || std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)); }

double squared(const Mesh& m, uint32_t u, uint32_t v) {
  const double dx = m.point(u)[0] - m.point(v)[0], dy = m.point(u)[1] - m.point(v)[1];
  return dx * dx + dy * dy;
}

// A max_edge halfway (in squared length) between two of the Delaunay edge
// lengths, so that no edge is near it and doubles decide the reference: about
// `fraction` of the edges are long.
double max_edge_between(const Mesh& dt, double fraction) {
  std::vector<double> len;
  for (uint32_t e = 0; e < dt.triangles.size(); ++e) len.push_back(squared(dt, dt.origin(e), dt.target(e)));
  std::sort(len.begin(), len.end());
  len.erase(std::unique(len.begin(), len.end()), len.end());
  const size_t i = std::min(len.size() - 2, static_cast<size_t>(static_cast<double>(len.size()) * (1 - fraction)));
  return std::sqrt((len[i] + len[i + 1]) / 2);
}

// Every measure of docs/objectives.md ("The domain"), from the mesh's stars and edges.
double reference(Objective o, const Mesh& m) {
  const double L2 = m.coords.max_edge() * m.coords.max_edge();
  const uint32_t n = m.num_vertices(), nt = m.num_triangles();
  auto tri = [&](uint32_t t) { return Tri{m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]}; };
  std::vector<uint8_t> in(nt);
  for (uint32_t t = 0; t < nt; ++t) {
    const Tri c = tri(t);
    in[t] = squared(m, c[0], c[1]) <= L2 && squared(m, c[1], c[2]) <= L2 && squared(m, c[2], c[0]) <= L2;
  }
  std::vector<uint8_t> hull(n, 0);
  for (uint32_t v : m.hull) hull[v] = 1;
  // Per vertex: its triangles, all inside or not, neighbours over inside triangles.
  std::vector<std::vector<uint32_t>> star(n);
  for (uint32_t t = 0; t < nt; ++t)
    for (uint32_t v : tri(t)) star[v].push_back(t);
  double sum = 0, max = 0;
  auto counted = [&](uint32_t v) {  // an interior vertex whose triangles are all inside
    return !hull[v] && std::all_of(star[v].begin(), star[v].end(), [&](uint32_t t) { return in[t] != 0; });
  };
  auto neighbours = [&](uint32_t v, bool inside_only) {
    std::set<uint32_t> nb;
    for (uint32_t t : star[v])
      if (!inside_only || in[t])
        for (uint32_t w : tri(t))
          if (w != v) nb.insert(w);
    return std::vector<uint32_t>(nb.begin(), nb.end());
  };
  for (uint32_t v = 0; v < n; ++v) {
    const std::vector<uint32_t> nb = neighbours(v, false);
    std::vector<const double*> p;
    for (uint32_t w : nb) p.push_back(m.point(w));
    if (counted(v)) {
      const int ext = extremum(m.point(v), p.data(), static_cast<uint32_t>(p.size()));
      const int cls = vertex_class(m.point(v), p.data(), static_cast<uint32_t>(p.size()));
      if (o == Objective::MinLocalMinima) sum += ext == kLocalMinimum;
      if (o == Objective::MinLocalExtrema) sum += ext != kNotExtremum;
      if (o == Objective::MaxConvexVertices) sum += cls == kConvex;
      if (o == Objective::MinMixedVertices) sum += cls == kMixed;
    }
    if (o == Objective::MinmaxDegree) max = std::max(max, static_cast<double>(neighbours(v, true).size()));
    if (o == Objective::MinmaxVertexAreaRatio || o == Objective::MinmaxVertexNormalAngle)
      for (uint32_t s : star[v])
        for (uint32_t t : star[v])
          if (s < t && in[s] && in[t])
            max = std::max(max, o == Objective::MinmaxVertexAreaRatio ? pair_area_ratio(m, tri(s), tri(t))
                                                                      : pair_normal_angle(m, tri(s), tri(t)));
  }
  for (uint32_t e = 0; e < m.halfedges.size(); ++e) {
    const int32_t f = m.halfedges[e];
    if (f >= 0 && static_cast<uint32_t>(f) < e) continue;
    const bool left = in[e / 3], right = f >= 0 && in[static_cast<uint32_t>(f) / 3];
    if (o == Objective::MinTotalEdgeLength && (left || right)) sum += edge_length(m.point(m.origin(e)), m.point(m.target(e)));
    if (!left || !right) continue;
    const Tri s = tri(e / 3), t = tri(static_cast<uint32_t>(f) / 3);
    if (o == Objective::MaxConvexEdges)
      sum += edge_shape(m.point(m.origin(e)), m.point(m.target(e)), m.point(m.apex(e)),
                        m.point(m.apex(static_cast<uint32_t>(f)))) == kConvexEdge;
    if (o == Objective::MinmaxEdgeAreaRatio) max = std::max(max, pair_area_ratio(m, s, t));
    if (o == Objective::MinmaxEdgeNormalAngle) max = std::max(max, pair_normal_angle(m, s, t));
    if (o == Objective::MinmaxEdgeEnclosingCircle) max = std::max(max, pair_enclosing_circle(m, s, t));
  }
  for (uint32_t t = 0; t < nt; ++t)
    if (o == Objective::MinmaxTriangleArea && in[t]) {
      const Tri c = tri(t);
      max = std::max(max, triangle_area(m.point(c[0]), m.point(c[1]), m.point(c[2])));
    }
  const bool summed = o == Objective::MaxConvexVertices || o == Objective::MinLocalMinima || o == Objective::MinLocalExtrema ||
                      o == Objective::MinMixedVertices || o == Objective::MinTotalEdgeLength || o == Objective::MaxConvexEdges;
  return summed ? sum : max;
}

FirstOrder with_domain(uint64_t seed, double fraction) {
  FirstOrder fo = first_order(delaunay(validate_points(mixed_instance(seed, 1)).xyz));
  fo.base.coords.set_max_edge(max_edge_between(fo.base, fraction));
  return fo;
}

}  // namespace

TEST_CASE("domain: every measure reads inside triangles only, as the definitions say") {
  uint64_t outside = 0;
  for (uint64_t seed = 1; seed <= 120; ++seed) {
    const FirstOrder fo = with_domain(seed, 0.1 + 0.1 * static_cast<double>(seed % 4));
    for (uint32_t k : {1u, 3u}) {
      int seen = 0;
      enumerate_k_order(fo.base, k, 100'000, [&](const std::vector<Tri>& tris) {
        if (++seen > 12) return;
        const Mesh m = mesh_of(fo.base.coords, tris);
        const std::vector<uint8_t> in = inside_triangles(m);
        outside += static_cast<uint64_t>(std::count(in.begin(), in.end(), 0));
        for (const auto& oi : objectives()) {
          CAPTURE(seed);
          CAPTURE(oi.id);
          CHECK(close(evaluate(oi.objective, m), reference(oi.objective, m)));
        }
      });
    }
  }
  CHECK(outside > 1000);  // (the domain was at work)
}

TEST_CASE("domain: a max_edge above every edge changes nothing; exact length comparisons") {
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    FirstOrder fo = first_order(delaunay(validate_points(mixed_instance(seed, 2)).xyz));
    const auto plain = evaluate_all(fo.base);
    fo.base.coords.set_max_edge(1e9);
    CHECK(evaluate_all(fo.base) == plain);
  }
  // An edge exactly max_edge long is inside; one ulp shorter max_edge puts it out.
  const double a[3] = {0.1, 0.2, 0}, b[3] = {0.4, 0.6, 0};  // length 0.5 in decimal, not in binary
  const double len = std::hypot(0.4 - 0.1, 0.6 - 0.2);
  const int s = compare_length(a, b, len);
  CHECK(compare_length(a, b, std::nextafter(len, 0.0)) >= s);
  CHECK(compare_length(a, b, std::nextafter(len, 1.0)) <= s);
  const double p[3] = {3, 0, 0}, q[3] = {0, 4, 0};
  CHECK(compare_length(p, q, 5) == 0);
  CHECK(compare_length(p, q, std::nextafter(5.0, 0.0)) == 1);
  CHECK(compare_length(p, q, std::nextafter(5.0, 9.0)) == -1);
  const double big[3] = {1e300, 0, 0}, zero[3] = {0, 0, 0};
  CHECK(compare_length(big, zero, 1e300) == 0);
  CHECK(compare_length(big, zero, INFINITY) == -1);
}

TEST_CASE("domain: every method at orders 1 to 3 equals brute force over what the domain measures") {
  uint64_t changed = 0;
  for (uint32_t k : {1u, 2u, 3u}) {
    for (uint64_t seed = 1; seed <= 120; ++seed) {
      const FirstOrder fo = with_domain(seed * 5 + k, 0.1 + 0.1 * static_cast<double>(seed % 4));
      for (const auto& oi : objectives()) {
        CAPTURE(k);
        CAPTURE(seed);
        CAPTURE(oi.id);
        SolveOptions bf;
        bf.method = Method::BruteForce;
        bf.order = k;
        const Solution want = solve(fo, oi.objective, bf);
        for (Method method : {Method::Exact, Method::Auto}) {
          SolveOptions run;
          run.method = method;
          run.order = k;
          const Solution got = solve(fo, oi.objective, run);
          CHECK(got.optimal);
          CHECK(close(got.value, want.value));
          const Mesh m = got.mesh ? *got.mesh : triangulate(fo, got.choice);
          CHECK(got.value == evaluate(oi.objective, m));
          CHECK(is_k_order(m, fo.base, k));
          if (got.critical) CHECK(got.critical->value == got.value);
        }
        FirstOrder plain = fo;
        plain.base.coords.set_max_edge(INFINITY);
        changed += want.value != solve(plain, oi.objective, bf).value;
      }
    }
  }
  CHECK(changed > 300);  // (the domain changed many optima)
}

TEST_CASE("domain: approximations within a domain keep their bound") {
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    FirstOrder fo = first_order(delaunay(validate_points(dem_points(400, seed)).xyz));
    fo.base.coords.set_max_edge(max_edge_between(fo.base, 0.15));
    for (const auto& oi : objectives()) {
      SolveOptions approx;
      approx.method = Method::Approx;
      const Solution h = solve(fo, oi.objective, approx);
      const Solution e = solve(fo, oi.objective, {});
      CAPTURE(oi.id);
      CHECK(h.value == evaluate(oi.objective, triangulate(fo, h.choice)));
      if (e.optimal) {
        CHECK(!better(oi.sense, h.value, e.value));
        if (h.bound) CHECK(!better(oi.sense, e.value, *h.bound));
      }
    }
  }
}

TEST_CASE("domain: a terrain keeps its max_edge through edits and rejects bad lengths") {
  Terrain t = Terrain::from_points(dem_points(50, 1));
  CHECK_THROWS_AS(t.set_max_edge(0), InputError);
  CHECK_THROWS_AS(t.set_max_edge(-1), InputError);
  CHECK_THROWS_AS(t.set_max_edge(NAN), InputError);
  t.set_max_edge(0.2);
  const double before = t.delaunay_value(Objective::MinTotalEdgeLength);
  t.add_point(0.5, 0.5, 3);
  t.remove_point(t.num_input_points() - 1);
  CHECK(t.max_edge() == 0.2);
  CHECK(t.delaunay_value(Objective::MinTotalEdgeLength) == before);
  t.set_max_edge(INFINITY);
  CHECK(t.delaunay_value(Objective::MinTotalEdgeLength) > before);
}

namespace {

// A small raster with NODATA: a w x h grid (exact, or jittered), heights of few
// levels (ties) or smooth, with a few cells dropped, and max_edge between 1.2 and
// 2.5 cells, so that the holes' bridges and some diagonals are outside.
// small: a 4 x 4 raster with its points moved off the lattice (few k-OD
// triangulations, for brute force at order 3).
FirstOrder raster_with_holes(uint64_t seed, bool small = false) {
  Rng r(seed);
  int w = 4 + static_cast<int>(r.below(2)), h = 4 + static_cast<int>(r.below(2));
  bool jitter = r.below(2) != 0;
  const bool ties = r.below(2) != 0;
  if (small) w = h = 4, jitter = true;
  std::vector<double> p;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      if (r.below(6) == 0 && i > 0 && j > 0 && i + 1 < w && j + 1 < h) continue;  // a NODATA cell
      const double dx = jitter ? (static_cast<double>(r.below(1000)) / 1000 - 0.5) * 0.3 : 0;
      const double dy = jitter ? (static_cast<double>(r.below(1000)) / 1000 - 0.5) * 0.3 : 0;
      p.insert(p.end(), {i + dx, j + dy, ties ? static_cast<double>(r.below(3)) : dem_height(i / 3.0, j / 3.0, seed)});
    }
  FirstOrder fo = first_order(delaunay(validate_points(p).xyz));
  fo.base.coords.set_max_edge(1.2 + static_cast<double>(r.below(1000)) / 1000 * 1.3);
  return fo;
}

}  // namespace

TEST_CASE("domain: rasters with holes at order 1: the first order paths equal brute force") {
  // Every objective keeps its first order algorithm within a
  // domain (2-SAT, the claim structure of the extrema, the rules with the factor
  // graph on the quads touching a triangle outside), not the region engine.
  uint64_t tried = 0, changed = 0;
  for (uint64_t seed = 1; seed <= 150; ++seed) {
    const FirstOrder fo = raster_with_holes(seed);
    if (fo.num_quads() > 14) continue;  // (brute force: 2^quads triangulations per objective)
    ++tried;
    for (const auto& oi : objectives()) {
      CAPTURE(seed);
      CAPTURE(oi.id);
      SolveOptions bf;
      bf.method = Method::BruteForce;
      const Solution want = solve(fo, oi.objective, bf);
      for (Method method : {Method::Exact, Method::Auto}) {
        SolveOptions run;
        run.method = method;
        const Solution got = solve(fo, oi.objective, run);
        CHECK(got.optimal);
        CHECK(got.value == want.value);
        CHECK(got.value == evaluate(oi.objective, triangulate(fo, got.choice)));
        CHECK(got.details.find("regions") == std::string::npos);
        if (got.critical) CHECK(got.critical->value == got.value);
      }
      FirstOrder plain = fo;
      plain.base.coords.set_max_edge(INFINITY);
      changed += want.value != solve(plain, oi.objective, bf).value;
    }
  }
  MESSAGE(tried, " rasters, ", changed, " optima changed by the domain");
  CHECK(tried > 100);
  CHECK(changed > 200);  // (the domain changed many optima)
}

TEST_CASE("domain: one that leaves almost every triangle outside says so, with the count and the spacing") {
  // A 20 x 20 grid of unit cells: edges of 1 and 1.41, median 1.
  FirstOrder fo = first_order(delaunay(validate_points(grid_points(20, 20, 3)).xyz));
  CHECK(!empty_domain_warning(fo.base));  // (no domain)
  fo.base.coords.set_max_edge(5);
  CHECK(!empty_domain_warning(fo.base));  // (every triangle inside)
  fo.base.coords.set_max_edge(0.5);       // every triangle outside
  const std::optional<std::string> none = empty_domain_warning(fo.base);
  REQUIRE(none);
  CHECK(none->find("leaves 0 of " + std::to_string(fo.base.num_triangles()) + " triangles inside") != std::string::npos);
  CHECK(none->find("median Delaunay edge length) is 1") != std::string::npos);
  CHECK(none->find("maxEdge 0.5") != std::string::npos);
  // A few triangles inside, at most 1%: still a warning; all inside: none.
  std::vector<double> p = grid_points(20, 20, 3);
  for (int k = 0; k < 3; ++k) p.insert(p.end(), {20 + 0.1 * k, 0.05 * k * k, 0});
  FirstOrder few = first_order(delaunay(validate_points(p).xyz));
  few.base.coords.set_max_edge(0.5);
  const std::optional<std::string> w = empty_domain_warning(few.base);
  REQUIRE(w);
  CHECK(w->find("leaves 1 of") != std::string::npos);  // (the three added points' triangle)
  fo.base.coords.set_max_edge(1.5);
  CHECK(!empty_domain_warning(fo.base));
}

TEST_CASE("domain: rasters with holes at orders 2 and 3: every objective equals brute force") {
  // The order-k engine within a domain: the vertices away from the holes read
  // the terms without a domain and their summaries, those beside them the
  // domain's (classes with one more, a triangle outside), all against every
  // k-OD triangulation measured as the domain says. Rasters whose k-OD
  // triangulations are too many to list (cocircular cells at order 3) are
  // left out: the search tree's size bounds the test's time.
  constexpr uint64_t kNodes = 300'000;
  uint64_t tried = 0, changed = 0;
  for (uint32_t k : {2u, 3u}) {
    for (uint64_t seed = 1; seed <= 12; ++seed) {
      const FirstOrder fo = raster_with_holes(seed * 3 + k, k == 3 && seed % 2 == 0);
      const auto want = k_order_optima(fo.base, k, kNodes);
      if (!want) continue;
      FirstOrder plain = fo;
      plain.base.coords.set_max_edge(INFINITY);
      const auto without = k_order_optima(plain.base, k, kNodes);
      REQUIRE(without);  // (the same triangulations)
      ++tried;
      for (const auto& oi : objectives()) {
        CAPTURE(k);
        CAPTURE(seed);
        CAPTURE(oi.id);
        const double best = (*want)[static_cast<size_t>(oi.objective)];
        for (Method method : {Method::Exact, Method::Auto}) {
          SolveOptions run;
          run.method = method;
          run.order = k;
          const Solution got = solve(fo, oi.objective, run);
          CHECK(got.optimal);
          CHECK(got.value == best);
          REQUIRE(got.mesh);
          CHECK(got.value == evaluate(oi.objective, *got.mesh));
          CHECK(is_k_order(*got.mesh, fo.base, k));
        }
        changed += best != (*without)[static_cast<size_t>(oi.objective)];
      }
    }
  }
  MESSAGE(tried, " rasters, ", changed, " optima changed by the domain");
  CHECK(tried >= 12);
  CHECK(changed > 50);  // (the domain changed many optima)
}

TEST_CASE("domain: the vertices marked near outside are the corners of every k-OD triangle outside, and few") {
  uint64_t outside = 0, marked = 0, vertices = 0;
  for (uint64_t seed = 1; seed <= 60; ++seed) {
    const FirstOrder fo = seed % 2 ? raster_with_holes(seed) : with_domain(seed, 0.1 + 0.1 * static_cast<double>(seed % 3));
    for (uint32_t k : {1u, 2u, 3u}) {
      const std::vector<uint8_t> near = vertices_near_outside(fo.base, useful_edges(fo.base, k));
      marked += static_cast<uint64_t>(std::count(near.begin(), near.end(), 1)), vertices += near.size();
      int seen = 0;
      enumerate_k_order(fo.base, k, 100'000, [&](const std::vector<Tri>& tris) {
        if (++seen > 40) return;
        for (const Tri& t : tris)
          if (!triangle_inside(fo.base, t)) {
            ++outside;
            CAPTURE(seed);
            CAPTURE(k);
            CHECK((near[t[0]] && near[t[1]] && near[t[2]]));
          }
      });
    }
    FirstOrder all_in = fo;
    all_in.base.coords.set_max_edge(1e9);  // (a domain, every triangle inside)
    const std::vector<uint8_t> none = vertices_near_outside(all_in.base, useful_edges(all_in.base, 3));
    CHECK(std::count(none.begin(), none.end(), 1) == 0);
  }
  CHECK(outside > 1000);
  CHECK(marked < vertices);
}

namespace {

// A w x h grid of unit cells with smooth heights (cocircular: the symbolic
// perturbation decides), NODATA in the given cells' points, max_edge 3 cells
// (a raster's default): bridges over the holes are outside.
FirstOrder grid_with_holes(int w, int h, uint64_t seed, const std::vector<std::array<int, 4>>& holes) {
  std::vector<double> p;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const bool hole = std::any_of(holes.begin(), holes.end(), [&](const std::array<int, 4>& b) {
        return i >= b[0] && i < b[0] + b[2] && j >= b[1] && j < b[1] + b[3];
      });
      if (!hole) p.insert(p.end(), {double(i), double(j), dem_height(i / 9.0, j / 9.0, seed)});
    }
  FirstOrder fo = first_order(delaunay(validate_points(p).xyz));
  fo.base.coords.set_max_edge(3);
  return fo;
}

size_t regions_with_a_choice(const Regions& R) {
  return static_cast<size_t>(std::count_if(R.regions.begin(), R.regions.end(), [](const Region& g) { return g.states.size() > 1; }));
}

}  // namespace

TEST_CASE("domain: at order k the vertices away from the holes keep the fast paths, with the same optima") {
  // Each objective's engine on a grid with holes, as it runs (only the vertices
  // near a triangle that may be outside read the domain's terms), against the
  // same engine with every vertex reading them (Regions::near_outside all
  // set): equal optima, and about as few regions with a choice as without a
  // domain, where reading every vertex's triangles lists hundreds.
  const FirstOrder fo = grid_with_holes(18, 16, 3, {{4, 4, 3, 2}, {11, 9, 2, 4}, {0, 13, 2, 3}});
  const Mesh& dt = fo.base;
  FirstOrder plain = fo;
  plain.base.coords.set_max_edge(INFINITY);
  for (uint32_t k : {2u, 3u}) {
    const KOrderStructure structure(dt, k, {});
    const Regions skeleton = k_order_skeleton(dt, k, structure.useful, {});
    CHECK(std::count(skeleton.near_outside.begin(), skeleton.near_outside.end(), 1) * 4 < static_cast<long>(dt.num_vertices()));
    Regions everywhere = skeleton;
    everywhere.near_outside.assign(dt.num_vertices(), 1);
    const KOrderStructure plain_structure(plain.base, k, {});
    for (const auto& oi : objectives()) {
      CAPTURE(k);
      CAPTURE(oi.id);
      const RegionEngine fast(dt, oi.objective, structure, skeleton, RegionLimits{}, {});
      const RegionEngine slow(dt, oi.objective, structure, everywhere, RegionLimits{}, {});
      const RegionEngine none(plain.base, oi.objective, plain_structure, k, RegionLimits{}, {});
      CHECK(regions_with_a_choice(fast.R) <= regions_with_a_choice(slow.R));
      const bool by_neighbours = objective_terms_inside(oi.objective).neighbor_class || objective_terms_inside(oi.objective).drop_neighbors;
      if (by_neighbours) CHECK(regions_with_a_choice(fast.R) <= regions_with_a_choice(none.R) + regions_with_a_choice(none.R) / 2 + 10);
      if (objective_terms_inside(oi.objective).drop_neighbors) CHECK(regions_with_a_choice(fast.R) < regions_with_a_choice(slow.R));
      std::string refused_fast, refused_slow;
      const auto a = fast.exact({}, refused_fast), b = slow.exact({}, refused_slow);
      if (!a || !b) continue;
      CHECK(evaluate(oi.objective, fast.R.triangulation(dt, *a)) == evaluate(oi.objective, slow.R.triangulation(dt, *b)));
    }
  }
  // And through solve: the minima, which read classes, listed as without a domain.
  SolveOptions two;
  two.order = 2;
  const Solution in = solve(fo, Objective::MinLocalMinima, two), out = solve(plain, Objective::MinLocalMinima, two);
  CHECK(in.optimal);
  CAPTURE(in.details);
  CAPTURE(out.details);
  CHECK(in.details.substr(0, in.details.find(" regions")) == out.details.substr(0, out.details.find(" regions")));
}

TEST_CASE("domain: the vertices' fans read the domain's terms: one fan window over everything, the stars' bound and floor, against brute force (k = 1 to 3)") {
  // A fan decides which of its triangles are inside: one window over every
  // vertex finds the optimum, and the stars never bound past it.
  // (instances whose k-OD triangulations are too many to list are left out)
  int instances = 0, whole = 0, bounds = 0, floors = 0, tight = 0;
  for (uint32_t k : {1u, 2u, 3u})
    for (uint64_t seed = 1; seed <= 16; ++seed) {
      const FirstOrder fo = seed % 2 ? raster_with_holes(seed * 7 + k) : with_domain(seed * 7 + k, 0.1 + 0.1 * static_cast<double>(seed % 4));
      const Mesh& dt = fo.base;
      const KOrderStructure structure(dt, k, {});
      const auto wants = k_order_optima(dt, k, 300'000);
      if (!wants) continue;
      ++instances;
      for (const auto& oi : objectives()) {
        CAPTURE(k);
        CAPTURE(seed);
        CAPTURE(oi.id);
        const double want = (*wants)[static_cast<size_t>(oi.objective)];
        const double delaunay_value = evaluate(oi.objective, dt);
        WindowLimits all;
        all.per_window = 1u << 30, all.max_steps = 100'000'000;
        if (oi.objective != Objective::MinTotalEdgeLength && objective_terms(oi.objective, dt).combine == Combine::Sum) {
          const auto best = improve_by_windows(dt, oi.objective, structure.candidates, dt, all);
          const double got = best ? evaluate(oi.objective, mesh_of(dt.coords, *best)) : delaunay_value;
          if (best) CHECK(is_k_order(mesh_of(dt.coords, *best), dt, k));
          CHECK(got == want);
          ++whole;
        }
        if (const auto b = star_bound(dt, oi.objective, structure.candidates, delaunay_value, {})) {
          CHECK((oi.sense == Sense::Max ? b->bound >= want : b->bound <= want));
          ++bounds, tight += b->bound == want;
        }
        if (const auto f = star_floor(dt, oi.objective, structure.candidates, {})) {
          CHECK(*f <= want);
          ++floors;
        }
      }
    }
  MESSAGE(instances << " instances, " << whole << " whole windows, " << bounds << " star bounds (" << tight << " tight), " << floors << " star floors");
  CHECK(instances >= 36);
  CHECK(whole == instances * 5);  // (the counts: convex and mixed vertices, minima, extrema, convex edges)
  CHECK(bounds == whole);
  CHECK(tight > bounds / 2);
  CHECK(floors == instances * 7);  // (every min-max objective)
}
