#include "higher_order/regions/region_model.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <unordered_set>

#include "hodt/error.hpp"
#include "hodt/measures.hpp"
#include "containers/words_memo.hpp"
#include "higher_order/regions/neighbor_filter.hpp"
#include "higher_order/regions/region_terms.hpp"

namespace hodt {

std::vector<uint32_t> RegionModel::region_states(const std::vector<uint32_t>& variable_state) const {
  std::vector<uint32_t> s(variable_of_region.size(), 0);
  for (size_t r = 0; r < s.size(); ++r)
    if (variable_of_region[r] >= 0) s[r] = variable_state[static_cast<size_t>(variable_of_region[r])];
  return s;
}

std::vector<uint32_t> RegionModel::variable_states(const std::vector<uint32_t>& region_state) const {
  std::vector<uint32_t> s(region_of_variable.size(), 0);
  for (size_t x = 0; x < region_of_variable.size(); ++x) s[x] = region_state[region_of_variable[x]];
  return s;
}

namespace {

// What each state of a region puts around each of its vertices: the fan of
// triangles at the vertex, as a class (states with equal fans share a class).
struct Fans {
  std::vector<uint32_t> vertices;                  // sorted
  std::vector<std::vector<uint32_t>> class_of;     // per local vertex, per state
  std::vector<std::vector<std::vector<Tri>>> fan;  // per local vertex, per class
  std::vector<uint8_t> merged;                     // per local vertex: merge_classes ran
  uint32_t local(uint32_t v) const {
    return static_cast<uint32_t>(std::lower_bound(vertices.begin(), vertices.end(), v) - vertices.begin());
  }
};

// States with the same neighbours at a vertex (or the same neighbour classes)
// share a class: what vertex terms see; for vertex-pair terms, and at a vertex
// that reads the domain's terms (TermsAtVertex), the same triangles.
// items: a view's (only their vertices are read from it); null: every vertex
// (a region, or its first view, which speaks for everything no other view does).
Fans fans_of(const TermsAtVertex& at, const std::vector<std::vector<Tri>>& states,
             const std::vector<Tri>* items, const std::function<void()>& tick) {
  Fans f;
  if (items) {  // (a view of one vertex of a long region: not its hundreds of others)
    for (const Tri& item : *items)
      if (item == RegionTerms::vertex_item(item[1])) f.vertices.push_back(item[1]);
  } else {
    for (const Tri& t : states[0]) f.vertices.insert(f.vertices.end(), t.begin(), t.end());
  }
  std::sort(f.vertices.begin(), f.vertices.end());
  f.vertices.erase(std::unique(f.vertices.begin(), f.vertices.end()), f.vertices.end());
  const size_t nv = f.vertices.size();
  f.class_of.assign(nv, std::vector<uint32_t>(states.size()));
  f.fan.assign(nv, {});
  f.merged.assign(nv, 0);
  // (Classes by their key's words, local vertex first, in one memo: no
  // allocation per key, where a map of triangle vectors per vertex made one.)
  WordsMemo ids;
  std::vector<std::vector<Tri>> around(nv);
  std::vector<uint32_t> key, nb;
  std::vector<const ObjectiveTerms*> terms(nv);
  for (size_t i = 0; i < nv; ++i) terms[i] = &at.at(f.vertices[i]);
  for (size_t s = 0; s < states.size(); ++s) {
    tick();
    for (auto& a : around) a.clear();
    for (const Tri& t : states[s])
      for (uint32_t v : t) {
        const uint32_t lv = f.local(v);
        if (lv < nv && f.vertices[lv] == v) around[lv].push_back(t);
      }
    for (size_t i = 0; i < nv; ++i) {
      key.assign(1, static_cast<uint32_t>(i));
      const ObjectiveTerms& d = *terms[i];
      if (at.by_classes(f.vertices[i])) {  // their classes (TermsAtVertex::classes)
        star_neighbors(f.vertices[i], around[i], nb);
        key.push_back(at.classes(f.vertices[i], nb, around[i]));
      } else if (!reads_star_triangles(d)) {  // the neighbours (or their count)
        star_neighbors(f.vertices[i], around[i], nb);
        if (d.term_of_degree) key.push_back(static_cast<uint32_t>(nb.size()));  // (the region's fixed ones are the same in every state)
        else key.insert(key.end(), nb.begin(), nb.end());
      } else {
        for (const Tri& t : around[i]) key.insert(key.end(), t.begin(), t.end());
      }
      bool found = false;
      const std::span<const uint32_t> id = ids.find(key, found);
      if (found) {
        f.class_of[i][s] = id[0];
        continue;
      }
      const uint32_t c = static_cast<uint32_t>(f.fan[i].size());
      ids.insert(key, std::span<const uint32_t>(&c, 1));
      f.fan[i].push_back(around[i]);
      f.class_of[i][s] = c;
    }
  }
  return f;
}

// Classes at local vertex i whose neighbour sets no other neighbours can tell
// apart (NeighborFilter: the same cone of neighbours) made one: fewer entries
// in the tables of a vertex that regions share. (Not worth its cost for a
// vertex that one region decides alone.)
void merge_classes(const NeighborFilter& filter, Fans& f, uint32_t i) {
  if (f.merged[i]) return;
  f.merged[i] = 1;
  std::map<std::vector<uint32_t>, uint32_t> reduced;
  std::vector<uint32_t> to(f.fan[i].size()), nb;
  std::vector<std::vector<Tri>> kept;
  for (uint32_t c = 0; c < f.fan[i].size(); ++c) {
    star_neighbors(f.vertices[i], f.fan[i][c], nb);
    filter.reduce(f.vertices[i], nb);
    const auto [it, fresh] = reduced.try_emplace(nb, static_cast<uint32_t>(kept.size()));
    if (fresh) kept.push_back(std::move(f.fan[i][c]));
    to[c] = it->second;
  }
  f.fan[i] = std::move(kept);
  for (uint32_t& c : f.class_of[i]) c = to[c];
}

// The apex of directed edge u -> v in a list of counterclockwise triangles.
uint32_t apex_of(const std::vector<Tri>& tris, uint32_t u, uint32_t v) {
  for (const Tri& t : tris)
    for (int i = 0; i < 3; ++i)
      if (t[i] == u && t[(i + 1) % 3] == v) return t[(i + 2) % 3];
  return kNoApex;
}

// What the model reads a region through: its list of triangulations, or in a
// relaxation one of its views (region_views.hpp), which speaks for some items.
struct Source {
  uint32_t region;
  const std::vector<std::vector<Tri>>* states;
  const std::vector<Tri>* items;  // null: the region itself, every item
};

struct Builder {
  const Mesh& dt;
  const Regions& R;
  const ObjectiveTerms& d;
  const Objective o;
  RegionModel& M;
  StateGraph& g;
  const Progress& progress;
  std::vector<Source> src;
  std::vector<uint32_t> first_src;    // per region: its first source (its own terms)
  std::vector<int32_t> var_of_src;    // -1 for a source with one state
  // Per region, whether its terms are built (null: every region's): an update
  // rebuilds only the terms that read a changed region.
  const std::vector<uint8_t>* only = nullptr;
  bool built(uint32_t r) const { return !only || (*only)[r]; }
  uint64_t work = 0;
  // Reports every few thousand terms (a term may cost a vertex class test).
  void tick(double done, double total) {
    if (progress && (++work & 2047) == 0 && !progress(done, total)) throw Cancelled();
  }

