// Terrain's live edits (terrain.hpp): local Delaunay updates (delaunay_edit.hpp)
// and a local recomputation of flippability. An edge's flippability depends only
// on its two triangles and the stars of its ends (first_order.cpp), so only edges
// at vertices whose star changed need a new look.
#include <algorithm>
#include <cmath>

#include "hodt/error.hpp"
#include "hodt/format.hpp"
#include "hodt/terrain.hpp"
#include "mesh/delaunay_edit.hpp"

namespace hodt {

namespace {

std::vector<uint8_t> marks_of(const FirstOrder& fo) {
  std::vector<uint8_t> marked(fo.base.halfedges.size(), 0);
  for (const Quad& q : fo.quads) marked[q.edge] = 1;
  return marked;
}

void follow_moves(std::vector<uint8_t>& marked, const MeshEdit& edit) {
  for (const auto& [from, to] : edit.moved_triangles) std::copy_n(&marked[3 * from], 3, &marked[3 * to]);
}

}  // namespace

uint32_t Terrain::vertex_of_input(uint32_t i) const {
  if (i >= num_input_)
    throw InputError("point " + std::to_string(i) + " is out of range (" + std::to_string(num_input_) + " points)");
  const auto it = std::find(input_index_.begin(), input_index_.end(), i);
  if (it == input_index_.end()) throw InputError("point " + std::to_string(i) + " was dropped as a duplicate");
  return static_cast<uint32_t>(it - input_index_.begin());
}

void Terrain::check_editable(double x, double y, double z, const std::string& what) const {
  if (!fo_.is_delaunay || input_index_.empty())
    throw InputError("only a terrain built from points can be edited (this one is a given triangulation)");
  const double v[3] = {x, y, z};
  for (int k = 0; k < 3; ++k) check_coordinate(v[k], k, what);
}

void Terrain::forget_delaunay_values() {
  have_delaunay_value_.fill(false);
  delaunay_.reset();
}

void Terrain::restructure(Mesh mesh, std::vector<uint8_t> marked, const std::vector<uint32_t>& changed) {
  marked.resize(mesh.halfedges.size(), 0);
  const std::vector<int32_t> out = vertex_halfedges(mesh);
  for (uint32_t w : changed) {
    const uint32_t start = static_cast<uint32_t>(out[w]);
    uint32_t e = start;
    for (;;) {  // every edge at w: e (w -> .) and prev(e) (. -> w) of each triangle
      for (uint32_t h : {e, prev_halfedge(e)}) {
        const int32_t f = mesh.halfedges[h];
        marked[h] = 0;
        if (f < 0) continue;
        const uint32_t g = static_cast<uint32_t>(f), rep = std::min(h, g);
        marked[std::max(h, g)] = 0;
        marked[rep] = flippable(mesh, out, rep);
      }
      const int32_t t = mesh.halfedges[prev_halfedge(e)];
      if (t < 0) break;
      e = static_cast<uint32_t>(t);
      if (e == start) break;
    }
  }
  fo_ = first_order_of_marked(std::move(mesh), marked);
  forget_delaunay_values();
}

void Terrain::rebuild(const std::vector<double>& xyz, const std::vector<uint32_t>& input_of, uint32_t num_input) {
  Terrain t = from_points(xyz);
  t.fo_.base.coords.set_max_edge(max_edge());
  for (uint32_t& i : t.input_index_) i = input_of[i];
  t.num_input_ = num_input;
  *this = std::move(t);
}

uint32_t Terrain::add_point(double x, double y, double z) {
  const uint32_t i = num_input_;
  check_editable(x, y, z, "point " + std::to_string(i));
  const int64_t w = vertex_at(fo_.base, x, y);
  if (w >= 0)
    throw InputError("point " + std::to_string(i) + " has the same (x, y) = (" + format_number(x) + ", " +
                     format_number(y) + ") as point " + std::to_string(to_input(static_cast<uint32_t>(w))));
  std::vector<uint8_t> marked = marks_of(fo_);
  Mesh m = std::move(fo_.base);
  const MeshEdit edit = insert_vertex(m, x, y, z);
  input_index_.push_back(i);
  ++num_input_;
  restructure(std::move(m), std::move(marked), edit.changed_vertices);
  return i;
}

void Terrain::move_point(uint32_t i, double x, double y, double z) {
  check_editable(x, y, z, "point " + std::to_string(i));
  const uint32_t v = vertex_of_input(i);
  const double* p = fo_.base.point(v);
  if (p[0] == x && p[1] == y) {  // a new height only: the structure is planar
    fo_.base.coords.write()[3 * size_t(v) + 2] = z;
    forget_delaunay_values();
    return;
  }
  const int64_t w = vertex_at(fo_.base, x, y);
  if (w >= 0)
    throw InputError("point " + std::to_string(i) + " cannot move to (" + format_number(x) + ", " + format_number(y) +
                     "): point " + std::to_string(to_input(static_cast<uint32_t>(w))) + " is there");
  std::vector<uint8_t> marked = marks_of(fo_);
  MeshEdit edit;
  if (!remove_vertex(fo_.base, v, edit)) {
    std::vector<double> xyz = fo_.base.coords.vector();
    xyz[3 * size_t(v)] = x, xyz[3 * size_t(v) + 1] = y, xyz[3 * size_t(v) + 2] = z;
    rebuild(xyz, input_index_, num_input_);
    return;
  }
  input_index_[v] = input_index_.back();  // the last vertex took number v
  input_index_.pop_back();
  follow_moves(marked, edit);
  Mesh m = std::move(fo_.base);
  const MeshEdit inserted = insert_vertex(m, x, y, z);
  input_index_.push_back(i);
  std::vector<uint32_t> changed = std::move(edit.changed_vertices);
  changed.insert(changed.end(), inserted.changed_vertices.begin(), inserted.changed_vertices.end());
  restructure(std::move(m), std::move(marked), changed);
}

void Terrain::remove_point(uint32_t i) {
  check_editable(0, 0, 0, "point " + std::to_string(i));
  auto shift = [i](uint32_t k) { return k > i ? k - 1 : k; };
  if (i < num_input_ && std::find(input_index_.begin(), input_index_.end(), i) == input_index_.end()) {
    // A duplicate dropped when the terrain was built: it has no vertex, so only
    // the later points' indices change.
    for (uint32_t& k : input_index_) k = shift(k);
    --num_input_;
    return;
  }
  const uint32_t v = vertex_of_input(i);
  std::vector<uint8_t> marked = marks_of(fo_);
  MeshEdit edit;
  if (!remove_vertex(fo_.base, v, edit)) {
    std::vector<double> xyz;
    std::vector<uint32_t> input_of;
    for (uint32_t u = 0; u < fo_.base.num_vertices(); ++u)
      if (u != v) {
        xyz.insert(xyz.end(), fo_.base.point(u), fo_.base.point(u) + 3);
        input_of.push_back(shift(input_index_[u]));
      }
    rebuild(xyz, input_of, num_input_ - 1);
    return;
  }
  input_index_[v] = input_index_.back();
  input_index_.pop_back();
  for (uint32_t& k : input_index_) k = shift(k);
  --num_input_;
  follow_moves(marked, edit);
  restructure(std::move(fo_.base), std::move(marked), edit.changed_vertices);
}

}  // namespace hodt
