#!/usr/bin/env bash
# A libFuzzer campaign over gmr's parsers (tools/fuzzing/targets): builds the fuzz targets with
# clang, ASan and UBSan in build-fuzz/, runs each for SECONDS (default 60) with its dictionary, a
# working corpus in out/fuzz/parsers/<target>/ seeded with the CTest seeds, and writes the
# summary (executions, crashes, leaks, timeouts, out-of-memory per target) to
# out/fuzz/parsers/summary.md and .json. Findings go to out/fuzz/parsers/findings/; minimise one
# with the target's -minimize_crash=1 and add it to tools/fuzzing/corpus/<target>/ so that every
# test run replays it.
#   tools/fuzzing/campaign.sh [SECONDS] [TARGET...]
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
seconds="${1:-60}"; shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(gmap_json rule_json voxels off obj jme expression orbit_type match)
build="$root/build-fuzz" out="$root/out/fuzz/parsers"
export CCACHE_BASEDIR="$root"
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGMR_LIBFUZZER=ON \
    -DGMR_TESTS=OFF -DGMR_CGAL=OFF -DGMR_UNITY=OFF -DGMR_PCH=OFF >/dev/null
fi
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/#/gmr_fuzz_}"
mkdir -p "$out/findings"
# The CTest seeds of each target (tools/fuzzing/CMakeLists.txt).
seeds_of() {
  case "$1" in
    gmap_json) ls "$root"/model/map_io/tests/data/*.json ;;
    rule_json) ls "$root"/tools/data/rules/*.json "$root"/checker/tests/data/*.json ;;
    voxels) ls "$root"/tools/data/*.voxels.json ;;
    off) ls "$root"/tools/data/*.off "$root"/model/map_io/tests/data/*.off ;;
    jme) ls "$root"/tools/data/jerboa/*.jme ;;
    obj|expression|orbit_type|match) ls "$root"/tools/fuzzing/seeds/"$1"/* ;;
  esac
  find "$root/tools/fuzzing/corpus/$1" -type f ! -name .keep
}
dict_of() { case "$1" in gmap_json|rule_json|voxels) echo json ;; off) echo off ;; obj) echo obj ;; jme) echo xml ;; expression) echo expression ;; *) echo orbit ;; esac; }
echo "| target | executions | seconds | crashes | leaks | timeouts | out of memory |" >"$out/summary.md"
echo "|---|---|---|---|---|---|---|" >>"$out/summary.md"
json="["
for t in "${targets[@]}"; do
  corpus="$out/$t"; mkdir -p "$corpus"
  seeds_of "$t" | while read -r f; do cp -n "$f" "$corpus/" 2>/dev/null || true; done
  log="$out/$t.log"
  before=$(ls "$out/findings" | wc -l)
  ASAN_OPTIONS=detect_leaks=1 "$build/tools/fuzzing/gmr_fuzz_$t" "$corpus" -dict="$root/tools/fuzzing/dict/$(dict_of "$t").dict" \
    -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=4096 -artifact_prefix="$out/findings/$t-" \
    -print_final_stats=1 >"$log" 2>&1 || true
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  count() { ls "$out/findings" 2>/dev/null | grep -c "^$t-$1" || true; }
  crashes=$(count crash-) leaks=$(count leak-) timeouts=$(count timeout-) ooms=$(count oom-)
  echo "| $t | $runs | $seconds | $crashes | $leaks | $timeouts | $ooms |" >>"$out/summary.md"
  json+="{\"target\":\"$t\",\"executions\":$runs,\"seconds\":$seconds,\"crashes\":$crashes,\"leaks\":$leaks,\"timeouts\":$timeouts,\"oom\":$ooms},"
  [ -t 1 ] && echo "gmr fuzz: $t: $runs executions, $crashes crashes"
done
echo "${json%,}]" >"$out/summary.json"
cat "$out/summary.md"
