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
(the weave's crossing, as ``bm.stability`` names it), and ``dA/dp`` of its generated code comes from
the same complex step through that code (the generated coefficients take complex parameters): exact
to rounding there too.  Elasticities are
``(p / v*) d v* / d p`` (per cent change of the speed per per cent change of the parameter).
"""

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from types import SimpleNamespace

from ..core.tables import Table
from ..models.whipple_generated import second_order_entries
from ..models.family import parameters_of
from ..models.parameters import NAMES, parameter_units
from .engine import closed_form, scalar
from .engine.crossings import OSCILLATORY, REAL
from .model import STEP, STIFFNESS_ENTRIES, values_of
from .engine.critical import critical_speeds
from .results import _stiffness
from ..core.results import Result, quantity
from ..core.frozen import freeze, frozen_fields, thaw
from ..core.limits import MAX_SPEED
from ..core.real import finite_real
from ..core.errors import InputError, short
from ..core.keywords import renamed_keywords
from ..models.members.rider_lean.parameters import RiderLeanParameters
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


PER_PARAMETER = "m/s per unit of each parameter (SI, angles rad)"
"""The unit of a derivative of a critical speed by each of several parameters."""


@dataclass(frozen=True, repr=False)
class Sensitivity(Result):
    """Critical speeds (m/s, ``None`` if none) and their derivatives ``{name: (m/s) per unit}``
    (read-only mappings); ``params`` the values differentiated by (SI, each in its own unit);
    ``param_units`` the units of a member's own parameters (``{"CaF": "1/rad", ...}``, as its
    generated code declares them; ``None`` for the benchmark names alone), read by :meth:`unit_of`.

    Examples
    --------
    >>> import bikemass as bm
    >>> s = bm.sensitivity(bm.parameters("benchmark"))
    >>> print(type(s).__name__, f"{s.weave_speed:.4f} m/s, d/dc {s.d_weave_speed['c']:.3f}")
    Sensitivity 4.2924 m/s, d/dc 11.480
    """

    params: Mapping
    weave_speed: float | None = quantity("m/s", "the weave speed (None: none)")
    capsize_speed: float | None = quantity("m/s", "the capsize speed (None: none)")
    d_weave_speed: Mapping = quantity(PER_PARAMETER, "{name: derivative of the weave speed}")
    d_capsize_speed: Mapping = quantity(PER_PARAMETER, "{name: derivative of the capsize speed}")
    d_stiffness: Mapping | None = quantity("m/s per N m/rad", "{speed key: {S entry: derivative}}; rigid: None",
                                           default=None)
    param_units: Mapping | None = None

    def __post_init__(self):
        frozen_fields(self, "params", "d_weave_speed", "d_capsize_speed", "d_stiffness", "param_units")

    def unit_of(self, name):
        """The SI unit of parameter ``name`` (``"m"``, ``"1/rad"``, ...): a benchmark name's, or what the
        model's code declares for a member's own parameter (``param_units``)."""
        return (self.param_units or {}).get(name) or parameter_units().get(name, "SI")

    def units(self):
        """The ``units`` block of :meth:`to_dict`: the fields' declared units and the elasticities'."""
        return {**self.field_units(), "elasticity_weave_speed": "1", "elasticity_capsize_speed": "1"}

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
        return {k: (self.params[k] * x / v + 0.0 if v and x is not None else None) for k, x in d.items()}

    def tables(self):
        """``{"parameters": Table}``: one row per parameter differentiated by (its value and unit, the
        derivatives of the weave and capsize speeds in (m/s) per unit of it, the dimensionless
        elasticities ``(p/v) dv/dp``), and with a rear-frame stiffness ``{"stiffness": Table}``: one
        row per critical speed and entry of S ((m/s) per N m/rad). The critical speeds are the
        frames' ``attrs``."""
        names = list(dict.fromkeys((*self.d_weave_speed, *self.d_capsize_speed)))
        e_weave, e_capsize = self.elasticities("weave_speed"), self.elasticities("capsize_speed")
        per = "m/s per unit of the parameter"
        columns = {"parameter": names, "value": [self.params.get(n) for n in names],
                   "unit": [self.unit_of(n) for n in names],
                   "d_weave_speed": [self.d_weave_speed.get(n) for n in names],
                   "d_capsize_speed": [self.d_capsize_speed.get(n) for n in names],
                   "elasticity_weave_speed": [e_weave.get(n) for n in names],
                   "elasticity_capsize_speed": [e_capsize.get(n) for n in names]}
        attrs = {"weave_speed": self.weave_speed, "capsize_speed": self.capsize_speed}
        out = {"parameters": Table(columns, {"d_weave_speed": per, "d_capsize_speed": per,
                                             "elasticity_weave_speed": "1", "elasticity_capsize_speed": "1"},
                                   attrs)}
        if self.d_stiffness is not None:
            rows = [(speed, entry, d) for speed, entries in self.d_stiffness.items() for entry, d in entries.items()]
            out["stiffness"] = Table({"speed": [r[0] for r in rows], "entry": [r[1] for r in rows],
                                      "derivative": [r[2] for r in rows]}, {"derivative": "m/s per N m/rad"}, attrs)
        return out

    def to_dict(self):
        out = {"weave_speed": self.weave_speed, "capsize_speed": self.capsize_speed,
               "d_weave_speed": thaw(self.d_weave_speed), "d_capsize_speed": thaw(self.d_capsize_speed),
               "elasticity_weave_speed": self.elasticities("weave_speed"),
               "elasticity_capsize_speed": self.elasticities("capsize_speed")}
        if self.d_stiffness is not None:
            out["d_stiffness"] = thaw(self.d_stiffness)
        return out


