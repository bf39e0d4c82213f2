"""Uncertainty of the canonical matrices, eigenvalues and critical speeds from input uncertainties.

Inputs are independent, each with a distribution about its nominal value: ``normal``
(``std``) or ``uniform`` (``half_width``, std = half_width / sqrt 3).  An input is one of
the 26 benchmark names or a geometry-level key of :mod:`bikemass.scenario.inputs`.

* ``linear``: first-order propagation, ``std(y) = sqrt(sum_i (dy/dx_i std_i)^2)`` (what the
  ``uncertainties`` package does).  ``dy/dx_i`` by the complex step along the input's
  direction in parameter (and stiffness) space: exact for the matrices; eigenvalue
  derivatives from left/right eigenvectors, critical-speed derivatives by the implicit
  function theorem (:mod:`bikemass.analysis.sensitivity`).  A geometry-level input's
  direction ``dp/dx`` (and ``dS/dx``) is a central difference through the model.
* ``montecarlo``: ``samples`` draws of all inputs (seeded), every output recomputed.

That is the Whipple model's way (``M``, ``C1``, ``K0``, ``K2`` are its 2x2 matrices).  Any other
member of the family (a :class:`~bikemass.scenario.scenario.Scenario` with ``model=``) goes through
the engine: ``linear`` takes each input's ``dA/dx`` (the dynamic block, at every speed) by the complex
step through the generated code for a parameter of the model's code (exact) or a central difference
through the builder for a design input, and ``montecarlo`` builds every draw; its ``matrices`` are the
dynamic block's coefficients ``A0, A1, A2`` of ``A(v) = A0 + v A1 + v**2 A2`` (the model's own
coordinates are more than roll and steer).

They agree while the outputs are close to linear over a few standard deviations.  They
cannot agree where an eigenvalue is not differentiable: where two real roots merge into
a complex pair (the weave's birth, ~0.7-1.8 m/s on the benchmark) the linear std of the
eigenvalues grows without bound, and a critical speed that some samples do not have
(no crossing) has no linear counterpart.
"""

import os
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, fields

import numpy as np
from numpy.typing import ArrayLike

from ..core.tables import Table
from ..core.choices import Choice
from ..core.results import Result, quantity
from ..core.frozen import thaw
from ..core.plain import plain
from ..core.real import finite_real
from ..core.errors import InputError
from ..core.keywords import renamed_keywords
from ..core.limits import MAX_SPEEDS
from ..core.units import ARTICLES, UnitError, dimension_of, split_quantity, to_si
from ..models.canonical import CanonicalMatrices
from ..models.members.rider_lean.parameters import RiderLeanParameters
from ..models.parameters import NAMES
from ..models.family import member_inputs
from ..plots.stability import mode_colours
from ..scenario.scenario import Scenario
from .engine.critical import critical_speeds
from .engine.modes import follow_many, follow_modes
from .engine.speeds import speed_grid, speed_values
from .model import STEP, model_of, values_of
from .sensitivity import SPEEDS, speed_derivatives

class Distribution(Choice):
    """An input's distribution about its nominal value (a member is its string: ``"normal"``).

    See Also
    --------
    Spread : Holds one.

    Examples
    --------
    >>> import bikemass as bm
    >>> bm.Distribution.values()
    ('normal', 'uniform')
    >>> bm.Spread("uniform", 0.005).kind is bm.Distribution.UNIFORM
    True
    """

    NORMAL = "normal"
    """Normal, of standard deviation ``std``."""
    UNIFORM = "uniform"
    """Uniform on ``+-half_width``, ``std = half_width / sqrt 3``."""


DISTRIBUTIONS = Distribution.values()
"""The distributions' names: ``("normal", "uniform")``."""


class PropagationMethod(Choice):
    """How :func:`uncertainty` propagates the inputs' spreads (a member is its string).

    See Also
    --------
    bikemass.uncertainty : Takes it as ``method=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> bm.PropagationMethod.values()
    ('linear', 'montecarlo')
    >>> bm.uncertainty("benchmark", {"c": 0.005}, method=bm.PropagationMethod.LINEAR).method == "linear"
    True
    """

    LINEAR = "linear"
    """First order, with exact derivatives."""
    MONTECARLO = "montecarlo"
    """Seeded draws of every input, every output recomputed."""


METHODS = PropagationMethod.values()
"""The methods' names: ``("linear", "montecarlo")``."""


@dataclass(frozen=True)
class Spread:
    """One input's distribution about its nominal value: ``kind`` a :class:`Distribution` (normal or
    uniform; another kind is kept as given, and refused by :func:`propagate`), ``std`` (SI: m,
    kg, rad, ... as the input's value).

    See Also
    --------
    bikemass.uncertainty : Takes ``{input key: Spread}``.

    Examples
    --------
    >>> import bikemass as bm
    >>> u = bm.uncertainty("benchmark", {"c": bm.Spread("uniform", 0.005)})     # +-8.7 mm, std 5 mm
    >>> w = u.speeds["weave_speed"]
    >>> print(f"weave {w.nominal:.4f} +- {w.std:.4f} m/s")
    weave 4.2924 +- 0.0574 m/s
    """

    kind: "Distribution | str"
    std: float

    def __post_init__(self):
        if isinstance(self.kind, str) and self.kind in DISTRIBUTIONS:
            object.__setattr__(self, "kind", Distribution(self.kind))

    def sample(self, rng, n):
        if self.kind == "uniform":
            half = self.std * np.sqrt(3.0)
            return rng.uniform(-half, half, n)
        return rng.normal(0.0, self.std, n)


