!> Explicit interfaces to the LAPACK routines hillstab calls (the build compiles with
!> `-Werror=implicit-interface`, so every external routine is declared once, here).
module hillstab_ffi_lapack
   use hillstab_core_kinds, only: wp
   implicit none
   private
   public :: dsbgv, dgeev, dsbev, zhbev, zggev

   interface
      !> Generalised symmetric-definite banded eigenproblem A z = λ B z.
      subroutine dsbgv(jobz, uplo, n, ka, kb, ab, ldab, bb, ldbb, w, z, ldz, work, info)
         import :: wp
         character, intent(in) :: jobz  !! 'N' eigenvalues only, 'V' also eigenvectors
         character, intent(in) :: uplo  !! 'U' or 'L': which triangle the bands hold
         integer, intent(in) :: n       !! order of the matrices
         integer, intent(in) :: ka      !! super-diagonals of A
         integer, intent(in) :: kb      !! super-diagonals of B
         integer, intent(in) :: ldab    !! leading dimension of ab
         integer, intent(in) :: ldbb    !! leading dimension of bb
         integer, intent(in) :: ldz     !! leading dimension of z
         real(wp), intent(inout) :: ab(ldab, *)  !! A in band storage (overwritten)
         real(wp), intent(inout) :: bb(ldbb, *)  !! B in band storage (overwritten by its split Cholesky factor)
         real(wp), intent(out) :: w(*)           !! eigenvalues, ascending
         real(wp), intent(out) :: z(ldz, *)      !! eigenvectors if jobz = 'V'
         real(wp), intent(out) :: work(*)        !! workspace, 3n
         integer, intent(out) :: info            !! 0 on success
      end subroutine dsbgv

      !> Eigenvalues and, optionally, left and right eigenvectors of a general real matrix.
      subroutine dgeev(jobvl, jobvr, n, a, lda, wr, wi, vl, ldvl, vr, ldvr, work, lwork, info)
         import :: wp
         character, intent(in) :: jobvl  !! 'N' or 'V': left eigenvectors
         character, intent(in) :: jobvr  !! 'N' or 'V': right eigenvectors
         integer, intent(in) :: n        !! order of a
         integer, intent(in) :: lda      !! leading dimension of a
         integer, intent(in) :: ldvl     !! leading dimension of vl
         integer, intent(in) :: ldvr     !! leading dimension of vr
         integer, intent(in) :: lwork    !! size of work
         real(wp), intent(inout) :: a(lda, *)   !! the matrix (overwritten)
         real(wp), intent(out) :: wr(*)         !! real parts of the eigenvalues
         real(wp), intent(out) :: wi(*)         !! imaginary parts of the eigenvalues
         real(wp), intent(out) :: vl(ldvl, *)   !! left eigenvectors if jobvl = 'V'
         real(wp), intent(out) :: vr(ldvr, *)   !! right eigenvectors if jobvr = 'V'
         real(wp), intent(out) :: work(*)       !! workspace
         integer, intent(out) :: info           !! 0 on success
      end subroutine dgeev

      !> Generalised eigenvalues of a pair of general complex matrices: A x = λ B x, with
      !> λ = alpha/beta (beta = 0: an infinite eigenvalue).
      subroutine zggev(jobvl, jobvr, n, a, lda, b, ldb, alpha, beta, vl, ldvl, vr, ldvr, work, lwork, rwork, info)
         import :: wp
         character, intent(in) :: jobvl  !! 'N' or 'V': left eigenvectors
         character, intent(in) :: jobvr  !! 'N' or 'V': right eigenvectors
         integer, intent(in) :: n        !! order of a and b
         integer, intent(in) :: lda      !! leading dimension of a
         integer, intent(in) :: ldb      !! leading dimension of b
         integer, intent(in) :: ldvl     !! leading dimension of vl
         integer, intent(in) :: ldvr     !! leading dimension of vr
         integer, intent(in) :: lwork    !! size of work (at least 2n)
         complex(wp), intent(inout) :: a(lda, *)  !! A (overwritten)
         complex(wp), intent(inout) :: b(ldb, *)  !! B (overwritten)
         complex(wp), intent(out) :: alpha(*)     !! numerators of the eigenvalues
         complex(wp), intent(out) :: beta(*)      !! denominators of the eigenvalues
         complex(wp), intent(out) :: vl(ldvl, *)  !! left eigenvectors if jobvl = 'V'
         complex(wp), intent(out) :: vr(ldvr, *)  !! right eigenvectors if jobvr = 'V'
         complex(wp), intent(out) :: work(*)      !! workspace
         real(wp), intent(out) :: rwork(*)        !! workspace, 8n
         integer, intent(out) :: info             !! 0 on success
      end subroutine zggev

      !> Eigenvalues and, optionally, eigenvectors of a real symmetric band matrix.
      subroutine dsbev(jobz, uplo, n, kd, ab, ldab, w, z, ldz, work, info)
         import :: wp
         character, intent(in) :: jobz  !! 'N' eigenvalues only, 'V' also eigenvectors
         character, intent(in) :: uplo  !! 'U' or 'L': which triangle the band holds
         integer, intent(in) :: n       !! order of the matrix
         integer, intent(in) :: kd      !! super-diagonals
         integer, intent(in) :: ldab    !! leading dimension of ab (≥ kd + 1)
         integer, intent(in) :: ldz     !! leading dimension of z
         real(wp), intent(inout) :: ab(ldab, *)  !! the matrix in band storage (overwritten)
         real(wp), intent(out) :: w(*)           !! eigenvalues, ascending
         real(wp), intent(out) :: z(ldz, *)      !! eigenvectors if jobz = 'V'
         real(wp), intent(out) :: work(*)        !! workspace, max(1, 3n − 2)
         integer, intent(out) :: info            !! 0 on success
      end subroutine dsbev

      !> Eigenvalues and, optionally, eigenvectors of a complex Hermitian band matrix.
      subroutine zhbev(jobz, uplo, n, kd, ab, ldab, w, z, ldz, work, rwork, info)
         import :: wp
         character, intent(in) :: jobz  !! 'N' eigenvalues only, 'V' also eigenvectors
         character, intent(in) :: uplo  !! 'U' or 'L': which triangle the band holds
         integer, intent(in) :: n       !! order of the matrix
         integer, intent(in) :: kd      !! super-diagonals
         integer, intent(in) :: ldab    !! leading dimension of ab (≥ kd + 1)
         integer, intent(in) :: ldz     !! leading dimension of z
         complex(wp), intent(inout) :: ab(ldab, *)  !! the matrix in band storage (overwritten)
         real(wp), intent(out) :: w(*)              !! eigenvalues, ascending
         complex(wp), intent(out) :: z(ldz, *)      !! eigenvectors if jobz = 'V'
         complex(wp), intent(out) :: work(*)        !! workspace, n
         real(wp), intent(out) :: rwork(*)          !! workspace, max(1, 3n − 2)
         integer, intent(out) :: info               !! 0 on success
      end subroutine zhbev
   end interface
end module hillstab_ffi_lapack
