"""The thesis's open question answered with a rider in the loop (Williams 2015, Sec. 6.1: the
Aerobars and Aero Tuck positions are self-stable up to higher speeds, which "conflicts with
commonly held rider perceptions ... other factors relating to control may be the cause").

Every rider position on the Jamis and the Cargo (corrected run: published bodies and riders,
parallel-axis theorem; rigid frame), ridden by the Hess, Moore & Hubbard (2012) rider with gains
from the published procedure at each speed (:func:`bikemass.handling`): the peak of the handling
quality metric against speed, beside the position's self-stable speeds (corrected run, exact).
"""

import warnings

import numpy as np

from ..analysis.handling.quality import LEVEL_BOUNDS
from ..analysis.handling.survey import handling
from ..core.errors import BikemassWarning
from .configurations import RIDERS, THESIS_NAMES, Configuration
from .runs import CORRECTED
from .tables import Table

BICYCLES = ("jamis", "cargo")
"""The bicycles the question is asked of."""
SPEEDS = tuple(float(v) for v in np.arange(2.0, 12.01, 1.0))
"""Speeds (m/s) at which the rider is tuned and the HQM found."""
SHOWN = (3.0, 4.0, 5.0, 6.0, 8.0, 10.0)
"""Speeds of the report's table (m/s)."""


def handled():
    """The (bike, rider) pairs of the handling question: the five rider positions on each bicycle."""
    return [(bike, rider) for bike in BICYCLES for rider in RIDERS[1:]]


def handling_result(inputs, bike, rider):
    """The :class:`~bikemass.analysis.handling.survey.HandlingResult` of ``rider`` on ``bike``,
    rigid frame (corrected run), over :data:`SPEEDS`."""
    params = inputs.parameters(CORRECTED, Configuration(bike, rider, "infinite"))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BikemassWarning)       # speeds without gains are nan
        return handling(params, SPEEDS)


def stable_speeds(outcomes, bike, rider):
    """The self-stable speed ranges (m/s) of ``bike`` with ``rider``, rigid frame (exact)."""
    outcome = outcomes[Configuration(bike, rider, "infinite")]
    return tuple(tuple(r) for r in outcome.ranges["exact"]["strict"]["overall"])


def level_one_from(result):
    """The lowest speed (m/s) from which the closed loop is stable with an HQM peak below the
    Level 1 bound at every faster speed of the survey, or ``None``."""
    good = result.closed_loop_stable & (result.hqm_peak < LEVEL_BOUNDS[0])
    if not good[-1]:
        return None
    k = len(good) - 1
    while k > 0 and good[k - 1]:
        k -= 1
    return float(result.speeds[k])


def _peak_at(result, speed):
    k = int(np.argmin(np.abs(result.speeds - speed)))
    ok = result.closed_loop_stable[k] and np.isfinite(result.hqm_peak[k])
    return float(result.hqm_peak[k]) if ok else None


def _ranges(ranges):
    return ", ".join(f"{a:.2f}..{b:.2f}" for a, b in ranges) or "-"


def handling_table(results, outcomes):
    """The study's handling table: per bicycle and position its self-stable speeds, the HQM peak at
    :data:`SHOWN` speeds (``-``: no gains or an unstable closed loop) and the Level 1 speed."""
    rows = []
    for bike, by_rider in results.items():
        for rider, result in by_rider.items():
            rows.append([THESIS_NAMES[bike], THESIS_NAMES[rider], _ranges(stable_speeds(outcomes, bike, rider)),
                         *(_peak_at(result, v) for v in SHOWN), level_one_from(result)])
    headers = ("bicycle", "rider", "self-stable (m/s)", *(f"HQM {v:g} m/s" for v in SHOWN), "Level 1 from (m/s)")
    formats = {i: "{:.2f}" for i in range(3, len(headers))}
    return Table("handling", "Handling: the Hess, Moore & Hubbard (2012) rider on every position (rigid frame)",
                 headers, rows, formats,
                 notes=("HQM: peak of the handling quality metric (Level 1 below 5, Level 3 above 8; Hess, Moore "
                        "& Hubbard 2012); gains by the published procedure at each speed (docs/handling.md). "
                        "'-': the procedure found no gains, or they leave the closed loop unstable.",))


def handling_findings(results, outcomes):
    """Plain sentences: what the rider in the loop says about the thesis's question, per bicycle."""
    lines = []
    for bike, by_rider in results.items():
        name = THESIS_NAMES[bike]
        tuned = {r: res for r, res in by_rider.items() if res.closed_loop_stable.any()}
        if not tuned:
            lines.append(f"{name}: the published gain procedure finds no gains that close the loop stably at "
                         f"{SPEEDS[0]:g}-{SPEEDS[-1]:g} m/s for any rider position, so the rider model says "
                         "nothing about its handling (docs/handling.md, \"Where the procedure finds no gains\").")
            continue
        common = [v for v in SPEEDS if all(_peak_at(res, v) is not None for res in tuned.values())]
        slow = common[0] if common else None
        parts = []
        if slow is not None:
            order = sorted(tuned, key=lambda r: _peak_at(tuned[r], slow))
            parts.append(f"at {slow:g} m/s the HQM peak runs from {_peak_at(tuned[order[0]], slow):.2f} "
                         f"({THESIS_NAMES[order[0]]}) to {_peak_at(tuned[order[-1]], slow):.2f} "
                         f"({THESIS_NAMES[order[-1]]})")
        level = {r: level_one_from(res) for r, res in tuned.items()}
        known = {r: v for r, v in level.items() if v is not None}
        if known:
            groups = {}
            for r, v in known.items():
                groups.setdefault(v, []).append(THESIS_NAMES[r])
            parts.append("Level 1 (little rider compensation) is reached from " + " and ".join(
                f"{v:g} m/s ({', '.join(names)})" for v, names in sorted(groups.items())))
        stable_to = {r: max((b for _, b in stable_speeds(outcomes, bike, r)), default=-np.inf) for r in tuned}
        furthest = sorted(tuned, key=lambda r: stable_to[r])[-2:]
        if slow is not None and np.isfinite(stable_to[furthest[0]]):
            hardest = sorted(tuned, key=lambda r: _peak_at(tuned[r], slow))[-2:]
            names = " and ".join(THESIS_NAMES[r] for r in furthest)
            if set(hardest) == set(furthest):
                parts.append(f"the two positions self-stable up to the highest speeds ({names}) are the two that "
                             f"need the most rider compensation at {slow:g} m/s: what riders perceive")
            else:
                parts.append(f"the positions self-stable up to the highest speeds ({names}) are not the ones that "
                             f"need the most rider compensation at {slow:g} m/s ("
                             + " and ".join(THESIS_NAMES[r] for r in hardest) + ")")
        lines.append(f"{name}, rigid frame, Hess-Moore-Hubbard rider: " + "; ".join(parts) + ".")
    return lines
