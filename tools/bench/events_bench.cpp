// Event detection on rule applications (Gaide et al. 2023, §5): the static analysis with its
// run-time confirmation (checker/events/event_log.hpp) against the dynamic detector, which names
// every orbit of G before and of H after the application and compares them
// (checker/events/dynamic_events.hpp), in the same process, per orbit type and object size.
//
// Scenarios (the paper's three; its meshes and sizes are not given):
//   creation   face extrusion (tools/data/rules/face_extrusion.json) of one quad of a torus;
//   split      quad subdivision (tools/data/rules/quad_subdivision.json, orbit <0,1,2>: the whole
//              object) of a cube already subdivided k times (iterated), and, as a local split, face
//              triangulation (face_triangulation.json) of one quad of a torus;
//   merge      deletion of the middle shared face of a stack of cubes (a 3-G-map polycube), which
//              merges the two volumes and their border faces: Jerboa's MergeHFaces, from the
//              Jerboa fixture tools/data/jerboa/JerboaTrackingOrbit.jme.
// Objects of about 10^3 to 10^6 darts. For each (scenario, size, orbit type) three benchmarks:
//   apply     the application alone (scheme::apply);
//   static    the application with the event log of that orbit type (static events computed once,
//             outside the timing; confirmation, naming of the touched orbits);
//   dynamic   snapshot of G (orbit names and links), the application, the comparison with H.
// Each iteration applies the rule to a fresh copy of the object (the copy is not timed: manual
// timing, in thread CPU time; the copy has room for the new darts and an allocated marker, as a map
// in a modeler), after the same method was run, untimed, on a copy of the scenario's smallest
// object: copying a large object evicts the code and the rule's data from the caches, the warm-up
// puts every size in the state of a modeler between two operations. tools/bench/events.sh prints
// the ratios dynamic/static, with and without the application's own time.
//
// GMR_BENCH_SCALE (environment, default 1.0) scales the largest sizes down (e.g. 0.01).
#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "checker/events/dynamic_events.hpp"
#include "checker/events/event_log.hpp"
#include "checker/events/static_events.hpp"
#include "model/core/builders.hpp"
#include "model/rule_io/jme_import.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/scheme/scheme_engine.hpp"
#include "tools/bench/bench_scale.hpp"

using namespace gmr;
using namespace gmr::events;
using scheme::RuleScheme;
using scheme::SchemeEngine;

namespace {

using bench::scale;

RuleScheme library_rule(const std::string& name) {
  return io::read_scheme_file(std::string(GMR_SOURCE_DIR) + "/tools/data/rules/" + name + ".json");
}
RuleScheme jerboa_rule(const std::string& name) {
  for (auto& r :
       io::read_jme_file(std::string(GMR_SOURCE_DIR) + "/tools/data/jerboa/JerboaTrackingOrbit.jme")
           .rules)
    if (r.name == name) return r;
  throw std::runtime_error("no Jerboa rule " + name);
}

// One prepared case: an object, a rule, its hooks.
struct Case {
  Map object{2};
  std::unique_ptr<SchemeEngine> engine;
  std::vector<Dart> hooks;
};

// Torus of about `darts` darts (8wh darts, w = h).
Map torus_of(double darts) {
  const auto w = static_cast<size_t>(std::max(3.0, std::round(std::sqrt(darts / 8))));
  return make_torus(w, w);
}

Case creation_case(double darts) {
  return {torus_of(darts), std::make_unique<SchemeEngine>(library_rule("face_extrusion")), {0}};
}
Case local_split_case(double darts) {
  return {torus_of(darts), std::make_unique<SchemeEngine>(library_rule("face_triangulation")), {0}};
}
// The cube subdivided until it has about `darts` darts (48 * 4^k).
Case split_case(double darts) {
  Case c{make_cube(), std::make_unique<SchemeEngine>(library_rule("quad_subdivision")), {0}};
  while (static_cast<double>(c.object.size()) * 4 <= darts * 1.3)
    scheme::apply(*c.engine, c.object, {0});
  return c;
}
// A stack of k cubes (48 darts each); the hook is a dart of the middle shared face.
Case merge_case(double darts) {
  const int k = std::max(2, static_cast<int>(std::round(darts / 48)));
  std::vector<Voxel> voxels;
  for (int z = 0; z < k; ++z) voxels.push_back({0, 0, z});
  Case c{make_polycube(voxels), std::make_unique<SchemeEngine>(jerboa_rule("MergeHFaces")), {}};
  // The shared faces, in dart order: take the middle one.
  std::vector<Dart> shared;
  for (Dart d : c.object.darts())
    if (!c.object.is_free(3, d) && d < c.object.alpha(3, d)) shared.push_back(d);
  c.hooks = {shared[shared.size() / 2]};
  Map probe = c.object;
  if (!scheme::apply(*c.engine, probe, c.hooks))
    throw std::runtime_error("MergeHFaces does not apply to the stack");
  return c;
}

using Factory = Case (*)(double);

// The cases are built once per (scenario, size).
Case& cached(const std::string& scenario, Factory f, double darts) {
  static std::map<std::pair<std::string, double>, Case> cache;
  auto key = std::make_pair(scenario, darts);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, f(darts)).first;
  return it->second;
}

