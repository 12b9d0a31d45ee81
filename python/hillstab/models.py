"""Models of the coefficient Q(τ) of the Hill equation x'' + Q(τ) x = 0 as objects.

Every model of the library's registry is available by name (`model_names`): ``elastic``,
the elastic pendulum's Q(τ) = (β − α cos πτ)/(1 − (α/π²) cos πτ), and ``mathieu``,
q(τ) = β − α cos πτ. A model that carries data (a Fourier series of Q) takes it through
`Model.set`.
"""
import ctypes

import numpy as np

from . import _capi
from ._capi import lib, check


def model_names():
    """The names of the models the library knows, in the order of their codes.

    >>> model_names()
    ['elastic', 'mathieu']
    """
    return [_capi.text_out(lib.hillstab_model_registry_name, k, length=64)
            for k in range(1, lib.hillstab_model_count() + 1)]


class Model:
    """A model of Q(τ) from the library's registry, by name (any case).

    >>> m = Model("mathieu")
    >>> m.name, m.formula
    ('mathieu', ...)

    An unknown name raises ValueError listing the known ones. The model is freed with the
    object; several threads may compute with it at once.
    """

    def __init__(self, name="elastic"):
        handle = _capi._model_p()
        check(lib.hillstab_model_new(str(name).encode(), ctypes.byref(handle)))
        self._handle = handle

    def __del__(self):
        handle = getattr(self, "_handle", None)
        if handle is not None and handle.value:
            try:
                lib.hillstab_model_free(handle)
            except Exception:  # the interpreter is shutting down
                pass
            self._handle = None

    @property
    def handle(self):
        """The C handle (``hillstab_model *``)."""
        return self._handle

    @property
    def name(self):
        """The model's name, as a scene's ``&scene model`` gives it."""
        return _capi.text_out(lib.hillstab_model_name, self._handle, length=256)

    @property
    def formula(self):
        """The coefficient Q(τ) as output files' headers state it."""
        return _capi.text_out(lib.hillstab_model_formula, self._handle)

    @property
    def variables(self):
        """The model's variables as {name: most numbers it takes} (empty for elastic and mathieu)."""
        count = ctypes.c_int(0)
        check(lib.hillstab_model_variable_count(self._handle, ctypes.byref(count)))
        result = {}
        for k in range(1, count.value + 1):
            buffer = ctypes.create_string_buffer(256)
            most = ctypes.c_int(0)
            check(lib.hillstab_model_variable_name(self._handle, k, buffer, len(buffer), ctypes.byref(most)))
            result[buffer.value.decode()] = most.value
        return result

    def set(self, variable, values):
        """Set a variable of the model (e.g. Fourier coefficients) to the given numbers, or
        a text variable (an equation's expressions and names) to a string; ValueError with
        the library's message when the model has no such variable or refuses the values.
        Returns the model."""
        if isinstance(values, str):
            check(lib.hillstab_model_set_text(self._handle, str(variable).encode(), values.encode()))
            return self
        array = _capi.as_doubles(np.atleast_1d(values))
        check(lib.hillstab_model_set(self._handle, str(variable).encode(), _capi.doubles(array), array.size))
        return self

    def check(self):
        """Raise ValueError naming what is missing when the model is not complete."""
        check(lib.hillstab_model_check(self._handle))

    def q(self, tau, alpha, beta, epsilon=0.0):
        """Q(τ) − ε²/4 of the model (the damping shift of eq. (47)) at the point (α, β)
        (scalars; through ``hillstab_q``, which knows the models without data)."""
        if self.variables:
            raise NotImplementedError("q() of a model with data: hillstab_q takes a model code, not a handle")
        code = model_names().index(self.name) + 1
        out = ctypes.c_double(0.0)
        check(lib.hillstab_q(code, float(alpha), float(beta), float(epsilon), float(tau), ctypes.byref(out)))
        return out.value

    def tau_rate(self, alpha, beta):
        """dτ/dt at the points (α, β) (arrays broadcast together): μ times it is the Floquet
        exponent per unit of the model's own time t — an equation's Ω/π at each point (its
        drive may depend on either axis); 0 for a model in τ alone (elastic, Mathieu) and at a
        point outside the domain. Through ``hillstab_model_tau_rate``."""
        a, b = np.broadcast_arrays(_capi.real_array("alpha", alpha), _capi.real_array("beta", beta))
        shape = a.shape
        a, b = (_capi.as_doubles(x.ravel()) for x in (a, b))
        rate = np.empty(a.size)
        check(lib.hillstab_model_tau_rate(self._handle, a.size, _capi.doubles(a), _capi.doubles(b),
                                          _capi.doubles(rate)))
        return rate.reshape(shape)

    def __repr__(self):
        return "hillstab.Model({!r})".format(self.name)


class Equation(Model):
    """An equation as its user writes it, in physical time t with named parameters:
    m x'' + c x' + k(t) x = 0, k of period 2π/Ω (the scene group ``&equation``).

    ``stiffness`` k(t), ``mass`` m and ``damping`` c are expressions (numbers, + - * / ^,
    parentheses, pi, sin cos tan exp log sqrt abs sinh cosh tanh atan atan2, t and the
    parameters; m and c without t); ``frequency`` Ω or ``period`` T (expressions of the
    parameters); ``parameters`` a dict ``{name: value}`` in order (or the scene's text
    ``"g = 9.81, l = 0.2"``); ``alpha`` and ``beta`` the parameters the points' two
    coordinates are: `floquet` and `chart` take their values as ``alpha`` and ``beta``.
    Either axis may enter anywhere (the frequency, the damping, the mass, the stiffness).
    Where the β axis enters the stiffness alone and affinely (a drive amplitude, a load), the
    points of a chart row share their meshes; else each point is computed alone (slower: no
    work is shared along a row). The damping is the equation's own, at
    every point (``epsilon`` must stay 0); the results are the physical equation's: its
    multipliers over one period, ``S`` S₁ = e^{cT/(2m)} times the trace of its
    monodromy, ``mu`` μ per unit τ = Ωt/π (μ Ω/π per unit time: ``mu * tau_rate(alpha, beta)``).

    >>> kapitza = Equation("-g/l + A*w^2/l*cos(w*t)", frequency="w", damping="kappa",
    ...                    parameters={"g": 9.81, "l": 0.2, "kappa": 0.2, "A": 0.005, "w": 314.16},
    ...                    alpha="w", beta="A")
    >>> floquet(314.16, [0.006, 0.007], model=kapitza).stable
    """

    def __init__(self, stiffness, frequency=None, period=None, parameters=None, mass="1", damping="0",
                 alpha=None, beta=None):
        super().__init__("equation")
        if parameters is None:
            parameters = ""
        if isinstance(parameters, dict):
            parameters = ", ".join("{} = {!r}".format(name, float(value)) for name, value in parameters.items())
        for name, text in (("parameters", parameters), ("stiffness", stiffness), ("mass", mass),
                           ("damping", damping), ("frequency", frequency), ("period", period),
                           ("alpha", alpha), ("beta", beta)):
            if text is None:
                continue
            if not isinstance(text, str):
                if name in ("mass", "damping", "frequency", "period"):
                    text = repr(float(text))
                else:
                    raise ValueError("{}: a string, got {!r}".format(name, text))
            self.set(name, text)
        self.check()
        #: the parameters of the two axes, as files name their columns
        self.axes = (alpha, beta)

    def __repr__(self):
        return "hillstab.Equation({!r})".format(self.formula)


def as_model(model):
    """A Model from a Model or a name."""
    if isinstance(model, Model):
        return model
    return Model(model)
