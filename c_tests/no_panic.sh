#!/usr/bin/env bash
# Proves that no exported function can panic, with the `no-panic` crate: under the feature
# `no-panic-proof` every export carries `#[no_panic]` and the catch_unwind boundary is left
# out, so a panic path that the optimiser cannot remove leaves a reference to an undefined
# symbol named "ERROR[no-panic]: detected panic in function `…`", and linking the shared
# library with --no-undefined fails. Without --no-undefined the check would pass silently.
# Runs the proof with the platform's math and with the pure-Rust libm of the real-time
# build, then shows on a deliberately panicking export that the proof can fail.
# Usage: c_tests/no_panic.sh  (from anywhere).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

proof() {
  cargo rustc --quiet --release --lib --crate-type cdylib --target-dir target/no-panic \
    --features "$1" -- -C link-arg=-Wl,--no-undefined
}

failed=0
# Every export must carry the attribute: each #[no_mangle] in src/ffi follows it.
missing=$(awk 'FNR==1{prev=""} /^#\[no_mangle\]/ && prev !~ /no_panic::no_panic/ {print FILENAME": "FNR} {prev=$0}' src/ffi/*.rs)
if [ -n "$missing" ]; then
  echo "no-panic: exports without #[cfg_attr(feature = \"no-panic-proof\", no_panic::no_panic)]:"
  echo "$missing"
  failed=1
fi

for features in no-panic-proof no-panic-proof,pure-rust-math; do
  if out=$(proof "$features" 2>&1); then
    echo "no-panic ($features): no export can panic"
  else
    echo "no-panic ($features): FAILED"
    grep -F "ERROR[no-panic]" <<<"$out" || echo "$out" | tail -20
    failed=1
  fi
done

if out=$(proof no-panic-canary 2>&1); then
  echo "no-panic: the canary export linked although it can panic: the proof is broken"
  failed=1
elif grep -qF 'detected panic in function `cncrot_no_panic_canary`' <<<"$out"; then
  echo "no-panic: the proof fails on the canary export, as it must"
else
  echo "no-panic: the canary build failed for another reason:"
  echo "$out" | tail -20
  failed=1
fi
exit $failed