  // The source that speaks for `item` of region r (its first one, by default).
  uint32_t source(uint32_t r, const Tri& item) const {
    for (uint32_t i = first_src[r]; i < src.size() && src[i].region == r && src[i].items; ++i)
      if (std::binary_search(src[i].items->begin(), src[i].items->end(), item)) return i;
    return first_src[r];
  }
  const std::vector<std::vector<Tri>>& states(uint32_t i) const { return *src[i].states; }
  int32_t var(uint32_t i) const { return var_of_src[i]; }
  void add_constant(double v) { g.constant = combine(d.combine, g.constant, v); }
  // A new variable, after all the others: region r read through its view `view`
  // (0: the region itself), of n states.
  int32_t add_variable(uint32_t r, uint32_t view, size_t n, bool partial) {
    M.region_of_variable.push_back(r);
    M.view_of_variable.push_back(view);
    g.domain.push_back(static_cast<uint32_t>(n));
    g.unary.emplace_back(n, 0.0);
    g.unary_terms.push_back(0);
    g.partial.push_back(partial);
    return static_cast<int32_t>(g.domain.size() - 1);
  }
  // A term of source i that depends on its state only.
  void add_unary(uint32_t i, uint32_t s, double v, bool count) {
    const int32_t x = var(i);
    if (x < 0) return add_constant(v);
    g.unary[x][s] = combine(d.combine, g.unary[x][s], v);
    g.unary_terms[x] += count;
  }

