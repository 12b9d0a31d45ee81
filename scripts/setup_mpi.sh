#!/usr/bin/env bash
# Install what the MPI build needs on a Debian machine, skipping what is present:
# Open MPI (compiler wrappers with the Fortran mpi_f08 module, mpirun), with what
# scripts/setup.sh installs (CMake among it), which does the installing.
# Not part of the default build: only `make mpi`, `make test-mpi` and CI call it.
set -euo pipefail
missing=()
command -v mpirun >/dev/null 2>&1 || missing+=(openmpi-bin)
ls /usr/lib/*/fortran/*/openmpi/mpi_f08.mod >/dev/null 2>&1 || missing+=(libopenmpi-dev)
bash "$(dirname "$0")/setup.sh" "${missing[@]}"
