#!/usr/bin/env bash
# The Windows artefacts, built on Linux, checked and run under Wine:
#   MinGW-w64 (x86_64-pc-windows-gnu): cncrot.dll, its import library libcncrot.dll.a and the
#     static libcncrot.a, for the std and the real-time build;
#   MSVC (x86_64-pc-windows-msvc): the real-time static library cncrot.lib (an archive needs
#     no linker; MSVC's link.exe is not available here).
# Checks: clippy with -D warnings for both targets; each DLL exports exactly the header's
# functions (and include/cncrot.def lists them); the real-time libraries need nothing from
# the host but the memory functions (no allocator, no unwinder); the C harness, built with
# MinGW-w64, passes under Wine against the real-time static library, the real-time DLL and
# the MSVC library (linked here by MinGW's linker, not by link.exe). The std builds are
# built and linked but not run: the Rust standard library imports bcryptprimitives.dll (its
# random source), which Wine 8 does not have; Windows 10 and later do.
# Usage: c_tests/windows.sh [smoke|full]   smoke: test_core and test_cycle600 (./test.sh);
#                                          full: every C test (.ci/long-runs)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mode=${1:-smoke}
gnu=x86_64-pc-windows-gnu
msvc=x86_64-pc-windows-msvc
cc=x86_64-w64-mingw32-gcc
objdump=x86_64-w64-mingw32-objdump
installed=$(rustup target list --installed)
for t in $gnu $msvc; do
  grep -qx "$t" <<<"$installed" || rustup target add "$t"
done
target=${CARGO_TARGET_DIR:-target}
build=c_tests/build/windows
mkdir -p "$build"
failed=0
fail() { echo "windows: FAILED: $*"; failed=1; }

echo "== Windows builds"
cargo build --release --lib --target $gnu --quiet
cargo build --profile rt --no-default-features --lib --target $gnu --quiet
cargo rustc --profile rt --no-default-features --lib --target $msvc --crate-type staticlib --quiet
std=$target/$gnu/release
rt=$target/$gnu/rt
ms=$target/$msvc/rt
echo "== clippy for the Windows targets"
cargo clippy --lib --target $gnu --quiet -- -D warnings
cargo clippy --profile rt --lib --no-default-features --target $gnu --quiet -- -D warnings
cargo clippy --profile rt --lib --no-default-features --target $msvc --quiet -- -D warnings

echo "== Windows symbols"
declared=$(grep -oE '\bcncrot_[a-z0-9_]+\(' include/cncrot.h | tr -d '(' | sort -u)
[ "$declared" = "$(awk '/^    cncrot_/ {print $1}' include/cncrot.def | sort -u)" ] \
  || fail "include/cncrot.def differs from the header's functions"
for dll in "$std/cncrot.dll" "$rt/cncrot.dll"; do
  exported=$($objdump -p "$dll" | awk '/\[Ordinal\/Name Pointer\] Table/ {f = 1; next} f && NF == 0 {f = 0} f {print $NF}' | sort -u)
  if [ "$declared" != "$exported" ]; then
    fail "$dll exports differ from the header:"
    diff <(echo "$declared") <(echo "$exported") | sed 's/^/  /' || true
  fi
done
echo "windows: real-time DLL imports from: $($objdump -p "$rt/cncrot.dll" | awk '/DLL Name:/ {print $3}' | tr '\n' ' ')"
# What a library needs: link every export into a DLL without any system library and read
# the undefined references. The MSVC library's 128-bit division helpers are weak externals
# with a default inside the library (link.exe takes the default; GNU ld does not look).
refs=$build/refs.c
{ echo '#include "cncrot.h"'; echo 'void *cncrot_all[] = {'; sed 's/.*/  (void *)&,/' <<<"$declared"; echo '};'; } > "$refs"
for lib in "$rt/libcncrot.a" "$ms/cncrot.lib"; do
  needs=$($cc -Iinclude -nostdlib -shared -o "$build/refs.dll" "$refs" "$lib" 2>&1 \
    | grep -o "undefined reference to \`[^']*'" | sed "s/undefined reference to \`//; s/'//" | sort -u || true)
  extra=""
  for n in $needs; do
    case "$n" in
      memcpy|memmove|memset|memcmp) ;;
      __udivti3|__umodti3|__divti3|__modti3)
        grep -qaF ".weak.$n.default" "$lib" || extra="$extra $n" ;;
      *) extra="$extra $n" ;;
    esac
  done
  echo "windows: $(basename "$lib") (real-time) needs: $(echo $needs)"
  [ -z "$extra" ] || fail "$lib needs more than the memory functions:$extra"
done

echo "== C harness under Wine"
if [ "$mode" = full ]; then
  tests=(test_core test_cycle600 test_dialects test_program test_kinematics test_batch)
else
  tests=(test_core test_cycle600)
fi
export WINEPREFIX=$root/$build/wineprefix WINEDEBUG=-all
warn=(-std=c99 -O1 -Wall -Wextra -Werror -pedantic -Iinclude -Ic_tests)
cp "$rt/cncrot.dll" "$build/"
for t in "${tests[@]}"; do
  src=c_tests/$t.c
  $cc "${warn[@]}" "$src" "$rt/libcncrot.a" -o "$build/${t}_rt_static.exe"
  $cc "${warn[@]}" "$src" -L"$rt" -lcncrot.dll -o "$build/${t}_rt_dll.exe"
  $cc "${warn[@]}" "$src" "$ms/cncrot.lib" -o "$build/${t}_msvc_rt.exe"
  # The std builds link (static: with the system libraries rustc names).
  $cc "${warn[@]}" "$src" "$std/libcncrot.a" -lws2_32 -luserenv -lntdll -lbcrypt -o "$build/${t}_std_static.exe"
  $cc "${warn[@]}" "$src" -L"$std" -lcncrot.dll -o "$build/${t}_std_dll.exe"
  for variant in rt_static rt_dll msvc_rt; do
    echo "== $t ($variant, Wine)"
    # (Wine may warn on stderr that its 32-bit part is missing: these are 64-bit programs.)
    wine "$build/${t}_$variant.exe" 2>/dev/null | tr -d '\r' || fail "$t ($variant) under Wine"
  done
done
[ $failed -eq 0 ] && echo "windows: all checks passed"
exit $failed
