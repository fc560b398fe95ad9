#!/usr/bin/env bash
# Event detection benchmark (tools/bench/events_bench.cpp): builds it (-DGMR_BENCH=ON, Release) and
# prints, per scenario, size and orbit type, the times (minimum over the repetitions, or median) of the application alone, of the
# application with the static events confirmed (static) and with the dynamic detector (dynamic),
# and the ratios dynamic/static (whole step) and (dynamic - apply)/(static - apply) (detection
# only; empty when static - apply is below the timer's noise, 0.5 us). Then the summary per scenario
# and size over the orbit types other than the component type <0,...,n> (ranges, as in
# docs/benchmarks.md), and the plot docs/events_bench.svg (gnuplot).
#
#   tools/bench/events.sh                                   # everything (tens of minutes)
#   tools/bench/events.sh --benchmark_filter='creation/'    # extra arguments go to Google Benchmark
#   GMR_BENCH_BUILD=/tmp/b tools/bench/events.sh            # build directory (default: build-bench)
#   GMR_BENCH_REPS=5 tools/bench/events.sh                  # repetitions, medians (default 11)
#   GMR_BENCH_REBUILD=0 GMR_BENCH_BUILD=build tools/bench/events.sh  # use an existing build as is
#   GMR_BENCH_RESULTS=a.json,b.json tools/bench/events.sh   # no run: summarize and plot saved results
#   GMR_BENCH_PLOT=/tmp/e.svg tools/bench/events.sh         # where the plot goes (default docs/events_bench.svg)
#   GMR_BENCH_STAT=median tools/bench/events.sh             # statistic over the repetitions (default min:
#                                                           # the cost without interference on a shared machine)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
reps=${GMR_BENCH_REPS:-11}
plot=${GMR_BENCH_PLOT:-$root/docs/events_bench.svg}

if [[ -n "${GMR_BENCH_RESULTS:-}" ]]; then
  results=$GMR_BENCH_RESULTS
else
  if [[ "${GMR_BENCH_REBUILD:-1}" == 1 || ! -x "$build/tools/bench/gmr_bench_events" ]]; then
    bench_build gmr_bench_events
  fi
  results="$build/bench-results-events.json"
  "$build/tools/bench/gmr_bench_events" --benchmark_repetitions="$reps" \
    --benchmark_report_aggregates_only=true --benchmark_out="$results" --benchmark_out_format=json "$@" >/dev/null
fi

