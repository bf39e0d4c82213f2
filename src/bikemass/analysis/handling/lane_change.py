"""A lane change followed by the rider and bicycle in closed loop (Hess, Moore & Hubbard 2012:
"a 2-m lane-change maneuver and return"; the geometry and command path of HumanControl's
``lane_change.m`` and ``WhippleModel.mdl``).

The road (lateral offset ``y``, m, against the distance ``x`` travelled, m): straight to 35 m,
up at slope 0.2 to 2 m at 45 m, held to 85 m, back down to 0 at 95 m, straight to 250 m (a single
lane change stays at 2 m after 45 m).  The rider previews the road: the track ``y(v t)`` passes
the path filter ``F_p(s) = 2.4^2 / (s^2 + 2 (2.4) s + 2.4^2)`` and commands the front contact's
lateral position, while the bicycle meets that road ``tau_p = 2.75 s`` later, so the road at the
front contact is ``y(v (t - tau_p))`` (the preview delays the road, never the rider's command).

The rider on the nonlinear Whipple bicycle (``nonlinear=True``, :func:`follow_nonlinear`): the closed loop is the nonlinear bicycle's minimal state (:data:`bikemass.models.nonlinear.STATE`,
10 entries) with the rider's neuromuscular states (steer torque ``T``, N m, and its rate) and the
path filter's (command ``y_c``, m, and its rate) integrated alongside::

    x'  = f(x, T)                                      the nonlinear bicycle (NonlinearWhipple.rates)
    T'' = w_nm^2 (u - T) - 2 zeta_nm w_nm T'           the neuromuscular system
    u   = k_delta (k_phidot (k_phi (k_psi (k_y (y_c - y_Q) - psi) - phi) - phidot) - delta)
    y_c'' = w_p^2 (y_road(v t) - y_c) - 2 w_p y_c'     the path filter of the linear run

with the loop signals read from the nonlinear state: the steer angle, roll rate, roll angle, the
heading (the yaw) and ``y_Q``, the front contact's lateral position on the ground, computed exactly
from the configuration (:func:`front_contact`).  The gains are those of the linear procedure
(tuned at the speed on the linear model), the road and the preview are the linear run's (the road is read at the nominal speed's distance
``v t``: the rider is given the same command), and the bicycle starts upright and straight at the
speed.  scipy's DOP853 integrates between the road's kinks (rtol 1e-10, atol 1e-10).
"""

import math
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import ArrayLike

from ...core.choices import Choice
from ...core.results import Result, quantity, renamed_units
from ...core.real import finite_real
from ...core.errors import BikemassWarning, InputError, short
from ...core.frozen import FrozenMap, readonly, short_repr
from ...core.limits import MAX_SAMPLES
from ...core.tables import Table
from ...core.threads import one_blas_thread
from .discrete import march
from .gains import Gains, as_gains
from .plant import System, linear_model
from .rider import NEUROMUSCULAR_DAMPING, NEUROMUSCULAR_FREQUENCY, closed_loop, rider_plant
from .tuning import GainsNotFound, tune_gains

START, WIDTH, SLOPE, LENGTH, HELD = 35.0, 2.0, 0.2, 250.0, 40.0
"""The road (m): the manoeuvre starts at 35 m, is 2 m wide, rises at slope 0.2, the road is
250 m long, and a double lane change holds the offset for 40 m (45 to 85 m)."""
PATH_FILTER_FREQUENCY = 2.4
"""``F_p``'s natural frequency (rad/s); its damping ratio is 1."""
PREVIEW = 2.75
"""``tau_p`` (s): how far ahead in time the rider sees the road (steer-torque control)."""


class Manoeuvre(Choice):
    """The lane change driven (a member is its string: ``Manoeuvre.DOUBLE == "double"``).

    See Also
    --------
    bikemass.lane_change : Takes it as ``kind=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> once = bm.lane_change(bm.parameters("benchmark"), 5.0, kind=bm.Manoeuvre.SINGLE)
    >>> print(f"road at the end {once.road[-1]:.1f} m")
    road at the end 2.0 m
    """

    DOUBLE = "double"
    """Over 2 m at 35-45 m, held to 85 m, back to 0 at 95 m."""
    SINGLE = "single"
    """Over 2 m at 35-45 m, held to the road's end."""


