"""Why an entry is missed: is the thesis's value within reach of the rounding of its printed inputs?

The thesis-mode run uses the thesis's inputs as printed: Table 3-9 and Table 3-4 to
three decimals (SI units), Table 3-12 to five significant digits.  The thesis computed
with unrounded values.  For a missed entry the configuration is re-run with its
printed inputs perturbed by half a unit of their last printed digit: each input
alone by + and - (one at a time), and :data:`JOINT_SAMPLES` runs with all inputs drawn
at once uniformly within +-half a unit (fixed seed).  If the thesis's value lies within
the spread of the entry over these runs, the miss is "explained by the rounding of
the printed parameters"; otherwise it is reported as not explained.
"""

import dataclasses
from dataclasses import dataclass

import numpy as np

from ..mass.inertia import MassProperties, combine, combine_without_parallel_axis
from .runs import THESIS, evaluate
from .stability_tables import TOLERANCE, single_run

TABLE_DECIMALS = 3
"""Tables 3-9 and 3-4 print three decimals (m, kg, kg m^2, rad)."""
STIFFNESS_DIGITS = 5
"""Table 3-12 prints five significant digits (N m/rad)."""
FRAME_PARAMETERS = ("w", "c", "lam", "rR", "mR", "IRxx", "IRyy", "xB", "zB", "mB", "IBxx", "IByy",
                    "IBzz", "IBxz", "xH", "zH", "mH", "IHxx", "IHyy", "IHzz", "IHxz", "rF", "mF",
                    "IFxx", "IFyy")
"""Printed Table 3-9 values (lam = pi/2 - the printed head angle)."""
RIDER_PARAMETERS = ("mass", "x", "z", "Ixx", "Iyy", "Izz", "Ixz")
STIFFNESS_PARAMETERS = ("Kpp", "Kpd", "Kdd")
JOINT_SAMPLES = 64
SEED = 20150501


def with_rider(frame, rider, how="thesis"):
    """``frame`` (BenchmarkParameters, no rider) with ``rider`` (MassProperties) on the rear frame.

    ``how``: ``thesis`` (Eq. 3.6, inertias added) or ``exact`` (parallel-axis theorem).
    """
    if rider is None:
        return frame
    B = MassProperties(frame.mB, [frame.xB, 0.0, frame.zB], frame.inertia("B"))
    total = (combine if how == "exact" else combine_without_parallel_axis)((B, rider))
    I = total.inertia
    return dataclasses.replace(frame, mB=total.mass, xB=total.com[0], zB=total.com[2],
                               IBxx=I[0, 0], IByy=I[1, 1], IBzz=I[2, 2], IBxz=I[0, 2])


def half_unit_of_stiffness(value):
    """Half a unit of the last of :data:`STIFFNESS_DIGITS` significant digits of ``value``."""
    return 0.5 * 10.0 ** (np.floor(np.log10(abs(value))) - (STIFFNESS_DIGITS - 1))


@dataclass(frozen=True)
class PrintedInputs:
    """The printed inputs of one configuration: frame parameters, rider, S (or None)."""

    frame: object
    rider: object
    S: object

    def names(self):
        """Names of the printed inputs that can be perturbed."""
        return (FRAME_PARAMETERS + (RIDER_PARAMETERS if self.rider is not None else ())
                + (STIFFNESS_PARAMETERS if self.S is not None else ()))

    def half_units(self):
        half = 0.5 * 10.0 ** -TABLE_DECIMALS
        S = self.S
        stiff = ((half_unit_of_stiffness(S[0, 0]), half_unit_of_stiffness(S[0, 1]),
                  half_unit_of_stiffness(S[1, 1])) if S is not None else ())
        return np.array([half] * (len(self.names()) - len(stiff)) + list(stiff))

    def perturbed(self, deltas):
        """(frame with rider as the thesis combined them, S) with ``deltas`` (one per name) added."""
        d = dict(zip(self.names(), deltas))
        frame = dataclasses.replace(self.frame, **{k: getattr(self.frame, k) + d[k] for k in FRAME_PARAMETERS})
        rider = self.rider
        if rider is not None:
            I = rider.inertia + np.array([[d["Ixx"], 0, d["Ixz"]], [0, d["Iyy"], 0], [d["Ixz"], 0, d["Izz"]]])
            rider = MassProperties(rider.mass + d["mass"], rider.com + [d["x"], 0, d["z"]], I)
        S = self.S
        if S is not None:
            S = S + np.array([[d["Kpp"], d["Kpd"]], [d["Kpd"], d["Kdd"]]])
        return with_rider(frame, rider, THESIS.combine), S


