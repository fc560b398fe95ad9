#!/usr/bin/env bash
# The main demo: installs what is missing, builds what is stale, runs `gmr demo`.
# Usage: tools/demo.sh [gmr demo options, e.g. --out out/demo]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/tools/setup.sh"
build="$root/build"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target gmr -j"$(nproc)"
cd "$root"
exec "$build/tools/gmr" demo "$@"
