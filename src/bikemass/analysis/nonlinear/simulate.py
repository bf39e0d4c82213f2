"""Time responses of the nonlinear Whipple bicycle (:mod:`bikemass.models.nonlinear`).

The minimal equations (forward speed, roll and steer rates independent; the pitch solved from the
holonomic constraint by Newton's method at every evaluation, the other speeds from the rolling
constraints) are integrated with scipy's DOP853 (an explicit Runge-Kutta method of order 8) at a
relative tolerance of 1e-10 (absolute 1e-9); the samples come from its dense output.  The constraints therefore
hold to round-off along the run, and the energy (kinetic plus potential, the ground at zero height)
drifts only by the integration error (about 1e-8 % over 20 s of the IFToMM runs).

A run stops early, keeps what it computed and says why in one line (``stopped``, and a
:class:`~bikemass.core.errors.BikemassWarning`) when the bicycle falls (the roll passes
:data:`FALL_ROLL`, or a frame's centre of mass reaches the ground), when the front wheel turns
across the frame (:data:`STEER_LIMIT`), or when the integration breaks down (no pitch puts the front
wheel on the ground, or the step size vanishes): never a row of NaN.
"""

import math
import numbers
import warnings
from collections.abc import Mapping

import numpy as np

from ...core.choices import closest
from ...core.real import finite_real
from ...core.errors import BikemassWarning, InputError, short, wrong_type
from ...core.limits import MAX_SPEED
from ...models.nonlinear import ConstraintError, NonlinearWhipple
from ...models.parameters import BenchmarkParameters
from ..handling.discrete import sample_times
from ..sampled import checked_inputs
from .response import NAMES, UNITS, NonlinearResponse  # noqa: F401 (NAMES, UNITS: the outputs, defined with the result)

FALL_ROLL = math.radians(60.0)
"""Roll (rad) at which a run stops as a fall: 60 degrees.  A real bicycle's pedals, handlebar or
frame have touched the ground before that; the Whipple bicycle has no such parts (its knife-edge
wheels alone touch the ground), so this is where its motion stops meaning a ride."""
STEER_LIMIT = math.radians(90.0)
"""Steer (rad) at which a run stops: the front wheel across the frame (the model's constraints
become singular there)."""

INITIAL = ("roll-angle", "steer-angle", "roll-rate", "steer-rate", "heading", "lateral")
"""The states an initial condition may set (the forward speed is the ``speed`` argument)."""
INPUTS = ("roll-torque", "steer-torque")
RTOL = 1e-10
"""The integrator's relative tolerance."""
ATOL = 1e-9
"""The integrator's absolute tolerance (in each state's unit: rad, rad/s, m, m/s).  It sets the
step once the motion has decayed (a roll of 1e-4 rad at 1e-10 relative would ask for 1e-14)."""
_INDEX = {"roll-angle": 3, "steer-angle": 5, "roll-rate": 8, "steer-rate": 9, "heading": 2, "lateral": 1}


def _number(value, source, key):
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not finite_real(value):
        raise InputError(source, key, f"a finite number, got {short(value)}")
    return float(value)


def _initial(initial):
    out = {}
    if initial is None:
        return out
    if not isinstance(initial, Mapping):
        raise wrong_type("initial", initial, "initial conditions are a mapping {state name: value}")
    for name, value in initial.items():
        if name not in INITIAL:
            raise InputError("initial", short(name), f"a state of the nonlinear model: {', '.join(INITIAL)} "
                             f"(the forward speed is the speed){closest(name, INITIAL)}")
        out[name] = _number(value, "initial", name)
    return out


def _inputs(inputs):
    def known(name):
        if name not in INPUTS:
            raise InputError("input", short(name), f"one of {', '.join(INPUTS)}{closest(name, INPUTS)}")
    return checked_inputs(inputs, known, lambda size, name, kind: _number(size, "inputs", name))


def _fallen(bike, state):
    """Why the motion at ``state`` is over (one line), or ``""``."""
    roll, steer = state[3], state[5]
    if abs(roll) >= FALL_ROLL:
        return f"the bicycle fell (roll reached {math.degrees(FALL_ROLL):g} degrees)"
    if abs(steer) >= STEER_LIMIT:
        return f"the front wheel turned across (steer reached {math.degrees(STEER_LIMIT):g} degrees)"
    heights = bike.heights(roll, steer)
    if min(heights[1], heights[2]) <= 0.0:
        return "the bicycle fell (a frame's centre of mass reached the ground)"
    return ""


def _crossing(bike, dense, t0, t1):
    """The first time in ``(t0, t1]`` at which the motion is over (bisection on the dense output)."""
    lo, hi = t0, t1
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        try:
            over = bool(_fallen(bike, dense(mid)))
        except ConstraintError:
            over = True
        lo, hi = (lo, mid) if over else (mid, hi)
        if hi - lo < 1e-12 * max(1.0, hi):
            break
    return hi


