// The pair measures of the min-max objectives, on triangles given by vertex index,
// computed exactly as evaluate_all computes them (bit-identical values).
#pragma once
#include <cmath>
#include <optional>

#include "hodt/mesh.hpp"
#include "hodt/objectives.hpp"
#include "hodt/skeleton.hpp"
#include "hodt/solution.hpp"

namespace hodt {

// The measures of the min-max pair objectives: the objective terms name one
// per pair site (objective_terms.hpp), and each engine maps it to its own fast
// form of the measure.
enum class PairMeasure : uint8_t { None, AreaRatio, NormalAngle, EnclosingCircle };

double pair_area_ratio(const Mesh& m, const Tri& s, const Tri& t);
double pair_normal_angle(const Mesh& m, const Tri& s, const Tri& t);
// The same when it exceeds `cut`, else some value <= cut (a max over pairs that
// starts at cut loses nothing): float estimates show most pairs far below the
// cut, without accurate areas or normals, arctangents or circles.
double pair_area_ratio(const Mesh& m, const Tri& s, const Tri& t, double cut);
double pair_normal_angle(const Mesh& m, const Tri& s, const Tri& t, double cut);
// Whether every pair of the triangles t[0..n) measures at most cut, from float
// estimates (false when unsure): a star's candidates far below the cut are
// skipped whole, in time linear in its triangles rather than in its pairs.
bool star_area_ratio_below(const Mesh& m, const Tri* t, size_t n, double cut);
bool star_normal_angle_below(const Mesh& m, const Tri* t, size_t n, double cut);
// Smallest circle around the four points of two edge-adjacent triangles; with a
// cut, as above.
double pair_enclosing_circle(const Mesh& m, const Tri& s, const Tri& t);
double pair_enclosing_circle(const Mesh& m, const Tri& s, const Tri& t, double cut);

// Is the objective a max over pairs (edge- or vertex-adjacent)?
bool is_pair_objective(Objective o);
// The pair of triangles attaining a pair objective's value on a triangulation.
// expected: the value, when a solver knows it (then the pairs below it take no
// accurate measure; the answer is the same).
std::optional<CriticalPair> critical_pair(Objective o, const Mesh& m, const Progress& progress = {},
                                          double expected = -INFINITY);

}  // namespace hodt
