// Query by signature against testing each pattern by isomorphism (Damiand & Nivoliers 2022 §6.3,
// Table 2 "time-qrn"): the 6209 hex-conformal configurations are looked up among the 226
// unoriented class representatives (flagged boundaries), (a) by the pattern store as
// query-replace uses it (PatternStore::match: profile, then one word comparison or the signature
// and the hash table), (b) by computing each configuration's signature and hashing it, (c) by the
// core isomorphism test (Theorem 1, O(n^2) per test) against each representative in turn until
// one fits. All find the class of every configuration (the store's patterns are the
// representatives lifted to 3-G-maps, boundary only).
// Hexahedral subdivision (§7.1, Table 1 "time-qr" against "time-direct"): one level on blocks of
// unit hexahedra with positions, (d) by query-replace (final size reserved, every edge split in 2,
// f-pattern on the faces, v-pattern on the volumes, queries included) and (e) by the direct
// subdivision (direct_hex_subdivision.hpp). The input copy is not timed. Both are dominated by
// the first touch of fresh memory on some machines: tools/bench/replace.sh runs them with the
// allocator returning memory to the kernel (cold) and keeping it (warm).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "model/core/builders.hpp"
#include "model/core/orbit.hpp"
#include "model/core/signature.hpp"
#include "model/core/validity.hpp"
#include "model/replace/configurations.hpp"
#include "model/replace/direct_hex_subdivision.hpp"
#include "model/replace/edge_split.hpp"
#include "model/replace/pattern_folder.hpp"
#include "model/replace/pattern_store.hpp"
#include "model/replace/query_replace.hpp"
#include "model/replace/replace_only.hpp"
#include "model/replace/unit_hex_positions.hpp"

namespace {

using namespace gmr;
using namespace gmr::replace;

struct Data {
  ConfigurationSet set = generate_configurations("hex-conformal");
  std::vector<size_t> reps;  // one configuration per class
  std::unordered_map<Word, size_t, WordHash> table;
  PatternStore store{Mode::Unoriented};
  Data() {
    for (size_t i = 0; i < set.configurations.size(); ++i) {
      const Configuration& c = set.configurations[i];
      const Word key =
          store_key(cell_boundary(c.map.map, 3, c.cell, c.map.flag, {}), 3, Mode::Unoriented);
      if (table.emplace(key, reps.size()).second) reps.push_back(i);
    }
    for (size_t r : reps) {
      const Configuration& c = set.configurations[r];
      FlaggedMap m{lift(c.map.map, 3), c.map.flag, {}};
      store.add(make_pattern("class" + std::to_string(r), std::move(m)));
    }
  }
};
const Data& data() {
  static const Data d;
  return d;
}

void BM_QueryByPatternStore(benchmark::State& state) {
  const Data& d = data();
  for (auto _ : state) {
    size_t found = 0;
    for (const Configuration& c : d.set.configurations)
      found +=
          d.store.match(cell_boundary(c.map.map, 3, c.cell, c.map.flag, {}), 3).hits != nullptr;
    if (found != d.set.configurations.size()) state.SkipWithError("a configuration was not found");
    benchmark::DoNotOptimize(found);
  }
  state.counters["patterns"] = static_cast<double>(d.reps.size());
  // The store's lookup words: one per start dart of each pattern (automorphic starts once).
  state.counters["lookup_words"] = static_cast<double>(d.store.lookup_words());
  state.counters["lookup_MB"] =
      static_cast<double>(d.store.lookup_letters()) * sizeof(uint32_t) / 1e6;
}

void BM_QueryBySignature(benchmark::State& state) {
  const Data& d = data();
  for (auto _ : state) {
    size_t found = 0;
    for (const Configuration& c : d.set.configurations) {
      const Word key =
          store_key(cell_boundary(c.map.map, 3, c.cell, c.map.flag, {}), 3, Mode::Unoriented);
      found += d.table.count(key);
    }
    if (found != d.set.configurations.size()) state.SkipWithError("a configuration was not found");
    benchmark::DoNotOptimize(found);
  }
  state.counters["patterns"] = static_cast<double>(d.reps.size());
}

void BM_QueryByIsomorphismTests(benchmark::State& state) {
  const Data& d = data();
  for (auto _ : state) {
    size_t found = 0;
    for (const Configuration& c : d.set.configurations)
      for (size_t r : d.reps) {
        const Configuration& p = d.set.configurations[r];
        if (is_isomorphic(p.map.map, c.map.map, &p.map.flag, &c.map.flag)) {
          ++found;
          break;
        }
      }
    if (found != d.set.configurations.size()) state.SkipWithError("a configuration was not found");
    benchmark::DoNotOptimize(found);
  }
  state.counters["patterns"] = static_cast<double>(d.reps.size());
}

// A block of side^3 unit hexahedra, every dart flagged, with positions (one per side, kept).
const FlaggedMap& block(int side) {
  static std::map<int, FlaggedMap> blocks;
  auto it = blocks.find(side);
  if (it != blocks.end()) return it->second;
  std::vector<Voxel> voxels;
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y)
      for (int z = 0; z < side; ++z) voxels.push_back({x, y, z});
  FlaggedMap b{make_polycube(voxels), {}, {}};
  b.flag.assign(b.map.capacity(), 1);
  b.position = unit_hex_positions(b.map);
  return blocks.emplace(side, std::move(b)).first->second;
}

