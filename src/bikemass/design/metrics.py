"""What a design can be scored by: the metrics of ``bikemass optimise``, their units and their values.

Three kinds of metric:

* **speeds** of the linear model's crossings of ``Re = 0`` on ``(0, max_speed]`` (m/s): the weave,
  capsize and wobble speeds (the first crossing of each), and the widest strictly self-stable speed
  range (``stable-range``, its width; ``stable-from`` and ``stable-to``, its ends).  A speed's
  gradient is exact in the model's parameters (eigenvalue derivatives,
  :func:`bikemass.analysis.sensitivity.speed_derivatives`);
* **parameter functions** of the benchmark set of the bicycle with its rider seated (trail, wheel
  flop, wheelbase, the front wheel's share of the weight, the total mass, any of the 26 parameters
  by name): differentiated by the complex step, exact to rounding;
* **geometry** of the built bicycle and seated rider (toe overlap): differentiated by central
  differences in the design variables.

A speed that does not exist on the span (no weave crossing below ``max_speed``, no stable range) is
given the value of its limit (:data:`UNDEFINED`: ``max_speed`` for a crossing, 0 for a range's width)
with a zero gradient, and the optimiser's result says so.
"""

from dataclasses import dataclass
from types import SimpleNamespace

import numpy as np

from ..analysis.engine.crossings import OSCILLATORY, REAL
from ..analysis.engine.naming import WOBBLE, family, is_weave
from ..analysis.handling.quality import hqm, hqm_peak
from ..analysis.handling.rider import closed_loop, rider_plant
from ..analysis.handling.tuning import GainsNotFound, tune
from ..core.errors import InputError, short
from ..models.parameters import NAMES, parameter_units
from ..rider.fit import FOOT_PER_INSEAM, SHOE, TOE_AHEAD_OF_BALL

SPEED, PARAMETERS, GEOMETRY, HANDLING = "speed", "parameters", "geometry", "handling"
"""The kinds of metric (see the module docstring)."""


@dataclass(frozen=True)
class Metric:
    """One metric: its name (as in a spec), SI unit, kind and what it is."""

    name: str
    unit: str
    kind: str
    description: str


def _front_load(p):
    """Share of the weight on the front wheel (1): ``x_T / w``, the whole bicycle's (rider
    included) centre of mass ahead of the rear contact over the wheelbase (moments about the rear
    contact)."""
    mass = p.mR + p.mB + p.mH + p.mF
    return (p.xB * p.mB + p.xH * p.mH + p.w * p.mF) / mass / p.w


PARAMETER_FUNCTIONS = {
    "trail": (lambda p: p.c, "m", "trail c: the steer axis' ground point ahead of the front contact"),
    "wheel-flop": (lambda p: p.c * np.sin(p.lam) * np.cos(p.lam), "m",
                   "wheel flop c sin(lam) cos(lam): the front's drop per unit steer at small angles"),
    "wheelbase": (lambda p: p.w, "m", "wheelbase w"),
    "front-load": (_front_load, "1", "share of the bicycle's and rider's weight on the front wheel (rider "
                   "seated; EN 15194 asks at least 0.25)"),
    "total-mass": (lambda p: p.mR + p.mB + p.mH + p.mF, "kg", "mass of the bicycle with its rider"),
}
"""Parameter functions: ``name -> (f(params), unit, description)``; ``f`` takes any object with the
26 attributes, complex values included (the complex step)."""

SPEEDS = {
    "weave-speed": "the first speed where the weave crosses Re = 0 (the lower end of self-stability)",
    "capsize-speed": "the first speed where a real root (capsize) crosses Re = 0",
    "wobble-speed": "the first speed where the wobble crosses Re = 0 (models with the flexible member)",
    "stable-range": "width of the widest strictly self-stable speed range",
    "stable-from": "lower end of the widest strictly self-stable speed range",
    "stable-to": "upper end of the widest strictly self-stable speed range",
}
UNDEFINED = {"stable-range": 0.0}
"""The value given to a speed metric where it does not exist on the span: 0 for a range's width,
``max_speed`` (the span's end) for every other."""

HANDLINGS = {
    "hqm-peak": ("1", "peak of the handling quality metric at the spec's speed, the rider's gains tuned by its "
                      "tuning (hmh2012 or bmd2016); a design for which the tuning finds no gains scores 100"),
    "closed-loop-real": ("1/s", "largest real part of the rider-and-bicycle closed loop's eigenvalues at the spec's "
                                "speed (the gains tuned as for hqm-peak); 100 where no gains are found"),
}
NO_GAINS = 100.0
"""The ``hqm-peak`` and ``closed-loop-real`` of a design for which the tuning finds no gains."""
STABILITY_MARGIN = 1e-5
"""1/s: where ``hqm-peak`` is optimised without a bound on ``closed-loop-real``, the closed loop is held to
``closed-loop-real <= -STABILITY_MARGIN`` (the HQM's optima lie on the edge of closed-loop stability:
Moore, Hubbard & Hess 2016's optimal bicycles have a lightly damped pair there)."""

GEOMETRIES = {
    "toe-overlap": ("m", "how far the toe (crank forward) reaches into the front wheel's circle; negative: "
                         "the clearance (needs a rider with an inseam: a person or a chain pose)"),
}


