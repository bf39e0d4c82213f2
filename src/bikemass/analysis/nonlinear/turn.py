"""Steady turns of the nonlinear Whipple bicycle: circles at constant speed, lean and steer.

In a steady turn the roll, steer and pitch stay constant and the bicycle yaws at a constant rate;
the dependent speeds follow from the rolling constraints, every acceleration vanishes and so does
``b = A' u`` (the configuration does not change).  Kane's equations then reduce to the generalised
forces ``G = S^T F`` of the independent speeds (:meth:`~bikemass.models.nonlinear.NonlinearWhipple.
steady_forces`): the forward one vanishes identically (no work is done), the roll one must vanish,
and the steer one is balanced by the rider's steer torque.  So, for a speed ``v``:

- given the turn's radius (of the rear contact's circle) or the steer angle, the lean solves
  ``G_roll = 0`` (with the radius ``v / yaw rate`` as the second equation), and the steer torque is
  ``-G_steer``;
- hands-free circles (no steer torque) solve ``G_roll = G_steer = 0`` for the lean and the speed at
  a given steer angle: a family over the steer angle that starts, at zero steer, at the linear
  model's capsize speed (where ``det(g K0 + v^2 K2) = 0``), as Basu-Mandal et al. (2007) found.

Newton's method (finite-difference-free: scipy's ``root`` with its Jacobian by differences of the
smooth residual) starts from the linear model's steady turn (``(g K0 + v^2 K2) [phi, delta] =
[0, T]``, the yaw rate ``v delta cos(lam) / w``).
"""

import math
import numbers
import warnings
from dataclasses import dataclass

import numpy as np

from ...core.choices import RIGID
from ...core.results import Result, quantity
from ...scenario.scenario import Built, Scenario
from ...core.keywords import renamed_keywords
from ...core.real import finite_real
from ...core.errors import BikemassWarning, InputError, short, wrong_type
from ...core.frozen import readonly, short_repr
from ...core.limits import MAX_SPEED
from ...models.whipple_generated import whipple_matrices
from ...models.nonlinear import ConstraintError, NonlinearWhipple
from ...models.parameters import BenchmarkParameters
from ...models.registry import BASE

CONTINUATION_STEP = 0.01
"""Largest step in steer angle (rad) when following the hands-free family from one solution to
the next (finer steps than asked are taken in between)."""
TOLERANCE = 1e-9
"""What the solutions satisfy: the generalised forces (N m) and the radius (relative) to this."""


@dataclass(frozen=True, repr=False)
class SteadyTurn(Result):
    """One steady turn of the nonlinear Whipple bicycle.

    Attributes
    ----------
    speed : float
        Forward speed of the rear contact (m/s).
    radius : float
        Radius of the rear contact's circle (m); positive turning right.
    roll, steer, pitch : float
        Lean (rad, right positive), steer angle and the rear frame's pitch (rad).
    steer_torque : float
        The rider's steer torque that holds it (N m).
    yaw_rate : float
        Turning rate (rad/s).
    linear_roll, linear_steer, linear_steer_torque : float
        The linear model's steady turn at the same speed and radius (rad, rad, N m).

    Examples
    --------
    >>> import bikemass as bm
    >>> turn = bm.steady_turn(bm.parameters("benchmark"), 5.0, radius=10.0)
    >>> print(f"lean {turn.roll:.4f} rad, steer {turn.steer:.4f} rad, torque {turn.steer_torque:.4f} N m")
    lean 0.2444 rad, steer 0.1037 rad, torque -0.1469 N m
    """

    speed: float = quantity("m/s", "forward speed of the rear contact")
    radius: float = quantity("m", "radius of the rear contact's circle, positive turning right")
    roll: float = quantity("rad", "lean, right positive")
    steer: float = quantity("rad", "steer angle")
    pitch: float = quantity("rad", "the rear frame's pitch")
    steer_torque: float = quantity("N m", "the rider's steer torque that holds the turn")
    yaw_rate: float = quantity("rad/s", "turning rate")
    linear_roll: float = quantity("rad", "the linear model's lean at the same speed and radius")
    linear_steer: float = quantity("rad", "the linear model's steer angle")
    linear_steer_torque: float = quantity("N m", "the linear model's steer torque")

    def to_dict(self):
        """Plain ``{name: float}`` (SI; angles in rad)."""
        return {k: float(getattr(self, k)) for k in self.__dataclass_fields__}

    def unit_block(self):
        """The unit of each key of :meth:`to_dict`: its fields' declared units (:meth:`units`)."""
        return self.units()

    def __repr__(self):
        return short_repr(self, ("speed", f"{self.speed:g} m/s"), ("radius", f"{self.radius:.4g} m"),
                          ("roll", f"{self.roll:.4g} rad"), ("steer", f"{self.steer:.4g} rad"),
                          ("steer_torque", f"{self.steer_torque:.4g} N m"))


