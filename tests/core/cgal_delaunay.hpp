// The reference: CGAL's Delaunay_triangulation_2 (exact predicates, symbolic
// perturbation) of the same points, as a set of triangles, to check hodt's own
// triangulator against.
#pragma once
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <set>
#include <vector>

#include "hodt/mesh.hpp"

namespace hodt::test {

using TriangleSet = std::set<std::array<uint32_t, 3>>;

inline std::array<uint32_t, 3> rotated_to_smallest(uint32_t a, uint32_t b, uint32_t c) {
  std::array<uint32_t, 3> t = {a, b, c};
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

inline TriangleSet cgal_delaunay(const std::vector<double>& xyz) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, K>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using DT = CGAL::Delaunay_triangulation_2<K, Tds>;
  DT dt;
  for (uint32_t i = 0; i < xyz.size() / 3; ++i) dt.insert(K::Point_2(xyz[3 * i], xyz[3 * i + 1]))->info() = i;
  TriangleSet out;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    out.insert(rotated_to_smallest(f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()));
  return out;
}

inline TriangleSet triangle_set(const Mesh& m) {
  TriangleSet out;
  for (uint32_t t = 0; t < m.num_triangles(); ++t)
    out.insert(rotated_to_smallest(m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]));
  return out;
}

}  // namespace hodt::test