def _spread_value(node, problem=None):
    """A std or half width in SI: a bare number is SI (m, kg, rad, ... as the input's value is,
    :func:`~bikemass.scenario.inputs.get_path`), ``"0.1 mm"`` or ``"3 deg"`` is converted; a unit the input
    cannot carry (``problem(unit)``: what the input is, or ``None`` where the unit fits) is refused naming both."""
    if isinstance(node.value, str):
        try:
            number, unit = split_quantity(node.value)
        except UnitError as exc:
            node.fail(f"a spread: a number in SI or '<number> <unit>' ({exc})")
        if number < 0:
            node.fail(f"a spread >= 0, got {node.value!r}")
        expected = problem(unit) if unit and problem is not None else None
        if expected is not None:
            given = dimension_of(unit)
            node.fail(f"a spread of {expected} (a number in SI or '<number> <unit>' of its dimension), got "
                      f"{node.value!r} ({ARTICLES.get(given, 'a')} {given})")
        return to_si(node.value, dimension_of(unit)) if unit else number
    return node.number("dimensionless", nonnegative=True)


def read_spreads(node, unit_problem=None):
    """``{key: Spread}`` from a config Node mapping ``key: std`` or ``key: {std: s}`` or
    ``key: {distribution: normal|uniform, std: s | half_width: h}``; each a number in SI or
    ``"<number> <unit>"`` (``"0.1 mm"``, ``"3 deg"``).  ``unit_problem(key, unit)``, where given, says what
    input ``key`` is where it cannot carry ``unit`` (``None`` where it can): such a spread is refused."""
    out = {}
    for key, item in node.items():
        problem = None if unit_problem is None else (lambda unit, key=str(key): unit_problem(key, unit))
        if isinstance(item.value, dict):
            item.check_keys(optional=("distribution", "std", "half_width"))
            kind = item["distribution"].string(DISTRIBUTIONS) if item.has("distribution") else "normal"
            if item.has("half_width") == item.has("std"):
                item.fail("exactly one of std or half_width")
            std = (_spread_value(item["std"], problem) if item.has("std")
                   else _spread_value(item["half_width"], problem) / np.sqrt(3.0))
            if kind == "normal" and item.has("half_width"):
                item.fail("std for a normal distribution (half_width is for uniform)")
        else:
            kind, std = "normal", _spread_value(item, problem)
        out[str(key)] = Spread(kind, float(std))
    return out


def directions(scenario, spreads, step=1e-4):
    """``{key: (dp, dS)}``: derivative of the 26 parameters (dict) and of S (2x2 or None) per unit
    of each input of the Whipple ``scenario``; exact unit vectors for parameter names, central
    differences for the rest."""
    built = scenario.build()
    S0 = built.stiffness
    out = {}
    for key in spreads:
        if key in NAMES:
            out[key] = ({n: float(n == key) for n in NAMES}, None if S0 is None else np.zeros((2, 2)))
            continue
        x = scenario.value(key)
        h = step * abs(x) if x else step
        a, b = scenario.build({key: x + h}), scenario.build({key: x - h})
        dp = {n: (getattr(a.parameters, n) - getattr(b.parameters, n)) / (2 * h) for n in NAMES}
        out[key] = (dp, None if S0 is None else (np.asarray(a.stiffness) - np.asarray(b.stiffness)) / (2 * h))
    return out


def member_directions(scenario, spreads, speeds, step=1e-4):
    """``{key: dA}``: the dynamic block's derivative (n_speeds, n, n) per unit of each input of a
    member other than the Whipple bicycle: by the complex step through the generated code for a
    parameter of the model's code, by a central difference through the builder (relative step
    ``step``, absolute for an input at zero) for a design input (geometry, pose, material)."""
    built = scenario.build()
    taken = set(NAMES) | set(member_inputs(built.choice))       # a code parameter that is no input: value() says
    own = tuple(key for key in spreads if key in taken)
    out = dict(built.derivatives(speeds, own, STEP)) if own else {}
    for key in spreads:
        if key in out:
            continue
        x = scenario.value(key)
        h = step * abs(x) if x else step
        a, b = scenario.build({key: x + h}).model, scenario.build({key: x - h}).model
        out[key] = (a.dynamic_matrix(speeds) - b.dynamic_matrix(speeds)) / (2 * h)
    return out


def _directional_model(params, S, dp, dS):
    """The model at ``params + i h dp``, ``S + i h dS`` (complex step) and its values."""
    base = values_of(params)
    values = {n: base[n] + 1j * STEP * dp[n] for n in NAMES}
    Sc = None if S is None else np.asarray(S, dtype=float) + 1j * STEP * (0 if dS is None else dS)
    return model_of(values, Sc), values


