#!/usr/bin/env bash
# Hexahedral subdivision by query-replace against the direct subdivision (tools/bench/replace_bench.cpp,
# Damiand & Nivoliers 2022 §7.1, Table 1): builds the benchmark (-DGMR_BENCH=ON, Release), runs the
# HexSubdivision benchmarks and prints, per block size, the CPU medians and the overhead
# (method - direct) / direct of query-replace (with and without the validity check of its input,
# AssumeValid) and of replace only (the paper's Table 1: no query, every cell known to match its
# pattern; replace_only.hpp). Both methods write tens of megabytes of fresh arrays; where the
# first touch of a page is expensive (a virtual machine), the page faults are most of both
# times, and how many there are depends on whether freed memory is reused:
#   fresh:   one process per measurement and one run each (as the paper timed whole program
#            runs), arrays above 128 KiB mapped fresh: every page touched is new;
#   cold:    in one process, repeated runs, arrays above 128 KiB mapped fresh and unmapped when
#            freed (every run touches new pages, except the link arrays the map keeps in its
#            buffer pool, buffer_pool.hpp);
#   warm:    in one process, freed memory kept and reused (after the first run no page is new):
#            the work itself;
#   paired:  in one process, each sequence and the direct subdivision run in pairs, alternating
#            (BM_HexSubdivisionPaired: 200, 100, 50 pairs at sides 12, 16, 20; thread CPU time),
#            with glibc's default allocator and with freed memory kept (as warm); per process the
#            ratio of the medians, sequence / direct; printed per side and variant: the median and
#            the range over the repetitions (one process each).
# The methods alternate per size (in fresh, per repetition). The machine load is printed before
# and after.
#
#   tools/bench/replace.sh                          # 7 repetitions, medians
#   GMR_BENCH_REPS=3 tools/bench/replace.sh
#   GMR_BENCH_REBUILD=0 tools/bench/replace.sh      # use build-bench as is
#   GMR_BENCH_BUILD=/tmp/b tools/bench/replace.sh   # build directory (default: build-bench)
#   GMR_BENCH_REGIMES="warm" tools/bench/replace.sh # a subset of: fresh cold warm paired
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
reps=${GMR_BENCH_REPS:-7}
regimes=${GMR_BENCH_REGIMES:-fresh cold warm paired}
if [[ "${GMR_BENCH_REBUILD:-1}" == 1 || ! -x "$build/tools/bench/gmr_bench_replace" ]]; then
  bench_build gmr_bench_replace
fi
bench=$build/tools/bench/gmr_bench_replace
data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
declare -A tunables=(
  [fresh]="glibc.malloc.mmap_threshold=131072"
  [cold]="glibc.malloc.mmap_threshold=131072"
  [warm]="glibc.malloc.mmap_threshold=4294967295:glibc.malloc.trim_threshold=4294967295"
)
for regime in $regimes; do
  if [[ $regime == fresh ]]; then
    for ((r = 0; r < reps; ++r)); do
      for side in 8 12 16 20; do
        for method in QueryReplace QueryReplaceAssumeValid ReplaceOnly Direct; do
          GLIBC_TUNABLES=${tunables[fresh]} "$bench" --benchmark_filter="^BM_HexSubdivision$method/$side\$" \
            --benchmark_min_time=0 --benchmark_format=json 2>/dev/null >"$data/fresh-$r-$side-$method.json"
        done
      done
    done
  elif [[ $regime == paired ]]; then
    for ((r = 0; r < reps; ++r)); do
      for memory in default warm; do
        GLIBC_TUNABLES=$([[ $memory == warm ]] && echo "${tunables[warm]}" || echo "") "$bench" \
          --benchmark_filter='^BM_HexSubdivisionPaired/' --benchmark_format=json 2>/dev/null >"$data/paired-$memory-$r.json"
      done
    done
  else
    GLIBC_TUNABLES=${tunables[$regime]} "$bench" \
      --benchmark_filter='^BM_HexSubdivision(QueryReplace|QueryReplaceAssumeValid|ReplaceOnly|Direct|QueryReplaceUnreserved)/' \
      --benchmark_repetitions="$reps" --benchmark_report_aggregates_only=true \
      --benchmark_out="$data/$regime.json" --benchmark_out_format=json >/dev/null 2>&1
  fi
