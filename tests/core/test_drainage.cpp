// The drainage network (drainage.hpp) against a reference written from the
// definitions (DEFINITIONS.md, "Drainage"): neighbours read off the triangles as a
// set of edges, slopes compared in CGAL's exact MP_Float arithmetic, every path
// walked down to its end, on random, DEM-like and flat integer terrains (ties in
// height and in slope everywhere), Delaunay and solved at orders 1 to 3.
#include <doctest/doctest.h>

#include <CGAL/MP_Float.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "hodt/cli.hpp"
#include "hodt/drainage.hpp"
#include "hodt/format.hpp"
#include "hodt/objectives.hpp"
#include "hodt/predicates.hpp"
#include "hodt/solve.hpp"
#include "hodt/terrain.hpp"
#include "generators.hpp"
#include "io/drainage_geojson.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

using F = CGAL::MP_Float;

// Sign of slope(v -> a) - slope(v -> b), both descents: squared slopes compared
// exactly, cross-multiplied.
int reference_compare(const double* v, const double* a, const double* b) {
  const F za = F(v[2]) - F(a[2]), zb = F(v[2]) - F(b[2]);
  const F la = (F(v[0]) - F(a[0])) * (F(v[0]) - F(a[0])) + (F(v[1]) - F(a[1])) * (F(v[1]) - F(a[1]));
  const F lb = (F(v[0]) - F(b[0])) * (F(v[0]) - F(b[0])) + (F(v[1]) - F(b[1])) * (F(v[1]) - F(b[1]));
  const F d = za * za * lb - zb * zb * la;
  return d > 0 ? 1 : d < 0 ? -1 : 0;
}

struct Reference {
  std::vector<int32_t> downstream, basin;
  std::vector<uint32_t> accumulation, pits, outlets, local_minima;
};

// Points and triangles by one indexing, as the reference reads them.
struct Triangulated {
  const std::vector<double>& xyz;
  std::vector<uint32_t> triangles;
  double max_edge;
  const double* point(uint32_t v) const { return xyz.data() + 3 * size_t(v); }
  uint32_t num_vertices() const { return static_cast<uint32_t>(xyz.size() / 3); }
  uint32_t num_triangles() const { return static_cast<uint32_t>(triangles.size() / 3); }
};

// The definitions, directly: O(n * path length), no shared code with drainage.cpp.
Reference reference(const Triangulated& m) {
  const uint32_t n = m.num_vertices();
  std::set<std::pair<uint32_t, uint32_t>> directed;
  for (uint32_t t = 0; t < m.num_triangles(); ++t)
    for (uint32_t k = 0; k < 3; ++k) directed.insert({m.triangles[3 * t + k], m.triangles[3 * t + (k + 1) % 3]});
  std::vector<std::set<uint32_t>> nb(n);
  std::vector<uint8_t> boundary(n, 0);
  for (const auto& [u, v] : directed) {
    nb[u].insert(v), nb[v].insert(u);
    if (!directed.count({v, u})) boundary[u] = boundary[v] = 1;  // a hull edge
  }
  // Within a domain: a corner of a triangle with an edge longer than max_edge.
  const double max_edge = m.max_edge;
  if (max_edge < INFINITY)
    for (uint32_t t = 0; t < m.num_triangles(); ++t) {
      bool outside = false;
      for (uint32_t k = 0; k < 3; ++k) {
        const double *p = m.point(m.triangles[3 * t + k]), *q = m.point(m.triangles[3 * t + (k + 1) % 3]);
        const F dx = F(p[0]) - F(q[0]), dy = F(p[1]) - F(q[1]);
        outside = outside || dx * dx + dy * dy > F(max_edge) * F(max_edge);
      }
      if (outside)
        for (uint32_t k = 0; k < 3; ++k) boundary[m.triangles[3 * t + k]] = 1;
    }
  Reference r;
  r.downstream.assign(n, -1);
  for (uint32_t v = 0; v < n; ++v) {
    bool minimum = true;
    for (uint32_t u : nb[v]) {  // ascending: a tie keeps the smaller index
      minimum = minimum && m.point(u)[2] > m.point(v)[2];
      if (!(m.point(u)[2] < m.point(v)[2])) continue;
      if (r.downstream[v] < 0 || reference_compare(m.point(v), m.point(u), m.point(r.downstream[v])) > 0)
        r.downstream[v] = static_cast<int32_t>(u);
    }
    if (r.downstream[v] < 0) (boundary[v] ? r.outlets : r.pits).push_back(v);
    if (minimum && !boundary[v]) r.local_minima.push_back(v);
  }
  r.basin.assign(n, -1);
  r.accumulation.assign(n, 0);
  for (uint32_t v = 0; v < n; ++v) {
    uint32_t w = v, steps = 0;
    for (;;) {
      ++r.accumulation[w];
      if (r.downstream[w] < 0) break;
      REQUIRE(m.point(static_cast<uint32_t>(r.downstream[w]))[2] < m.point(w)[2]);
      w = static_cast<uint32_t>(r.downstream[w]);
      REQUIRE(++steps <= n);  // no cycle
    }
    r.basin[v] = static_cast<int32_t>(w);
  }
  return r;
}

