#!/usr/bin/env bash
# Builds gmr_bench_smt (-DGMR_BENCH=ON, Release) and prints the time to a verdict of the SMT engine
# and of the enumerator by bound (darts) and rule size (nodes), CPU milliseconds, in one run
# (tools/bench/smt_bench.cpp), then the encoding choices and the session comparison, then the
# thesis conditions validated on the whole family of 1-G-map rules (symbolic engine against the
# enumerator rule by rule), and plots the times into docs/smt_time_to_verdict.svg (gnuplot).
#
#   tools/bench/run_smt.sh                      # enumerator up to 6 darts (~1 min)
#   GMR_BENCH_ENUM_MAX=7 tools/bench/run_smt.sh # enumerator up to 7 darts (~+15 s CPU)
#   GMR_BENCH_BUILD=/tmp/b tools/bench/run_smt.sh
#   GMR_BENCH_REPLOT=1 tools/bench/run_smt.sh  # tables and plot from the last run's saved output
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
bench_build gmr_bench_smt
if [ -n "${GMR_BENCH_REPLOT:-}" ]; then  # tables and plot again from the last run's output
  out=$(cat "$build/smt_bench.txt")
else
  out=$("$build/tools/bench/gmr_bench_smt" "$@" 2>/dev/null)
  echo "$out" > "$build/smt_bench.txt"
fi
echo "$out" | grep -E '^BM_(SmtVariant|FamilySession)' || true
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

echo
echo "CPU ms to validate the thesis conditions on every 1-G-map rule of at most m nodes (labels 0,1):"
echo "symbolic engine vs the enumerator rule by rule ('-': not run)"
dat="$build/smt_time_to_verdict.dat"
echo "$out" | awk -v dat="$dat" '
  /^BM_(Smt|Enum|Symbolic|FamilyEnum)\// {
    split($1, a, "/"); d = a[2]; m = a[3];
    t[a[1], d, m] = ($0 ~ /ERROR/) ? "-" : $4; ds[d] = 1
  }
  function v(e, d, m) { return ((e, d, m) in t) ? t[e, d, m] : "-" }
  END {
    printf "%-6s", "darts";
    for (m = 1; m <= 4; m++) printf " | sym m=%d famenum m=%d", m, m;
    printf "\n";
    for (d = 4; d <= 10; d++) {
      if (!(d in ds)) continue;
      printf "%-6s", d;
      for (m = 1; m <= 4; m++) printf " | %9s %12s", v("BM_Symbolic", d, m), v("BM_FamilyEnum", d, m);
      printf "\n";
      # darts, then per m: smt enum symbolic family-enum
      line = d;
      for (m = 1; m <= 4; m++)
        line = line " " v("BM_Smt", d, m) " " v("BM_Enum", d, m) " " v("BM_Symbolic", d, m) " " v("BM_FamilyEnum", d, m);
      print line > dat;
    }
  }'
if command -v gnuplot >/dev/null; then
  gnuplot <<EOF
set terminal svg size 1000,760 dynamic font "sans,11"
set output "$root/docs/smt_time_to_verdict.svg"
set datafile missing "-"
set logscale y
set format y "10^{%L}"
set xlabel "maps of at most k darts"
set ylabel "CPU ms to the verdict"
set key top left font ",9"
set grid
set multiplot layout 2,2 title "Time to a verdict (one run; tools/bench/run_smt.sh)" noenhanced
do for [m=1:4] {
  c = 2 + 4*(m-1)
  set title sprintf("rules of %d node%s", m, m > 1 ? "s" : "")
  plot "$dat" using 1:c with linespoints title "SMT, one rule (identity on a path, 2-G-maps)", \
       "" using 1:(column(c+1)) with linespoints title "enumerator, same rule", \
       "" using 1:(column(c+2)) with linespoints title "symbolic, every 1-G-map rule (thesis)", \
       "" using 1:(column(c+3)) with linespoints title "enumerator rule by rule, same family"
}
unset multiplot
EOF
  echo "plot: $root/docs/smt_time_to_verdict.svg"
fi
