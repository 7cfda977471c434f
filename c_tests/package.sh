#!/usr/bin/env bash
# The library as a C developer gets it: install.sh into a fresh prefix, then every C example
# of the documentation (README.md and docs/*.md, blocks with a main and a "prints:" comment)
# built through pkg-config alone, shared (rpath from pkg-config, no LD_LIBRARY_PATH) and
# static, and the first one through CMake's find_package; the soname, the CMake package's
# version rule, and the MEX functions built from the installed copy (when Octave is there).
# Usage: c_tests/package.sh  (needs cc, pkg-config, cmake, objdump, readelf).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix
failed=0
fail() { echo "package: FAILED: $*"; failed=1; }

./install.sh --prefix "$prefix" >/dev/null
unset LD_LIBRARY_PATH
export PKG_CONFIG_PATH=$prefix/lib/pkgconfig
version=$(pkg-config --modversion cncrot)
major=${version%%.*}; rest=${version#*.}; minor=${rest%%.*}
if [ "$major" = 0 ]; then abi=0.$minor; next=0.$((minor + 1)); else abi=$major; next=$((major + 1)).0; fi
echo "package: cncrot $version installed (ABI $abi)"
# The command-line tool beside the library: the paper's Example 3.
cli_out=$("$prefix/bin/cncrot" convert --from extrinsic:XYZ --to intrinsic:ZXY 30 45 60 2>&1) || fail "bin/cncrot did not run: $cli_out"
grep -q "37.7923 20.7048 49.1066" <<<"$cli_out" || fail "bin/cncrot convert: $cli_out"

soname=$(objdump -p "$prefix/lib/libcncrot.so.$version" | awk '$1 == "SONAME" {print $2}')
[ "$soname" = "libcncrot.so.$abi" ] || fail "soname '$soname', expected libcncrot.so.$abi"
[ "$(readlink "$prefix/lib/libcncrot.so")" = "libcncrot.so.$abi" ] || fail "libcncrot.so link"
[ "$(readlink "$prefix/lib/libcncrot.so.$abi")" = "libcncrot.so.$version" ] || fail "soname link"

# The documentation's complete C programs, each with the output it promises.
awk -v dir="$work" '
  /^```c$/ { inblock = 1; text = ""; next }
  /^```$/ && inblock {
    inblock = 0
    if (text ~ /int main\(/ && text ~ /prints: /) { n++; printf "%s", text > (dir "/example_" n ".c"); close(dir "/example_" n ".c") }
    next
  }
  inblock { text = text $0 "\n" }
' README.md docs/*.md
count=$(find "$work" -maxdepth 1 -name "example_*.c" | wc -l)
[ "$count" -ge 2 ] || { fail "found $count C examples with a main in the documentation"; exit 1; }
warn=(-std=c99 -Wall -Wextra -Werror -pedantic)
for src in "$work"/example_*.c; do
  name=$(basename "$src" .c)
  want=$(sed -n 's|.*prints: \(.*\) \*/.*|\1|p' "$src")
  # shellcheck disable=SC2046
  cc "${warn[@]}" "$src" $(pkg-config --cflags --libs cncrot) \
    -Wl,-rpath,"$(pkg-config --variable=libdir cncrot)" -o "$work/$name.shared"
  # shellcheck disable=SC2046
  cc "${warn[@]}" "$src" $(pkg-config --cflags --libs cncrot-static) -o "$work/$name.static"
  readelf -d "$work/$name.shared" | grep -q "NEEDED.*\[libcncrot.so.$abi\]" \
    || fail "$name.shared does not need libcncrot.so.$abi"
  if readelf -d "$work/$name.static" | grep -q 'NEEDED.*libcncrot'; then
    fail "$name.static needs the shared library"
  fi
  for kind in shared static; do
    got=$("$work/$name.$kind")
    if [ "$got" = "$want" ]; then echo "package: $name ($kind, pkg-config): $got"
    else fail "$name ($kind): printed '$got', the documentation says '$want'"; fi
  done
done

# CMake: find_package with the installed version's ABI, shared and static.
example=$work/example_1.c
want=$(sed -n 's|.*prints: \(.*\) \*/.*|\1|p' "$example")
cmake -S c_tests/consumer -B "$work/cmake" -DCMAKE_PREFIX_PATH="$prefix" -DCNCROT_WANT="$abi" \
  -DCNCROT_EXAMPLE="$example" >/dev/null
cmake --build "$work/cmake" >/dev/null
for kind in shared static; do
  got=$("$work/cmake/example_$kind")
  if [ "$got" = "$want" ]; then echo "package: example_1 ($kind, CMake): $got"
  else fail "CMake example_$kind printed '$got', expected '$want'"; fi
done
# The package refuses a version of another ABI.
for other in "$next" 99.0; do
  if cmake -S c_tests/consumer -B "$work/cmake_$other" -DCMAKE_PREFIX_PATH="$prefix" \
       -DCNCROT_WANT="$other" -DCNCROT_EXAMPLE="$example" >/dev/null 2>&1; then
    fail "find_package(cncrot $other) accepted version $version"
  fi
done

# MATLAB/Octave: build_mex in the installed copy finds the installed library by itself.
if command -v octave-cli >/dev/null; then
  # (Octave 7 may print an error about an exception while exiting: the result line counts.)
  out=$(cd "$prefix/share/cncrot/matlab" && octave-cli -q --no-gui --eval \
    "build_mex(); printf('result: %.4f %.4f %.4f\n', cncrot_convert(0, 57, [30 45 60], 1, 39));" 2>&1) || true
  if grep -qx 'result: 37.7923 20.7048 49.1066' <<<"$out"; then
    echo "package: MEX built from the installed copy: $(grep '^result: ' <<<"$out")"
  else fail "MEX from the installed copy: $out"; fi
fi

[ $failed -eq 0 ] && echo "package: all consumers passed"
exit $failed
