"""Time responses of a linear model: from initial conditions, and to steps and impulses of its
inputs, sampled at ``0, dt, 2 dt, ..., T`` and exact at the samples (the matrix exponential,
:mod:`~bikemass.analysis.handling.discrete`).

A step of size ``a`` (N m) holds the input at ``a`` from ``t = 0``; an impulse of size ``J``
(N m s) adds ``B J`` to the state at ``t = 0``, so the first sample is the state just after it.

With the held inputs as further states (``u' = 0``) the response is ``z[k] = Phi^k z[0]`` with one
matrix exponential ``Phi`` over a step: the samples are filled by doubling (``z[m:2m] = z[0:m]
(Phi^m)^T``, then ``Phi^2m = (Phi^m)^2``), ``log2(n)`` matrix products for ``n`` samples instead of a
Python loop of ``n`` steps.

An unstable model's response grows without bound (at standstill the bicycle falls: roll grows like
``exp(3 t)``).  Where a state passes :data:`DIVERGED` times its unit's bound of :data:`LIMITS` (far
past any meaning of a linear model about the upright run, and long before the numbers overflow)
the response stops at the last sample before, with a one-line :class:`~bikemass.core.errors.BikemassWarning`.
Initial values and input sizes beyond the bounds of :data:`LIMITS` are refused.
"""

import math
import warnings
from collections.abc import Mapping
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from ...core.choices import closest
from ...core.errors import BikemassWarning, InputError, short, wrong_type
from ...core.frozen import short_repr
from ...core.real import finite_real
from .discrete import hold_matrices, sample_times
from ..nonlinear.response import NonlinearResponse
from ..sampled import SampledResponse, checked_inputs
from .plant import System, check_speed, input_index, linear_model

if TYPE_CHECKING:                          # the annotations' names only
    from numpy.typing import ArrayLike


"""How an input is applied."""

DEFAULT_DURATION = 5.0
DEFAULT_STEP = 0.01

LIMITS = {"rad": math.pi, "rad/s": 100.0, "m": 1e3, "m/s": 100.0, "N": 1e5, "N m": 1e4, "N m s": 1e4}
"""Largest magnitude of an initial value, a step or an impulse, by unit (another unit: 1e6): half a
turn, 100 rad/s, 1 km, 100 m/s, 100 kN, 10 kN m, 10 kN m s.  Beyond them a linear model about the
upright run means nothing."""
DEFAULT_LIMIT = 1e6
DIVERGED = 1e3
"""A response stops where a state passes DIVERGED times its unit's :data:`LIMITS`."""


def _number(value, source, key, unit=None):
    if not finite_real(value):
        raise InputError(source, key, f"a finite number, got {short(value)}")
    if unit is not None and not abs(value) <= LIMITS.get(unit, DEFAULT_LIMIT):
        raise InputError(source, key, f"at most {LIMITS.get(unit, DEFAULT_LIMIT):g} {unit} in magnitude (a linear "
                         f"model about the upright run), got {short(value)}")
    return float(value)


def initial_state(model, initial):
    """The state vector (N,) from ``{state name: value}`` (the states' units), zero elsewhere."""
    x0 = np.zeros(len(model.states))
    if initial is None:
        return x0
    if not isinstance(initial, Mapping):
        raise wrong_type("initial", initial, "initial conditions are a mapping {state name: value}")
    for name, value in initial.items():
        if name not in model.state_names:
            raise InputError("initial", short(name), f"a state of the model: {', '.join(model.state_names)}"
                             f"{closest(name, model.state_names)}")
        i = model.state_index(name)
        x0[i] = _number(value, "initial", name, model.states[i].unit)
    return x0


def applied_inputs(model, inputs):
    """``{input name: (kind, size)}`` checked: kind ``step`` (N m) or ``impulse`` (N m s)."""
    return checked_inputs(inputs, lambda name: input_index(model, name),
                          lambda size, name, kind: _number(size, "inputs", name, "N m" if kind == "step" else "N m s"))


