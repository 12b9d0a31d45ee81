#!/usr/bin/env bash
# Every linked ELF file under the build tree (the fpm programs, test programs, examples and
# shared libraries of `make test` / `make test-debug`, the legacy build's libraries) must
# carry a non-executable stack (GNU_STACK RW): a trampoline built by gfortran for an
# internal procedure passed as an argument would make it RWE, and hardened systems refuse
# to load such files. Silent on success; names every offending file and exits 1 otherwise.
# Usage: scripts/check_stack.sh [DIR]   (default: build)
set -euo pipefail
dir=${1:-build}
command -v readelf >/dev/null 2>&1 || { echo "check_stack: readelf not found (Debian package binutils)" >&2; exit 1; }
[ -d "$dir" ] || { echo "check_stack: $dir: no build tree (run make test first)" >&2; exit 1; }
checked=0
bad=0
while IFS= read -r -d '' f; do
   # linked ELF files only: executables and shared objects (objects have no program headers)
   [ "$(head -c 4 "$f" | od -An -tx1 | tr -d ' \n')" = 7f454c46 ] || continue
   type=$(readelf -hW "$f" 2>/dev/null | awk '$1 == "Type:" {print $2}')
   [ "$type" = EXEC ] || [ "$type" = DYN ] || continue
   checked=$((checked + 1))
   flags=$(readelf -lW "$f" | awk '$1 == "GNU_STACK" {print $7}')
   if [ "$flags" != RW ]; then
      echo "check_stack: $f has an executable stack (GNU_STACK ${flags:-missing})" >&2
      bad=$((bad + 1))
   fi
done < <(find "$dir" -type f \( -perm -u+x -o -name '*.so*' \) -not -name '*.o' -print0)
if [ "$checked" = 0 ]; then
   echo "check_stack: no linked ELF file under $dir" >&2
   exit 1
fi
if [ "$bad" != 0 ]; then
   echo "check_stack: $bad of $checked linked files under $dir have an executable stack" >&2
   exit 1
fi
