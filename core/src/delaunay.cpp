#include "hodt/delaunay.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "hodt/kernel.hpp"
#include "hodt/predicates.hpp"
#include "hodt/spatial_order.hpp"

namespace hodt {

namespace {

// CGAL's kernel with the project's own filtered predicates (predicates.hpp):
// CGAL's interval filters need nextafter in round-to-nearest builds (wasm), which
// makes them several times slower; the decisions are the same exact signs.
struct Traits : Kernel {
  struct Orientation_2 {
    CGAL::Orientation operator()(const Point2& p, const Point2& q, const Point2& r) const {
      const double a[2] = {p.x(), p.y()}, b[2] = {q.x(), q.y()}, c[2] = {r.x(), r.y()};
      return static_cast<CGAL::Orientation>(orient2d(a, b, c));
    }
  };
  struct Side_of_oriented_circle_2 {
    CGAL::Oriented_side operator()(const Point2& p, const Point2& q, const Point2& r, const Point2& t) const {
      const double a[2] = {p.x(), p.y()}, b[2] = {q.x(), q.y()}, c[2] = {r.x(), r.y()}, d[2] = {t.x(), t.y()};
      return static_cast<CGAL::Oriented_side>(in_circle_sign(a, b, c, d));
    }
  };
  Orientation_2 orientation_2_object() const { return {}; }
  Side_of_oriented_circle_2 side_of_oriented_circle_2_object() const { return {}; }
};

}  // namespace

Mesh delaunay(std::vector<double> xyz, bool spatially_ordered) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, Traits>;
  using Fb = CGAL::Triangulation_face_base_2<Traits>;
  using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
  using DT = CGAL::Delaunay_triangulation_2<Traits, Tds>;

  const uint32_t n = static_cast<uint32_t>(xyz.size() / 3);
  Mesh m;
  {  // CGAL's triangulation is freed before the flat mesh is linked
    // Points are inserted one by one along a Morton order, each located from the
    // previous one: short walks, and none of the copies a range insertion makes.
    DT dt;
    DT::Face_handle hint;
    const std::vector<uint32_t> order = spatially_ordered ? std::vector<uint32_t>() : spatial_order(xyz);
    for (uint32_t k = 0; k < n; ++k) {
      const uint32_t i = spatially_ordered ? k : order[k];
      const auto v = dt.insert(Point2(xyz[3 * i], xyz[3 * i + 1]), hint);
      v->info() = i;
      hint = v->face();
    }
    m.triangles.reserve(3 * dt.number_of_faces());
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      for (int k = 0; k < 3; ++k) m.triangles.push_back(f->vertex(k)->info());
  }
  m.coords = std::move(xyz);
  canonicalize(m);
  return m;
}

}  // namespace hodt
