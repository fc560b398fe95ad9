#!/usr/bin/env bash
# Builds gmr_bench_smt (-DGMR_BENCH=ON, Release) and prints the time to a verdict of the SMT engine
# and of the enumerator by bound (darts) and rule size (nodes), CPU milliseconds, in one run
# (tools/bench/smt_bench.cpp), then the encoding choices and the session comparison.
#
#   tools/bench/run_smt.sh                      # enumerator up to 6 darts (~1 min)
#   GMR_BENCH_ENUM_MAX=7 tools/bench/run_smt.sh # enumerator up to 7 darts (~+15 s CPU)
#   GMR_BENCH_BUILD=/tmp/b tools/bench/run_smt.sh
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
build=${GMR_BENCH_BUILD:-$root/build-bench}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DGMR_BENCH=ON -DGMR_TESTS=OFF >/dev/null
cmake --build "$build" --target gmr_bench_smt -j"$(nproc 2>/dev/null || echo 2)"
out=$("$build/tools/bench/gmr_bench_smt" "$@" 2>/dev/null)
echo "$out" | grep -E '^BM_(SmtVariant|FamilySession)'
echo
echo "CPU ms to the verdict (identity rule on a path of m nodes, 2-G-maps; '-': not run)"
echo "$out" | awk '
  /^BM_(Smt|Enum)\// {
    split($1, a, "/"); eng = (a[1] == "BM_Smt") ? "smt" : "enum"; d = a[2]; m = a[3];
    t[eng, d, m] = ($0 ~ /ERROR/) ? "-" : $4; ds[d] = 1
  }
  END {
    printf "%-6s", "darts";
    for (m = 1; m <= 4; m++) printf " | smt m=%d  enum m=%d", m, m;
    printf "\n";
    for (d = 4; d <= 10; d++) {
      if (!(d in ds)) continue;
      printf "%-6s", d;
      for (m = 1; m <= 4; m++) printf " | %8s %8s", ((("smt", d, m) in t) ? t["smt", d, m] : "-"), ((("enum", d, m) in t) ? t["enum", d, m] : "-");
      printf "\n";
    }
  }'
