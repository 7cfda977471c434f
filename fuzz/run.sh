#!/usr/bin/env bash
# Runs every cargo-fuzz target for a bounded time and records what it covered.
#   fuzz/run.sh [SECONDS]      default 20 per target (the README's test command); the long
#                              run is `fuzz/run.sh 600` (.ci/long-runs; docs/realtime.md, "Fuzzing")
# Starts from the committed seeds (fuzz/seeds/TARGET) plus the corpus of earlier runs
# (fuzz/corpus/TARGET, not committed). Crashes land in fuzz/artifacts/TARGET and fail the
# script. Each target's last libFuzzer status line (coverage "cov", features "ft", corpus
# size, executions) is appended to fuzz/coverage.log and printed.
# Needs cargo-fuzz (installed if missing); works with the stable toolchain: RUSTC_BOOTSTRAP
# lets it accept the -Z flags of the sanitizer build when no nightly toolchain is present.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
cd "$here"
seconds=${1:-20}
command -v cargo-fuzz >/dev/null || cargo install cargo-fuzz --locked --quiet
toolchain=()
if rustup toolchain list 2>/dev/null | grep -q '^nightly'; then
  toolchain=(+nightly)
else
  export RUSTC_BOOTSTRAP=1
fi
cargo "${toolchain[@]}" fuzz build -O 2>&1 | grep -vE '^\s*(Compiling|Finished)' || true
failed=0
for target in $(cargo "${toolchain[@]}" fuzz list); do
  mkdir -p "corpus/$target" "artifacts/$target"
  log=$(mktemp)
  if cargo "${toolchain[@]}" fuzz run -O "$target" "corpus/$target" "seeds/$target" -- \
      -max_total_time="$seconds" -timeout=5 -rss_limit_mb=2048 -print_final_stats=1 >"$log" 2>&1; then
    status=ok
  else
    status=FAILED
    failed=1
    grep -E "ERROR|panicked|SUMMARY|Test unit written" "$log" | head -20
  fi
  last=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
  execs=$(grep -E 'stat::number_of_executed_units' "$log" | awk '{print $2}' || true)
  line="$(date -u +%Y-%m-%dT%H:%MZ) $target ${seconds}s $status execs=${execs:-?} $last"
  echo "fuzz: $line"
  echo "$line" >>coverage.log
  rm -f "$log"
done
exit $failed
