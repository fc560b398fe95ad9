// The rule-scheme engine (model/scheme_engine.hpp) against hand-written CGAL code (CGAL 5.5
// Generalized_map<2>), in the same process, on the same operation: quad subdivision
// (tools/data/rules/quad_subdivision.json, Catmull–Clark topology) of every face of a closed
// torus, make_torus(250, 250): 500,000 darts before, 2,000,000 after (>= 10^6 required).
//
//   quadsub/gmr   one application of the scheme at dart 0 (orbit <0,1,2> = the whole torus) with a
//                 SchemeEngine prepared once;
//   quadsub/cgal  the same subdivision written by hand for CGAL: per original dart d, three new
//                 darts n1, n2, n3 (create_dart), then basic_link_alpha exactly as the scheme's R
//                 (n0 –0– n1 –1– n2 –0– n3; n1 –2– n1', n2 –2– n2'', n3 –2– n3'' and n3 –1– n3'''
//                 with ' = alpha2(d), '' = alpha0(d), ''' = alpha1(d)); the original darts keep
//                 alpha1 and alpha2. Neighbour indices are kept in the darts' info (Dart_info).
// Each iteration starts from a fresh copy of the torus (copy not timed). The counter
// darts_per_second is the number of darts created per second (3 per original dart).
// At start-up both results are checked: valid, equal cell counts (vertices, edges, faces,
// components), and on a small torus the CGAL result converted back is isomorphic to gmr's.
//
// GMR_BENCH_SCALE (environment, default 1.0) scales the number of darts.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "model/core/builders.hpp"
#include "model/core/orbit.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/rule_io/scheme_json.hpp"
#include "model/scheme/scheme_engine.hpp"
#include "model/testing/cgal_generalized_map.hpp"
#include "tools/bench/bench_scale.hpp"

using namespace gmr;

using gmr::Dart;
using gmr::Map;

