#!/usr/bin/env bash
# Builds the C tests against the shared and the static library, with AddressSanitizer +
# UndefinedBehaviorSanitizer, and under valgrind; then against the real-time build (`core`
# only, panic = abort) whose symbols c_tests/symbols.sh checks; checks that both builds give
# the same bits (c_tests/same_bits.c) and that the header compiles as C99 and as C++. Usage: c_tests/run.sh  (from anywhere; needs a C compiler and
# valgrind).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
build=c_tests/build
mkdir -p "$build"
cargo build --release --quiet
cargo build --profile rt --no-default-features --lib --quiet
lib=target/release
rt=target/rt
# The shared library carries its soname (libcncrot.so.0.2): a program linked against it
# asks for that file, which cargo leaves in the build tree only as libcncrot.so.
for d in "$lib" "$rt"; do
  so=$(objdump -p "$d/libcncrot.so" | awk '$1 == "SONAME" {print $2}')
  [ -n "$so" ] && ln -sf libcncrot.so "$d/$so"
done
warn=(-Wall -Wextra -Werror -pedantic -Iinclude -Ic_tests)

echo "== header compiles as C99 and C++"
cc -std=c99 "${warn[@]}" -c c_tests/header_check.c -o "$build/header_c.o"
c++ -std=c++11 "${warn[@]}" -x c++ -c c_tests/header_check.c -o "$build/header_cpp.o"

echo "== exported and imported symbols"
failed=0
bash c_tests/symbols.sh "$lib" exports || failed=1
bash c_tests/symbols.sh "$rt" core || failed=1
echo "== worst-case stack of every export"
bash c_tests/stack.sh || failed=1
# The check must be able to fail: the std build imports the allocator and the unwinder.
if bash c_tests/symbols.sh "$lib" core >/dev/null; then
  echo "symbols: the core check passed the std build, which needs malloc: the check is broken"
  failed=1
fi

echo "== the same bits from the std and the real-time build"
cc -std=c99 -O1 "${warn[@]}" c_tests/same_bits.c "$lib/libcncrot.a" -lm -lpthread -ldl -o "$build/same_bits_std"
cc -std=c99 -O1 "${warn[@]}" c_tests/same_bits.c "$rt/libcncrot.a" -o "$build/same_bits_rt"
same_std=$("$build/same_bits_std") || failed=1
same_rt=$("$build/same_bits_rt") || failed=1
echo "$same_std (std)"
echo "$same_rt (real-time)"
if [ -z "$same_std" ] || [ "$same_std" != "$same_rt" ]; then
  echo "same_bits: the builds differ"
  failed=1
fi

tests=(test_core test_cycle600 test_dialects test_program test_kinematics test_batch)
for t in "${tests[@]}"; do
  src=c_tests/$t.c
  cc -std=c99 -O1 -g "${warn[@]}" "$src" -L"$lib" -lcncrot -Wl,-rpath,"$root/$lib" -lm -o "$build/${t}_shared"
  cc -std=c99 -O1 -g "${warn[@]}" "$src" "$lib/libcncrot.a" -lm -lpthread -ldl -o "$build/${t}_static"
  cc -std=c99 -O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer \
    "${warn[@]}" "$src" "$lib/libcncrot.a" -lm -lpthread -ldl -o "$build/${t}_asan"
  # The real-time build needs no -lpthread/-ldl; -lm is for the test's own fabs.
  cc -std=c99 -O1 -g "${warn[@]}" "$src" "$rt/libcncrot.a" -lm -o "$build/${t}_rt_static"
  cc -std=c99 -O1 -g "${warn[@]}" "$src" -L"$rt" -lcncrot -Wl,-rpath,"$root/$rt" -lm -o "$build/${t}_rt_shared"
  for variant in shared static asan rt_static rt_shared; do
    echo "== $t ($variant)"
    "$build/${t}_$variant" || failed=1
  done
  echo "== $t (shared, valgrind)"
  valgrind -q --error-exitcode=99 --leak-check=full "$build/${t}_shared" || failed=1
  echo "== $t (static, valgrind)"
  valgrind -q --error-exitcode=99 --leak-check=full "$build/${t}_static" || failed=1
  echo "== $t (real-time static, valgrind)"
  valgrind -q --error-exitcode=99 --leak-check=full "$build/${t}_rt_static" || failed=1
done
exit $failed