enum class Method { Apply, Static, Dynamic };

// The thread's CPU time: the machine the numbers come from is shared, and wall time would count the
// time the thread waits for a core.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void run(benchmark::State& state, const std::string& scenario, Factory f, double darts,
         const OrbitType& o, Method m) {
  Case& c = cached(scenario, f, darts);
  // The warm-up object: the same scenario at its smallest size.
  Case& w = cached(scenario, f, 1e3);
  const StaticEvents st = analyse(c.engine->scheme(), {o});
  size_t events = 0, traversed = 0;
  // A fresh copy, prepared as a map that lives in a modeler (room for new darts, a marker already
  // allocated), so that neither method pays for growing the arrays.
  auto fresh = [](const Map& object) {
    Map g = object;
    g.reserve(g.capacity() + 4096);
    ScopedMarker(g).set_clean();
    return g;
  };
  auto step = [&](const Case& k, Map& g) {
    switch (m) {
      case Method::Apply: {
        const auto app = scheme::apply(*k.engine, g, k.hooks);
        benchmark::DoNotOptimize(app.applied);
        break;
      }
      case Method::Static: {
        EventRecorder recorder(k.engine->scheme(), st);
        scheme::apply(*k.engine, g, k.hooks, &recorder);
        const EventLog& log = recorder.logs().back();
        events = log.orbits[0].events.size();
        traversed = log.orbits[0].traversed;
        break;
      }
      case Method::Dynamic: {
        const OrbitSnapshot before = snapshot(g, o);
        const auto app = scheme::apply(*k.engine, g, k.hooks);
        events = dynamic_events(before, g, &app.match).size();
        break;
      }
    }
  };
  for (auto _ : state) {
    // Not timed: the copy, then the same method once on a copy of the small object. Copying a large
    // object evicts the code and the rule's data from the caches, which a modeler applying one
    // operation after another does not; the warm-up puts every size in the same state.
    Map g = fresh(c.object);
    Map gw = fresh(w.object);
    step(w, gw);
    const double t0 = cpu_seconds();
    step(c, g);
    state.SetIterationTime(cpu_seconds() - t0);
  }
  state.counters["darts"] = static_cast<double>(c.object.size());
  state.counters["events"] = static_cast<double>(events);
  if (m == Method::Static) state.counters["traversed"] = static_cast<double>(traversed);
}

void register_scenario(const std::string& scenario, Factory f, int n,
                       const std::vector<double>& sizes) {
  const char* methods[] = {"apply", "static", "dynamic"};
  for (double size : sizes) {
    const double darts = size * (size > 1e4 ? scale() : 1.0);
    for (const OrbitType& o : all_orbit_types(n))
      for (int k = 0; k < 3; ++k) {
        const std::string name = scenario + "/" + std::to_string(static_cast<long>(size)) + "/" +
                                 o.str() + "/" + methods[k];
        const Method m = static_cast<Method>(k);
        benchmark::RegisterBenchmark(
            name.c_str(), [=](benchmark::State& st) { run(st, scenario, f, darts, o, m); })
            ->UseManualTime()
            // The minimum over the repetitions: the cost without interference from the other
            // processes of the machine (events.sh reports it next to the median).
            ->ComputeStatistics(
                "min",
                [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); })
            // Few iterations per repetition on large objects, many repetitions (events.sh takes the
            // medians): an iteration disturbed by the machine then spoils one sample, not a mean.
            ->Iterations(size >= 1e6 || (scenario == "split" && size >= 1e5) ? 1
                         : size >= 1e5                                       ? 3
                                                                             : 20)
            ->Unit(benchmark::kMicrosecond);
      }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<double> sizes = {1e3, 1e4, 1e5, 1e6};
  register_scenario("creation", creation_case, 2, sizes);
  register_scenario("split-local", local_split_case, 2, sizes);
  register_scenario("split", split_case, 2, sizes);
  register_scenario("merge", merge_case, 3, sizes);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
