#!/usr/bin/env bash
# Builds and runs the text benchmark (benches/text.c): cncrot's program-line writer and
# reader against glibc's snprintf and strtod on the same numbers, printing ratios.
# Usage: benches/text.sh  (from anywhere; uses ${CARGO_TARGET_DIR:-target}).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
target=${CARGO_TARGET_DIR:-target}
case $target in /*) ;; *) target=$root/$target ;; esac
cargo build --release --quiet
mkdir -p "$target/bench-text"
cc -std=c99 -O2 -Wall -Wextra -Werror -Iinclude benches/text.c "$target/release/libcncrot.a" \
  -lm -lpthread -ldl -o "$target/bench-text/text"
"$target/bench-text/text"