@renamed_keywords(S="stiffness", params="system", vmax="max_speed")
def sensitivity(system: "BenchmarkParameters | RiderLeanParameters | Scenario | Built", stiffness: "ArrayLike | None" = None,
                max_speed: float = 30.0, names: "Sequence[str] | None" = None, model: "str | None" = None,
                **members: object) -> Sensitivity:
    """Exact derivatives of the weave and capsize speeds with respect to each parameter of the model.

    The first crossing of each kind on ``(0, max_speed]`` and its derivative by the implicit function
    theorem on the crossing eigenvalue (left and right eigenvectors), with the matrices'
    derivatives by the complex step: exact to rounding, no finite differences.

    Parameters
    ----------
    system : BenchmarkParameters, RiderLeanParameters, Scenario or Built
        A benchmark set (the Whipple model, with rear-frame stiffness ``stiffness``), a leaning
        rider's set (the ``rider-lean`` model; its 26 benchmark names are those of the bicycle
        without the upper body), or a :class:`~bikemass.scenario.scenario.Scenario` (built) of any
        member of the model family.
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad) of a benchmark set; ``None`` = rigid, and ``None`` with a
        scenario (it has its own). With S the derivatives with respect to its entries are given
        too. (``S=`` is the deprecated old name.)
    max_speed : float
        Highest speed searched (m/s), positive and finite.
    names : sequence of str, optional
        The parameters to differentiate by.  Default: of the Whipple bicycle all 26
        (:data:`~bikemass.PARAMETER_NAMES`); of any other member of the family every parameter its
        code takes: the 26 and the member's own (the tyres' ``CaF``, ``CgF``, ``sigmaF``, ..., the
        upper body's ``mU``, ``klean``, ``clean``, the arms' ``k_arms``, ``c_arms``, the flexible
        frame's compliances and modal masses), each in the SI unit the code declares
        (:meth:`Sensitivity.unit_of`).
    model : str, optional
        A member of the model family (``"tyre"``, ``"rider-lean+tyre"``, ...), as for
        :func:`~bikemass.stability`: the parameter set's own by default, a Scenario's own replaced.
    **members
        A member's parameters by its keyword (``tyres=``, ``arms=``), as for :func:`~bikemass.stability`.

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
        ``max_speed`` that is not a positive finite speed, or ``names`` not among the model's
        parameters.

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
    if isinstance(system, RiderLeanParameters) or (model is not None or members) and \
            isinstance(system, BenchmarkParameters):
        system = Scenario(system, model=model, member_inputs=members)    # a member (a set's own: the leaning rider)
    elif isinstance(system, Scenario) and (model is not None or members):
        system = system.replace(**({"model": model} if model is not None else {}), **members)
    elif isinstance(system, Built) and (model is not None or members):
        raise InputError("model", model or ", ".join(members), "nothing beside a built scenario (its model and "
                         "members are built in): give the Scenario")
    if isinstance(system, (Scenario, Built)):
        if stiffness is not None:
            raise InputError("stiffness", "(matrix)", "none with a scenario (its stiffness choice is built in)")
        built = system.build() if isinstance(system, Scenario) else system
        if built.choice.members:
            own = tuple(built.values())
            _checked(built.parameters, None, max_speed, NAMES)
            return _member_sensitivity(built, max_speed, _member_names(names, own, built.choice))
        system, stiffness = built.parameters, built.stiffness
    system, S, names = _checked(system, stiffness, max_speed, NAMES if names is None else names)
    return _whipple_sensitivity(system, S, max_speed, names)


def _member_names(names, own, choice):
    """``names`` (default: every one of ``own``, the parameters of the code of the member ``choice``) checked
    to be among ``own`` and at least one (InputError otherwise)."""
    if names is None:
        return own
    names = names if isinstance(names, str) else tuple(names)
    if isinstance(names, str) or not names or not all(isinstance(n, str) and n in own for n in names):
        raise InputError("names", short(names), f"a sequence of the {choice.name} model's parameter names "
                                                f"({', '.join(own)})")
    return tuple(names)


def _whipple_sensitivity(params, S, vmax, names):
    """:class:`Sensitivity` of the Whipple bicycle: one complex-step batch through the closed form.

    Row 0 of the batch is the configuration, row ``1 + j`` has ``i h`` added to the ``j``-th of
    ``names`` (then to each entry of S): the canonical matrices, the quartic's pieces and the two
    quadratics in ``v^2`` are evaluated on all rows at once, and each crossing's root is taken on
    the branch the real configuration's crossing is on, so ``Im v* / h`` is ``d v* / d p`` exact to
    rounding (an analytic function of the parameters: no subtraction, no step error)."""
    base = values_of(params)
    stepped = (*names, *(STIFFNESS_ENTRIES if S is not None else ()))
    B = 1 + len(stepped)
    columns = {k: np.full(B, complex(v)) for k, v in base.items()}
    for j, name in enumerate(names):
        columns[name][1 + j] += 1j * STEP
    Sc = None
    if S is not None:
        Sc = np.broadcast_to(np.asarray(S, dtype=complex), (B, 2, 2)).copy()
        for j, cells in enumerate(STIFFNESS_ENTRIES.values()):
            for cell in cells:
                Sc[1 + len(names) + j][cell] += 1j * STEP
    p = _batch_pieces(columns, Sc)
    real = scalar.whipple_pieces(params, S)
    speeds, derivs = {}, {}
    for key, kind in SPEEDS.items():
        branch = _first_crossing_branch(real, kind, vmax)
        if branch is None:
            speeds[key] = None
            derivs[key] = {n: None for n in stepped}
            continue
        v = _crossing_speed(p, kind, branch)
        speeds[key] = float(branch[2])
        derivs[key] = {n: float(x) for n, x in zip(stepped, v[1:].imag / STEP)}
    d_s = None
    if S is not None:
        d_s = {key: {k: d.pop(k, None) for k in STIFFNESS_ENTRIES} for key, d in derivs.items()}
    return Sensitivity(params=base, weave_speed=speeds["weave_speed"],
                       capsize_speed=speeds["capsize_speed"], d_weave_speed=derivs["weave_speed"],
                       d_capsize_speed=derivs["capsize_speed"], d_stiffness=d_s)


def _batch_pieces(columns, S):
    """closed_form.pieces of the Whipple bicycle of ``columns`` (complex arrays (B,) of the 26
    parameters), with stacked rear-frame stiffness ``S`` (B, 2, 2) or None."""
    M, C1, K0, K2 = (np.moveaxis(np.array(np.broadcast_arrays(*[x for row in m for x in row])).reshape(2, 2, -1),
                                 -1, 0) for m in second_order_entries(SimpleNamespace(**columns)))
    G = columns["g"][:, None, None] * K0
    if S is not None:
        G = G - np.swapaxes(G, -1, -2) @ np.linalg.solve(G + S, G)
    return closed_form.pieces(M, C1, G, K2)


def _quadratics(p):
    """The two quadratics in ``u = v^2`` of the closed form: ``{kind: (a, b, c)}``."""
    alpha, gamma, beta, a4 = p["alpha"], p["gamma"], p["beta"], p["a4"]
    h2 = alpha * p["a21"] * gamma - a4 * gamma * gamma - alpha * alpha * p["d2"]
    h1 = alpha * (p["a20"] * gamma + p["a21"] * beta) - 2 * a4 * beta * gamma - alpha * alpha * p["d1"]
    h0 = alpha * p["a20"] * beta - a4 * beta * beta - alpha * alpha * p["d0"]
    return {REAL: (p["d2"], p["d1"], p["d0"]), OSCILLATORY: (h2, h1, h0)}


def _first_crossing_branch(real, kind, vmax):
    """``(root index, a == 0, speed)`` of the first crossing of ``kind`` on (0, vmax] of the real pieces
    ``real`` (scalar.pieces), or None: which root of which quadratic (scalar.quadratic_roots) it is."""
    candidates = scalar.candidates(real)
    speeds = candidates[0] if kind == REAL else candidates[1]
    inside = [(s, i) for i, s in enumerate(speeds) if 0 < s <= vmax]
    if not inside:
        return None
    s, i = min(inside)
    return i, _quadratics(real)[kind][0] == 0, s


def _crossing_speed(p, kind, branch):
    """The crossing speed (complex (B,)) on ``branch`` of the batch's quadratic of ``kind``, the root
    taken by the formulas of scalar.quadratic_roots with the real row's choices (a complex step stays
    on one branch)."""
    index, linear, _ = branch
    a, b, c = _quadratics(p)[kind]
    if linear:
        u = -c / b
    else:
        root = np.sqrt(b * b - 4 * a * c)
        q = -0.5 * (b + np.copysign(1.0, b[0].real) * root)
        u = q / a if index == 0 else c / q
    return np.sqrt(u)


def member_state_derivatives(built, speed, names=NAMES):
    """``{name: dA/dp}`` (dynamic block at ``speed``) of a built member's generated model, by the
    complex step through its generated code (:func:`~bikemass.models.family.dynamic_derivatives`):
    exact to rounding, the same rule as the Whipple bicycle's."""
    return built.derivatives(speed, names, STEP)


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
                       d_capsize_speed=derivs["capsize_speed"], param_units=_own_units(built, names))


