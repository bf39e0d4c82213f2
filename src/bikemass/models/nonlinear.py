"""The nonlinear Whipple bicycle of one benchmark parameter set: its minimal equations of motion.

The generated code (:mod:`bikemass.models.generated.nonlinear_whipple`, derived by
:mod:`bikemass.models.derive.nonlinear`) gives, for a configuration (roll, pitch, steer), the
generalised forces of every speed as if all were independent, ``H = -M u' + F``, the velocity
constraints ``A u = 0`` (``A u' + b = 0``, ``b`` by a complex step) and the holonomic constraint
``f = 0`` (the front wheel touching the ground).  Here they become Kane's equations of the constrained system::

    u_D = W u_I,   W = -A_D^-1 A_I            the dependent speeds (yaw, pitch, lateral, wheel rates)
    u'  = S u_I' + s,  S = [1; W],  s_D = -A_D^-1 b
    S^T M S u_I' = S^T (F - M s)              Kane's equations (the contact forces drop out)

with the independent speeds ``u_I``: the rear contact's forward speed ``u_lon`` (m/s), the roll rate
and the steer rate (rad/s).  The pitch is solved from the holonomic constraint by Newton's method
whenever it is needed, so the constraints hold to round-off along any trajectory; ``A_D`` is
regular at zero steer, upright or rolled (tests/test_models_nonlinear.py).

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

SPEEDS = ("u_lon", "u_lat", "u_psi", "u_phi", "u_theta", "u_betaR", "u_delta", "u_betaF")
"""The speeds in the order of :attr:`Configuration.speeds`: the rear contact's velocity along and
across the heading (m/s), then the rates (rad/s) of yaw, roll, pitch, rear wheel, steer, front wheel."""
_NATURAL = np.array([_code.SPEEDS.index(n) for n in SPEEDS])
"""Where each of :data:`SPEEDS` sits in the generated order (independent speeds first)."""
INDEPENDENT = tuple(SPEEDS.index(n) for n in _code.SPEEDS[:3])
"""Indices in :data:`SPEEDS` of the independent speeds: forward speed, roll rate, steer rate."""
DEPENDENT = tuple(SPEEDS.index(n) for n in _code.SPEEDS[3:])
"""Indices in :data:`SPEEDS` of the dependent speeds, in the order the constraints fix them."""
_RATES = np.array([_code.SPEEDS.index(n) for n in ("u_psi", "u_phi", "u_betaR", "u_delta", "u_betaF")])
"""Where (generated order) the rates of the state's yaw, roll, rear wheel, steer, front wheel sit."""
_LON, _LAT = _code.SPEEDS.index("u_lon"), _code.SPEEDS.index("u_lat")
_EYE3 = np.eye(3)

COMPLEX_STEP = 1e-20
"""The step (s) of the complex-step derivative of the constraints along the motion: its error is of
the order of its square, far below round-off."""

PITCH_STEP = 1e-8
"""Newton on the pitch stops after a step below this (rad): it converges quadratically, so the pitch
is then off by about the step squared times f''/2f' (under 1e-16 rad; round-off)."""
PITCH_TOLERANCE = 1e-15
"""Newton on the pitch of many samples at once stops when every step is below this (rad)."""


def _solve3(a, r):
    """``a^-1 r`` (3,) for a 3x3 ``a`` and ``r`` given as lists (Cramer's rule: a numpy call costs
    more than the arithmetic); ArithmeticError when ``a`` is singular."""
    (a00, a01, a02), (a10, a11, a12), (a20, a21, a22) = a
    c00, c01, c02 = a11 * a22 - a12 * a21, a12 * a20 - a10 * a22, a10 * a21 - a11 * a20
    det = a00 * c00 + a01 * c01 + a02 * c02
    if det == 0.0 or not math.isfinite(det):
        raise ArithmeticError("the reduced mass matrix is singular")
    r0, r1, r2 = r
    x0 = (r0 * c00 + r1 * (a02 * a21 - a01 * a22) + r2 * (a01 * a12 - a02 * a11)) / det
    x1 = (r0 * c01 + r1 * (a00 * a22 - a02 * a20) + r2 * (a02 * a10 - a00 * a12)) / det
    x2 = (r0 * c02 + r1 * (a01 * a20 - a00 * a21) + r2 * (a00 * a11 - a01 * a10)) / det
    return np.array((x0, x1, x2))


