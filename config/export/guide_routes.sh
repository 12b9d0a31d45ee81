#!/usr/bin/env bash
# The linking routes of the library guide, run as printed (make check-install). Argument 1:
# a home directory whose opt/hillstab is an installed prefix ($HOME/opt/hillstab of the
# guide); 2: the route that installed it, for messages.
# docs/guide/library.md marks each route: a fenced block after `<!-- route: NAME -->` is a
# shell script, one after `<!-- route-file: PATH -->` a file written before the routes run.
# Each script runs in a scratch directory that holds the repository's example/ (the guide
# runs them from the repository root), with HOME set to argument 1 and PKG_CONFIG_PATH,
# LD_LIBRARY_PATH and CMAKE_PREFIX_PATH unset, so that what the guide sets is what makes
# it work; the examples check their own results and exit non-zero on a mismatch. Then: a
# program of the RPATH route runs with no LD_LIBRARY_PATH, one of the LD_LIBRARY_PATH
# route does not (as the guide says), a static program needs no libhillstab at all.
set -euo pipefail
home=$(cd "$1" && pwd)
route_name=${2:-install}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
guide=$root/docs/guide/library.md
say() { echo "check-install ($route_name): $*"; }
die() { echo "check-install ($route_name): FAILED: $*" >&2; exit 1; }
[ -f "$home/opt/hillstab/lib/pkgconfig/hillstab.pc" ] || die "no prefix $home/opt/hillstab"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ln -s "$root/example" "$work/example"

# the marked blocks of the guide, one file each: routes/NAME.sh, files/PATH
mkdir -p "$work/routes" "$work/files"
awk -v out="$work" '
   /^<!-- route: [A-Za-z0-9_.-]+ -->$/ { target = out "/routes/" $3 ".sh"; order = order $3 " "; next }
   /^<!-- route-file: [A-Za-z0-9_.\/-]+ -->$/ { name = $3; gsub(/\//, "%", name); target = out "/files/" name; files = files $3 " "; next }
   target != "" && !inside && /^```/ { inside = 1; next }
   inside && /^```/ { inside = 0; close(target); target = ""; next }
   inside { print > target }
   END { print order > (out "/order"); print files > (out "/file_list") }
' "$guide"
routes=$(cat "$work/order")
[ -n "$routes" ] || die "no route marked in $guide"
for file in $(cat "$work/file_list"); do
   mkdir -p "$work/$(dirname "$file")"
   cp "$work/files/${file//\//%}" "$work/$file"
done

for name in $routes; do
   if [ "${name#*cmake}" != "$name" ] && ! command -v cmake >/dev/null 2>&1; then
      say "cmake not found: guide route $name not run"
      continue
   fi
   if ! (cd "$work" && env -u PKG_CONFIG_PATH -u LD_LIBRARY_PATH -u CMAKE_PREFIX_PATH HOME="$home" \
            bash -euo pipefail "$work/routes/$name.sh") > "$work/$name.log" 2>&1; then
      cat "$work/$name.log" >&2
      die "the route '$name' of docs/guide/library.md does not run as printed"
   fi
   say "guide route $name: built and ran as printed"
done

# what the guide says of each kind of program, checked on what the routes built
check_runs() {  # program, expectation (runs | fails), why
   local status=0
   (cd "$work" && env -u LD_LIBRARY_PATH "./$1") >/dev/null 2>"$work/$1.err" || status=$?
   case "$2" in
      runs) [ "$status" = 0 ] || { cat "$work/$1.err" >&2; die "$1 does not run without LD_LIBRARY_PATH ($3)"; } ;;
      fails) grep -q "libhillstab" "$work/$1.err" || die "$1 runs without LD_LIBRARY_PATH, which the guide says it needs" ;;
   esac
}
[ -x "$work/trace_c" ] && check_runs trace_c runs "its RPATH names the library's directory"
[ -x "$work/trace_f77" ] && check_runs trace_f77 fails ""
if [ -x "$work/trace_c_static" ]; then
   readelf -dW "$work/trace_c_static" | grep -q 'NEEDED.*libhillstab' && die "trace_c_static needs the shared library"
   check_runs trace_c_static runs "it is linked statically"
fi
say "the guide's routes ($(echo $routes | wc -w)): RPATH and CMake programs run without LD_LIBRARY_PATH, the LD_LIBRARY_PATH one needs it, the static one needs no libhillstab"
