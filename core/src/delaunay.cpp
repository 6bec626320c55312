#include "hodt/delaunay.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "hodt/kernel.hpp"

namespace hodt {

Mesh delaunay(std::vector<double> xyz) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, Kernel>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb>;
  using DT = CGAL::Delaunay_triangulation_2<Kernel, Tds>;

  const uint32_t n = static_cast<uint32_t>(xyz.size() / 3);
  std::vector<std::pair<Point2, uint32_t>> pts;
  pts.reserve(n);
  for (uint32_t i = 0; i < n; ++i) pts.emplace_back(Point2(xyz[3 * i], xyz[3 * i + 1]), i);
  Mesh m;
  {  // CGAL's triangulation is freed before the flat mesh is linked
    DT dt(pts.begin(), pts.end());
    pts = {};
    m.triangles.reserve(3 * dt.number_of_faces());
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      for (int k = 0; k < 3; ++k) m.triangles.push_back(f->vertex(k)->info());
  }
  m.coords = std::move(xyz);
  canonicalize(m);
  return m;
}

}  // namespace hodt