@dataclass(frozen=True, eq=False, repr=False)
class HandsFreeTurns(Result):
    """The hands-free steady turns (no steer torque) of the nonlinear Whipple bicycle, one per
    steer angle.

    Attributes
    ----------
    steer : numpy.ndarray (n,)
        Steer angles (rad) the family is computed at.
    speed, roll, radius, pitch : numpy.ndarray (n,)
        Forward speed (m/s), lean (rad), radius of the rear contact's circle (m) and pitch (rad);
        NaN where Newton's method found no circle.
    capsize_speed : float
        The linear model's speed with ``det(g K0 + v^2 K2) = 0`` (m/s): the family's zero-steer limit.

    Examples
    --------
    >>> import bikemass as bm
    >>> family = bm.hands_free_turns(bm.parameters("benchmark"), [0.01, 0.05])
    >>> print(f"{family.capsize_speed:.4f} m/s; {family.speed[0]:.4f} m/s at 0.01 rad of steer")
    6.0243 m/s; 6.0212 m/s at 0.01 rad of steer
    """

    steer: np.ndarray = quantity("rad", "steer angles the family is computed at")
    speed: np.ndarray = quantity("m/s", "forward speed of each turn (NaN: no circle found)")
    roll: np.ndarray = quantity("rad", "lean of each turn")
    radius: np.ndarray = quantity("m", "radius of the rear contact's circle")
    pitch: np.ndarray = quantity("rad", "the rear frame's pitch")
    capsize_speed: float = quantity("m/s", "the linear model's det(g K0 + v^2 K2) = 0 speed")

    def __post_init__(self):
        for name in ("steer", "speed", "roll", "radius", "pitch"):
            object.__setattr__(self, name, readonly(getattr(self, name), float))

    def to_dict(self):
        """Plain data: the capsize speed and the family's columns."""
        return {"capsize_speed": self.capsize_speed, "steer": self.steer.tolist(), "speed": self.speed.tolist(),
                "roll": self.roll.tolist(), "radius": self.radius.tolist(), "pitch": self.pitch.tolist()}

    def unit_block(self):
        """The unit of each key of :meth:`to_dict`: its fields' declared units (:meth:`units`)."""
        return self.units()

    def __repr__(self):
        return short_repr(self, ("turns", len(self.steer)), ("capsize_speed", f"{self.capsize_speed:.4f} m/s"))


def _benchmark_set(system) -> BenchmarkParameters:
    """The benchmark parameter set of ``system``: a parameter set, a Scenario (the Whipple bicycle's set of
    its bicycle and rider) or a built scenario; anything else an InputTypeError.  A scenario of another
    model (a member: its equations are not the nonlinear Whipple bicycle's) or with a flexible frame is
    refused in one line, never turned as the rigid Whipple bicycle without a word."""
    if isinstance(system, Scenario):
        system = system.build()             # what it builds: its model, and its frame (a file's stiffness too)
    if isinstance(system, Built):
        if system.choice.members:
            raise InputError("model", system.choice.name, f"{BASE}: the steady turns are the nonlinear Whipple "
                             "bicycle's (a rigid rider and frame, no tyre model)")
        if system.stiffness is not None:
            raise InputError("stiffness", "a flexible rear frame", f"{RIGID}: the nonlinear Whipple bicycle's frame "
                             "is rigid")
        system = system.parameters
    if not isinstance(system, BenchmarkParameters):
        raise wrong_type("system", system, "a benchmark parameter set, a Scenario or a built scenario")
    return system


