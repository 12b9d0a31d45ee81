#!/usr/bin/env bash
# Print the extra compiler flags of hillstab's release builds: -march=native when the
# compiler accepts it (method auto propagates many points at once in vectorised
# loops; wide vector units roughly double its speed), else nothing.
# HILLSTAB_RELEASE_FLAGS overrides (e.g. HILLSTAB_RELEASE_FLAGS= for a generic build).
if [ -n "${HILLSTAB_RELEASE_FLAGS+set}" ]; then
   echo "$HILLSTAB_RELEASE_FLAGS"
elif echo "end" | gfortran -march=native -x f95 -fsyntax-only - >/dev/null 2>&1; then
   echo "-march=native"
fi
