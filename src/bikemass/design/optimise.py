"""``bm.optimise``: the design in a box that maximises, minimises or hits a metric under constraints.

The search: the box is screened (its centre and a scrambled Sobol sample, values only), then a
gradient-based local search (scipy's SLSQP, with bounds and the constraints) starts from each of the
best ``starts`` screened designs; the best feasible end point is the answer, or the best feasible
design built on the way where a local search wandered off a better one (then ``converged`` is false).  Variables are scaled
to the unit box, the objective by its size at the box's centre.  Gradients are those of
:class:`~bikemass.design.problem.Problem`.

A metric that is not smooth (a stable range whose end switches from one mode to another, a speed
that leaves the span) would fool a gradient method into a false convergence, so the end point is
checked: the one-sided slopes of the objective along each free variable must agree.  Where they
do not, ``converged`` is false and the result says along which variable the kink lies.
"""

import os
import time
import warnings
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np

from ..core.errors import InputError, short
from ..core.results import Result, quantity
from ..models.parameters import NAMES, parameter_units
from .metrics import CURVE_FREQUENCIES, metric
from .problem import Problem
from .spec import OptimiseSpec, read_spec

FEASIBLE = 1e-6
"""Largest constraint violation accepted, relative to the constraint's scale."""
KINK = 0.05
"""One-sided slopes differing by more than this share of the larger one make a kink."""
KINK_STEP = 1e-4
"""Step of the one-sided slopes, as a share of the variable's range."""
SLSQP_TOLERANCE = {"target": 1e-16, "maximise": 1e-10, "minimise": 1e-10}
"""SLSQP's ``ftol`` on the scaled objective (a target's is the square of a relative miss)."""
TARGET_TOLERANCE = 1e-6
"""A target is reached where the metric is within this share of the target's size (1 where it is 0)."""
MAX_ITERATIONS = 100
ROUGH_SIMPLEX = 0.05
"""Size of Nelder-Mead's first simplex (:func:`_rough`), a share of the unit box."""
ROUGH_PENALTY = 1e3
"""Weight of the constraints' violation in :func:`_rough`'s objective."""
ROUGH_EVALUATIONS = 400
"""Designs one Nelder-Mead search may build (:func:`_rough`)."""
ROUGH_RESTARTS = 1
"""Times :func:`_rough` restarts Nelder-Mead from where it ended."""
IMPROVEMENT = 1e-6
"""A design built on the way replaces the local searches' best end point where it is better by more than
this (the scaled objective: a share of the objective's size at the box's centre)."""
SCREENING = 32
"""Designs screened per design variable (rounded up to a power of two): a metric such as the HQM peak
under a stable closed loop is defined well on a tenth of a box and rough there, so the local searches
need starts that are already good."""


@dataclass(frozen=True, eq=False)
class Evaluation(Result):
    """One design the search asked for: its variables (SI, in the spec's order), the objective's
    metric there and the largest constraint violation (0: feasible; in each constraint's SI unit
    relative to its scale)."""

    variables: tuple = ()
    objective: float = 0.0
    violation: float = 0.0


