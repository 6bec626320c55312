// Baker's shifting at order k (the paper's Section 4.3, Theorem 10).
//
// Vertices get depths from the hull (hull_depth, an outerplanarity peeling). For a
// shift s, every Delaunay triangle with a corner at a depth d = s (mod lambda) is
// kept (its edges forced). No useful edge crosses such a band, and no vertex or
// edge has free triangles on both of its sides (adjacent vertices' depths differ
// by at most one), so the bands cut the instance into independent rings of
// lambda - 1 layers, and the regions too large for the engine into pieces it can
// list. Each shift's problem is solved by the region engine (exactly when it
// fits) and the best shift wins: a k-OD triangulation, never a proof (the paper's
// 1 - epsilon guarantee needs every thick layer of lambda = 2k / epsilon layers
// solved exactly; the certified bound stays the relaxation's).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/objectives.hpp"
#include "hodt/progress.hpp"
#include "higher_order/regions/region_engine.hpp"

namespace hodt {

struct KOrderBaker {
  std::optional<Mesh> triangulation;  // the best shift's (none if no shift ran)
  double value = 0;
  uint32_t lambda = 0;
  bool reduced = false;       // lambda below the paper's 2k / epsilon
  uint32_t shifts = 0;        // shifts solved
  uint32_t exact_shifts = 0;  // of them, solved exactly (every piece listed)
  std::string summary() const;
};

// Per Delaunay halfedge: kept by the shift (both halves of an edge alike).
std::vector<uint8_t> baker_bands(const Mesh& delaunay, const std::vector<uint32_t>& depth, uint32_t lambda,
                                 uint32_t shift);

// structure: the instance's at order k (region_engine.hpp), restricted per shift.
KOrderBaker k_order_baker(const Mesh& delaunay, Objective o, const KOrderStructure& structure, uint32_t k,
                          double epsilon, uint64_t max_nodes, const Progress& progress = {});

}  // namespace hodt
