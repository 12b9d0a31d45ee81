#!/usr/bin/env bash
# Print the Fortran sources under src/ (every folder) in compilation order (modules before their users),
# for builds without fpm (make lib). Uses the `module`/`use` statements and tsort.
set -euo pipefail
cd "$(dirname "$0")/.."
declare -A file_of
sources=$(find src -name "*.f90" | LC_ALL=C sort)
for f in $sources; do
   m=$(grep -iE '^\s*module\s+[a-z_0-9]+\s*$' "$f" | head -1 | awk '{print tolower($2)}' || true)
   [ -n "$m" ] && file_of[$m]=$f
done
{
   for f in $sources; do
      echo "$f $f"
      for u in $(grep -iE '^\s*use\s+[a-z_0-9]+' "$f" | grep -viE 'intrinsic' | sed -E 's/^\s*use\s+([A-Za-z_0-9]+).*/\1/' | tr 'A-Z' 'a-z' | sort -u); do
         dep=${file_of[$u]:-}
         [ -n "$dep" ] && [ "$dep" != "$f" ] && echo "$dep $f"
      done
   done
} | tsort
