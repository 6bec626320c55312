// Which neighbours can still change a vertex's class (convex, concave, flat,
// mixed), once some of its neighbours are known to be there.
//
// With c_w = w - v, the planes through v with every neighbour on or below them
// are the gradients a with c_w . (a, -1) >= 0 for all w: v is convex iff this
// set is not empty and v is not flat, concave likewise with "on or above", flat
// iff the two sets meet. So the class is a function of the two sets alone. By
// Farkas' lemma, once every vertex of F is a neighbour, w's constraint changes
// the "below" set only if c_w is outside cone(c_F, -e_z) (the "above" set:
// cone(c_F, +e_z)), and never when the set is already empty (e_z in cone(c_F)).
// Cone membership is decided with exact orientations, certified by a linearly
// independent triple of generators (Caratheodory); when none certifies it, the
// answer is "may change": only the "cannot change" answers must be right.
#pragma once
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "hodt/mesh.hpp"

namespace hodt {

enum class StarSide : int8_t { Below = 1, Above = -1 };  // neighbours on or below / on or above a plane

// Marks, after the vertices in a reduced neighbour list: the side is empty.
constexpr uint32_t kNoPlaneAbove = UINT32_MAX - 3, kNoPlaneBelow = UINT32_MAX - 2;

// Reduces nb (v's neighbours so far, sorted, maybe with marks) to what decides
// the planes on each of `sides`, given that `fixed` will be neighbours: a side
// with no plane left becomes its mark; on the others, the neighbours that the
// rest and `fixed` imply are dropped (in general position what remains are the
// neighbours defining the side's polygon, whatever order they came in). Equal
// results mean equal sides for every completion of the star.
void drop_implied_neighbors(const Mesh& m, uint32_t v, const std::vector<uint32_t>& fixed, std::vector<uint32_t>& nb,
                            std::initializer_list<StarSide> sides);

}  // namespace hodt
