"""A lane change followed by the rider and bicycle in closed loop (Hess, Moore & Hubbard 2012:
"a 2-m lane-change maneuver and return"; the geometry and command path of HumanControl's
``lane_change.m`` and ``WhippleModel.mdl``).

The road (lateral offset ``y``, m, against the distance ``x`` travelled, m): straight to 35 m,
up at slope 0.2 to 2 m at 45 m, held to 85 m, back down to 0 at 95 m, straight to 250 m (a single
lane change stays at 2 m after 45 m).  The rider previews the road: the track ``y(v t)`` passes
the path filter ``F_p(s) = 2.4^2 / (s^2 + 2 (2.4) s + 2.4^2)`` and commands the front contact's
lateral position, while the bicycle meets that road ``tau_p = 2.75 s`` later, so the road at the
front contact is ``y(v (t - tau_p))`` (the preview delays the road, never the rider's command).
"""

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from ...core.display import Display
from ...core.real import finite_real
from ...core.errors import InputError, short
from ...core.frozen import FrozenMap, readonly, short_repr
from ...core.tables import Table
from ...core.threads import one_blas_thread
from .discrete import march
from .gains import Gains, as_gains
from .plant import System, linear_model
from .rider import closed_loop, rider_plant
from .tuning import GainsNotFound, tune_gains

START, WIDTH, SLOPE, LENGTH, HELD = 35.0, 2.0, 0.2, 250.0, 40.0
"""The road (m): the manoeuvre starts at 35 m, is 2 m wide, rises at slope 0.2, the road is
250 m long, and a double lane change holds the offset for 40 m (45 to 85 m)."""
PATH_FILTER_FREQUENCY = 2.4
"""``F_p``'s natural frequency (rad/s); its damping ratio is 1."""
PREVIEW = 2.75
"""``tau_p`` (s): how far ahead in time the rider sees the road (steer-torque control)."""
KINDS = ("double", "single")
MAX_SAMPLES = 1_000_000
"""Most samples of one run (its states, a few hundred bytes a sample)."""


def check_step(step, speed=None):
    """``step`` (s) as a float: a finite number above 0 giving at most :data:`MAX_SAMPLES` samples
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
class LaneChange(Display):
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
    units : mapping
        ``{name: unit}`` of :attr:`signals`.
    stable : bool
        Whether the closed loop is stable.
    """

    speed: float
    time: np.ndarray
    road: np.ndarray
    command: np.ndarray
    signals: FrozenMap
    units: FrozenMap
    stable: bool

    def __post_init__(self):
        for name in ("time", "road", "command"):
            object.__setattr__(self, name, readonly(getattr(self, name), float))
        object.__setattr__(self, "signals", FrozenMap({k: readonly(v, float) for k, v in self.signals.items()}))
        object.__setattr__(self, "units", FrozenMap(self.units))

    @property
    def distance(self):
        """Where the front contact is along the road (m): ``v (t - tau_p)``, negative before the
        previewed road's start."""
        return readonly(self.speed * (self.time - PREVIEW))

    def to_dict(self):
        """Plain data: speed, time, road, command and every signal."""
        return {"speed": self.speed, "stable": bool(self.stable), "time": self.time.tolist(),
                "road": self.road.tolist(), "command": self.command.tolist(),
                "signals": {k: v.tolist() for k, v in self.signals.items()}}

    def unit_block(self):
        """The unit of each key of :meth:`to_dict` that holds a quantity."""
        return {"speed": "m/s", "time": "s", "road": "m", "command": "m", **self.units}

    def tables(self):
        """``{"signals": Table}``: one row per sample: ``time`` (s), ``road`` and ``command`` (m) and
        every signal in its unit. Speed and stability are the frame's ``attrs``."""
        columns = {"time": self.time, "road": self.road, "command": self.command, **dict(self.signals)}
        units = {k: u for k, u in self.unit_block().items() if k in columns}
        return {"signals": Table(columns, units, {"speed": self.speed, "stable": bool(self.stable)})}

    def __repr__(self):
        return short_repr(self, ("speed", f"{self.speed:g} m/s"), ("time", f"0..{self.time[-1]:g} s x {len(self.time)}"),
                          ("stable", self.stable))


def follow_lane_change(closed, lateral_row, names, units, kind="double", step=0.01):
    """:class:`LaneChange` of a :class:`~bikemass.analysis.handling.rider.ClosedLoop`.

    ``lateral_row`` (N,) gives the fed back lateral position from the bicycle's N states; ``names``
    and ``units`` are the bicycle's states'.  The time runs over the whole road (250 m).
    """
    if not isinstance(kind, str) or kind not in KINDS:
        raise InputError("kind", short(kind), f"one of {', '.join(KINDS)}")
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
                kind: str = "double", step: float = 0.01, stiffness: "ArrayLike | None" = None) -> LaneChange:
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

    Returns
    -------
    LaneChange
        ``time``, ``road`` and ``command`` (m), and ``signals`` (roll, steer, lateral position,
        steer torque, ...).

    Raises
    ------
    InputError
        A speed not above 0, gains that are not five finite numbers, an unknown ``kind`` or a bad
        ``step``.

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
    """
    check_step(step)
    if not isinstance(kind, str) or kind not in KINDS:
        raise InputError("kind", short(kind), f"one of {', '.join(KINDS)}")
    model = linear_model(system, stiffness)
    plant = rider_plant(model, speed)
    check_step(step, plant.speed)
    if gains is None:
        try:
            gains = tune_gains(plant)
        except GainsNotFound as exc:
            raise InputError("speed", f"{plant.speed:g}", f"{exc}; give the gains") from None
    closed = closed_loop(plant, as_gains(gains))
    return follow_lane_change(closed, model.output_matrix([plant.lateral])[0], model.state_names,
                              tuple(s.unit for s in model.states), kind, step)
