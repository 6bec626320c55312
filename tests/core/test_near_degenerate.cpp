// Near-degenerate input (issues 16 and 17): a point within rounding of a segment,
// points computed on a rotated hull edge, near-collinear and cocircular sets. Every
// measured value is checked against exact rational arithmetic (exact_reference.hpp),
// and every solve against the exact optimum over all k-OD triangulations, found by
// enumeration and evaluated exactly.
#include <doctest/doctest.h>

#include <cstdio>
#include <set>
#include <string>

#include "exact_reference.hpp"
#include "generators.hpp"
#include "hodt/cli.hpp"
#include "hodt/error.hpp"
#include "hodt/format.hpp"
#include "hodt/k_order.hpp"
#include "hodt/measures.hpp"
#include "hodt/solve.hpp"
#include "hodt/terrain.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

// Error bounds the measures promise, in ulps of the computed value: an area (or a
// normal component) is one 2x2 determinant, its sign exact; a ratio divides two.
constexpr double kAreaUlps = 4, kRatioUlps = 9, kRadiusUlps = 16, kLengthSumUlps = 64;

double promised_ulps(Objective o) {
  return o == Objective::MinmaxTriangleArea ? kAreaUlps : o == Objective::MinTotalEdgeLength ? kLengthSumUlps : kRatioUlps;
}

const Objective kMeasured[] = {Objective::MinmaxEdgeAreaRatio, Objective::MinmaxVertexAreaRatio,
                               Objective::MinmaxTriangleArea, Objective::MinTotalEdgeLength};

struct Instance {
  std::string name;
  std::vector<double> xyz;
};

// The fixture families, deterministic; `count` instances of each.
std::vector<Instance> instances(int count) {
  std::vector<Instance> out;
  for (int s = 0; s < count; ++s) {
    out.push_back({"sliver " + std::to_string(s), sliver_points(12, 7000 + s)});
    out.push_back({"rotated hull edge " + std::to_string(s), rotated_hull_points(6, 1 + s % 3, 8000 + s)});
    out.push_back({"near-collinear " + std::to_string(s), near_collinear_points(9, 9000 + s)});
  }
  // Cocircular (exactly: Pythagorean points) at every scale the input allows.
  for (double scale : {1e-44, 1e-20, 1.0, 3.0, 1e20, 1e44}) {
    std::vector<double> p = cocircular_points(12, 5);
    for (size_t i = 0; i < p.size(); i += 3) p[i] *= scale, p[i + 1] *= scale;  // powers of 10: rounded, still near-cocircular
    out.push_back({"cocircular x " + format_number(scale), p});
  }
  return out;
}