const PatternStore& hex_patterns() {
  static const PatternStore s = [] {
    PatternStore store(Mode::Unoriented);
    const char* src = std::getenv("GMR_SOURCE_DIR");
    for (auto& p : load_patterns(std::string(src ? src : GMR_SOURCE_DIR) +
                                 "/tools/data/patterns/hex-subdivision"))
      store.add(std::move(p));
    return store;
  }();
  return s;
}

// The darts of the hexahedral subdivision of m (the sequence's reservation): every edge split in
// 2, then the faces' and the volumes' replacement rooms bounded from the dart count (exact here:
// one pattern per dimension).
size_t subdivision_size(const FlaggedMap& m, const PatternStore& store) {
  return 2 * m.map.size() + replacement_room_bound(2 * m.map.size(), store, {2, 3});
}

size_t pattern_named(const std::string& name) {
  const PatternStore& store = hex_patterns();
  for (size_t i = 0; i < store.patterns().size(); ++i)
    if (store.patterns()[i].name == name) return i;
  throw std::runtime_error("no pattern " + name);
}
size_t split4() { return pattern_named("split4"); }
size_t hex8() { return pattern_named("hex8"); }

// How the sequence below looks cells up and checks its input.
enum class Sequence {
  QueryReplace,             // queries; the input's validity checked once, before the first step
  QueryReplaceAssumeValid,  // queries; no validity check (the caller built the block)
  ReplaceOnly,              // no query: the paper's Table 1, "only the replace part"
};

// Query-replace as an application runs the sequence (refine_adaptively does the same): the
// input checked once when asked (each step keeps the map valid: the replacement tests check it
// after every step, so the steps themselves skip the check), its final size reserved once from the
// patterns (replacement_room), every edge split in 2 at once (split_all_edges), f-pattern on the
// faces, v-pattern on the volumes. ReplaceOnly: split4 on every face and hex8 on every volume
// without a query, each cell numbered along the pattern's word from its smallest dart, a flagged
// corner matched with the pattern's start (replace_only.hpp). Returns the volumes made, 0 if a cell
// matched no pattern.
size_t subdivide_by_patterns(FlaggedMap& m, Sequence sequence) {
  const PatternStore& store = hex_patterns();
  if (sequence == Sequence::QueryReplace) {
    const ValidityReport v = check_validity(m.map, 1);
    if (!v.ok()) throw std::runtime_error("the block is not valid");
  }
  m.reserve(subdivision_size(m, store));
  split_all_edges(m, 2);
  const bool lookup = sequence != Sequence::ReplaceOnly;
  const QueryReplaceReport f =
      lookup ? query_replace(m, store, 2, {}, {}, {}, nullptr, Precondition::AssumeValid)
             : replace_only(m, store, split4(), nullptr, Precondition::AssumeValid);
  const QueryReplaceReport v =
      lookup ? query_replace(m, store, 3, {}, {}, {}, nullptr, Precondition::AssumeValid)
             : replace_only(m, store, hex8(), nullptr, Precondition::AssumeValid);
  if (!f.unmatched.empty() || !v.unmatched.empty()) return 0;
  return v.replaced() * 8;
}