Reference reference(const Mesh& m) { return reference(Triangulated{m.coords.vector(), m.triangles, m.coords.max_edge()}); }

// Checks the network of a triangulation m of terrain t's points xyz (all kept)
// against the reference and its invariants, in the mesh's vertex indices and in
// the input's (which decide ties); returns the pit count.
size_t check_network(const Terrain& t, const std::vector<double>& xyz, const Mesh& m) {
  {
    const Drainage d = drainage(m);  // (the mesh's own indices)
    const Reference r = reference(m);
    CHECK(d.downstream == r.downstream);
    CHECK(d.accumulation == r.accumulation);
  }
  const Drainage d = drainage(t, m);
  const Reference r = reference(Triangulated{xyz, t.to_input(m.triangles), m.coords.max_edge()});
  const uint32_t n = m.num_vertices();
  CHECK(d.downstream == r.downstream);
  CHECK(d.basin == r.basin);
  CHECK(d.accumulation == r.accumulation);
  CHECK(d.pits == r.pits);
  CHECK(d.outlets == r.outlets);
  // Accumulations: 1 + those of the upstream neighbours; basins partition the points.
  std::vector<uint64_t> upstream_sum(n, 0);
  for (uint32_t v = 0; v < n; ++v)
    if (d.downstream[v] >= 0) upstream_sum[static_cast<uint32_t>(d.downstream[v])] += d.accumulation[v];
  for (uint32_t v = 0; v < n; ++v) CHECK(d.accumulation[v] == 1 + upstream_sum[v]);
  uint64_t basins = 0;
  for (uint32_t v : d.pits) basins += d.accumulation[v];
  for (uint32_t v : d.outlets) basins += d.accumulation[v];
  CHECK(basins == n);
  for (uint32_t v = 0; v < n; ++v) {
    const auto b = static_cast<uint32_t>(d.basin[v]);
    CHECK(d.downstream[b] == -1);
  }
  // Every local minimum is a pit, and their number is the objective's.
  const std::set<uint32_t> pits(d.pits.begin(), d.pits.end());
  for (uint32_t v : r.local_minima) CHECK(pits.count(v) == 1);
  CHECK(static_cast<double>(r.local_minima.size()) == evaluate(Objective::MinLocalMinima, m));
  CHECK(static_cast<double>(reference(m).local_minima.size()) == evaluate(Objective::MinLocalMinima, m));
  return d.pits.size();
}

std::vector<double> integer_heights(std::vector<double> p, uint64_t seed, int levels) {
  Rng r(seed);
  for (size_t i = 2; i < p.size(); i += 3) p[i] = r.below(levels);
  return p;
}

// The kinds of terrain drainage meets: random, DEM-like, and integer grids with a
// few integer heights (flats and equal slopes everywhere), two of them at UTM-like
// offsets where the differences are exact but the coordinates large.
std::vector<double> instance(uint64_t seed) {
  switch (seed % 5) {
    case 0: return uniform_points(40 + static_cast<int>(seed % 60), seed);
    case 1: return dem_points(60 + static_cast<int>(seed % 90), seed);
    case 2: return grid_points(6 + static_cast<int>(seed % 5), 7, seed, true);
    case 3: return integer_heights(jittered_grid(8, 8, 0.3, seed), seed, 3);
    default: {
      std::vector<double> p = grid_points(9, 8, seed, true);
      for (size_t i = 0; i < p.size(); i += 3) p[i] = 731012.25 + 30 * p[i], p[i + 1] = 4100000.5 + 30 * p[i + 1];
      return p;
    }
  }
}

}  // namespace

