"""Exact derivatives of the weave and capsize speeds with respect to the 26 benchmark parameters.

At a critical speed ``v*`` a root ``lambda`` of the state matrix ``A(v, p)`` has ``Re = 0``.
With right and left eigenvectors ``x``, ``y`` (``y^H`` = a row of ``X^-1``)::

    d lambda / d p = y^H (dA/dp) x / (y^H x),     d lambda / d v = y^H (dA/dv) x / (y^H x)

and, by the implicit function theorem on ``Re lambda(v, p) = 0``::

    d v* / d p = -Re(d lambda / d p) / Re(d lambda / d v)

For the Whipple model ``dA/dp`` comes from the complex step through the one model builder
(:mod:`bikemass.analysis.model`), so every number is exact to rounding: there is no
finite-difference step anywhere, and the critical speeds are the engine's closed form
(:mod:`bikemass.analysis.engine.closed_form`), the same numbers ``bm.stability`` reports.  Any
other member of the family (a :class:`~bikemass.scenario.scenario.Scenario` with ``model=``) goes
through the engine: its critical speeds are :func:`~bikemass.analysis.engine.critical.critical_speeds`
(the weave's crossing, as ``bm.stability`` names it), and ``dA/dp`` of its generated code is a five-point
central difference in each parameter (relative step :data:`MEMBER_STEP`; truncation error of order
``step**4``, rounding of order ``1e-16 / step``: about 1e-10 relative).  Elasticities are
``(p / v*) d v* / d p`` (per cent change of the speed per per cent change of the parameter).
"""

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from ..models.parameters import NAMES
from .engine import closed_form
from .engine.crossings import OSCILLATORY, REAL
from .model import STIFFNESS_ENTRIES, model_of, state_matrix_derivatives, stiffness_state_derivatives, values_of
from .engine.critical import critical_speeds
from .results import _stiffness
from ..core.display import Display
from ..core.limits import MAX_SPEED
from ..core.real import finite_real
from ..core.errors import InputError, short
from ..core.keywords import renamed_keywords
from ..models.parameters import BenchmarkParameters
from ..models.plausibility import check_parameters
from ..core.errors import wrong_type
from ..scenario.scenario import Built, Scenario

SPEEDS = {"weave_speed": OSCILLATORY, "capsize_speed": REAL}
"""Output name -> crossing kind (first crossing of that kind on (0, vmax])."""


def crossing_root(A, kind, frequency):
    """Index of the eigenvalue of ``A`` that is on the imaginary axis (``+i w`` or 0), its
    eigenvalues and right eigenvectors."""
    values, X = np.linalg.eig(A)
    target = 1j * frequency if kind == OSCILLATORY else 0.0
    return int(np.argmin(np.abs(values - target))), values, X


def speed_derivatives(model, dA, speed, kind, frequency):
    """``{name: d speed / d p}`` at a crossing of ``model`` from ``{name: dA/dp}`` (dynamic blocks;
    see the module docstring)."""
    n = model.n_dynamic
    A = np.real(model.dynamic_matrix(speed))
    i, _, X = crossing_root(A, kind, frequency)
    Y = np.linalg.inv(X)                      # rows: left eigenvectors, normalised so y^H x = 1

    def dlam(dM):
        return Y[i] @ dM @ X[:, i]
    dv = dlam(np.real(model.speed_derivative(speed))[:n, :n]).real
    return {name: float(-dlam(d).real / dv) for name, d in dA.items()}


@dataclass(frozen=True, repr=False)
class Sensitivity(Display):
    """Critical speeds (m/s, ``None`` if none) and their derivatives ``{name: (m/s) per unit}``."""

    params: dict
    weave_speed: float
    capsize_speed: float
    d_weave_speed: dict
    d_capsize_speed: dict
    d_stiffness: dict = None      # {speed key: {S entry: (m/s) per N m/rad}}, rigid frame: None

    def display_rows(self):
        """The two speeds and their three largest elasticities (Jupyter's table, ``repr``)."""
        rows = []
        for which in ("weave_speed", "capsize_speed"):
            v = getattr(self, which)
            rows.append((which, "none" if v is None else f"{v:.6g}", "m/s"))
            if v is not None:
                e = {k: x for k, x in self.elasticities(which).items() if x is not None}
                top = sorted(e, key=lambda k: -abs(e[k]))[:3]
                rows.append((f"largest elasticities of the {which.replace('_', ' ')}",
                             ", ".join(f"{k} {e[k]:+.3g}" for k in top), "(p/v) dv/dp"))
        return rows

    def elasticities(self, which):
        """``{name: (p / v) dv/dp}`` for ``which`` in ``weave_speed`` | ``capsize_speed``."""
        v, d = getattr(self, which), getattr(self, "d_" + which)
        return {k: (self.params[k] * x / v if v else None) for k, x in d.items()}

    def to_dict(self):
        out = {"weave_speed": self.weave_speed, "capsize_speed": self.capsize_speed,
               "d_weave_speed": self.d_weave_speed, "d_capsize_speed": self.d_capsize_speed,
               "elasticity_weave_speed": self.elasticities("weave_speed"),
               "elasticity_capsize_speed": self.elasticities("capsize_speed")}
        if self.d_stiffness is not None:
            out["d_stiffness"] = self.d_stiffness
        return out