void hex_subdivision_by_patterns(benchmark::State& state, Sequence sequence) {
  const FlaggedMap& input = block(static_cast<int>(state.range(0)));
  size_t volumes = 0;
  for (auto _ : state) {
    state.PauseTiming();
    FlaggedMap m = input;
    state.ResumeTiming();
    volumes = subdivide_by_patterns(m, sequence);
    if (!volumes) state.SkipWithError("a cell was not matched");
  }
  state.counters["volumes"] = static_cast<double>(volumes);
}

// Without the reservation: one split_edge per edge, each step growing the arrays (copying them),
// each step checking its input.
void BM_HexSubdivisionQueryReplaceUnreserved(benchmark::State& state) {
  const PatternStore& store = hex_patterns();
  const FlaggedMap& input = block(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    state.PauseTiming();
    FlaggedMap m = input;
    state.ResumeTiming();
    for (Dart e : orbit_representatives(m.map, cell_type(m.map, 1))) split_edge(m, e, 2);
    const QueryReplaceReport f = query_replace(m, store, 2);
    const QueryReplaceReport v = query_replace(m, store, 3);
    if (!f.unmatched.empty() || !v.unmatched.empty()) state.SkipWithError("a cell was not matched");
  }
}

// One step of the reserved sequence timed alone (range(1): 0 the reservation with its room counts,
// 1 the edge split, 2 the faces, 3 the volumes; range(2): 0 query-replace, 1 replace only;
// AssumeValid): the map before the step is made once, and each iteration copies it and reserves the
// final size untimed.
void BM_HexStep(benchmark::State& state) {
  const PatternStore& store = hex_patterns();
  const int side = static_cast<int>(state.range(0)), step = static_cast<int>(state.range(1));
  const bool lookup = state.range(2) == 0;
  FlaggedMap before = block(side);
  const size_t final_size = subdivision_size(before, store);  // before any step runs
  auto run = [&](FlaggedMap& m, int s) {
    if (s == 0) m.reserve(subdivision_size(m, store));  // as the sequence does
    if (s == 1) split_all_edges(m, 2);
    if (s == 2 && lookup)
      query_replace(m, store, 2, {}, {}, {}, nullptr, Precondition::AssumeValid);
    if (s == 3 && lookup)
      query_replace(m, store, 3, {}, {}, {}, nullptr, Precondition::AssumeValid);
    if (s == 2 && !lookup) replace_only(m, store, split4(), nullptr, Precondition::AssumeValid);
    if (s == 3 && !lookup) replace_only(m, store, hex8(), nullptr, Precondition::AssumeValid);
  };
  for (int s = 0; s < step; ++s) run(before, s);
  for (auto _ : state) {
    state.PauseTiming();
    FlaggedMap m = before;
    if (step > 0) m.reserve(final_size);
    state.ResumeTiming();
    run(m, step);
  }
}

void BM_HexSubdivisionQueryReplace(benchmark::State& state) {
  hex_subdivision_by_patterns(state, Sequence::QueryReplace);
}
void BM_HexSubdivisionQueryReplaceAssumeValid(benchmark::State& state) {
  hex_subdivision_by_patterns(state, Sequence::QueryReplaceAssumeValid);
}
void BM_HexSubdivisionReplaceOnly(benchmark::State& state) {
  hex_subdivision_by_patterns(state, Sequence::ReplaceOnly);
}

void BM_HexSubdivisionDirect(benchmark::State& state) {
  const FlaggedMap& input = block(static_cast<int>(state.range(0)));
  size_t darts = 0;
  for (auto _ : state) {
    FlaggedMap r = subdivide_hexahedra(input);
    darts = r.map.size();
  }
  state.counters["volumes"] = static_cast<double>(darts / 48);
}

double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

// A sequence against the direct subdivision in one process, pair by pair (range(1): 0 query-replace
// with its input checked once, 1 with AssumeValid, 2 replace only): each iteration runs both on
// copies of the block, the one that goes first alternating, each timed alone (thread CPU time;
// the copies and the results' destruction not timed), so that both see the same load and the same
// state of the allocator. Counters: the medians of the two times over the iterations and their
// ratio, the overhead of the target (sequence / direct).
void BM_HexSubdivisionPaired(benchmark::State& state) {
  const FlaggedMap& input = block(static_cast<int>(state.range(0)));
  const Sequence sequence = static_cast<Sequence>(state.range(1));
  std::vector<double> direct, method;
  bool method_first = true;
  for (auto _ : state) {
    for (int turn = 0; turn < 2; ++turn) {
      if ((turn == 0) == method_first) {
        FlaggedMap m = input;
        const double t0 = thread_cpu_ms();
        const size_t volumes = subdivide_by_patterns(m, sequence);
        method.push_back(thread_cpu_ms() - t0);
        if (!volumes) state.SkipWithError("a cell was not matched");
      } else {
        const double t0 = thread_cpu_ms();
        FlaggedMap r = subdivide_hexahedra(input);
        direct.push_back(thread_cpu_ms() - t0);
        benchmark::DoNotOptimize(r.map.size());
      }
    }
    method_first = !method_first;
  }
  state.counters["direct_ms"] = median(direct);
  state.counters["method_ms"] = median(method);
  state.counters["ratio"] = median(method) / median(direct);
}