def catalogue():
    """``{name: Metric}`` of every metric, the 26 parameters last."""
    units = parameter_units()
    out = {name: Metric(name, "m/s", SPEED, text) for name, text in SPEEDS.items()}
    out.update({name: Metric(name, unit, PARAMETERS, text) for name, (_, unit, text) in PARAMETER_FUNCTIONS.items()})
    out.update({name: Metric(name, unit, GEOMETRY, text) for name, (unit, text) in GEOMETRIES.items()})
    out.update({name: Metric(name, unit, HANDLING, text) for name, (unit, text) in HANDLINGS.items()})
    out.update({name: Metric(name, units[name], PARAMETERS, f"benchmark parameter {name}") for name in NAMES})
    return out


def metric(name, source="metric"):
    """The :class:`Metric` called ``name``; InputError listing the metrics otherwise."""
    known = catalogue()
    if not isinstance(name, str) or name not in known:
        raise InputError(source, short(name), f"a metric: {', '.join(known)}")
    return known[name]


def parameter_function(name):
    """``f(params)`` of a parameter metric (a function of the benchmark set)."""
    if name in PARAMETER_FUNCTIONS:
        return PARAMETER_FUNCTIONS[name][0]
    return lambda p: getattr(p, name)


COMPLEX_STEP = 1e-30


def parameter_gradient(name, params):
    """``{parameter: d metric / d parameter}`` of parameter metric ``name`` at ``params`` (a
    :class:`~bikemass.models.parameters.BenchmarkParameters`), by the complex step."""
    f = parameter_function(name)
    base = {n: float(getattr(params, n)) for n in NAMES}
    out = {}
    for n in NAMES:
        stepped = SimpleNamespace(**{**base, n: base[n] + 1j * COMPLEX_STEP})
        out[n] = float(np.imag(f(stepped)) / COMPLEX_STEP)
    return out


def speed_crossings(name, critical):
    """``(value or None, crossings)`` of speed metric ``name`` from a
    :class:`~bikemass.analysis.engine.critical.CriticalSpeeds`: the crossings whose speeds make the
    value, as ``((sign, crossing), ...)`` (``value = sum sign * crossing.speed``); a range end at
    the span's limit is no crossing (it does not move with the design)."""
    crossings = critical.crossings
    if name in ("weave-speed", "capsize-speed", "wobble-speed"):
        test = {"weave-speed": lambda c: c.kind == OSCILLATORY and is_weave(c.mode),
                "capsize-speed": lambda c: c.kind == REAL,
                "wobble-speed": lambda c: c.kind == OSCILLATORY and family(c.mode) == WOBBLE}[name]
        found = next((c for c in crossings if test(c)), None)
        return (None, ()) if found is None else (found.speed, ((1.0, found),))
    if not critical.stable:
        return None, ()
    lo, hi = max(critical.stable, key=lambda r: r[1] - r[0])
    ends = {e: next((c for c in crossings if c.speed == e), None) for e in (lo, hi)}
    if name == "stable-from":
        parts, value = ((1.0, ends[lo]),), lo
    elif name == "stable-to":
        parts, value = ((1.0, ends[hi]),), hi
    else:
        parts, value = ((1.0, ends[hi]), (-1.0, ends[lo])), hi - lo
    return value, tuple((s, c) for s, c in parts if c is not None)


def toe_overlap_of(bicycle, inseam):
    """Signed toe overlap (m) of a rider of ``inseam`` (m) on ``bicycle``: positive where the toe
    (crank forward and level) reaches into the front wheel's circle, negative the clearance
    (:func:`bikemass.rider.fit.toe_overlap` without its floor at 0)."""
    contacts = bicycle.contacts
    if contacts is None:
        raise InputError("toe-overlap", "(bicycle)", "a bicycle with pedals (contacts) for the toe overlap")
    toe = contacts.pedal(0.0) + [TOE_AHEAD_OF_BALL * FOOT_PER_INSEAM * inseam + SHOE, 0.0, 0.0]
    g = bicycle.geometry
    gap = float(np.hypot(toe[0] - g.front_axle[0], toe[2] - g.front_axle[2]))
    return g.front_wheel_radius - gap


CURVE_FREQUENCIES = np.geomspace(0.05, 40.0, 240)
"""Where the HQM curve is held below the peak in a minimax search of ``hqm-peak`` (rad/s; the HQM's
peaks lie between the weave's and the filter's 20 rad/s)."""


def rider_in_loop(model, speed, tuning):
    """``(plant, gains)`` of a linear model at ``speed`` (m/s), the rider's gains tuned by ``tuning``;
    ``gains`` is ``None`` where the tuning finds none."""
    plant = rider_plant(model, speed)
    try:
        return plant, tuple(tune(plant, tuning))
    except GainsNotFound:
        return plant, None


def handling_of(plant, gains):
    """``(hqm-peak, closed-loop-real)`` of a rider plant and gains (:func:`rider_in_loop`): the HQM peak and
    the closed loop's largest real part (1/s), :data:`NO_GAINS` for both without gains."""
    if gains is None:
        return NO_GAINS, NO_GAINS
    return hqm_peak(plant, gains)[0], closed_loop(plant, gains).max_real


def hqm_curve_of(plant, gains):
    """The HQM at :data:`CURVE_FREQUENCIES` (:data:`NO_GAINS` everywhere without gains)."""
    if gains is None:
        return np.full(len(CURVE_FREQUENCIES), NO_GAINS)
    return hqm(plant, gains, CURVE_FREQUENCIES)
