#!/usr/bin/env bash
# The two gfortran 12 artefacts that the sanitizer build of the test suite met (issue 19),
# each as a minimal program; both must report (UBSan: signed integer overflow in
# absent_optional.f90; LeakSanitizer: two leaks from new_item in constructor_leak.f90).
# hillstab avoids both patterns (src/hillstab/integrate/rk.f90, testing/src/hillstab_testing.f90,
# test/main.f90); when a newer gfortran no longer reports them, the workarounds may go.
# usage: bash scripts/sanitize/reproduce.sh   (x86-64, gfortran and gcc with libasan/libubsan)
set -u
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
FC="${FC:-gfortran}"
CC="${CC:-gcc}"
status=0
"$FC" -g -O0 -fsanitize=undefined -c "$here/absent_optional.f90" -o absent_optional.o &&
   "$CC" -O1 -c "$here/dirty_registers.c" -o dirty_registers.o &&
   "$FC" -fsanitize=undefined absent_optional.o dirty_registers.o -o absent_optional || exit 2
if ./absent_optional 2>&1 | tee absent.log | grep -q "runtime error: signed integer overflow"; then
   echo "reproduced: UBSan's overflow in the descriptor of an absent optional array passed on"
else
   echo "not reproduced: absent optional arrays passed on (this compiler may not need the workaround)"
   status=1
fi
"$FC" -g -fsanitize=address "$here/constructor_leak.f90" -o constructor_leak || exit 2
if ASAN_OPTIONS=detect_leaks=1 ./constructor_leak 2>&1 | grep -q "LeakSanitizer: detected memory leaks"; then
   echo "reproduced: LeakSanitizer's leaks of function results in an array constructor"
else
   echo "not reproduced: array constructor of function results with allocatable components"
   status=1
fi
exit "$status"
