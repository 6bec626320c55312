// Elementary functions computed with + - * / only, so that native and wasm builds
// (glibc vs musl) return bit-identical results: measured values that feed the
// solvers' comparisons must not differ across platforms.
#pragma once

namespace hodt {

// Arc tangent, after fdlibm's s_atan.c (error < 1 ulp).
double portable_atan(double x);
// Angle of the vector (x, y) for y >= 0, in [0, pi].
double portable_angle(double y, double x);

}  // namespace hodt
