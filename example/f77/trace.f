C     Links against an installed hillstab from fixed-form FORTRAN 77
C     with no USE: HSTRACE, HSFLOQ and HSERRM are called through
C     implicit interfaces, like LAPACK. Compiled with -std=legacy.
C     References: eq. (37) at the paper's case (b) gives S = -3.6282;
C     case (c) is stable (mu = 0); alpha = 10 > pi**2 is refused.
      PROGRAM F77TRC
      DOUBLE PRECISION S, MU
      INTEGER INFO, ISTAB
      CHARACTER*120 MSG
C     eq. (37): MODEL 1 (elastic), METHOD 1 (formula)
      CALL HSTRACE(1, 3.7D0, 2.47D0, 0.0D0, 1, 2, 1, 1.0D-10, S, INFO)
      WRITE (*, 10) S, INFO
   10 FORMAT ('F77: S(eq. 37) = ', F10.6, ', INFO = ', I2)
      IF (INFO .NE. 0 .OR. ABS(S + 3.6282D0) .GT. 1.0D-3) STOP 1
C     METHOD 0 (auto) at case (c): stable, exponent 0
      CALL HSFLOQ(1, 2.57D0, 1.29D0, 0.0D0, 0, 2, 1, 1.0D-10,
     &            S, MU, ISTAB, INFO)
      WRITE (*, 20) S, MU, ISTAB, INFO
   20 FORMAT ('F77: S(auto) = ', F10.6, ', MU = ', F8.5,
     &        ', ISTAB = ', I1, ', INFO = ', I2)
      IF (INFO .NE. 0 .OR. ISTAB .NE. 1) STOP 1
      IF (ABS(S + 1.640081756D0) .GT. 1.0D-8) STOP 1
C     alpha beyond pi**2: INFO = 1 and the message names the limit
      CALL HSTRACE(1, 10.0D0, 2.47D0, 0.0D0, 1, 2, 1, 1.0D-10, S, INFO)
      CALL HSERRM(MSG)
      WRITE (*, 30) INFO, MSG(1:LEN_TRIM(MSG))
   30 FORMAT ('F77: alpha = 10 -> INFO = ', I2, ': ', A)
      IF (INFO .NE. 1 .OR. INDEX(MSG, '9.8696') .EQ. 0) STOP 1
      END
