"""Handling against speed (``bm.handling``): at every speed the rider's gains (tuned, or given),
the closed loop's stability, and the handling quality metric and its peak."""

import math
import numbers
import os
import warnings
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from ...core.choices import Tuning, check
from ...core.real import finite_real
from ...core.errors import BikemassWarning, InputError, short
from ...core.frozen import readonly, short_repr
from ...core.results import Result, quantity
from ...core.tables import Table
from ...core.limits import MAX_SPEED
from ...core.threads import one_blas_thread
from .gains import NAMES, UNITS, Gains, as_gains, read_gain_table
from .plant import System, linear_model
from .quality import hqm, hqm_peak, level
from .rider import closed_loop, rider_plant
from .tuning import GainsNotFound, tune

CURVE_FREQUENCIES = np.linspace(0.01, 40.0, 800)
"""Frequencies (rad/s) of the HQM curves kept for figures (linear, as the published figures)."""
MAX_SURVEY_SPEEDS = 1000
"""Most speeds of one survey (the gains of one speed cost about 0.2 s)."""
SPEED_MATCH = 1e-9
"""How close (m/s) a speed must be to a gains file's to take its gains."""


GRADED_SOURCES = ("tuned", "given")
"""The :attr:`HandlingResult.gain_source` of a speed that has a handling level."""
NO_GAINS = "none: the published procedure found no gains at this speed"


def gain_source(given, found, stable, peak, max_real=0.0):
    """What :attr:`HandlingResult.gain_source` says of one speed: where its gains came from
    (``given`` or tuned; ``found``: whether there are any) and, unless the speed is graded (a
    ``stable`` closed loop and a finite HQM ``peak``), why it has no handling level
    (``max_real``: the closed loop's largest real part, 1/s; ``nan`` where it overflowed)."""
    if not found:
        return NO_GAINS
    source = GRADED_SOURCES[bool(given)]
    if not math.isfinite(max_real):
        return f"{source}: closed loop not computable (the gains overflow it), no handling level"
    if not stable:
        return f"{source}: closed loop unstable, no handling level"
    if not math.isfinite(peak):
        return f"{source}: HQM peak not finite, no handling level"
    return source


def check_speeds(speeds):
    """``speeds`` (m/s) as an increasing 1-D float array in [0, MAX_SPEED]; InputError otherwise."""
    values = np.atleast_1d(np.asarray(speeds, dtype=object))
    if values.ndim != 1 or not 1 <= values.size <= MAX_SURVEY_SPEEDS or not all(
            finite_real(v) and 0 <= v <= MAX_SPEED
            for v in values):
        raise InputError("speeds", short(speeds), f"1 to {MAX_SURVEY_SPEEDS} forward speeds in m/s, finite, "
                         f"in 0..{MAX_SPEED:g}")
    v = values.astype(float)
    if np.any(np.diff(v) <= 0):
        raise InputError("speeds", short(speeds), "increasing speeds (m/s)")
    return v


def given_gains(gains, speeds):
    """``(speeds, [Gains or None per speed])`` from the ``gains`` argument of :func:`handling`."""
    if gains is None:
        if speeds is None:
            raise InputError("speeds", "(argument)", "the speeds (m/s) at which to tune the rider's gains")
        v = check_speeds(speeds)
        return v, [None] * len(v)
    if isinstance(gains, (str, os.PathLike)):
        table, source = read_gain_table(gains), os.fspath(gains)
    elif isinstance(gains, Mapping) and not gains:
        raise InputError("gains", "{}", "{speed in m/s: five gains} with at least one speed")
    elif isinstance(gains, Mapping):
        table, source = {_speed_key(k): as_gains(g, "gains", f"speed {k}") for k, g in gains.items()}, "gains"
    else:
        fixed = as_gains(gains)
        v = check_speeds(speeds) if speeds is not None else None
        if v is None:
            raise InputError("speeds", "(argument)", "the speeds (m/s) at which to use the gains")
        return v, [fixed] * len(v)
    v = check_speeds(sorted(table) if speeds is None else speeds)
    known = np.array(sorted(table))
    chosen = []
    for speed in v:
        k = int(np.argmin(np.abs(known - speed)))
        if abs(known[k] - speed) > SPEED_MATCH:
            raise InputError(source, f"speed {speed:g}", "a row of gains for every speed asked for (speeds in the "
                             f"file: {', '.join(f'{s:g}' for s in known[:12])}{', ...' if len(known) > 12 else ''})")
        chosen.append(table[float(known[k])])
    return v, chosen