def _own_units(built, names):
    """``{name: SI unit}`` of those of ``names`` that are a member's own parameters (not one of the 26), as the
    code of ``built``'s model declares them."""
    return {name: unit for name, unit, _ in parameters_of(built.choice) if name in names and name not in NAMES}


def _checked(params, S, vmax, names):
    """``(params, S, names)`` checked as :func:`sensitivity` needs them (InputError otherwise)."""
    if not isinstance(params, BenchmarkParameters):
        raise wrong_type("params", params, "BenchmarkParameters (bm.parameters)")
    check_parameters(params, "params")
    S = _stiffness(S)
    if not finite_real(vmax) or not 0 < vmax <= MAX_SPEED:
        raise InputError("vmax", short(vmax), f"a speed in m/s above 0 and at most {MAX_SPEED:g}")
    names = names if isinstance(names, str) else tuple(names)
    if isinstance(names, str) or not names or not all(n in NAMES for n in names):
        raise InputError("names", short(names), f"a sequence of benchmark parameter names ({', '.join(NAMES)})")
    return params, S, names


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
MIN_STEP = 1e-10
"""Smallest relative step taken: a smaller one leaves a difference of rounding errors (0 at 1e-17)."""


def geometry_sensitivity(scenario: Scenario, keys: "str | Sequence[str]", result: Sensitivity | None = None,
                         step: float = GEOMETRY_STEP) -> Mapping:
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
        ``"sections.seat_stay.wall"``, ``"chart.stack"``, ``"rider.posture.elbow"``) or
        benchmark names; see :mod:`bikemass.scenario.inputs`.
    result : Sensitivity, optional
        The scenario's :func:`sensitivity` if already computed.
    step : float
        Relative step of the central differences, from 1e-10 to 0.1.

    Returns
    -------
    Mapping
        Read-only ``{key: {"value", "step", "weave_speed", "capsize_speed", "difference_check"}}``: the
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
    if isinstance(step, bool) or not isinstance(step, (int, float)) or not MIN_STEP <= step <= 0.1:
        raise InputError("step", short(step), f"a relative step from {MIN_STEP:g} to 0.1 (below it the difference "
                                              "is rounding: x + h rounds to x)")
    built = scenario.build()
    member = bool(built.choice.members)
    result = result or sensitivity(built)
    if member and not set(built.values()) <= set(result.d_weave_speed):    # a result of some names only
        result = _all_member_derivatives(built, result)
    out = {}
    for key in keys:
        x = scenario.value(key)
        h = step * abs(x) if x else step
        estimates = []
        for hh in (h, 2 * h):
            a, b, width = difference_sides(lambda value, key=key: scenario.build({key: value}), x, hh)
            if member:
                va, vb = a.values(), b.values()
                dp = {n: (va[n] - vb[n]) / width for n in result.params}
            else:
                dp = {n: (getattr(a.parameters, n) - getattr(b.parameters, n)) / width for n in result.params}
            dS = None if built.stiffness is None else (np.asarray(a.stiffness) - np.asarray(b.stiffness)) / width
            estimates.append({k: _chain(result, k, dp, dS) for k in SPEEDS})
        out[key] = {"value": x, "step": h, **estimates[0],
                    "difference_check": max((abs(estimates[0][k] - estimates[1][k])
                                             for k in SPEEDS if estimates[0][k] is not None), default=None)}
    return freeze(out)


