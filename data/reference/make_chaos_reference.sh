#!/usr/bin/env bash
# Remake data/reference/chaos_verdicts.dat, the reference verdicts of the chaos tests
# (test/pendulum/test_chaos.f90): the paper's Fig. 4 points and the cell-centred 8 x 8 grid of the
# physical domain, alpha_i = (i - 1/2) pi^2/8, beta_j = (j - 1/2) pi^2/8, each integrated for
# 3000 radial periods by lyapunov_largest (DOP853 on the variational equations at
# tolerance 1e-11, the code that predates the symplectic tangent maps) from phi0 = 0.017,
# with the verdict rule of app/hillstab_chaos_reference.f90. Run from the repository
# root (about a minute on two cores; OMP_NUM_THREADS sets the threads). The tests only
# read the table.
set -euo pipefail
list=$(mktemp)
trap 'rm -f "$list"' EXIT
{
   echo "# the paper's Fig. 4 points (a) (b) (c) (d) (e) (g)"
   printf '%s\n' "1.48 2.47" "3.70 2.47" "2.57 1.29" "5.0 0.76" "7.88 3.95" "7.48 2.47"
   echo "# the cell-centred 8 x 8 grid of the physical domain"
   python3 -c 'import math
n = 8; p2 = math.pi**2
for i in range(n):
    for j in range(n):
        print(repr((i + 0.5)*p2/n), repr((j + 0.5)*p2/n))'
} > "$list"
bash scripts/fpm.sh run --profile release hillstab_chaos_reference -- points "$list" 3000 1e-11 \
   data/reference/chaos_verdicts.dat