def _speed_key(key):
    """A key of a ``{speed: gains}`` mapping as a speed (m/s); InputError unless a finite number >= 0."""
    if isinstance(key, bool) or not isinstance(key, (numbers.Real, str)):
        raise InputError("gains", short(key), "{speed in m/s: five gains}: a speed as each key")
    try:
        speed = float(key)
    except ValueError:
        raise InputError("gains", short(key), "{speed in m/s: five gains}: a speed as each key (for one set of "
                         "gains at every speed, five numbers or bm.Gains)") from None
    if not (math.isfinite(speed) and speed >= 0):
        raise InputError("gains", short(key), "{speed in m/s: five gains}: a finite speed >= 0 as each key")
    return speed


@dataclass(frozen=True, eq=False, repr=False)
class HandlingResult(Result):
    """The rider and bicycle at every speed.

    Attributes
    ----------
    speeds : numpy.ndarray (n,)
        m/s.
    gains : tuple of Gains or None
        The gains used at each speed (``None`` where the procedure found none).
    gain_source : tuple of str
        ``"tuned"`` (the published procedure, :mod:`~bikemass.analysis.handling.tuning`) or
        ``"given"`` at each speed; where the speed gets no handling level, followed by why
        (``"tuned: closed loop unstable, no handling level"``), or ``"none: ..."`` where the
        procedure found no gains (:func:`gain_source`).
    closed_loop_stable : numpy.ndarray (n,) of bool
        Whether every closed-loop eigenvalue has a negative real part.
    max_real : numpy.ndarray (n,)
        The largest closed-loop real part (1/s).
    hqm_peak, hqm_peak_frequency : numpy.ndarray (n,)
        The HQM's peak (dimensionless) and where it is (rad/s); ``nan`` without gains.  Where
        the closed loop is unstable the formula's value is kept but grades nothing
        (:attr:`levels` is ``None`` there).
    hqm_frequencies : numpy.ndarray (k,)
        rad/s, of :attr:`hqm`.
    hqm : numpy.ndarray (n, k)
        The HQM against frequency at each speed.
    lateral : str
        The lateral position the outer loop feeds back (``front-lateral``, or ``lateral``).

    See Also
    --------
    bikemass.handling : Makes it.

    Examples
    --------
    >>> import bikemass as bm
    >>> r = bm.handling(bm.parameters("benchmark"), [5.0])
    >>> r.gain_source, r.levels, r.lateral
    (('tuned',), (1,), 'front-lateral')
    >>> r.units()["k_delta"], r.units()["hqm_peak_frequency"]
    ('N m/rad', 'rad/s')
    """

    speeds: np.ndarray = quantity("m/s", "forward speeds")
    gains: tuple = ()
    gain_source: tuple = ()
    closed_loop_stable: np.ndarray = quantity("", "whether every closed-loop eigenvalue has a negative real part "
                                              "(bool)", default=None)
    max_real: np.ndarray = quantity("1/s", "the largest closed-loop real part", default=None)
    hqm_peak: np.ndarray = quantity("1", "the HQM's peak (dimensionless)", default=None)
    hqm_peak_frequency: np.ndarray = quantity("rad/s", "where the HQM peaks", default=None)
    hqm_frequencies: np.ndarray = quantity("rad/s", "the frequencies of hqm", default=None)
    hqm: np.ndarray = quantity("1", "(n, k) the HQM against frequency at each speed", default=None)
    lateral: str | None = None

    def __post_init__(self):
        for name in ("speeds", "closed_loop_stable", "max_real", "hqm_peak", "hqm_peak_frequency",
                     "hqm_frequencies", "hqm"):
            object.__setattr__(self, name, readonly(getattr(self, name)))
        object.__setattr__(self, "gains", tuple(self.gains))
        object.__setattr__(self, "gain_source", tuple(self.gain_source))

    @property
    def graded(self):
        """Whether each speed has a handling level (n,): gains, a stable closed loop and a finite
        HQM peak.  The HQM of an unstable closed loop is no handling quality (its frequency
        response is never reached), so such a speed gets no level whatever its peak."""
        return readonly(self.closed_loop_stable & np.isfinite(self.hqm_peak))

    @property
    def levels(self):
        """The handling-quality level (1, 2, 3) at each speed; ``None`` where there is none
        (no gains, or the closed loop unstable: :attr:`graded`; :attr:`gain_source` says why)."""
        return tuple(level(p) if ok else None for p, ok in zip(self.hqm_peak, self.graded))

    def gain(self, name):
        """One gain (``k_delta``, ...) at every speed, (n,); ``nan`` without gains."""
        return readonly([getattr(g, name) if g is not None else np.nan for g in self.gains])

    def tables(self):
        """``{"speeds": Table, "hqm": Table}``: one row per speed (the five gains in their units,
        ``nan`` where none were found; ``gain_source``, ``closed_loop_stable``, ``max_real`` 1/s,
        ``hqm_peak``, ``hqm_peak_frequency`` rad/s, ``level``), and one row per frequency of the HQM
        (``frequency`` rad/s, then one column per speed, named by the speed in m/s)."""
        gains = {n: self.gain(n) for n in NAMES}
        columns = {"speed": self.speeds, **gains, "gain_source": list(self.gain_source),
                   "closed_loop_stable": self.closed_loop_stable, "max_real": self.max_real,
                   "hqm_peak": self.hqm_peak, "hqm_peak_frequency": self.hqm_peak_frequency,
                   "level": list(self.levels)}
        declared = self.field_units()
        units = {"speed": declared["speeds"], **UNITS, **{k: declared[k] for k in ("max_real", "hqm_peak",
                                                                                   "hqm_peak_frequency")}}
        attrs = {"lateral_feedback": self.lateral}
        hqm = {"frequency": self.hqm_frequencies, **{f"{v:g}": row for v, row in zip(self.speeds, self.hqm)}}
        return {"speeds": Table(columns, units, attrs),
                "hqm": Table(hqm, {"frequency": declared["hqm_frequencies"],
                                   **{k: declared["hqm"] for k in hqm if k != "frequency"}},
                             {**attrs, "columns": "speeds in m/s"})}

    def to_dict(self):
        """Plain data: speeds, gains, gain_source, closed_loop_stable, closed_loop_max_real,
        hqm_peak, hqm_peak_frequency, level, lateral_feedback (``null`` where no gains were found;
        ``level`` ``null`` also where the closed loop is unstable)."""
        def listed(values):
            return [float(x) if np.isfinite(x) else None for x in values]
        return {"speeds": self.speeds.tolist(),
                "gains": {name: listed(self.gain(name)) for name in NAMES},
                "gain_source": list(self.gain_source),
                "closed_loop_stable": [bool(x) for x in self.closed_loop_stable],
                "closed_loop_max_real": listed(self.max_real),
                "hqm_peak": listed(self.hqm_peak), "hqm_peak_frequency": listed(self.hqm_peak_frequency),
                "level": list(self.levels), "lateral_feedback": self.lateral}

    def units(self):
        """The units block of :meth:`to_dict`: the fields' declared units (``max_real`` written as
        ``closed_loop_max_real``) and each gain's as :class:`~bikemass.analysis.handling.gains.Gains`
        declares it."""
        declared = self.field_units()
        return {"speeds": declared["speeds"], **UNITS, "closed_loop_max_real": declared["max_real"],
                "hqm_peak": declared["hqm_peak"], "hqm_peak_frequency": declared["hqm_peak_frequency"]}

    def unit_block(self):
        """:meth:`units` (its name before 0.3)."""
        return self.units()

    def __repr__(self):
        v = self.speeds
        peaks = ", ".join(f"{p:.3g}" for p in self.hqm_peak[:6]) + (", ..." if len(v) > 6 else "")
        return short_repr(self, ("speeds", f"{v[0]:g}..{v[-1]:g} m/s x {len(v)}"),
                          ("stable", f"{int(self.closed_loop_stable.sum())}/{len(v)}"), ("hqm_peak", f"({peaks})"))


