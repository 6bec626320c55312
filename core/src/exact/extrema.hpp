// Fewest local minima / extrema over first order triangulations (after Gudmundsson, Hammar and van Kreveld, 2002).
//
// Why these are optimal. A vertex v always keeps the neighbours it has through
// fixed edges; a quad's choice only decides whether its diagonal's endpoints see
// each other. Call v a *potential minimum* if it is interior and all its fixed
// neighbours are strictly higher (otherwise it is never a minimum); it is a local
// minimum unless some quad joins it, by the chosen diagonal, to a partner p with
// z_p <= z_v ("helps" it). A quad's two sides are fixed edges, so a potential
// minimum v in quad q is strictly lower than both quad vertices adjacent to it.
//
// Minima: let w be a lowest vertex of q. The diagonal not through w joins u and u',
// both adjacent to w; u would need z_u' <= z_u < z_w, impossible as w is lowest. So
// only the diagonal through a lowest vertex can help, and taking it in every quad
// helps every vertex any choice could: optimal (fewest_local_minima).
//
// Extrema (minima + maxima): each side s of quad q helps a set H_s(q) of its
// diagonal's endpoints; a side cannot help both a minimum and a maximum (that would
// need its endpoints both below and above the other two). With heights in general
// position |H_s(q)| <= 1, and the problem is to let each quad "claim" one of at most
// two vertices so as to claim as many distinct vertices as possible: in each
// connected component of the graph (vertices; a quad is an edge between its two
// candidates, or a loop when only one side helps) with V vertices and E edges and
// loops, min(V, E) vertices can be claimed (a spanning tree claims every vertex but
// its root; one more edge or loop claims the root) and no more (each edge claims
// one). When ties make some |H_s(q)| = 2, the same objective is solved exactly by
// the factor graph engine on the claim structure, component by component.
//
// Within a domain a vertex counts only if all its triangles are inside
// (docs/objectives.md, "The domain"). A vertex beside a fixed triangle outside is
// never a candidate; a side whose triangle is outside also helps that triangle's
// candidate corners. Sides can then help up to four vertices, and for minima both
// sides of a quad can help: the same claim structure, solved the same way.
#pragma once
#include "hodt/first_order.hpp"
#include "engines/factor_graph.hpp"

namespace hodt {

Choice fewest_local_minima(const FirstOrder& fo, const DpLimits& limits = {});
Choice fewest_local_extrema(const FirstOrder& fo, const DpLimits& limits = {});

}  // namespace hodt
