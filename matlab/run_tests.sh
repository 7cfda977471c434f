#!/usr/bin/env bash
# Builds the MEX functions with GNU Octave against the static library and runs the
# MATLAB/Octave suite, including bit-for-bit parity with the C library.
# The library is taken from ${CARGO_TARGET_DIR:-target}/release (build_mex.m reads the
# same variable), so a separate cargo target directory works as well as the default.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
target=${CARGO_TARGET_DIR:-target}
case "$target" in
  /*) ;;
  *) target="$root/$target" ;;
esac
export CARGO_TARGET_DIR="$target"
cargo build --release --quiet
mkdir -p c_tests/build
cc -std=c99 -O1 -Wall -Wextra -Werror -pedantic -Iinclude -Ic_tests c_tests/parity.c \
  "$target/release/libcncrot.a" -lm -lpthread -ldl -o c_tests/build/parity
c_tests/build/parity > c_tests/build/parity_cases.txt
octave-cli -q --no-gui --eval "cd('$root/matlab'); build_mex(); addpath('$root/matlab/tests'); test_cncrot('$root/c_tests/build/parity_cases.txt');"
