#include "exact/bottleneck.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "hodt/explain.hpp"
#include "engines/parity_sat.hpp"
#include "engines/two_sat.hpp"

namespace hodt {

BottleneckBuilder::BottleneckBuilder(uint32_t num_quads, bool prune, bool repeated_pairs)
    : prune_(prune), repeated_pairs_(repeated_pairs), unary_seq_(num_quads, kUnary), unary_term_(num_quads, kNone),
      in_binary_(num_quads, 0) {
  model_.num_quads = num_quads;
  if (repeated_pairs) index_.reserve(2 * size_t(num_quads));  // no rehash of a large map in one step
}

void BottleneckBuilder::constant(double v) { model_.floor = std::max(model_.floor, v); }

bool BottleneckBuilder::below_floor(const double* v, int n) const {
  return prune_ && std::all_of(v, v + n, [&](double x) { return x <= model_.floor; });
}

PairTerm* BottleneckBuilder::find(uint32_t q, uint32_t r) {
  const uint32_t at = r == kUnary ? unary_term_[q] : index_.find((uint64_t(q) << 32) | r);
  return at == kNone ? nullptr : &model_.terms[at];
}

void BottleneckBuilder::add(const PairTerm& t, uint32_t seq) {
  const uint32_t at = static_cast<uint32_t>(model_.terms.size());
  if (t.r < 0) unary_term_[t.q] = at;
  else if (repeated_pairs_) index_.insert((uint64_t(uint32_t(t.q)) << 32) | uint32_t(t.r), at);
  if (t.r >= 0) in_binary_[t.q] = in_binary_[t.r] = 1;
  model_.terms.push_back(t);
  seq_.push_back(seq);
}

void BottleneckBuilder::unary(uint32_t q, double v0, double v1) {
  if (unary_seq_[q] == kUnary) unary_seq_[q] = next_seq_++;
  // Quad q takes one of its states, so every triangulation's max is at least the
  // smaller value: a floor as good as a fixed pair's (on a grid, where no triangle
  // is fixed, it is the only one and prunes the whole model).
  if (prune_) model_.floor = std::max(model_.floor, std::min(v0, v1));
  const double v[2] = {v0, v1};
  if (below_floor(v, 2)) return;
  if (PairTerm* t = find(q, kUnary)) {
    t->v[0] = t->v[2] = std::max(t->v[0], v0);
    t->v[1] = t->v[3] = std::max(t->v[1], v1);
    return;
  }
  PairTerm t;
  t.q = static_cast<int32_t>(q);
  t.v[0] = t.v[2] = v0;
  t.v[1] = t.v[3] = v1;
  add(t, unary_seq_[q]);
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
  const uint32_t seq = next_seq_++;
  // (Only quads that both have a kept binary term can share one: on a raster,
  // where the floor prunes most pairs, most lookups end here.)
  PairTerm* kept = repeated_pairs_ && in_binary_[t.q] && in_binary_[t.r] ? find(uint32_t(t.q), uint32_t(t.r)) : nullptr;
  if (kept) seq_[static_cast<size_t>(kept - model_.terms.data())] = seq;  // even when this part is pruned
  if (below_floor(t.v, 4)) return;
  if (!kept) {
    add(t, seq);
    kept = &model_.terms.back();
  } else {
    for (int k = 0; k < 4; ++k) kept->v[k] = std::max(kept->v[k], t.v[k]);
  }
  // Likewise the pair takes one of its four states: the search's lower end.
  // (On a grid, where every term is binary, the floor rises to it and prunes
  // the rest as they come; an entry a cut answered is at most the floor and
  // raises nothing.)
  if (prune_) model_.floor = std::max(model_.floor, *std::min_element(kept->v, kept->v + 4));
}

BottleneckModel BottleneckBuilder::finish(const Progress& progress) {
  // Terms kept before the floor rose may have fallen under it.
  report(progress, 0, 3);
  index_.clear();  // freed now, between progress points
  report(progress, 1, 3);
  std::vector<uint32_t> order;
  for (uint32_t k = 0; k < model_.terms.size(); ++k)
    if (!below_floor(model_.terms[k].v, 4)) order.push_back(k);
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return seq_[a] < seq_[b]; });
  report(progress, 2, 3);
  std::vector<PairTerm> terms(order.size());
  for (size_t k = 0; k < order.size(); ++k) terms[k] = model_.terms[order[k]];
  model_.terms = std::move(terms);
  return std::move(model_);
}

