"""Critical speeds as roots: where a mode's real part (or stability margin) crosses zero.

Each sign change of a mode on the speed grid brackets one root; Brent's method
(:mod:`~bikemass.analysis.stability.roots`) then finds it to ``roots.XTOL`` (1e-13 m/s) on the eigenvalue, at any
speed, that continues the tracked mode (the root nearest to the straight line between
the two bracketing values).  Eigenvalues at single speeds come from LAPACK on the 4x4
state matrix and are memoised (:class:`SpeedEigenvalues`): the two members of a pair,
a mode's range ends and the overall range ends revisit the same speeds.

Every crossing of ``Re = 0`` is classified by the root that crosses, at the crossing:
``oscillatory`` (a complex pair crosses; weave-like) or ``real`` (a real root passes
through zero; capsize-like), whatever its tracked label: a weave pair that has split
into two real roots crosses as a real root.  Two crossings inside one grid step are not
seen: use a finer grid.
"""

from dataclasses import dataclass

import numpy as np

from .criteria import ZERO_TOL, margin
from .roots import brent

KINDS = ("oscillatory", "real")
"""Kinds of crossing: a complex pair or a real root crosses ``Re = 0``."""
DIRECTIONS = ("stabilising", "destabilising")


class SpeedEigenvalues:
    """``at(v)``: the four eigenvalues (1/s) at speed ``v`` (m/s), memoised; LAPACK ``eigvals``
    of the state matrix ``[[0, I], [-M^-1 (g K0 + v^2 K2), -v M^-1 C1]]``."""

    def __init__(self, matrices):
        Minv = np.linalg.inv(matrices.M)
        self._K0, self._K2, self._C1 = Minv @ matrices.gK0, Minv @ matrices.K2, Minv @ matrices.C1
        self._cache = {}

    def __call__(self, v):
        v = float(v)
        out = self._cache.get(v)
        if out is None:
            A = np.zeros((4, 4))
            A[0, 2] = A[1, 3] = 1.0
            A[2:, :2] = -(self._K0 + (v * v) * self._K2)
            A[2:, 2:] = -v * self._C1
            out = self._cache[v] = np.linalg.eigvals(A)
        return out

    @property
    def evaluations(self):
        """How many distinct speeds were solved."""
        return len(self._cache)


def evaluator(matrices_or_at):
    """A :class:`SpeedEigenvalues` (passed through) for canonical matrices or an evaluator."""
    return matrices_or_at if isinstance(matrices_or_at, SpeedEigenvalues) else SpeedEigenvalues(matrices_or_at)


def _tracked_root(roots, values, speeds, i, j, v):
    guess = values[i] + (values[j] - values[i]) * (v - speeds[i]) / (speeds[j] - speeds[i])
    return roots[np.argmin(np.abs(roots - guess))]


def mode_margin(at, speeds, values, i, j, marginal=None):
    """Function ``v -> margin`` on ``[speeds[i], speeds[j]]`` of the mode whose tracked values are ``values``."""
    at = evaluator(at)
    return lambda v: float(margin(_tracked_root(at(v), values, speeds, i, j, v), marginal))


def overall_margin(at, marginal=None):
    """Function ``v -> largest margin of all four eigenvalues`` (negative = all stable)."""
    at = evaluator(at)
    return lambda v: float(np.max(margin(at(v), marginal)))


def root_in(f, a, b):
    """Root of ``f`` in ``[a, b]``; the end nearer a zero value when ``f`` does not change sign."""
    fa, fb = f(a), f(b)
    if fa == 0 or fb == 0 or np.sign(fa) == np.sign(fb):
        return a if abs(fa) <= abs(fb) else b
    return brent(f, a, b, fa, fb)


def sign_changes(x):
    """Pairs ``(i, j)`` of grid indices bracketing each sign change of ``x`` (values within ZERO_TOL of 0 skipped)."""
    s = np.where(x > ZERO_TOL, 1, np.where(x < -ZERO_TOL, -1, 0))
    idx = np.flatnonzero(s)
    change = s[idx[1:]] != s[idx[:-1]]
    return list(zip(idx[:-1][change], idx[1:][change]))


@dataclass(frozen=True)
class Crossing:
    """One crossing of ``Re = 0``: ``speed`` (m/s), ``kind`` (:data:`KINDS`), ``direction``
    (:data:`DIRECTIONS`, as speed grows) and ``mode``, the tracked label of the root."""

    speed: float
    kind: str
    direction: str
    mode: str

    def to_dict(self):
        return {"speed": self.speed, "kind": self.kind, "direction": self.direction, "mode": self.mode}


def crossing_kind(roots, root):
    """``"real"`` or ``"oscillatory"``: the kind of ``root`` (one of ``roots`` at a crossing speed).

    The root that crosses is the one with ``Re = 0``: ``root`` if it is near zero, else
    (a tracked root that jumped to another branch inside the bracket) the root nearest zero.
    """
    if abs(root.real) > 1e-6 * (1.0 + abs(root)):
        root = roots[np.argmin(np.abs(roots.real))]
    return "real" if root.imag == 0 else "oscillatory"


def mode_crossings(at, modes, label):
    """:class:`Crossing` list (ascending speed) where mode ``label``'s real part crosses zero."""
    at = evaluator(at)
    v, values = modes.speeds, modes[label]
    out = []
    for i, j in sign_changes(values.real):
        speed = float(root_in(mode_margin(at, v, values, i, j), v[i], v[j]))
        roots = at(speed)
        kind = crossing_kind(roots, _tracked_root(roots, values, v, i, j, speed))
        out.append(Crossing(speed, kind, DIRECTIONS[0] if values.real[i] > 0 else DIRECTIONS[1], label))
    return out


def all_crossings(at, modes):
    """Every :class:`Crossing` of every labelled mode, by speed (then label order)."""
    at = evaluator(at)
    found = [c for label in modes.labels for c in mode_crossings(at, modes, label)]
    return sorted(found, key=lambda c: (c.speed, modes.labels.index(c.mode)))


def speeds_of_kind(crossings, kind, tol=1e-8):
    """Sorted distinct speeds (m/s) of the crossings of ``kind`` (a pair's two members count once)."""
    out = []
    for s in sorted(c.speed for c in crossings if c.kind == kind):
        if not out or s - out[-1] > tol:
            out.append(s)
    return out
