#!/usr/bin/env bash
# Builds the C library and installs it the way C libraries are installed (the layout
# cargo-c gives Rust C libraries):
#   PREFIX/include/cncrot/cncrot.h
#   LIBDIR/libcncrot.a, LIBDIR/libcncrot.so.X.Y.Z with its soname link libcncrot.so.ABI and
#          the development link libcncrot.so (ABI: 0.Y for 0.Y.Z, X for X.Y.Z)
#   LIBDIR/pkgconfig/cncrot.pc (shared) and cncrot-static.pc (static)
#   LIBDIR/cmake/cncrot/cncrotConfig.cmake (+ ConfigVersion): cncrot::cncrot, cncrot::cncrot_static
#   PREFIX/share/cncrot/matlab (the MEX sources; build_mex there finds this installation)
#   PREFIX/share/doc/cncrot (README and docs)
#   PREFIX/bin/cncrot (the command-line tool; not with --realtime or --target)
#
# Usage: ./install.sh [--prefix DIR] [--libdir DIR] [--destdir DIR] [--realtime] [--target T]
#   --prefix   where the library is to live (default /usr/local)
#   --libdir   default PREFIX/lib
#   --destdir  stage the files under DIR (for packagers); the paths written into the
#              pkg-config files are still PREFIX's
#   --realtime install the real-time build (core only, panic = abort, no allocator)
#   --target   build for Windows on this machine (docs/windows.md):
#              x86_64-pc-windows-gnu: PREFIX/bin/cncrot.dll, PREFIX/lib/libcncrot.dll.a,
#                libcncrot.a and cncrot.def (no pkg-config or CMake files);
#              x86_64-pc-windows-msvc (with --realtime): PREFIX/lib/cncrot.lib
# Needs cargo, and objdump (binutils) to read the soname; for Windows MinGW-w64.
set -euo pipefail
root=$(cd "$(dirname "$0")" && pwd)
cd "$root"

prefix=/usr/local
libdir=
destdir=
realtime=0
target=
while [ $# -gt 0 ]; do
  case "$1" in
    --prefix) prefix=$2; shift 2 ;;
    --prefix=*) prefix=${1#*=}; shift ;;
    --libdir) libdir=$2; shift 2 ;;
    --libdir=*) libdir=${1#*=}; shift ;;
    --destdir) destdir=$2; shift 2 ;;
    --destdir=*) destdir=${1#*=}; shift ;;
    --realtime) realtime=1; shift ;;
    --target) target=$2; shift 2 ;;
    --target=*) target=${1#*=}; shift ;;
    -h|--help) sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "install.sh: unknown option $1 (see --help)" >&2; exit 2 ;;
  esac
