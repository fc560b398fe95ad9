// Subdivision with positions: gmr's rule schemes with expressions (tools/data/rules, applied at
// every dart, model/expr/propagation.hpp) against CGAL::Subdivision_method_3 on a Surface_mesh, in
// the same process, 3 iterations of Catmull-Clark and of Loop on a CGAL data mesh (default:
// elephant, 33,348 darts -> 2,134,272 after 3 iterations; GMR_BENCH_MESH names another mesh of
// CGAL's data.tar.gz, e.g. bunny00). The mesh is unpacked from Debian's libcgal-demo archive into
// the working directory. Each iteration starts from a copy of the loaded mesh (copy not timed).
// The schemes rewrite whole components, so apply_everywhere takes its whole-component path
// (model/scheme/component_rewrite.hpp; tested equal to one engine application per dart). Both
// libraries reuse memory across iterations the way they normally do: CGAL through malloc's free
// chunks, gmr through the thread's buffer pool (model/core/buffer_pool.hpp); nothing is tuned.
// Counters: darts_per_second (darts of the result per second of subdivision: gmr's darts; for
// CGAL the same number, the results being isomorphic — model/expr/tests/subdivision_slow_test.cpp)
// and vertices_per_second (vertices of the result per second). `gmr_topology_only` runs the same
// applications on the map without embeddings (the engine's share of gmr's time); `link_write_floor`
// is the memory traffic any rewrite of these maps pays, as plain sequential loops: per iteration,
// the links before copied into the result's arrays and every added dart's links written once from
// them (3 arrays of the result's darts written, the arrays before read), in storage reused across
// iterations as gmr's buffer pool reuses it. `paired` runs gmr and CGAL one after the other in
// every benchmark iteration and reports the median of the pairs' ratios (the comparison that holds
// on a machine whose speed drifts: run_paired).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/core/embedded_map.hpp"
#include "model/core/orbit.hpp"
#include "model/expr/compiled_scheme.hpp"
#include "model/expr/propagation.hpp"
#include "model/map_io/off.hpp"
#include "model/rule_io/scheme_json.hpp"