def matrices_of(model, g):
    """``{"M", "C1", "K0", "K2"}`` of a Whipple model (``K0`` = static stiffness / g)."""
    mech = model.mechanics
    return {"M": mech.M, "C1": mech.C[1], "K0": mech.K[0] / g, "K2": mech.K[2]}


STATE_COEFFICIENTS = ("A0", "A1", "A2")
"""A member's matrices in a propagation: the dynamic block of ``A(v) = A0 + v A1 + v**2 A2``."""


def coefficients_of(model):
    """``{"A0", "A1", "A2"}``: the dynamic block of a model's state matrix, coefficient by power of the speed
    (zero beyond its degree)."""
    n = model.n_dynamic
    A = np.asarray(model.A)[:, :n, :n]
    return {name: A[k] if k < len(A) else np.zeros((n, n)) for k, name in enumerate(STATE_COEFFICIENTS)}


def model_matrices(built):
    """The matrices a propagation reports for a built scenario: the Whipple bicycle's ``M, C1, K0, K2``, or a
    member's state-matrix coefficients (:func:`coefficients_of`)."""
    if built.choice.members:
        return coefficients_of(built.model)
    return matrices_of(built.model, built.parameters.g)


_COEFFICIENT_SPEEDS = np.array([0.0, 1.0, 2.0])
"""Speeds (m/s) at which a member's derivative of ``A(v)`` is taken to give its coefficients' (exact for
the quadratic ``A(v)``: ``dA0 = dA(0)``, ``dA2 = (dA(2) - 2 dA(1) + dA(0)) / 2``, ``dA1 = dA(1) - dA0 - dA2``)."""


def _coefficient_derivatives(dA):
    """``{"A0", "A1", "A2"}`` of a member's ``dA`` at :data:`_COEFFICIENT_SPEEDS`."""
    a0 = dA[0]
    a2 = (dA[2] - 2 * dA[1] + dA[0]) / 2
    return dict(zip(STATE_COEFFICIENTS, (a0, dA[1] - a0 - a2, a2)))


@dataclass(frozen=True)
class Estimate(Result):
    """A critical speed's estimate: its ``nominal`` value and standard deviation ``std`` (m/s;
    ``None`` where the nominal bicycle has no such speed) and, from Monte Carlo draws, the linear
    std, the draws' mean and 2.5 % / 97.5 % quantiles (m/s) and the fraction of draws without it.

    Dict access (``estimate["std"]``, ``estimate.get("q025")``), what a propagation's ``speeds``
    held before 0.3, still works for one release with a :class:`DeprecationWarning`.

    See Also
    --------
    bikemass.uncertainty : Gives one per critical speed.

    Examples
    --------
    >>> import bikemass as bm
    >>> w = bm.uncertainty("benchmark", {"c": 0.005}).speeds["weave_speed"]
    >>> print(f"{w.nominal:.4f} +- {w.std:.4f} {w.units()['std']}", w.sampled)
    4.2924 +- 0.0574 m/s False
    """

    nominal: float | None = quantity("m/s", "the nominal bicycle's critical speed", default=None)
    std: float | None = quantity("m/s", "standard deviation (the method's)", default=None)
    linear_std: float | None = quantity("m/s", "Monte Carlo: the linear propagation's std", default=None)
    mean: float | None = quantity("m/s", "Monte Carlo: the draws' mean", default=None)
    q025: float | None = quantity("m/s", "Monte Carlo: 2.5 % quantile", default=None)
    q975: float | None = quantity("m/s", "Monte Carlo: 97.5 % quantile", default=None)
    fraction_without: float | None = quantity("", "Monte Carlo: fraction of draws without it", default=None)

    @property
    def sampled(self):
        """True for a Monte Carlo estimate."""
        return self.fraction_without is not None

    def to_dict(self):
        """``{"nominal", "std"}`` and, from Monte Carlo, ``linear_std, mean, q025, q975, fraction_without``."""
        keys = [f.name for f in fields(self)] if self.sampled else ["nominal", "std"]
        return {k: getattr(self, k) for k in keys}

    def _old_access(self, key):
        warnings.warn(f"Estimate[{key!r}]: an estimate is a typed value now; read .{key} (dict access goes "
                      "in the next release)", DeprecationWarning, stacklevel=3)

    def __getitem__(self, key):
        self._old_access(key)
        if key not in self.to_dict():
            raise KeyError(key)
        return getattr(self, key)

    def get(self, key, default=None):
        """Deprecated dict access: ``getattr(estimate, key)``, ``default`` for a key it lacks."""
        self._old_access(key)
        return getattr(self, key) if key in self.to_dict() else default

    def __contains__(self, key):
        return key in self.to_dict()

    def __iter__(self):
        self._old_access("...")
        return iter(self.to_dict())


STATE_UNITS = "SI (each entry's from its row and column states)"
"""The unit of a member's state-matrix coefficients in a propagation."""
MATRICES_UNIT = "each matrix's, as CanonicalMatrices declares it (a member's state-matrix coefficients: SI)"
"""What :attr:`Propagation.matrices` is declared in: each matrix in its own unit (:func:`propagation_units`)."""