namespace {

using bench::scale;

struct Items {
  template <class Refs>
  struct Dart_wrapper {
    typedef std::uint32_t Dart_info;
  };
};
using CMap = CGAL::Generalized_map<2, Items>;
using DH = CMap::Dart_handle;

void to_cgal(const Map& g, CMap& m) {
  std::vector<DH> h(g.capacity());
  g.for_each_dart([&](Dart d) { h[d] = m.create_dart(); });
  for (unsigned i = 0; i <= 2; ++i)
    g.for_each_dart([&](Dart d) {
      const Dart e = g.alpha(static_cast<int>(i), d);
      if (e > d) m.basic_link_alpha(h[d], h[e], i);
    });
}

Map from_cgal(CMap& m) {
  Map g(2);
  g.add_darts(m.number_of_darts());
  std::uint32_t k = 0;
  for (auto it = m.darts().begin(); it != m.darts().end(); ++it) m.info(it) = k++;
  for (auto it = m.darts().begin(); it != m.darts().end(); ++it)
    for (unsigned i = 0; i <= 2; ++i)
      g.set_alpha(static_cast<int>(i), m.info(it), m.info(m.alpha(it, i)));
  return g;
}

// The hand-written CGAL quad subdivision of every face of a closed 2-G-map.
size_t cgal_quad_subdivision(CMap& m) {
  std::vector<DH> n0;
  n0.reserve(m.number_of_darts());
  for (auto it = m.darts().begin(), end = m.darts().end(); it != end; ++it) {
    m.info(it) = static_cast<std::uint32_t>(n0.size());
    n0.push_back(it);
  }
  const size_t s = n0.size();
  std::vector<DH> n1(s), n2(s), n3(s);
  for (size_t k = 0; k < s; ++k) {
    n1[k] = m.create_dart();
    n2[k] = m.create_dart();
    n3[k] = m.create_dart();
  }
  for (size_t k = 0; k < s; ++k) {
    const DH d = n0[k];
    const std::uint32_t a0 = m.info(m.alpha(d, 0)), a1 = m.info(m.alpha(d, 1)),
                        a2 = m.info(m.alpha(d, 2));
    // links inside the quad corner of d
    m.basic_link_alpha(n1[k], n2[k], 1);
    m.basic_link_alpha(n2[k], n3[k], 0);
    // across the old edge (alpha2 of d) and along it (alpha0 of d): each pair once
    if (a2 >= k) m.basic_link_alpha(n1[k], n1[a2], 2);
    if (a0 >= k) {
      m.basic_link_alpha(n2[k], n2[a0], 2);
      m.basic_link_alpha(n3[k], n3[a0], 2);
    }
    if (a1 >= k) m.basic_link_alpha(n3[k], n3[a1], 1);
  }
  // the old darts' alpha0 goes to their edge-midpoint dart (alpha0 was read above)
  for (size_t k = 0; k < s; ++k) m.basic_link_alpha(n0[k], n1[k], 0);
  return 3 * s;
}

struct Fixture {
  Map torus{2};
  CMap ctorus;
  std::unique_ptr<gmr::scheme::SchemeEngine> engine;
};

bool same_cells(const Map& g, CMap& c) {
  auto gc = gmr::count_all_cells(g);
  gc.push_back(gmr::count_components(g));
  const auto cc = c.count_all_cells();
  return std::vector<size_t>(cc.begin(), cc.end()) == gc;
}

Fixture& fixture() {
  static std::unique_ptr<Fixture> f;
  if (f) return *f;
  f = std::make_unique<Fixture>();
  f->engine = std::make_unique<gmr::scheme::SchemeEngine>(
      gmr::io::read_scheme_file(GMR_RULES_DIR "/quad_subdivision.json"));
  // Correctness on a small torus: the CGAL result is isomorphic to the engine's.
  {
    Map g = gmr::make_torus(5, 7);
    CMap c;
    to_cgal(g, c);
    if (!scheme::apply(*f->engine, g, {0}).applied) std::abort();
    cgal_quad_subdivision(c);
    const bool iso = gmr::is_isomorphic(g, from_cgal(c));
    std::fprintf(stderr, "[bench] quadsub on torus 5x7: gmr and CGAL results %s\n",
                 iso ? "isomorphic" : "DIFFER");
    if (!iso || !c.is_valid()) std::abort();
  }
  const auto side = static_cast<size_t>(std::lround(250 * std::sqrt(scale())));
  f->torus = gmr::make_torus(side, side);
  to_cgal(f->torus, f->ctorus);
  Map g = f->torus;
  CMap c(f->ctorus);
  if (!scheme::apply(*f->engine, g, {0}).applied) std::abort();
  cgal_quad_subdivision(c);
  const bool gv = gmr::is_valid(g), cv = c.is_valid(), same = same_cells(g, c);
  std::fprintf(stderr,
               "[bench] quadsub on torus %zux%zu: %zu -> %zu darts (CGAL %zu), valid gmr=%d "
               "cgal=%d, cell counts %s\n",
               side, side, f->torus.size(), g.size(), c.number_of_darts(), gv, cv,
               same ? "agree" : "DISAGREE");
  if (!gv || !cv || !same || g.size() != c.number_of_darts()) std::abort();
  return *f;
}

void quadsub_gmr(benchmark::State& state) {
  Fixture& f = fixture();
  size_t added = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Map g = f.torus;
    state.ResumeTiming();
    const gmr::scheme::SchemeApplication a = scheme::apply(*f.engine, g, {0});
    benchmark::DoNotOptimize(a.darts_added);
    added += a.darts_added;
    state.PauseTiming();
    { Map dead = std::move(g); }  // freeing is not timed
    state.ResumeTiming();
  }
  state.counters["darts_per_second"] =
      benchmark::Counter(static_cast<double>(added), benchmark::Counter::kIsRate);
  state.counters["darts_after"] = static_cast<double>(f.torus.size() * 4);
}

void quadsub_cgal(benchmark::State& state) {
  Fixture& f = fixture();
  size_t added = 0;
  for (auto _ : state) {
    state.PauseTiming();
    auto c = std::make_unique<CMap>(f.ctorus);
    state.ResumeTiming();
    added += cgal_quad_subdivision(*c);
    benchmark::DoNotOptimize(c->number_of_darts());
    state.PauseTiming();
    c.reset();
    state.ResumeTiming();
  }
  state.counters["darts_per_second"] =
      benchmark::Counter(static_cast<double>(added), benchmark::Counter::kIsRate);
  state.counters["darts_after"] = static_cast<double>(f.torus.size() * 4);
}

}  // namespace

BENCHMARK(quadsub_gmr)->Name("torus2d/quadsub/gmr")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(quadsub_cgal)->Name("torus2d/quadsub/cgal")->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
