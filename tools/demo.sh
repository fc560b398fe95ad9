#!/usr/bin/env bash
# The main demo: installs what is missing, builds what is stale, runs `gmr demo`.
# Usage: tools/demo.sh [gmr demo options, e.g. --out out/demo]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/tools/setup.sh"
# ccache keys on paths relative to the checkout, so a fresh clone reuses the cache.
export CCACHE_BASEDIR="$root"
build="$root/build"
gen=(); [ -f "$build/CMakeCache.txt" ] || gen=(-G Ninja)
cmake -S "$root" -B "$build" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target gmr -j"$(nproc)"
cd "$root"
exec "$build/tools/gmr" demo "$@"
