"""The nonlinear Whipple bicycle of one benchmark parameter set: its minimal equations of motion.

The generated code (:mod:`bikemass.models.generated.nonlinear_whipple`, derived by
:mod:`bikemass.models.derive.nonlinear`) gives, for a configuration (roll, pitch, steer), the
generalised forces of every speed as if all were independent, ``H = -M u' + F``, the velocity
constraints ``A u = 0`` (``A u' + b = 0``) and the holonomic constraint ``f = 0`` (the front wheel
touching the ground).  Here they become Kane's equations of the constrained system::

    u_D = W u_I,   W = -A_D^-1 A_I            the dependent speeds (yaw, pitch, lateral, wheel rates)
    u'  = S u_I' + s,  S = [1; W],  s_D = -A_D^-1 b
    S^T M S u_I' = S^T (F - M s)              Kane's equations (the contact forces drop out)

with the independent speeds ``u_I``: the rear contact's forward speed ``u_lon`` (m/s), the roll rate
and the steer rate (rad/s).  The pitch is solved from the holonomic constraint by Newton's method
whenever it is needed, so the constraints hold to round-off along any trajectory; ``A_D`` is
regular at zero steer (its determinant vanishes only with the front wheel across the frame).

The minimal state (:data:`STATE`) is ``[x, y, yaw, roll, rear wheel, steer, front wheel, u_lon,
roll rate, steer rate]``; :meth:`NonlinearWhipple.rates` is its time derivative.
"""

import math
from dataclasses import dataclass

import numpy as np

from .generated import nonlinear_whipple as _code
from .parameters import BenchmarkParameters

STATE = ("x", "y", "yaw", "roll", "rear-wheel", "steer", "front-wheel", "forward-speed", "roll-rate",
         "steer-rate")
"""Names of the minimal state's entries (m, m, rad, rad, rad, rad, rad, m/s, rad/s, rad/s)."""
STATE_UNITS = ("m", "m", "rad", "rad", "rad", "rad", "rad", "m/s", "rad/s", "rad/s")

_SPEED = {name: i for i, name in enumerate(_code.SPEEDS)}
INDEPENDENT = (_SPEED["u_lon"], _SPEED["u_phi"], _SPEED["u_delta"])
"""Indices in the generated SPEEDS of the independent speeds: forward speed, roll rate, steer rate."""
DEPENDENT = tuple(_code.DEPENDENT)
_COORDINATE_RATE = tuple(_SPEED[n] for n in ("u_psi", "u_phi", "u_betaR", "u_delta", "u_betaF"))
"""Speeds that are the rates of the state's yaw, roll, rear wheel, steer, front wheel."""

_ORDER = np.array(INDEPENDENT + DEPENDENT)
_EYE3 = np.eye(3)

PITCH_TOLERANCE = 1e-15
"""Newton on the pitch stops when its step is below this (rad; round-off is ~1e-16)."""


class ConstraintError(ArithmeticError):
    """The holonomic constraint has no solution near the guess (front wheel off the ground or across)."""


@dataclass(frozen=True)
class Configuration:
    """One instant of the nonlinear bicycle: the pitch (rad), every speed (``speeds`` in the
    generated order ``u_lon, u_lat, yaw rate, roll rate, pitch rate, rear wheel rate, steer rate,
    front wheel rate``: m/s, m/s, rad/s, ...), the accelerations of the independent speeds
    (``accelerations``: forward, roll, steer) and those of every speed (``speed_rates``, in the
    order of ``speeds``)."""

    pitch: float
    speeds: np.ndarray
    accelerations: np.ndarray
    speed_rates: np.ndarray