def simulate_nonlinear(parameters: BenchmarkParameters, speed: float, initial: "Mapping[str, float] | None" = None,
                       inputs: "Mapping[str, tuple[str, float]] | None" = None, duration: float = 5.0,
                       step: float = 0.01, rtol: float = RTOL, atol: float = ATOL) -> NonlinearResponse:
    """The nonlinear Whipple bicycle's motion from initial conditions and under steps and impulses
    of the roll and steer torques.

    Parameters
    ----------
    parameters : BenchmarkParameters
        The bicycle (and rider) as the 26 benchmark parameters.
    speed : float
        Initial forward speed of the rear contact (m/s); it then changes as the bicycle moves.
    initial : mapping, optional
        ``{state name: value}`` at ``t = 0`` (rad, rad/s, m) of :data:`INITIAL`; others start at
        zero (upright, straight, the pitch from the constraint).
    inputs : mapping, optional
        ``{"roll-torque" or "steer-torque": (kind, size)}``: ``("step", a)`` holds the torque at
        ``a`` N m from ``t = 0``; ``("impulse", J)`` is ``J`` N m s at ``t = 0``.
    duration, step : float
        The samples ``0, step, ...`` up to ``duration`` (s); default 5 s in 0.01 s.
    rtol, atol : float
        The integrator's tolerances (default 1e-10 and 1e-9).

    Returns
    -------
    NonlinearResponse
        The outputs :data:`NAMES` at the samples; ``stopped`` says why a run ended early.

    Raises
    ------
    InputError
        A bad speed, state, input, duration or step, or an initial configuration with no pitch
        that puts the front wheel on the ground.

    Warns
    -----
    BikemassWarning
        The run stopped early (a fall, the steer past 90 degrees, or the integration breaking down).

    Examples
    --------
    >>> import bikemass as bm
    >>> from bikemass.analysis.nonlinear.simulate import simulate_nonlinear
    >>> r = simulate_nonlinear(bm.parameters("benchmark"), 4.6, initial={"roll-rate": 0.5}, duration=1.0)
    >>> print(f"{r['roll-rate'][-1]:.6f} rad/s, {r['forward-speed'][-1]:.4f} m/s")
    -0.211102 rad/s, 4.6223 m/s
    """
    # lazy: scipy's integrator only for a nonlinear run
    from scipy.integrate import DOP853

    if not isinstance(parameters, BenchmarkParameters):
        raise wrong_type("system", parameters, "a benchmark parameter set (the nonlinear model is the Whipple "
                                                "bicycle)")
    if isinstance(speed, bool) or not isinstance(speed, numbers.Real) or not finite_real(speed) \
            or not 0 <= speed <= MAX_SPEED:
        raise InputError("speed", short(speed), f"a forward speed in m/s, a finite number in 0..{MAX_SPEED:g}")
    start = _initial(initial)
    applied = _inputs(inputs)
    t = sample_times(duration, step)
    for key, value in (("rtol", rtol), ("atol", atol)):
        if isinstance(value, bool) or not isinstance(value, numbers.Real) or not 0 < value < 1:
            raise InputError(key, short(value), "a tolerance between 0 and 1")
    bike = NonlinearWhipple(parameters)
    y0 = np.zeros(10)
    y0[7] = float(speed)
    for name, value in start.items():
        y0[_INDEX[name]] = value
    why = _fallen_safely(bike, y0)
    if why:
        raise InputError("initial", short(dict(start)), f"a state before a fall or a broken constraint, got: {why}")
    torques = np.zeros(2)
    for name, (kind, size) in applied.items():
        j = INPUTS.index(name)
        if kind == "step":
            torques[j] = size
        else:
            impulse = np.zeros(2)
            impulse[j] = size
            y0[7:10] += bike.configuration(y0, impulse).accelerations - bike.configuration(y0).accelerations
    torques = tuple(float(x) for x in torques)

    def rates(_, y):
        return bike.rates(y, torques)

    solver = DOP853(rates, 0.0, y0, float(t[-1]), rtol=rtol, atol=atol)
    states = [y0]
    k, stopped = 1, ""
    with np.errstate(over="raise", divide="raise", invalid="raise"):
        while solver.status == "running" and k < len(t):
            try:
                solver.step()
            except (ConstraintError, np.linalg.LinAlgError, FloatingPointError, ArithmeticError):
                stopped = f"stopped after t = {solver.t:.6g} s: the integration broke down (no pitch puts the " \
                          "front wheel on the ground, or the equations became singular)"
                break
            if solver.status == "failed" or not np.all(np.isfinite(solver.y)):
                stopped = f"stopped after t = {solver.t:.6g} s: the integration diverged"
                break
            dense = solver.dense_output()
            end = solver.t
            why = _fallen_safely(bike, solver.y)
            if why:
                end = _crossing(bike, dense, solver.t_old, solver.t)
                stopped = f"stopped at t = {end:.4f} s: {why}"
            n = k
            while n < len(t) and t[n] <= end * (1 + 1e-14) and (not why or t[n] < end):
                n += 1
            if n > k:
                states.extend(np.atleast_2d(dense(t[k:n]).T))
                k = n
            if why:
                break
    states = np.array(states)
    pitch, kinetic, potential = bike.samples(states)
    rows = np.column_stack((states[:, [3, 5, 8, 9, 2, 1, 7]], pitch, states[:, 0], kinetic + potential))
    if stopped:
        warnings.warn(stopped, BikemassWarning, stacklevel=2)
    return NonlinearResponse(float(speed), t[:len(rows)], NAMES, UNITS, rows, applied, stopped)


def _fallen_safely(bike, state):
    """:func:`_fallen`, a broken constraint counting as the end of the motion."""
    try:
        return _fallen(bike, state)
    except ConstraintError as exc:
        return str(exc)