@dataclass(frozen=True, eq=False)
class OptimiseResult(Result):
    """The best design found by :func:`optimise` and how it was found.

    Attributes
    ----------
    variables : mapping
        ``{key: value}`` of the design (SI: m, rad, kg, ...).
    objective : float
        The objective's metric at the design (its SI unit: :attr:`metric_units`).
    metric, sense : str
        The objective's metric and ``"maximise"``, ``"minimise"`` or ``"target"``.
    target : float or None
        The target value (``sense == "target"``).
    metrics : mapping
        ``{metric: value}`` of the objective's and the constraints' metrics at the design (SI).
    converged : bool
        The local search ended at a stationary point that meets every constraint, and the objective is
        smooth there (see the module docstring).
    evaluations : int
        Designs built (each a bicycle, its rider re-seated, its model), gradients' differences included.
    history : tuple of Evaluation
        Every design the search asked for, in order (the screening first).
    message : str
        Why the search stopped.
    notes : tuple of str
        What a reader must know: kinks, metrics undefined on part of the box, active bounds.
    gradient : str
        How the gradients were computed.
    variable_units, metric_units : mapping
        SI units of the variables and of the metrics.
    seconds : float
        Wall time of the search (s).

    Examples
    --------
    >>> import bikemass as bm
    >>> from bikemass.design.spec import DesignVariable, OptimiseSpec
    >>> spec = OptimiseSpec(source="example", bike="benchmark", variables=(DesignVariable("mH", 2.0, 6.0),),
    ...                     sense="maximise", objective="stable-range")
    >>> result = bm.optimise(spec)
    >>> print(f"mH = {result.variables['mH']:.1f} kg: stable over {result.objective:.3f} m/s", result.notes)
    mH = 6.0 kg: stable over 1.912 m/s ('at a bound of the box: mH',)
    """

    variables: Mapping[str, float]
    objective: float
    metric: str
    sense: str
    target: float | None
    metrics: Mapping[str, float]
    converged: bool
    evaluations: int
    history: tuple
    message: str
    notes: tuple
    gradient: str
    variable_units: Mapping[str, str]
    metric_units: Mapping[str, str]
    seconds: float = quantity("s", default=0.0)

    def to_dict(self):
        """The ``bikemass optimise --format json`` document."""
        return {"variables": dict(self.variables), "objective": self.objective, "metric": self.metric,
                "sense": self.sense, "target": self.target, "metrics": dict(self.metrics),
                "converged": self.converged, "evaluations": self.evaluations,
                "history": [{"variables": list(h.variables), "objective": h.objective, "violation": h.violation}
                            for h in self.history],
                "message": self.message, "notes": list(self.notes), "gradient": self.gradient,
                "seconds": self.seconds}

    def units(self):
        """The ``units`` block of :meth:`to_dict`: each variable's and metric's SI unit."""
        unit = self.metric_units[self.metric]
        return {**dict(self.variable_units), **dict(self.metric_units), "objective": unit, "target": unit,
                "violation": "SI of each constraint's metric, relative to its bound", "seconds": "s"}

    def display_rows(self):
        rows = [(k, f"{v:.6g}", self.variable_units[k]) for k, v in self.variables.items()]
        rows.append((f"{self.sense} {self.metric}", f"{self.objective:.6g}", self.metric_units[self.metric]))
        rows += [(k, f"{v:.6g}", self.metric_units[k]) for k, v in self.metrics.items() if k != self.metric]
        rows += [("converged", "yes" if self.converged else "no", ""), ("evaluations", str(self.evaluations), "")]
        return rows


def optimise(spec: "OptimiseSpec | str | os.PathLike",
             progress: "Callable[[], object] | None" = None) -> OptimiseResult:
    """The design of a spec's box that maximises, minimises or hits its objective under its constraints.

    Parameters
    ----------
    spec : OptimiseSpec or path
        An :class:`~bikemass.design.spec.OptimiseSpec` or the YAML file of one (docs/optimise.md).
    progress : callable, optional
        Called with no argument after each design the search asks for (a progress bar's step).

    Returns
    -------
    OptimiseResult
        The design (SI), the objective and the constraints' metrics there, whether the search
        converged, the designs built, the history.

    Raises
    ------
    InputError
        A bad spec, or a box where no design can be built.

    See Also
    --------
    plot_optimisation : Draw the search and the objective around the design.
    sweep : Every design of a grid instead of the best one.
    sensitivity : The exact derivatives the gradients are made of.

    Examples
    --------
    The benchmark bicycle's trail that puts its weave speed at 5 m/s:

    >>> import bikemass as bm
    >>> from bikemass.design.spec import Bounds, DesignVariable, OptimiseSpec
    >>> spec = OptimiseSpec(source="example", bike="benchmark", variables=(DesignVariable("c", 0.02, 0.2),),
    ...                     sense="target", objective="weave-speed", target=5.0)
    >>> result = bm.optimise(spec)
    >>> print(f"c = {result.variables['c']:.6f} m, weave speed {result.objective:.6f} m/s, {result.converged}")
    c = 0.157486 m, weave speed 5.000000 m/s, True
    """
    start_time = time.perf_counter()
    checked = check_spec(spec)
    problem = Problem(checked)
    result = _search(checked, problem, progress, start_time)
    problem.warn([result.variables[v.key] for v in checked.variables])
    return result


