"""Exact derivatives of the weave and capsize speeds with respect to the 26 benchmark parameters.

At a critical speed ``v*`` a root ``lambda`` of the state matrix ``A(v, p)`` has ``Re = 0``.
With right and left eigenvectors ``x``, ``y`` (``y^H`` = a row of ``X^-1``)::

    d lambda / d p = y^H (dA/dp) x / (y^H x),     d lambda / d v = y^H (dA/dv) x / (y^H x)

and, by the implicit function theorem on ``Re lambda(v, p) = 0``::

    d v* / d p = -Re(d lambda / d p) / Re(d lambda / d v)

``dA/dp`` comes from the complex step through the matrix formulas
(:mod:`bikemass.analysis.model`), so every number is exact to rounding: there is no
finite-difference step anywhere.  Elasticities are ``(p / v*) d v* / d p``
(per cent change of the speed per per cent change of the parameter).
"""

from dataclasses import dataclass

import numpy as np

from ..parameters import NAMES
from .crossings import OSCILLATORY, REAL, critical_speeds
from .model import state_matrix_derivatives, system, values_of

SPEEDS = {"weave_speed": OSCILLATORY, "capsize_speed": REAL}
"""Output name -> crossing kind (first crossing of that kind on (0, vmax])."""


def crossing_root(A, kind, frequency):
    """Index of the eigenvalue of ``A`` that is on the imaginary axis (``+i w`` or 0), its
    eigenvalues and right eigenvectors."""
    values, X = np.linalg.eig(A)
    target = 1j * frequency if kind == OSCILLATORY else 0.0
    return int(np.argmin(np.abs(values - target))), values, X


def speed_derivatives(sys_, dA, speed, kind, frequency):
    """``{name: d speed / d p}`` at a crossing from ``{name: dA/dp}`` (see the module docstring)."""
    A = np.real(sys_.state_matrix(speed))
    i, _, X = crossing_root(A, kind, frequency)
    Y = np.linalg.inv(X)                      # rows: left eigenvectors, normalised so y^H x = 1

    def dlam(dM):
        return Y[i] @ dM @ X[:, i]
    dv = dlam(np.real(sys_.state_matrix_speed_derivative(speed))).real
    return {name: float(-dlam(d).real / dv) for name, d in dA.items()}


@dataclass(frozen=True)
class Sensitivity:
    """Critical speeds (m/s, ``None`` if none) and their derivatives ``{name: (m/s) per unit}``."""

    params: dict
    weave_speed: float
    capsize_speed: float
    d_weave_speed: dict
    d_capsize_speed: dict

    def elasticities(self, which):
        """``{name: (p / v) dv/dp}`` for ``which`` in ``weave_speed`` | ``capsize_speed``."""
        v, d = getattr(self, which), getattr(self, "d_" + which)
        return {k: (self.params[k] * x / v if v else None) for k, x in d.items()}

    def to_dict(self):
        return {"weave_speed": self.weave_speed, "capsize_speed": self.capsize_speed,
                "d_weave_speed": self.d_weave_speed, "d_capsize_speed": self.d_capsize_speed,
                "elasticity_weave_speed": self.elasticities("weave_speed"),
                "elasticity_capsize_speed": self.elasticities("capsize_speed")}


def sensitivity(params, S=None, vmax=30.0, names=NAMES):
    """:class:`Sensitivity` of ``params`` (:class:`~bikemass.parameters.BenchmarkParameters`) with
    rear-frame stiffness ``S`` (2x2 N m/rad or ``None``); crossings searched on ``(0, vmax]`` m/s."""
    sys_ = system(values_of(params), S)
    found = critical_speeds(sys_, vmax)
    speeds, derivs = {}, {}
    for key, kind in SPEEDS.items():
        crossing = next((c for c in found.crossings if c.kind == kind), None)
        speeds[key] = None if crossing is None else crossing.speed
        if crossing is None:
            derivs[key] = {n: None for n in names}
            continue
        dA = state_matrix_derivatives(params, crossing.speed, S, names)
        derivs[key] = speed_derivatives(sys_, dA, crossing.speed, kind, crossing.frequency)
    return Sensitivity(params=values_of(params), weave_speed=speeds["weave_speed"],
                       capsize_speed=speeds["capsize_speed"], d_weave_speed=derivs["weave_speed"],
                       d_capsize_speed=derivs["capsize_speed"])


def sensitivity_figure(result, title=""):
    """Horizontal bar chart of the elasticities of both speeds (a matplotlib Figure)."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(10, 7.5), layout="constrained")
    axes = fig.subplots(1, 2, sharey=True)
    names = list(result.d_weave_speed)
    y = np.arange(len(names))
    for ax, which, colour in zip(axes, SPEEDS, ("tab:blue", "tab:red")):
        e = result.elasticities(which)
        vals = [np.nan if e[n] is None else e[n] for n in names]
        ax.barh(y, vals, color=colour)
        ax.axvline(0, color="k", lw=0.6)
        v = getattr(result, which)
        ax.set_title(f"{which.replace('_', ' ')} = {v:.4f} m/s" if v else f"{which.replace('_', ' ')}: none")
        ax.set_xlabel("elasticity (p/v) dv/dp")
        ax.grid(axis="x", alpha=0.3)
    axes[0].set_yticks(y, names)
    axes[0].invert_yaxis()
    if title:
        fig.suptitle(title)
    return fig
