!> Working precision and mathematical constants shared by every hillstab module.
module hillstab_core_kinds
   use, intrinsic :: iso_fortran_env, only: wp => real64, int64
   implicit none
   private
   public :: wp, int64, pi, pi2, pi2_lo, half_pi, log_huge, version_string

   !> Archimedes' constant.
   real(wp), parameter :: pi = 3.14159265358979323846264338327950288_wp
   !> π², the upper bound of the amplitude parameter α and the isotropic value of β.
   real(wp), parameter :: pi2 = pi*pi
   !> π² − pi2 (π² = pi2 + pi2_lo to about 32 digits): with it, π² − α keeps its relative
   !> accuracy as α → π² (pi2 − α is exact there, Sterbenz).
   real(wp), parameter :: pi2_lo = 6.2652955087397117e-16_wp
   !> π/2.
   real(wp), parameter :: half_pi = 0.5_wp*pi
   !> Natural logarithm of the largest finite real(wp); magnitudes are reported
   !> as logarithms beyond roughly this value.
   real(wp), parameter :: log_huge = 709.0_wp
   !> Package version, written into every output header.
   character(len=*), parameter :: version_string = "0.1.0"
end module hillstab_core_kinds