TEST_CASE("drainage: compare_descents is the exact sign of the squared slopes' difference") {
  Rng r(7);
  int ties = 0, near = 0;
  for (int i = 0; i < 30000; ++i) {
    double v[3], a[3], b[3];
    switch (i % 6) {
      case 0:  // random
        for (double* p : {v, a, b}) p[0] = r.uniform(), p[1] = r.uniform(), p[2] = r.uniform();
        break;
      case 1:  // integer lattice, small heights: exact ties
        for (double* p : {v, a, b}) p[0] = r.below(5), p[1] = r.below(5), p[2] = r.below(3);
        break;
      case 2: {  // a tie, then b moved by an ulp or two (the filter's edge)
        v[0] = 731012.3456789, v[1] = 4100000.25, v[2] = 300 + r.below(50);
        const double dx = 74.98765 * (1 + r.below(3)), dz = 1 + r.below(20);
        a[0] = v[0] + dx, a[1] = v[1], a[2] = v[2] - dz;
        b[0] = v[0], b[1] = v[1] - dx, b[2] = v[2] - dz;
        for (int k = r.below(3); k > 0; --k) b[2] = std::nextafter(b[2], r.below(2) ? 0.0 : 1e9);
        break;
      }
      case 4: {  // drops near 2^51 on a lattice: slopes within 1e-15, beyond the filter, exact integers
        const double p = 1 + r.below(1000), q = r.below(1000), z = 0x1p51 + r.below(1000);
        v[0] = 0, v[1] = 0, v[2] = 0x1p52;
        a[0] = p, a[1] = q, a[2] = v[2] - z;
        b[0] = -q, b[1] = p, b[2] = a[2] + (r.below(5) - 2);  // the same length, rotated
        break;
      }
      case 5: {  // a rotated copy of a in doubles: lengths within rounding, inexact differences
        for (double* p : {v, a}) p[0] = 100 * r.uniform(), p[1] = r.uniform(), p[2] = r.uniform();
        v[2] += 2;
        b[0] = v[0] - (a[1] - v[1]), b[1] = v[1] + (a[0] - v[0]), b[2] = a[2];
        break;
      }
      default: {  // random slopes near each other, scaled
        const double s = std::ldexp(1.0, r.below(80) - 40);
        for (double* p : {v, a, b}) p[0] = s * r.uniform(), p[1] = s * r.uniform();
        v[2] = 2 * s, a[2] = s * r.uniform(), b[2] = a[2] * (1 + 1e-15 * (r.below(3) - 1));
      }
    }
    if (!(a[2] < v[2] && b[2] < v[2]) || (a[0] == v[0] && a[1] == v[1]) || (b[0] == v[0] && b[1] == v[1])) continue;
    const int expected = reference_compare(v, a, b);
    ties += expected == 0;
    near += expected != 0 && (i % 6 == 4 || i % 6 == 5);
    CHECK(compare_descents(v, a, b) == expected);
    CHECK(compare_descents(v, b, a) == -expected);
  }
  CHECK(ties > 1000);  // the ties were met, not only the easy cases
  CHECK(near > 1000);  // and decisions beyond the filter that are not ties
}

TEST_CASE("drainage: the definition on random, DEM-like and flat grid terrains, Delaunay and solved at orders 1 to 3") {
  size_t flats = 0;  // pits that are not local minima: a flat decided them
  for (uint64_t seed = 1; seed <= 40; ++seed) {
    CAPTURE(seed);
    const std::vector<double> xyz = instance(seed);
    const Terrain t = Terrain::from_points(xyz);
    const size_t pits = check_network(t, xyz, t.structure().base);
    flats += pits - reference(t.structure().base).local_minima.size();
    for (uint32_t order = 1; order <= 3; ++order) {
      CAPTURE(order);
      SolveOptions options;
      options.order = order;
      const Solution s = solve(t.structure(), Objective::MinLocalMinima, options);
      const Mesh m = s.mesh ? *s.mesh : triangulate(t.structure(), s.choice);
      check_network(t, xyz, m);
      CHECK(static_cast<double>(reference(m).local_minima.size()) == s.value);
    }
  }
  CHECK(flats > 0);
}

