# Sourced by the benchmark scripts of tools/bench: the checkout root, the build directory of the
# benchmarks (GMR_BENCH_BUILD, default build-bench), the parallel jobs, and bench_build.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${GMR_BENCH_BUILD:-$root/build-bench}
jobs=$(nproc 2>/dev/null || echo 2)

# bench_build TARGET...: configures the benchmark build (-DGMR_BENCH=ON, Release, no tests) and
# builds the targets.
bench_build() {
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DGMR_BENCH=ON -DGMR_TESTS=OFF >/dev/null
  cmake --build "$build" --target "$@" -j"$jobs"
}
