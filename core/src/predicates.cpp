#include "hodt/predicates.hpp"

#include <algorithm>

#include "hodt/kernel.hpp"

namespace hodt {
namespace {
Point2 p2(const double* p) { return Point2(p[0], p[1]); }
Point3 p3(const double* p) { return Point3(p[0], p[1], p[2]); }
int sign(CGAL::Sign s) { return static_cast<int>(s); }
}  // namespace

int orient2d(const double* a, const double* b, const double* c) {
  return sign(CGAL::orientation(p2(a), p2(b), p2(c)));
}

int orient3d(const double* a, const double* b, const double* c, const double* d) {
  return sign(CGAL::orientation(p3(a), p3(b), p3(c), p3(d)));
}

int compare_xy(const double* a, const double* b) {
  return sign(CGAL::compare_xy(p2(a), p2(b)));
}

// Mirrors Triangulation_2::side_of_oriented_circle(p0, p1, p2, p, perturb = true)
// so that this predicate and CGAL's Delaunay triangulation decide degenerate
// (cocircular) cases the same way.
bool in_circle(const double* a, const double* b, const double* c, const double* d) {
  const Point2 p0 = p2(a), p1 = p2(b), q2 = p2(c), p = p2(d);
  const CGAL::Oriented_side os = CGAL::side_of_oriented_circle(p0, p1, q2, p);
  if (os != CGAL::ON_ORIENTED_BOUNDARY) return os == CGAL::ON_POSITIVE_SIDE;
  const Point2* pts[4] = {&p0, &p1, &q2, &p};
  std::sort(pts, pts + 4, [](const Point2* u, const Point2* v) {
    return CGAL::compare_xy(*u, *v) == CGAL::SMALLER;
  });
  for (int i = 3; i > 0; --i) {
    if (pts[i] == &p) return false;
    CGAL::Orientation o;
    if (pts[i] == &q2 && (o = CGAL::orientation(p0, p1, p)) != CGAL::COLLINEAR)
      return o == CGAL::POSITIVE;
    if (pts[i] == &p1 && (o = CGAL::orientation(p0, p, q2)) != CGAL::COLLINEAR)
      return o == CGAL::POSITIVE;
    if (pts[i] == &p0 && (o = CGAL::orientation(p, p1, q2)) != CGAL::COLLINEAR)
      return o == CGAL::POSITIVE;
  }
  return false;
}

}  // namespace hodt
