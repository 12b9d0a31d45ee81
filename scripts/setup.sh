#!/usr/bin/env bash
# Install what hillstab needs on a Debian machine, skipping what is present:
# gfortran, LAPACK/BLAS, GSL and gnuplot through apt-get; fpm through pip.
set -euo pipefail

missing=()
command -v gfortran >/dev/null 2>&1 || missing+=(gfortran)
command -v gnuplot >/dev/null 2>&1 || missing+=(gnuplot-nox)
[ -e /usr/include/gsl/gsl_sf_mathieu.h ] || missing+=(libgsl-dev)
ls /usr/lib/*/liblapack.so >/dev/null 2>&1 || missing+=(liblapack-dev)
ls /usr/lib/*/libblas.so >/dev/null 2>&1 || missing+=(libblas-dev)
command -v make >/dev/null 2>&1 || missing+=(make)

if [ ${#missing[@]} -gt 0 ]; then
   echo "setup: installing ${missing[*]}" >&2
   SUDO=""
   if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
   export DEBIAN_FRONTEND=noninteractive
   $SUDO apt-get update -qq
   $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

if ! command -v fpm >/dev/null 2>&1; then
   echo "setup: installing fpm" >&2
   python3 -m pip install --quiet fpm
   hash -r
fi
command -v fpm >/dev/null 2>&1 || { echo "setup: fpm not on PATH after install" >&2; exit 1; }
