"""Critical speeds in closed form: where a root of the characteristic quartic reaches Re = 0.

``det(M s^2 + v C1 s + K + v^2 K2) = a4 s^4 + a3 s^3 + a2 s^2 + a1 s + a0`` with
(``u = v^2``, ``x.y`` the symmetric bilinear form with ``x.x = 2 det x``)::

    a4 = det M               a3 = v (M.C1)          a2 = M.K + u (M.K2 + det C1)
    a1 = v (C1.K + u C1.K2)  a0 = det K + u K.K2 + u^2 det K2

* a **real** root crosses Re = 0 at ``s = 0``: ``a0 = 0``, a quadratic in ``u``;
* an **oscillatory** pair crosses at ``s = +-i w``: the real and imaginary parts of
  ``P(i w) = 0`` give ``w^2 = a1 / a3 > 0`` and the Hurwitz determinant
  ``a3 a2 a1 - a4 a1^2 - a3^2 a0 = 0``, which is ``u`` times a quadratic in ``u``.

So every crossing is a root of one of two quadratics in ``v^2`` (no grid, no iteration,
nothing missed between grid speeds).  A crossing's direction and the stable speed ranges
follow from the eigenvalues at one speed inside each interval between crossings.
"""

from dataclasses import dataclass

import numpy as np

OSCILLATORY, REAL = "oscillatory", "real"


def _dot(x, y):
    """Symmetric bilinear form on 2x2 matrices with ``_dot(x, x) = 2 det x``."""
    return x[0, 0] * y[1, 1] + y[0, 0] * x[1, 1] - x[0, 1] * y[1, 0] - y[0, 1] * x[1, 0]


def _det(x):
    return x[0, 0] * x[1, 1] - x[0, 1] * x[1, 0]


def _quadratic_roots(a, b, c):
    """Real roots of ``a u^2 + b u + c`` (``a`` may be 0), computed without cancellation."""
    if a == 0:
        return [] if b == 0 else [-c / b]
    disc = b * b - 4 * a * c
    if disc < 0:
        return []
    q = -0.5 * (b + np.copysign(np.sqrt(disc), b))
    return [q / a, c / q] if q != 0 else [0.0]


@dataclass(frozen=True)
class Crossing:
    speed: float          # m/s
    kind: str             # "oscillatory" | "real"
    direction: str        # "stabilising" | "destabilising" | "touching"
    frequency: float      # |Im| of the crossing root (rad/s), 0 for a real root


@dataclass(frozen=True)
class CriticalSpeeds:
    """All crossings in ``(0, vmax]`` (ascending) and the strictly stable ranges ``[[a, b], ...]``."""

    crossings: tuple
    stable: tuple
    vmax: float

    def first(self, kind):
        """Speed (m/s) of the first crossing of ``kind``, or ``None``."""
        return next((c.speed for c in self.crossings if c.kind == kind), None)

    @property
    def weave_speed(self):
        return self.first(OSCILLATORY)

    @property
    def capsize_speed(self):
        return self.first(REAL)

    @property
    def stable_from(self):
        return self.stable[0][0] if self.stable else None

    @property
    def stable_to(self):
        return self.stable[0][1] if self.stable else None

    def to_dict(self):
        return {"weave_speed": self.weave_speed, "capsize_speed": self.capsize_speed,
                "stable_from": self.stable_from, "stable_to": self.stable_to,
                "crossings": [c.__dict__ for c in self.crossings],
                "stable_ranges": [list(r) for r in self.stable], "max_speed": self.vmax}


def _pieces(system):
    """The speed-independent pieces of the quartic's coefficients (see the module docstring)."""
    M, C1, K, K2 = (np.real(x) for x in (system.M, system.C1, system.K, system.K2))
    return {"a4": _det(M), "alpha": _dot(M, C1), "a20": _dot(M, K), "a21": _dot(M, K2) + _det(C1),
            "beta": _dot(C1, K), "gamma": _dot(C1, K2), "d0": _det(K), "d1": _dot(K, K2), "d2": _det(K2)}


def quartic(system, v, pieces=None):
    """Coefficients ``(a4, a3, a2, a1, a0)`` of the characteristic quartic at speed ``v`` (m/s)."""
    c = pieces or _pieces(system)
    u = v * v
    return (c["a4"], v * c["alpha"], c["a20"] + u * c["a21"], v * (c["beta"] + u * c["gamma"]),
            c["d0"] + u * c["d1"] + u * u * c["d2"])


def crossing_candidates(system, pieces=None):
    """``[(speed, kind, w)]``: every positive speed (m/s) where a root is on the imaginary axis."""
    c = pieces or _pieces(system)
    a4, alpha, a20, a21 = c["a4"], c["alpha"], c["a20"], c["a21"]
    beta, gamma, d0, d1, d2 = c["beta"], c["gamma"], c["d0"], c["d1"], c["d2"]
    out = []
    for u in _quadratic_roots(d2, d1, d0):
        if u > 0:
            out.append((float(np.sqrt(u)), REAL, 0.0))
    if alpha != 0:
        hurwitz = (alpha * a21 * gamma - a4 * gamma ** 2 - alpha ** 2 * d2,
                   alpha * (a20 * gamma + a21 * beta) - 2 * a4 * beta * gamma - alpha ** 2 * d1,
                   alpha * a20 * beta - a4 * beta ** 2 - alpha ** 2 * d0)
        for u in _quadratic_roots(*hurwitz):
            w2 = (beta + u * gamma) / alpha
            if u > 0 and w2 > 0:
                out.append((float(np.sqrt(u)), OSCILLATORY, float(np.sqrt(w2))))
    return sorted(out)


def unstable_count(coefficients):
    """Number of roots with Re > 0 of a real quartic (highest power first): sign changes in the
    first column of the Routh array; ``np.roots`` where that column has a zero."""
    a4, a3, a2, a1, a0 = coefficients
    if a3 != 0:
        b1 = (a3 * a2 - a4 * a1) / a3
        if b1 != 0:
            c1 = (b1 * a1 - a3 * a0) / b1
            if c1 != 0 and a0 != 0:
                column = np.sign([a4, a3, b1, c1, a0])
                return int(np.sum(column[1:] != column[:-1]))
    return int(np.sum(np.roots(coefficients).real > 0))


def critical_speeds(system, vmax=30.0):
    """:class:`CriticalSpeeds` of a :class:`~bikemass.analysis.model.System` on ``(0, vmax]`` m/s."""
    pieces = _pieces(system)
    found = [c for c in crossing_candidates(system, pieces) if c[0] <= vmax]
    ends = [0.0] + [c[0] for c in found] + [vmax]
    counts = [unstable_count(quartic(system, (a + b) / 2, pieces)) if b > a else None
              for a, b in zip(ends, ends[1:])]
    crossings = []
    for k, (speed, kind, w) in enumerate(found):
        before, after = counts[k], counts[k + 1]
        if before is None or after is None or before == after:
            direction = "touching"
        else:
            direction = "stabilising" if after < before else "destabilising"
        crossings.append(Crossing(speed, kind, direction, w))
    stable = []
    for (a, b), n in zip(zip(ends, ends[1:]), counts):
        if n == 0:
            if stable and stable[-1][1] == a:
                stable[-1][1] = b
            else:
                stable.append([a, b])
    return CriticalSpeeds(tuple(crossings), tuple(tuple(r) for r in stable), float(vmax))