@renamed_keywords(S="stiffness")
def sensitivity(params: "BenchmarkParameters | Scenario | Built", stiffness: "ArrayLike | None" = None,
                vmax: float = 30.0, names: "Sequence[str]" = NAMES) -> Sensitivity:
    """Exact derivatives of the weave and capsize speeds with respect to each benchmark parameter.

    The first crossing of each kind on ``(0, vmax]`` and its derivative by the implicit function
    theorem on the crossing eigenvalue (left and right eigenvectors), with the matrices'
    derivatives by the complex step: exact to rounding, no finite differences.

    Parameters
    ----------
    params : BenchmarkParameters, Scenario or Built
        A benchmark set (the Whipple model, with rear-frame stiffness ``stiffness``), or a
        :class:`~bikemass.scenario.scenario.Scenario` (built) of any member of the model family.
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad) of a benchmark set; ``None`` = rigid, and ``None`` with a
        scenario (it has its own). With S the derivatives with respect to its entries are given
        too. (``S=`` is the deprecated old name.)
    vmax : float
        Highest speed searched (m/s), positive and finite.
    names : sequence of str
        The parameters to differentiate by (default all 26, :data:`~bikemass.PARAMETER_NAMES`).

    Returns
    -------
    Sensitivity
        ``weave_speed``, ``capsize_speed`` (m/s, ``None`` if none); ``d_weave_speed``,
        ``d_capsize_speed`` ``{name: (m/s) per unit of the parameter}``; ``d_stiffness``
        ``{speed: {S entry: (m/s) per N m/rad}}`` or ``None``; ``elasticities(which)`` the
        dimensionless ``(p/v) dv/dp``.

    Raises
    ------
    InputError
        Parameters the model is not defined for, an S that is not symmetric positive definite, a
        ``vmax`` that is not a positive finite speed, or ``names`` not among the 26.

    See Also
    --------
    geometry_sensitivity : Derivatives with respect to the geometry a bicycle file is written in.
    uncertainty : Spreads of the inputs carried to spreads of the speeds.

    Examples
    --------
    >>> import bikemass as bm
    >>> p = bm.parameters("benchmark")
    >>> s = bm.sensitivity(p, names=("c", "lam", "mB"))
    >>> print(f"weave {s.weave_speed:.6f} m/s: d/dc {s.d_weave_speed['c']:+.4f} (m/s)/m, "
    ...       f"d/dlam {s.d_weave_speed['lam']:+.4f} (m/s)/rad")
    weave 4.292383 m/s: d/dc +11.4800 (m/s)/m, d/dlam +4.1767 (m/s)/rad
    >>> {k: round(v, 4) for k, v in s.elasticities("capsize_speed").items()}
    {'c': 0.3836, 'lam': 0.2247, 'mB': 0.3585}

    The same derivative by a central difference of two stability analyses:

    >>> h = 1e-5
    >>> weave = lambda c: bm.stability(p.replace(c=c)).weave_speeds[0]
    >>> print(f"{(weave(p.c + h) - weave(p.c - h)) / (2 * h):+.4f} (m/s)/m")
    +11.4800 (m/s)/m
    """
    if isinstance(params, (Scenario, Built)):
        if stiffness is not None:
            raise InputError("stiffness", "(matrix)", "none with a scenario (its stiffness choice is built in)")
        built = params.build() if isinstance(params, Scenario) else params
        if built.choice.members:
            _checked(built.parameters, None, vmax, names)
            return _member_sensitivity(built, vmax, tuple(names))
        params, stiffness = built.parameters, built.stiffness
    params, S, names = _checked(params, stiffness, vmax, names)
    model = model_of(values_of(params), S)
    found = closed_form.axis_crossings(model, 0.0, vmax)
    speeds, derivs = {}, {}
    for key, kind in SPEEDS.items():
        crossing = next(((speed, w) for speed, k, w in found if k == kind), None)
        speeds[key] = None if crossing is None else crossing[0]
        if crossing is None:
            derivs[key] = {n: None for n in (*names, *(STIFFNESS_ENTRIES if S is not None else ()))}
            continue
        dA = {**state_matrix_derivatives(params, crossing[0], S, names),
              **stiffness_state_derivatives(params, crossing[0], S)}
        derivs[key] = speed_derivatives(model, dA, crossing[0], kind, crossing[1])
    d_s = None
    if S is not None:
        d_s = {key: {k: d.pop(k, None) for k in STIFFNESS_ENTRIES} for key, d in derivs.items()}
    return Sensitivity(params=values_of(params), weave_speed=speeds["weave_speed"],
                       capsize_speed=speeds["capsize_speed"], d_weave_speed=derivs["weave_speed"],
                       d_capsize_speed=derivs["capsize_speed"], d_stiffness=d_s)