def propagation_units():
    """The units block of a :class:`Propagation`'s document: ``{M, C1, K0, K2}`` as
    :class:`~bikemass.models.canonical.CanonicalMatrices` declares them, ``weave_speed`` and
    ``capsize_speed`` as :class:`Estimate` declares its values, ``eigenvalues`` as
    :attr:`Propagation.eigen` is declared (1/s)."""
    speed = Estimate.field_units()["nominal"]
    return {**{k: u for k, u in CanonicalMatrices.field_units().items() if k != "g"},
            **{k: STATE_UNITS for k in STATE_COEFFICIENTS}, "weave_speed": speed, "capsize_speed": speed, "eigenvalues": Propagation.field_units()["eigen"]}


@dataclass(frozen=True, eq=False, repr=False)
class Propagation(Result):
    """Nominal values and standard deviations; ``linear`` and (if sampled) ``montecarlo`` results
    (read-only mappings of read-only arrays).

    Attributes
    ----------
    matrices : mapping
        ``{M|C1|K0|K2: {"nominal": 2x2, "std": 2x2, ...}}`` (the method's std; for a member other than the
        Whipple bicycle ``{A0|A1|A2: ...}``, the dynamic block of its state matrix ``A0 + v A1 + v**2 A2``),
        each in its unit as
        :class:`~bikemass.models.canonical.CanonicalMatrices` declares it; empty for a member other
        than the Whipple bicycle.
    speeds : mapping
        ``{weave_speed|capsize_speed: Estimate}`` (m/s, declared by :class:`Estimate`).
    eigen : mapping
        ``{"speeds": (n,) m/s, "modes": {label: {"nominal": complex (n,), "std_re", "std_im", ...}}}``, 1/s.
    inputs : mapping
        ``{key: {"distribution", "std"}}``: each input's spread, in the input's own SI unit.
    method : PropagationMethod
        ``"linear"`` or ``"montecarlo"`` (a string enum).
    samples : mapping or None
        Monte Carlo draws ``{"weave_speed": (n,), "capsize_speed": (n,)}`` (m/s, ``nan`` where a draw
        has none), ``None`` for the linear method.

    See Also
    --------
    bikemass.uncertainty : Makes it.

    Examples
    --------
    >>> import bikemass as bm
    >>> u = bm.uncertainty("benchmark", {"c": 0.005})
    >>> print(u.method, sorted(u.matrices), u.units()["M"], u.units()["weave_speed"])
    linear ['C1', 'K0', 'K2', 'M'] kg m^2 m/s
    """

    matrices: Mapping = quantity(MATRICES_UNIT, "{M|C1|K0|K2: {nominal, std, ...}}")
    speeds: Mapping = quantity("m/s", "{weave_speed|capsize_speed: Estimate}")
    eigen: Mapping = quantity("1/s", "the eigenvalue bands over eigen['speeds'] (m/s)")
    inputs: Mapping = quantity("SI, each input's own", "{key: {distribution, std}}")
    method: PropagationMethod = PropagationMethod.LINEAR
    samples: Mapping | None = quantity("m/s", "Monte Carlo draws of the critical speeds, or None", default=None)

    def __post_init__(self):
        super().__post_init__()
        object.__setattr__(self, "method", PropagationMethod(self.method))

    def units(self):
        """The units block of :meth:`to_dict`: the matrices' as
        :class:`~bikemass.models.canonical.CanonicalMatrices` declares them, the critical speeds' as
        :class:`Estimate` does, the eigenvalues' as :attr:`eigen` is declared."""
        return propagation_units()

    def display_rows(self):
        """The method, the inputs' spreads and each critical speed's nominal value and std (Jupyter's
        table, ``repr``)."""
        rows = [("method", self.method, ""),
                ("inputs", ", ".join(f"{k} +- {v['std']:.3g}" for k, v in self.inputs.items()), "SI")]
        for key, value in self.speeds.items():
            nominal, std = value.nominal, value.std
            shown = "none" if nominal is None else f"{nominal:.6g}" + ("" if std is None else f" +- {std:.3g}")
            rows.append((key, shown, "m/s"))
        return rows

    def tables(self):
        """``{"speeds": Table, "eigenvalues": Table}``: one row per critical speed (its nominal value,
        standard deviation and, from Monte Carlo, mean, linear std, 2.5 % and 97.5 % quantiles, the
        fraction of draws without it; m/s), and one row per speed of the eigenvalue bands (each
        mode's nominal real and imaginary part and their standard deviations, 1/s; Monte Carlo's
        2.5 % and 97.5 % quantiles of the real part). The method and the inputs' spreads are the
        frames' ``attrs``."""
        names = list(self.speeds)
        keys = list(dict.fromkeys(k for v in self.speeds.values() for k in v.to_dict()))
        columns = {"output": names, **{k: [getattr(self.speeds[n], k) for n in names] for k in keys}}
        units = {k: "1" if k == "fraction_without" else "m/s" for k in keys}
        attrs = {"method": self.method, "inputs": {k: dict(v) for k, v in self.inputs.items()}}
        bands, band_units = {"speed": np.asarray(self.eigen["speeds"], dtype=float)}, {"speed": "m/s"}
        for label, m in self.eigen["modes"].items():
            for key, values in (("real", m["nominal"].real), ("imaginary", m["nominal"].imag),
                                ("std real", m["std_re"]), ("std imaginary", m["std_im"]),
                                ("real q025", m.get("re_q025")), ("real q975", m.get("re_q975"))):
                if values is not None:
                    bands[f"{label} {key}"] = np.asarray(values, dtype=float)
                    band_units[f"{label} {key}"] = "1/s"
        return {"speeds": Table(columns, units, attrs), "eigenvalues": Table(bands, band_units, attrs)}

    def to_dict(self):
        eig = {"speeds": list(map(float, self.eigen["speeds"])), "modes": {
            label: {"re": m["nominal"].real, "im": m["nominal"].imag, "std_re": m["std_re"],
                    "std_im": m["std_im"], **({"re_q025": m["re_q025"], "re_q975": m["re_q975"]}
                                              if "re_q025" in m else {})}
            for label, m in self.eigen["modes"].items()}}
        return {"method": str(self.method), "inputs": plain(self.inputs), "matrices": thaw(self.matrices),
                **{k: v.to_dict() for k, v in self.speeds.items()}, "eigenvalues": eig}


