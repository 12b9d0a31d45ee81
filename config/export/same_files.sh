#!/usr/bin/env bash
# The make and CMake install routes install the same files (arguments: the two prefixes).
# Only CMake's exported-target files (hillstab-targets*.cmake), which the make route's
# hand-written hillstab-config.cmake replaces, may differ.
set -euo pipefail
list() { (cd "$1" && find . \( -type f -o -type l \) | grep -v '/hillstab-targets.*\.cmake$' | sort); }
if ! diff <(list "$1") <(list "$2"); then
   echo "check-install: FAILED: the make install (<) and the CMake install (>) differ" >&2
   exit 1
fi
echo "check-install: make and CMake install the same $(list "$1" | wc -l) files"
