// Exact geometric decisions. Every yes/no question of the project goes through
// these functions; measured values (areas, angles) live in measures.hpp.
#pragma once
#include <cstdint>
#include <vector>

namespace hodt {

// Sign of the xy orientation of (a, b, c): +1 counterclockwise, -1 clockwise, 0 collinear.
int orient2d(const double* a, const double* b, const double* c);

// Sign of the 3D orientation: +1 if d lies strictly above the plane through the
// lifted points a, b, c when (a, b, c) is counterclockwise in xy, -1 below, 0 on it.
int orient3d(const double* a, const double* b, const double* c, const double* d);

// Is d strictly inside the circle through a, b, c (counterclockwise)? Points on the
// circle are decided by CGAL's symbolic perturbation (lexicographic xy order), the
// same one that makes the Delaunay triangulation unique; so this predicate never
// answers "on the circle" and agrees with every decision the triangulation made.
bool in_circle(const double* a, const double* b, const double* c, const double* d);

// Unperturbed in-circle sign: +1 if d is strictly inside the circle through a, b, c
// (counterclockwise), 0 on it, -1 outside.
int in_circle_sign(const double* a, const double* b, const double* c, const double* d);

// Position of r against the circle with diameter pq: +1 inside, 0 on, -1 outside.
int diametral_sign(const double* p, const double* q, const double* r);

// Lexicographic xy order, exact: -1, 0, +1.
int compare_xy(const double* a, const double* b);

}  // namespace hodt
