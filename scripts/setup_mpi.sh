#!/usr/bin/env bash
# Provide what the MPI build needs (make mpi, make test-mpi): the compiler and libraries,
# CMake and Open MPI with the Fortran mpi_f08 module, through scripts/setup.sh (which
# installs only what is missing, or says what is missing when it cannot install).
set -euo pipefail
exec bash "$(dirname "$0")/setup.sh" compiler mpi
