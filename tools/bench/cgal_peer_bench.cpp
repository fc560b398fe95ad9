// gmr against CGAL::Generalized_map (CGAL 5.5, default storage) on G-maps of at least 10^7 darts,
// built once per process and identically in both libraries (CGAL copy: one CGAL dart per gmr
// dart, same alpha links).
//
// Maps:
//   torus2d   make_torus(1120, 1120): a closed 2-G-map, 10,035,200 darts;
//   box3d     a 60 x 60 x 58 voxel box, identical to make_polycube of the same voxel list (checked
//             at start-up on a small box): a 3-G-map, 10,022,400 darts.
// Benchmarks (each `<map>/<what>/gmr` has a `<map>/<what>/cgal` peer doing the same work):
//   orbits<o>  traverse every <o>-orbit once (marker + per-orbit traversal, counting darts and
//              orbits); gmr: visit_all_orbits, CGAL: a marker + darts_of_orbit<o> per orbit;
//   components every connected component (box3d; torus2d: orbits<0,1,2>): gmr visit_all_orbits
//              over all dimensions, CGAL darts_of_cell<4> (darts_of_orbit<0,1,2,3> does not compile
//              in CGAL 5.5);
//   valid      full validity check; gmr::is_valid vs CGAL is_valid;
//   cells      number of i-cells for every i and of connected components; gmr::count_all_cells +
//              count_components vs CGAL count_all_cells.
// Memory (bytes per dart) is printed after the benchmarks: gmr Map::memory_bytes()/size(), and
// for both libraries the heap growth measured with mallinfo2 around the construction.
//
// GMR_BENCH_SCALE (environment, default 1.0) scales the number of darts (e.g. 0.05 for a quick
// run); the maps are then below 10^7 darts.
#include <benchmark/benchmark.h>
#include <malloc.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "model/core/builders.hpp"
#include "model/core/orbit.hpp"
#include "model/core/validity.hpp"
#include "model/testing/cgal_generalized_map.hpp"
#include "tools/bench/bench_scale.hpp"

using namespace gmr;

using gmr::Dart;
using gmr::Map;