def _speed(value):
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not finite_real(value) \
            or not 0 < value <= MAX_SPEED:
        raise InputError("speed", short(value), f"a forward speed in m/s, a finite number in (0, {MAX_SPEED:g}]")
    return float(value)


def _state(roll, steer, speed):
    state = np.zeros(10)
    state[3], state[5], state[7] = roll, steer, speed
    return state


def _yaw_rate(bike, roll, steer, speed):
    pitch = bike.pitch(roll, steer, guess=0.0)          # the upright configuration's branch, whatever came before
    return float(bike.speeds(roll, pitch, steer, (speed, 0.0, 0.0))[2]), pitch


def _roll_force(bike, roll, steer, speed):
    """The roll equation's residual (N m) of a steady turn, with the pitch of the upright configuration's branch
    (the solver's pitch starts from its last solution otherwise: a scan over sharp turns could leave it on
    the branch where the frame has pitched over, and the same turn gave another residual)."""
    bike.pitch(roll, steer, guess=0.0)
    return bike.steady_forces(_state(roll, steer, speed))[1]


def _linear(parameters, speed, steer):
    """The linear model's ``(roll, steer torque)`` at ``steer`` (rad) and ``speed``."""
    m = whipple_matrices(parameters)
    K = m.g * m.K0 + speed ** 2 * m.K2
    roll = -K[0, 1] * steer / K[0, 0]
    return roll, K[1, 0] * roll + K[1, 1] * steer


def _roll_guess(parameters, speed, steer):
    """A start for the lean of the steady turn at ``steer`` (rad) and ``speed``: the linear model's, or for a
    turn too sharp for it (a lean of a radian or more) the point mass's on the kinematic circle,
    ``atan(v^2 tan(steer) cos(lam) / (g w))``, which stays on the upright side."""
    roll = _linear(parameters, speed, steer)[0]
    if abs(roll) < 1.0:
        return roll
    p = parameters
    return math.atan(speed * speed * math.tan(steer) * math.cos(p.lam) / (p.g * p.w))


def _upright_roll(bike, p, v, delta):
    """The lean (rad) of the upright steady turn at steer ``delta`` (rad) and speed ``v``: the roll equation solved
    from :func:`_roll_guess`; ArithmeticError where none is found, or where the lean found is past lying flat or
    turns the bicycle against its steer (no upright turn)."""
    roll = float(_root(lambda x: [_roll_force(bike, x[0], delta, v)], [_roll_guess(p, v, delta)],
                       "no lean balances it")[0])
    yaw_rate, _ = _yaw_rate(bike, roll, delta, v)
    if not abs(roll) < math.pi / 2 or (delta and yaw_rate * delta <= 0):
        raise ArithmeticError(f"the lean that balances it, {roll:.3g} rad, is past lying flat or turns the bicycle "
                              "against its steer: no upright turn")
    return roll


