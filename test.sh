#!/usr/bin/env bash
# Runs every test of cncrot: formatting, clippy, the Rust tests (unit, integration, doc,
# header freshness, no-allocation), the C harness (shared and static library, ASan+UBSan,
# valgrind, header as C99 and C++) and the MATLAB/Octave suite.
# Installs what the tests need (C compiler, valgrind, GNU Octave) with apt-get when missing.
set -euo pipefail
cd "$(dirname "$0")"

need=()
command -v cc >/dev/null || need+=(gcc)
command -v c++ >/dev/null || need+=(g++)
command -v valgrind >/dev/null || need+=(valgrind)
command -v mkoctfile >/dev/null || need+=(octave liboctave-dev)
if [ ${#need[@]} -gt 0 ]; then
  echo "== installing ${need[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${need[@]}" >/dev/null
fi

# A committed header that no longer matches the sources must fail, not be rewritten.
export CNCROT_FROZEN_HEADER=1

echo "== cargo fmt --check"
cargo fmt --check
echo "== cargo clippy"
cargo clippy --all-targets -- -D warnings
cargo clippy --profile rt --lib --no-default-features -- -D warnings
echo "== cargo test"
cargo test
echo "== no-panic proof"
bash c_tests/no_panic.sh
echo "== C harness"
bash c_tests/run.sh
if [ -f matlab/run_tests.sh ]; then
  echo "== MATLAB/Octave"
  bash matlab/run_tests.sh
fi
