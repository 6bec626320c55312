// A mesh from its triangles (counterclockwise vertex indices into coords), in
// the canonical order every triangulation of the engine is compared and
// returned in.
#pragma once
#include <vector>

#include "hodt/mesh.hpp"
#include "hodt/skeleton.hpp"

namespace hodt {

Mesh mesh_of(const Coords& coords, const std::vector<Tri>& triangles);

}  // namespace hodt