def _search(spec, problem, progress, start_time):
    """:func:`optimise` of a checked spec on its :class:`~bikemass.design.problem.Problem`."""
    # lazy: scipy's optimizers and quasi-Monte Carlo load in about 0.3 s; only a search needs them
    from scipy.optimize import minimize
    from scipy.stats import qmc

    target_metric = metric(spec.objective)
    constraints = [(metric(c.metric), c) for c in spec.all_constraints]
    lo = np.array([v.low for v in spec.variables])
    hi = np.array([v.high for v in spec.variables])
    span = hi - lo
    n = len(lo)
    history = []

    def x_of(u):
        return lo + np.clip(u, 0.0, 1.0) * span

    def raw(u):
        return problem.value(target_metric, x_of(u))

    centre = np.full(n, 0.5)
    with warnings.catch_warnings():     # the design as given: a bad bicycle, rider or model is its own error,
        warnings.simplefilter("ignore")  # not the box's (its warnings are the designs' to give)
        problem.scenario.build()
    try:
        scale = abs(raw(centre)) or 1.0
    except InputError as exc:
        raise InputError(spec.source, "variables", f"a box whose centre can be built: {exc}") from None
    if spec.sense == "target":
        scale = abs(spec.target) or 1.0

    def scaled(m):
        """The search's objective (minimised, scaled) of the metric's value ``m``."""
        if spec.sense == "target":
            return ((m - spec.target) / scale) ** 2
        return (-m if spec.sense == "maximise" else m) / scale

    def objective(u):
        return scaled(raw(u))

    def objective_gradient(u):
        x = x_of(u)
        g = problem.gradient(target_metric, x) * span
        if spec.sense == "target":
            return 2 * (problem.value(target_metric, x) - spec.target) / scale ** 2 * g
        return (-g if spec.sense == "maximise" else g) / scale

    bound_scales = {}
    for m, c in constraints:             # each constraint scaled by its bounds' size or its metric's at the centre
        try:
            at_centre = abs(problem.value(m, x_of(centre)))
        except InputError:
            at_centre = 0.0
        bound_scales[id(c)] = max(*(abs(b) for b in (c.low, c.high) if b is not None), at_centre) or 1.0

    def inequalities(u):
        """Every constraint as ``g >= 0`` (scaled)."""
        x = x_of(u)
        out = []
        for m, c in constraints:
            value = problem.value(m, x)
            if c.low is not None:
                out.append((value - c.low) / bound_scales[id(c)])
            if c.high is not None:
                out.append((c.high - value) / bound_scales[id(c)])
        return np.array(out)

    def inequality_jacobian(u):
        x = x_of(u)
        rows = []
        for m, c in constraints:
            g = problem.gradient(m, x) * span / bound_scales[id(c)]
            if c.low is not None:
                rows.append(g)
            if c.high is not None:
                rows.append(-g)
        return np.array(rows).reshape(len(rows), n)

    def violation(u):
        g = inequalities(u) if constraints else np.zeros(0)
        return float(max(0.0, -g.min())) if len(g) else 0.0

    seen = {}

    def record(u):
        key = tuple(np.clip(u, 0.0, 1.0))
        if key not in seen:
            seen[key] = Evaluation(tuple(x_of(u).tolist()), raw(u), violation(u))
            history.append(seen[key])
            if progress is not None:
                progress()
        return seen[key]

    def tracked(f):
        def call(u):
            record(u)
            return f(u)
        return call

    # screening: the design as given, the centre and a scrambled Sobol sample of the box, values only
    m = int(np.ceil(np.log2(max(8, SCREENING * n))))
    points = [centre, *qmc.Sobol(d=n, scramble=True, seed=spec.seed).random_base2(m)]
    given = (np.array([problem.scenario.value(v.key) for v in spec.variables]) - lo) / span
    if np.all((given >= 0) & (given <= 1)):
        points.insert(0, given)                 # the design as given, where it lies in the box
    screened = []
    for u in points:
        try:
            e = record(u)
        except InputError:
            continue
        score = -e.objective if spec.sense == "maximise" else e.objective
        if spec.sense == "target":
            score = abs(e.objective - spec.target)
        screened.append((e.violation > FEASIBLE, e.violation, score, tuple(u)))
    if not screened:
        raise InputError(spec.source, "variables", "a box where some design can be built (none of the "
                         f"{len(points)} screened designs could)")
    for used, key in ((target_metric, spec.sense), *((m, f"constraints.{c.metric}") for m, c in constraints)):
        if used.name in problem.undefined and used.name not in problem.defined:
            raise InputError(spec.source, key, f"a metric that exists somewhere in the box: {used.name} exists at "
                             f"none of the {len(screened)} designs screened (the {problem.scenario.model.name} model; "
                             f"{used.name}: {used.description})")
    screened.sort()
    runs = []
    cons = ([{"type": "ineq", "fun": tracked(inequalities), "jac": inequality_jacobian}] if constraints else [])
    minimax = spec.objective == "hqm-peak" and spec.sense == "minimise"
    for *_, u0 in screened[:spec.starts]:
        try:
            if minimax:                    # a maximum over frequency: a kinked, steep objective (see _rough)
                res = _rough(tracked(objective), violation, np.array(u0), minimize)
            else:
                res = minimize(tracked(objective), np.array(u0), jac=objective_gradient, method="SLSQP",
                               bounds=[(0.0, 1.0)] * n, constraints=cons,
                               options={"ftol": SLSQP_TOLERANCE[spec.sense], "maxiter": MAX_ITERATIONS})
            if minimax:                    # polished as a minimax problem from where the direct search ended
                polished = _minimax(problem, x_of, span, scale, record, cons, np.clip(res.x, 0.0, 1.0), minimize)
                if violation(polished.x[:n]) <= FEASIBLE and objective(polished.x[:n]) <= objective(res.x):
                    res = polished
        except InputError as exc:          # the start stands (the screening built it), with why the search stopped
            v0 = violation(np.array(u0))
            runs.append((v0 > FEASIBLE, v0, float(objective(np.array(u0))), np.array(u0), False,
                         f"a design the search reached failed: {exc}"))
            continue
        u = np.clip(res.x[:n], 0.0, 1.0)
        v = violation(u)
        runs.append((v > FEASIBLE, v, float(objective(u)), u, bool(res.success), str(res.message)))
    best_built = min(((e.violation > FEASIBLE, e.violation, scaled(e.objective), e) for e in history),
                     key=lambda r: r[:3])       # from the values recorded, no design built again
    best_run = min(runs, key=lambda r: r[:3])
    if not best_built[0] and (best_run[0] or best_built[2] < best_run[2] - IMPROVEMENT):
        # a feasible design built on the way beats every end point clearly
        runs.append((*best_built[:3], (np.array(best_built[3].variables) - lo) / span, False,
                     "the best design built on the way (no local search ended at a better one)"))
    runs.sort(key=lambda r: (r[0], r[1], r[2]))
    infeasible, worst, _, u_best, success, message = runs[0]
    x_best = x_of(u_best)
    notes = []
    kinks = [] if minimax else _kinks(raw, u_best, n, spec, scale)
    if minimax:
        notes.append("the HQM peak, a maximum over frequency, was polished as a minimax problem (the curve held "
                     f"below a bound on {len(CURVE_FREQUENCIES)} frequencies, the bound minimised): at its optimum two "
                     "local peaks are often equal, a kink of the peak by design")
    if kinks:
        notes.append("the objective is not smooth at the design (one-sided slopes differ along "
                     + ", ".join(kinks) + "): e.g. a stable range whose end switches to another mode, a speed "
                     "that leaves the span, an HQM peak that moves to another frequency or gains that jump; the "
                     "design is the best found, not a stationary point")
    if infeasible:
        notes.append(f"no design met every constraint (largest violation {worst:.3g}, relative)")
    for name in sorted(problem.undefined):
        notes.append(f"{name} does not exist on part of the box: there it counted as "
                     f"{'0' if name == 'stable-range' else f'max_speed ({spec.max_speed:g} m/s)'}")
    active = [v.key for v, u in zip(spec.variables, u_best) if u <= 1e-9 or u >= 1 - 1e-9]
    if active:
        notes.append("at a bound of the box: " + ", ".join(active))
    missed = spec.sense == "target" and not abs(raw(u_best) - spec.target) <= TARGET_TOLERANCE * scale
    for used in dict.fromkeys(m for m, _ in constraints):
        if used.name != target_metric.name and not problem.exists(used, x_best):
            notes.append(f"{used.name} does not exist at the design found: its constraint was checked on the stand-in "
                         "for none (see above), not on a value")
    absent = not problem.exists(target_metric, x_best)
    if absent:
        notes.append(f"{target_metric.name} does not exist at the design found: its value is the stand-in for none "
                     "(see above), not a result")
    elif missed:
        notes.append(f"the target {spec.target:g} is not reached in the box: the nearest design found gives "
                     f"{raw(u_best):.6g} ({target_metric.unit})")
    metrics = {name: problem.value(metric(name), x_best) for name in spec.metrics}
    gradient = _gradient_description(spec, problem.design(x_best).built.choice.members)
    return OptimiseResult(
        variables={v.key: float(x) for v, x in zip(spec.variables, x_best)},
        objective=float(problem.value(target_metric, x_best)), metric=spec.objective, sense=spec.sense,
        target=spec.target, metrics=metrics, converged=bool(success and not infeasible and not kinks and not missed and not absent),
        evaluations=problem.builds, history=tuple(history), message=message, notes=tuple(notes),
        gradient=gradient, variable_units={v.key: _unit_of(v) for v in spec.variables},
        metric_units={name: metric(name).unit for name in spec.metrics},
        seconds=time.perf_counter() - start_time)


