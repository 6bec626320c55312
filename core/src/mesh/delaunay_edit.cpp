#include "mesh/delaunay_edit.hpp"

#include <algorithm>
#include <stdexcept>

#include "hodt/delaunay.hpp"
#include "mesh/delaunay_builder.hpp"

namespace hodt {

int64_t vertex_at(const Mesh& m, double x, double y, uint32_t start) {
  const double q[2] = {x, y};
  const uint32_t e = locate(m, q, 3 * start);
  for (uint32_t v : {m.origin(e), m.target(e), m.apex(e)})
    if (m.point(v)[0] == x && m.point(v)[1] == y) return v;
  return -1;
}

MeshEdit insert_vertex(Mesh& m, double x, double y, double z, uint32_t start) {
  MeshEdit edit;
  std::vector<uint32_t> touched;
  std::vector<double>& xyz = m.coords.write();
  xyz.insert(xyz.end(), {x, y, z});
  Builder b(m, &touched);
  b.start_near(start);
  b.insert(m.num_vertices() - 1);
  b.finish();
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for (uint32_t t : touched) edit.changed_vertices.insert(edit.changed_vertices.end(), &m.triangles[3 * t], &m.triangles[3 * t + 3]);
  return edit;
}

namespace {

// Moves the last triangle into slot s (its twins follow) and drops the last slot.
void fill_slot(Mesh& m, uint32_t s, MeshEdit& edit) {
  const uint32_t last = m.num_triangles() - 1;
  if (s != last) {
    for (uint32_t k = 0; k < 3; ++k) {
      m.triangles[3 * s + k] = m.triangles[3 * last + k];
      const int32_t f = m.halfedges[3 * last + k];
      m.halfedges[3 * s + k] = f;
      if (f >= 0) m.halfedges[static_cast<uint32_t>(f)] = static_cast<int32_t>(3 * s + k);
    }
    edit.moved_triangles.emplace_back(last, s);
  }
  m.triangles.resize(3 * size_t(last));
  m.halfedges.resize(3 * size_t(last));
}

}  // namespace

bool remove_vertex(Mesh& m, uint32_t v, MeshEdit& edit, uint32_t max_degree) {
  const auto it = std::find(m.triangles.begin(), m.triangles.end(), v);
  if (it == m.triangles.end()) throw std::logic_error("remove_vertex: vertex " + std::to_string(v) + " is not in the mesh");
  // The star: triangles (v, u_i, u_i+1) counterclockwise; u_i -> u_i+1 faces outside.
  std::vector<uint32_t> star, link;
  std::vector<int32_t> outside;
  const uint32_t first = static_cast<uint32_t>(it - m.triangles.begin());
  uint32_t e = first;
  do {
    if (star.size() >= max_degree) return false;
    star.push_back(e / 3);
    link.push_back(m.target(e));
    outside.push_back(m.halfedges[next_halfedge(e)]);
    const int32_t t = m.halfedges[prev_halfedge(e)];
    if (t < 0) return false;  // v is on the hull
    e = static_cast<uint32_t>(t);
  } while (e != first);
  const uint32_t k = static_cast<uint32_t>(link.size());

  // The new triangles are those of the neighbours' own Delaunay triangulation that
  // lie inside the star polygon (each has an empty circle through three of them;
  // together they tile the hole), found by flooding from the polygon's sides.
  std::vector<double> xyz;
  for (uint32_t u : link) xyz.insert(xyz.end(), m.point(u), m.point(u) + 3);
  const Mesh local = delaunay(std::move(xyz));
  auto side_of = [&](uint32_t h) -> int32_t {  // polygon side i if h runs u_i -> u_i+1
    const uint32_t a = local.origin(h), b = local.target(h);
    return (a + 1) % k == b ? static_cast<int32_t>(a) : -1;
  };
  auto is_polygon_edge = [&](uint32_t h) { return side_of(h) >= 0 || (local.target(h) + 1) % k == local.origin(h); };
  std::vector<int32_t> slot(local.num_triangles(), -1);  // local triangle -> its slot in m
  std::vector<uint32_t> inside, queue;
  for (uint32_t h = 0; h < local.triangles.size(); ++h)
    if (side_of(h) >= 0 && slot[h / 3] < 0) {
      slot[h / 3] = 0;
      queue.push_back(h / 3);
    }
  while (!queue.empty()) {
    const uint32_t t = queue.back();
    queue.pop_back();
    inside.push_back(t);
    for (uint32_t h = 3 * t; h < 3 * t + 3; ++h) {
      const int32_t g = local.halfedges[h];
      if (g < 0 || is_polygon_edge(h) || slot[static_cast<uint32_t>(g) / 3] >= 0) continue;
      slot[static_cast<uint32_t>(g) / 3] = 0;
      queue.push_back(static_cast<uint32_t>(g) / 3);
    }
  }
  if (inside.size() != k - 2) throw std::logic_error("remove_vertex: the star's retriangulation does not tile it");

  for (uint32_t i = 0; i < k - 2; ++i) slot[inside[i]] = static_cast<int32_t>(star[i]);
  for (uint32_t i = 0; i < k - 2; ++i) {
    const uint32_t t = inside[i], s = star[i];
    for (uint32_t j = 0; j < 3; ++j) {
      const uint32_t h = 3 * t + j;
      m.triangles[3 * s + j] = link[local.triangles[h]];
      const int32_t side = side_of(h);
      if (side >= 0) {
        const int32_t f = outside[static_cast<uint32_t>(side)];
        m.halfedges[3 * s + j] = f;
        if (f >= 0) m.halfedges[static_cast<uint32_t>(f)] = static_cast<int32_t>(3 * s + j);
      } else {
        const uint32_t g = static_cast<uint32_t>(local.halfedges[h]);
        m.halfedges[3 * s + j] = static_cast<int32_t>(3 * static_cast<uint32_t>(slot[g / 3]) + g % 3);
      }
    }
  }
  edit.changed_vertices = link;
  // Free the two spare slots (largest first, so the last slot is never a freed one).
  std::vector<uint32_t> freed = {star[k - 2], star[k - 1]};
  std::sort(freed.rbegin(), freed.rend());
  for (uint32_t s : freed) fill_slot(m, s, edit);
  // The last vertex takes number v.
  const uint32_t last = m.num_vertices() - 1;
  if (v != last) {
    std::vector<double>& xyz = m.coords.write();
    std::copy_n(&xyz[3 * size_t(last)], 3, &xyz[3 * size_t(v)]);
    for (uint32_t& u : m.triangles)
      if (u == last) u = v;
    for (uint32_t& u : edit.changed_vertices)
      if (u == last) u = v;
  }
  m.coords.write().resize(3 * size_t(last));
  Builder(m).finish();  // the hull's vertex numbers may have changed
  return true;
}

}  // namespace hodt
