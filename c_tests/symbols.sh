#!/usr/bin/env bash
# Checks the symbols of a built library pair (libcncrot.a and libcncrot.so in DIR; the
# archive alone for targets without shared libraries).
#   c_tests/symbols.sh DIR exports   the .so exports exactly the functions of include/cncrot.h
#   c_tests/symbols.sh DIR core      also: the .a and .so need nothing from the host but the
#                                    memory functions below: no allocator, no unwinder, no
#                                    panic machinery, no I/O, no threads, no libm
# readelf is used for the archive because binutils' nm gives up on members that carry LLVM
# bitcode (".llvmbc") and prints "no symbols"; readelf reads the ELF symbol table as the
# linker does. Exit status 1 and a list of the offending symbols on failure.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$1
mode=$2
so=$dir/libcncrot.so
a=$dir/libcncrot.a
allowed_host='^(memcpy|memmove|memset|memcmp|bcmp)$'
forbidden='malloc|calloc|realloc|free|__rust_alloc|__rust_dealloc|__rust_realloc|_Unwind_|rust_eh_personality|rust_begin_unwind|abort|pthread|printf|write|syscall'
bad=0

declared=$(grep -oE '\bcncrot_[a-z0-9_]+\(' "$root/include/cncrot.h" | tr -d '(' | sort -u)
# Targets without shared libraries (bare metal: aarch64-unknown-none) have only the archive.
has_so=0
[ -f "$so" ] && has_so=1
if [ $has_so -eq 1 ]; then
  exported=$(nm -D --defined-only "$so" | awk '{print $3}' | sort -u)
else
  exported=$(readelf -sW "$a" 2>/dev/null | awk '$7!="UND" && $5=="GLOBAL" && $6=="DEFAULT" && $8 ~ /^cncrot_/ {print $8}' | sort -u)
fi
if [ "$declared" != "$exported" ]; then
  echo "symbols: $dir exports differ from the functions of include/cncrot.h:"
  diff <(echo "$declared") <(echo "$exported") | sed 's/^/  /' || true
  bad=1
fi

if [ "$mode" = core ]; then
  # Strong undefined symbols of the shared library (weak ones belong to the C runtime's
  # start files and may stay unresolved).
  so_needs=""
  [ $has_so -eq 1 ] && so_needs=$(nm -D --undefined-only "$so" | awk '$1=="U"{print $2}' | sort -u)
  # An archive needs what one member leaves undefined and no member defines.
  members=$(readelf -sW "$a" 2>/dev/null)
  a_undef=$(awk '$7=="UND" && $8!="" {print $8}' <<<"$members" | sort -u)
  a_def=$(awk '$7!="UND" && $7!="Ndx" && ($5=="GLOBAL" || $5=="WEAK") {print $8}' <<<"$members" | sort -u)
  a_needs=$(comm -23 <(echo "$a_undef") <(echo "$a_def"))
  for lib in so a; do
    needs_var=${lib}_needs
    needs=${!needs_var}
    extra=$(grep -vE "$allowed_host" <<<"$needs" | grep -v '^$' || true)
    if [ -n "$extra" ]; then
      echo "symbols: libcncrot.$lib needs more than the memory functions from the host:"
      echo "$extra" | sed 's/^/  /'
      bad=1
    fi
    hits=$(grep -E "$forbidden" <<<"$needs" || true)
    if [ -n "$hits" ]; then
      echo "symbols: libcncrot.$lib needs forbidden symbols:"
      echo "$hits" | sed 's/^/  /'
      bad=1
    fi
  done
  [ $has_so -eq 1 ] && echo "symbols: libcncrot.so needs from the host: $(echo $so_needs)"
  echo "symbols: libcncrot.a needs from the host: $(echo $a_needs)"
fi
[ $bad -eq 0 ] && echo "symbols ($mode): $dir ok"
exit $bad
