"""The rider's gains for any bicycle and speed: the automated procedure of Hess, Moore & Hubbard
(2012) as Moore (2012) states it and his HumanControl code runs it (``generate_data.m``,
``exact_gains``; tags ``ieee`` and ``dissertation``).

Sequential loop closure, inner to outer, each loop with the inner ones closed and the outer ones
open:

1. ``k_delta`` and ``k_phidot``: the closed steer-angle loop ``delta / delta_c``, then the closed
   roll-rate loop ``phidot / phidot_c``, has a resonant (neuromuscular) peak 10 dB above the
   "valley" just below it (Moore 2012: "the desired 10 dB peaking", Fig. 10.13; "The gain
   choices for proper neuromuscular peaks ... require good initial guesses, as there are often
   multiple solutions.  The correct solution puts the neuromuscular natural frequency at a
   typical value").  The peak and the valley are found as HumanControl's ``delta_mag_closed``
   finds them, on its grid of 1000 frequencies from 0.01 to 100 rad/s
   (:func:`peak_to_valley`).  Where HumanControl starts its root finder from the published gains,
   bikemass scans the gain (``k_delta > 0``, ``k_phidot < 0``: Moore 2012, the roll-rate
   feedback is positive) and, of the gains where the ratio passes 10 dB, keeps those whose peak
   belongs to a stable pole pair (past the gain where the loop's resonance turns unstable the
   ratio falls through 10 dB again) and takes the one whose peak lies nearest 10 rad/s (Moore
   2012's design requirement 3): the neuromuscular peak, not the weave's (at low speeds the
   weave makes a 10 dB peak of its own near 2 rad/s at small ``k_delta``).
2. ``k_phi``, ``k_psi``, ``k_y``: the open roll, heading and lateral loops cross over at 2, 1 and
   0.5 rad/s: ``k = 1 / |G_o(j w_c)|`` with that loop's gain 1 (Moore 2012, Eqs. ``eqKPhi``,
   ``eqKPsi``, ``eqKYq``).  HumanControl interpolates ``|G_o|`` linearly on 1000 frequencies
   instead, which moves the fourth or fifth digit; bikemass evaluates it at ``w_c``.

Moore, Hubbard & Hess (2016, BMD, "An optimal handling bicycle") choose the two inner gains
otherwise (:func:`tune_gains_bmd2016`, ``tuning="bmd2016"``): one pole pair of each closed inner loop
on a line of constant damping ratio, 0.1289 for the steer loop and 0.0855 for the roll-rate loop
(the dampings the 10 dB rule gives the benchmark bicycle at 5 m/s), the outer loops crossing over as
above.  The paper solves twelve polynomial equations (the closed loops' characteristic polynomials
matched to a quadratic factor of that damping times a quartic) from a starting guess; bikemass finds
every solution instead: closing one loop with gain ``k`` puts a pole at ``s`` where
``1 + k G(s) = 0`` (``G`` the loop's open transfer function), so a pole lies on the damping line
``s = w (-zeta + j sqrt(1 - zeta^2))`` exactly where ``Im G(s) = 0`` there, with ``k = -1 / Re G(s)``:
a one-dimensional root search in ``w``.  Which of the solutions is taken: :func:`tune_gains_bmd2016`.
It finds the negative ``k_delta`` and positive ``k_phidot`` of the optimal bicycles, which the 10 dB
scan (``k_delta > 0``) cannot reach.

The procedure and its other published variant (Moore 2012's worked root-locus example) are
compared in docs/handling.md.
"""

import numpy as np
import scipy.optimize

from ...core.threads import one_blas_thread
from .frequency import response
from .gains import Gains
from .rider import loop_system
from .transfer import coupled_states
from ...core.choices import Tuning, check

PEAK_DB = 10.0
"""Height of the neuromuscular peak over the valley below it (dB)."""
PEAK_FREQUENCIES = np.logspace(-2, 2, 1000)
"""Where the closed inner loops' magnitude is looked at (rad/s): HumanControl's grid."""
VALLEY_FALLBACK = 3.0
"""Where the roll-rate loop's valley is taken when the magnitude has no flat point (rad/s;
HumanControl's ``wMid``)."""
CROSSOVERS = (2.0, 1.0, 0.5)
"""Crossover frequencies (rad/s) of the open roll angle, heading and lateral loops."""
SCANS = ((0.5, 5e3, 1.0), (1e-4, 10.0, -1.0))
"""``(smallest, largest |k|, sign)`` over which ``k_delta`` and ``k_phidot`` are scanned."""
SCAN_FACTOR = 1.25
"""Ratio of consecutive gains of the scan (the neuromuscular root and the next root of the same
loop, where that loop's closure turns unstable and back, lie a factor of about 3 apart)."""
NEUROMUSCULAR_TARGET = 10.0
"""Where the closed inner loops' neuromuscular peak should lie (rad/s): Moore 2012, design
requirement 3 ("a natural frequency around 10 rad/s", typical of laboratory tracking tasks)."""