def _radius_turn(bike, p, v, R):
    """``(roll, steer)`` (rad) of the upright steady turn on the rear contact's circle of radius ``R`` (m) at speed
    ``v``: Newton's method on both equations from the kinematic steer, and where that finds no upright turn (a
    sharp turn, far from its start), the steer whose upright turn has that radius, bracketed over steer angles
    and refined by Brent's method (each steer's lean by :func:`_upright_roll`)."""
    delta0 = math.atan(p.w / (R * math.cos(p.lam)))

    def residual(x):
        yaw_rate, _ = _yaw_rate(bike, x[0], x[1], v)
        return [_roll_force(bike, x[0], x[1], v), (yaw_rate * R - v) / v]
    try:
        roll, delta = (float(z) for z in _root(residual, [_roll_guess(p, v, delta0), delta0], "no steady turn"))
        if abs(roll) < math.pi / 2 and abs(delta) < math.pi / 2 and delta * R > 0:
            return roll, delta
    except ArithmeticError:
        pass
    def miss(delta):                      # the upright turn's curvature at this steer minus the circle's
        yaw_rate, _ = _yaw_rate(bike, _upright_roll(bike, p, v, delta), delta, v)
        return yaw_rate / v - 1 / R
    steers = math.copysign(1.0, R) * np.linspace(1e-3, math.pi / 2 - 1e-3, STEER_SCAN)
    found = {}
    for k, delta in enumerate(steers.tolist()):
        try:
            found[k] = miss(delta)
        except ArithmeticError:
            continue
    brackets = [(float(steers[k]), float(steers[k + 1])) for k, f in found.items()   # neighbours that both have a
                if k + 1 in found and f * found[k + 1] <= 0]                           # turn, the sign changing
    for k, f in found.items():                  # or a steer with a turn and the edge of the steers that have one
        for step in (1, -1):
            if 0 <= k + step < len(steers) and k + step not in found:
                edge, f_edge = _edge(miss, float(steers[k]), float(steers[k + step]))
                if f * f_edge <= 0:
                    brackets.append((float(steers[k]), edge))
    for a, b in brackets:
        delta = _bracketed_root(miss, a, b)
        if delta is not None:
            return _upright_roll(bike, p, v, delta), delta
    raise ArithmeticError("no steady turn")


def _bracketed_root(f, a, b, depth=2):
    """The root of ``f`` in ``[a, b]`` (a sign change of ``f`` there) by Brent's method, or ``None``; where ``f`` is
    not defined somewhere inside (ArithmeticError), the interval is searched on a finer scan of its own for a
    bracket without such points (``depth`` times)."""
    # lazy: scipy's bracketed root finder only for a sharp turn
    from scipy.optimize import brentq
    try:
        return float(brentq(f, a, b, xtol=1e-14, rtol=4 * np.finfo(float).eps))
    except ArithmeticError:
        if depth == 0:
            return None
    points = np.linspace(a, b, 17).tolist()
    values = {}
    for x in points:
        try:
            values[x] = f(x)
        except ArithmeticError:
            continue
    for x, y in zip(points, points[1:]):
        if x in values and y in values and values[x] * values[y] <= 0:
            root = _bracketed_root(f, x, y, depth - 1)
            if root is not None:
                return root
    return None


def _edge(f, inside, outside, halvings=40):
    """``(x, f(x))``: the point nearest ``outside`` where ``f`` is still defined (no ArithmeticError), found by
    halving the interval from ``inside`` (defined) towards ``outside`` (not)."""
    f_inside = f(inside)
    for _ in range(halvings):
        middle = 0.5 * (inside + outside)
        try:
            f_inside, inside = f(middle), middle
        except ArithmeticError:
            outside = middle
    return inside, f_inside


STEER_SCAN = 64
"""Steer angles (from 0 to pi/2) on which a sharp circle's steer is bracketed (:func:`_radius_turn`)."""


def _root(function, guess, what):
    # lazy: scipy's root finder only for a steady turn
    from scipy.optimize import root

    try:
        with np.errstate(all="ignore"):
            solution = root(function, guess, method="hybr", tol=1e-14)
    except ConstraintError:
        raise ArithmeticError(what) from None
    if not np.all(np.isfinite(solution.x)) or np.max(np.abs(function(solution.x))) > TOLERANCE:
        raise ArithmeticError(what)
    return solution.x


