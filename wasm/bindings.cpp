// The embind layer: converts typed arrays in and out of the core's types and turns
// the core's exceptions into JS errors. No logic of its own: everything is in core/.
#include <emscripten/bind.h>
#include <emscripten/heap.h>
#include <emscripten/val.h>

#include "hodt/brute_force.hpp"
#include "hodt/cli.hpp"
#include "hodt/domain.hpp"
#include "hodt/drainage.hpp"
#include "hodt/error.hpp"
#include "hodt/explain.hpp"
#include "hodt/higher_order.hpp"
#include "hodt/measures.hpp"
#include "hodt/read_points.hpp"
#include "hodt/report.hpp"
#include "hodt/solve.hpp"
#include "hodt/solve_options.hpp"
#include "hodt/terrain.hpp"
#include "vector_binding.hpp"

using emscripten::val;
using namespace hodt;

namespace {

// A JS copy of a C++ array (vector_binding.hpp): the result never points into the
// wasm heap, so memory growth cannot detach it.
using hodt_wasm::to_js;

// Runs f, converting the core's exceptions into a JS Error whose name is the kind.
template <class F>
auto guarded(F f) -> decltype(f()) {
  std::string kind, message;
  try {
    return f();
  } catch (const InputError& e) {
    kind = "InputError", message = e.what();
  } catch (const LimitError& e) {
    kind = "LimitError", message = e.what();
  } catch (const Cancelled& e) {
    kind = "Cancelled", message = e.what();
  } catch (const std::bad_alloc&) {
    kind = "LimitError", message = "out of memory";
  } catch (const std::exception& e) {
    kind = "InternalError", message = e.what();
  }
  val error = val::global("Error").new_(message);
  error.set("name", kind);
  error.throw_();
}

Objective objective_of(const std::string& id) {
  const auto o = parse_objective(id);
  if (!o) throw InputError("unknown objective '" + id + "'; valid objectives: " + objective_ids());
  return *o;
}

class TerrainHandle {
 public:
  explicit TerrainHandle(Terrain t) : t_(std::move(t)) {}

  uint32_t numPoints() const { return t_.structure().base.num_vertices(); }
  uint32_t numInputPoints() const { return t_.num_input_points(); }
  uint32_t numQuads() const { return t_.structure().num_quads(); }
  bool isDelaunay() const { return t_.structure().is_delaunay; }
  val inputIndex() const {
    std::vector<uint32_t> idx(numPoints());
    for (uint32_t v = 0; v < idx.size(); ++v) idx[v] = t_.to_input(v);
    return to_js(idx);
  }
  val points() const { return to_js(t_.structure().base.coords.vector()); }
  val quads() const {
    std::vector<uint32_t> q;
    for (const Quad& k : t_.structure().quads) q.insert(q.end(), {k.a, k.b, k.c, k.d});
    return to_js(t_.to_input(q));
  }
  val quadEdges() const {
    std::vector<uint32_t> q;
    for (const Quad& k : t_.structure().quads) q.push_back(k.edge);
    return to_js(q);
  }
  val quadOfTriangle() const { return to_js(t_.structure().quad_of_triangle); }
  // The domain: Infinity for none.
  double maxEdge() const { return t_.max_edge(); }
  void setMaxEdge(double max_edge) { guarded([&] { t_.set_max_edge(max_edge); }); }
  // The warning of a domain that leaves almost nothing inside ("" for none).
  std::string emptyDomainWarning() const { return empty_domain_warning(t_.structure().base).value_or(""); }

  // Live edits (input indices; see Terrain::add_point).
  uint32_t addPoint(double x, double y, double z) { return guarded([&] { return t_.add_point(x, y, z); }); }
  void movePoint(uint32_t i, double x, double y, double z) { guarded([&] { t_.move_point(i, x, y, z); }); }
  void removePoint(uint32_t i) { guarded([&] { t_.remove_point(i); }); }