namespace {

using Mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
constexpr int kIterations = 3;

std::string mesh_path() {
  const char* m = std::getenv("GMR_BENCH_MESH");
  const std::string name = m ? m : "elephant";
  const char* archive = "/usr/share/doc/libcgal-dev/data.tar.gz";
  const std::filesystem::path off =
      std::filesystem::current_path() / "cgal-data/data/meshes" / (name + ".off");
  if (!std::filesystem::exists(off)) {
    std::filesystem::create_directories(std::filesystem::current_path() / "cgal-data");
    const std::string cmd =
        std::string("tar xzf ") + archive + " -C cgal-data data/meshes/" + name + ".off";
    if (std::system(cmd.c_str()) != 0)
      throw std::runtime_error(
          "CGAL's data meshes are missing: install libcgal-demo (tools/setup.sh)");
  }
  return off.string();
}

struct Fixture {
  gmr::EmbeddedMap map;
  Mesh mesh;
  Fixture() {
    const std::string off = mesh_path();
    map = gmr::io::read_off_file(off);
    std::ifstream in(off);
    if (!CGAL::IO::read_OFF(in, mesh)) throw std::runtime_error("CGAL cannot read " + off);
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

// A scheme with its expressions, read and compiled once.
struct GmrSubdivision {
  gmr::scheme::RuleScheme scheme;
  gmr::scheme::SchemeEngine engine;
  gmr::expr::CompiledScheme compiled;
  explicit GmrSubdivision(const char* rule)
      : scheme(gmr::io::read_scheme_file(std::string(GMR_RULES_DIR) + "/" + rule)),
        engine(scheme),
        compiled(gmr::expr::compile_scheme(scheme)) {}
  // kIterations applications at every dart with positions; false on an embedding issue.
  bool run(gmr::EmbeddedMap& m) const {
    for (int k = 0; k < kIterations; ++k) {
      gmr::expr::EmbeddingPropagation p(compiled, m);
      gmr::scheme::apply_everywhere(engine, m.map, {.keep_tables = false, .observer = &p});
      if (p.issue_count() != 0) return false;
    }
    return true;
  }
};

void cgal_catmull_clark(Mesh& m) {
  CGAL::Subdivision_method_3::CatmullClark_subdivision(
      m, CGAL::parameters::number_of_iterations(kIterations));
}
void cgal_loop(Mesh& m) {
  CGAL::Subdivision_method_3::Loop_subdivision(m,
                                               CGAL::parameters::number_of_iterations(kIterations));
}

void run_gmr(benchmark::State& state, const char* rule) {
  const Fixture& f = fixture();
  const GmrSubdivision sub(rule);
  size_t darts = 0, vertices = 0;
  for (auto _ : state) {
    state.PauseTiming();
    gmr::EmbeddedMap m = f.map;
    state.ResumeTiming();
    if (!sub.run(m)) state.SkipWithError("embedding issues");
    state.PauseTiming();
    darts = m.map.size();
    vertices = gmr::count_orbits(m.map, gmr::OrbitType{1, 2});
    state.ResumeTiming();
  }
  state.counters["darts_per_second"] =
      benchmark::Counter(static_cast<double>(darts), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["vertices_per_second"] = benchmark::Counter(
      static_cast<double>(vertices), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["darts_after"] = static_cast<double>(darts);
}

// The same applications without embeddings (the topology alone), to separate the engine's share.
void run_gmr_topology(benchmark::State& state, const char* rule) {
  const Fixture& f = fixture();
  const GmrSubdivision sub(rule);
  const gmr::scheme::SchemeEngine& engine = sub.engine;
  for (auto _ : state) {
    state.PauseTiming();
    gmr::Map g = f.map.map;
    state.ResumeTiming();
    for (int k = 0; k < kIterations; ++k)
      gmr::scheme::apply_everywhere(engine, g, {.keep_tables = false});
    benchmark::DoNotOptimize(g.size());
  }
}

void run_link_floor(benchmark::State& state, const char* rule) {
  const Fixture& f = fixture();
  const GmrSubdivision sub(rule);
  const gmr::scheme::SchemeEngine& engine = sub.engine;
  std::vector<size_t> sizes{
      f.map.map.capacity()};  // darts before each iteration, and after the last
  gmr::Map g = f.map.map;
  for (int k = 0; k < kIterations; ++k) {
    gmr::scheme::apply_everywhere(engine, g, {.keep_tables = false});
    sizes.push_back(g.capacity());
  }
  const int dims = g.dimension() + 1;
  std::vector<std::vector<gmr::Dart>> a(static_cast<size_t>(dims),
                                        std::vector<gmr::Dart>(sizes.back())),
      b = a;  // touched before timing
  for (int i = 0; i < dims; ++i)
    std::copy_n(f.map.map.links(i).begin(), sizes[0], a[static_cast<size_t>(i)].begin());
  for (auto _ : state) {
    for (int k = 0; k < kIterations; ++k) {
      const size_t n = sizes[static_cast<size_t>(k)],
                   blocks = sizes[static_cast<size_t>(k) + 1] / n;
      for (size_t i = 0; i < a.size(); ++i) {
        const gmr::Dart* from = a[i].data();
        gmr::Dart* to = b[i].data();
        for (size_t r = 0; r < blocks; ++r)
          for (size_t x = 0; x < n; ++x) to[r * n + x] = from[x] + static_cast<gmr::Dart>(r * n);
      }
      std::swap(a, b);
    }
    benchmark::DoNotOptimize(a[0].data());
    benchmark::ClobberMemory();
  }
}

template <class Subdivide>
void run_cgal(benchmark::State& state, Subdivide subdivide) {
  const Fixture& f = fixture();
  size_t darts = 0, vertices = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Mesh m = f.mesh;
    state.ResumeTiming();
    subdivide(m);
    benchmark::DoNotOptimize(m.number_of_vertices());
    darts = 4 * m.number_of_edges();  // a closed surface: 4 darts of a 2-G-map per edge
    vertices = m.number_of_vertices();
  }
  state.counters["darts_per_second"] =
      benchmark::Counter(static_cast<double>(darts), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["vertices_per_second"] = benchmark::Counter(
      static_cast<double>(vertices), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["darts_after"] = static_cast<double>(darts);
}

// gmr and CGAL in pairs: each benchmark iteration runs both on fresh copies of the mesh (copies
// not timed), in turn first, and the ratio gmr/CGAL is taken within the pair, so that the
// machine's speed, which drifts over seconds on a shared machine, divides out. Counters: the
// median of the pairs' ratios and each library's median time (ms); the iteration time reported
// is gmr's.
void run_paired(benchmark::State& state, const char* rule, void (*cgal)(Mesh&)) {
  using Clock = std::chrono::steady_clock;
  const Fixture& f = fixture();
  const GmrSubdivision sub(rule);
  std::vector<double> ratios, gmr_ms, cgal_ms;
  for (auto _ : state) {
    gmr::EmbeddedMap m = f.map;
    Mesh mesh = f.mesh;
    double tg = 0, tc = 0;
    for (int turn = 0; turn < 2; ++turn) {
      const bool gmr_turn = (turn == 0) == (ratios.size() % 2 == 0);
      const auto t0 = Clock::now();
      if (gmr_turn && !sub.run(m)) state.SkipWithError("embedding issues");
      if (!gmr_turn) cgal(mesh);
      const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
      (gmr_turn ? tg : tc) = ms;
    }
    benchmark::DoNotOptimize(mesh.number_of_vertices());
    state.SetIterationTime(tg / 1000);
    ratios.push_back(tg / tc);
    gmr_ms.push_back(tg);
    cgal_ms.push_back(tc);
  }
  auto median = [](std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  state.counters["ratio_median"] = median(ratios);
  state.counters["gmr_ms_median"] = median(gmr_ms);
  state.counters["cgal_ms_median"] = median(cgal_ms);
  state.counters["pairs"] = static_cast<double>(ratios.size());
}

void BM_catmull_clark_gmr(benchmark::State& state) { run_gmr(state, "quad_subdivision.json"); }
void BM_catmull_clark_cgal(benchmark::State& state) { run_cgal(state, cgal_catmull_clark); }
void BM_catmull_clark_paired(benchmark::State& state) {
  run_paired(state, "quad_subdivision.json", cgal_catmull_clark);
}
void BM_loop_paired(benchmark::State& state) {
  run_paired(state, "loop_subdivision.json", cgal_loop);
}
void BM_loop_gmr(benchmark::State& state) { run_gmr(state, "loop_subdivision.json"); }
void BM_catmull_clark_topology(benchmark::State& state) {
  run_gmr_topology(state, "quad_subdivision.json");
}
void BM_loop_topology(benchmark::State& state) { run_gmr_topology(state, "loop_subdivision.json"); }
void BM_catmull_clark_floor(benchmark::State& state) {
  run_link_floor(state, "quad_subdivision.json");
}
void BM_loop_floor(benchmark::State& state) { run_link_floor(state, "loop_subdivision.json"); }
void BM_loop_cgal(benchmark::State& state) { run_cgal(state, cgal_loop); }

}  // namespace

BENCHMARK(BM_catmull_clark_gmr)
    ->Name("subdivision_catmull_clark/gmr")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_catmull_clark_cgal)
    ->Name("subdivision_catmull_clark/cgal")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_loop_gmr)->Name("subdivision_loop/gmr")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_loop_cgal)
    ->Name("subdivision_loop/cgal")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_catmull_clark_paired)
    ->Name("subdivision_catmull_clark/paired")
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(4);
BENCHMARK(BM_loop_paired)
    ->Name("subdivision_loop/paired")
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(2);
BENCHMARK(BM_catmull_clark_topology)
    ->Name("subdivision_catmull_clark/gmr_topology_only")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_loop_topology)
    ->Name("subdivision_loop/gmr_topology_only")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_catmull_clark_floor)
    ->Name("subdivision_catmull_clark/link_write_floor")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_loop_floor)
    ->Name("subdivision_loop/link_write_floor")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_MAIN();
