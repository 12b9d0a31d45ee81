"""The exceptions and warnings of hillstab.

Bad input (a point outside the model's domain, an unknown method, a bad scene variable)
raises ValueError with the library's own message; a computation that failed raises
HillstabError. Per-point failures of a batch do not raise: their status is 2 (and
HillstabWarning says how many); `trace` alone, which returns bare values, raises for them.
"""


class HillstabError(RuntimeError):
    """A computation of the library failed; `code` is its error code (include/hillstab.h)."""

    def __init__(self, message, code=0):
        super().__init__(message)
        #: the library's error code (HILLSTAB_ERR_*)
        self.code = code


class PointsFailedError(HillstabError):
    """A scene ran and wrote its file, but some of its points failed (status 2 rows, the
    command line's exit status 3); `path` is the file written."""

    def __init__(self, message, code=8, path=None):
        super().__init__(message, code)
        #: the output file, written all the same
        self.path = path


class HillstabWarning(UserWarning):
    """Some points are round-off limited (status 1) or failed (status 2)."""