namespace {

using bench::scale;

size_t heap_bytes() {
  const struct mallinfo2 mi = mallinfo2();
  return mi.uordblks + mi.hblkhd;
}

// --- the maps ------------------------------------------------------------------------------

// A box of X*Y*Z voxels, voxel (x,y,z) at index x + X*(y + Y*z), built like make_polycube of that
// voxel list but in O(darts): the cube of one voxel and the 3-link patterns between two voxels
// adjacent along each axis are taken from make_polycube itself.
Map make_box(int X, int Y, int Z) {
  const Map one = gmr::make_polycube({{0, 0, 0}});
  const Dart per = one.capacity();  // 48
  std::vector<std::pair<Dart, Dart>> pattern[3];
  for (int axis = 0; axis < 3; ++axis) {
    gmr::Voxel next{0, 0, 0};
    next[axis] = 1;
    const Map two = gmr::make_polycube({{0, 0, 0}, next});
    for (Dart d = 0; d < per; ++d)
      if (!two.is_free(3, d)) pattern[axis].emplace_back(d, two.alpha(3, d) - per);
  }
  const size_t voxels = size_t(X) * Y * Z;
  Map g(3);
  g.add_darts(voxels * per);
  for (size_t v = 0; v < voxels; ++v) {
    const Dart base = static_cast<Dart>(v * per);
    for (int i = 0; i <= 2; ++i)
      for (Dart d = 0; d < per; ++d) g.set_alpha(i, base + d, base + one.alpha(i, d));
  }
  const size_t stride[3] = {1, size_t(X), size_t(X) * Y};
  for (int z = 0; z < Z; ++z)
    for (int y = 0; y < Y; ++y)
      for (int x = 0; x < X; ++x) {
        const int c[3] = {x, y, z}, lim[3] = {X, Y, Z};
        const size_t v = x + stride[1] * y + stride[2] * z;
        for (int axis = 0; axis < 3; ++axis) {
          if (c[axis] + 1 >= lim[axis]) continue;
          const size_t w = v + stride[axis];
          for (auto [a, b] : pattern[axis])
            g.link(3, static_cast<Dart>(v * per + a), static_cast<Dart>(w * per + b));
        }
      }
  return g;
}

// make_box must give exactly make_polycube's map.
bool check_box_against_polycube() {
  std::vector<gmr::Voxel> vox;
  for (int z = 0; z < 3; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 4; ++x) vox.push_back({x, y, z});
  const Map a = make_box(4, 2, 3), b = gmr::make_polycube(vox);
  if (a.capacity() != b.capacity()) return false;
  for (int i = 0; i <= 3; ++i)
    if (a.links(i) != b.links(i)) return false;
  return true;
}

template <unsigned N>
using CMap = CGAL::Generalized_map<N>;

template <unsigned N>
void to_cgal(const Map& g, CMap<N>& m) {
  std::vector<typename CMap<N>::Dart_handle> h(g.capacity());
  g.for_each_dart([&](Dart d) { h[d] = m.create_dart(); });
  for (unsigned i = 0; i <= N; ++i)
    g.for_each_dart([&](Dart d) {
      const Dart e = g.alpha(static_cast<int>(i), d);
      if (e > d) m.basic_link_alpha(h[d], h[e], i);
    });
}

struct Memory {
  size_t darts = 0;
  size_t gmr_memory_bytes = 0;  // Map::memory_bytes()
  size_t gmr_heap = 0;   // heap growth while building the gmr map (builder temporaries freed)
  size_t cgal_heap = 0;  // heap growth while copying it into CGAL (handle table freed)
  size_t cgal_sizeof_dart = 0;
  int n = 0;
};
std::map<std::string, Memory> g_memory;

template <unsigned N>
struct Fixture {
  Map g{static_cast<int>(N)};
  CMap<N> c;
};

template <unsigned N, class Build>
Fixture<N>& fixture(const std::string& name, Build&& build) {
  static std::unique_ptr<Fixture<N>> f;
  if (!f) {
    Memory mem;
    std::fprintf(stderr, "[bench] building %s ...\n", name.c_str());
    const size_t h0 = heap_bytes();
    f = std::make_unique<Fixture<N>>();
    f->g = build();
    malloc_trim(0);
    const size_t h1 = heap_bytes();
    to_cgal<N>(f->g, f->c);
    malloc_trim(0);
    const size_t h2 = heap_bytes();
    mem.darts = f->g.size();
    mem.gmr_memory_bytes = f->g.memory_bytes();
    mem.gmr_heap = h1 - h0;
    mem.cgal_heap = h2 - h1;
    mem.cgal_sizeof_dart = sizeof(typename CMap<N>::Dart);
    mem.n = static_cast<int>(N);
    // Both must describe the same map before anything is timed.
    const bool gv = gmr::is_valid(f->g), cv = f->c.is_valid();
    auto gc = gmr::count_all_cells(f->g);
    gc.push_back(gmr::count_components(f->g));
    const auto cc = f->c.count_all_cells();
    const bool same = std::vector<size_t>(cc.begin(), cc.end()) == gc;
    std::fprintf(stderr, "[bench] %s: %zu darts, valid gmr=%d cgal=%d, cell counts %s\n",
                 name.c_str(), mem.darts, gv, cv, same ? "agree" : "DISAGREE");
    if (!gv || !cv || !same) std::abort();
    g_memory[name] = mem;
  }
  return *f;
}

Fixture<2>& torus() {
  const auto side = static_cast<size_t>(std::lround(1120 * std::sqrt(scale())));
  return fixture<2>("torus2d", [&] { return gmr::make_torus(side, side); });
}

Fixture<3>& box() {
  const double s = std::cbrt(scale());
  const int x = std::max(2, int(std::lround(60 * s))), z = std::max(2, int(std::lround(58 * s)));
  return fixture<3>("box3d", [&] { return make_box(x, x, z); });
}

// --- benchmarks ----------------------------------------------------------------------------

// gmr: every <mask>-orbit once (visit_all_orbits: marker + visit_orbit_marked per orbit).
template <unsigned N>
void gmr_orbits(benchmark::State& state, Fixture<N>& f, gmr::DimMask mask) {
  const Map& g = f.g;
  size_t orbits = 0, darts = 0;
  for (auto _ : state) {
    darts = 0;
    orbits = gmr::visit_all_orbits(
        g, mask, [](Dart) {}, [&](Dart) { ++darts; });
    benchmark::DoNotOptimize(darts);
  }
  state.counters["orbits"] = static_cast<double>(orbits);
  if (darts != g.size()) state.SkipWithError("not every dart visited");
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * g.size()));
}