MEMBER_STEP = 1e-3
"""Relative step of the five-point central difference of a member's ``dA/dp`` (absolute for a zero
parameter, in its SI unit)."""


def member_state_derivatives(built, speed, names=NAMES, step=MEMBER_STEP):
    """``{name: dA/dp}`` (dynamic block at ``speed``) of a built member's generated model, by a
    five-point central difference in each benchmark parameter of the set it takes."""
    base = built.values()
    n = built.model.n_dynamic

    def at(name, x):
        return built.with_values({**base, name: x}).dynamic_matrix(speed)[:n, :n]
    out = {}
    for name in names:
        x = base[name]
        h = step * abs(x) if x else step
        out[name] = (8 * (at(name, x + h) - at(name, x - h)) - (at(name, x + 2 * h) - at(name, x - 2 * h))) / (12 * h)
    return out


def _member_sensitivity(built, vmax, names):
    """:class:`Sensitivity` of a built member of the family other than the Whipple bicycle."""
    found = critical_speeds(built.model, vmax)
    speeds, derivs = {}, {}
    for key, kind in SPEEDS.items():
        crossing = found.weave_crossing if kind == OSCILLATORY else found.capsize_crossing
        speeds[key] = None if crossing is None else crossing.speed
        derivs[key] = ({n: None for n in names} if crossing is None else speed_derivatives(
            built.model, member_state_derivatives(built, crossing.speed, names), crossing.speed, kind,
            crossing.frequency))
    base = built.values()
    return Sensitivity(params={n: float(base[n]) for n in names}, weave_speed=speeds["weave_speed"],
                       capsize_speed=speeds["capsize_speed"], d_weave_speed=derivs["weave_speed"],
                       d_capsize_speed=derivs["capsize_speed"])


def _checked(params, S, vmax, names):
    """``(params, S, names)`` checked as :func:`sensitivity` needs them (InputError otherwise)."""
    if not isinstance(params, BenchmarkParameters):
        raise wrong_type("params", params, "BenchmarkParameters (bm.parameters)")
    check_parameters(params, "params")
    S = _stiffness(S)
    if not finite_real(vmax) or not 0 < vmax <= MAX_SPEED:
        raise InputError("vmax", short(vmax), f"a speed in m/s above 0 and at most {MAX_SPEED:g}")
    if isinstance(names, str) or not all(n in NAMES for n in names):
        raise InputError("names", short(names), f"a sequence of benchmark parameter names ({', '.join(NAMES)})")
    return params, S, tuple(names)


def sensitivity_figure(result, title="", size=None):
    """Horizontal bar chart of the elasticities of both speeds (a matplotlib Figure; ``size`` in inches)."""
    # lazy: matplotlib only for a figure
    from ..plots.figure import Figure

    fig = Figure(figsize=size or (10, 7.5), layout="constrained")
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


GEOMETRY_STEP = 1e-4
"""Default relative step of the geometry -> parameters central difference."""