def linear_derivatives(params, S, dirs, speeds):
    """``{key: {"matrices": {name: 2x2}, "eig": (n, 4) complex, "weave_speed": float|None, ...}}``
    and the nominal modes, critical speeds."""
    model0 = model_of(values_of(params), S)
    modes = follow_modes(model0, speeds)
    X = modes.eigenvectors                                 # (n, 4, 4), columns = labelled modes
    Y = np.linalg.inv(X)
    found = critical_speeds(model0, max(float(np.max(speeds)), 30.0))
    crossings = _first_crossings(found)
    v = np.asarray(speeds, dtype=float)
    out = {}
    for key, (dp, dS) in dirs.items():
        mc, values = _directional_model(params, S, dp, dS)
        d = {"matrices": {m: np.imag(x) / STEP for m, x in matrices_of(mc, values["g"]).items()}}
        dA = np.imag(mc.dynamic_matrix(v)) / STEP
        d["eig"] = np.einsum("nij,njk,nki->ni", Y, dA, X)
        for name, c in crossings.items():
            d[name] = None if c is None else speed_derivatives(
                model0, {key: np.imag(mc.dynamic_matrix(c.speed)) / STEP}, c.speed, SPEEDS[name], c.frequency)[key]
        out[key] = d
    return out, modes, crossings


def _first_crossings(found):
    """``{weave_speed|capsize_speed: Crossing or None}`` of :class:`CriticalSpeeds` ``found``: the weave's
    first crossing and the first real one."""
    return {"weave_speed": found.weave_crossing, "capsize_speed": found.capsize_crossing}


def first_crossings(model, speeds):
    """``{weave_speed|capsize_speed: Crossing or None}``: the first crossing of the weave and the first
    real one on ``(0, max(speeds, 30)]`` m/s."""
    return _first_crossings(critical_speeds(model, max(float(np.max(speeds)), 30.0)))


def member_derivatives(scenario, built, spreads, speeds, step):
    """As :func:`linear_derivatives`, for a member other than the Whipple bicycle (its matrices: the state
    matrix's coefficients, :func:`coefficients_of`)."""
    model0 = built.model
    modes = follow_modes(model0, speeds)
    X = modes.eigenvectors
    Y = np.linalg.inv(X)
    crossings = first_crossings(model0, speeds)
    v = np.asarray(speeds, dtype=float)
    at = {name: np.array([c.speed]) for name, c in crossings.items() if c is not None}
    out = {}
    extra = len(_COEFFICIENT_SPEEDS)
    for key, dA in member_directions(scenario, spreads, np.concatenate([v, *at.values(), _COEFFICIENT_SPEEDS]),
                                     step).items():
        d = {"matrices": _coefficient_derivatives(dA[len(dA) - extra:]),
             "eig": np.einsum("nij,njk,nki->ni", Y, dA[:len(v)], X)}
        ends = dict(zip(at, dA[len(v):len(dA) - extra]))
        for name, c in crossings.items():
            d[name] = None if c is None else speed_derivatives(
                model0, {key: ends[name]}, c.speed, SPEEDS[name], c.frequency)[key]
        out[key] = d
    return out, modes, crossings


