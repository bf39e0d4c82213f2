"""The handling quality metric (HQM) of the rider and bicycle, after Hess (2006) as Hess, Moore &
Hubbard (2012) extend it to the bicycle; the definition as Moore, Hubbard & Hess (2016, BMD,
Eq. ``hqm-def``) state it and HumanControl computes it (``WhippleModel.mdl``, ``isHandling``)::

    HQM(w) = | F_hq(j w) U_m(j w) / phi_c(j w) | / |k_phi|,    U_m = phidot + delta / k_phidot

``U_m`` is the rate signal of the primary (roll angle) loop, the whole signal the roll-rate
junction feeds back; the steer, roll-rate and roll loops are closed, the heading and lateral
loops open, and the command is the roll angle's.  ``F_hq(s) = 400 / (s^2 + 40 s + 400)``
(20 rad/s, critically damped) filters it (HumanControl's ``handlingFilterNum/Den``).

Levels (Moore, Hubbard & Hess 2016 after Hess 2006, from Cooper-Harper ratings 1-3.5, 3.5-6.5,
above 6.5): a peak below 5 is Level 1 ("little rider compensation required"), 5 to 8 Level 2
("moderate"), above 8 Level 3 ("significant").  The bounds hold for a roll loop crossing over
at 2 rad/s, which the tuned gains give.
"""

import numpy as np
import scipy.optimize

from .frequency import response
from .rider import loop_system

FILTER_FREQUENCY = 20.0
"""``F_hq``'s natural frequency (rad/s); its damping ratio is 1."""
LEVEL_BOUNDS = (5.0, 8.0)
"""HQM peaks separating Levels 1 | 2 | 3."""
PEAK_RANGE = (0.01, 40.0)
"""Where the peak is sought (rad/s; HumanControl's ``handling_vs_speed.m`` grid)."""
PEAK_GRID = 2000
"""Frequencies (logarithmic over :data:`PEAK_RANGE`) before the peak is refined."""


def hqm_filter(frequencies):
    """``|F_hq(j w)|`` at ``frequencies`` (rad/s)."""
    s = 1j * np.asarray(frequencies, dtype=float)
    w = FILTER_FREQUENCY
    return np.abs(w ** 2 / (s ** 2 + 2 * w * s + w ** 2))


def hqm(plant, gains, frequencies):
    """``HQM(w)`` (dimensionless) of a :class:`~bikemass.analysis.handling.rider.RiderPlant` with
    ``gains`` (five, inner first) at ``frequencies`` (rad/s)."""
    gains = tuple(gains)
    rate = plant.rows[1] + plant.rows[0] / gains[1]
    A, b, c = loop_system(plant, gains, 2, (True, True, True), output=rate)
    return hqm_filter(frequencies) * np.abs(response(A, b, c, frequencies)) / abs(gains[2])


def hqm_peak(plant, gains):
    """``(peak, frequency)``: the largest HQM over :data:`PEAK_RANGE` (rad/s), found on
    :data:`PEAK_GRID` logarithmic frequencies and refined between the neighbours of the largest."""
    w = np.geomspace(*PEAK_RANGE, PEAK_GRID)
    values = hqm(plant, gains, w)
    k = int(np.argmax(values))
    if k in (0, len(w) - 1):
        return float(values[k]), float(w[k])
    best = scipy.optimize.minimize_scalar(lambda x: -hqm(plant, gains, [x])[0], bounds=(w[k - 1], w[k + 1]),
                                          method="bounded", options={"xatol": 1e-10})
    if -best.fun >= values[k]:
        return float(-best.fun), float(best.x)
    return float(values[k]), float(w[k])


def level(peak):
    """The handling-quality level (1, 2, 3) of an HQM peak."""
    return 1 + int(np.searchsorted(LEVEL_BOUNDS, peak, side="right"))