TEST_CASE("drainage: within a domain, the vertices at its edge are outlets") {
  for (uint64_t seed = 1; seed <= 10; ++seed) {
    CAPTURE(seed);
    const std::vector<double> xyz = instance(seed);
    Terrain t = Terrain::from_points(xyz);
    const size_t outlets = drainage(t.structure().base).outlets.size();
    // A domain of the median edge: many triangles outside, many more outlets.
    std::vector<double> lengths;
    const Mesh& b = t.structure().base;
    for (uint32_t e = 0; e < b.triangles.size(); ++e)
      lengths.push_back(std::hypot(b.point(b.origin(e))[0] - b.point(b.target(e))[0], b.point(b.origin(e))[1] - b.point(b.target(e))[1]));
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    t.set_max_edge(lengths[lengths.size() / 2]);
    check_network(t, xyz, t.structure().base);
    CHECK(drainage(t.structure().base).outlets.size() >= outlets);
    SolveOptions options;
    options.order = 2;
    const Solution s = solve(t.structure(), Objective::MinLocalMinima, options);
    check_network(t, xyz, *s.mesh);
  }
}

TEST_CASE("drainage: in input indices, a dropped duplicate has none") {
  // A square around a low centre, the centre's duplicate last.
  const std::vector<double> xyz = {0, 0, 5, 4, 0, 6, 4, 4, 7, 0, 4, 8, 2, 2, 1, 2, 2, 3};
  const Terrain t = Terrain::from_points(xyz, Dedupe::KeepFirst);
  const Drainage d = drainage(t, t.structure().base);
  CHECK(d.downstream == std::vector<int32_t>{4, 4, 4, 4, -1, -1});
  CHECK(d.basin == std::vector<int32_t>{4, 4, 4, 4, 4, -1});
  CHECK(d.accumulation == std::vector<uint32_t>{1, 1, 1, 1, 5, 0});
  CHECK(d.pits == std::vector<uint32_t>{4});
  CHECK(d.outlets.empty());
}

TEST_CASE("drainage: a flat drains nowhere, ties go to the smaller index") {
  // A 3 x 3 grid, heights rising in x, the centre as low as the left column.
  std::vector<double> xyz;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) xyz.insert(xyz.end(), {double(i), double(j), double(i)});
  xyz[3 * 4 + 2] = 0;  // a flat with the left column, nothing lower: a pit
  const Terrain t = Terrain::from_points(xyz);
  const Drainage d = drainage(t, t.structure().base);  // (input indices)
  CHECK(d.pits == std::vector<uint32_t>{4});
  // Points 1 and 7 fall by 1 over 1 to the centre and to their left neighbour
  // (0 and 6); a diagonal, if any, is less steep: the smaller index wins.
  CHECK(d.downstream[1] == 0);
  CHECK(d.downstream[7] == 4);
  CHECK(d.downstream[4] == -1);
  for (uint32_t v : {0u, 3u, 6u}) CHECK(d.downstream[v] == -1);  // the flat left column: outlets
  CHECK(d.outlets == std::vector<uint32_t>{0, 3, 6});
  check_network(t, xyz, t.structure().base);
}

TEST_CASE("drainage: the GeoJSON has a line per drainage edge and a point per pit and outlet") {
  const std::vector<double> xyz = {0, 0, 5, 4, 0, 6, 4, 4, 7, 0, 4, 8, 2, 2, 1.5, 2, 2, 3};
  const Terrain t = Terrain::from_points(xyz, Dedupe::KeepFirst);
  const std::string g = drainage_geojson(drainage(t, t.structure().base), xyz, "EPSG:32633");
  CHECK(g.rfind("{\"type\":\"FeatureCollection\",\"crs\":{\"type\":\"name\",\"properties\":{\"name\":\"urn:ogc:def:crs:EPSG::32633\"}},\"features\":[\n", 0) == 0);
  CHECK(g.find("{\"type\":\"Feature\",\"properties\":{\"from\":0,\"to\":4,\"accumulation\":1},\"geometry\":{\"type\":\"LineString\",\"coordinates\":[[0,0,5],[2,2,1.5]]}},\n") != std::string::npos);
  CHECK(g.find("{\"type\":\"Feature\",\"properties\":{\"point\":4,\"kind\":\"pit\",\"basinSize\":5},\"geometry\":{\"type\":\"Point\",\"coordinates\":[2,2,1.5]}}\n]}\n") != std::string::npos);
  CHECK(std::count(g.begin(), g.end(), '\n') == 1 + 4 + 1 + 1);
  // A CRS that GeoJSON's named member cannot hold is left out.
  CHECK(drainage_geojson(drainage(t, t.structure().base), xyz, "+proj=utm +zone=33").find("\"crs\"") == std::string::npos);
}

