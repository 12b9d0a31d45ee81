#!/usr/bin/env bash
# Provide what a make target needs, and nothing more. Each argument names a need:
#
#   compiler  gfortran, a C compiler, make, and LAPACK/BLAS and GSL that link
#   fpm       the Fortran package manager (PyPI package `fpm`)
#   plot      gnuplot (make run and the benchmarks draw figures)
#   python    python3 (make test: the documentation check; make fuzz)
#   python-package  python3 with venv and pip (make test-python: pip install . into a fresh
#             virtual environment, which compiles the library with CMake from PyPI when missing)
#   valgrind  valgrind (make check-memory)
#   install   pkg-config, cmake and readelf (make check-install: both install routes, stack flags)
#   mpi       cmake and Open MPI with the Fortran mpi_f08 module (make mpi, make test-mpi)
#   doc       python3 with pip and FORD (make doc); Debian's Bootstrap 5 when available, so
#             that the site is styled without a network
#   pkg:NAME  one more Debian package (scripts/setup_mpi.sh passes its own)
#
# What is present is never installed again: a tool found on PATH or a library that links
# (through LIBRARY_PATH, as `module load` sets it) counts as present, whatever put it there.
# What is missing is installed with apt-get as root (or through sudo); fpm and FORD through
# pip, into the user's site when the system one is not writable. Without root and without
# sudo the script lists what is missing, with the ways to provide it, and exits 1.
# `--check` only lists what is missing (exit 1 if anything is).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)

check_only=0
needs=()
for arg in "$@"; do
   case "$arg" in
      --check) check_only=1 ;;
      *) needs+=("$arg") ;;
   esac
done
[ ${#needs[@]} -gt 0 ] || needs=(compiler fpm plot python)

packages=()    # Debian packages to install
tools=()       # what they provide, for the message
add() { packages+=("$1"); tools+=("$2"); }
have() { command -v "$1" >/dev/null 2>&1; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# a library counts as present when a program links against it
links() {
   have gfortran || return 1
   printf 'end\n' > "$scratch/t.f90"
   gfortran "$scratch/t.f90" "$@" -o "$scratch/t" >/dev/null 2>&1
}
need_fpm=0
need_ford=0
need_bootstrap=0

for need in "${needs[@]}"; do
   case "$need" in
      compiler)
         have gfortran || add gfortran gfortran
         have cc || add gcc "a C compiler (cc)"
         have make || add make make
         if ! links -llapack -lblas; then
            ls /usr/lib/*/liblapack.so >/dev/null 2>&1 || add liblapack-dev "LAPACK (-llapack)"
            ls /usr/lib/*/libblas.so >/dev/null 2>&1 || add libblas-dev "BLAS (-lblas)"
         fi
         if ! links -lgsl -lgslcblas; then
            [ -e /usr/include/gsl/gsl_sf_mathieu.h ] || add libgsl-dev "GSL (-lgsl -lgslcblas)"
         fi ;;
      fpm)
         bash "$here/fpm.sh" --version >/dev/null 2>&1 || need_fpm=1 ;;
      plot) have gnuplot || add gnuplot-nox gnuplot ;;
      python) have python3 || add python3 python3 ;;
      python-package)
         have python3 || add python3 python3
         # Debian's python3 makes virtual environments with pip only with python3-venv
         python3 -c 'import venv, ensurepip' >/dev/null 2>&1 || add python3-venv "python3 -m venv (python3-venv)" ;;
      valgrind) have valgrind || add valgrind valgrind ;;
      install)
         have pkg-config || add pkg-config pkg-config
         have cmake || add cmake cmake
         have readelf || add binutils readelf ;;
      mpi)
         have cmake || add cmake cmake
         have mpirun || add openmpi-bin "mpirun (Open MPI)"
         printf 'program t\nuse mpi_f08\nend program t\n' > "$scratch/m.f90"
         if ! have mpif90 || ! (cd "$scratch" && mpif90 -c m.f90 -o m.o >/dev/null 2>&1); then
            add libopenmpi-dev "the MPI Fortran wrapper mpif90 with the mpi_f08 module"
         fi ;;
      doc)
         have python3 || add python3 python3
         bash "$here/doc.sh" --find-ford >/dev/null 2>&1 || need_ford=1
         [ -e /usr/share/javascript/bootstrap5/css/bootstrap.min.css ] || need_bootstrap=1 ;;
      pkg:*) add "${need#pkg:}" "${need#pkg:}" ;;
      *) echo "setup: unknown need '$need'" >&2; exit 2 ;;
   esac