KINDS = Manoeuvre.values()
"""The manoeuvres' names: ``("double", "single")``."""


class Dynamics(Choice):
    """Which bicycle a lane change ran on (:attr:`LaneChange.model`).

    Examples
    --------
    >>> import bikemass as bm
    >>> lane = bm.lane_change(bm.parameters("benchmark"), 5.0)
    >>> lane.model is bm.Dynamics.LINEAR, lane.model == "linear"
    (True, True)
    """

    LINEAR = "linear"
    """The linear model about the upright run."""
    NONLINEAR = "nonlinear"
    """The nonlinear Whipple bicycle (:func:`follow_nonlinear`)."""


def check_step(step, speed=None):
    """``step`` (s) as a float: a finite number above 0 giving at most :data:`~bikemass.core.limits.MAX_SAMPLES` samples
    over the road at ``speed`` (m/s, when known); InputError otherwise."""
    if not finite_real(step) or step <= 0:
        raise InputError("step", short(step), "a time step in s, a finite number above 0")
    if speed is not None and speed > 0 and LENGTH / speed / step > MAX_SAMPLES:
        raise InputError("step", short(step), f"a time step of at least {LENGTH / speed / MAX_SAMPLES:.3g} s at "
                         f"{speed:g} m/s (at most {MAX_SAMPLES} samples over the {LENGTH:g} m road)")
    return float(step)


def road(distance, kind="double"):
    """The road's lateral offset (m) at ``distance`` (m) along it."""
    x = np.asarray(distance, dtype=float)
    rise = np.clip(SLOPE * (x - START), 0.0, WIDTH)
    if kind == "single":
        return rise
    back = np.clip(SLOPE * (x - (START + WIDTH / SLOPE + HELD)), 0.0, WIDTH)
    return rise - back


def with_path_filter(A, b):
    """The closed loop ``(A, b)`` (commanded by the lateral position) behind the path filter: two
    more states (the filter's output, m, and its rate, m/s), input the track (m)."""
    n, w = len(A), PATH_FILTER_FREQUENCY
    Af = np.zeros((n + 2, n + 2))
    Af[:n, :n], Af[:n, n] = A, b
    Af[n, n + 1] = 1.0
    Af[n + 1, n], Af[n + 1, n + 1] = -w ** 2, -2 * w
    bf = np.zeros(n + 2)
    bf[n + 1] = w ** 2
    return Af, bf


