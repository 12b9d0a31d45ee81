#!/usr/bin/env bash
# Run every scene of data/scenes and compare what it writes with the stored checksums
# of data/reference/scene_checksums.txt: the data lines (every line not starting with
# '#') must be byte-identical; headers are compared too (without the line naming the
# scene file), and a header that differs is listed, since a change may mean to alter
# it. `make check-scenes` runs this; a refactor runs it before its first commit and
# after its last.
#
#   bash scripts/check_scenes.sh            compare (exit 1 when a data line differs)
#   bash scripts/check_scenes.sh --update   store the checksums of this build
#   bash scripts/check_scenes.sh --strict   also exit 1 when a header differs
#   HILLSTAB_SCENES_KEEP=DIR bash scripts/check_scenes.sh   also copy the files written into DIR
#   (for scripts/compare_scenes.py, which says by how much two such sets differ)
#
# The build is fpm's release profile without -march=native (HILLSTAB_RELEASE_FLAGS
# empty), so the checksums depend on the compiler and libraries, not on the CPU;
# OMP_NUM_THREADS=2 (a chart with few rows splits them over the threads). Scenes run
# from a scratch directory holding a link to data/, so nothing in out/ is touched.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
mode=compare
case "${1:-}" in
   --update) mode=update ;;
   --strict) mode=strict ;;
   "") ;;
   *) echo "usage: check_scenes.sh [--update | --strict]" >&2; exit 2 ;;
esac
stored=data/reference/scene_checksums.txt

export OMP_NUM_THREADS=2
export HILLSTAB_RELEASE_FLAGS=""
mkdir -p build
bash scripts/fpm.sh build --profile release --flag "" >"$root/build/check_scenes.log" 2>&1 \
   || { cat "$root/build/check_scenes.log" >&2; echo "check_scenes: build failed" >&2; exit 1; }
hillstab=$(bash scripts/fpm.sh run --profile release --flag "" --runner echo hillstab 2>/dev/null | tail -1)
[ -x "$hillstab" ] || { echo "check_scenes: hillstab not built" >&2; exit 1; }
case "$hillstab" in /*) ;; *) hillstab=$root/$hillstab ;; esac

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ln -s "$root/data" "$work/data"
mkdir -p "$work/out"
start=$(date +%s)
for scene in data/scenes/*.nml; do
   (cd "$work" && "$hillstab" --quiet "$scene") || {
      status=$?
      # exit 3: written, with failed points (still compared)
      [ "$status" -eq 3 ] || { echo "check_scenes: $scene: exit status $status" >&2; exit 1; }
   }
done
seconds=$(( $(date +%s) - start ))
if [ -n "${HILLSTAB_SCENES_KEEP:-}" ]; then
   mkdir -p "$HILLSTAB_SCENES_KEEP"
   cp "$work"/out/* "$HILLSTAB_SCENES_KEEP"/
fi

# every data line is numbers, so that numpy.loadtxt(comments='#') and awk read the files as
# they are (the column names are on the '# columns:' line only)
for file in "$work"/out/*; do
   if grep -av '^#' "$file" | grep -aqvE '^[[:space:]]*$|^[-+0-9.eE[:space:]]+$'; then
      echo "check_scenes: $(basename "$file"): a data line that is not numbers" >&2
      exit 1
   fi
done

current=$work/checksums.txt
(
   cd "$work/out"
   for file in $(ls | LC_ALL=C sort); do
      data=$(grep -av '^#' "$file" | sha256sum | cut -c1-64)
      header=$(grep -a '^#' "$file" | grep -av '^# scene file: ' | sha256sum | cut -c1-64)
      echo "$file $data $header"
   done
) >"$current"

if [ "$mode" = update ]; then
   {
      echo "# data/reference/scene_checksums.txt: sha256 of the data lines and of the header (without"
      echo "# its 'scene file:' line) of every file the scenes of data/scenes write; made by"
      echo "# scripts/check_scenes.sh --update ($(gfortran -dumpfullversion 2>/dev/null | sed 's/^/gfortran /'), fpm release profile, no -march=native)"
      cat "$current"
   } >"$stored"
   echo "check_scenes: stored $(wc -l <"$current") files' checksums in $stored (${seconds} s)"
   exit 0
fi

[ -f "$stored" ] || { echo "check_scenes: $stored missing (run with --update)" >&2; exit 1; }
data_diff=0
header_diff=0
missing=0
while read -r file data header; do
   case "$file" in '#'*) continue ;; esac
   line=$(grep -E "^$file " "$current" || true)
   if [ -z "$line" ]; then
      echo "  MISSING $file (not written)"
      missing=$((missing + 1))
      continue
   fi
   set -- $line
   if [ "$2" != "$data" ]; then
      echo "  DATA    $file: data lines differ"
      data_diff=$((data_diff + 1))
   fi
   if [ "$3" != "$header" ]; then
      echo "  HEADER  $file: header differs"
      header_diff=$((header_diff + 1))
   fi
done <"$stored"
while read -r file _; do
   grep -qE "^$file " "$stored" || echo "  NEW     $file (no stored checksum)"
done <"$current"
n=$(grep -vc '^#' "$stored")
echo "check_scenes: $n files: $data_diff with other data lines, $missing missing, $header_diff with another header (${seconds} s)"
if [ "$data_diff" -gt 0 ] || [ "$missing" -gt 0 ]; then exit 1; fi
if [ "$mode" = strict ] && [ "$header_diff" -gt 0 ]; then exit 1; fi
exit 0