// CGAL: every orbit once, a marker over the darts and `darts_of(m, it)` the range of the orbit of
// an unmarked dart.
template <unsigned N, class DartsOf>
void cgal_marked_orbits(benchmark::State& state, Fixture<N>& f, DartsOf darts_of) {
  const CMap<N>& m = f.c;
  size_t orbits = 0, darts = 0;
  for (auto _ : state) {
    const auto mark = m.get_new_mark();
    orbits = darts = 0;
    for (auto it = m.darts().begin(), end = m.darts().end(); it != end; ++it) {
      if (m.is_marked(it, mark)) continue;
      ++orbits;
      for (auto o = darts_of(m, it).begin(); o.cont(); ++o) {
        m.mark(o, mark);
        ++darts;
      }
    }
    m.free_mark(mark);  // every dart is marked: O(1)
    benchmark::DoNotOptimize(darts);
  }
  state.counters["orbits"] = static_cast<double>(orbits);
  if (darts != m.number_of_darts()) state.SkipWithError("not every dart visited");
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * m.number_of_darts()));
}

// CGAL: every <Alpha...>-orbit once.
template <unsigned N, unsigned... Alpha>
void cgal_orbits(benchmark::State& state, Fixture<N>& f) {
  cgal_marked_orbits(
      state, f, [](const CMap<N>& m, auto it) { return m.template darts_of_orbit<Alpha...>(it); });
}

// CGAL: every I-cell once (darts_of_cell<I>; I = N+1: connected components).
template <unsigned N, unsigned I>
void cgal_cell_orbits(benchmark::State& state, Fixture<N>& f) {
  cgal_marked_orbits(state, f,
                     [](const CMap<N>& m, auto it) { return m.template darts_of_cell<I>(it); });
}

template <unsigned N>
void gmr_valid(benchmark::State& state, Fixture<N>& f) {
  bool ok = true;
  for (auto _ : state) {
    ok = gmr::is_valid(f.g);
    benchmark::DoNotOptimize(ok);
  }
  if (!ok) state.SkipWithError("invalid");
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * f.g.size()));
}

template <unsigned N>
void cgal_valid(benchmark::State& state, Fixture<N>& f) {
  bool ok = true;
  for (auto _ : state) {
    ok = f.c.is_valid();
    benchmark::DoNotOptimize(ok);
  }
  if (!ok) state.SkipWithError("invalid");
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * f.c.number_of_darts()));
}

template <unsigned N>
void gmr_cells(benchmark::State& state, Fixture<N>& f) {
  std::vector<size_t> c;
  for (auto _ : state) {
    c = gmr::count_all_cells(f.g);
    c.push_back(gmr::count_components(f.g));
    benchmark::DoNotOptimize(c.data());
  }
  for (size_t i = 0; i < c.size(); ++i)
    state.counters["c" + std::to_string(i)] = static_cast<double>(c[i]);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * f.g.size()));
}

template <unsigned N>
void cgal_cells(benchmark::State& state, Fixture<N>& f) {
  std::vector<unsigned> c;
  for (auto _ : state) {
    c = f.c.count_all_cells();
    benchmark::DoNotOptimize(c.data());
  }
  for (size_t i = 0; i < c.size(); ++i)
    state.counters["c" + std::to_string(i)] = static_cast<double>(c[i]);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * f.c.number_of_darts()));
}

gmr::DimMask mask_of(std::initializer_list<int> dims) {
  gmr::DimMask m = 0;
  for (int i : dims) m |= gmr::DimMask(1) << i;
  return m;
}

