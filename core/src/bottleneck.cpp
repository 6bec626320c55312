#include "hodt/bottleneck.hpp"

#include <algorithm>

#include "hodt/two_sat.hpp"

namespace hodt {

BottleneckBuilder::BottleneckBuilder(uint32_t num_quads) : unary_index_(num_quads, -1) {
  model_.num_quads = num_quads;
}

void BottleneckBuilder::constant(double v) { model_.floor = std::max(model_.floor, v); }

void BottleneckBuilder::unary(uint32_t q, double v0, double v1) {
  if (unary_index_[q] < 0) {
    unary_index_[q] = static_cast<int32_t>(model_.terms.size());
    PairTerm t;
    t.q = static_cast<int32_t>(q);
    t.v[0] = t.v[2] = v0;
    t.v[1] = t.v[3] = v1;
    model_.terms.push_back(t);
    return;
  }
  PairTerm& t = model_.terms[static_cast<size_t>(unary_index_[q])];
  t.v[0] = t.v[2] = std::max(t.v[0], v0);
  t.v[1] = t.v[3] = std::max(t.v[1], v1);
}

void BottleneckBuilder::binary(uint32_t q, uint32_t r, const double v[4]) {
  PairTerm t;
  if (q < r) {
    t.q = static_cast<int32_t>(q), t.r = static_cast<int32_t>(r);
    std::copy(v, v + 4, t.v);
  } else {  // store with q < r: swap the roles of the two index bits
    t.q = static_cast<int32_t>(r), t.r = static_cast<int32_t>(q);
    t.v[0] = v[0], t.v[1] = v[2], t.v[2] = v[1], t.v[3] = v[3];
  }
  binary_keys_.push_back({(uint64_t(uint32_t(t.q)) << 32) | uint32_t(t.r), static_cast<uint32_t>(model_.terms.size())});
  model_.terms.push_back(t);
}

BottleneckModel BottleneckBuilder::finish() {
  // Merge binary terms over the same pair of quads (elementwise max).
  std::sort(binary_keys_.begin(), binary_keys_.end());
  std::vector<uint8_t> drop(model_.terms.size(), 0);
  for (size_t i = 1; i < binary_keys_.size(); ++i) {
    if (binary_keys_[i].first != binary_keys_[i - 1].first) continue;
    PairTerm& keep = model_.terms[binary_keys_[i].second];
    const PairTerm& gone = model_.terms[binary_keys_[i - 1].second];
    for (int k = 0; k < 4; ++k) keep.v[k] = std::max(keep.v[k], gone.v[k]);
    drop[binary_keys_[i - 1].second] = 1;
  }
  // Compact in place (a second vector would double the peak memory).
  size_t kept = 0;
  for (size_t i = 0; i < model_.terms.size(); ++i)
    if (!drop[i]) model_.terms[kept++] = model_.terms[i];
  model_.terms.resize(kept);
  binary_keys_ = {};
  return std::move(model_);
}

namespace {

// Is there a choice with every term at most t? The paper's eliminations (a pair
// over the threshold between fixed triangles, or in both states of a quad: "no";
// in one state: the quad is forced) become unit clauses; the rest 2-SAT.
std::optional<Choice> feasible(const BottleneckModel& m, double t, ThresholdStep& step) {
  step = ThresholdStep{t, false, 0, 0, false};
  if (m.floor > t) {
    step.immediate_no = true;
    return std::nullopt;
  }
  TwoSat sat(m.num_quads);
  for (const PairTerm& term : m.terms) {
    const uint32_t q = static_cast<uint32_t>(term.q);
    if (term.r < 0) {
      const bool over0 = term.v[0] > t, over1 = term.v[1] > t;
      if (over0 && over1) {
        step.immediate_no = true;
        return std::nullopt;
      }
      if (over0 || over1) {
        ++step.forced;
        sat.forbid(q, over1);
      }
      continue;
    }
    for (int x = 0; x < 2; ++x)
      for (int y = 0; y < 2; ++y)
        if (term.v[x + 2 * y] > t) sat.forbid(q, x, term.r, y);
  }
  step.clauses = static_cast<uint32_t>(sat.num_clauses());
  auto a = sat.solve();
  step.satisfiable = a.has_value();
  return a;
}

}  // namespace

BottleneckResult solve_bottleneck(const BottleneckModel& m) {
  // Bounds: every term takes one of its values (lower), Delaunay achieves upper.
  double lower = m.floor, upper = m.floor;
  for (const PairTerm& term : m.terms) {
    const int n = term.r < 0 ? 2 : 4;
    lower = std::max(lower, *std::min_element(term.v, term.v + n));
    upper = std::max(upper, term.v[0]);
  }
  std::vector<double> cand = {lower, upper};
  for (const PairTerm& term : m.terms)
    for (int k = 0; k < (term.r < 0 ? 2 : 4); ++k)
      if (term.v[k] > lower && term.v[k] < upper) cand.push_back(term.v[k]);
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());

  BottleneckResult r;
  r.choice.assign(m.num_quads, 0);  // Delaunay: feasible at `upper`
  size_t lo = 0, hi = cand.size() - 1;
  while (lo < hi) {
    const size_t mid = lo + (hi - lo) / 2;
    ThresholdStep step;
    auto a = feasible(m, cand[mid], step);
    r.trace.push_back(step);
    if (a) {
      hi = mid;
      r.choice = std::move(*a);
    } else {
      lo = mid + 1;
    }
  }
  r.value = cand[lo];
  // Among the optimal choices prefer Delaunay diagonals: revert a flipped quad when
  // every term it is part of stays within the optimum (fewer, meaningful flips).
  std::vector<std::vector<uint32_t>> terms_of(m.num_quads);
  for (uint32_t k = 0; k < m.terms.size(); ++k) {
    terms_of[static_cast<uint32_t>(m.terms[k].q)].push_back(k);
    if (m.terms[k].r >= 0) terms_of[static_cast<uint32_t>(m.terms[k].r)].push_back(k);
  }
  for (uint32_t q = 0; q < m.num_quads; ++q) {
    if (!r.choice[q]) continue;
    r.choice[q] = 0;
    for (uint32_t k : terms_of[q]) {
      const PairTerm& t = m.terms[k];
      const int idx = r.choice[static_cast<uint32_t>(t.q)] + (t.r >= 0 ? 2 * r.choice[static_cast<uint32_t>(t.r)] : 0);
      if (t.v[idx] > r.value) {
        r.choice[q] = 1;
        break;
      }
    }
  }
  return r;
}

}  // namespace hodt
