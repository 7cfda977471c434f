#!/usr/bin/env bash
# Cross-builds the real-time library and checks it on other targets:
#   - bare metal aarch64-unknown-none, armv7a-none-eabi, thumbv7em-none-eabihf: the archive
#     builds (this compiles the trap and personality assembly of each architecture) and
#     needs nothing from the host;
#   - aarch64-unknown-linux-gnu: the C harness, linked statically against the archive,
#     passes under qemu-aarch64; the shared library exports only cncrot_* and needs only
#     memory functions.
# Installs the targets (rustup), the cross compiler and qemu-user (apt-get) when missing.
# Part of .ci/long-runs, not of ./test.sh (it downloads toolchain components).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
need=()
command -v aarch64-linux-gnu-gcc >/dev/null || need+=(gcc-aarch64-linux-gnu)
command -v qemu-aarch64 >/dev/null || need+=(qemu-user)
if [ ${#need[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${need[@]}" >/dev/null
fi
bare=(aarch64-unknown-none armv7a-none-eabi thumbv7em-none-eabihf)
linux=aarch64-unknown-linux-gnu
rustup target add "${bare[@]}" "$linux" >/dev/null
failed=0
for t in "${bare[@]}"; do
  cargo build --quiet --profile rt --no-default-features --lib --target "$t" 2>&1 |
    grep -vE "dropping unsupported crate type|^$" || true
  bash c_tests/symbols.sh "target/$t/rt" core || failed=1
done
CARGO_TARGET_AARCH64_UNKNOWN_LINUX_GNU_LINKER=aarch64-linux-gnu-gcc \
  cargo build --quiet --profile rt --no-default-features --lib --target "$linux"
# The archive for Linux on aarch64 carries compiler-runtime members for atomics that name
# getauxval; nothing in cncrot pulls them in (the shared library built from the same code
# needs only memory functions), so only the exports are compared here.
bash c_tests/symbols.sh "target/$linux/rt" exports || failed=1
so_needs=$(aarch64-linux-gnu-nm -D --undefined-only "target/$linux/rt/libcncrot.so" | awk '$1=="U"{print $2}' | tr '\n' ' ')
echo "cross: $linux libcncrot.so needs: $so_needs"
if grep -qvE '^(memcpy|memmove|memset|memcmp|bcmp) ?$' <<<"$(tr ' ' '\n' <<<"$so_needs" | grep -v '^$')"; then
  echo "cross: $linux libcncrot.so needs more than memory functions"
  failed=1
fi
mkdir -p c_tests/build/cross
for test in test_core test_cycle600; do
  aarch64-linux-gnu-gcc -std=c99 -O1 -Wall -Wextra -Werror -pedantic -Iinclude -Ic_tests \
    "c_tests/$test.c" "target/$linux/rt/libcncrot.a" -lm -static -o "c_tests/build/cross/$test"
  echo "== $test ($linux, qemu)"
  qemu-aarch64 "c_tests/build/cross/$test" || failed=1
done
exit $failed