@renamed_keywords(parameters="system")
def steady_turn(system: "BenchmarkParameters | Scenario | Built", speed: float, radius: "float | None" = None,
                steer: "float | None" = None) -> SteadyTurn:
    """The nonlinear bicycle's steady turn at ``speed`` on a circle of ``radius`` or at ``steer``.

    Parameters
    ----------
    system : BenchmarkParameters, Scenario or Built
        The bicycle and rider.
    speed : float
        Forward speed of the rear contact (m/s), above zero.
    radius : float, optional
        Radius of the rear contact's circle (m); negative turns left.  Give it or ``steer``.
    steer : float, optional
        Steer angle (rad), instead of the radius.

    Returns
    -------
    SteadyTurn
        Lean, steer, pitch, steer torque and yaw rate, and the linear model's lean, steer and torque
        for the same circle.

    Raises
    ------
    InputError
        Not exactly one of ``radius`` and ``steer``, a bad value, or no steady turn found there (a
        circle too tight for the front wheel, or no lean that balances it).

    See Also
    --------
    hands_free_turns : The circles that need no steer torque.

    Examples
    --------
    >>> import bikemass as bm
    >>> turn = bm.steady_turn(bm.parameters("benchmark"), 5.0, steer=0.05)
    >>> print(f"radius {turn.radius:.3f} m, lean {turn.roll:.4f} rad (linear {turn.linear_roll:.4f})")
    radius 21.281 m, lean 0.1187 rad (linear 0.1199)
    """
    params = _benchmark_set(system)
    v = _speed(speed)
    if (radius is None) == (steer is None):
        raise InputError("steady_turn", "radius/steer", "exactly one of a radius (m) and a steer angle (rad)")
    bike = NonlinearWhipple(params)
    p = params

    if steer is not None:
        if isinstance(steer, bool) or not isinstance(steer, numbers.Real) or not abs(steer) < math.pi / 2:
            raise InputError("steer", short(steer), "a steer angle in rad, below pi/2 in size")
        delta = float(steer)
        try:
            roll = _upright_roll(bike, p, v, delta)
        except ArithmeticError as exc:
            raise InputError("steer", short(steer), f"a steer angle with a steady turn at {v:g} m/s ({exc})") from None
    else:
        if isinstance(radius, bool) or not isinstance(radius, numbers.Real) or not finite_real(radius) \
                or radius == 0:
            raise InputError("radius", short(radius), "a radius in m, finite and not 0 (negative turns left)")
        try:
            roll, delta = _radius_turn(bike, p, v, float(radius))
        except ArithmeticError as exc:
            raise InputError("radius", short(radius), f"a radius with a steady turn at {v:g} m/s ({exc})") from None
    yaw_rate, pitch = _yaw_rate(bike, roll, delta, v)
    forces = bike.steady_forces(_state(roll, delta, v))         # at that pitch (the solver's last)
    linear_steer = p.w * yaw_rate / (v * math.cos(p.lam))          # the linear model's circle: same radius
    linear_roll, linear_torque = _linear(p, v, linear_steer)
    if not (abs(linear_roll) < math.pi / 2 and abs(linear_steer) < math.pi / 2):
        warnings.warn(f"steady turn at {v:g} m/s: the linear model's lean and steer for this circle ({linear_roll:.3g} "
                      f"rad, {linear_steer:.3g} rad) are outside any angle it describes; its columns are no "
                      "comparison here", BikemassWarning, stacklevel=3)
    return SteadyTurn(v, v / yaw_rate if yaw_rate else math.inf, roll, delta, pitch, -float(forces[2]), yaw_rate,
                      float(linear_roll), float(linear_steer), float(linear_torque))


def capsize_speed(parameters):
    """The speed (m/s) at which ``det(g K0 + v^2 K2)`` vanishes (the linear capsize speed of a bicycle
    like the benchmark's), or NaN if it does not."""
    m = whipple_matrices(parameters)
    a, b = m.g * m.K0, m.K2
    # det(a + s b) = 0, s = v^2: a quadratic in s
    c2 = b[0, 0] * b[1, 1] - b[0, 1] * b[1, 0]
    c1 = a[0, 0] * b[1, 1] + a[1, 1] * b[0, 0] - a[0, 1] * b[1, 0] - a[1, 0] * b[0, 1]
    c0 = a[0, 0] * a[1, 1] - a[0, 1] * a[1, 0]
    roots = np.roots([c2, c1, c0]) if c2 else np.array([-c0 / c1])
    positive = [r.real for r in roots if abs(r.imag) < 1e-12 and r.real > 0]
    return math.sqrt(min(positive)) if positive else math.nan