namespace {

// The quads' states a term forbids at threshold t: bit x + 2 y for (x_q, x_r) =
// (x, y); a unary term's bit x for x_q = x.
uint32_t forbidden(const PairTerm& term, double t) {
  uint32_t f = 0;
  for (int k = 0; k < (term.r < 0 ? 2 : 4); ++k) f |= uint32_t(term.v[k] > t) << k;
  return f;
}

// The test as a parity system (parity_sat.hpp), if every binary term forbids
// no state, both mixed or both equal states, or all states but those of one
// quad's value: else nothing (a term that forbids one state is a true clause).
std::optional<ParitySat> as_parity(const BottleneckModel& m, double t) {
  ParitySat p(m.num_quads);
  for (const PairTerm& term : m.terms) {
    const uint32_t f = forbidden(term, t), q = static_cast<uint32_t>(term.q), r = static_cast<uint32_t>(term.r);
    if (term.r < 0) {
      if (f == 1 || f == 2) p.fix(q, f == 1);  // (both: the caller stops first)
      continue;
    }
    switch (f) {
      case 0b0000: break;
      case 0b0110: p.relate(q, r, false); break;  // no mixed states
      case 0b1001: p.relate(q, r, true); break;   // no equal states
      case 0b0011: p.fix(r, true); break;         // y = 0 forbidden
      case 0b1100: p.fix(r, false); break;
      case 0b0101: p.fix(q, true); break;         // x = 0 forbidden
      case 0b1010: p.fix(q, false); break;
      case 0b1111: p.relate(q, q, true); break;   // (a contradiction)
      default:
        if (__builtin_popcount(f) != 3) return std::nullopt;
        const uint32_t allowed = 0b1111 & ~f;  // one state left: x = its bit 1, y = its bit 2
        p.fix(q, allowed & 0b1010), p.fix(r, allowed & 0b1100);
    }
  }
  return p;
}

// Is there a choice with every term at most t? The paper's eliminations (a pair
// over the threshold between fixed triangles, or in both states of a quad: "no";
// in one state: the quad is forced) become unit clauses; the rest 2-SAT, decided
// as a parity system when it is one (the same answer, found faster).
// test (optional) records what the test saw, in full.
std::optional<Choice> feasible(const BottleneckModel& m, double t, ThresholdStep& step, const Progress& progress,
                               double done, double total, ThresholdTest* test) {
  step = ThresholdStep{t, false, 0, 0, false};
  if (test) test->threshold = t;
  if (m.floor > t) {
    step.immediate_no = true;
    if (test) test->immediate_no = true;
    return std::nullopt;
  }
  TwoSat sat(m.num_quads);
  WorkCounter work;
  uint32_t clauses = 0;
  for (const PairTerm& term : m.terms) {
    if (work.tick()) report(progress, done, total);
    const uint32_t q = static_cast<uint32_t>(term.q), f = forbidden(term, t);
    if (term.r < 0) {
      if (f == 3) {
        step.immediate_no = true;
        if (test) test->immediate_no = true, test->blocked.push_back(q);
        return std::nullopt;
      }
      if (f) {
        ++step.forced, ++clauses;
        if (test) test->forced.insert(test->forced.end(), {q, f == 2 ? 0u : 1u});
      }
      continue;
    }
    clauses += static_cast<uint32_t>(__builtin_popcount(f));
  }
  step.clauses = clauses;
  std::optional<ParitySat> parity = as_parity(m, t);
  std::optional<Choice> a;
  if (parity) a = parity->solve();
  if (!parity || test) {  // the clauses (and for a record, their components)
    for (const PairTerm& term : m.terms) {
      if (work.tick()) report(progress, done, total);
      const uint32_t q = static_cast<uint32_t>(term.q), f = forbidden(term, t);
      for (uint32_t x = 0; x < 2; ++x)
        for (uint32_t y = 0; y < (term.r < 0 ? 1u : 2u); ++y)
          if ((f >> (x + 2 * y)) & 1) term.r < 0 ? sat.forbid(q, x) : sat.forbid(q, x, term.r, y);
    }
    std::optional<Choice> general = sat.solve(progress, done, total, test ? &test->component : nullptr);
    if (!parity) a = std::move(general);
    else if (general.has_value() != a.has_value()) throw std::logic_error("bottleneck: parity and 2-SAT disagree");
  }
  step.satisfiable = a.has_value();
  if (test) {
    test->satisfiable = step.satisfiable;
    for (const TwoSat::Clause& c : sat.clauses()) test->clauses.insert(test->clauses.end(), {c.a, c.b});
    for (uint32_t q = 0; q < m.num_quads; ++q)
      if (test->component[2 * q] >= 0 && test->component[2 * q] == test->component[2 * q + 1]) test->conflicts.push_back(q);
    if (a) test->assignment = *a;
  }
  return a;
}

}  // namespace

