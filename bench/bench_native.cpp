// Native side of `npm run bench`: times the same steps the wasm side times through
// the JS API (terrain, drainage, solves), on the same points (a binary file of doubles x, y, z, ... written by
// scripts/bench.mjs). Prints one JSON object of median milliseconds.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "hodt/delaunay.hpp"
#include "hodt/drainage.hpp"
#include "hodt/error.hpp"
#include "hodt/format.hpp"
#include "hodt/solve.hpp"
#include "hodt/terrain.hpp"

using namespace hodt;
using Clock = std::chrono::steady_clock;

static double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}
static double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: hodt_bench POINTS.bin REPS [--approx | --auto] [OBJECTIVE...]\n";
    return 2;
  }
  std::ifstream in(argv[1], std::ios::binary);
  std::vector<double> xyz((std::istreambuf_iterator<char>(in)), {});
  {
    std::ifstream again(argv[1], std::ios::binary);
    again.seekg(0, std::ios::end);
    xyz.resize(static_cast<size_t>(again.tellg()) / sizeof(double));
    again.seekg(0);
    again.read(reinterpret_cast<char*>(xyz.data()), static_cast<std::streamsize>(xyz.size() * sizeof(double)));
  }
  const int reps = std::stoi(argv[2]);
  // "terrain": the whole construction (what the JS API's terrain() does);
  // "structure": the first order structure alone, rebuilt from the triangulation.
  std::vector<double> triangulate, structure;
  Terrain terrain;
  for (int r = 0; r < reps; ++r) {
    auto t0 = Clock::now();
    terrain = Terrain::from_points(xyz);  // validate, order, triangulate, structure
    triangulate.push_back(ms_since(t0));
    t0 = Clock::now();
    FirstOrder fo = first_order(terrain.structure().base);
    structure.push_back(ms_since(t0));
  }
  // "drainage": the network of the Delaunay triangulation, in input indices (what
  // the JS API's terrain.drainage() computes before copying it out).
  std::vector<double> drain;
  size_t pits = 0;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = Clock::now();
    pits = drainage(terrain, terrain.structure().base).pits.size();
    drain.push_back(ms_since(t0));
  }
  std::string out = "{\"terrain\": " + format_number(median(triangulate)) +
                    ", \"structure\": " + format_number(median(structure)) + ", \"drainage\": " +
                    format_number(median(drain)) + ", \"pits\": " + std::to_string(pits) + ", \"quads\": " +
                    std::to_string(terrain.structure().num_quads()) + ", \"objectives\": {";
  const std::string flag = argc > 3 ? argv[3] : "";
  const bool approx = flag == "--approx", automatic = flag == "--auto";
  const int first = approx || automatic ? 4 : 3;
  for (int k = first; k < argc; ++k) {
    const auto o = parse_objective(argv[k]);
    if (!o) return 2;
    std::vector<double> t;
    std::string error;
    for (int r = 0; r < reps && error.empty(); ++r) {
      SolveOptions opt;
      opt.method = approx ? Method::Approx : automatic ? Method::Auto : Method::Exact;
      const auto t0 = Clock::now();
      try {
        Solution sol = solve(terrain.structure(), *o, opt);
        if (r == 0) sol.delaunay_value = terrain.delaunay_value(*o);  // as the bindings do
      } catch (const std::exception& e) {
        error = e.what();
      }
      t.push_back(ms_since(t0));
    }
    out += std::string(k > first ? ", " : "") + "\"" + argv[k] + "\": " + (error.empty() ? format_number(median(t)) : "null");
  }
  std::cout << out << "}}\n";
}
