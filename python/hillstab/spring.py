"""A real spring in SI units: a mass m on a spring of constant k and natural length r0,
bounced vertically by an amplitude a under gravity g, optionally damped at a rate κ.

ρ = r0 + g/ω² is the loaded length (eq. (4)), ω = √(k/m); the Hill equation of the swing
has α = aπ²/ρ, β = gπ²/(ρω²) (eq. (24)) and ε = κπ/ω (eq. (46)), and τ = ωt/π, so a
Floquet exponent μ per unit τ is μω/π per second. The conversions are the library's (the
same as a scene's ``&physical``), so the values equal the command line's to the bit.
"""
import math

import numpy as np

from . import _capi
from ._capi import lib, check
from .floquet import floquet, ALL_VALUES
from .models import as_model
from .scenes import run_groups, Series


class Spring:
    """A spring: ``Spring(k=25, m=0.25, r0=0.3)`` (or ``omega=`` instead of k and m), g
    defaulting to 9.81 m/s², κ to 0.

    >>> s = Spring(k=25, m=0.25, r0=0.3)
    >>> s.beta                          # 2.43...
    >>> s.growth_per_second([0.02, 0.05])
    >>> s.critical_amplitudes()         # [0.003811...]
    """

    def __init__(self, k=None, m=None, r0=None, g=9.81, kappa=0.0, omega=None, model="elastic"):
        if omega is None:
            if k is None or m is None:
                raise ValueError("give the spring constant k (N/m) and the mass m (kg), or omega (rad/s)")
            if not float(k) > 0.0:
                raise ValueError("k: the spring constant must be > 0, got {!r}".format(float(k)))
            if not float(m) > 0.0:
                raise ValueError("m: the mass must be > 0, got {!r}".format(float(m)))
            omega = math.sqrt(float(k) / float(m))
        elif k is not None or m is not None:
            raise ValueError("give omega or k and m, not both")
        if r0 is None:
            raise ValueError("give the natural length r0 (m)")
        #: spring constant (N/m) and mass (kg), when given
        self.k, self.m = k, m
        #: radial angular frequency ω = √(k/m) (rad/s)
        self.omega = float(omega)
        #: natural length (m), gravity (m/s²), damping rate (1/s)
        self.r0, self.g, self.kappa = float(r0), float(g), float(kappa)
        self.model = as_model(model)
        # checks the spring and gives beta, epsilon
        _, self._beta, self._epsilon = self._point(0.0)

    def _point(self, a):
        alpha, beta, epsilon = (_capi.ctypes.c_double() for _ in range(3))
        check(lib.hillstab_physical(self.model.handle, self.r0, self.g, self.omega, float(a), self.kappa,
                                    _capi.ctypes.byref(alpha), _capi.ctypes.byref(beta),
                                    _capi.ctypes.byref(epsilon)))
        return alpha.value, beta.value, epsilon.value

    @property
    def rho(self):
        """The loaded (equilibrium) length ρ = r0 + g/ω² (m)."""
        return self.r0 + self.g / (self.omega * self.omega)

    @property
    def beta(self):
        """β = gπ²/(ρω²) of the spring (every amplitude has it)."""
        return self._beta

    @property
    def epsilon(self):
        """The damping ε = κπ/ω."""
        return self._epsilon

    def alpha(self, a):
        """α = aπ²/ρ of bounce amplitudes a (m); ValueError for a outside [0, ρ)."""
        a = np.asarray(a, dtype=np.float64)
        return np.array([self._point(x)[0] for x in a.ravel()]).reshape(a.shape)

    def floquet(self, a, method="auto", tolerance=1e-10, values=ALL_VALUES, threads=0):
        """`floquet` at the bounce amplitudes a (m), with ``growth_per_second`` μω/π (1/s)
        added when ``mu`` (the exponent) is asked for."""
        alpha = self.alpha(a)
        result = floquet(alpha, self.beta, self.model, self.epsilon, method, tolerance, values=values,
                         threads=threads)
        result.alpha_of_a = alpha
        if "mu" in result.names:
            result.growth_per_second = result.mu * (self.omega / math.pi) + 0.0
        return result

    def growth_per_second(self, a, method="auto", tolerance=1e-10, threads=0):
        """How fast the swing grows at bounce amplitudes a (m): μω/π per second (the
        ``mu_per_s`` column; −κ/2 where the bounce is stable)."""
        return self.floquet(a, method, tolerance, values=("mu",), threads=threads).growth_per_second

    def stable(self, a, method="auto", tolerance=1e-10, threads=0):
        """The verdict at bounce amplitudes a (m): 1 stable, 0 unstable, 0.5 marginal."""
        return self.floquet(a, method, tolerance, values=("stable",), threads=threads).stable

    def _physical(self):
        group = {"g": self.g, "kappa": self.kappa, "r0": self.r0}
        if self.k is not None:
            group.update(k=float(self.k), m=float(self.m))
        else:
            group["omega"] = self.omega
        return group

    def critical_amplitudes(self, tolerance=1e-10, quiet=True):
        """The bounce amplitudes (m) where the stability of the bounce changes, ascending,
        as task ``boundaries`` with ``&physical`` finds them (the curves by Hill's method,
        each crossing checked by method auto). The intervals between them alternate
        stable and unstable: ``stable()`` at a point inside tells which."""
        out = run_groups({"scene": {"task": "boundaries", "model": self.model.name, "tolerance": tolerance},
                          "physical": self._physical()}, quiet)
        return np.sort(out["a"])

    def series(self, a, phi0=0.017, periods=50, duration=None, samples_per_period=100, tolerance=1e-10,
               quiet=True):
        """The nonlinear pendulum bounced by a (m) from φ(0) = phi0 (rad), as task ``series``
        computes it with ``&physical``: a `Series` of arrays (t, r, phi, x, z, energy, ...)."""
        group = self._physical()
        group["a"] = float(a)
        motion = {"phi0": phi0, "samples_per_period": samples_per_period}
        if duration is None:
            motion["periods"] = periods
        else:
            motion["duration"] = duration
        return Series(run_groups({"scene": {"task": "series", "model": self.model.name, "tolerance": tolerance},
                                  "physical": group, "series": motion}, quiet))

    def __repr__(self):
        return "hillstab.Spring(omega={}, r0={}, g={}, kappa={})".format(self.omega, self.r0, self.g, self.kappa)