@dataclass(frozen=True)
class Explanation:
    """Spread ``low..high`` (m/s; ``none_reached``: some run had no stable range) of an entry."""

    explained: bool
    low: float
    high: float
    none_reached: bool
    runs: int
    movers: tuple

    def text(self):
        if self.runs == 0:
            return "not explained: the benchmark's parameters are exact (nothing printed to round)"
        spread = "no stable run" if self.low is None else f"{self.low:.2f}..{self.high:.2f} m/s"
        if self.none_reached and self.low is not None:
            spread += " or no stable run"
        movers = ", ".join(self.movers) or "none"
        verdict = ("explained by the rounding of the printed parameters" if self.explained
                   else "not explained by the rounding of the printed parameters")
        return (f"{verdict}: +-half a unit of the last printed digit gives {spread} over {self.runs} "
                f"runs (largest effect: {movers})")


def _largest_effects(base, values, names, half, count=3):
    """``"name +h -> value"`` of the (at most ``count``) one-at-a-time runs moving the entry most.

    ``values``: the entry after ``+half`` for every name, then after ``-half``; only runs
    that move it by at least a grid step (or make it appear or vanish) are listed.
    """
    def shift(v):
        if v is None or base is None:
            return 0.0 if v is base else np.inf
        return abs(v - base)
    labels = [f"{name} {sign}{h:g}" for sign in "+-" for name, h in zip(names, half)]
    moved = sorted(((shift(v), label, v) for label, v in zip(labels, values)), key=lambda m: -m[0])
    return tuple(f"{label} -> {'none' if v is None else f'{v:.2f}'}"
                 for d, label, v in moved[:count] if d > TOLERANCE / 2)


def _value(entry, params, S, configuration):
    outcome = evaluate(configuration, params, S, exact=False)
    return single_run(outcome.ranges["grid"][entry.criterion][entry.mode], entry.part)[0]


def explain(entry, inputs):
    """:class:`Explanation` of a missed :class:`~bikemass.study.stability_tables.Entry`."""
    c = entry.configuration
    if c.is_benchmark:
        return Explanation(False, None, None, False, 0, ())
    frame = inputs.parameters(THESIS, type(c)(c.bike, "none", c.stiffness))
    rider_name = THESIS.rider_name(c.rider)
    rider = None if rider_name is None else inputs.rider(rider_name).properties("exact")
    printed = PrintedInputs(frame, rider, inputs.stiffness(THESIS, c))
    half = printed.half_units()
    n = len(half)
    one_at_a_time = np.concatenate([np.diag(half), -np.diag(half)])
    joint = np.random.default_rng(SEED).uniform(-1, 1, (JOINT_SAMPLES, n)) * half
    values = [_value(entry, *printed.perturbed(d), c) for d in np.concatenate([one_at_a_time, joint])]
    numbers = [v for v in values if v is not None]
    low, high = (min(numbers), max(numbers)) if numbers else (None, None)
    none_reached = len(numbers) < len(values)
    if entry.thesis is None:
        explained = none_reached
    else:
        explained = bool(numbers) and low - 1e-9 <= entry.thesis <= high + 1e-9
    movers = _largest_effects(entry.ours, values[:2 * n], printed.names(), half)
    return Explanation(explained, low, high, none_reached, len(values), movers)