@renamed_keywords(parameters="system")
def hands_free_turns(system: "BenchmarkParameters | Scenario | Built", steers: "np.typing.ArrayLike") -> HandsFreeTurns:
    """The steady turns that need no steer torque, one per steer angle: a family that starts, at
    zero steer, at the linear model's capsize speed.

    Parameters
    ----------
    system : BenchmarkParameters, Scenario or Built
        The bicycle and rider.
    steers : array_like (n,)
        Steer angles (rad), each nonzero and below pi/2 in size; the family is followed from small
        steer angles in steps of at most :data:`CONTINUATION_STEP`, each solution the next one's start.

    Returns
    -------
    HandsFreeTurns
        Speed, lean, radius and pitch per steer angle (NaN where none was found, with a warning).

    Raises
    ------
    InputError
        A steer angle of zero (the straight run, hands-free at any speed), or out of range.

    See Also
    --------
    steady_turn : A turn of a given radius or steer angle, and its steer torque.

    Examples
    --------
    >>> import bikemass as bm
    >>> family = bm.hands_free_turns(bm.parameters("benchmark"), [0.1, 0.2])
    >>> [f"{v:.3f}" for v in family.speed]
    ['5.692', '4.783']
    """
    params = _benchmark_set(system)
    values = np.atleast_1d(np.asarray(steers, dtype=float)) if not isinstance(steers, str) else None
    if values is None or values.ndim != 1 or len(values) == 0 or not np.all(np.isfinite(values)) \
            or np.any(values == 0) or np.any(np.abs(values) >= math.pi / 2):
        raise InputError("steers", short(steers), "steer angles in rad, nonzero and below pi/2 in size")
    bike = NonlinearWhipple(params)
    v0 = capsize_speed(params)
    out = np.full((len(values), 4), np.nan)
    guess, previous = None, 0.0

    def circle(delta, guess):
        def residual(x):
            forces = bike.steady_forces(_state(x[0], delta, x[1]))
            return [forces[1], forces[2]]
        roll, v = _root(residual, guess, "no hands-free circle")
        if not v > 0:
            raise ArithmeticError("the family turned to riding backwards")
        return [roll, v]

    for i, delta in enumerate(values):
        try:
            if guess is None or np.sign(delta) != np.sign(previous):
                v = v0 if math.isfinite(v0) else 5.0
                start = math.copysign(min(abs(delta), CONTINUATION_STEP), delta)
                guess, previous = circle(start, [_linear(params, v, start)[0], v]), start
            steps = max(1, math.ceil(abs(delta - previous) / CONTINUATION_STEP))
            for between in np.linspace(previous, delta, steps + 1)[1:]:
                guess = circle(float(between), guess)
            previous = delta
        except (ArithmeticError, ConstraintError):
            guess = None
            continue
        roll, v = guess
        yaw_rate, pitch = _yaw_rate(bike, roll, delta, v)
        out[i] = roll, v, v / yaw_rate, pitch
    missing = values[np.isnan(out[:, 1])]
    if len(missing):
        warnings.warn(f"hands-free circles: none found at {len(missing)} of {len(values)} steer angles (smallest "
                      f"in size {float(missing[np.argmin(np.abs(missing))]):.4g} rad; their rows are NaN): the family "
                      "ends where its speed falls to 0, a static equilibrium (Basu-Mandal et al. 2007), or the "
                      "continuation lost it", BikemassWarning, stacklevel=2)
    return HandsFreeTurns(values, out[:, 1], out[:, 0], out[:, 2], out[:, 3], v0)
