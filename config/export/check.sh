#!/usr/bin/env bash
# Consumers of an installed hillstab (argument 1: the install prefix; 2: the route that
# installed it, for messages). Checks that the prefix holds every installed file, then
# builds and runs the examples of example/ against it:
#   pkg-config: C (shared library, `--libs` without --static, and static), modern Fortran
#               (also config/export/own_names.f90: its own pi and wp beside `use hillstab`),
#               fixed-form FORTRAN 77 compiled with -std=legacy and no USE (implicit interfaces);
#   CMake find_package(hillstab): C, Fortran and FORTRAN 77, shared and static targets;
#   the installed program: --version and --help.
# Also checks that linking prints no executable-stack warning and that the installed
# libraries and program and the consumers have a non-executable stack (GNU_STACK RW, by
# scripts/check_stack.sh); HILLSTAB_STACK_CHECK=report only reports an executable stack
# instead of failing.
set -euo pipefail
prefix=$(cd "$1" && pwd)
route=${2:-install}
stack_check=${HILLSTAB_STACK_CHECK:-fail}
here=$(cd "$(dirname "$0")" && pwd)
examples=$(cd "$here/../../example" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
say() { echo "check-install ($route): $*"; }
die() { echo "check-install ($route): FAILED: $*" >&2; exit 1; }

pc=$(find "$prefix" -name hillstab.pc -path '*/pkgconfig/*' | head -1)
[ -n "$pc" ] || die "no hillstab.pc under $prefix"
libdir=$(cd "$(dirname "$pc")/.." && pwd)
for f in "$libdir/libhillstab.a" "$libdir/libhillstab.so" "$prefix/include/hillstab.h" \
         "$libdir/cmake/hillstab/hillstab-config.cmake" "$prefix/bin/hillstab"; do
   [ -e "$f" ] || die "missing $f"
done
ls "$prefix"/include/hillstab/*/hillstab.mod "$prefix"/include/hillstab/*/hillstab_interop_legacy.mod >/dev/null \
   || die "missing .mod files under $prefix/include/hillstab/"
say "installed: static and shared library, .mod files, hillstab.h, hillstab.pc, CMake config, bin/hillstab"

needed=$(readelf -dW "$libdir/libhillstab.so" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p' | tr '\n' ' ')
for dep in libgsl libgfortran libgomp; do
   case " $needed" in *" $dep"*) ;; *) die "libhillstab.so does not record $dep (NEEDED: $needed)";; esac
done

export PKG_CONFIG_PATH="$libdir/pkgconfig"
export LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
cflags=$(pkg-config --cflags hillstab)
libs=$(pkg-config --libs hillstab)
# with both libraries in libdir, -lhillstab picks the shared one: name the archive
static_libs="$(pkg-config --variable=libdir hillstab)/libhillstab.a $(pkg-config --libs --static hillstab | sed 's/-L[^ ]*//; s/-lhillstab//')"
# build: compiler, source, output, link flags...; fails on an executable-stack warning
build() {
   local compiler=$1 source=$2 out=$3
   shift 3
   "$compiler" $cflags "$source" -o "$work/$out" "$@" 2> "$work/$out.log" || { cat "$work/$out.log" >&2; die "cannot build $out"; }
   if grep -q "executable stack" "$work/$out.log"; then
      [ "$stack_check" = fail ] && { cat "$work/$out.log" >&2; die "$out: linking warns about an executable stack"; }
      say "REPORT: linking $out warns about an executable stack"
   fi
}
build cc "$examples/c/trace.c" trace_c $libs
build cc "$examples/c/trace.c" trace_c_static $static_libs
build gfortran "$examples/fortran/trace.f90" trace_f $libs
# a program with its own pi, wp, error_t and determinant beside `use hillstab`
build gfortran "$here/own_names.f90" own_names $libs
build gfortran "$examples/f77/trace.f" trace_f77 -std=legacy $libs
build gfortran "$examples/f77/trace.f" trace_f77_static -std=legacy $static_libs
for p in trace_c trace_c_static trace_f own_names trace_f77 trace_f77_static; do
   "$work/$p" > "$work/$p.out" || { cat "$work/$p.out"; die "$p failed"; }
done
for p in trace_c trace_f trace_f77; do
   readelf -dW "$work/$p" | grep -q 'NEEDED.*libhillstab\.so' || die "$p does not use the shared library"
done
for p in trace_c_static trace_f77_static; do
   readelf -dW "$work/$p" | grep -q 'NEEDED.*libhillstab' && die "$p depends on the shared library"
done
cat "$work/trace_c.out" "$work/trace_f.out" "$work/own_names.out" "$work/trace_f77.out"
say "pkg-config: C, Fortran (also with its own pi and wp beside use hillstab) and fixed-form FORTRAN 77 link (shared: '$libs'; static too) and run"

if command -v cmake >/dev/null 2>&1; then
   cmake -S "$here" -B "$work/cmake" -DCMAKE_PREFIX_PATH="$prefix" >"$work/cmake.log" 2>&1 \
      && cmake --build "$work/cmake" >>"$work/cmake.log" 2>&1 || { cat "$work/cmake.log" >&2; die "CMake consumer"; }
   for p in trace_c trace_c_static trace_f own_names trace_f77; do
      "$work/cmake/$p" >/dev/null || die "CMake-built $p failed"
   done
   say "CMake find_package(hillstab): C, Fortran, FORTRAN 77 (shared and static targets) link and run"
else
   say "cmake not found: find_package not checked"
fi

"$prefix/bin/hillstab" --version | grep -q "^hillstab " || die "bin/hillstab --version"
"$prefix/bin/hillstab" --help >/dev/null || die "bin/hillstab --help"
tasks=$("$prefix/bin/hillstab" --help | sed -n 's/^Tasks: //p' | tr -d ',')
[ -n "$tasks" ] || die "bin/hillstab --help lists no tasks"
echo "3.7 2.47" > "$work/points.dat"
# every template is a scene the program accepts and runs; a long task (a Lyapunov map) is
# stopped after 10 s, by which time bad input would long have been refused (exit 2)
long=""
for task in $tasks; do
   "$prefix/bin/hillstab" --template "$task" > "$work/template_$task.nml" || die "hillstab --template $task"
   status=0
   (cd "$work" && timeout 10 "$prefix/bin/hillstab" --quiet "template_$task.nml") || status=$?
   if [ "$status" = 124 ]; then
      long="$long $task"
   elif [ "$status" != 0 ]; then
      die "the template of task $task does not run (exit status $status)"
   elif ! ls "$work"/template_"$task"_*.dat >/dev/null 2>&1; then
      die "the template of task $task wrote no file"
   fi
done
say "bin/hillstab runs the template of every task ($tasks)${long:+; still running after 10 s, stopped:$long}"

# every linked file installed (libraries, program) and every consumer built above
for dir in "$prefix" "$work"; do
   if ! bash "$here/../../scripts/check_stack.sh" "$dir"; then
      [ "$stack_check" = fail ] && die "executable stack under $dir (above)"
      say "REPORT: executable stack under $dir (above); HILLSTAB_STACK_CHECK=report, not failing"
   fi
done
say "installed library and program, and the consumers: non-executable stack (GNU_STACK RW)"
