#!/usr/bin/env bash
# Builds the C tests against the shared and the static library, with AddressSanitizer +
# UndefinedBehaviorSanitizer, and under valgrind; checks that the header compiles as C99 and
# as C++. Usage: c_tests/run.sh  (from anywhere; needs a C compiler and valgrind).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
build=c_tests/build
mkdir -p "$build"
CNCROT_FROZEN_HEADER=1 cargo build --release --quiet
lib=target/release
warn=(-Wall -Wextra -Werror -pedantic -Iinclude -Ic_tests)

echo "== header compiles as C99 and C++"
cc -std=c99 "${warn[@]}" -c c_tests/header_check.c -o "$build/header_c.o"
c++ -std=c++11 "${warn[@]}" -x c++ -c c_tests/header_check.c -o "$build/header_cpp.o"

tests=(test_core test_cycle600)
failed=0
for t in "${tests[@]}"; do
  src=c_tests/$t.c
  cc -std=c99 -O1 -g "${warn[@]}" "$src" -L"$lib" -lcncrot -Wl,-rpath,"$root/$lib" -lm -o "$build/${t}_shared"
  cc -std=c99 -O1 -g "${warn[@]}" "$src" "$lib/libcncrot.a" -lm -lpthread -ldl -o "$build/${t}_static"
  cc -std=c99 -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer \
    "${warn[@]}" "$src" "$lib/libcncrot.a" -lm -lpthread -ldl -o "$build/${t}_asan"
  for variant in shared static asan; do
    echo "== $t ($variant)"
    "$build/${t}_$variant" || failed=1
  done
  echo "== $t (shared, valgrind)"
  valgrind -q --error-exitcode=99 --leak-check=full "$build/${t}_shared" || failed=1
  echo "== $t (static, valgrind)"
  valgrind -q --error-exitcode=99 --leak-check=full "$build/${t}_static" || failed=1
done
exit $failed
