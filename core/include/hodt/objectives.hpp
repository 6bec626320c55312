// The 13 objectives of docs/objectives.md: ids, senses, and their value on a triangulation.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "hodt/mesh.hpp"
#include "hodt/progress.hpp"

namespace hodt {

enum class Objective : uint8_t {
  MaxConvexVertices,
  MinmaxEdgeAreaRatio,
  MinmaxEdgeNormalAngle,
  MinmaxEdgeEnclosingCircle,
  MinmaxVertexAreaRatio,
  MinmaxVertexNormalAngle,
  MinLocalMinima,
  MinLocalExtrema,
  MinTotalEdgeLength,
  MinmaxTriangleArea,
  MaxConvexEdges,
  MinMixedVertices,
  MinmaxDegree,
};
constexpr size_t kNumObjectives = 13;

enum class Sense : uint8_t { Min, Max };

// How an objective's local terms make its value: their sum (counts, lengths) or
// their largest (the min-max objectives). Every engine reads this one enum.
enum class Combine : uint8_t { Sum, Max };
// Two values combined (the identity is 0: every term is >= 0, and a max over nothing is 0).
inline double combine(Combine c, double a, double b) { return c == Combine::Sum ? a + b : (a > b ? a : b); }

// What the objective table knows of each objective; the solvers, the factor
// models, the help texts and the bindings read it here rather than keeping
// their own list.
struct ObjectiveInfo {
  Objective objective;
  const char* id;  // e.g. "max-convex-vertices"
  Sense sense;
  Combine combine;
  bool integral;           // counts and degrees (exact integers)
  bool polynomial;         // a polynomial exact algorithm at first order (else NP-hard)
  const char* unit;        // of the value, e.g. "ratio, >= 1"
  const char* reference;   // the result it rests on, e.g. "Thm 3, 2-SAT"
  const char* summary;     // one line, for help texts
};

const std::array<ObjectiveInfo, kNumObjectives>& objectives();
const ObjectiveInfo& info(Objective o);
std::optional<Objective> parse_objective(std::string_view id);
// "a, b, c" list of the valid ids, for error messages.
std::string objective_ids();

// Is value a strictly better than b for objective o?
inline bool better(Sense s, double a, double b) { return s == Sense::Min ? a < b : a > b; }
// Of two proven bounds on an optimum, the one closer to it (the less good value).
inline double tighter(Sense s, double a, double b) { return better(s, a, b) ? b : a; }

// The value of every objective on one triangulation (max over an empty set of
// pairs is 0). Indexed by static_cast<size_t>(Objective).
std::array<double, kNumObjectives> evaluate_all(const Mesh& mesh);
// One objective's value; progress (solvers measure their result) is called
// along the way and may cancel.
double evaluate(Objective o, const Mesh& mesh, const Progress& progress = {});

}  // namespace hodt