BENCHMARK(BM_QueryByPatternStore)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_QueryBySignature)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_QueryByIsomorphismTests)->Unit(benchmark::kMillisecond);
// Block sides 8, 12, 16 and 20 (512 to 8,000 hexahedra, subdivided into 4,096 to 64,000); the
// methods alternate per size.
BENCHMARK(BM_HexSubdivisionQueryReplace)->Unit(benchmark::kMillisecond)->Arg(8);
BENCHMARK(BM_HexSubdivisionQueryReplaceAssumeValid)->Unit(benchmark::kMillisecond)->Arg(8);
BENCHMARK(BM_HexSubdivisionReplaceOnly)->Unit(benchmark::kMillisecond)->Arg(8);
BENCHMARK(BM_HexSubdivisionDirect)->Unit(benchmark::kMillisecond)->Arg(8);
BENCHMARK(BM_HexSubdivisionQueryReplace)->Unit(benchmark::kMillisecond)->Arg(12);
BENCHMARK(BM_HexSubdivisionQueryReplaceAssumeValid)->Unit(benchmark::kMillisecond)->Arg(12);
BENCHMARK(BM_HexSubdivisionReplaceOnly)->Unit(benchmark::kMillisecond)->Arg(12);
BENCHMARK(BM_HexSubdivisionDirect)->Unit(benchmark::kMillisecond)->Arg(12);
BENCHMARK(BM_HexSubdivisionQueryReplace)->Unit(benchmark::kMillisecond)->Arg(16);
BENCHMARK(BM_HexSubdivisionQueryReplaceAssumeValid)->Unit(benchmark::kMillisecond)->Arg(16);
BENCHMARK(BM_HexSubdivisionReplaceOnly)->Unit(benchmark::kMillisecond)->Arg(16);
BENCHMARK(BM_HexSubdivisionDirect)->Unit(benchmark::kMillisecond)->Arg(16);
BENCHMARK(BM_HexSubdivisionQueryReplaceUnreserved)->Unit(benchmark::kMillisecond)->Arg(16);
BENCHMARK(BM_HexSubdivisionQueryReplace)->Unit(benchmark::kMillisecond)->Arg(20);
BENCHMARK(BM_HexStep)
    ->Unit(benchmark::kMillisecond)
    ->ArgsProduct({{16}, {0, 1, 2, 3}, {0, 1}})
    ->ComputeStatistics("min", [](const std::vector<double>& v) {
      return *std::min_element(v.begin(), v.end());
    });
BENCHMARK(BM_HexSubdivisionQueryReplaceAssumeValid)->Unit(benchmark::kMillisecond)->Arg(20);
BENCHMARK(BM_HexSubdivisionReplaceOnly)->Unit(benchmark::kMillisecond)->Arg(20);
BENCHMARK(BM_HexSubdivisionDirect)->Unit(benchmark::kMillisecond)->Arg(20);
// Pairs per size: about 3 s of work each.
BENCHMARK(BM_HexSubdivisionPaired)
    ->Unit(benchmark::kMillisecond)
    ->ArgsProduct({{12}, {0, 1, 2}})
    ->Iterations(200);
BENCHMARK(BM_HexSubdivisionPaired)
    ->Unit(benchmark::kMillisecond)
    ->ArgsProduct({{16}, {0, 1, 2}})
    ->Iterations(100);
BENCHMARK(BM_HexSubdivisionPaired)
    ->Unit(benchmark::kMillisecond)
    ->ArgsProduct({{20}, {0, 1, 2}})
    ->Iterations(50);

}  // namespace

BENCHMARK_MAIN();