def propagate(scenario, spreads, method="linear", samples=1000, seed=0, speeds=None, step=1e-4,
              max_speeds=MAX_SPEEDS):
    """:class:`Propagation` of ``spreads`` (``{key: Spread}``) through a
    :class:`~bikemass.scenario.scenario.Scenario` (any member of the model family); ``speeds`` (m/s)
    for the eigenvalue bands, at most ``max_speeds`` of them, and at most :data:`MAX_BAND_VALUES`
    Monte Carlo samples x speeds."""
    if not isinstance(scenario, Scenario):
        raise InputError("scenario", "(argument)", f"a bikemass.Scenario, not {type(scenario).__name__}")
    _check_options(spreads, method, samples, seed)
    speeds = speed_grid(0, 10, 0.1) if speeds is None else speed_values(speeds, max_speeds)
    if method == "montecarlo" and samples * len(speeds) > MAX_BAND_VALUES:
        raise InputError("samples", samples, f"at most {MAX_BAND_VALUES} samples x speeds (the Monte Carlo bands "
                         f"keep 4 real parts each), got {samples} x {len(speeds)}")
    built = scenario.build()
    sigma = {k: s.std for k, s in spreads.items()}
    if built.choice.members:
        derivs, modes, crossings = member_derivatives(scenario, built, spreads, speeds, step)
        nominal = coefficients_of(built.model)
    else:
        params, S = built.parameters, built.stiffness
        derivs, modes, crossings = linear_derivatives(params, S, directions(scenario, spreads, step), speeds)
        nominal = matrices_of(model_of(values_of(params), S), params.g)

    def rss(get):
        return np.sqrt(sum((np.asarray(get(derivs[k]), dtype=float) * sigma[k]) ** 2 for k in spreads))

    matrices = {m: {"nominal": np.real(nominal[m]), "std": rss(lambda d, m=m: d["matrices"][m])} for m in nominal}
    speed_out = {}
    for name, c in crossings.items():
        speed_out[name] = Estimate(None if c is None else c.speed,
                                   None if c is None else float(rss(lambda d, name=name: d[name])))
    eig_modes = {label: {"nominal": modes.eigenvalues[:, i],
                         "std_re": rss(lambda d, i=i: d["eig"][:, i].real),
                         "std_im": rss(lambda d, i=i: d["eig"][:, i].imag)}
                 for i, label in enumerate(modes.labels)}
    inputs = {k: {"distribution": s.kind, "std": s.std} for k, s in spreads.items()}
    if method == "linear":
        return Propagation(matrices, speed_out, {"speeds": speeds, "modes": eig_modes}, inputs, method)
    return _montecarlo(scenario, spreads, samples, seed, speeds, matrices, speed_out, eig_modes, inputs)


MAX_SAMPLES = 10 ** 6
"""Most Monte Carlo draws of one propagation."""
MAX_BAND_VALUES = 10 ** 7
"""Most Monte Carlo samples x speeds of one propagation (4 real parts of 8 bytes each: 320 MB)."""


def _check_options(spreads, method, samples, seed):
    """InputError for options :func:`propagate` cannot use: a spread that is not a
    :class:`Spread` of a known kind with a finite std >= 0, an unknown method, a number of
    Monte Carlo samples outside 2 .. :data:`MAX_SAMPLES`, a seed that is not a whole number >= 0."""
    for key, spread in spreads.items():
        if not isinstance(key, str):
            raise InputError("spreads", repr(key), "an input key: a parameter name or a dotted path (a string)")
        if not isinstance(spread, Spread) or spread.kind not in DISTRIBUTIONS:
            raise InputError("spreads", key, f"a Spread of kind {' or '.join(DISTRIBUTIONS)}, got {spread!r}")
        if not finite_real(spread.std) or spread.std < 0:
            raise InputError("spreads", key, f"a finite standard deviation >= 0, got {spread.std!r}")
    if method not in METHODS:
        raise InputError("method", method, "linear or montecarlo")
    if method == "montecarlo":
        if isinstance(samples, bool) or not isinstance(samples, (int, np.integer)) or not 2 <= samples <= MAX_SAMPLES:
            raise InputError("samples", samples, f"a number of samples from 2 to {MAX_SAMPLES}")
        if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
            raise InputError("seed", seed, "a random seed: a whole number >= 0")


