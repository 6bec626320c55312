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

struct ObjectiveInfo {
  Objective objective;
  const char* id;       // e.g. "max-convex-vertices"
  Sense sense;
  bool integral;        // counts and degrees (exact integers)
  const char* summary;  // one line, for help texts
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
