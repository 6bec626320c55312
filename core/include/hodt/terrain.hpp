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

  // Live edits of a terrain built from points. The triangulation and the first
  // order structure are updated around the change, and equal those of a terrain
  // built from the edited points (the same triangles and quads; their order may
  // differ). Indices are input indices: add_point appends (and returns the new
  // index), remove_point shifts later indices down by one, like splicing an array.
  // Bad values, an index out of range, a position taken by another point, or too
  // few / collinear points left throw InputError and leave the terrain unchanged.
  // Removing a point dropped as a duplicate (Dedupe::KeepFirst) only shifts the
  // indices; moving one is refused.
  uint32_t add_point(double x, double y, double z);
  void move_point(uint32_t i, double x, double y, double z);
  void remove_point(uint32_t i);

  // The domain (domain.hpp): triangles with an edge longer than max_edge are
  // not measured. Infinity (the default): no domain. Throws InputError for a
  // length that is not positive.
  double max_edge() const { return fo_.base.coords.max_edge(); }
  void set_max_edge(double max_edge);

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
  // One objective's value on the Delaunay (base) triangulation, computed once
  // (progress as for a solve, which measures it too).
  double delaunay_value(Objective o, const Progress& progress = {}) const;
  // The Delaunay triangulation of the points (the base, unless the user gave one).
  const Mesh& delaunay_mesh() const;

 private:
  uint32_t vertex_of_input(uint32_t i) const;
  void check_editable(double x, double y, double z, const std::string& what) const;
  // After a local mesh edit: recompute flippability around the changed vertices.
  void restructure(Mesh mesh, std::vector<uint8_t> marked, const std::vector<uint32_t>& changed);
  // When a local edit does not apply (hull vertex, huge star): build anew.
  void rebuild(const std::vector<double>& xyz, const std::vector<uint32_t>& input_of, uint32_t num_input);
  void forget_delaunay_values();

  FirstOrder fo_;
  std::vector<uint32_t> input_index_;  // empty: identity
  uint32_t num_input_ = 0;
  mutable std::array<double, kNumObjectives> delaunay_values_{};
  mutable std::array<bool, kNumObjectives> have_delaunay_value_{};
  mutable std::shared_ptr<const Mesh> delaunay_;  // only for user triangulations
};

}  // namespace hodt