  void triangle_terms() {
    for (uint32_t r = 0; r < R.regions.size(); ++r) {
      if (!built(r)) continue;
      const uint32_t i = first_src[r];
      for (uint32_t s = 0; s < states(i).size(); ++s)
        for (const Tri& t : states(i)[s]) add_unary(i, s, triangle_term(d, dt, t), s == 0);
    }
  }

  void edge_terms() {
    // Fixed edges with one region on both sides: with the other fixed edges below
    // (their sides may be read through different views).
    std::unordered_set<uint64_t> self_fixed;
    for (uint32_t e = 0; e < dt.halfedges.size(); ++e) {
      const int32_t f = dt.halfedges[e];
      if (f >= 0 && R.fixed[e] && R.region_of_triangle[e / 3] == R.region_of_triangle[static_cast<uint32_t>(f) / 3])
        self_fixed.insert(edge_key(std::min(dt.origin(e), dt.target(e)), std::max(dt.origin(e), dt.target(e))));
    }
    // Edges inside a region: both triangles are the region's.
    for (uint32_t r = 0; r < R.regions.size(); ++r)
      for (uint32_t s = 0, i = first_src[r]; built(r) && s < states(i).size(); ++s) {
        tick(r, static_cast<double>(R.regions.size()));
        const auto& tris = states(i)[s];
        for (const Tri& t : tris)
          for (int i = 0; i < 3; ++i) {
            const uint32_t u = t[i], v = t[(i + 1) % 3];
            if (u > v || (!self_fixed.empty() && self_fixed.count(edge_key(u, v)))) continue;
            const uint32_t x = apex_of(tris, v, u);
            if (x != kNoApex) add_unary(first_src[r], s, edge_term(d, dt, u, v, t[(i + 2) % 3], x), s == 0);
          }
      }
    // Fixed edges between regions, and hull edges.
    for (uint32_t e = 0; e < dt.halfedges.size(); ++e) {
      tick(e, static_cast<double>(dt.halfedges.size()));
      const int32_t f = dt.halfedges[e];
      const uint32_t u = dt.origin(e), v = dt.target(e), r1 = R.region_of_triangle[e / 3];
      if (f < 0) {
        if (interior_only(d.site) || !built(r1)) continue;
        const auto& s1 = states(first_src[r1]);
        for (uint32_t s = 0; s < s1.size(); ++s)
          add_unary(first_src[r1], s, edge_term(d, dt, u, v, apex_of(s1[s], u, v), kNoApex), s == 0);
        continue;
      }
      const uint32_t r2 = R.region_of_triangle[static_cast<uint32_t>(f) / 3];
      if (f < static_cast<int32_t>(e) || (r1 == r2 && !R.fixed[e])) continue;  // once; inside a region: done above
      if (!built(r1) && !built(r2)) continue;
      const uint32_t i1 = source(r1, RegionTerms::edge_item(u, v)), i2 = source(r2, RegionTerms::edge_item(v, u));
      const auto &s1 = states(i1), &s2 = states(i2);
      if (i1 == i2) {  // both sides read from the same states
        for (uint32_t s = 0; s < s1.size(); ++s)
          add_unary(i1, s, edge_term(d, dt, u, v, apex_of(s1[s], u, v), apex_of(s1[s], v, u)), s == 0);
        continue;
      }
      // Apex classes on each side.
      auto classes = [&](const std::vector<std::vector<Tri>>& states, uint32_t a, uint32_t b, std::vector<uint32_t>& apex) {
        std::vector<uint32_t> cls(states.size());
        for (size_t s = 0; s < states.size(); ++s) {
          const uint32_t w = apex_of(states[s], a, b);
          auto it = std::find(apex.begin(), apex.end(), w);
          cls[s] = static_cast<uint32_t>(it - apex.begin());
          if (it == apex.end()) apex.push_back(w);
        }
        return cls;
      };
      std::vector<uint32_t> a1, a2;
      std::vector<uint32_t> c1 = classes(s1, u, v, a1), c2 = classes(s2, v, u, a2);
      const int32_t x1 = var(i1), x2 = var(i2);
      if (x1 < 0 || x2 < 0) {  // at most one side has a choice: a unary term
        const bool left = x1 >= 0;
        const auto& cls = left ? c1 : c2;
        for (uint32_t s = 0; s < cls.size(); ++s)
          add_unary(left ? i1 : i2, s,
                    edge_term(d, dt, u, v, a1[left ? cls[s] : 0], a2[left ? 0 : cls[s]]), s == 0);
        continue;
      }
      StateFactor fac;
      fac.scope = {static_cast<uint32_t>(x1), static_cast<uint32_t>(x2)};
      fac.dims = {static_cast<uint32_t>(a1.size()), static_cast<uint32_t>(a2.size())};
      for (uint32_t j = 0; j < a2.size(); ++j)
        for (uint32_t i = 0; i < a1.size(); ++i) fac.table.push_back(edge_term(d, dt, u, v, a1[i], a2[j]));
      fac.project = {std::move(c1), std::move(c2)};
      g.factors.push_back(std::move(fac));
    }
  }

