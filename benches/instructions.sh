#!/usr/bin/env bash
# Instructions per call of each row of the timing benchmark (function and input class),
# counted by valgrind's callgrind: the same for every run of the same binary, whatever else
# the machine does, so input classes compare without the noise of a shared machine.
# Each row runs twice, with 1000 and 11000 calls; the difference over 10000 is the
# instructions of one call, without one-time costs (lazy symbol binding). Prints a table with
# each class relative to the function's random class.
# Usage: benches/instructions.sh [FEATURES]  (needs valgrind; part of .ci/long-runs).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
features=${1:-}
bin=$(cargo bench --bench timing ${features:+--features "$features"} --no-run 2>&1 |
  grep -oE 'target/release/deps/timing-[0-9a-f]+' | tail -1)
count() {
  local out
  out=$(mktemp)
  valgrind --tool=callgrind --callgrind-out-file="$out" --toggle-collect='*one_call*' \
    "$bin" --calls "$1" --only "$2" >/dev/null 2>&1
  awk '$1=="summary:" {print $2}' "$out"
  rm -f "$out"
}
echo "instructions per call (${features:-platform libm}), callgrind"
printf '%-30s %-22s %12s %8s\n' function "input class" instructions class
declare -A base
"$bin" --calls 1 | awk 'substr($0,1,7)=="cncrot_" {f=substr($0,1,30); c=substr($0,32,20); sub(/ +$/,"",f); sub(/ +$/,"",c); print f "/" c}' |
  while IFS= read -r row; do
    few=$(count 1000 "$row")
    many=$(count 11000 "$row")
    per=$(( (many - few) / 10000 ))
    fn=${row%%/*}
    class=${row#*/}
    [ -n "${base[$fn]:-}" ] || base[$fn]=$per
    ratio=$(awk -v a="$per" -v b="${base[$fn]}" 'BEGIN {printf "%.2f", a / b}')
    printf '%-30s %-22s %12d %8s\n' "$fn" "$class" "$per" "$ratio"
  done