@dataclass(frozen=True, eq=False, repr=False)
class LaneChange(Result):
    """The closed loop through a lane change at one speed.

    Attributes
    ----------
    speed : float
        m/s.
    time : numpy.ndarray (n,)
        s.
    road : numpy.ndarray (n,)
        The road's lateral offset at the front contact (m).
    command : numpy.ndarray (n,)
        The rider's commanded lateral position of the front contact (m): the previewed, filtered road.
    signals : mapping
        ``{name: samples}`` of the bicycle's states, its lateral position fed back and the rider's
        steer torque (rad, rad/s, m, N m); read-only arrays.
    signal_units : mapping
        ``{name: unit}`` of :attr:`signals` (``units``, its name before 0.3, still reads it with a
        DeprecationWarning; ``units()`` is the units block of :meth:`to_dict`).
    stable : bool
        Whether the closed loop is stable.
    model : Dynamics
        ``"linear"`` or ``"nonlinear"`` (the nonlinear Whipple bicycle; its signals add
        ``forward-speed``, m/s); a string enum.
    stopped : str
        Why a nonlinear run ended before the road's end (a fall); empty otherwise.

    See Also
    --------
    bikemass.lane_change : Makes it.

    Examples
    --------
    >>> import bikemass as bm
    >>> lc = bm.lane_change(bm.parameters("benchmark"), 5.0)
    >>> print(lc.model, lc.stable, f"road up to {lc.road.max():.1f} m")
    linear True road up to 2.0 m
    >>> print(f"steer torque at most {abs(lc.signals['steer-torque']).max():.3f} {lc.signal_units['steer-torque']}")
    steer torque at most 0.155 N m
    """

    speed: float = quantity("m/s", "forward speed")
    time: np.ndarray = quantity("s", "the samples' times")
    road: np.ndarray = quantity("m", "the road's lateral offset at the front contact")
    command: np.ndarray = quantity("m", "the rider's commanded lateral position of the front contact")
    signals: Mapping = quantity("each signal's (signal_units)", "{name: samples}")
    signal_units: Mapping = field(default_factory=FrozenMap)
    stable: bool = False
    model: Dynamics = Dynamics.LINEAR
    stopped: str = ""

    units = renamed_units("signal_units")

    def __post_init__(self):
        for name in ("time", "road", "command"):
            object.__setattr__(self, name, readonly(getattr(self, name), float))
        object.__setattr__(self, "signals", FrozenMap({k: readonly(v, float) for k, v in self.signals.items()}))
        object.__setattr__(self, "signal_units", FrozenMap(self.signal_units))
        object.__setattr__(self, "stable", bool(self.stable))
        object.__setattr__(self, "model", Dynamics(self.model))

    @property
    def distance(self):
        """Where the front contact is along the road (m): ``v (t - tau_p)``, negative before the
        previewed road's start."""
        return readonly(self.speed * (self.time - PREVIEW))

    def to_dict(self):
        """Plain data: speed, time, road, command and every signal."""
        return {"speed": self.speed, "stable": bool(self.stable), "model": str(self.model), "stopped": self.stopped,
                "time": self.time.tolist(),
                "road": self.road.tolist(), "command": self.command.tolist(),
                "signals": {k: v.tolist() for k, v in self.signals.items()}}

    def unit_block(self):
        """The units block of :meth:`to_dict`: the declared units of speed, time, road and command,
        each signal's."""
        declared = self.field_units()
        return {**{k: declared[k] for k in ("speed", "time", "road", "command")}, **self.signal_units}

    def tables(self):
        """``{"signals": Table}``: one row per sample: ``time`` (s), ``road`` and ``command`` (m) and
        every signal in its unit. Speed and stability are the frame's ``attrs``."""
        columns = {"time": self.time, "road": self.road, "command": self.command, **dict(self.signals)}
        units = {k: u for k, u in self.unit_block().items() if k in columns}
        return {"signals": Table(columns, units, {"speed": self.speed, "stable": bool(self.stable)})}

    def __repr__(self):
        return short_repr(self, ("speed", f"{self.speed:g} m/s"), ("model", self.model), ("time", f"0..{self.time[-1]:g} s x {len(self.time)}"),
                          ("stable", self.stable))


def follow_lane_change(closed, lateral_row, names, units, kind="double", step=0.01):
    """:class:`LaneChange` of a :class:`~bikemass.analysis.handling.rider.ClosedLoop`.

    ``lateral_row`` (N,) gives the fed back lateral position from the bicycle's N states; ``names``
    and ``units`` are the bicycle's states'.  The time runs over the whole road (250 m).
    """
    if not isinstance(kind, str) or kind not in KINDS:
        raise InputError("kind", short(kind), f"one of {', '.join(KINDS)}")
    kind = Manoeuvre(kind)
    v = closed.speed
    if not v > 0:
        raise InputError("speed", short(v), "a lane change needs a forward speed above 0 m/s")
    step = check_step(step, v)
    t = np.arange(int(np.floor(LENGTH / v / step)) + 1) * step
    A, b = with_path_filter(closed.A, closed.b)
    x = march(A, b, np.zeros(len(A)), road(v * t, kind), step)
    n = len(names)
    signals = {name: x[:, i] for i, name in enumerate(names)}
    signals[closed.lateral] = x[:, :n] @ lateral_row
    signals["steer-torque"] = x[:, n]
    all_units = {**dict(zip(names, units)), closed.lateral: "m", "steer-torque": "N m"}
    return LaneChange(v, t, road(v * (t - PREVIEW), kind), x[:, n + 2], signals,
                      {k: all_units[k] for k in signals}, closed.stable)