BottleneckResult solve_bottleneck(const BottleneckModel& m, const Progress& progress, SearchExplanation* record) {
  // Bounds: every term takes one of its values (lower), Delaunay achieves upper.
  double lower = m.floor, upper = m.floor;
  report(progress, 0, 1);
  for (const PairTerm& term : m.terms) {
    const int n = term.r < 0 ? 2 : 4;
    lower = std::max(lower, *std::min_element(term.v, term.v + n));
    upper = std::max(upper, term.v[0]);
  }
  std::vector<double> cand = {lower, upper};
  for (const PairTerm& term : m.terms)
    for (int k = 0; k < (term.r < 0 ? 2 : 4); ++k)
      if (term.v[k] > lower && term.v[k] < upper) cand.push_back(term.v[k]);
  report(progress, 0, 1);
  std::sort(cand.begin(), cand.end());
  cand.erase(std::unique(cand.begin(), cand.end()), cand.end());

  if (record) record->floor = m.floor, record->candidates = cand;
  BottleneckResult r;
  r.choice.assign(m.num_quads, 0);  // Delaunay: feasible at `upper`
  size_t lo = 0, hi = cand.size() - 1;
  // Progress: the binary search's steps (about log2 of the candidates), and
  // the lower bound's test first: on a raster, where pairs tie in large groups,
  // the optimum is often the bound itself, one test instead of all the steps
  // (and elsewhere one test more).
  const double steps = std::ceil(std::log2(static_cast<double>(cand.size()))) + 2;
  bool lower_first = true;
  while (lo < hi) {
    const size_t mid = lower_first ? lo : lo + (hi - lo) / 2;
    lower_first = false;
    ThresholdStep step;
    const double done = static_cast<double>(r.trace.size());
    report(progress, done, steps);
    ThresholdTest* test = record ? &record->tests.emplace_back() : nullptr;
    auto a = feasible(m, cand[mid], step, progress, done, steps, test);
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
  // Terms of each quad in compressed rows, in term order.
  std::vector<uint32_t> first(m.num_quads + 1, 0), terms_of;
  for (const PairTerm& t : m.terms) {
    ++first[static_cast<uint32_t>(t.q) + 1];
    if (t.r >= 0) ++first[static_cast<uint32_t>(t.r) + 1];
  }
  for (uint32_t q = 0; q < m.num_quads; ++q) first[q + 1] += first[q];
  terms_of.resize(first.back());
  {
    std::vector<uint32_t> fill(first.begin(), first.end() - 1);
    for (uint32_t k = 0; k < m.terms.size(); ++k) {
      terms_of[fill[static_cast<uint32_t>(m.terms[k].q)]++] = k;
      if (m.terms[k].r >= 0) terms_of[fill[static_cast<uint32_t>(m.terms[k].r)]++] = k;
    }
  }
  for (uint32_t q = 0; q < m.num_quads; ++q) {
    if (!r.choice[q]) continue;
    r.choice[q] = 0;
    for (uint32_t k = first[q]; k < first[q + 1]; ++k) {
      const PairTerm& t = m.terms[terms_of[k]];
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
