"""hillstab: stability of Hill equations x'' + Q(τ) x = 0 by Floquet theory, from Python.

The Fortran library hillstab computes; this package passes numpy arrays through its C
interface (ctypes; the GIL is released during every computation, which runs on the
library's OpenMP threads). What it offers:

- models as objects: `Model` (``"elastic"``, ``"mathieu"``: `model_names`);
- systems of n coupled Hill equations: `System` (numpy matrices in; `System.monodromy`,
  `System.floquet`: multipliers, exponents, verdict and kind of instability at a point, or
  arrays of them over arrays of points; `System.chart` over a grid); `Equations`, the
  system as its user writes it (n coupled equations in physical time, named parameters
  and matrices), with the same methods;
- `floquet`, `trace` over arrays of (α, β) and `chart` over a grid, returning numpy arrays
  (S, verdicts, multipliers, exponents, error estimates) with a per-point ``status``;
- `transition_curves` (Hill's method) and Mathieu's characteristic values `mathieu_a`,
  `mathieu_b`; `critical_drives`; `regions`, the resonance regions of a driven model or
  system and their tips;
- `Spring`: a real spring in SI units (α, β, growth per second, critical amplitudes,
  the nonlinear motion);
- `series`: the nonlinear pendulum over time; `run_scene` and `read_output`: namelist
  scenes and output files of the command line.

Bad input raises ValueError with the library's message; a failed computation raises
`HillstabError`; per-point failures are status 2 (placeholders, never NaN) with a
`HillstabWarning`.
"""
from ._capi import lib as _lib
from .errors import HillstabError, HillstabWarning, PointsFailedError
from .models import Model, Equation, model_names
from .floquet import floquet, trace, chart, Result, ALL_VALUES, ALIASES
from .curves import transition_curves, critical_drives, mathieu_a, mathieu_b, Curves, CriticalDrives, regions, Regions
from .spring import Spring
from .scenes import run_scene, read_output, series, Output, Series
from .system import System, Equations, SystemFloquet, SystemResult

#: the version of the library loaded
__version__ = _lib.hillstab_version().decode()

__all__ = ["Model", "Equation", "model_names", "floquet", "trace", "chart", "Result", "ALL_VALUES", "ALIASES", "transition_curves", "critical_drives", "CriticalDrives",
           "regions", "Regions",
           "mathieu_a", "mathieu_b", "Curves", "Spring", "run_scene", "read_output", "series", "Output", "Series",
           "System", "Equations", "SystemFloquet", "SystemResult",
           "HillstabError", "HillstabWarning", "PointsFailedError"]