  void vertex_terms(double max_factor, VertexTermMemo* memo) {
    std::vector<Fans> fans(src.size());
    std::vector<uint8_t> have(src.size(), 0);
    // The terms each vertex reads (within a domain: those without one where
    // nothing can be outside). (Only terms over neighbour sets drop neighbours:
    // a filter for them alone, read at the vertices that read them.)
    const TermsAtVertex at(dt, R, o);
    const std::optional<NeighborFilter> filter =
        at.inside().drop_neighbors ? std::optional<NeighborFilter>(std::in_place, dt, R, at.inside()) : std::nullopt;
    auto fans_at = [&](uint32_t i) -> const Fans& {
      if (!have[i]) {
        const std::vector<Tri>* items = i == first_src[src[i].region] ? nullptr : src[i].items;
        fans[i] = fans_of(at, states(i), items, [&] { tick(i, src.size()); }), have[i] = 1;
      }
      return fans[i];
    };
    std::vector<uint8_t> on_hull(dt.num_vertices(), 0);
    for (uint32_t v : dt.hull) on_hull[v] = 1;
    const Stars st = build_stars(dt);
    std::vector<uint32_t> around, nb;
    std::vector<Tri> tris;
    for (uint32_t v = 0; v < dt.num_vertices(); ++v) {
      if (interior_only(d.site) && on_hull[v]) continue;
      tick(v, dt.num_vertices());
      around.clear();
      for (uint32_t i = st.tri_offset[v]; i < st.tri_offset[v + 1]; ++i) around.push_back(R.region_of_triangle[st.triangle[i]]);
      std::sort(around.begin(), around.end());
      around.erase(std::unique(around.begin(), around.end()), around.end());
      if (only && std::none_of(around.begin(), around.end(), [&](uint32_t r) { return built(r); })) continue;
      for (uint32_t& r : around) r = source(r, RegionTerms::vertex_item(v));  // (regions become sources)
      // Fixed fans, and the regions with a choice with their fan classes.
      std::vector<Tri> fixed;
      std::vector<uint32_t> choice_regions, local;
      double size = 1;
      for (uint32_t r : around) {
        const Fans& f = fans_at(r);
        const uint32_t lv = f.local(v);
        if (var(r) < 0) {
          const auto& fan = f.fan[lv][0];
          fixed.insert(fixed.end(), fan.begin(), fan.end());
        } else {
          choice_regions.push_back(r), local.push_back(lv);
        }
      }
      const ObjectiveTerms& dv = at.at(v);
      for (size_t j = 0; j < choice_regions.size(); ++j) {
        if (filter && dv.drop_neighbors && choice_regions.size() > 1) merge_classes(*filter, fans[choice_regions[j]], local[j]);
        size *= static_cast<double>(fans[choice_regions[j]].fan[local[j]].size());
      }
      auto term = [&](const std::vector<uint32_t>& cls) {
        tris = fixed;
        for (size_t j = 0; j < choice_regions.size(); ++j) {
          const auto& fan = fans[choice_regions[j]].fan[local[j]][cls[j]];
          tris.insert(tris.end(), fan.begin(), fan.end());
        }
        star_neighbors(v, tris, nb);
        auto eval = [&] { return vertex_term(dv, dt, Star(v, nb, tris)); };
        return memo ? (*memo)(v, nb, eval) : eval();
      };
      if (choice_regions.empty()) {
        add_constant(term({}));
        continue;
      }
      if (size > max_factor) {  // relaxed: the model ignores this term
        ++g.relaxed_terms;
        continue;
      }
      if (choice_regions.size() == 1) {
        const uint32_t r = choice_regions[0];
        const Fans& f = fans[r];
        std::vector<double> by_class(f.fan[local[0]].size());
        for (uint32_t c = 0; c < by_class.size(); ++c) by_class[c] = term({c});
        for (uint32_t s = 0; s < states(r).size(); ++s) add_unary(r, s, by_class[f.class_of[local[0]][s]], s == 0);
        continue;
      }
      StateFactor fac;
      for (size_t j = 0; j < choice_regions.size(); ++j) {
        const Fans& f = fans[choice_regions[j]];
        fac.scope.push_back(static_cast<uint32_t>(var(choice_regions[j])));
        fac.project.push_back(f.class_of[local[j]]);
        fac.dims.push_back(static_cast<uint32_t>(f.fan[local[j]].size()));
      }
      std::vector<uint32_t> cls(fac.dims.size(), 0);
      fac.table.reserve(static_cast<size_t>(size));
      for (;;) {
        tick(v, dt.num_vertices());
        fac.table.push_back(term(cls));
        size_t j = 0;
        while (j < cls.size() && ++cls[j] == fac.dims[j]) cls[j++] = 0;
        if (j == cls.size()) break;
      }
      g.factors.push_back(std::move(fac));
    }
  }
};

}  // namespace

RegionModel region_model(const Mesh& dt, const Regions& R, Objective o, const RegionModelLimits& limits,
                         const Progress& progress, const std::vector<std::vector<RegionView>>* views) {
  const ObjectiveTerms& d = objective_terms(o, dt);
  RegionModel M;
  StateGraph& g = M.graph;
  g.combine = d.combine;
  g.sense = info(o).sense;
  g.term_max = d.term_max;
  Builder b{dt, R, d, o, M, g, progress, {}, {}, {}};
  M.variable_of_region.assign(R.regions.size(), -1);
  for (uint32_t r = 0; r < R.regions.size(); ++r) {
    const Region& region = R.regions[r];
    b.first_src.push_back(static_cast<uint32_t>(b.src.size()));
    const bool split = views && !(*views)[r].empty();
    if (!split) b.src.push_back({r, &region.states, nullptr});
    else
      for (const RegionView& view : (*views)[r]) b.src.push_back({r, &view.states, &view.items});
    for (uint32_t i = b.first_src[r]; i < b.src.size(); ++i) {
      const size_t n = b.states(i).size();
      const bool partial = !split && !region.complete;
      b.var_of_src.push_back(-1);
      if (n < 2 && !partial) continue;
      b.var_of_src.back() = b.add_variable(r, i - b.first_src[r], n, partial);
      if (i == b.first_src[r]) M.variable_of_region[r] = b.var_of_src.back();
    }
  }
  if (vertex_site(d.site)) b.vertex_terms(limits.max_factor, limits.memo);
  else if (edge_site(d.site)) b.edge_terms();
  else b.triangle_terms();
  return M;
}

RegionModel update_region_model(RegionModel M, const Mesh& dt, const Regions& R, Objective o,
                                const std::vector<uint8_t>& changed, const RegionModelLimits& limits,
                                const Progress& progress, const std::vector<std::vector<RegionView>>* views) {
  auto whole = [&] { return region_model(dt, R, o, limits, progress, views); };
  // (Relaxed terms are counted, not listed: whether one is still relaxed is not known.)
  if (M.graph.relaxed_terms || M.variable_of_region.size() != R.regions.size() ||
      std::any_of(M.view_of_variable.begin(), M.view_of_variable.end(), [](uint32_t v) { return v != 0; }))
    return whole();
  const ObjectiveTerms& d = objective_terms(o, dt);
  StateGraph& g = M.graph;
  Builder b{dt, R, d, o, M, g, progress, {}, {}, {}};
  std::vector<uint8_t> var_changed(g.domain.size(), 0);
  auto reset = [&](int32_t x, size_t n, bool partial) {
    g.domain[x] = static_cast<uint32_t>(n);
    g.unary[x].assign(n, 0.0);
    g.unary_terms[x] = 0;
    g.partial[x] = partial;
    var_changed[x] = 1;
  };
  for (uint32_t r = 0; r < R.regions.size(); ++r) {
    const Region& region = R.regions[r];
    const bool split = views && !(*views)[r].empty();
    const size_t n = split ? (*views)[r][0].states.size() : region.states.size();
    const bool partial = !split && !region.complete;
    const int32_t x = M.variable_of_region[r];
    // Each region keeps its variable or its lack of one (a changed region left
    // with one triangulation keeps its variable, of one state), and only changed
    // ones change: else the numbering, or the constant, would move.
    const bool kept_with_one = changed[r] && x >= 0 && n == 1;
    if (((n >= 2 || partial) != (x >= 0) && !kept_with_one) || (changed[r] && x < 0) ||
        (!changed[r] && (split || (x >= 0 && g.domain[x] != n))))
      return whole();
    b.first_src.push_back(static_cast<uint32_t>(b.src.size()));
    b.src.push_back({r, split ? &(*views)[r][0].states : &region.states, split ? &(*views)[r][0].items : nullptr});
    b.var_of_src.push_back(x);
    if (changed[r]) reset(x, n, partial);
    // Its other views: variables after all the others (one each of two states or more).
    for (size_t j = 1; split && j < (*views)[r].size(); ++j) {
      const RegionView& view = (*views)[r][j];
      b.src.push_back({r, &view.states, &view.items});
      // (no factor reads it yet: nothing to erase)
      b.var_of_src.push_back(view.states.size() < 2 ? -1 : b.add_variable(r, static_cast<uint32_t>(j), view.states.size(), false));
    }
  }
  // The terms that read a changed region, built again: every factor over one
  // goes, and each one's unary (its terms alone) starts over.
  std::erase_if(g.factors, [&](const StateFactor& f) {
    return std::any_of(f.scope.begin(), f.scope.end(), [&](uint32_t x) { return var_changed[x] != 0; });
  });
  b.only = &changed;
  if (vertex_site(d.site)) b.vertex_terms(limits.max_factor, limits.memo);
  else if (edge_site(d.site)) b.edge_terms();
  else b.triangle_terms();
  return M;
}

}  // namespace hodt