done
echo "load after:  $(cut -d' ' -f1-3 /proc/loadavg)"
python3 - "$data" "$regimes" <<'PY'
import glob, json, os, re, statistics, sys
data, regimes = sys.argv[1], sys.argv[2].split()
print(f"{'memory':7} {'side':>4} {'volumes':>7} {'direct':>8} {'qr':>8} {'overhead':>8} {'qr assume-valid':>15} "
      f"{'overhead':>8} {'replace only':>12} {'overhead':>8} {'qr unreserved':>13}   (CPU ms, medians)")
for regime in regimes:
    med = {}
    if regime == "paired":
        continue
    if regime == "fresh":
        runs = {}
        for f in glob.glob(f"{data}/fresh-*.json"):
            for b in json.load(open(f))["benchmarks"]:
                name, side = re.match(r"BM_HexSubdivision(\w+)/(\d+)", b["run_name"]).groups()
                runs.setdefault((name, int(side)), []).append((b["cpu_time"], b.get("volumes", 0)))
        for key, v in runs.items():
            med[key] = (statistics.median(t for t, _ in v), v[0][1])
    else:
        for b in json.load(open(f"{data}/{regime}.json"))["benchmarks"]:
            if b.get("aggregate_name") != "median":
                continue
            name, side = re.match(r"BM_HexSubdivision(\w+)/(\d+)", b["run_name"]).groups()
            med[(name, int(side))] = (b["cpu_time"], b.get("volumes", 0))
    def cell(name, side, d, overhead=True):
        m = med.get((name, side))
        if m is None:
            return ("", "") if overhead else ""
        return (f"{m[0]:.1f}", f"{100 * (m[0] - d) / d:.0f}%") if overhead else f"{m[0]:.1f}"
    for side in sorted({s for _, s in med}):
        d, vol = med[("Direct", side)]
        q, qo = cell("QueryReplace", side, d)
        a, ao = cell("QueryReplaceAssumeValid", side, d)
        o, oo = cell("ReplaceOnly", side, d)
        u = cell("QueryReplaceUnreserved", side, d, False)
        print(f"{regime:7} {side:>4} {int(vol):>7} {d:>8.1f} {q:>8} {qo:>8} {a:>15} {ao:>8} {o:>12} {oo:>8} {u:>13}")
PY
if [[ " $regimes " == *" paired "* ]]; then
  python3 - "$data" <<'PY'
import glob, json, re, statistics, sys
data = sys.argv[1]
variants = {"0": "qr, input checked once", "1": "qr assume-valid", "2": "replace only"}
print(f"{'paired':7} {'memory':8} {'side':>4} {'direct ms':>9}  " + "  ".join(f"{v:>22}" for v in variants.values()))
for memory in ("default", "warm"):
    ratios, direct = {}, {}
    for f in glob.glob(f"{data}/paired-{memory}-*.json"):
        for b in json.load(open(f))["benchmarks"]:
            side, variant = re.match(r"BM_HexSubdivisionPaired/(\d+)/(\d)", b["run_name"]).groups()
            ratios.setdefault((int(side), variant), []).append(b["ratio"])
            direct.setdefault(int(side), []).append(b["direct_ms"])
    for side in sorted(direct):
        cells = []
        for v in variants:
            r = ratios.get((side, v), [])
            cells.append(f"{statistics.median(r):.2f} [{min(r):.2f}-{max(r):.2f}]" if r else "")
        print(f"{'':7} {memory:8} {side:>4} {statistics.median(direct[side]):>9.2f}  " + "  ".join(f"{c:>22}" for c in cells))
PY
fi
