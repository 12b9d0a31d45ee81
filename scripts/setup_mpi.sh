#!/usr/bin/env bash
# Install what the MPI build needs on a Debian machine, skipping what is present:
# Open MPI (compiler wrappers with the Fortran mpi_f08 module, mpirun) and CMake.
# Not part of the default build: only `make mpi`, `make test-mpi` and CI call it.
set -euo pipefail
bash "$(dirname "$0")/setup.sh"
missing=()
command -v mpirun >/dev/null 2>&1 || missing+=(openmpi-bin)
ls /usr/lib/*/fortran/*/openmpi/mpi_f08.mod >/dev/null 2>&1 || missing+=(libopenmpi-dev)
command -v cmake >/dev/null 2>&1 || missing+=(cmake)
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
if [ ${#missing[@]} -gt 0 ]; then
   echo "setup_mpi: installing ${missing[*]}" >&2
   export DEBIAN_FRONTEND=noninteractive
   $SUDO apt-get update -qq
   $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