def _rough(objective, violation, u0, minimize):
    """Nelder-Mead from ``u0`` (a simplex of :data:`ROUGH_SIMPLEX` of the box) on the objective plus
    :data:`ROUGH_PENALTY` times the constraints' violation: no gradient, so a kink or a steep side of
    the objective cannot throw the search across the box as a first gradient step does."""
    n = len(u0)

    def penalised(u):
        return objective(u) + ROUGH_PENALTY * violation(u)
    res = None
    for _ in range(ROUGH_RESTARTS + 1):    # restarted from where it ended with a fresh simplex: a collapsed one stalls
        simplex = np.vstack([u0, u0 + ROUGH_SIMPLEX * np.eye(n)])
        simplex = np.where(simplex > 1.0, 2 * u0 - simplex, simplex)      # kept in the box
        res = minimize(penalised, u0, method="Nelder-Mead", bounds=[(0.0, 1.0)] * n,
                       options={"initial_simplex": simplex, "xatol": 1e-6, "fatol": 1e-9,
                                "maxfev": ROUGH_EVALUATIONS})
        u0 = np.clip(res.x, 0.0, 1.0)
    return res


def _minimax(problem, x_of, span, scale, record, constraints, u0, minimize):
    """SLSQP on ``min t`` subject to ``HQM(w_j; x) <= t`` at :data:`~bikemass.design.metrics.CURVE_FREQUENCIES`
    and the spec's ``constraints`` (functions of the design ``u`` alone): the HQM peak, a maximum over
    frequency, minimised without differentiating a maximum.  The decision vector is ``(u, t)``."""
    n = len(u0)

    def curve(z):
        record(z[:n])
        return problem.hqm_curve(x_of(z[:n])) / scale

    def below(z):
        return z[n] - curve(z)

    def below_jacobian(z):
        jac = problem.hqm_curve_jacobian(x_of(z[:n])) * span / scale
        return np.hstack([-jac, np.ones((len(jac), 1))])

    lifted = [{"type": "ineq", "fun": below, "jac": below_jacobian}]
    for c in constraints:                           # the spec's constraints, on u alone
        fun, jac = c["fun"], c["jac"]
        lifted.append({"type": "ineq", "fun": lambda z, f=fun: f(z[:n]),
                       "jac": lambda z, j=jac: np.hstack([j(z[:n]), np.zeros((len(j(z[:n])), 1))])})
    z0 = np.append(u0, float(np.max(curve(np.append(u0, 0.0)))))
    return minimize(lambda z: z[n], z0, jac=lambda z: np.eye(n + 1)[n], method="SLSQP",
                    bounds=[(0.0, 1.0)] * n + [(0.0, None)], constraints=lifted,
                    options={"ftol": SLSQP_TOLERANCE["minimise"], "maxiter": MAX_ITERATIONS})


