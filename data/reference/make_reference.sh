#!/usr/bin/env bash
# Remake data/reference/hard_set.dat: installs mpmath (and gmpy2, which makes it
# several times faster) from PyPI into the user's site if missing, then runs
# data/reference/make_reference.py. Run from the repository root. The tests read
# the stored table and do not need Python.
set -euo pipefail
python3 -c "import mpmath" 2>/dev/null || python3 -m pip install --user mpmath || \
   python3 -m pip install --user --break-system-packages mpmath
python3 -c "import gmpy2" 2>/dev/null || python3 -m pip install --user gmpy2 || \
   python3 -m pip install --user --break-system-packages gmpy2 || true
python3 data/reference/make_reference.py data/reference/hard_set.dat