  // The triangulation of a choice: {triangles, halfedges, hull} in input indices.
  val triangulation(val choice) const {
    return guarded([&] {
      const Mesh m = triangulate(t_.structure(), choice_of(choice));
      val out = val::object();
      out.set("triangles", to_js(t_.to_input(m.triangles)));
      out.set("halfedges", to_js(m.halfedges));
      out.set("hull", to_js(t_.to_input(m.hull)));
      return out;
    });
  }
  // Per-element measures of a choice's triangulation; vertex arrays by kept index.
  val measures(val choice) const {
    return guarded([&] {
      return measures_value(measure(triangulate(t_.structure(), choice_of(choice))));
    });
  }
  val evaluate(val choice) const {
    return guarded([&] {
      const auto v = evaluate_all(triangulate(t_.structure(), choice_of(choice)));
      return to_js(std::vector<double>(v.begin(), v.end()));
    });
  }
  // Values and measures of any triangulation of the points (input indices), such as
  // a higher order result that is not a choice of diagonals.
  val evaluateTriangles(val triangles) const {
    return guarded([&] {
      const auto v = evaluate_all(t_.mesh_of_input_triangles(emscripten::convertJSArrayToNumberVector<uint32_t>(triangles)));
      return to_js(std::vector<double>(v.begin(), v.end()));
    });
  }
  val measuresOfTriangles(val triangles) const {
    return guarded([&] {
      return measures_value(measure(t_.mesh_of_input_triangles(emscripten::convertJSArrayToNumberVector<uint32_t>(triangles))));
    });
  }
  // The drainage network (drainage.hpp) of the base triangulation (triangles null)
  // or of any triangulation of the points (input indices); per input point.
  Drainage drainage(val triangles) const {
    return guarded([&] {
      if (triangles.isNull() || triangles.isUndefined()) return hodt::drainage(t_, t_.structure().base);
      return hodt::drainage(t_, t_.mesh_of_input_triangles(emscripten::convertJSArrayToNumberVector<uint32_t>(triangles)));
    });
  }
  val delaunayValues() const {
    const auto& v = t_.delaunay_values();
    return to_js(std::vector<double>(v.begin(), v.end()));
  }
  static val measures_value(const Measures& ms) {
    val out = val::object();
    out.set("edgeShape", to_js(ms.edge_shape));
    out.set("vertexClass", to_js(ms.vertex_class));
    out.set("extremum", to_js(ms.extremum));
    out.set("degree", to_js(ms.degree));
    out.set("inside", to_js(ms.inside));
    return out;
  }

  static SolveOptions options_of(const std::string& method, double epsilon, bool trace, double order, val progress) {
    SolveOptions options;
    const auto m = parse_method(method);
    if (!m) throw InputError("unknown method '" + method + "'; valid methods: " + method_ids());
    options.method = *m;
    options.epsilon = epsilon;
    options.order = order_from_number(order);
    options.trace = trace;
    if (progress.typeOf().as<std::string>() == "function")
      options.progress = phased([progress](const ProgressPoint& p) {
        // (done, total, info): the phase's fraction as done out of 1, and the phase by name.
        val info = val::object();
        info.set("phase", std::string(phase_name(p.phase)));
        info.set("fraction", p.fraction);
        info.set("sized", p.sized);
        const std::optional<double> left = seconds_left(p);
        info.set("secondsLeft", left ? val(*left) : val::null());
        const val r = progress(p.fraction, 1, info);
        return !(r.isFalse());
      });
    check_options(options);
    return options;
  }

