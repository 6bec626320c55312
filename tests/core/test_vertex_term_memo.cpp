// Vertex terms remembered by their stars' neighbours: the memo answers what
// the evaluation would, evaluates each star once, and region models built with
// it (again and again, as one solve builds them) are the models built without.
#include <doctest/doctest.h>

#include <map>

#include "hodt/higher_order.hpp"
#include "generators.hpp"
#include "higher_order/regions/region_model.hpp"
#include "higher_order/regions/regions.hpp"
#include "higher_order/regions/vertex_term_memo.hpp"
#include "k_order_reference.hpp"

using namespace hodt;
using namespace hodt::test;

namespace {

void check_same_graph(const StateGraph& a, const StateGraph& b) {
  CHECK(a.constant == b.constant);
  CHECK(a.domain == b.domain);
  CHECK(a.unary == b.unary);
  CHECK(a.relaxed_terms == b.relaxed_terms);
  REQUIRE(a.factors.size() == b.factors.size());
  for (size_t i = 0; i < a.factors.size(); ++i) {
    CHECK(a.factors[i].scope == b.factors[i].scope);
    CHECK(a.factors[i].project == b.factors[i].project);
    CHECK(a.factors[i].table == b.factors[i].table);
  }
}

}  // namespace

TEST_CASE("vertex term memo: each star evaluated once, the same value back, nothing kept past its cap") {
  Rng r(7);
  VertexTermMemo memo;
  VertexTermMemo capped(5);
  std::map<std::pair<uint32_t, std::vector<uint32_t>>, double> truth;
  uint64_t evaluations = 0, capped_evaluations = 0;
  for (int i = 0; i < 20'000; ++i) {
    // Few centres and short neighbour lists: keys repeat, and lists that are
    // prefixes of others or differ in one place meet.
    const uint32_t v = static_cast<uint32_t>(r.below(20));
    std::vector<uint32_t> nb;
    for (uint32_t w = 0, n = static_cast<uint32_t>(r.below(5)); nb.size() < n; ++w)
      if (r.below(3) == 0) nb.push_back(w);
    const double value = static_cast<double>(v) * 1000 + static_cast<double>(nb.size()) + (nb.empty() ? 0 : nb.back() * 0.5);
    truth.emplace(std::pair{v, nb}, value);
    CHECK(memo(v, nb, [&] { ++evaluations; return value; }) == value);
    CHECK(capped(v, nb, [&] { ++capped_evaluations; return value; }) == value);
    CHECK(evaluations == truth.size());
  }
  CHECK(memo.size() == truth.size());
  CHECK(capped.size() == 5);
  CHECK(capped_evaluations > truth.size());
}

TEST_CASE("region models built with a memo, first and again, are the models built without (vertex objectives, k = 2, 3, 4)") {
  const Objective vertex_objectives[] = {Objective::MaxConvexVertices,     Objective::MinMixedVertices,
                                         Objective::MinLocalMinima,        Objective::MinLocalExtrema,
                                         Objective::MinmaxVertexAreaRatio, Objective::MinmaxVertexNormalAngle,
                                         Objective::MinmaxDegree};
  size_t remembered = 0;
  for_small_k_instances({2, 3, 4}, 25, 131, [&](uint32_t k, uint64_t seed, const FirstOrder& fo, const KOrderStructure&) {
    const Regions R = k_order_regions(fo.base, k);
    // The same regions with one triangulation each: a model whose stars are a
    // subset, built first (as a ladder's lower order is).
    Regions first = R;
    for (Region& g : first.regions) g.states.resize(1);
    for (const Objective o : vertex_objectives) {
      INFO("k = " << k << ", seed " << seed << ", " << info(o).id);
      VertexTermMemo memo;
      RegionModelLimits with;
      with.memo = &memo;
      check_same_graph(region_model(fo.base, first, o).graph, region_model(fo.base, first, o, with).graph);
      const RegionModel plain = region_model(fo.base, R, o);
      check_same_graph(plain.graph, region_model(fo.base, R, o, with).graph);
      check_same_graph(plain.graph, region_model(fo.base, R, o, with).graph);
      remembered += memo.size();
    }
  });
  CHECK(remembered > 1000);
}