class ConstraintError(ArithmeticError):
    """The holonomic constraint has no solution near the guess (front wheel off the ground or across)."""


@dataclass(frozen=True)
class Configuration:
    """One instant of the nonlinear bicycle: the pitch (rad), every speed (``speeds`` in the
    order of :data:`SPEEDS`: ``u_lon, u_lat, yaw rate, roll rate, pitch rate, rear wheel rate, steer rate,
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
        functions = dict(zip((name for name, _, _ in _code.FUNCTIONS), _code.bind(*values)))
        self._functions = functions
        self._holonomic, self._constraints = functions["holonomic"], functions["constraints"]
        self._complex_constraints, self._dynamics = functions["constraints_complex"], functions["dynamics"]
        self._energy, self._heights = functions["energy"], functions["heights"]
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
            if abs(step) <= PITCH_STEP:
                self._guess = theta
                return theta
        raise ConstraintError(f"no pitch puts the front wheel on the ground at roll {roll:.6g} rad, "
                              f"steer {steer:.6g} rad")

    def speeds(self, roll, pitch, steer, independent):
        """Every speed (8,) in the order of :data:`SPEEDS` from the independent ones ``(u_lon, roll
        rate, steer rate)``."""
        return self._speeds(roll, pitch, steer, np.asarray(independent, dtype=float))[_NATURAL]

    def _speeds(self, roll, pitch, steer, ui):
        """Every speed in the generated order (independent first)."""
        A = self._constraints(roll, pitch, steer)
        return np.concatenate((ui, -np.linalg.solve(A[:, 3:], A[:, :3] @ ui)))

    def _solve(self, state, torques):
        """``(pitch, speeds, speed rates)``, both in the generated order (independent first)."""
        roll, steer = float(state[3]), float(state[5])      # floats: the generated code runs on them
        ui = np.asarray(state[7:10], dtype=float)
        pitch = self.pitch(roll, steer)
        A = self._constraints(roll, pitch, steer)
        inverse = np.linalg.inv(A[:, 3:])
        W = inverse @ A[:, :3]
        W *= -1.0
        u = np.concatenate((ui, W @ ui))
        speeds = u.tolist()
        M, F = self._dynamics(roll, pitch, steer, *speeds, *torques)
        h = COMPLEX_STEP                # A' u = Im A(q + i h q') u / h, q' = (roll, pitch, steer rates)
        b = self._complex_constraints(complex(roll, h * speeds[1]), complex(pitch, h * speeds[3]),
                                      complex(steer, h * speeds[2])).imag @ u
        b /= h
        s_D = inverse @ b
        s_D *= -1.0
        S = np.vstack((_EYE3, W))
        ST = S.T
        accelerations = _solve3((ST @ (M @ S)).tolist(), (ST @ (np.asarray(F) - M[:, 3:] @ s_D)).tolist())
        return pitch, u, np.concatenate((accelerations, W @ accelerations + s_D))

    def steady_forces(self, state, torques=(0.0, 0.0)):
        """The generalised forces (3,) of the independent speeds (forward, roll, steer) with every
        acceleration zero, ``S^T (F - M s)``: zero in a steady motion (N, N m, N m)."""
        state = np.asarray(state, dtype=float)
        roll, steer = float(state[3]), float(state[5])
        ui = state[7:10]
        pitch = self.pitch(roll, steer)
        A = self._constraints(roll, pitch, steer)
        inverse = np.linalg.inv(A[:, 3:])
        W = -inverse @ A[:, :3]
        u = np.concatenate((ui, W @ ui))
        speeds = u.tolist()
        M, F = self._dynamics(roll, pitch, steer, *speeds, *torques)
        h = COMPLEX_STEP
        b = self._complex_constraints(complex(roll, h * speeds[1]), complex(pitch, h * speeds[3]),
                                      complex(steer, h * speeds[2])).imag @ u / h
        s_D = -inverse @ b
        S = np.vstack((_EYE3, W))
        return S.T @ (np.asarray(F) - M[:, 3:] @ s_D)

    def configuration(self, state, torques=(0.0, 0.0)):
        """:class:`Configuration` at the minimal ``state`` (10,) with ``torques`` (roll, steer; N m)."""
        pitch, u, ud = self._solve(np.asarray(state, dtype=float), torques)
        return Configuration(pitch, u[_NATURAL], ud[:3].copy(), ud[_NATURAL])

    def rates(self, state, torques=(0.0, 0.0)):
        """The time derivative (10,) of the minimal ``state`` (:data:`STATE`)."""
        _, u, ud = self._solve(state, torques)
        yaw = state[2]
        cy, sy = math.cos(yaw), math.sin(yaw)
        out = np.empty(10)
        out[0] = u[_LON] * cy - u[_LAT] * sy
        out[1] = u[_LON] * sy + u[_LAT] * cy
        out[2:7] = u[_RATES]
        out[7:10] = ud[:3]
        return out

    def energy(self, state):
        """``(kinetic, potential)`` energy (J) at the minimal ``state``; the ground is zero height."""
        roll, steer = float(state[3]), float(state[5])
        pitch = self.pitch(roll, steer)
        u = self._speeds(roll, pitch, steer, np.asarray(state[7:10], dtype=float))
        kinetic, potential = self._energy(roll, pitch, steer, *u.tolist())
        return kinetic, potential

    def samples(self, states):
        """``(pitch, kinetic, potential)``: arrays (n,) at the minimal ``states`` (n, 10), evaluated
        for all of them at once (the pitch by Newton's method on every sample together)."""
        f = self._functions
        states = np.asarray(states, dtype=float)
        roll, steer = states[:, 3], states[:, 5]
        pitch = np.zeros(len(states))
        for _ in range(30):
            (value,), (_, dtheta, _) = f["holonomic_arrays"](roll, pitch, steer)
            step = value / dtheta
            pitch -= step
            if np.all(np.abs(step) <= PITCH_TOLERANCE * (1.0 + np.abs(pitch))):
                break
        else:
            raise ConstraintError("no pitch puts the front wheel on the ground at some sample")
        A = np.array(f["constraints_arrays"](roll, pitch, steer)).T.reshape(len(states), 5, 8)
        ui = states[:, 7:10]
        dependent = -np.linalg.solve(A[:, :, 3:], (A[:, :, :3] @ ui[:, :, None]))[:, :, 0]
        u = np.concatenate((ui, dependent), axis=1)
        kinetic, potential = f["energy_arrays"](roll, pitch, steer, *u.T)
        return pitch, kinetic, potential

    def heights(self, roll, steer):
        """Heights (m) above the ground of the centres of mass of the rear wheel, rear frame, front
        frame and front wheel at ``roll`` and ``steer`` (rad)."""
        return self._heights(roll, self.pitch(roll, steer), steer)

    def constraint_forces(self, state, torques=(0.0, 0.0)):
        """The multipliers (5,) of the velocity constraints at the minimal ``state``, from
        ``-M u' + F + A^T lambda = 0``: the ground's forces (N) on the contacts along the constraints'
        rows (rear wheel along and across the heading, front wheel along and across its line on the
        ground, then the vertical one of the front wheel, +z down: minus its normal force)."""
        state = np.asarray(state, dtype=float)
        pitch, u, ud = self._solve(state, torques)
        roll, steer = float(state[3]), float(state[5])
        A = self._constraints(roll, pitch, steer)
        M, F = self._dynamics(roll, pitch, steer, *u.tolist(), *torques)
        return np.linalg.lstsq(A.T, M @ ud - np.asarray(F), rcond=None)[0]