  // The JS object of a solution (all arrays copied out of the heap).
  val solution_object(const Solution& s) const {
    val out = solution_value(s);
    out.set("order", s.order);
    if (s.mesh) out.set("triangles", to_js(t_.to_input(s.mesh->triangles)));
    return out;
  }
  val solution_value(const Solution& s) const {
    const Objective o = s.objective;
    val out = val::object();
    out.set("objective", std::string(info(o).id));
    out.set("sense", std::string(info(o).sense == Sense::Min ? "min" : "max"));
    out.set("method", s.method);
    out.set("value", s.value);
    out.set("delaunayValue", s.delaunay_value);
    out.set("optimal", s.optimal);
    out.set("bound", s.bound ? val(*s.bound) : val::null());
    out.set("flipped", s.mesh ? s.non_delaunay_edges : count_flipped(s.choice));
    out.set("timeMs", s.time_ms);
    out.set("choice", to_js(s.choice));
    out.set("localSearchImproved", s.local_search_improved);
    out.set("details", s.details);
    if (s.critical) {
      val c = val::object();
      c.set("first", to_js(t_.to_input(std::vector<uint32_t>(s.critical->first.begin(), s.critical->first.end()))));
      c.set("second", to_js(t_.to_input(std::vector<uint32_t>(s.critical->second.begin(), s.critical->second.end()))));
      c.set("value", s.critical->value);
      out.set("critical", c);
    } else {
      out.set("critical", val::null());
    }
    out.set("trace", to_js(s.trace));
    val phases = val::array();  // (by hand: a value_object has no optional fields)
    for (const PhaseStep& p : s.phases) {
      val step = val::object();
      step.set("phase", p.name);
      step.set("ms", p.ms);
      step.set("value", p.value ? val(*p.value) : val::null());
      step.set("bound", p.bound ? val(*p.bound) : val::null());
      step.set("improved", p.improved);
      step.set("tightened", p.tightened);
      step.set("proved", p.proved);
      phases.call<void>("push", step);
    }
    out.set("phases", phases);
    return out;
  }

  // Any order (order k > 1: k-th order Delaunay triangulations; the result then
  // also carries its triangles, input indices, since it is not a choice of
  // diagonals). The core checks every option (check_options). progress:
  // undefined, or a JS function (done, total, info) returning false to cancel.
  val solve(const std::string& objective, const std::string& method, double epsilon, bool trace, double order,
            val progress) const {
    return guarded([&] {
      const Objective o = objective_of(objective);
      const SolveOptions options = options_of(method, epsilon, trace, order, progress);
      // Measured first, where progress can still stop it.
      const double delaunay_value = t_.delaunay_value(o, in_phase(options.progress, Phase::Measuring));
      Solution s = hodt::solve(t_.structure(), o, options);
      s.delaunay_value = delaunay_value;
      return solution_object(s);
    });
  }
  // The same solve, with the structures its solvers built (explain.hpp) beside the
  // solution; vertex indices are input indices.
  val explain(const std::string& objective, const std::string& method, double epsilon, double order, val progress) const {
    return guarded([&] {
      const Objective o = objective_of(objective);
      const SolveOptions options = options_of(method, epsilon, true, order, progress);
      const double delaunay_value = t_.delaunay_value(o, in_phase(options.progress, Phase::Measuring));
      Explanation e = hodt::explain(t_.structure(), o, options);
      e.solution.delaunay_value = delaunay_value;
      if (e.regions) {
        RegionExplanation& r = *e.regions;
        r.useful = t_.to_input(r.useful), r.fixed = t_.to_input(r.fixed), r.triangles = t_.to_input(r.triangles);
      }
      val out = val::object();
      out.set("solution", solution_object(e.solution));
      out.set("search", e.search ? val(*e.search) : val::null());
      out.set("baker", e.baker ? val(*e.baker) : val::null());
      out.set("exact", e.exact ? val(*e.exact) : val::null());
      out.set("regions", e.regions ? val(*e.regions) : val::null());
      return out;
    });
  }
  // Values of all objectives for all 2^m choices, row-major (choice index, objective).
  val enumerateAll() const {
    return guarded([&] {
      const auto rows = enumerate_all(t_.structure());
      std::vector<double> flat;
      flat.reserve(rows.size() * kNumObjectives);
      for (const auto& r : rows) flat.insert(flat.end(), r.begin(), r.end());
      return to_js(flat);
    });
  }
  // order: 0 for none.
  std::string statsJson(double order) const {
    return guarded([&] { return stats_json(t_, order == 0 ? 0 : order_from_number(order)); });
  }
  // Useful k-OD edges (pairs) and triangles (triples), input indices.
  val usefulEdges(double order) const {
    return guarded([&] {
      const uint32_t k = order_from_number(order);
      std::vector<uint32_t> flat;
      for (auto [u, v] : useful_edges(t_.delaunay_mesh(), k)) flat.insert(flat.end(), {u, v});
      return to_js(t_.to_input(flat));
    });
  }
  val usefulTriangles(double order) const {
    return guarded([&] {
      const uint32_t k = order_from_number(order);
      const auto edges = useful_edges(t_.delaunay_mesh(), k);
      std::vector<uint32_t> flat;
      for (const auto& tri : useful_triangles(t_.delaunay_mesh(), k, edges)) flat.insert(flat.end(), tri.begin(), tri.end());
      return to_js(t_.to_input(flat));
    });
  }