data=$(mktemp -d)
trap 'rm -rf "$data"' EXIT
python3 - "$results" "$data" <<'PY'
import json, os, sys
stat = os.environ.get("GMR_BENCH_STAT", "min")
runs = {}
for path in sys.argv[1].split(","):
    for b in json.load(open(path))["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != stat:
            continue
        name = b.get("run_name", b["name"]).split("/iterations")[0]
        scen, size, orbit, method = name.split("/")
        unit = {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[b.get("time_unit", "us")]
        runs.setdefault((scen, int(size), orbit), {})[method] = b["real_time"] * unit
        runs[(scen, int(size), orbit)]["darts"] = b.get("darts", 0)
print(f"{'scenario':12} {'size':>8} {'darts':>8} {'orbit':10} {'apply us':>10} {'static us':>10} {'dynamic us':>11} {'dyn/stat':>9} {'detection':>10}")
full = {k: r for k, r in runs.items() if all(m in r for m in ("apply", "static", "dynamic"))}
for (scen, size, orbit), r in full.items():
    a, s, d = r["apply"], r["static"], r["dynamic"]
    det = f"{(d - a) / (s - a):10.0f}" if s - a > 0.5 else f"{'':>10}"
    print(f"{scen:12} {size:>8} {int(r['darts']):>8} {orbit:10} {a:10.1f} {s:10.1f} {d:11.1f} {d / s:9.0f} {det}")

# Summary per (scenario, size): ranges over the non-component orbit types; the component type apart.
def fmt(x):
    return f"{x:,.0f}" if x >= 100 else f"{x:.1f}" if x >= 10 else f"{x:.2f}" if x < 1 else f"{x:.1f}"
print()
print("| scenario | darts | static | dynamic | dynamic / static | static − apply | ⟨0,…,n⟩: static / dynamic |")
print("|---|---|---|---|---|---|---|")
groups = {}
for (scen, size, orbit), r in full.items():
    groups.setdefault((scen, size), []).append((orbit, r))
order = {"creation": 0, "split-local": 1, "merge": 2, "split": 3}
dat = open(sys.argv[2] + "/summary.dat", "w")
for (scen, size) in sorted(groups, key=lambda k: (order.get(k[0], 9), k[1])):
    rows = groups[(scen, size)]
    comp = max(rows, key=lambda x: x[0].count(","))[0]
    rest = [r for o, r in rows if o != comp]
    c = dict(rows)[comp]
    st = [r["static"] for r in rest]; dy = [r["dynamic"] for r in rest]
    ra = [r["dynamic"] / r["static"] for r in rest]; de = [r["static"] - r["apply"] for r in rest]
    darts = int(rest[0]["darts"])
    rng = lambda v: f"{fmt(min(v))}–{fmt(max(v))}"
    print(f"| {scen} | {darts:,} | {rng(st)} | {rng(dy)} | {rng(ra)} | {rng(de)} | {fmt(c['static'])} / {fmt(c['dynamic'])} |")
    dat.write(f"{scen} {darts} {min(st)} {max(st)} {min(dy)} {max(dy)} {min(ra)} {max(ra)} "
              f"{sorted(st)[len(st)//2]} {sorted(dy)[len(dy)//2]}\n")
dat.close()
PY

if command -v gnuplot >/dev/null; then
  for s in creation split-local merge split; do
    awk -v s="$s" '$1 == s' "$data/summary.dat" > "$data/$s.dat"
  done
  gnuplot <<GP
set terminal svg size 1000,420 dynamic font "sans,11"
set output "$plot"
set multiplot layout 1,2
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set xlabel "darts"
set grid
set key top left font ",9"
set title "time per application (µs), range over orbit types ≠ <0,…,n>"
plot "$data/creation.dat" u 2:9:3:4 w yerrorlines lc rgb "#1f77b4" pt 7 t "creation, static", \
     "$data/creation.dat" u 2:10:5:6 w yerrorlines lc rgb "#1f77b4" dt 2 pt 6 t "creation, dynamic", \
     "$data/split-local.dat" u 2:9:3:4 w yerrorlines lc rgb "#2ca02c" pt 5 t "local split, static", \
     "$data/split-local.dat" u 2:10:5:6 w yerrorlines lc rgb "#2ca02c" dt 2 pt 4 t "local split, dynamic", \
     "$data/merge.dat" u 2:9:3:4 w yerrorlines lc rgb "#d62728" pt 9 t "merge (3D), static", \
     "$data/merge.dat" u 2:10:5:6 w yerrorlines lc rgb "#d62728" dt 2 pt 8 t "merge (3D), dynamic", \
     "$data/split.dat" u 2:9:3:4 w yerrorlines lc rgb "#7f7f7f" pt 13 t "global split, static", \
     "$data/split.dat" u 2:10:5:6 w yerrorlines lc rgb "#7f7f7f" dt 2 pt 12 t "global split, dynamic"
set title "dynamic / static, lowest and highest over orbit types ≠ <0,…,n>"
set key top left
plot 1000 w l lc rgb "black" dt 3 t "1000×", \
     "$data/creation.dat" u 2:7 w lp lc rgb "#1f77b4" pt 7 t "creation, lowest", \
     "$data/creation.dat" u 2:8 w lp lc rgb "#1f77b4" dt 2 pt 6 t "creation, highest", \
     "$data/split-local.dat" u 2:7 w lp lc rgb "#2ca02c" pt 5 t "local split, lowest", \
     "$data/split-local.dat" u 2:8 w lp lc rgb "#2ca02c" dt 2 pt 4 t "local split, highest", \
     "$data/merge.dat" u 2:7 w lp lc rgb "#d62728" pt 9 t "merge (3D), lowest", \
     "$data/merge.dat" u 2:8 w lp lc rgb "#d62728" dt 2 pt 8 t "merge (3D), highest", \
     "$data/split.dat" u 2:7 w lp lc rgb "#7f7f7f" pt 13 t "global split, lowest"
unset multiplot
GP
  echo "plot: $plot"
fi
