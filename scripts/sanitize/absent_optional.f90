! gfortran 12 artefact behind UBSan's "signed integer overflow" in rk_integrate (issue 19:
! rk.f90, passing its absent optional y_out(:, :) on to the driver's routines).
!
! When an optional assumed-shape dummy is passed on to another optional dummy, gfortran
! builds a new descriptor for the callee from local copies of the dummy's strides. It sets
! those copies only when the array is present, yet computes the new descriptor's offset
! (-stride1 - stride2) unconditionally, and only then passes a null pointer for an absent
! array. The subtraction runs on whatever the locals held (at -O0 with the sanitizers:
! callee-saved registers of the caller), so it may overflow: undefined behaviour that
! UBSan reports, although the descriptor is discarded. See -fdump-tree-original of
! `outer`: `parm.offset = -stride.7 - stride.9; D = a.0 != 0B ? &parm : 0B`.
!
! Built and run by scripts/sanitize/reproduce.sh with dirty_registers.c, which calls
! `outer()` with large values in those registers (x86-64).
module absent_optional
   implicit none
contains
   subroutine inner(a)
      real, intent(inout), optional :: a(:, :)
      if (present(a)) a = 2
   end subroutine inner
   subroutine outer(a)
      real, intent(out), optional :: a(:, :)
      call inner(a)
   end subroutine outer
end module absent_optional