def geometry_sensitivity(scenario: Scenario, keys: "str | Sequence[str]", result: Sensitivity | None = None,
                         step: float = GEOMETRY_STEP) -> dict:
    """Derivatives of the weave and capsize speeds with respect to geometry-level inputs.

    Chain rule: ``dv/dx = sum_p (dv/dp)(dp/dx) + sum_S (dv/dS)(dS/dx)``.  ``dv/dp`` and ``dv/dS``
    are exact (:func:`sensitivity`); for a member other than the Whipple bicycle ``p`` runs over every
    parameter its generated code takes (the upper body's, the tyres', the compliances' too) and
    ``dv/dp`` is :func:`member_state_derivatives`'.  ``dp/dx`` and ``dS/dx`` (geometry -> mass
    properties, beam stiffness, rider pose) are central differences with relative step ``step``, and
    again with twice the step: ``difference_check`` is the largest change between the two (m/s per
    unit), an estimate of the finite-difference error.

    Parameters
    ----------
    scenario : Scenario
        A bicycle, rider, stiffness and model: ``bm.Scenario("jamis", "relaxed", "steel")``.
    keys : str or sequence of str
        Dotted paths into the bicycle or pose YAML (``"geometry.trail"``,
        ``"sections.seat_stay.wall"``, ``"chart.stack"``, ``"rider.segments.torso.angle"``) or
        benchmark names; see :mod:`bikemass.scenario.inputs`.
    result : Sensitivity, optional
        The scenario's :func:`sensitivity` if already computed.
    step : float
        Relative step of the central differences, in (0, 0.1].

    Returns
    -------
    dict
        ``{key: {"value", "step", "weave_speed", "capsize_speed", "difference_check"}}``: the
        input's value and step in SI (m, kg, rad, ... whatever unit its file writes it in);
        ``weave_speed`` and ``capsize_speed`` the derivatives of those speeds, and
        ``difference_check``, in m/s per SI unit.

    Raises
    ------
    InputError
        An unknown key, a ``step`` out of range, or a scenario that cannot be built.
    InputTypeError
        ``scenario`` not a :class:`~bikemass.scenario.scenario.Scenario`.

    See Also
    --------
    sensitivity : The exact parameter derivatives it chains.

    Examples
    --------
    >>> import bikemass as bm
    >>> d = bm.geometry_sensitivity(bm.Scenario("jamis", "relaxed"), ["geometry.trail"])["geometry.trail"]
    >>> print(f"trail {d['value']:.3f} m: d(weave speed)/d(trail) {d['weave_speed']:+.2f} (m/s)/m")
    trail 0.060 m: d(weave speed)/d(trail) +15.50 (m/s)/m
    """
    if not isinstance(scenario, Scenario):
        raise wrong_type("scenario", scenario, "a bikemass.Scenario")
    if isinstance(keys, str):
        keys = [keys]
    if isinstance(step, bool) or not isinstance(step, (int, float)) or not 0 < step <= 0.1:
        raise InputError("step", short(step), "a relative step between 0 and 0.1")
    built = scenario.build()
    member = bool(built.choice.members)
    result = result or sensitivity(built)
    if member:
        result = _all_member_derivatives(built, result)
    out = {}
    for key in keys:
        x = scenario.value(key)
        h = step * abs(x) if x else step
        estimates = []
        for hh in (h, 2 * h):
            a, b = scenario.build({key: x + hh}), scenario.build({key: x - hh})
            if member:
                va, vb = a.values(), b.values()
                dp = {n: (va[n] - vb[n]) / (2 * hh) for n in result.params}
            else:
                dp = {n: (getattr(a.parameters, n) - getattr(b.parameters, n)) / (2 * hh) for n in result.params}
            dS = None if built.stiffness is None else (np.asarray(a.stiffness) - np.asarray(b.stiffness)) / (2 * hh)
            estimates.append({k: _chain(result, k, dp, dS) for k in SPEEDS})
        out[key] = {"value": x, "step": h, **estimates[0],
                    "difference_check": max((abs(estimates[0][k] - estimates[1][k])
                                             for k in SPEEDS if estimates[0][k] is not None), default=None)}
    return out


def _all_member_derivatives(built, result):
    """``result`` with the speeds' derivatives by every parameter of a member's generated code."""
    names = tuple(built.values())
    derivs = {}
    for key, kind in SPEEDS.items():
        v = getattr(result, key)
        if v is None:
            derivs[key] = {n: None for n in names}
            continue
        crossing = min((c for c in critical_speeds(built.model, v + 1.0).crossings if c.kind == kind),
                       key=lambda c: abs(c.speed - v))          # the crossing the result found, for its frequency
        derivs[key] = speed_derivatives(built.model, member_state_derivatives(built, v, names), v, kind,
                                        crossing.frequency)
    return Sensitivity(params=built.values(), weave_speed=result.weave_speed, capsize_speed=result.capsize_speed,
                       d_weave_speed=derivs["weave_speed"], d_capsize_speed=derivs["capsize_speed"])


def _chain(result, key, dp, dS):
    d = getattr(result, "d_" + key)
    if getattr(result, key) is None:
        return None
    total = sum(d[n] * dp[n] for n in dp)
    if dS is not None:
        ds = result.d_stiffness[key]
        total += ds["S_phiphi"] * dS[0, 0] + ds["S_phidelta"] * dS[0, 1] + ds["S_deltadelta"] * dS[1, 1]
    return float(total)