DAMPING_LINES = (0.1289, 0.0855)
"""The damping ratios of the steer and roll-rate loops' placed pole pairs (Moore, Hubbard & Hess 2016)."""
LINE_FREQUENCIES = np.geomspace(0.05, 300.0, 3000)
"""Where along a damping line the poles are sought (rad/s): from below the weave to beyond the
neuromuscular system's 30 rad/s."""


class GainsNotFound(ValueError):
    """The procedure found no gain for a loop (at very low speeds the 10 dB peak may not exist)."""


def peak_to_valley(magnitude, loop):
    """``|G|`` at its peak over ``|G|`` at the valley below it, by HumanControl's rule.

    The magnitude is cut at its maximum; the valley is the last point before the maximum of the
    second difference at which the second difference turns from negative to positive (the flat
    part of the slope).  Without one, the steer loop takes the smallest first difference and
    the roll-rate loop the frequency nearest :data:`VALLEY_FALLBACK`.
    """
    top = int(np.argmax(magnitude))
    m = magnitude[:top + 1]
    first = np.concatenate([[0.0], np.diff(m)])
    second = np.concatenate([[0.0], np.diff(first)])
    start = int(np.argmax(second))
    turns = np.nonzero((second[:start] < 0) & (second[1:start + 1] > 0))[0]
    if turns.size:
        valley = int(turns[-1]) + 1
    elif loop == 0:
        valley = int(np.argmin(first))
    else:
        valley = int(np.argmin(np.abs(VALLEY_FALLBACK - PEAK_FREQUENCIES[:top + 1])))
    return magnitude[top] / m[valley]


def closed_magnitude(plant, gains, loop):
    """``|G|`` of the closed loop ``loop`` (inner loops closed) on :data:`PEAK_FREQUENCIES`."""
    A, b, c = loop_system(plant, gains, loop, (True,) * (loop + 1))
    keep = coupled_states(A, b, c)
    return np.abs(response(A[np.ix_(keep, keep)], b[keep], c[keep], PEAK_FREQUENCIES))


def resonance_is_stable(plant, gains, loop, frequency):
    """Whether the closed-loop pole that makes the peak at ``frequency`` (rad/s; the pole of
    positive imaginary part nearest ``j frequency``) has a negative real part: a peak of an
    unstable loop is no resonance."""
    A, b, c = loop_system(plant, gains, loop, (True,) * (loop + 1))
    poles = np.linalg.eigvals(A)
    upper = poles[poles.imag > 0]
    if not upper.size:
        return False
    return bool(upper[np.argmin(np.abs(upper - 1j * frequency))].real < 0)


def inner_gain(plant, gains, loop):
    """``k_delta`` (``loop`` 0) or ``k_phidot`` (1) with the inner ``gains`` set: the 10 dB peak.

    Every gain of the scan where the peak-to-valley ratio passes 10 dB (either way) is a
    candidate, refined to its root.  Candidates whose peak belongs to a stable pole pair come
    first (where there are any), and of those the one whose peak lies nearest
    :data:`NEUROMUSCULAR_TARGET` (on a log scale) is taken.
    """
    low, high, sign = SCANS[loop]
    target = 10 ** (PEAK_DB / 20)

    def excess(size):
        magnitude = closed_magnitude(plant, (*gains, sign * size), loop)
        return peak_to_valley(magnitude, loop) - target

    sizes = np.geomspace(low, high, int(np.ceil(np.log(high / low) / np.log(SCAN_FACTOR))) + 1)
    values = np.array([excess(k) for k in sizes])
    found = []
    for i in np.nonzero(np.sign(values[:-1]) != np.sign(values[1:]))[0]:
        size = scipy.optimize.brentq(excess, sizes[i], sizes[i + 1], xtol=1e-12, rtol=1e-13)
        k = (*gains, sign * size)
        peak = PEAK_FREQUENCIES[int(np.argmax(closed_magnitude(plant, k, loop)))]
        found.append((not resonance_is_stable(plant, k, loop, peak), abs(np.log(peak / NEUROMUSCULAR_TARGET)), size))
    if not found:
        raise GainsNotFound(f"no {('k_delta', 'k_phi_dot')[loop]} gives the {PEAK_DB:g} dB neuromuscular peak "
                            f"at {plant.speed:g} m/s")
    return sign * min(found)[2]