@one_blas_thread()
def lane_change(system: System, speed: float, gains: "Gains | ArrayLike | None" = None,
                kind: str = "double", step: float = 0.01, stiffness: "ArrayLike | None" = None,
                nonlinear: bool = False) -> LaneChange:
    """The rider and bicycle through a 2 m lane change (and back, ``kind="double"``).

    Parameters
    ----------
    system : LinearModel, Scenario, Built, BenchmarkParameters or RiderLeanParameters
        A linear model, a scenario, or a parameter set (the Whipple bicycle, or the leaning rider's
        model of RiderLeanParameters).
    speed : float
        Forward speed (m/s), above 0.
    gains : Gains or five numbers, optional
        ``k_delta, k_phi_dot, k_phi, k_psi, k_y``; default tuned by the published procedure.
    kind : {"double", "single"}
        A lane change and return (default), or one lane change.
    step : float
        Time step of the samples (s); the run covers the whole 250 m road.
    stiffness : array_like (2, 2), optional
        Rear-frame stiffness S (N m/rad) of a parameter set.
    nonlinear : bool
        The rider (the same gains, tuned on the linear model) steering the nonlinear Whipple
        bicycle of a parameter set instead (:func:`follow_nonlinear`;
        docs/nonlinear.md); a fall (roll 60 degrees) ends the run with a warning.

    Returns
    -------
    LaneChange
        ``time``, ``road`` and ``command`` (m), and ``signals`` (roll, steer, lateral position,
        steer torque, ...).

    Raises
    ------
    InputError
        A speed not above 0, gains that are not five finite numbers, an unknown ``kind`` or a bad
        ``step``; ``nonlinear`` with anything but a parameter set, with a stiffness, or where the
        closed loop is unstable.

    See Also
    --------
    handling : The rider's gains and handling qualities over speed.
    plot_lane_change : Draw the run.

    Examples
    --------
    >>> import bikemass as bm
    >>> run = bm.lane_change(bm.parameters("benchmark"), 5.0)
    >>> peak = abs(run.signals["steer-torque"]).max()
    >>> print(run.stable, f"{run.time[-1]:.1f} s, steer torque at most {peak:.3f} N m")
    True 50.0 s, steer torque at most 0.155 N m
    >>> n = bm.lane_change(bm.parameters("benchmark"), 5.0, nonlinear=True)
    >>> print(n.model, f"steer torque at most {abs(n.signals['steer-torque']).max():.4f} N m")
    nonlinear steer torque at most 0.1544 N m
    """
    check_step(step)
    if nonlinear:
        check_parameters(system)
        if stiffness is not None:
            raise InputError("stiffness", short(stiffness), "none: the nonlinear model has a rigid frame")
    if not isinstance(kind, str) or kind not in KINDS:
        raise InputError("kind", short(kind), f"one of {', '.join(KINDS)}")
    kind = Manoeuvre(kind)
    model = linear_model(system, stiffness)
    plant = rider_plant(model, speed)
    check_step(step, plant.speed)
    if gains is None:
        try:
            gains = tune_gains(plant)
        except GainsNotFound as exc:
            raise InputError("speed", f"{plant.speed:g}", f"{exc}; give the gains") from None
    closed = closed_loop(plant, as_gains(gains))
    if nonlinear:
        if not closed.stable:
            raise InputError("speed", f"{plant.speed:g}", "a speed where the rider's closed loop is stable (on the "
                             "linear model, with these gains): otherwise the nonlinear run only diverges")
        return follow_nonlinear(system, closed, kind, step)
    return follow_lane_change(closed, model.output_matrix([plant.lateral])[0], model.state_names,
                              tuple(s.unit for s in model.states), kind, step)