done
case "$prefix" in /*) ;; *) prefix=$(pwd)/$prefix ;; esac
libdir=${libdir:-$prefix/lib}
case "$libdir" in /*) ;; *) libdir=$(pwd)/$libdir ;; esac
includedir=$prefix/include
datadir=$prefix/share

version=$(sed -n 's/^version = "\(.*\)"/\1/p' Cargo.toml | head -n 1)
major=${version%%.*}
rest=${version#*.}
minor=${rest%%.*}
if [ "$major" = 0 ]; then abi=0.$minor; else abi=$major; fi

if [ -n "$target" ]; then
  case "$target" in
    x86_64-pc-windows-gnu) ;;
    x86_64-pc-windows-msvc)
      [ $realtime -eq 1 ] || { echo "install.sh: for MSVC only the real-time static library can be built here (--realtime): the DLL needs link.exe" >&2; exit 2; } ;;
    *) echo "install.sh: --target $target: x86_64-pc-windows-gnu or x86_64-pc-windows-msvc" >&2; exit 2 ;;
  esac
  rustup target list --installed | grep -qx "$target" || rustup target add "$target"
  if [ $realtime -eq 1 ]; then profile=rt; flags=(--profile rt --no-default-features); else profile=release; flags=(--release); fi
  echo "install.sh: building cncrot $version ($profile) for $target"
  built=${CARGO_TARGET_DIR:-target}/$target/$profile
  install -d "$destdir$includedir/cncrot" "$destdir$libdir" "$destdir$datadir/cncrot/matlab/src" \
    "$destdir$datadir/cncrot/matlab/tests" "$destdir$datadir/doc/cncrot/docs"
  if [ "$target" = x86_64-pc-windows-msvc ]; then
    cargo rustc "${flags[@]}" --lib --target "$target" --crate-type staticlib --quiet
    install -m 644 "$built/cncrot.lib" "$destdir$libdir/cncrot.lib"
  else
    cargo build "${flags[@]}" --lib --target "$target" --quiet
    install -d "$destdir$prefix/bin"
    install -m 755 "$built/cncrot.dll" "$destdir$prefix/bin/cncrot.dll"
    install -m 644 "$built/libcncrot.dll.a" "$built/libcncrot.a" "$destdir$libdir/"
    install -m 644 include/cncrot.def "$destdir$libdir/cncrot.def"
  fi
  install -m 644 include/cncrot.h "$destdir$includedir/cncrot/cncrot.h"
  install -m 644 matlab/*.m "$destdir$datadir/cncrot/matlab/"
  install -m 644 matlab/src/*.c matlab/src/*.h "$destdir$datadir/cncrot/matlab/src/"
  install -m 644 matlab/tests/*.m "$destdir$datadir/cncrot/matlab/tests/"
  install -m 644 README.md "$destdir$datadir/doc/cncrot/"
  install -m 644 docs/*.md "$destdir$datadir/doc/cncrot/docs/"
  echo "install.sh: cncrot $version for $target installed under $destdir$prefix"
  exit 0
fi

# One build gives the libraries and what the static one needs from the system.
if [ $realtime -eq 1 ]; then
  profile=rt
  flags=(--profile rt --no-default-features)
else
  profile=release
  flags=(--release)
fi
echo "install.sh: building cncrot $version ($profile)"
if ! out=$(cargo rustc "${flags[@]}" --lib --quiet -- --print native-static-libs 2>&1); then
  echo "$out" >&2
  exit 1
fi
native=$(sed -n 's/.*native-static-libs: //p' <<<"$out" | tail -n 1)
if [ -z "$native" ]; then
  # The library was already built with these flags, so rustc did not run again: the
  # real-time build needs nothing; the std build needs libm, threads and the loader.
  if [ $realtime -eq 1 ]; then native="-lc"; else native="-lgcc_s -lutil -lrt -lpthread -lm -ldl -lc"; fi
fi
built=${CARGO_TARGET_DIR:-target}/$profile
soname=$(objdump -p "$built/libcncrot.so" | awk '$1 == "SONAME" {print $2}')
if [ "$soname" != "libcncrot.so.$abi" ]; then
  echo "install.sh: $built/libcncrot.so has soname '$soname', expected libcncrot.so.$abi" >&2
  exit 1
fi

stage() { echo "$destdir$1"; }
install -d "$(stage "$includedir/cncrot")" "$(stage "$libdir/pkgconfig")" \
  "$(stage "$libdir/cmake/cncrot")" "$(stage "$datadir/cncrot/matlab/src")" \
  "$(stage "$datadir/cncrot/matlab/tests")" "$(stage "$datadir/doc/cncrot/docs")"
install -m 644 include/cncrot.h "$(stage "$includedir/cncrot")/cncrot.h"
install -m 644 "$built/libcncrot.a" "$(stage "$libdir")/libcncrot.a"
install -m 755 "$built/libcncrot.so" "$(stage "$libdir")/libcncrot.so.$version"
ln -sf "libcncrot.so.$version" "$(stage "$libdir")/libcncrot.so.$abi"
ln -sf "libcncrot.so.$abi" "$(stage "$libdir")/libcncrot.so"

cat > "$(stage "$libdir/pkgconfig")/cncrot.pc" <<EOF
prefix=$prefix
libdir=$libdir
includedir=\${prefix}/include

Name: cncrot
Description: Coordinate rotations for CNC controllers (C ABI)
Version: $version
Libs: -L\${libdir} -lcncrot
Libs.private: $native
Cflags: -I\${includedir}/cncrot
EOF
cat > "$(stage "$libdir/pkgconfig")/cncrot-static.pc" <<EOF
prefix=$prefix
libdir=$libdir
includedir=\${prefix}/include

Name: cncrot-static
Description: Coordinate rotations for CNC controllers (C ABI), linked statically
Version: $version
Libs: \${libdir}/libcncrot.a $native
Cflags: -I\${includedir}/cncrot
EOF

# The CMake package finds its files relative to itself, so a staged or moved tree works.
rel_include=$(realpath -m --relative-to="$libdir/cmake/cncrot" "$includedir/cncrot")
cmake_native=$(echo "$native" | tr -s ' ' ';')
cat > "$(stage "$libdir/cmake/cncrot")/cncrotConfig.cmake" <<EOF
# cncrot $version: imported targets cncrot::cncrot (shared) and cncrot::cncrot_static.
get_filename_component(_cncrot_libdir "\${CMAKE_CURRENT_LIST_DIR}/../.." ABSOLUTE)
get_filename_component(_cncrot_include "\${CMAKE_CURRENT_LIST_DIR}/$rel_include" ABSOLUTE)
if(NOT TARGET cncrot::cncrot)
  add_library(cncrot::cncrot SHARED IMPORTED)
  set_target_properties(cncrot::cncrot PROPERTIES
    IMPORTED_LOCATION "\${_cncrot_libdir}/libcncrot.so.$version"
    IMPORTED_SONAME "libcncrot.so.$abi"
    INTERFACE_INCLUDE_DIRECTORIES "\${_cncrot_include}")
  add_library(cncrot::cncrot_static STATIC IMPORTED)
  set_target_properties(cncrot::cncrot_static PROPERTIES
    IMPORTED_LOCATION "\${_cncrot_libdir}/libcncrot.a"
    INTERFACE_INCLUDE_DIRECTORIES "\${_cncrot_include}"
    INTERFACE_LINK_LIBRARIES "$cmake_native")
endif()
unset(_cncrot_libdir)
unset(_cncrot_include)
EOF
cat > "$(stage "$libdir/cmake/cncrot")/cncrotConfigVersion.cmake" <<EOF
# cncrot $version is compatible with a request for any version up to it with the same ABI
# ($abi: 0.Y for 0.Y.Z releases, X for X.Y.Z), as the soname says.
set(PACKAGE_VERSION "$version")
set(PACKAGE_VERSION_COMPATIBLE FALSE)
if(NOT PACKAGE_FIND_VERSION)
  set(PACKAGE_VERSION_COMPATIBLE TRUE)
elseif(NOT PACKAGE_FIND_VERSION VERSION_GREATER PACKAGE_VERSION)
  if("$major" STREQUAL "0")
    if(PACKAGE_FIND_VERSION_MAJOR EQUAL 0 AND PACKAGE_FIND_VERSION_MINOR EQUAL $minor)
      set(PACKAGE_VERSION_COMPATIBLE TRUE)
    endif()
  elseif(PACKAGE_FIND_VERSION_MAJOR EQUAL $major)
    set(PACKAGE_VERSION_COMPATIBLE TRUE)
  endif()
endif()
if(PACKAGE_FIND_VERSION STREQUAL PACKAGE_VERSION)
  set(PACKAGE_VERSION_EXACT TRUE)
endif()
if(NOT CMAKE_SIZEOF_VOID_P STREQUAL "" AND NOT CMAKE_SIZEOF_VOID_P EQUAL $(( $(getconf LONG_BIT) / 8 )))
  set(PACKAGE_VERSION_UNSUITABLE TRUE)
endif()
EOF

install -m 644 matlab/*.m "$(stage "$datadir/cncrot/matlab")/"
install -m 644 matlab/src/*.c matlab/src/*.h "$(stage "$datadir/cncrot/matlab/src")/"
install -m 644 matlab/tests/*.m "$(stage "$datadir/cncrot/matlab/tests")/"
install -m 644 README.md "$(stage "$datadir/doc/cncrot")/"
install -m 644 docs/*.md "$(stage "$datadir/doc/cncrot/docs")/"
# The command-line tool, for people who do not program (its own release build).
if [ $realtime -eq 0 ]; then
  cargo build --release --quiet -p cncrot-cli
  install -d "$(stage "$prefix/bin")"
  install -m 755 "${CARGO_TARGET_DIR:-target}/release/cncrot" "$(stage "$prefix/bin")/cncrot"
fi
echo "install.sh: cncrot $version installed under $destdir$prefix (soname libcncrot.so.$abi)"