 private:
  Choice choice_of(const val& v) const {
    Choice c = v.isUndefined() || v.isNull() ? Choice(t_.structure().num_quads(), 0)
                                              : emscripten::convertJSArrayToNumberVector<uint8_t>(v);
    t_.check_choice(c);
    return c;
  }
  Terrain t_;
};

TerrainHandle* fromPoints(val xyz, bool dedupe) {
  return guarded([&] {
    std::vector<double> v = emscripten::convertJSArrayToNumberVector<double>(xyz);
    return new TerrainHandle(Terrain::from_points(std::move(v), dedupe ? Dedupe::KeepFirst : Dedupe::Error));
  });
}

TerrainHandle* fromTriangulation(val xyz, val triangles, val flippable) {
  return guarded([&] {
    return new TerrainHandle(Terrain::from_triangulation(
        emscripten::convertJSArrayToNumberVector<double>(xyz),
        emscripten::convertJSArrayToNumberVector<uint32_t>(triangles),
        emscripten::convertJSArrayToNumberVector<uint32_t>(flippable)));
  });
}

// A file's contents given as a string (UTF-8) or as its bytes (a Uint8Array, so
// that the core decodes them, byte order marks and UTF-16 included).
std::string bytes_of(const val& v) {
  if (v.isString()) return v.as<std::string>();
  std::string out(v["length"].as<size_t>(), '\0');
  val(emscripten::typed_memory_view(out.size(), reinterpret_cast<uint8_t*>(out.data()))).call<void>("set", v);
  return out;
}

// Parses a point file's text: {xyz: Float64Array, lines: Int32Array}.
val readPoints(val text, const std::string& name) {
  return guarded([&] {
    const ParsedPoints p = read_points(bytes_of(text), name);
    val out = val::object();
    out.set("xyz", to_js(p.xyz));
    out.set("lines", to_js(p.lines));
    if (p.max_edge < INFINITY) out.set("maxEdge", p.max_edge);
    return out;
  });
}

// An Error returned by a front end callback, as the core's reason: its Node code
// (ENOENT, ...) if it has one, else its message.
std::string reason_of(const val& error) {
  if (error.isUndefined() || error.isNull()) return "";
  const val code = error["code"];
  return code.isString() ? code.as<std::string>() : error["message"].as<std::string>();
}

bool is_function(const val& v) { return v.typeOf().as<std::string>() == "function"; }

// A TinData as hodt/export's MeshData.
val mesh_data(const TinData& tin) {
  val out = val::object();
  out.set("points", to_js(tin.points));
  out.set("triangles", to_js(tin.triangles));
  out.set("vertexClass", to_js(tin.vertex_class));
  out.set("extremum", to_js(tin.extremum));
  out.set("nonDelaunay", to_js(tin.non_delaunay));
  if (!tin.outside.empty()) out.set("outside", to_js(tin.outside));
  out.set("comment", tin.comment);
  if (!tin.crs.empty()) out.set("crs", tin.crs);
  return out;
}

// The CLI. read(path) returns the file's text or bytes, or an Error. io (optional):
// {writeFile(path, bytes), writeMesh(path, format, mesh)} returning nothing or an
// Error, progress(text), notes(text) (the input's notes once it is accepted),
// stderrIsTerminal.
val runCli(val args, val read, val io) {
  std::vector<std::string> a;
  const unsigned n = args["length"].as<unsigned>();
  for (unsigned i = 0; i < n; ++i) a.push_back(args[i].as<std::string>());
  CliHost host;
  host.read = [&](const std::string& path, std::string& error) -> std::optional<std::string> {
    const val text = read(path);
    if (text.isString() || text.instanceof(val::global("Uint8Array"))) return bytes_of(text);
    error = reason_of(text);
    return std::nullopt;
  };
  const bool have_io = io.typeOf().as<std::string>() == "object" && !io.isNull();
  if (have_io && is_function(io["writeFile"]))
    host.write = [&](const std::string& path, std::string_view bytes, std::string& error) {
      // The file's bytes, copied out of the heap: a 50 MB JSON as a string would
      // be decoded from UTF-8 here and encoded again by the writer.
      const val copy = val::global("Uint8Array")
                           .new_(emscripten::typed_memory_view(bytes.size(), reinterpret_cast<const uint8_t*>(bytes.data())));
      const val failed = io.call<val>("writeFile", path, copy);
      error = reason_of(failed);
      return failed.isUndefined() || failed.isNull();
    };
  if (have_io && is_function(io["writeMesh"]))
    host.write_mesh = [&](const std::string& path, OutputFormat format, const TinData& tin, std::string& error) {
      const val failed = io.call<val>("writeMesh", path, std::string(format_id(format)), mesh_data(tin));
      error = reason_of(failed);
      return failed.isUndefined() || failed.isNull();
    };
  if (have_io && is_function(io["progress"]))
    host.show_progress = [&](const std::string& text) { io.call<void>("progress", text); };
  if (have_io && is_function(io["notes"]))
    host.show_notes = [&](const std::string& text) { io.call<void>("notes", text); };
  host.stderr_is_terminal = have_io && io["stderrIsTerminal"].isTrue();
  const CliResult r = run_cli(a, host);
  val out = val::object();
  out.set("exitCode", r.exit_code);
  out.set("stdout", r.out);
  out.set("stderr", r.err);
  return out;
}

val objectiveTable() {
  val out = val::array();
  for (const auto& i : objectives()) {
    val o = val::object();
    o.set("id", std::string(i.id));
    o.set("sense", std::string(i.sense == Sense::Min ? "min" : "max"));
    o.set("combine", std::string(i.combine == Combine::Sum ? "sum" : "max"));
    o.set("integral", i.integral);
    o.set("polynomial", i.polynomial);
    o.set("unit", std::string(i.unit));
    o.set("reference", std::string(i.reference));
    o.set("summary", std::string(i.summary));
    out.call<void>("push", o);
  }
  return out;
}

}  // namespace