done
if [ $need_fpm = 1 ] || [ $need_ford = 1 ]; then
   have python3 || add python3 python3
   python3 -m pip --version >/dev/null 2>&1 || add python3-pip "pip (python3 -m pip)"
fi

# the de-duplicated list
if [ ${#packages[@]} -gt 0 ]; then
   mapfile -t packages < <(printf '%s\n' "${packages[@]}" | awk '!seen[$0]++')
fi

sudo_cmd=""
can_install=1
if [ "$(id -u)" -ne 0 ]; then
   if have sudo; then sudo_cmd="sudo"; else can_install=0; fi
fi

report_missing() {
   local pip_items=()
   [ $need_fpm = 1 ] && pip_items+=(fpm)
   [ $need_ford = 1 ] && pip_items+=(ford)
   {
      echo "setup: missing for this target:"
      [ ${#packages[@]} -gt 0 ] && echo "  Debian packages: ${packages[*]}" \
         && printf '    (%s)\n' "$(IFS=','; echo "${tools[*]}" | sed 's/,/, /g')"
      [ ${#pip_items[@]} -gt 0 ] && echo "  Python packages: ${pip_items[*]}"
      echo "Provide them, then run the same make target again:"
      [ ${#packages[@]} -gt 0 ] && echo "  as root:         apt-get install ${packages[*]}"
      [ ${#packages[@]} -gt 0 ] && echo "  on a cluster:    module load the compiler, LAPACK, GSL (and gnuplot, cmake, MPI) modules"
      [ ${#packages[@]} -gt 0 ] && echo "  with conda:      conda install -c conda-forge gfortran gsl lapack gnuplot cmake pkg-config"
      [ ${#pip_items[@]} -gt 0 ] && echo "  without root:    python3 -m pip install --user ${pip_items[*]}   (then ~/.local/bin is searched)"
      [ ${#pip_items[@]} -gt 0 ] && echo "  with conda:      conda install -c conda-forge ${pip_items[*]}"
      true
   } >&2
}

if [ ${#packages[@]} -eq 0 ] && [ $need_fpm = 0 ] && [ $need_ford = 0 ]; then
   if [ $need_bootstrap = 1 ] && [ $can_install = 1 ] && [ $check_only = 0 ]; then
      # optional: the site is still built without it (styled then only with a network)
      echo "setup: installing libjs-bootstrap5 (the site's styles without a network)" >&2
      export DEBIAN_FRONTEND=noninteractive
      { $sudo_cmd apt-get install -y -qq --no-install-recommends libjs-bootstrap5 >/dev/null 2>&1 \
         || { $sudo_cmd apt-get update -qq >/dev/null 2>&1 \
              && $sudo_cmd apt-get install -y -qq --no-install-recommends libjs-bootstrap5 >/dev/null 2>&1; }; } \
         || echo "setup: libjs-bootstrap5 not installed; the site loads Bootstrap from its CDN" >&2
   fi
   exit 0
fi
if [ $check_only = 1 ]; then report_missing; exit 1; fi

if [ ${#packages[@]} -gt 0 ]; then
   if [ $can_install = 0 ]; then
      report_missing
      echo "setup: not root and no sudo: nothing installed" >&2
      exit 1
   fi
   if [ $need_bootstrap = 1 ]; then packages+=(libjs-bootstrap5); fi
   echo "setup: installing ${packages[*]}" >&2
   export DEBIAN_FRONTEND=noninteractive
   $sudo_cmd apt-get update -qq
   $sudo_cmd apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null
fi

pip_install() {
   echo "setup: installing $1 through pip" >&2
   # a Debian system Python refuses plain pip installs (PEP 668): fall back to --user/--break-system-packages
   python3 -m pip install --quiet "$1" 2>/dev/null \
      || python3 -m pip install --quiet --user "$1" 2>/dev/null \
      || python3 -m pip install --quiet --user --break-system-packages "$1"
   hash -r
}
if [ $need_fpm = 1 ]; then
   pip_install fpm
   bash "$here/fpm.sh" --version >/dev/null 2>&1 || { echo "setup: fpm not found after pip install" >&2; exit 1; }
fi
if [ $need_ford = 1 ]; then
   pip_install ford
   bash "$here/doc.sh" --find-ford >/dev/null 2>&1 || { echo "setup: ford not found after pip install" >&2; exit 1; }
fi
exit 0
