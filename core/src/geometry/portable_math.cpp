#include "geometry/portable_math.hpp"

#include <cmath>

namespace hodt {

namespace {
constexpr double kAtanHi[] = {4.63647609000806093515e-01, 7.85398163397448278999e-01,
                              9.82793723247329054082e-01, 1.57079632679489655800e+00};
constexpr double kAtanLo[] = {2.26987774529616870924e-17, 3.06161699786838301793e-17,
                              1.39033110312309984516e-17, 6.12323399573676603587e-17};
constexpr double kAT[] = {3.33333333333329318027e-01, -1.99999999998764832476e-01, 1.42857142725034663711e-01,
                          -1.11111104054623557880e-01, 9.09088713343650656196e-02, -7.69187620504482999495e-02,
                          6.66107313738753120669e-02,  -5.83357013379057348645e-02, 4.97687799461593236017e-02,
                          -3.65315727442169155270e-02, 1.62858201153657823623e-02};
constexpr double kPi = 3.14159265358979311600e+00, kPiLo = 1.2246467991473531772e-16;
}  // namespace

double portable_atan(double x) {
  if (std::isnan(x)) return x;
  const bool negative = x < 0;
  double a = negative ? -x : x;
  if (a >= 0x1p66) return negative ? -(kAtanHi[3] + kAtanLo[3]) : kAtanHi[3] + kAtanLo[3];
  int id;
  if (a < 0.4375) {
    if (a < 0x1p-27) return x;
    id = -1;
  } else if (a < 1.1875) {
    if (a < 0.6875) id = 0, a = (2.0 * a - 1.0) / (2.0 + a);
    else id = 1, a = (a - 1.0) / (a + 1.0);
  } else if (a < 2.4375) {
    id = 2, a = (a - 1.5) / (1.0 + 1.5 * a);
  } else {
    id = 3, a = -1.0 / a;
  }
  const double z = a * a, w = z * z;
  const double s1 = z * (kAT[0] + w * (kAT[2] + w * (kAT[4] + w * (kAT[6] + w * (kAT[8] + w * kAT[10])))));
  const double s2 = w * (kAT[1] + w * (kAT[3] + w * (kAT[5] + w * (kAT[7] + w * kAT[9]))));
  if (id < 0) return negative ? -(a - a * (s1 + s2)) : a - a * (s1 + s2);
  const double r = kAtanHi[id] - ((a * (s1 + s2) - kAtanLo[id]) - a);
  return negative ? -r : r;
}

double portable_angle(double y, double x) {
  if (x > 0) return portable_atan(y / x);
  if (x < 0) return (kPi - portable_atan(y / -x)) + kPiLo;
  return y > 0 ? kAtanHi[3] + kAtanLo[3] : 0.0;
}

}  // namespace hodt
