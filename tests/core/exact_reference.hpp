// Reference values of the measured objectives in exact rational arithmetic
// (Boost.Multiprecision), built from the doubles themselves. Nothing of the
// library's measures is used here: this is what they must approximate.
#pragma once
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/cpp_int.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "hodt/objectives.hpp"
#include "hodt/skeleton.hpp"

namespace hodt::test {

using Rational = boost::multiprecision::cpp_rational;
using Real = boost::multiprecision::cpp_bin_float_50;  // for square roots: 50 digits

// The exact value of a double (subnormals included).
inline Rational exact(double v) {
  if (v == 0) return 0;
  int e = 0;
  const double m = std::frexp(v, &e);  // v = m 2^e, 0.5 <= |m| < 1
  const boost::multiprecision::cpp_int mantissa = static_cast<int64_t>(std::ldexp(m, 53));
  e -= 53;
  const boost::multiprecision::cpp_int power = boost::multiprecision::cpp_int(1) << std::abs(e);
  return e >= 0 ? Rational(mantissa * power) : Rational(mantissa, power);
}

inline Real to_real(const Rational& q) { return Real(numerator(q)) / Real(denominator(q)); }

// (b_i - a_i)(c_j - a_j) - (b_j - a_j)(c_i - a_i), exactly: twice the signed area
// of the triangle projected on coordinates (i, j).
inline Rational exact_det(const double* a, const double* b, const double* c, int i = 0, int j = 1) {
  return (exact(b[i]) - exact(a[i])) * (exact(c[j]) - exact(a[j])) -
         (exact(b[j]) - exact(a[j])) * (exact(c[i]) - exact(a[i]));
}

inline Rational exact_squared_length(const double* a, const double* b) {
  const Rational dx = exact(b[0]) - exact(a[0]), dy = exact(b[1]) - exact(a[1]);
  return dx * dx + dy * dy;
}

// How far a computed double is from the exact value, in ulps of the computed one;
// infinite when it is not finite or its sign differs (zero only matches zero).
inline double ulps_off(double computed, const Real& exact_value) {
  if (!std::isfinite(computed)) return INFINITY;
  const int s = (computed > 0) - (computed < 0), t = (exact_value > 0) - (exact_value < 0);
  if (s != t) return INFINITY;
  if (s == 0) return 0;
  const double a = std::abs(computed), ulp = std::nextafter(a, INFINITY) - a;
  return static_cast<double>(abs(Real(computed) - exact_value) / Real(ulp));
}
inline double ulps_off(double computed, const Rational& exact_value) { return ulps_off(computed, to_real(exact_value)); }

// The measured objectives of triangulations of one point set, exactly (square roots
// to 50 digits). Triangles are counterclockwise vertex triples; areas and lengths
// are cached, since an enumeration meets the same triangles again and again.
class ExactObjectives {
 public:
  template <class Point>
  explicit ExactObjectives(Point point, uint32_t n) {
    for (uint32_t v = 0; v < n; ++v) points_.push_back(point(v));
  }

  static bool supports(Objective o) {
    return o == Objective::MinmaxEdgeAreaRatio || o == Objective::MinmaxVertexAreaRatio ||
           o == Objective::MinmaxTriangleArea || o == Objective::MinTotalEdgeLength;
  }

  // Twice the area (positive for a counterclockwise triangle).
  const Rational& area2(const Tri& t) {
    std::array<uint32_t, 3> key = t;
    std::sort(key.begin(), key.end());
    auto it = area2_.find(key);
    if (it == area2_.end()) it = area2_.emplace(key, abs(exact_det(points_[t[0]], points_[t[1]], points_[t[2]]))).first;
    return it->second;
  }

  Real value(Objective o, const std::vector<Tri>& tris) {
    switch (o) {
      case Objective::MinmaxTriangleArea: {
        Rational best = 0;
        for (const Tri& t : tris) best = std::max(best, area2(t));
        return to_real(Rational(best / 2));
      }
      case Objective::MinmaxEdgeAreaRatio: {
        std::map<std::pair<uint32_t, uint32_t>, std::vector<const Rational*>> sides;
        for (const Tri& t : tris)
          for (int k = 0; k < 3; ++k) sides[std::minmax(t[k], t[(k + 1) % 3])].push_back(&area2(t));
        Rational best = 0;  // no interior edge: 0 by definition
        for (const auto& [edge, a] : sides)
          if (a.size() == 2) best = std::max(best, Rational(*a[0] > *a[1] ? *a[0] / *a[1] : *a[1] / *a[0]));
        return to_real(best);
      }
      case Objective::MinmaxVertexAreaRatio: {
        std::map<uint32_t, std::pair<Rational, Rational>> range;  // min, max area at a vertex
        std::map<uint32_t, int> count;
        for (const Tri& t : tris)
          for (uint32_t v : t) {
            const Rational& a = area2(t);
            auto [it, fresh] = range.try_emplace(v, a, a);
            if (!fresh) it->second.first = std::min(it->second.first, a), it->second.second = std::max(it->second.second, a);
            ++count[v];
          }
        Rational best = 0;
        for (const auto& [v, r] : range)
          if (count[v] >= 2) best = std::max(best, Rational(r.second / r.first));
        return to_real(best);
      }
      case Objective::MinTotalEdgeLength: {
        std::map<std::pair<uint32_t, uint32_t>, bool> edges;
        for (const Tri& t : tris)
          for (int k = 0; k < 3; ++k) edges[std::minmax(t[k], t[(k + 1) % 3])] = true;
        Real sum = 0;
        for (const auto& [e, unused] : edges) sum += length(e);
        return sum;
      }
      default:
        throw std::logic_error("no exact reference for this objective");
    }
  }

 private:
  const Real& length(std::pair<uint32_t, uint32_t> e) {
    auto it = length_.find(e);
    if (it == length_.end())
      it = length_.emplace(e, sqrt(to_real(exact_squared_length(points_[e.first], points_[e.second])))).first;
    return it->second;
  }

  std::vector<const double*> points_;
  std::map<std::array<uint32_t, 3>, Rational> area2_;
  std::map<std::pair<uint32_t, uint32_t>, Real> length_;
};

// The triangles of a mesh as vertex triples.
template <class MeshT>
std::vector<Tri> triangles_of(const MeshT& m) {
  std::vector<Tri> t;
  for (uint32_t k = 0; k < m.num_triangles(); ++k) t.push_back({m.triangles[3 * k], m.triangles[3 * k + 1], m.triangles[3 * k + 2]});
  return t;
}

}  // namespace hodt::test
