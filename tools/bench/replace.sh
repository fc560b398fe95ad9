#!/usr/bin/env bash
# Hexahedral subdivision by query-replace against the direct subdivision (tools/bench/replace_bench.cpp,
# Damiand & Nivoliers 2022 §7.1, Table 1): builds the benchmark (-DGMR_BENCH=ON, Release), runs the
# HexSubdivision benchmarks under three allocator settings and prints, per block size, the CPU
# medians and the overhead (qr - direct) / direct, for query-replace with and without the
# validity check of its input (AssumeValid). Both methods write tens of megabytes of fresh
# arrays; where the first touch of a page is expensive (a virtual machine), the page faults are
# most of both times, and how many there are depends on whether freed memory is reused:
#   cold:    arrays above 128 KiB are mapped fresh and unmapped when freed (every run touches
#            new pages, as a fresh process does);
#   warm:    freed memory is kept and reused (after the first iteration no page is new);
#   default: glibc's adaptive thresholds (depends on the history of the process).
# The machine load is printed before and after.
#
#   tools/bench/replace.sh                          # 7 repetitions, medians
#   GMR_BENCH_REPS=3 tools/bench/replace.sh
#   GMR_BENCH_REBUILD=0 tools/bench/replace.sh      # use build-bench as is
#   GMR_BENCH_BUILD=/tmp/b tools/bench/replace.sh   # build directory (default: build-bench)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${GMR_BENCH_BUILD:-$root/build-bench}
reps=${GMR_BENCH_REPS:-7}
jobs=$(nproc 2>/dev/null || echo 2)
if [[ "${GMR_BENCH_REBUILD:-1}" == 1 || ! -x "$build/tools/bench/gmr_bench_replace" ]]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DGMR_BENCH=ON -DGMR_TESTS=OFF >/dev/null
  cmake --build "$build" --target gmr_bench_replace -j"$jobs"
fi
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
declare -A tunables=(
  [cold]="glibc.malloc.mmap_threshold=131072"
  [warm]="glibc.malloc.mmap_threshold=4294967295:glibc.malloc.trim_threshold=4294967295"
  [default]=""
)
for regime in cold warm default; do
  GLIBC_TUNABLES=${tunables[$regime]} "$build/tools/bench/gmr_bench_replace" --benchmark_filter=HexSubdivision \
    --benchmark_repetitions="$reps" --benchmark_report_aggregates_only=true \
    --benchmark_out="$data/$regime.json" --benchmark_out_format=json >/dev/null 2>&1
done
echo "load after:  $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$data" <<'PY'
import json, sys, re
print(f"{'memory':8} {'side':>4} {'volumes':>8} {'direct ms':>10} {'qr ms':>8} {'overhead':>9} "
      f"{'qr assume-valid ms':>19} {'overhead':>9} {'qr unreserved ms':>17}")
for regime in ("cold", "warm", "default"):
    runs = json.load(open(f"{sys.argv[1]}/{regime}.json"))["benchmarks"]
    med = {}
    for b in runs:
        if b.get("aggregate_name") != "median":
            continue
        name, side = re.match(r"BM_HexSubdivision(\w+)/(\d+)", b["run_name"]).groups()
        med[(name, int(side))] = (b["cpu_time"], b.get("volumes", 0))
    for side in sorted({s for _, s in med}):
        d, vol = med[("Direct", side)]
        q, _ = med[("QueryReplace", side)]
        u = med.get(("QueryReplaceUnreserved", side))
        a = med.get(("QueryReplaceAssumeValid", side))
        print(f"{regime:8} {side:>4} {int(vol):>8} {d:>10.1f} {q:>8.1f} {100 * (q - d) / d:>8.0f}% "
              f"{'' if a is None else f'{a[0]:.1f}':>19} {'' if a is None else f'{100 * (a[0] - d) / d:.0f}%':>9} "
              f"{'' if u is None else f'{u[0]:.1f}':>17}")
PY
