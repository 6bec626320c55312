#include "hodt/terrain.hpp"

#include "hodt/delaunay.hpp"
#include "hodt/domain.hpp"
#include "hodt/error.hpp"

#include <algorithm>

namespace hodt {

Terrain Terrain::from_points(std::vector<double> xyz, Dedupe dedupe, const PointLabels& labels) {
  Terrain t;
  t.num_input_ = static_cast<uint32_t>(xyz.size() / 3);
  // Vertices are numbered along a space-filling curve (cache-friendly); every
  // index leaving the terrain goes back through input_index_.
  TerrainPoints pts = validate_points(std::move(xyz), dedupe, labels, PointOrder::Spatial);
  t.input_index_ = std::move(pts.input_index);
  t.fo_ = first_order(delaunay(std::move(pts.xyz), true));
  return t;
}

Terrain Terrain::from_triangulation(const std::vector<double>& xyz, const std::vector<uint32_t>& triangles,
                                    const std::vector<uint32_t>& flippable_edges) {
  TerrainPoints pts = validate_points(xyz, Dedupe::Error);
  Terrain t;
  t.num_input_ = static_cast<uint32_t>(xyz.size() / 3);
  t.fo_ = singly_flippable(std::move(pts.xyz), triangles, flippable_edges);
  return t;
}

void Terrain::set_max_edge(double max_edge) {
  check_max_edge(max_edge);
  fo_.base.coords.set_max_edge(max_edge);
  forget_delaunay_values();
}

std::vector<uint32_t> Terrain::to_input(std::vector<uint32_t> indices) const {
  if (!input_index_.empty())
    for (uint32_t& v : indices) v = input_index_[v];
  return indices;
}

Mesh Terrain::mesh_of_input_triangles(const std::vector<uint32_t>& triangles) const {
  std::vector<int64_t> internal(num_input_, -1);
  for (uint32_t v = 0; v < fo_.base.num_vertices(); ++v) internal[to_input(v)] = v;
  if (triangles.size() % 3 != 0)
    throw InputError("triangles: " + std::to_string(triangles.size()) + " indices is not a multiple of 3");
  Mesh m;
  m.coords = fo_.base.coords;
  m.triangles.reserve(triangles.size());
  for (size_t k = 0; k < triangles.size(); ++k) {
    const uint32_t v = triangles[k];
    if (v >= num_input_ || internal[v] < 0)
      throw InputError("triangle " + std::to_string(k / 3) + ": point " + std::to_string(v) + " is not a vertex of this terrain");
    m.triangles.push_back(static_cast<uint32_t>(internal[v]));
  }
  std::string error = link_halfedges(m);
  if (error.empty()) error = validate(m);
  if (error.empty() && (m.num_triangles() != fo_.base.num_triangles() || m.hull != fo_.base.hull))
    error = "they do not triangulate the convex hull of the points";
  if (!error.empty()) throw InputError("triangles: " + error);
  return m;
}

void Terrain::check_choice(const Choice& choice) const {
  if (choice.size() != fo_.num_quads())
    throw InputError("choice has " + std::to_string(choice.size()) + " entries, expected one per quad (" +
                     std::to_string(fo_.num_quads()) + ")");
  for (size_t q = 0; q < choice.size(); ++q)
    if (choice[q] > 1)
      throw InputError("choice[" + std::to_string(q) + "] is " + std::to_string(choice[q]) + ", expected 0 or 1");
}

const Mesh& Terrain::delaunay_mesh() const {
  if (fo_.is_delaunay) return fo_.base;
  if (!delaunay_) {
    Mesh m = delaunay(fo_.base.coords.vector());
    m.coords.set_max_edge(max_edge());  // (measured within the terrain's domain too)
    delaunay_ = std::make_shared<const Mesh>(std::move(m));
  }
  return *delaunay_;
}

double Terrain::delaunay_value(Objective o, const Progress& progress) const {
  const size_t k = static_cast<size_t>(o);
  if (!have_delaunay_value_[k]) {
    delaunay_values_[k] = evaluate(o, fo_.base, progress);
    have_delaunay_value_[k] = true;
  }
  return delaunay_values_[k];
}

const std::array<double, kNumObjectives>& Terrain::delaunay_values() const {
  for (const auto& i : objectives()) delaunay_value(i.objective);
  return delaunay_values_;
}

}  // namespace hodt