@dataclass(frozen=True, eq=False, repr=False)
class TimeResponse(SampledResponse):
    """The states of a linear model against time.

    Attributes
    ----------
    speed : float
        Forward speed (m/s).
    time : numpy.ndarray (n,)
        Samples ``0, dt, ..., T`` (s).
    names, signal_units : tuple of str
        The states' names and units, in the model's order (``units``, the name of ``signal_units``
        before 0.3, still reads it with a DeprecationWarning; ``units()`` is the units block).
    values : numpy.ndarray (n, N)
        The states at the samples (their units); read-only.
    inputs : mapping
        ``{input name: Applied(kind, size)}`` that was applied (steps in N m, impulses in N m s).

    See Also
    --------
    bikemass.simulate : Makes it.

    Examples
    --------
    >>> import bikemass as bm
    >>> r = bm.simulate(bm.parameters("benchmark"), 4.6, initial={"roll-rate": 0.5}, duration=1.0)
    >>> r.names[:2], r.signal_units[:2], r.values.shape
    (('roll-angle', 'steer-angle'), ('rad', 'rad'), (101, 6))
    >>> r.units()["time"], r.units()["roll-rate"]        # the units block of r.to_dict()
    ('s', 'rad/s')
    """

    def to_dict(self):
        """Plain data: speed, time (s) and states (``{name: samples}`` in their units)."""
        return {"speed": self.speed, "time": self.time.tolist(),
                "states": {name: self[name].tolist() for name in self.names}}

    def __repr__(self):
        return short_repr(self, *self._repr_fields())


