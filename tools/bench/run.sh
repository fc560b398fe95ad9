#!/usr/bin/env bash
# Builds the benchmarks (-DGMR_BENCH=ON, Release) in a build directory of their own, runs gmr
# against CGAL on G-maps of >= 10^7 darts (tools/bench/cgal_peer_bench.cpp), and prints a table of
# gmr/CGAL time ratios (< 1: gmr faster) and the bytes per dart of both. Then the rule-scheme engine
# against hand-written CGAL code (tools/bench/scheme_bench.cpp: quad subdivision of a torus, 2*10^6
# darts after), with the darts created per second of both. Then subdivision with positions
# (tools/bench/subdivision_bench.cpp: Catmull-Clark and Loop, 3 iterations, on CGAL's elephant)
# against CGAL::Subdivision_method_3.
#
#   tools/bench/run.sh                                  # everything (~2-3 min, ~1.5 GB RAM)
#   tools/bench/run.sh --benchmark_filter='torus2d/'    # extra arguments go to Google Benchmark
#   GMR_BENCH_SCALE=0.05 tools/bench/run.sh             # small maps, quick check
#   GMR_BENCH_BUILD=/tmp/b tools/bench/run.sh           # build directory (default: build-bench)
#   GMR_BENCH_REPS=5 tools/bench/run.sh                 # repetitions, medians reported (default 3)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
reps=${GMR_BENCH_REPS:-3}

bench_build gmr_bench_cgal gmr_bench_scheme gmr_bench_subdivision

out="$build/bench-results.json"
mem="$build/bench-memory.txt"
"$build/tools/bench/gmr_bench_cgal" --benchmark_repetitions="$reps" \
  --benchmark_report_aggregates_only=true --benchmark_out="$out" --benchmark_out_format=json "$@" \
  | tee "$mem"
out2="$build/bench-results-scheme.json"
"$build/tools/bench/gmr_bench_scheme" --benchmark_repetitions="$reps" \
  --benchmark_report_aggregates_only=true --benchmark_out="$out2" --benchmark_out_format=json "$@" \
  || rm -f "$out2"  # e.g. a --benchmark_filter that matches none of its benchmarks
out3="$build/bench-results-subdivision.json"
(cd "$build" && "$build/tools/bench/gmr_bench_subdivision" --benchmark_repetitions="$reps" \
  --benchmark_report_aggregates_only=true --benchmark_out="$out3" --benchmark_out_format=json "$@") \
  || rm -f "$out3"

python3 - "$out" "$out2" "$out3" <<'PY'
import json, os, sys
benchmarks = []
for path in sys.argv[1:]:
    if os.path.exists(path):
        benchmarks += json.load(open(path))["benchmarks"]
runs = {}
rates = {}
paired = {}
for b in benchmarks:
    name = b.get("run_name", b["name"])
    if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
        continue
    name = name.replace("/real_time", "")
    runs[name] = (b["real_time"], b["cpu_time"], b.get("time_unit", "ms"))
    if "darts_per_second" in b:
        rates[name] = b["darts_per_second"]
    if "ratio_median" in b:
        paired[name.split("/min_time")[0]] = b
rows = []
for name, (rt, ct, unit) in runs.items():
    if not name.endswith("/gmr"):
        continue
    peer = name[: -len("/gmr")] + "/cgal"
    if peer not in runs:
        continue
    prt, pct, _ = runs[peer]
    rows.append((name[: -len("/gmr")], rt, prt, rt / prt, ct / pct, unit))
print()
print("gmr vs CGAL (medians; ratio = gmr / CGAL, < 1 means gmr is faster)")
print(f"{'benchmark':28} {'gmr':>10} {'CGAL':>10} {'real ratio':>11} {'cpu ratio':>10}")
for what, rt, prt, rr, cr, unit in rows:
    print(f"{what:28} {rt:8.1f}{unit:>2} {prt:8.1f}{unit:>2} {rr:11.2f} {cr:10.2f}")
slower = [r[0] for r in rows if r[3] > 1.0]
print("gmr slower than CGAL on: " + (", ".join(slower) if slower else "none"))
if rates:
    print()
    print("darts created per second (medians; rule-scheme engine vs hand-written CGAL; gmr/CGAL > 1 means gmr is faster)")
    print(f"{'benchmark':28} {'gmr':>12} {'CGAL':>12} {'gmr/CGAL':>10}")
    for name, r in rates.items():
        if not name.endswith("/gmr") or name[:-4] + "/cgal" not in rates:
            continue
        what = name[:-4]
        pr = rates[what + "/cgal"]
        print(f"{what:28} {r/1e6:9.1f}M/s {pr/1e6:9.1f}M/s {r/pr:10.2f}")
if paired:
    print()
    print("gmr and CGAL in pairs (each pair: both on fresh copies, in turn first; median of the pairs' ratios)")
    print(f"{'benchmark':28} {'gmr':>10} {'CGAL':>10} {'ratio':>7} {'pairs':>6}")
    for name, b in paired.items():
        print(f"{name:28} {b['gmr_ms_median']:8.1f}ms {b['cgal_ms_median']:8.1f}ms {b['ratio_median']:7.3f} {int(b['pairs']):6d}")
PY
