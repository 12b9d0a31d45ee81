#!/usr/bin/env bash
# Install what hillstab needs on a Debian machine, skipping what is present:
# gfortran, LAPACK/BLAS, GSL, gnuplot, pkg-config and CMake through apt-get; fpm through pip.
# Arguments: further Debian packages to install with them (scripts/setup_mpi.sh passes
# the missing Open MPI ones).
set -euo pipefail

missing=("$@")
command -v gfortran >/dev/null 2>&1 || missing+=(gfortran)
command -v gnuplot >/dev/null 2>&1 || missing+=(gnuplot-nox)
[ -e /usr/include/gsl/gsl_sf_mathieu.h ] || missing+=(libgsl-dev)
ls /usr/lib/*/liblapack.so >/dev/null 2>&1 || missing+=(liblapack-dev)
ls /usr/lib/*/libblas.so >/dev/null 2>&1 || missing+=(libblas-dev)
command -v make >/dev/null 2>&1 || missing+=(make)
command -v cc >/dev/null 2>&1 || missing+=(gcc)
command -v pkg-config >/dev/null 2>&1 || missing+=(pkg-config)
command -v cmake >/dev/null 2>&1 || missing+=(cmake)        # make check-install: the CMake route
command -v readelf >/dev/null 2>&1 || missing+=(binutils)   # make check-install: stack flags
command -v valgrind >/dev/null 2>&1 || missing+=(valgrind)  # make check-memory
command -v python3 >/dev/null 2>&1 || missing+=(python3)    # make fuzz

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
if [ ${#missing[@]} -gt 0 ]; then
   echo "setup: installing ${missing[*]}" >&2
   export DEBIAN_FRONTEND=noninteractive
   $SUDO apt-get update -qq
   $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

if ! bash "$(dirname "$0")/fpm.sh" --version >/dev/null 2>&1; then
   echo "setup: installing fpm" >&2
   command -v python3 >/dev/null 2>&1 || { $SUDO apt-get update -qq; $SUDO apt-get install -y -qq python3-pip >/dev/null; }
   python3 -m pip --version >/dev/null 2>&1 || { $SUDO apt-get update -qq; $SUDO apt-get install -y -qq python3-pip >/dev/null; }
   # a Debian system Python refuses plain pip installs (PEP 668): fall back to --user/--break-system-packages
   python3 -m pip install --quiet fpm 2>/dev/null \
      || python3 -m pip install --quiet --user --break-system-packages fpm
   hash -r
fi
bash "$(dirname "$0")/fpm.sh" --version >/dev/null 2>&1 || { echo "setup: fpm not found after install" >&2; exit 1; }
