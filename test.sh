#!/usr/bin/env bash
# Runs every test of cncrot: formatting, clippy, the Rust tests of the library and the
# command-line tool (unit, integration, doc, header freshness, ABI check, no-allocation,
# property and concurrency tests, every CLI subcommand, its pictures through librsvg), the
# no-panic proof, the C harness
# (shared and static library, ASan+UBSan, valgrind, header as C99 and C++, the real-time
# build and its symbols), the installed packages (pkg-config, CMake, MATLAB from the
# installed copy), the Windows builds (symbols, C harness under Wine), the system-call check of the timing benchmark, every fuzz target for
# 20 s, and the MATLAB/Octave suite.
# Installs what the tests need (C compiler, valgrind, strace, pkg-config, CMake, MinGW-w64,
# Wine, GNU Octave, librsvg's rsvg-convert, cargo-fuzz; the Rust Windows targets) when missing. Long runs (fuzzing for 10 minutes a target, timing over 10^7 calls): .ci/long-runs
set -euo pipefail
cd "$(dirname "$0")"

need=()
command -v cc >/dev/null || need+=(gcc)
command -v c++ >/dev/null || need+=(g++)
command -v valgrind >/dev/null || need+=(valgrind)
command -v strace >/dev/null || need+=(strace)
command -v pkg-config >/dev/null || need+=(pkg-config)
command -v cmake >/dev/null || need+=(cmake)
command -v x86_64-w64-mingw32-gcc >/dev/null || need+=(mingw-w64)
command -v wine >/dev/null || need+=(wine wine64)
command -v mkoctfile >/dev/null || need+=(octave liboctave-dev)
command -v rsvg-convert >/dev/null || need+=(librsvg2-bin)
if [ ${#need[@]} -gt 0 ]; then
  echo "== installing ${need[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${need[@]}" >/dev/null
fi


echo "== cargo fmt --check"
cargo fmt --all --check
cargo fmt --check --manifest-path fuzz/Cargo.toml
echo "== cargo clippy"
cargo clippy --workspace --all-targets --features cncrot/nalgebra -- -D warnings
cargo clippy --all-targets --features no-panic-proof,pure-rust-math -- -D warnings
cargo clippy --profile rt --lib --no-default-features -- -D warnings
cargo clippy --manifest-path fuzz/Cargo.toml --all-targets -- -D warnings
echo "== cargo test"
cargo test --workspace --features cncrot/nalgebra
# The trigonometry's bounds and lanes again with the real-time build's libm (sqrt, fmod).
cargo test --lib --features pure-rust-math math::
echo "== the CLI's pictures through a renderer (librsvg)"
bash cli/tests/render.sh
echo "== cargo doc"
RUSTDOCFLAGS="-D warnings" cargo doc --no-deps --quiet --features nalgebra
echo "== no-panic proof"
bash c_tests/no_panic.sh
echo "== C harness"
bash c_tests/run.sh
echo "== installed packages: pkg-config, CMake, MATLAB"
bash c_tests/package.sh
echo "== Windows: MinGW-w64 and MSVC builds, symbols, C harness under Wine (smoke)"
bash c_tests/windows.sh smoke
echo "== no system calls on the hot path"
bash benches/syscalls.sh
bash benches/syscalls.sh pure-rust-math
echo "== text benchmark against glibc (figures to read, not a check; docs/measurements.md#text)"
bash benches/text.sh
echo "== fuzzing (20 s per target)"
bash fuzz/run.sh 20
if [ -f matlab/run_tests.sh ]; then
  echo "== MATLAB/Octave"
  bash matlab/run_tests.sh
fi