NONLINEAR_RTOL, NONLINEAR_ATOL = 1e-10, 1e-10
"""DOP853's tolerances (relative; absolute in the states' units)."""
NONLINEAR_FALL = math.radians(60.0)
"""Roll (rad) at which a nonlinear run stops as a fall (as :mod:`bikemass.analysis.nonlinear.simulate`)."""
NONLINEAR_NAMES = ("roll-angle", "steer-angle", "roll-rate", "steer-rate", "heading", "lateral", "front-lateral",
         "steer-torque", "forward-speed", "pitch-angle", "energy")
"""The signals of a nonlinear run: the linear run's, then the forward speed of the rear contact, the
pitch and the energy (kinetic plus potential, the ground at zero height)."""
NONLINEAR_UNITS = ("rad", "rad", "rad/s", "rad/s", "rad", "m", "m", "N m", "m/s", "rad", "J")


def _rx(a):
    c, s = math.cos(a), math.sin(a)
    return np.array(((1.0, 0.0, 0.0), (0.0, c, -s), (0.0, s, c)))


def _ry(a):
    c, s = math.cos(a), math.sin(a)
    return np.array(((c, 0.0, s), (0.0, 1.0, 0.0), (-s, 0.0, c)))


def _rz(a):
    c, s = math.cos(a), math.sin(a)
    return np.array(((c, -s, 0.0), (s, c, 0.0), (0.0, 0.0, 1.0)))


def front_contact(parameters, x, y, yaw, roll, pitch, steer):
    """The front wheel's ground contact (3,) in the ground frame (m; x forward, y right, z down) of
    the configuration: the rear contact ``(x, y)``, yaw, roll, pitch and steer (rad).

    The kinematics of :mod:`bikemass.models.derive.bicycle`: the rear frame ``C = Rz(yaw) Rx(roll)
    Ry(pitch)``, the front frame ``E = C Ry(lam) Rz(steer) Ry(-lam)``; the rear wheel's centre ``rR``
    above the rear contact along the roll frame's z, the steer axis's foot ``w + c`` ahead of the rear
    contact, the front axle ``c`` behind it and ``rF`` above along the front frame, and the contact
    ``rF`` below the axle in the wheel's plane, along the steepest descent."""
    p = parameters
    A = _rz(yaw)
    B = A @ _rx(roll)
    C = B @ _ry(pitch)
    E = C @ _ry(p.lam) @ _rz(steer) @ _ry(-p.lam)
    rear_centre = np.array((x, y, 0.0)) - p.rR * B[:, 2]
    foot = rear_centre + (p.w + p.c) * C[:, 0] + p.rR * C[:, 2]
    axle = foot - p.c * E[:, 0] - p.rF * E[:, 2]
    tilt = E[2, 1]                                    # N.z . E.y
    down = np.array((0.0, 0.0, 1.0)) - tilt * E[:, 1]
    return axle + p.rF * down / math.sqrt(1.0 - tilt ** 2)