EMSCRIPTEN_BINDINGS(hodt) {
  emscripten::class_<TerrainHandle>("TerrainHandle")
      .function("numPoints", &TerrainHandle::numPoints)
      .function("numInputPoints", &TerrainHandle::numInputPoints)
      .function("numQuads", &TerrainHandle::numQuads)
      .function("isDelaunay", &TerrainHandle::isDelaunay)
      .function("inputIndex", &TerrainHandle::inputIndex)
      .function("points", &TerrainHandle::points)
      .function("quads", &TerrainHandle::quads)
      .function("quadEdges", &TerrainHandle::quadEdges)
      .function("quadOfTriangle", &TerrainHandle::quadOfTriangle)
      .function("maxEdge", &TerrainHandle::maxEdge)
      .function("emptyDomainWarning", &TerrainHandle::emptyDomainWarning)
      .function("setMaxEdge", &TerrainHandle::setMaxEdge)
      .function("addPoint", &TerrainHandle::addPoint)
      .function("movePoint", &TerrainHandle::movePoint)
      .function("removePoint", &TerrainHandle::removePoint)
      .function("triangulation", &TerrainHandle::triangulation)
      .function("measures", &TerrainHandle::measures)
      .function("evaluate", &TerrainHandle::evaluate)
      .function("delaunayValues", &TerrainHandle::delaunayValues)
      .function("evaluateTriangles", &TerrainHandle::evaluateTriangles)
      .function("measuresOfTriangles", &TerrainHandle::measuresOfTriangles)
      .function("drainage", &TerrainHandle::drainage)
      .function("solve", &TerrainHandle::solve)
      .function("explain", &TerrainHandle::explain)
      .function("enumerateAll", &TerrainHandle::enumerateAll)
      .function("statsJson", &TerrainHandle::statsJson)
      .function("usefulEdges", &TerrainHandle::usefulEdges)
      .function("usefulTriangles", &TerrainHandle::usefulTriangles);
  emscripten::value_object<Drainage>("Drainage")
      .field("downstream", &Drainage::downstream)
      .field("basin", &Drainage::basin)
      .field("accumulation", &Drainage::accumulation)
      .field("pits", &Drainage::pits)
      .field("outlets", &Drainage::outlets);
  emscripten::value_object<ThresholdStep>("ThresholdStep")
      .field("threshold", &ThresholdStep::threshold)
      .field("satisfiable", &ThresholdStep::satisfiable)
      .field("clauses", &ThresholdStep::clauses)
      .field("forced", &ThresholdStep::forced)
      .field("immediateNo", &ThresholdStep::immediate_no);
  emscripten::value_object<ThresholdTest>("ThresholdTest")
      .field("threshold", &ThresholdTest::threshold)
      .field("satisfiable", &ThresholdTest::satisfiable)
      .field("immediateNo", &ThresholdTest::immediate_no)
      .field("forced", &ThresholdTest::forced)
      .field("blocked", &ThresholdTest::blocked)
      .field("clauses", &ThresholdTest::clauses)
      .field("component", &ThresholdTest::component)
      .field("conflicts", &ThresholdTest::conflicts)
      .field("assignment", &ThresholdTest::assignment);
  emscripten::value_object<SearchExplanation>("SearchExplanation")
      .field("floor", &SearchExplanation::floor)
      .field("candidates", &SearchExplanation::candidates)
      .field("tests", &SearchExplanation::tests);
  emscripten::value_object<BakerShiftExplanation>("BakerShiftExplanation")
      .field("shift", &BakerShiftExplanation::shift)
      .field("relaxed", &BakerShiftExplanation::relaxed)
      .field("value", &BakerShiftExplanation::value)
      .field("bound", &BakerShiftExplanation::bound)
      .field("dropped", &BakerShiftExplanation::dropped)
      .field("choice", &BakerShiftExplanation::choice);
  emscripten::value_object<BakerExplanation>("BakerExplanation")
      .field("lambda", &BakerExplanation::lambda)
      .field("width", &BakerExplanation::width)
      .field("layer", &BakerExplanation::layer)
      .field("shifts", &BakerExplanation::shifts);
  emscripten::value_object<ExactExplanation>("ExactExplanation")
      .field("width", &ExactExplanation::width)
      .field("numComponents", &ExactExplanation::num_components)
      .field("order", &ExactExplanation::order)
      .field("component", &ExactExplanation::component);
  emscripten::value_object<RegionExplanation>("RegionExplanation")
      .field("order", &RegionExplanation::order)
      .field("useful", &RegionExplanation::useful)
      .field("fixed", &RegionExplanation::fixed)
      .field("triangles", &RegionExplanation::triangles)
      .field("regionOfTriangle", &RegionExplanation::region_of_triangle)
      .field("triangulations", &RegionExplanation::triangulations)
      .field("complete", &RegionExplanation::complete);
  emscripten::function("fromPoints", &fromPoints, emscripten::allow_raw_pointers());
  emscripten::function("fromTriangulation", &fromTriangulation, emscripten::allow_raw_pointers());
  emscripten::function("readPoints", &readPoints);
  emscripten::function("runCli", &runCli);
  emscripten::function("objectiveTable", &objectiveTable);
  // Bytes of wasm memory reserved so far: memory only grows, so this is the peak.
  emscripten::function("heapSize", +[]() { return static_cast<double>(emscripten_get_heap_size()); });
}