def simulate(system: System, speed: float, initial: "Mapping[str, float] | None" = None,
             inputs: "Mapping[str, tuple[str, float]] | None" = None, duration: float = DEFAULT_DURATION,
             step: float = DEFAULT_STEP, stiffness: "ArrayLike | None" = None,
             nonlinear: bool = False) -> "TimeResponse | NonlinearResponse":
    """The time response from initial conditions and to steps and impulses of the inputs.

    Parameters
    ----------
    system : LinearModel, Scenario, Built, BenchmarkParameters or RiderLeanParameters
        A linear model, a scenario, or a parameter set (the Whipple bicycle, or the leaning rider's
        model of RiderLeanParameters).
    speed : float
        Forward speed (m/s).
    initial : mapping, optional
        ``{state name: value}`` at ``t = 0`` in the states' units (rad, rad/s, m), e.g.
        ``{"roll-rate": 0.5}``; other states start at zero.
    inputs : mapping, optional
        ``{input name: (kind, size)}``: ``("step", a)`` holds the input at ``a`` N m from
        ``t = 0``; ``("impulse", J)`` is an impulse of ``J`` N m s at ``t = 0``.
    duration, step : float
        The samples ``0, step, 2 step, ...`` up to ``duration`` (s); default 5 s in 0.01 s.
    stiffness : array_like (2, 2), optional
        Rear-frame stiffness S (N m/rad) of a parameter set.
    nonlinear : bool
        The nonlinear Whipple bicycle of a parameter set instead (:mod:`bikemass.analysis.nonlinear`,
        integrated numerically): its states add the forward speed, pitch, x and energy, and a fall
        ends the run early (docs/nonlinear.md).

    Returns
    -------
    TimeResponse or NonlinearResponse
        ``time`` (s) and ``values`` (n, N); ``response["roll-rate"]`` is one state's samples.

    Raises
    ------
    InputError
        A bad speed, an unknown state or input, an input other than a step or an impulse, an initial
        value or input size beyond :data:`LIMITS`, or a duration or step out of range (at most 10^6
        samples).

    Warns
    -----
    BikemassWarning
        The response of an unstable model grew past :data:`DIVERGED` times a state's bound: it stops
        at the last sample before (``time`` is shorter than ``duration``).

    See Also
    --------
    plot_time_response : Draw it.
    plot_nonlinear_response : Draw a nonlinear run beside the linear one.
    lane_change : A rider steering the bicycle through a manoeuvre.

    Examples
    --------
    >>> import bikemass as bm
    >>> r = bm.simulate(bm.parameters("benchmark"), 4.6, initial={"roll-rate": 0.5}, duration=1.0)
    >>> print(r)
    TimeResponse(speed=4.6 m/s, time=0..1 s x 101, states=6, inputs=none)
    >>> print(f"{r['roll-rate'][-1]:.6f} rad/s")
    -0.249568 rad/s
    >>> n = bm.simulate(bm.parameters("benchmark"), 4.6, initial={"roll-rate": 0.5}, duration=1.0, nonlinear=True)
    >>> print(f"{n['roll-rate'][-1]:.6f} rad/s at {n['forward-speed'][-1]:.4f} m/s")
    -0.211102 rad/s at 4.6223 m/s
    """
    if nonlinear:
        # lazy: the nonlinear model (its generated code, scipy's integrator) only for a nonlinear run
        from ..nonlinear.simulate import simulate_nonlinear
        if stiffness is not None:
            raise InputError("stiffness", short(stiffness), "none: the nonlinear model has a rigid frame")
        # a parameter set only: simulate_nonlinear refuses any other system in one line
        return simulate_nonlinear(system, speed, initial, inputs, duration, step)  # type: ignore[arg-type]
    model = linear_model(system, stiffness)
    v = check_speed(speed)
    x0 = initial_state(model, initial)
    applied = applied_inputs(model, inputs)
    t = sample_times(duration, step)
    A, B = model.state_matrix(v), model.input_matrix(v)
    u = np.zeros(len(model.inputs))
    for name, (kind, size) in applied.items():
        j = model.input_names.index(name)
        if kind == "impulse":
            x0 = x0 + B[:, j] * size
        else:
            u[j] = size
    Phi, G0, _ = hold_matrices(A, B, float(step))
    n, m = len(x0), len(u)
    step_matrix = np.block([[Phi, G0], [np.zeros((m, n)), np.eye(m)]])
    values = powers_applied(step_matrix, np.concatenate([x0, u]), len(t))[:, :n]
    units = tuple(s.unit for s in model.states)
    kept = _bounded(values, units)
    if kept < len(t):
        bound = np.array([DIVERGED * LIMITS.get(unit, DEFAULT_LIMIT) for unit in units])
        worst = int(np.argmax(~(np.abs(values[kept]) <= bound)))
        warnings.warn(f"the response grows without bound at {v:g} m/s (an unstable model): {model.state_names[worst]} "
                      f"passes {bound[worst]:g} {units[worst]} after {t[kept]:g} s; stopped at {t[kept - 1]:g} s",
                      BikemassWarning, stacklevel=2)
        t, values = t[:kept], values[:kept]
    return TimeResponse(v, t, model.state_names, units, values, applied)


def powers_applied(step_matrix, z0, count):
    """``z[k] = step_matrix^k z0`` for ``k < count`` (count, N), by doubling: ``log2(count)`` matrix
    products (overflow gives inf or nan, silently: the caller bounds the samples)."""
    z = np.empty((count, len(z0)))
    z[0] = z0
    P, filled = np.asarray(step_matrix, dtype=float), 1
    with np.errstate(over="ignore", invalid="ignore"):
        while filled < count:
            take = min(filled, count - filled)
            z[filled:filled + take] = z[:take] @ P.T
            filled += take
            if filled < count:
                P = P @ P
    return z


def _bounded(values, units):
    """How many leading samples have every state within DIVERGED times its unit's bound (and finite)."""
    bound = np.array([DIVERGED * LIMITS.get(unit, DEFAULT_LIMIT) for unit in units])
    bad = ~np.all(np.abs(values) <= bound, axis=1)
    return int(np.argmax(bad)) if bad.any() else len(values)
