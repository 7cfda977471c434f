#!/usr/bin/env bash
# No system call on the hot path: runs the timing benchmark under `strace -f -c` with 10^3
# and with 10^5 calls per function and input class (3.2 million calls more in the second
# run) and requires the same number of system calls in both. Whatever the program does to
# start, print and allocate its fixed buffers is the same in both runs; a single system call
# per exported-function call would add millions. A canary row that calls sched_yield shows
# that the check can fail. Usage: benches/syscalls.sh (needs strace).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
features=${1:-}
bin=$(cargo bench --bench timing ${features:+--features "$features"} --no-run 2>&1 |
  grep -oE 'target/release/deps/timing-[0-9a-f]+' | tail -1)
count() {
  local out
  out=$(mktemp)
  strace -f -c -o "$out" "$bin" --calls "$@" >/dev/null
  # The summary's last line: "100.00 <seconds> <usecs/call> <calls> [errors] total".
  awk '$NF=="total" {print $4}' "$out"
  rm -f "$out"
}
few=$(count 1000)
many=$(count 100000)
echo "syscalls: $few system calls with 10^3 calls per row, $many with 10^5 per row (${features:-std math})"
if [ "$few" != "$many" ]; then
  echo "syscalls: the exported functions make system calls"
  exit 1
fi
# The check must see a system call when there is one: the canary row calls sched_yield.
if [ "$(count 1000 --syscall-canary)" = "$(count 100000 --syscall-canary)" ]; then
  echo "syscalls: the canary's sched_yield calls were not counted: the check is broken"
  exit 1
fi
