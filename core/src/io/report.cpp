#include "hodt/report.hpp"

#include <charconv>

#include <algorithm>
#include <cmath>

#include "hodt/domain.hpp"
#include "hodt/drainage.hpp"
#include "hodt/format.hpp"
#include "hodt/higher_order.hpp"

namespace hodt {

namespace {
// The domain, when there is one: its maxEdge and how many triangles of m are outside.
std::string domain_json(const Mesh& m) {
  if (!has_domain(m)) return "";
  const std::vector<uint8_t> inside = inside_triangles(m);
  return ", \"maxEdge\": " + json_number(m.coords.max_edge()) +
         ", \"outsideTriangles\": " + std::to_string(std::count(inside.begin(), inside.end(), 0));
}
// How many pits and outlets a drainage network has (drainage.hpp).
std::string drainage_json(const Drainage& d) {
  return ", \"drainage\": {\"pits\": " + std::to_string(d.pits.size()) + ", \"outlets\": " +
         std::to_string(d.outlets.size()) + "}";
}
}  // namespace

std::string stats_json(const Terrain& t, uint32_t order, const Drainage* drainage) {
  const Mesh& m = t.structure().base;
  const size_t hull_edges = m.hull.size();
  const size_t edges = (m.triangles.size() + hull_edges) / 2;
  std::string s = "{\"points\": " + std::to_string(m.num_vertices()) +
                  ", \"triangles\": " + std::to_string(m.num_triangles()) +
                  ", \"edges\": " + std::to_string(edges) +
                  ", \"flippable\": " + std::to_string(t.structure().num_quads()) +
                  ", \"hullVertices\": " + std::to_string(m.hull.size()) + ", \"delaunay\": {";
  const auto& v = t.delaunay_values();
  for (size_t k = 0; k < kNumObjectives; ++k)
    s += (k ? ", \"" : "\"") + std::string(objectives()[k].id) + "\": " + json_number(v[k]);
  s += "}" + domain_json(m) + drainage_json(drainage ? *drainage : hodt::drainage(t, m));
  if (order > 0) {
    const auto edges = useful_edges(t.delaunay_mesh(), order);
    const auto triangles = useful_triangles(t.delaunay_mesh(), order, edges);
    s += ", \"order\": " + std::to_string(order) + ", \"usefulEdges\": " + std::to_string(edges.size()) +
         ", \"usefulTriangles\": " + std::to_string(triangles.size());
  }
  return s + "}";
}

namespace {
std::string json_escape(const std::string& in) {
  std::string out;
  for (char c : in) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) out += ' ';
    else out += c;
  }
  return out;
}

std::string triangle_json(const Terrain& t, const Tri& tri) {
  std::string s = "[";
  s += std::to_string(t.to_input(tri[0])) + ", " + std::to_string(t.to_input(tri[1])) + ", ";
  return s + std::to_string(t.to_input(tri[2])) + "]";
}

// Milliseconds to the microsecond: finer digits are noise.
std::string ms_json(double ms) { return format_number(std::round(ms * 1000) / 1000); }
}  // namespace

std::string with_triangles_json(std::string s, const std::vector<uint32_t>& tris, const std::string& key) {
  s.pop_back();  // the closing brace
  s += ", \"" + key + "\": [";
  // Millions of triangles: each formatted in place, no temporary strings.
  s.reserve(s.size() + tris.size() * 10 + 2);
  char buf[48];
  for (size_t k = 0; k + 2 < tris.size(); k += 3) {
    char* p = buf;
    if (k) *p++ = ',', *p++ = ' ';
    *p++ = '[';
    for (size_t j = 0; j < 3; ++j) {
      if (j) *p++ = ',', *p++ = ' ';
      p = std::to_chars(p, buf + sizeof buf, tris[k + j]).ptr;
    }
    *p++ = ']';
    s.append(buf, p);
  }
  return s + "]}";
}

std::string solution_json(const Terrain& t, const Solution& r, const Mesh& mesh, const Drainage& drainage,
                          bool with_trace, const PhaseTimes* times) {
  const ObjectiveInfo& oi = info(r.objective);
  std::string s = "{\"objective\": \"" + std::string(oi.id) + "\", \"sense\": \"" +
                  (oi.sense == Sense::Min ? "min" : "max") + "\", \"method\": \"" + r.method +
                  "\", \"value\": " + json_number(r.value) +
                  ", \"delaunayValue\": " + json_number(r.delaunay_value) +
                  ", \"optimal\": " + (r.optimal ? "true" : "false") +
                  ", \"bound\": " + (r.bound ? json_number(*r.bound) : "null") +
                  ", \"flipped\": " + std::to_string(r.mesh ? r.non_delaunay_edges : count_flipped(r.choice)) +
                  ", \"timeMs\": " + json_number(r.time_ms);
  if (times)
    s += ", \"times\": {\"readMs\": " + ms_json(times->read_ms) + ", \"buildMs\": " + ms_json(times->build_ms) +
         ", \"solveMs\": " + ms_json(times->solve_ms) + "}";
  if (r.order > 1) s += ", \"order\": " + std::to_string(r.order);
  s += domain_json(mesh) + drainage_json(drainage);
  if (r.method == "approx") s += std::string(", \"localSearchImproved\": ") + (r.local_search_improved ? "true" : "false");
  if (!r.details.empty()) s += ", \"details\": \"" + json_escape(r.details) + "\"";
  if (r.critical)
    s += ", \"critical\": {\"first\": " + triangle_json(t, r.critical->first) + ", \"second\": " +
         triangle_json(t, r.critical->second) + ", \"value\": " + json_number(r.critical->value) + "}";
  if (with_trace) {
    s += ", \"trace\": [";
    for (size_t k = 0; k < r.trace.size(); ++k)
      s += std::string(k ? ", " : "") + "{\"threshold\": " + json_number(r.trace[k].threshold) +
           ", \"satisfiable\": " + (r.trace[k].satisfiable ? "true" : "false") +
           ", \"clauses\": " + std::to_string(r.trace[k].clauses) + "}";
    s += "]";
  }
  if (with_trace && !r.phases.empty()) {
    s += ", \"phases\": [";
    for (size_t k = 0; k < r.phases.size(); ++k) {
      const PhaseStep& p = r.phases[k];
      s += std::string(k ? ", " : "") + "{\"phase\": \"" + json_escape(p.name) + "\", \"ms\": " + ms_json(p.ms) +
           ", \"value\": " + (p.value ? json_number(*p.value) : "null") +
           ", \"bound\": " + (p.bound ? json_number(*p.bound) : "null") +
           ", \"improved\": " + (p.improved ? "true" : "false") + ", \"tightened\": " + (p.tightened ? "true" : "false") +
           ", \"proved\": " + (p.proved ? "true" : "false") + "}";
    }
    s += "]";
  }
  return s + "}";
}

}  // namespace hodt