@renamed_keywords(bike="bicycle")
def uncertainty(bicycle: "str | os.PathLike | RiderLeanParameters | Scenario",
                spreads: "Mapping[str, float | Spread] | None" = None,
                rider: "str | None" = None, stiffness: "str | None" = None, combine: "str | None" = None,
                method: str = "linear", samples: int = 1000, seed: int = 0, speeds: "ArrayLike | None" = None,
                max_speeds: int = MAX_SPEEDS, model: "str | None" = None, **members: object) -> Propagation:
    """The spread of the canonical matrices, eigenvalues and critical speeds from spreads of the inputs.

    ``linear``: first-order propagation, ``std(y) = sqrt(sum_i (dy/dx_i std_i)^2)``, with exact
    derivatives (complex step; eigenvalues and critical speeds by their implicit functions);
    ``montecarlo``: ``samples`` seeded draws of all inputs, every output recomputed. They agree
    while the outputs are close to linear over a few standard deviations (docs/analysis.md).

    Parameters
    ----------
    bicycle : str, os.PathLike or Scenario
        Anything ``bm.load_bicycle`` takes (a BicycleParameters file's ``+/-`` values are available
        as spreads), or a :class:`~bikemass.scenario.scenario.Scenario`, whose own rider, stiffness,
        model and tyres are used, each replaced by a keyword given here (``model=``, ``rider=``,
        ``stiffness=``, ``combine=``, a member's such as ``tyres=``). (``bike=`` is the deprecated old name.)
    spreads : Mapping, optional
        Default: the bicycle's own standard deviations (a bicycle computed from measurements: its
        measurements ``measured.<name>``, in its file's units; a parameter file with ``+/-`` values
        or an ``uncertainty:`` block: its parameters), as ``bikemass uncertainty`` takes them.
        ``{input key: std}`` (a normal distribution) or ``{input key: Spread}``
        (:class:`~bikemass.analysis.uncertainty.Spread`: ``normal`` or ``uniform``), the std in
        SI (m, kg, rad, ...) when bare, or a ``"<number> <unit>"`` string (``"0.1 mm"``). Keys: the 26 benchmark names or
        geometry-level paths (:mod:`bikemass.scenario.inputs`).
    rider : str, optional
        A pose name or file; ``None``: no rider (a Scenario's own).
    stiffness : str, optional
        ``"infinite"`` (rigid) or a material name, as for :func:`bikemass.stiffness`; ``None``: the
        bicycle's own (a parameter file's frame stiffness, else rigid; a Scenario's own).
    combine : {"exact", "thesis"}, optional
        How the rider joins the rear frame; ``None``: ``"exact"`` (a Scenario's own).
    method : {"linear", "montecarlo"}
        First-order propagation, or sampling (``samples`` draws from ``seed``).
    samples : int
        Monte Carlo draws (``montecarlo`` only).
    seed : int
        Seed of the Monte Carlo draws (a whole number >= 0): the same seed, the same result.
    speeds : array_like of shape (n,), optional
        Speeds (m/s) of the eigenvalue bands; default 0..10 m/s in 0.1 m/s.
    max_speeds : int
        Most speeds taken (default 100000); more is an InputError before any work.
    model : str, optional
        The member of the model family (``"whipple"``, ``"rider-lean"``, ``"tyre"``, ``"flexible"``
        or members joined by ``+``); default the bicycle's own (``"rider-lean"`` for
        RiderLeanParameters, else ``"whipple"``).
    **members
        A member's parameters by its keyword (``tyres=`` a tyre file or mapping; default: the published
        defaults), as for :class:`~bikemass.scenario.scenario.Scenario`.

    Returns
    -------
    Propagation
        ``speeds`` ``{weave_speed|capsize_speed: {"nominal", "std", ...}}`` (m/s), ``matrices``
        ``{M|C1|K0|K2: {"nominal", "std"}}``, ``eigen`` (the bands over ``speeds``), ``inputs``,
        ``method``, ``samples`` (the draws, Monte Carlo only).

    Raises
    ------
    InputError
        An unknown key, a negative std, an unknown method, a bad ``samples`` or ``seed``, more than
        ``max_speeds`` speeds, or a bicycle or rider that cannot be loaded.

    See Also
    --------
    sensitivity : The derivatives the linear method uses.

    Examples
    --------
    >>> import bikemass as bm
    >>> u = bm.uncertainty("benchmark", {"c": 0.005, "mB": 1.0})
    >>> w = u.speeds["weave_speed"]                   # an Estimate: nominal and std in m/s
    >>> print(f"weave {w.nominal:.4f} +- {w.std:.4f} m/s")
    weave 4.2924 +- 0.0594 m/s
    >>> mc = bm.uncertainty("benchmark", {"c": 0.005, "mB": 1.0}, method="montecarlo", samples=200, seed=1)
    >>> print(f"Monte Carlo: +- {mc.speeds['weave_speed'].std:.2f} m/s from {len(mc.samples['weave_speed'])} draws")
    Monte Carlo: +- 0.06 m/s from 200 draws

    A measured bicycle brings its own (here the Browser's 40 measurements):

    >>> import warnings
    >>> with warnings.catch_warnings():
    ...     warnings.simplefilter("ignore", bm.BikemassWarning)     # its IByy, as measured
    ...     u = bm.uncertainty("browser-measured")
    >>> print(len(u.inputs), f"weave +- {u.speeds['weave_speed'].std:.4f} m/s")
    40 weave +- 0.0453 m/s
    """
    if spreads is not None and not isinstance(spreads, dict):
        raise InputError("spreads", "(argument)", f"a mapping of input key -> std or Spread, got {type(spreads).__name__}")
    if isinstance(bicycle, Scenario):       # the keywords given change the scenario, as bm.stability's do
        given = {"rider": rider, "stiffness": stiffness, "combine": combine, "model": model}
        changes = {k: v for k, v in given.items() if v is not None}
        scenario = bicycle.replace(**changes, **members) if changes or members else bicycle
    else:
        scenario = Scenario(bicycle, rider, stiffness, combine or "exact", model=model, member_inputs=members)
    if spreads is None:
        spreads = scenario.measurement_std or scenario.file_std
        if not spreads:
            raise InputError("spreads", "(argument)", "standard deviations: the bicycle has none of its own (a "
                             "BicycleParameters file with +/- values, a parameter file with uncertainty:), so give them")
    spreads = {k: v if isinstance(v, Spread) else Spread("normal", v) for k, v in spreads.items()}
    return propagate(scenario, spreads, method, samples, seed, speeds, max_speeds=max_speeds)


