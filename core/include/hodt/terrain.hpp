// A terrain and its first order structure: the object every front end (native
// CLI, wasm bindings) holds. Indices inside are those of the kept points; the
// *_input functions translate to the caller's input indices.
#pragma once
#include <array>
#include <memory>
#include <cstdint>
#include <string>
#include <vector>

#include "hodt/first_order.hpp"
#include "hodt/objectives.hpp"
#include "hodt/points.hpp"
#include "hodt/solution.hpp"

namespace hodt {

class Terrain {
 public:
  // Validates the points (throws InputError) and builds Delaunay + first order structure.
  static Terrain from_points(std::vector<double> xyz, Dedupe dedupe = Dedupe::Error,
                             const PointLabels& labels = {});
  // A singly-flippable triangulation given by the user (see first_order.hpp).
  static Terrain from_triangulation(const std::vector<double>& xyz, const std::vector<uint32_t>& triangles,
                                    const std::vector<uint32_t>& flippable_edges);

  const FirstOrder& structure() const { return fo_; }
  uint32_t num_input_points() const { return num_input_; }
  uint32_t to_input(uint32_t v) const { return input_index_.empty() ? v : input_index_[v]; }
  std::vector<uint32_t> to_input(std::vector<uint32_t> indices) const;
  const std::vector<uint32_t>& input_index() const { return input_index_; }

  // A triangulation of the terrain's points given as triangles in input indices
  // (for example a higher order result), in the same triangle order, validated.
  Mesh mesh_of_input_triangles(const std::vector<uint32_t>& triangles) const;

  // Checks a choice from outside (length m, bytes 0/1); throws InputError.
  void check_choice(const Choice& choice) const;
  const std::array<double, kNumObjectives>& delaunay_values() const;
  // One objective's value on the Delaunay (base) triangulation, computed once.
  double delaunay_value(Objective o) const;
  // The Delaunay triangulation of the points (the base, unless the user gave one).
  const Mesh& delaunay_mesh() const;

 private:
  FirstOrder fo_;
  std::vector<uint32_t> input_index_;  // empty: identity
  uint32_t num_input_ = 0;
  mutable std::array<double, kNumObjectives> delaunay_values_{};
  mutable std::array<bool, kNumObjectives> have_delaunay_value_{};
  mutable std::shared_ptr<const Mesh> delaunay_;  // only for user triangulations
};

}  // namespace hodt