def crossover_gain(plant, gains, loop, frequency):
    """The gain of the open ``loop`` (2, 3 or 4; inner ``gains`` set) that crosses it over at
    ``frequency`` (rad/s): ``1 / |G_o(j w_c)|``; :class:`GainsNotFound` for the lateral loop (4) at
    standstill, where the heading moves the bicycle no sideways (``y' = v psi``) and ``|G_o|`` is
    round-off."""
    if loop == 4 and plant.speed == 0:
        raise GainsNotFound("no k_y at 0 m/s: a standing bicycle's heading does not move it sideways")
    A, b, c = loop_system(plant, (*gains, 1.0), loop, (True,) * loop + (False,))
    return float(1 / np.abs(response(A, b, c, [frequency])[0]))


@one_blas_thread()
def tune_gains(plant):
    """The five gains of a :class:`~bikemass.analysis.handling.rider.RiderPlant` by the procedure
    above; :class:`GainsNotFound` when a loop has no solution."""
    gains = []
    for loop in (0, 1):
        gains.append(inner_gain(plant, gains, loop))
    for loop, frequency in zip((2, 3, 4), CROSSOVERS):
        gains.append(crossover_gain(plant, gains, loop, frequency))
    return Gains(*gains)


def damping_line_gains(plant, gains, loop, zeta):
    """Every ``(w, k)``: a gain ``k`` of loop ``loop`` (0: ``k_delta``, 1: ``k_phidot``; the inner
    ``gains`` set) that puts a pole pair of the closed loop on the damping line ``zeta``, at frequency
    ``w`` (rad/s) on :data:`LINE_FREQUENCIES` (see the module docstring)."""
    A, b, c = loop_system(plant, (*gains, 1.0), loop, (True,) * loop + (False,))
    direction = -zeta + 1j * np.sqrt(1.0 - zeta ** 2)
    values, vectors = np.linalg.eig(A)
    left = np.linalg.solve(vectors, b)
    right = c @ vectors

    def transfer(w):
        """``G(s)`` on the line at ``w`` (rad/s; an array): the modal sum, every pole simple."""
        s = np.multiply.outer(np.atleast_1d(w), direction)
        return (right * left / (s[:, None] - values)).sum(axis=1)

    im = transfer(LINE_FREQUENCIES).imag
    found = []
    for i in np.nonzero(np.sign(im[:-1]) * np.sign(im[1:]) < 0)[0]:
        w = scipy.optimize.brentq(lambda x: float(transfer(x)[0].imag), LINE_FREQUENCIES[i], LINE_FREQUENCIES[i + 1],
                                  xtol=1e-13, rtol=1e-14)
        g = transfer(w)[0]
        if abs(g.imag) > 1e-9 * abs(g) or g.real == 0:        # a pole of G crossing the line, not a root
            continue
        found.append((float(w), float(-1.0 / g.real)))
    return found


@one_blas_thread()
def tune_gains_bmd2016(plant):
    """The five gains of a :class:`~bikemass.analysis.handling.rider.RiderPlant` by Moore, Hubbard & Hess
    (2016): a pole pair of each inner loop on :data:`DAMPING_LINES`, the outer loops crossing over at
    :data:`CROSSOVERS`; :class:`GainsNotFound` when an inner loop has no solution.

    The damping lines have several solutions (:func:`damping_line_gains`); the paper takes the one its
    root finder reaches from a starting guess.  bikemass takes, of every pair of inner solutions with
    the outer loops closed, those that close the whole loop stably (if any), and of those the one
    whose roll-rate loop moves the very pole pair the steer loop placed (the two pairs' frequencies
    nearest each other on a log scale): that gives the published gains of the benchmark and of the
    optimal bicycles for 4, 5, 6 and 8 m/s (tests/test_handling_bmd2016.py)."""
    choices = []
    for w0, k0 in damping_line_gains(plant, [], 0, DAMPING_LINES[0]):
        for w1, k1 in damping_line_gains(plant, [k0], 1, DAMPING_LINES[1]):
            gains = [k0, k1]
            for loop, frequency in zip((2, 3, 4), CROSSOVERS):
                gains.append(crossover_gain(plant, gains, loop, frequency))
            A, _, _ = loop_system(plant, gains, 4, (True,) * 5)
            stable = bool(np.linalg.eigvals(A).real.max() < 0)
            choices.append((not stable, abs(np.log(w1 / w0)), abs(np.log(w0 / NEUROMUSCULAR_TARGET)),
                            tuple(gains)))
    if not choices:
        raise GainsNotFound(f"no k_delta and k_phi_dot put the inner loops' pole pairs on the damping lines "
                            f"{DAMPING_LINES[0]:g} and {DAMPING_LINES[1]:g} at {plant.speed:g} m/s")
    return Gains(*min(choices)[3])


def tune(plant, tuning=Tuning.HMH2012):
    """The gains of ``plant`` by ``tuning`` (:class:`~bikemass.core.choices.Tuning`: ``"hmh2012"``, the
    10 dB rule, or ``"bmd2016"``, the damping lines)."""
    return {Tuning.HMH2012: tune_gains, Tuning.BMD2016: tune_gains_bmd2016}[check(Tuning, tuning)](plant)