@one_blas_thread()
def handling(system: System, speeds: "ArrayLike | None" = None,
             gains: "Gains | str | os.PathLike | Mapping | ArrayLike | None" = None,
             stiffness: "ArrayLike | None" = None, tuning: "Tuning | str" = Tuning.HMH2012) -> HandlingResult:
    """The rider in the loop at every speed: gains, closed-loop stability and handling qualities.

    Parameters
    ----------
    system : LinearModel, Scenario, Built, BenchmarkParameters or RiderLeanParameters
        A linear model with a steer-torque input and the signals the rider feeds back (every
        bicycle model of bikemass), a scenario, or a parameter set (the Whipple bicycle, or the
        leaning rider's model of RiderLeanParameters).
    speeds : array_like (n,), optional
        Increasing forward speeds (m/s); default the speeds of a gains file or mapping.
    gains : None, str, os.PathLike, mapping or five numbers
        ``None``: tuned at every speed by the published procedure
        (:mod:`~bikemass.analysis.handling.tuning`); a gains file (CSV, header
        ``speed,kDelta,kPhiDot,kPhi,kPsi,kY``) or ``{speed: (k_delta, k_phi_dot, k_phi, k_psi,
        k_y)}``: given per speed (every speed asked for must be there); five numbers: the same at
        every speed.
    stiffness : array_like (2, 2), optional
        Rear-frame stiffness S (N m/rad) of a parameter set.
    tuning : {"hmh2012", "bmd2016"}
        How gains are tuned where none are given (:class:`~bikemass.core.choices.Tuning`): the 10 dB
        rule of Hess, Moore & Hubbard (2012, default) or the damping lines of Moore, Hubbard & Hess
        (2016).

    Returns
    -------
    HandlingResult
        ``gains``, ``closed_loop_stable``, ``hqm_peak`` and the HQM curves at every speed.

    Raises
    ------
    InputError
        Bad speeds, a gains file or mapping without a speed asked for, gains that are not five
        finite numbers, or a system without a steer-torque input.

    Warns
    -----
    BikemassWarning
        At a speed where the procedure finds no gains (results there are ``nan``, not stable),
        and where the closed loop with the gains is unstable (no handling level there).

    See Also
    --------
    plot_handling : Draw the HQM curves and peaks.
    lane_change : The rider through a lane change.
    Gains : The five gains of the rider model.

    Examples
    --------
    >>> import bikemass as bm
    >>> r = bm.handling(bm.parameters("benchmark"), [5.0])
    >>> g = r.gains[0]
    >>> print(f"{g.k_delta:.4f} {g.k_phi_dot:.4f} {g.k_phi:.4f} {g.k_psi:.4f} {g.k_y:.4f}")
    46.5455 -0.0522 12.6611 0.1849 0.0959
    >>> print(bool(r.closed_loop_stable[0]), f"HQM peak {r.hqm_peak[0]:.3f} at {r.hqm_peak_frequency[0]:.2f} rad/s")
    True HQM peak 4.686 at 13.48 rad/s
    """
    tuning = check(Tuning, tuning)
    model = linear_model(system, stiffness)
    v, chosen = given_gains(gains, speeds)
    rows, sources = [], []
    lateral = None
    for speed, given in zip(v, chosen):
        plant = rider_plant(model, speed)
        lateral = plant.lateral
        g = given
        if g is None:
            try:
                g = tune(plant, tuning)
            except GainsNotFound as exc:
                warnings.warn(f"{exc}; that speed is left out", BikemassWarning, stacklevel=2)
        row = _at_speed(plant, g)
        source = gain_source(given is not None, g is not None, row[1], row[3], row[2])
        if g is not None and source not in GRADED_SOURCES:
            origin, reason = source.split(": ", 1)
            warnings.warn(f"at {speed:g} m/s with the {origin} gains: {reason}", BikemassWarning, stacklevel=2)
        rows.append(row)
        sources.append(source)
    return HandlingResult(v, tuple(r[0] for r in rows), tuple(sources),
                          np.array([r[1] for r in rows], bool), np.array([r[2] for r in rows]),
                          np.array([r[3] for r in rows]), np.array([r[4] for r in rows]), CURVE_FREQUENCIES,
                          np.array([r[5] for r in rows]).reshape(len(v), len(CURVE_FREQUENCIES)), lateral)


def _at_speed(plant, gains):
    """``(gains, stable, max real, peak, peak frequency, curve)`` at one speed."""
    if gains is None:
        return None, False, np.nan, np.nan, np.nan, np.full(len(CURVE_FREQUENCIES), np.nan)
    closed = closed_loop(plant, gains)
    if not np.all(np.isfinite(closed.A)):               # gains so large the loop overflows: nothing to grade
        return closed.gains, False, np.nan, np.nan, np.nan, np.full(len(CURVE_FREQUENCIES), np.nan)
    peak, where = hqm_peak(plant, gains)
    return closed.gains, closed.stable, closed.max_real, peak, where, hqm(plant, gains, CURVE_FREQUENCIES)