def _montecarlo(scenario, spreads, n, seed, speeds, matrices, speed_out, eig_modes, inputs):
    rng = np.random.default_rng(seed)
    keys = list(spreads)
    nominal = {k: scenario.value(k) for k in keys}
    draws = {k: nominal[k] + spreads[k].sample(rng, n) for k in keys}
    mats = {m: [] for m in matrices}
    crit = {name: [] for name in SPEEDS}
    models = []
    for j in range(n):
        try:
            built = scenario.build({k: float(draws[k][j]) for k in keys})
        except InputError as exc:            # a draw the model is not defined for: the spread is too wide
            raise InputError(exc.source, exc.key, f"spreads whose Monte Carlo draws stay valid (draw {j + 1} of "
                             f"{n}: {exc.expected})") from None
        for m, x in model_matrices(built).items():      # its matrices as built
            mats[m].append(np.real(x))
        found = critical_speeds(built.model)
        for name in SPEEDS:
            v = getattr(found, name)
            crit[name].append(np.nan if v is None else v)
        models.append(built.model)
    many = follow_many(models, speeds)       # the draws' modes followed at once where they can be
    reals = many[0].real if many is not None else [follow_modes(m, speeds).eigenvalues.real for m in models]
    for m in matrices:
        a = np.array(mats[m])
        matrices[m] = {**matrices[m], "linear_std": matrices[m]["std"], "std": a.std(axis=0, ddof=1),
                       "mean": a.mean(axis=0)}
    samples = {}
    for name in SPEEDS:
        a = np.array(crit[name])
        ok = a[np.isfinite(a)]
        samples[name] = a
        speed_out[name] = Estimate(nominal=speed_out[name].nominal, linear_std=speed_out[name].std,
                                   std=float(ok.std(ddof=1)) if ok.size > 1 else None,
                                   mean=float(ok.mean()) if ok.size else None,
                                   q025=float(np.quantile(ok, 0.025)) if ok.size else None,
                                   q975=float(np.quantile(ok, 0.975)) if ok.size else None,
                                   fraction_without=float(1 - ok.size / n))
    reals = np.array(reals)                                  # (n, speeds, 4)
    for i, label in enumerate(eig_modes):
        eig_modes[label] = {**eig_modes[label], "re_q025": np.quantile(reals[:, :, i], 0.025, axis=0),
                            "re_q975": np.quantile(reals[:, :, i], 0.975, axis=0)}
    return Propagation(matrices, speed_out, {"speeds": speeds, "modes": eig_modes}, inputs, "montecarlo",
                       samples)


def uncertainty_figure(result, title="", size=None):
    """Real parts against speed with +-2 std bands (linear) and 95 % Monte Carlo bands, and the
    Monte Carlo histograms of the critical speeds (a matplotlib Figure)."""
    # lazy: matplotlib only for a figure
    from ..plots.figure import Figure

    fig = Figure(figsize=size or (11, 5), layout="constrained")
    axes = fig.subplots(1, 2, width_ratios=(2, 1))
    v = result.eigen["speeds"]
    keys = {label: "weave" if label in ("weave 1", "weave 2") else label for label in result.eigen["modes"]}
    colours = mode_colours(keys.values())                    # "weave 1", "weave 2" -> the weave's colour
    for label, m in result.eigen["modes"].items():
        c = colours[keys[label]]
        re = m["nominal"].real
        axes[0].plot(v, re, color=c, ls="--" if label == "weave 2" else "-", label=label)
        axes[0].fill_between(v, re - 2 * m["std_re"], re + 2 * m["std_re"], color=c, alpha=0.2, lw=0)
        if "re_q025" in m:
            axes[0].plot(v, m["re_q025"], color=c, ls=":", lw=1)
            axes[0].plot(v, m["re_q975"], color=c, ls=":", lw=1)
    axes[0].axhline(0, color="k", lw=0.6)
    axes[0].set_ylim(-10, 10)
    axes[0].set_xlabel("speed (m/s)")
    axes[0].set_ylabel("Re(eigenvalue) (1/s)")
    axes[0].set_title("shaded: linear +-2 std" + ("; dotted: Monte Carlo 95 %" if result.samples else ""))
    axes[0].legend(loc="lower left", fontsize=8)
    for name, colour in zip(SPEEDS, ("tab:blue", "tab:red")):
        s = result.speeds[name]
        if result.samples is not None and np.isfinite(result.samples[name]).any():
            a = result.samples[name]
            axes[1].hist(a[np.isfinite(a)], bins=40, color=colour, alpha=0.5, label=name.replace("_", " "))
        elif s.nominal is not None:
            axes[1].axvspan(s.nominal - 2 * s.std, s.nominal + 2 * s.std, color=colour,
                            alpha=0.3, label=f"{name.replace('_', ' ')} +-2 std")
        if s.nominal is not None:
            axes[1].axvline(s.nominal, color=colour)
    axes[1].set_xlabel("critical speed (m/s)")
    axes[1].legend(fontsize=8)
    if title:
        fig.suptitle(title)
    return fig