TEST_CASE("format_number: the shortest round trip, found from 15 digits as from 1") {
  const auto slow = [](double v) {  // every precision in turn
    char buf[40];
    for (int prec = 1; prec <= 17; ++prec) {
      std::snprintf(buf, sizeof buf, "%.*g", prec, v);
      if (std::strtod(buf, nullptr) == v) break;
    }
    return std::string(buf);
  };
  Rng r(3);
  for (int i = 0; i < 200000; ++i) {
    double v;
    switch (i % 4) {
      case 0: {  // any bits
        uint64_t bits = r.next();
        std::memcpy(&v, &bits, sizeof v);
        if (!std::isfinite(v)) continue;
        break;
      }
      case 1: v = std::round(r.uniform() * 1e6) / std::pow(10.0, r.below(12)); break;  // short decimals
      case 2: v = 731012.3456789 + 74.98765 * r.below(1000); break;
      default: v = std::ldexp(r.uniform(), r.below(2000) - 1000); break;
    }
    if (v == std::floor(v) && std::fabs(v) < 9007199254740992.0) continue;  // (integers have their own path)
    CHECK(format_number(v) == slow(v));
  }
}

TEST_CASE("--drainage: stats and solve write the network, and print its counts") {
  std::map<std::string, std::string> files;
  const std::vector<double> xyz = uniform_points(60, 5);
  std::string text;
  for (size_t i = 0; i < xyz.size(); i += 3)
    text += format_number(xyz[i]) + " " + format_number(xyz[i + 1]) + " " + format_number(xyz[i + 2]) + "\n";
  files["p.txt"] = text;
  const Terrain t = Terrain::from_points(xyz);
  const Drainage delaunay = drainage(t, t.structure().base);
  CliHost host;
  host.read = [&](const std::string& path, std::string& error) -> std::optional<std::string> {
    if (!files.count(path)) return error = "ENOENT", std::nullopt;
    return files.at(path);
  };
  host.write = [&](const std::string& path, std::string_view bytes, std::string&) {
    files[path] = std::string(bytes);
    return true;
  };
  CliResult r = run_cli({"stats", "p.txt", "--drainage", "d.geojson", "--crs", "EPSG:2193"}, host);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find(", \"drainage\": {\"pits\": " + std::to_string(delaunay.pits.size()) + ", \"outlets\": " +
                   std::to_string(delaunay.outlets.size()) + "}") != std::string::npos);
  CHECK(files["d.geojson"] == drainage_geojson(delaunay, xyz, "EPSG:2193"));
  r = run_cli({"solve", "p.txt", "--objective", "min-local-minima", "--order", "2", "--drainage", "s.GeoJSON"}, host);
  REQUIRE(r.exit_code == 0);
  SolveOptions options;
  options.order = 2;
  const Drainage solved = drainage(t, *solve(t.structure(), Objective::MinLocalMinima, options).mesh);
  CHECK(r.out.find(", \"drainage\": {\"pits\": " + std::to_string(solved.pits.size()) + ", \"outlets\": " +
                   std::to_string(solved.outlets.size()) + "}") != std::string::npos);
  CHECK(files["s.GeoJSON"] == drainage_geojson(solved, xyz, ""));
  CHECK(solved.pits.size() < delaunay.pits.size());
  // Refusals: one line each.
  r = run_cli({"stats", "p.txt", "--drainage", "d.json"}, host);
  CHECK(r.exit_code == 2);
  CHECK(r.err == "hodt: --drainage 'd.json': the drainage network is GeoJSON; name the file .geojson\n");
  r = run_cli({"stats", "p.txt", "--drainage", "d.geojson"}, host.read);
  CHECK(r.err == "hodt: --drainage 'd.geojson': this front end writes no files\n");
  r = run_cli({"stats", "p.txt", "--drainage"}, host);
  CHECK(r.err == "hodt: --drainage needs a value\n");
}
