// Input validation of a terrain's points, exactly as docs/objectives.md says.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace hodt {

enum class Dedupe { Error, KeepFirst };
// Input: kept points in input order. Spatial: along spatial_order() (what the
// triangulation wants; input_index maps back).
enum class PointOrder { Input, Spatial };

// The points the triangulation uses: validated, duplicates removed if asked.
struct TerrainPoints {
  std::vector<double> xyz;            // x, y, z per kept point
  std::vector<uint32_t> input_index;  // input index of each kept point
};

// How to name point i in messages: "point 7" or, for a file, "point 7 (line 9)".
struct PointLabels {
  std::vector<int> lines;  // source line of each input point, or empty
  std::string describe(size_t i) const;
};

// The supported coordinates: 0, or a magnitude from kMinCoordinate to
// kMaxCoordinate (x, y and z alike). In this range every measure of every
// triangulation is a finite double, the exact arithmetic of the measures and
// predicates never underflows, and the predicates' fast filters keep deciding
// (subnormal coordinates defeat them: every decision exact, minutes for a solve).
// Why these bounds, in powers of two: a nonzero coordinate c has
// 2^-150 < 1e-45 <= |c| <= 1e45 < 2^150, so every coordinate is a multiple of
// 2^-202 (the ulp at 2^-150) and a nonzero difference of two is in [2^-202, 2^151].
//  - A product of two differences (squared length, area, normal component) is
//    then in [2^-404, 2^302], and a 2x2 determinant a multiple of 2^-404 below
//    2^303: every part of its exact expansion (accurate_det.hpp) is a multiple of
//    2^-404 too, far from underflow (2^-1022), and nothing nears 2^1024.
//  - Area ratios <= 2^302 / 2^-405 = 2^707; circumradii <= (2^152)^3 / 2^-403 =
//    2^859; total lengths <= 3n 2^152; normals are rescaled (measures.hpp).
//  - The predicates' smallest permanents (in-circle: 2^-404 * 2^-404 = 2^-808)
//    stay above their filters' floor (2^-900), and differences stay inside CGAL's
//    static filter bounds (in-circle: 1e-73 to 1e76; orient3d: 1e-97 to 1e102).
constexpr double kMinCoordinate = 1e-45, kMaxCoordinate = 1e45;

// Throws InputError if v is NaN, infinite or outside the supported range; the
// message names `who` ("point 7 (line 9)"), the axis (0, 1, 2: x, y, z), the value
// and the range.
void check_coordinate(double v, int axis, const std::string& who);

// Throws InputError for: a coordinate count not divisible by 3, NaN, infinite or
// out of range coordinates (naming index and coordinate), duplicate (x, y) (naming
// both indices, unless dedupe == KeepFirst), fewer than 3 points, all points collinear.
TerrainPoints validate_points(std::vector<double> xyz, Dedupe dedupe = Dedupe::Error,
                              const PointLabels& labels = {}, PointOrder order = PointOrder::Input);

}  // namespace hodt