class NonlinearWhipple:
    """The nonlinear equations of motion of one benchmark parameter set.

    Parameters
    ----------
    parameters : BenchmarkParameters
        The 26 benchmark parameters (SI).

    Examples
    --------
    >>> import bikemass as bm
    >>> from bikemass.models.nonlinear import NonlinearWhipple
    >>> bike = NonlinearWhipple(bm.parameters("benchmark"))
    >>> print(f"{bike.pitch(0.0, 0.0):.1e} rad")     # upright and straight: the reference pitch
    0.0e+00 rad
    """

    def __init__(self, parameters: BenchmarkParameters):
        self.parameters = parameters
        values = [float(getattr(parameters, name)) for name, _, _ in _code.PARAMETERS]
        (self._holonomic, self._constraints, self._dynamics, self._energy,
         self._heights) = _code.bind(*values)
        self._guess = 0.0

    def pitch(self, roll, steer, guess=None):
        """The pitch (rad) that puts the front wheel on the ground at ``roll`` and ``steer`` (rad):
        Newton's method from ``guess`` (default: the last solution).  Raises :class:`ConstraintError`
        when it does not converge."""
        theta = self._guess if guess is None else float(guess)
        for _ in range(30):
            f, (_, dtheta, _) = self._holonomic(roll, theta, steer)
            if dtheta == 0.0 or not math.isfinite(f):
                break
            step = f / dtheta
            theta -= step
            if abs(step) <= PITCH_TOLERANCE * (1.0 + abs(theta)):
                self._guess = theta
                return theta
        raise ConstraintError(f"no pitch puts the front wheel on the ground at roll {roll:.6g} rad, "
                              f"steer {steer:.6g} rad")

    def speeds(self, roll, pitch, steer, independent):
        """Every speed (8,) from the independent ones ``(u_lon, roll rate, steer rate)``."""
        A = self._constraints(roll, pitch, steer)
        W = -np.linalg.solve(A[:, DEPENDENT], A[:, INDEPENDENT])
        u = np.zeros(8)
        u[list(INDEPENDENT)] = independent
        u[list(DEPENDENT)] = W @ np.asarray(independent, dtype=float)
        return u

    def configuration(self, state, torques=(0.0, 0.0)):
        """:class:`Configuration` at the minimal ``state`` (10,) with ``torques`` (roll, steer; N m)."""
        roll, steer = float(state[3]), float(state[5])
        ui = np.asarray(state[7:10], dtype=float)
        pitch = self.pitch(roll, steer)
        A = self._constraints(roll, pitch, steer)[:, _ORDER]
        inverse = np.linalg.inv(A[:, 3:])
        W = -inverse @ A[:, :3]
        u = np.empty(8)
        u[_ORDER] = np.concatenate((ui, W @ ui))
        M, F, b = self._dynamics(roll, pitch, steer, *u, *torques)
        M = M[np.ix_(_ORDER, _ORDER)]
        F = np.asarray(F)[_ORDER]
        S = np.vstack((_EYE3, W))
        s_D = -inverse @ np.asarray(b)
        ST = S.T
        accelerations = np.linalg.solve(ST @ M @ S, ST @ F - ST @ (M[:, 3:] @ s_D))
        rates = np.empty(8)
        rates[_ORDER] = np.concatenate((accelerations, W @ accelerations + s_D))
        return Configuration(pitch, u, accelerations, rates)

    def rates(self, state, torques=(0.0, 0.0)):
        """The time derivative (10,) of the minimal ``state`` (:data:`STATE`)."""
        c = self.configuration(state, torques)
        u, yaw = c.speeds, state[2]
        cy, sy = math.cos(yaw), math.sin(yaw)
        out = np.empty(10)
        out[0] = u[0] * cy - u[1] * sy
        out[1] = u[0] * sy + u[1] * cy
        out[2:7] = u[list(_COORDINATE_RATE)]
        out[7:10] = c.accelerations
        return out

    def energy(self, state):
        """``(kinetic, potential)`` energy (J) at the minimal ``state``; the ground is zero height."""
        roll, steer = state[3], state[5]
        pitch = self.pitch(roll, steer)
        u = self.speeds(roll, pitch, steer, state[7:10])
        kinetic, potential = self._energy(roll, pitch, steer, *u)
        return kinetic, potential

    def heights(self, roll, steer):
        """Heights (m) above the ground of the centres of mass of the rear wheel, rear frame, front
        frame and front wheel at ``roll`` and ``steer`` (rad)."""
        return self._heights(roll, self.pitch(roll, steer), steer)

    def constraint_forces(self, state, torques=(0.0, 0.0)):
        """The multipliers (5,) of the velocity constraints at the minimal ``state``, from
        ``-M u' + F + A^T lambda = 0``: the ground's forces (N) on the contacts along the constraints'
        rows (rear wheel along and across the heading, front wheel along and across its line on the
        ground, then the vertical one of the front wheel, +z down: minus its normal force)."""
        c = self.configuration(state, torques)
        roll, steer = state[3], state[5]
        A = self._constraints(roll, c.pitch, steer)
        M, F, _ = self._dynamics(roll, c.pitch, steer, *c.speeds, *torques)
        ud = c.speed_rates
        return np.linalg.lstsq(A.T, M @ ud - np.asarray(F), rcond=None)[0]