def difference_sides(build, x, h):
    """``(plus, minus, width)`` of a central difference of step ``h`` at ``x``: ``build(x + h)``, ``build(x - h)``
    and their distance ``2 h``; where one side is outside what the input takes (``build`` raises InputError:
    a relaxation length or an arms' stiffness at its bound 0), that side is ``build(x)`` itself and the width
    ``h`` (a one-sided difference); where neither side can be built, the InputError of ``x - h``."""
    sides = []
    for value in (x + h, x - h):
        try:
            sides.append(build(value))
        except InputError:
            sides.append(None)
    if sides[0] is None and sides[1] is None:
        build(x - h)                                             # neither side can be built: its reason
    if None in sides:
        base = build(x)
        return (sides[0] or base), (sides[1] or base), h
    return sides[0], sides[1], 2 * h


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
                       d_weave_speed=derivs["weave_speed"], d_capsize_speed=derivs["capsize_speed"],
                       param_units=_own_units(built, names))


def _chain(result, key, dp, dS):
    d = getattr(result, "d_" + key)
    if getattr(result, key) is None:
        return None
    total = sum(d[n] * dp[n] for n in dp)
    if dS is not None:
        ds = result.d_stiffness[key]
        total += ds["S_phiphi"] * dS[0, 0] + ds["S_phidelta"] * dS[0, 1] + ds["S_deltadelta"] * dS[1, 1]
    return float(total)
