#include "approx/baker.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "hodt/error.hpp"
#include "hodt/measures.hpp"
#include "hodt/progress.hpp"

namespace hodt {

std::vector<uint32_t> hull_depth(const Mesh& m, const Progress& progress) {
  const Stars st = build_stars(m, progress);
  WorkCounter work;
  std::vector<uint32_t> depth(m.num_vertices(), UINT32_MAX), queue;
  for (uint32_t v : m.hull) depth[v] = 0, queue.push_back(v);
  for (size_t i = 0; i < queue.size(); ++i) {
    if (work.tick(16)) report(progress, i, m.num_vertices());
    const uint32_t v = queue[i];
    for (uint32_t k = st.offset[v]; k < st.offset[v + 1]; ++k) {
      const uint32_t w = st.neighbor[k];
      if (depth[w] == UINT32_MAX) depth[w] = depth[v] + 1, queue.push_back(w);
    }
  }
  return depth;
}

std::vector<uint32_t> quad_layers(const FirstOrder& fo, const Progress& progress) {
  const std::vector<uint32_t> depth = hull_depth(fo.base, progress);
  std::vector<uint32_t> layer(fo.num_quads());
  for (uint32_t q = 0; q < fo.num_quads(); ++q) {
    const Quad& k = fo.quads[q];
    layer[q] = std::min({depth[k.a], depth[k.b], depth[k.c], depth[k.d]});
  }
  return layer;
}

BakerResult baker(FactorGraph& g, const std::vector<uint32_t>& layer, double epsilon, const DpLimits& limits,
                  uint32_t max_scope, bool keep_shift_choices) {
  if (g.sense != Sense::Max || g.combine != Combine::Sum)
    throw std::logic_error("baker: expects a maximised sum of non-negative factors");
  const size_t nf = g.factors.size();
  std::vector<uint32_t> lo(nf), hi(nf);
  std::vector<double> top(nf);
  std::vector<uint8_t> always(nf, 0);
  uint32_t span = 1;
  double all_top = g.constant;
  WorkCounter work;
  for (size_t k = 0; k < nf; ++k) {
    const Factor& f = g.factors[k];
    if (work.tick(static_cast<double>(16 + f.table.size()))) report(limits.progress, 0, 1);
    if (*std::min_element(f.table.begin(), f.table.end()) < 0)
      throw std::logic_error("baker: factors must be non-negative");
    top[k] = *std::max_element(f.table.begin(), f.table.end());
    all_top += top[k];
    lo[k] = UINT32_MAX, hi[k] = 0;
    for (uint32_t v : f.scope) lo[k] = std::min(lo[k], layer[v]), hi[k] = std::max(hi[k], layer[v]);
    always[k] = f.scope.size() > max_scope;
    if (!always[k]) span = std::max(span, hi[k] - lo[k]);
  }
  BakerResult r;
  r.lambda = std::max<uint32_t>(1, static_cast<uint32_t>(std::ceil(span / epsilon - 1e-9)));
  r.bound = all_top;  // every factor at its best
  r.value = -INFINITY;
  r.width = 0;
  // Each shift's graph borrows the factors it keeps (moved, not copied: a copy
  // per shift, and freeing it, touches every factor's table as the DP's reading
  // does, and allocates besides), and gives them back even when its DP throws.
  struct Lent {
    FactorGraph& owner;
    FactorGraph sub;
    std::vector<uint32_t> from;  // per factor of sub, its index in owner
    ~Lent() {
      for (size_t i = 0; i < from.size(); ++i) owner.factors[from[i]] = std::move(sub.factors[i]);
    }
  };
  for (uint32_t shift = 0; shift < r.lambda; ++shift) {
    report(limits.progress, shift, r.lambda);
    double dropped_top = 0;
    uint32_t dropped = 0;
    DpResult dp;
    {
      // Cuts after the layers l with l mod lambda == shift: a factor is dropped
      // if its layers [lo, hi] contain such an l below hi.
      Lent lent{g, {}, {}};
      FactorGraph& sub = lent.sub;
      sub.num_vars = g.num_vars;
      sub.sense = g.sense;
      sub.combine = g.combine;
      sub.constant = g.constant;
      for (size_t k = 0; k < nf; ++k) {
        if (work.tick(static_cast<double>(32 + g.factors[k].table.size()))) report(limits.progress, shift, r.lambda);
        const uint32_t first_cut = lo[k] + (shift + r.lambda - lo[k] % r.lambda) % r.lambda;
        if (always[k] || first_cut < hi[k]) {
          dropped_top += top[k];
          ++dropped;
        } else {
          sub.factors.push_back(std::move(g.factors[k]));
          lent.from.push_back(static_cast<uint32_t>(k));
        }
      }
      dp = solve_exact(sub, limits);
    }
    r.width = std::max(r.width, dp.decomposition.width);
    report(limits.progress, shift + 1, r.lambda);
    BakerShift s{shift, dp.value, g.evaluate(dp.choice), dp.value + dropped_top, dropped};
    r.shifts.push_back(s);
    if (keep_shift_choices) r.shift_choices.push_back(dp.choice);
    r.bound = std::min(r.bound, s.bound);
    if (s.value > r.value) r.value = s.value, r.choice = dp.choice;
  }
  return r;
}

namespace {

// The factors of each variable.
std::vector<std::vector<uint32_t>> factors_touching(const FactorGraph& g, const Progress& progress) {
  std::vector<std::vector<uint32_t>> touching(g.num_vars);
  WorkCounter work;
  for (uint32_t k = 0; k < g.factors.size(); ++k) {
    for (uint32_t v : g.factors[k].scope) touching[v].push_back(k);
    if (work.tick(16.0 * g.factors[k].scope.size())) report(progress, 0, g.num_vars);
  }
  return touching;
}

}  // namespace

void prefer_delaunay(const FactorGraph& g, Choice& x, const Progress& progress) {
  if (g.combine != Combine::Sum) return;
  const double sign = g.sense == Sense::Max ? 1 : -1;
  const std::vector<std::vector<uint32_t>> touching = factors_touching(g, progress);
  auto local = [&](uint32_t v) {
    double s = 0;
    for (uint32_t k : touching[v]) {
      const Factor& f = g.factors[k];
      size_t idx = 0;
      for (size_t j = 0; j < f.scope.size(); ++j) idx |= size_t(x[f.scope[j]] & 1) << j;
      s += f.table[idx];
    }
    return s;
  };
  WorkCounter work;
  for (uint32_t v = 0; v < g.num_vars; ++v) {
    if (work.tick(static_cast<double>(touching[v].size()) + 1)) report(progress, v, g.num_vars);
    if (!x[v]) continue;
    const double before = local(v);
    x[v] = 0;
    if (sign * (local(v) - before) < 0) x[v] = 1;  // worse: keep the flip
  }
}

bool improve_locally(const FactorGraph& g, Choice& x, const Progress& progress) {
  if (g.combine != Combine::Sum) return false;
  const double sign = g.sense == Sense::Max ? 1 : -1;
  const std::vector<std::vector<uint32_t>> touching = factors_touching(g, progress);
  auto value_of = [&](uint32_t k) {
    const Factor& f = g.factors[k];
    size_t idx = 0;
    for (size_t j = 0; j < f.scope.size(); ++j) idx |= size_t(x[f.scope[j]] & 1) << j;
    return f.table[idx];
  };
  // Gain (in the improving direction) of flipping the variables in `flip`.
  std::vector<uint32_t> seen;
  auto gain = [&](std::initializer_list<uint32_t> flip) {
    seen.clear();
    for (uint32_t v : flip)
      for (uint32_t k : touching[v])
        if (std::find(seen.begin(), seen.end(), k) == seen.end()) seen.push_back(k);
    double before = 0, after = 0;
    for (uint32_t k : seen) before += value_of(k);
    for (uint32_t v : flip) x[v] ^= 1;
    for (uint32_t k : seen) after += value_of(k);
    for (uint32_t v : flip) x[v] ^= 1;
    return sign * (after - before);
  };
  bool improved = false;
  WorkCounter work;
  for (int pass = 0; pass < 50; ++pass) {
    report(progress, pass, 50);
    bool changed = false;
    for (uint32_t v = 0; v < g.num_vars; ++v) {
      if (work.tick(static_cast<double>(touching[v].size()) + 1)) report(progress, pass + 0.5 * v / g.num_vars, 50);
      if (!touching[v].empty() && gain({v}) > 1e-12) x[v] ^= 1, changed = true;
    }
    for (size_t k = 0; k < g.factors.size(); ++k) {
      const Factor& f = g.factors[k];
      for (size_t i = 0; i < f.scope.size(); ++i)
        for (size_t j = i + 1; j < f.scope.size(); ++j) {
          if (gain({f.scope[i], f.scope[j]}) > 1e-12) x[f.scope[i]] ^= 1, x[f.scope[j]] ^= 1, changed = true;
          if (work.tick(static_cast<double>(touching[f.scope[i]].size() + touching[f.scope[j]].size())))
            report(progress, pass + 0.5 + 0.5 * k / g.factors.size(), 50);
        }
    }
    if (!changed) break;
    improved = true;
  }
  return improved;
}

}  // namespace hodt
