#!/usr/bin/env bash
# Formats every C++ source of the checkout as .clang-format says (Debian's clang-format 14), or,
# with --check, lists the files that differ and exits 1 (the test command runs the check).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
if [ -d .git ] || [ -f .git ]; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp')
else
  mapfile -t files < <(find . -path ./build -prune -o -path './build-*' -prune -o \( -name '*.cpp' -o -name '*.hpp' \) -print)
fi
if [ "${1:-}" = "--check" ]; then
  # One warning line "<file>:<line>:<col>: error: code should be clang-formatted" per difference.
  mapfile -t bad < <(printf '%s\0' "${files[@]}" |
    xargs -0 clang-format --dry-run --Werror 2>&1 |
    sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: error: code should be clang-formatted.*/\1/p' | sort -u)
  if [ ${#bad[@]} -gt 0 ]; then
    echo "gmr format: ${#bad[@]} file(s) differ from .clang-format (run tools/format.sh):" >&2
    printf '  %s\n' "${bad[@]}" >&2
    exit 1
  fi
  exit 0
fi
printf '%s\0' "${files[@]}" | xargs -0 -n 50 clang-format -i
