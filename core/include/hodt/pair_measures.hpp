// The pair measures of the min-max objectives, on triangles given by vertex index,
// computed exactly as evaluate_all computes them (bit-identical values).
#pragma once
#include <array>
#include <optional>

#include "hodt/mesh.hpp"
#include "hodt/objectives.hpp"
#include "hodt/skeleton.hpp"
#include "hodt/solution.hpp"

namespace hodt {

// A triangle's area and normal (measures.hpp), by vertex index.
double triangle_area(const Mesh& m, const Tri& t);
std::array<double, 3> triangle_normal(const Mesh& m, const Tri& t);

double pair_area_ratio(const Mesh& m, const Tri& s, const Tri& t);
double pair_normal_angle(const Mesh& m, const Tri& s, const Tri& t);
// The same when it exceeds `cut`, else some value <= cut (a max over pairs that
// starts at cut loses nothing): float estimates show most pairs far below the
// cut, without accurate areas or normals, arctangents or circles.
double pair_area_ratio(const Mesh& m, const Tri& s, const Tri& t, double cut);
double pair_normal_angle(const Mesh& m, const Tri& s, const Tri& t, double cut);
// The same from the two triangles' normals (triangle_normal), for callers that
// compute each triangle's normal once.
double normal_angle_above(const std::array<double, 3>& n, const std::array<double, 3>& k, double cut);
// Smallest circle around the four points of two edge-adjacent triangles; with a
// cut, as above.
double pair_enclosing_circle(const Mesh& m, const Tri& s, const Tri& t);
double pair_enclosing_circle(const Mesh& m, const Tri& s, const Tri& t, double cut);

// Is the objective a max over pairs (edge- or vertex-adjacent)?
bool is_pair_objective(Objective o);
// The pair of triangles attaining a pair objective's value on a triangulation.
std::optional<CriticalPair> critical_pair(Objective o, const Mesh& m, const Progress& progress = {});

}  // namespace hodt
