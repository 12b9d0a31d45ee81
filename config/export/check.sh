#!/usr/bin/env bash
# Compile and run a C and a Fortran program against an installed hillstab (argument: prefix),
# using only its pkg-config file.
set -euo pipefail
prefix=$1
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cc $(pkg-config --cflags hillstab) "$here/trace.c" -o "$work/trace_c" \
   $(pkg-config --libs --static hillstab)
"$work/trace_c"
gfortran $(pkg-config --cflags hillstab) "$here/trace.f90" -o "$work/trace_f" \
   $(pkg-config --libs --static hillstab)
"$work/trace_f"
echo "check-install: the installed library links from C and Fortran"
if command -v cmake >/dev/null 2>&1; then
   cmake -S "$here" -B "$work/cmake" -DCMAKE_PREFIX_PATH="$prefix" >/dev/null
   cmake --build "$work/cmake" >/dev/null
   "$work/cmake/trace_c" && "$work/cmake/trace_f"
   echo "check-install: find_package(hillstab) works from CMake"
fi