void register_all() {
  using benchmark::RegisterBenchmark;
  auto reg = [](const std::string& name, auto fn) {
    RegisterBenchmark(name.c_str(), fn)->Unit(benchmark::kMillisecond)->UseRealTime();
  };
  // torus2d
  reg("torus2d/orbits<1,2>/gmr", [](benchmark::State& s) {
    gmr_orbits(s, torus(), mask_of({1, 2}));
  });
  reg("torus2d/orbits<1,2>/cgal", [](benchmark::State& s) { cgal_orbits<2, 1, 2>(s, torus()); });
  reg("torus2d/orbits<0,2>/gmr", [](benchmark::State& s) {
    gmr_orbits(s, torus(), mask_of({0, 2}));
  });
  reg("torus2d/orbits<0,2>/cgal", [](benchmark::State& s) { cgal_orbits<2, 0, 2>(s, torus()); });
  reg("torus2d/orbits<0,1>/gmr", [](benchmark::State& s) {
    gmr_orbits(s, torus(), mask_of({0, 1}));
  });
  reg("torus2d/orbits<0,1>/cgal", [](benchmark::State& s) { cgal_orbits<2, 0, 1>(s, torus()); });
  reg("torus2d/orbits<0,1,2>/gmr", [](benchmark::State& s) {
    gmr_orbits(s, torus(), mask_of({0, 1, 2}));
  });
  reg("torus2d/orbits<0,1,2>/cgal",
      [](benchmark::State& s) { cgal_orbits<2, 0, 1, 2>(s, torus()); });
  reg("torus2d/valid/gmr", [](benchmark::State& s) { gmr_valid(s, torus()); });
  reg("torus2d/valid/cgal", [](benchmark::State& s) { cgal_valid(s, torus()); });
  reg("torus2d/cells/gmr", [](benchmark::State& s) { gmr_cells(s, torus()); });
  reg("torus2d/cells/cgal", [](benchmark::State& s) { cgal_cells(s, torus()); });
  // box3d
  reg("box3d/orbits<1,2,3>/gmr", [](benchmark::State& s) {
    gmr_orbits(s, box(), mask_of({1, 2, 3}));
  });
  reg("box3d/orbits<1,2,3>/cgal", [](benchmark::State& s) { cgal_orbits<3, 1, 2, 3>(s, box()); });
  reg("box3d/orbits<0,2,3>/gmr", [](benchmark::State& s) {
    gmr_orbits(s, box(), mask_of({0, 2, 3}));
  });
  reg("box3d/orbits<0,2,3>/cgal", [](benchmark::State& s) { cgal_orbits<3, 0, 2, 3>(s, box()); });
  reg("box3d/orbits<0,1,3>/gmr", [](benchmark::State& s) {
    gmr_orbits(s, box(), mask_of({0, 1, 3}));
  });
  reg("box3d/orbits<0,1,3>/cgal", [](benchmark::State& s) { cgal_orbits<3, 0, 1, 3>(s, box()); });
  reg("box3d/orbits<0,1,2>/gmr", [](benchmark::State& s) {
    gmr_orbits(s, box(), mask_of({0, 1, 2}));
  });
  reg("box3d/orbits<0,1,2>/cgal", [](benchmark::State& s) { cgal_orbits<3, 0, 1, 2>(s, box()); });
  // CGAL 5.5 cannot compile darts_of_orbit with 4 alphas (GMap_extend_iterator<..., Tag_true>
  // calls alpha(amap, Ai)); the connected component is its (dimension+1)-cell.
  reg("box3d/components/gmr", [](benchmark::State& s) {
    gmr_orbits(s, box(), mask_of({0, 1, 2, 3}));
  });
  reg("box3d/components/cgal", [](benchmark::State& s) { cgal_cell_orbits<3, 4>(s, box()); });
  reg("box3d/orbits<1,2>/gmr", [](benchmark::State& s) { gmr_orbits(s, box(), mask_of({1, 2})); });
  reg("box3d/orbits<1,2>/cgal", [](benchmark::State& s) { cgal_orbits<3, 1, 2>(s, box()); });
  reg("box3d/valid/gmr", [](benchmark::State& s) { gmr_valid(s, box()); });
  reg("box3d/valid/cgal", [](benchmark::State& s) { cgal_valid(s, box()); });
  reg("box3d/cells/gmr", [](benchmark::State& s) { gmr_cells(s, box()); });
  reg("box3d/cells/cgal", [](benchmark::State& s) { cgal_cells(s, box()); });
}

void print_memory() {
  if (g_memory.empty()) return;
  std::printf("\nmemory (bytes per dart)\n");
  std::printf("%-10s %12s %10s %16s %16s %12s %12s\n", "map", "darts", "target", "gmr memory_bytes",
              "gmr heap growth", "cgal heap", "cgal sizeof");
  for (const auto& [name, m] : g_memory) {
    const double d = static_cast<double>(m.darts);
    std::printf("%-10s %12zu %10d %16.2f %16.2f %12.2f %12zu\n", name.c_str(), m.darts,
                4 * (m.n + 1) + 8, static_cast<double>(m.gmr_memory_bytes) / d,
                static_cast<double>(m.gmr_heap) / d, static_cast<double>(m.cgal_heap) / d,
                m.cgal_sizeof_dart);
  }
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  if (!check_box_against_polycube()) {
    std::fprintf(stderr, "make_box differs from make_polycube\n");
    return 1;
  }
  register_all();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  print_memory();
  return 0;
}