def follow_nonlinear(parameters, closed, kind="double", step=0.01, scale=1.0):
    """:class:`LaneChange` of the rider (the gains of ``closed``, a
    :class:`~bikemass.analysis.handling.rider.ClosedLoop`) on the nonlinear bicycle of ``parameters``.

    ``scale`` multiplies the road (1: the 2 m lane change; small: the linear limit).  The run stops
    early with ``stopped`` saying why (a fall past 60 degrees of roll, or the integration breaking
    down), keeping every sample before.
    """
    # lazy: scipy's integrator only for a nonlinear run
    from scipy.integrate import solve_ivp
    # lazy: the nonlinear model (its generated code) only for a nonlinear run
    from ...models.nonlinear import ConstraintError, NonlinearWhipple

    v = closed.speed
    gains = tuple(closed.gains)
    products = np.cumprod(gains)                       # k0, k0 k1, ..., k0 .. k4
    w2 = NEUROMUSCULAR_FREQUENCY ** 2
    damping = 2 * NEUROMUSCULAR_DAMPING * NEUROMUSCULAR_FREQUENCY
    wp = PATH_FILTER_FREQUENCY
    bike = NonlinearWhipple(parameters)
    p = parameters

    def track(t):
        return scale * float(road(v * t, kind))

    def lateral(z, pitch):
        return front_contact(p, z[0], z[1], z[2], z[3], pitch, z[5])[1]

    def rates(t, z):
        torque = z[10]
        signals = (z[5], z[8], z[3], z[2], lateral(z, bike.pitch(float(z[3]), float(z[5]))))
        u = products[4] * z[12] - float(np.dot(products, signals))
        out = np.empty(14)
        out[:10] = bike.rates(z[:10], (0.0, torque))
        out[10] = z[11]
        out[11] = w2 * (u - torque) - damping * z[11]
        out[12] = z[13]
        out[13] = wp ** 2 * (track(t) - z[12]) - 2 * wp * z[13]
        return out

    def fall(_, z):
        return NONLINEAR_FALL - abs(z[3])
    fall.terminal = True                               # type: ignore[attr-defined]

    t = np.arange(int(np.floor(LENGTH / v / step)) + 1) * step
    kinks = [START, START + WIDTH / SLOPE]
    if kind == "double":
        kinks += [kinks[1] + HELD, kinks[1] + HELD + WIDTH / SLOPE]
    edges = [0.0, *(d / v for d in kinks if d / v < t[-1]), float(t[-1])]
    z = np.zeros(14)
    z[7] = v
    states, stopped = [z[None, :]], ""
    done = 1
    with np.errstate(over="raise", divide="raise", invalid="raise"):
        for a, b in zip(edges[:-1], edges[1:]):
            upto = int(np.searchsorted(t, b * (1 + 1e-14), side="right"))
            inside = t[done:upto]
            try:
                sol = solve_ivp(rates, (a, b), z, method="DOP853", rtol=NONLINEAR_RTOL, atol=NONLINEAR_ATOL,
                                dense_output=True, events=fall)
            except (ConstraintError, np.linalg.LinAlgError, FloatingPointError, ArithmeticError):
                stopped = f"stopped after t = {a:.6g} s: the integration broke down"
                break
            if sol.status != 0:                        # a fall (the event) or a failure: samples up to it
                inside = inside[inside < sol.t[-1]]
                upto = done + len(inside)
                stopped = (f"stopped at t = {sol.t[-1]:.4f} s: the bicycle fell (roll reached 60 degrees)"
                           if sol.status == 1 else
                           f"stopped after t = {sol.t[-1]:.6g} s: the integration broke down ({sol.message})")
            samples = sol.sol(inside).T if len(inside) and sol.sol is not None else np.zeros((0, 14))
            states.append(samples)
            done = upto
            z = sol.y[:, -1]
            if stopped:
                break
    x = np.concatenate(states)
    t = t[:len(x)]
    pitch, kinetic, potential = bike.samples(x[:, :10])
    front = np.array([lateral(row, th) for row, th in zip(x, pitch)])
    columns = (x[:, 3], x[:, 5], x[:, 8], x[:, 9], x[:, 2], x[:, 1], front, x[:, 10], x[:, 7], pitch,
               kinetic + potential)
    signals = dict(zip(NONLINEAR_NAMES, columns))
    stable = closed.stable
    if stopped:
        warnings.warn(stopped, BikemassWarning, stacklevel=3)
    return LaneChange(v, t, scale * road(v * (t - PREVIEW), kind), x[:, 12], signals,
                      dict(zip(NONLINEAR_NAMES, NONLINEAR_UNITS)), stable, model=Dynamics.NONLINEAR,
                      stopped=stopped)


def check_parameters(system):
    """``system`` as a parameter set for the nonlinear model, else InputError."""
    # lazy: the parameter classes only to check a nonlinear run's system
    from ...models.parameters import BenchmarkParameters
    if not isinstance(system, BenchmarkParameters):
        raise InputError("system", type(system).__name__, "a benchmark parameter set (BenchmarkParameters): the "
                         "nonlinear model is the Whipple bicycle")
    return system
