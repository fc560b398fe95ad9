#!/usr/bin/env bash
# Time to a verdict of `gmr verify` on every rule of the library (tools/data/rules), by bound,
# with the SMT engine and with the enumerator, in one run: CPU seconds of the whole process (user +
# system, so Z3's and the process's start-up are included), as a Markdown table. The enumerator
# is run up to GMR_VERIFY_ENUM_MAX darts (default 7), the SMT engine up to GMR_VERIFY_MAX (default
# 10); a run longer than GMR_VERIFY_TIMEOUT seconds (default 120) is shown as '>T'.
#
#   tools/bench/verify_rules.sh [gmr binary, default build/tools/gmr]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
gmr=${1:-$root/build/tools/gmr}
enum_max=${GMR_VERIFY_ENUM_MAX:-7}
max=${GMR_VERIFY_MAX:-10}
timeout=${GMR_VERIFY_TIMEOUT:-120}
bounds=(4 6 7 8 10)

# cpu <engine> <rule> <bound>: CPU seconds, or >T on time-out, or the exit code on an error.
cpu() {
  local out rc=0
  out=$(mktemp)
  /usr/bin/time -o "$out" -f "%U %S" timeout "$timeout" "$gmr" verify "$2" --bound "$3" \
    --engine "$1" >/dev/null 2>&1 || rc=$?
  if [ "$rc" = 124 ]; then echo ">${timeout}"; else awk 'END { printf "%.2f", $1 + $2 }' "$out"; fi
  rm -f "$out"
}

printf "| rule |"; for k in "${bounds[@]}"; do printf " SMT %s | enum %s |" "$k" "$k"; done; echo
printf "|---|"; for k in "${bounds[@]}"; do printf -- "---|---|"; done; echo
for rule in "$root"/tools/data/rules/*.json; do
  printf "| %s |" "$(basename "$rule" .json)"
  for k in "${bounds[@]}"; do
    if [ "$k" -le "$max" ]; then printf " %s |" "$(cpu smt "$rule" "$k")"; else printf " – |"; fi
    if [ "$k" -le "$enum_max" ]; then printf " %s |" "$(cpu enum "$rule" "$k")"; else printf " – |"; fi
  done
  echo
done
