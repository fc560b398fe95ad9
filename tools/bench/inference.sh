#!/usr/bin/env bash
# Inference benchmarks (tools/bench/inference_bench.cpp): the inference paper's examples against its
# Jerboa timings (Powell–Sabin ≈ 5 ms, Doo–Sabin 3rd iteration ≈ 40 ms, (2,2,2)-Menger ≈ 150 ms),
# the naive driver in the same run, and the time per dart of inferring a quad subdivision from tori
# of 10^3 .. 10^6 darts (before + after), plotted with gnuplot into docs/inference-linear.svg.
#
# The linear series runs twice: with glibc's default allocator settings (buffers above the mmap
# threshold come back from the kernel at every iteration, so every page of them is faulted in and
# zeroed again) and with that threshold raised (GLIBC_TUNABLES), which leaves the algorithm's own cost.
#
#   tools/bench/inference.sh                     # ~3 min
#   GMR_BENCH_REPS=5 tools/bench/inference.sh    # repetitions, medians reported (default 3)
#   GMR_BENCH_BUILD=/tmp/b tools/bench/inference.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
reps=${GMR_BENCH_REPS:-3}

bench_build gmr_bench_inference
bin="$build/tools/bench/gmr_bench_inference"
common=(--benchmark_repetitions="$reps" --benchmark_report_aggregates_only=true --benchmark_out_format=json)

"$bin" "${common[@]}" --benchmark_out="$build/bench-inference.json" "$@"
GLIBC_TUNABLES=glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=1073741824 \
  "$bin" "${common[@]}" --benchmark_filter='quad_torus/gmr' --benchmark_out="$build/bench-inference-kept.json"

dat="$build/bench-inference-linear.dat"
python3 - "$build/bench-inference.json" "$build/bench-inference-kept.json" "$dat" <<'PY'
import json, sys

def medians(path):
    out = {}
    for b in json.load(open(path))["benchmarks"]:
        if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
            continue
        out[b.get("run_name", b["name"])] = b
    return out

runs, kept = medians(sys.argv[1]), medians(sys.argv[2])
ms = lambda b: b["cpu_time"] * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b.get("time_unit", "ns")]
wall = lambda b: b["real_time"] * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b.get("time_unit", "ns")]
paper = [("Powell-Sabin 6-split", 5.0), ("Doo-Sabin 3rd iteration", 40.0), ("(2,2,2)-Menger", 150.0)]
print("\nexample                    darts   gmr CPU ms  (wall)   Jerboa ms  speed-up   naive CPU ms  naive/gmr")
for k, (name, jerboa) in enumerate(paper):
    g, n = runs.get(f"infer/paper/gmr/{k}"), runs.get(f"infer/paper/naive/{k}")
    if not g:
        continue
    line = f"{name:24} {int(g['darts']):7d}   {ms(g):10.4f}  ({wall(g):.4f})  {jerboa:8.0f}  {jerboa / ms(g):8.0f}x"
    if n:
        line += f"   {ms(n):12.3f}  {ms(n) / ms(g):8.1f}x"
    print(line)
print("\nquad subdivision of a torus (before + after darts): CPU ns per dart; naive/gmr")
rows = []
for name, g in runs.items():
    if not name.startswith("infer/quad_torus/gmr/"):
        continue
    arg = name.rsplit("/", 1)[1]
    k = kept.get(name)
    n = runs.get(f"infer/quad_torus/naive/{arg}")
    d = g["darts"]
    rows.append((d, ms(g) * 1e6 / d, (ms(k) * 1e6 / d) if k else float("nan"), (ms(n) / ms(g)) if n else float("nan")))
rows.sort()
print("   darts   default allocator   memory kept   naive/gmr")
with open(sys.argv[3], "w") as f:
    f.write("# darts  ns_per_dart_default  ns_per_dart_memory_kept\n")
    for d, a, b, r in rows:
        print(f"{int(d):8d}   {a:17.1f}   {b:11.1f}   {r:9.1f}")
        f.write(f"{int(d)} {a:.3f} {b:.3f}\n")
PY

if command -v gnuplot >/dev/null; then
  gnuplot <<GP
set terminal svg size 640,400 dynamic font "sans,11" background rgb "white"
set output "$root/docs/inference-linear.svg"
set title "Inferring quad subdivision (orbit <0,1,2>) from tori: time per dart"
set xlabel "darts before + after"
set ylabel "CPU time per dart (ns)"
set logscale x
set format x "10^{%L}"
set yrange [0:*]
set key top left
set grid
plot "$dat" using 1:2 with linespoints title "default allocator", \
     "$dat" using 1:3 with linespoints title "memory kept by the allocator"
GP
  echo "plot: docs/inference-linear.svg"
fi
