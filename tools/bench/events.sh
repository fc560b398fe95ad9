#!/usr/bin/env bash
# Event detection benchmark (tools/bench/events_bench.cpp): builds it (-DGMR_BENCH=ON, Release) and
# prints, per scenario, size and orbit type, the median times of the application alone, of the
# application with the static events confirmed (static) and with the dynamic detector (dynamic),
# and the ratios dynamic/static (whole step) and (dynamic - apply)/(static - apply) (detection
# only; empty when static - apply is below the timer's noise, 0.5 us).
#
#   tools/bench/events.sh                                   # everything (a few minutes)
#   tools/bench/events.sh --benchmark_filter='creation/'    # extra arguments go to Google Benchmark
#   GMR_BENCH_BUILD=/tmp/b tools/bench/events.sh            # build directory (default: build-bench)
#   GMR_BENCH_REPS=5 tools/bench/events.sh                  # repetitions, medians (default 3)
#   GMR_BENCH_REBUILD=0 GMR_BENCH_BUILD=build tools/bench/events.sh  # use an existing build as is
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${GMR_BENCH_BUILD:-$root/build-bench}
reps=${GMR_BENCH_REPS:-3}
jobs=$(nproc 2>/dev/null || echo 2)

if [[ "${GMR_BENCH_REBUILD:-1}" == 1 || ! -x "$build/tools/bench/gmr_bench_events" ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DGMR_BENCH=ON -DGMR_TESTS=OFF >/dev/null
  cmake --build "$build" --target gmr_bench_events -j"$jobs"
fi
out="$build/bench-results-events.json"
"$build/tools/bench/gmr_bench_events" --benchmark_repetitions="$reps" \
  --benchmark_report_aggregates_only=true --benchmark_out="$out" --benchmark_out_format=json "$@" >/dev/null

python3 - "$out" <<'PY'
import json, sys
runs = {}
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
        continue
    name = b.get("run_name", b["name"]).split("/iterations")[0]
    scen, size, orbit, method = name.split("/")
    unit = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[b.get("time_unit", "us")]
    runs.setdefault((scen, int(size), orbit), {})[method] = b["real_time"] * unit
    runs[(scen, int(size), orbit)]["darts"] = b.get("darts", 0)
print(f"{'scenario':12} {'size':>8} {'darts':>8} {'orbit':10} {'apply us':>10} {'static us':>10} {'dynamic us':>11} {'dyn/stat':>9} {'detection':>10}")
for (scen, size, orbit), r in runs.items():
    if not all(k in r for k in ("apply", "static", "dynamic")):
        continue
    a, s, d = r["apply"], r["static"], r["dynamic"]
    det = f"{(d - a) / (s - a):10.0f}" if s - a > 0.5 else f"{'':>10}"
    print(f"{scen:12} {size:>8} {int(r['darts']):>8} {orbit:10} {a:10.1f} {s:10.1f} {d:11.1f} {d / s:9.0f} {det}")
PY