def _gradient_description(spec, members):
    """How the gradients of ``spec``'s metrics were computed, in words."""
    kinds = {metric(name).kind for name in spec.metrics}
    exact_x = all(v.key in NAMES for v in spec.variables) and not members
    parts = []
    if kinds - {"geometry", "handling"}:
        parts.append("exact in the model's parameters (eigenvalue derivatives and the complex step)"
                     + ("" if exact_x else ", chained with central differences (relative step 1e-4) of the "
                        "parameters with respect to the design variables (geometry, the rider re-seated)"))
    if kinds & {"geometry", "handling"}:
        parts.append("central differences (relative step 1e-4) of "
                     + " and ".join(sorted(n for n in spec.metrics if metric(n).kind in ("geometry", "handling"))))
    return "; ".join(parts)


def _unit_of(variable):
    """The SI unit of a design variable's value."""
    if variable.unit is not None:
        return variable.unit
    return parameter_units()[variable.key] if variable.key in NAMES else ""


def _kinks(metric_at, u, n, spec, scale):
    """The variables (keys) along which the one-sided slopes at ``u`` of the objective's metric
    (``metric_at(u)``, of size ``scale``) jump (a kink), free variables only (not at a bound).

    A smooth metric's one-sided slopes differ by its curvature times the step, so halving the step
    halves the difference; at a kink the difference stays.  A jump counts where it is above
    :data:`KINK` of the slopes (and round-off) at both steps and shrinks by less than a quarter."""
    out = []
    f0 = metric_at(u)

    def jump(k, h):
        step = np.zeros(n)
        step[k] = h
        up, down = (metric_at(u + step) - f0) / h, (f0 - metric_at(u - step)) / h
        return abs(up - down), max(abs(up), abs(down))
    for k in range(n):
        if u[k] <= KINK_STEP or u[k] >= 1 - KINK_STEP:
            continue
        try:
            (big, slope), (small, _) = jump(k, KINK_STEP), jump(k, KINK_STEP / 2)
        except InputError:
            continue
        floor = KINK * slope + 1e-8 * scale / KINK_STEP
        if big > floor and small > 0.75 * big:
            out.append(spec.variables[k].key)
    return out


def check_spec(spec: "OptimiseSpec | str | os.PathLike") -> OptimiseSpec:
    """``spec`` as an :class:`OptimiseSpec`: read from a path, or InputError for anything else."""
    if isinstance(spec, OptimiseSpec):
        return spec
    if isinstance(spec, str) or hasattr(spec, "__fspath__"):
        return read_spec(spec)
    raise InputError("spec", short(spec), "an optimisation spec: a YAML file or an OptimiseSpec")
