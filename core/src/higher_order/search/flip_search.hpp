// Local search by flips (after the flip heuristic of de Kok, van Kreveld and
// Loeffler): flip a diagonal when both new triangles are k-OD and the objective's
// terms around the quad (objective_terms.hpp) strictly improve.
#pragma once
#include <cstdint>

#include "hodt/mesh.hpp"
#include "hodt/objectives.hpp"
#include "engines/factor_graph.hpp"
#include "higher_order/regions/vertex_term_memo.hpp"

namespace hodt {

// Improves the k-OD triangulation m (same points as `delaunay`) in place, to a
// local optimum (no single such flip improves, unless 30 passes did not reach
// one); returns the number of flips made. memo: vertex terms of the solve's stars (for this
// objective; none within a domain: vertex_term_memo.hpp).
uint32_t improve_by_flips(Mesh& m, const Mesh& delaunay, uint32_t k, Objective o, const Progress& progress = {},
                          VertexTermMemo* memo = nullptr);

}  // namespace hodt