// A terrain, or nothing for a set that rounding left exactly collinear.
std::optional<Terrain> terrain_of(const Instance& in) {
  try {
    return Terrain::from_points(in.xyz);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

double radius_ulps(const double* a, const double* b, const double* c) {
  const Rational area2 = abs(exact_det(a, b, c));
  const Real r = sqrt(to_real(exact_squared_length(a, b))) * sqrt(to_real(exact_squared_length(b, c))) *
                 sqrt(to_real(exact_squared_length(c, a))) / (2 * to_real(area2));
  return ulps_off(circumradius(a, b, c), r);
}

}  // namespace

TEST_CASE("near-degenerate: areas, normals and circumradii of every k-OD triangle against exact arithmetic") {
  size_t triangles = 0, slivers = 0;
  double worst_area = 0, worst_normal = 0, worst_radius = 0;  // in ulps
  for (const Instance& in : instances(60)) {
    const auto t = terrain_of(in);
    if (!t) continue;
    const Mesh& dt = t->structure().base;
    std::set<Tri> seen;
    enumerate_k_order(dt, 3, 2'000'000, [&](const std::vector<Tri>& tris) { seen.insert(tris.begin(), tris.end()); });
    for (const Tri& tri : seen) {
      CAPTURE(in.name);
      const double *a = dt.point(tri[0]), *b = dt.point(tri[1]), *c = dt.point(tri[2]);
      const Rational area2 = exact_det(a, b, c);
      ++triangles;
      slivers += to_real(area2) < 1e-12 * to_real(exact_squared_length(a, b) + exact_squared_length(b, c));
      // The same value whatever corner comes first, within its bound of the exact area.
      const double area = triangle_area(a, b, c);
      CHECK(triangle_area(b, c, a) == area);
      CHECK(triangle_area(c, a, b) == area);
      worst_area = std::max(worst_area, ulps_off(area, area2 / 2));
      CHECK(ulps_off(area, area2 / 2) <= kAreaUlps);
      // Each normal component is such a determinant (on the planes yz, zx, xy).
      const double* corners[3] = {a, b, c};
      double n[3];
      triangle_normal(corners, n);
      const Rational exact_n[3] = {exact_det(a, b, c, 1, 2), exact_det(a, b, c, 2, 0), area2};
      // The normal may come scaled by a power of two: the one nearest to the ratio
      // of the largest components.
      int top = 0;
      for (int k = 1; k < 3; ++k)
        if (abs(exact_n[k]) > abs(exact_n[top])) top = k;
      const double ratio = n[top] / static_cast<double>(to_real(exact_n[top]));
      const Rational unit = exact(std::exp2(std::round(std::log2(std::abs(ratio)))));
      for (int k = 0; k < 3; ++k) {
        worst_normal = std::max(worst_normal, ulps_off(n[k], exact_n[k] * unit));
        CHECK(ulps_off(n[k], exact_n[k] * unit) <= kAreaUlps);
      }
      worst_radius = std::max(worst_radius, radius_ulps(a, b, c));
      CHECK(radius_ulps(a, b, c) <= kRadiusUlps);
    }
  }
  MESSAGE(triangles << " triangles checked, " << slivers << " slivers; worst ulps: area " << worst_area << ", normal "
                    << worst_normal << ", circumradius " << worst_radius);
  CHECK(slivers > 100);
}

namespace {

// One solve against the exact optimum over all k-OD triangulations.
void check_solve(const Instance& in, const Terrain& t, Objective o, uint32_t k, ExactObjectives& exact_values,
                 size_t& wrong, double& worst) {
  CAPTURE(in.name);
  CAPTURE(info(o).id);
  CAPTURE(k);
  const FirstOrder& fo = t.structure();
  Real optimum = -1;
  size_t count = 0;
  const bool complete = enumerate_k_order(fo.base, k, 5'000'000, [&](const std::vector<Tri>& tris) {
    const Real v = exact_values.value(o, tris);
    if (optimum < 0 || v < optimum) optimum = v;
    ++count;
  });
  REQUIRE(complete);
  if (k == 1) CHECK(count == (size_t(1) << fo.num_quads()));
  SolveOptions options;
  options.method = Method::Exact;
  Solution s;
  std::vector<Tri> returned;
  if (k == 1) {
    s = solve(fo, o, options);
    returned = triangles_of(triangulate(fo, s.choice));
  } else {
    s = k_order_solution(fo, o, k, options);
    REQUIRE(s.mesh);
    returned = triangles_of(*s.mesh);
  }
  CHECK(s.optimal);
  // The reported value is the returned triangulation's, within its error bound...
  const Real value = exact_values.value(o, returned);
  const double off = ulps_off(s.value, value);
  worst = std::max(worst, off);
  CHECK(off <= promised_ulps(o));
  // ...and that triangulation is optimal (up to ties within the measures' rounding).
  const Real slack = 1 + Real(4 * promised_ulps(o)) * Real(std::ldexp(1.0, -52));
  CHECK(value <= optimum * slack);
  wrong += !(off <= promised_ulps(o)) || !(value <= optimum * slack);
  // The Delaunay triangulation's value, as reported.
  CHECK(ulps_off(evaluate(o, fo.base), exact_values.value(o, triangles_of(fo.base))) <= promised_ulps(o));
}

}  // namespace

TEST_CASE("near-degenerate: solves at order 1, 2 and 3 equal the exact optimum") {
  size_t solves = 0, wrong = 0;
  double worst[kNumObjectives] = {};  // ulps of a reported value from the exact one
  int index = 0;
  for (const Instance& in : instances(100)) {
    const auto t = terrain_of(in);
    if (!t) continue;
    const Mesh& dt = t->structure().base;
    ExactObjectives exact_values([&](uint32_t v) { return dt.point(v); }, dt.num_vertices());
    const uint32_t max_order = index++ % 4 == 0 ? 3 : 2;
    for (uint32_t k = 1; k <= max_order; ++k)
      for (Objective o : kMeasured) {
        check_solve(in, *t, o, k, exact_values, wrong, worst[static_cast<size_t>(o)]);
        ++solves;
      }
  }
  MESSAGE(solves << " solves checked, " << wrong << " wrong; worst ulps: edge ratio "
                 << worst[size_t(Objective::MinmaxEdgeAreaRatio)] << ", vertex ratio "
                 << worst[size_t(Objective::MinmaxVertexAreaRatio)] << ", area " << worst[size_t(Objective::MinmaxTriangleArea)]
                 << ", total length " << worst[size_t(Objective::MinTotalEdgeLength)]);
}

TEST_CASE("near-degenerate: the CLI never prints a non-finite number") {
  for (const Instance& in : instances(8)) {
    std::string text;
    char line[100];
    for (size_t i = 0; i < in.xyz.size(); i += 3) {
      std::snprintf(line, sizeof line, "%.17g %.17g %.17g\n", in.xyz[i], in.xyz[i + 1], in.xyz[i + 2]);
      text += line;
    }
    auto read = [&](const std::string&, std::string&) -> std::optional<std::string> { return text; };
    auto run = [&](std::vector<std::string> args) {
      const CliResult r = run_cli(args, read);
      CAPTURE(in.name);
      CAPTURE(r.err);
      CHECK((r.exit_code == 0 || r.err.find("collinear") != std::string::npos));
      CHECK(r.out.find("Infinity") == std::string::npos);
      CHECK(r.out.find("NaN") == std::string::npos);
    };
    run({"stats", "p.txt", "--order", "2"});
    for (const auto& oi : objectives())
      for (const char* k : {"1", "2"}) run({"solve", "p.txt", "--objective", oi.id, "--order", k, "--method", "exact"});
  }
}
