"""One design problem: design variables -> a built scenario -> metric values and their gradients.

A design ``x`` (SI: m, rad, kg) is applied to the scenario as changes (a benchmark parameter by
value, a dotted path into the bicycle or pose YAML with its SI unit), built once and cached by
value.  Gradients chain exact derivatives with respect to the model's parameters with the
derivatives of those parameters with respect to ``x`` (:meth:`Problem.parameter_jacobian`): exact
for a benchmark parameter varied by name, a central difference of relative step
:data:`GEOMETRY_STEP` for a dotted path (the geometry -> mass properties -> parameters step, the
rider re-seated on every design).
"""

import warnings
from functools import cached_property

import numpy as np

from ..analysis.engine.critical import critical_speeds
from ..analysis.model import state_matrix_derivatives, stiffness_state_derivatives
from ..analysis.sensitivity import GEOMETRY_STEP, difference_sides, member_state_derivatives, speed_derivatives
from ..core.config import Node
from ..core.errors import InputError
from ..models.parameters import NAMES
from ..rider.body import load_body
from ..scenario.inputs import split_changes
from .metrics import GEOMETRY, HANDLING, PARAMETERS, UNDEFINED, handling_of, hqm_curve_of, rider_in_loop, parameter_function, \
    parameter_gradient, speed_crossings, toe_overlap_of

STIFFNESS_CELLS = {"S_phiphi": ((0, 0),), "S_phidelta": ((0, 1),), "S_deltadelta": ((1, 1),)}
"""The independent entries of the symmetric frame stiffness S and the cell each is read from."""


def _step_size(value):
    """The central differences' step for a variable at ``value``: :data:`GEOMETRY_STEP` relative, absolute
    at 0 (the same step wherever a design is differenced, so that its designs are built once)."""
    return GEOMETRY_STEP * abs(value) if value else GEOMETRY_STEP


class Design:
    """One design built: ``x`` (SI), the :class:`~bikemass.scenario.scenario.Built` and, on first
    use, its critical speeds on ``(0, max_speed]``."""

    def __init__(self, problem, x):
        self.problem, self.x = problem, x
        self.changes = problem.changes(x)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            self.built = problem.scenario.build(self.changes)
        self.warnings = tuple(caught)
        """The warnings building the design raised (kept, not shown: :meth:`Problem.warn` shows a design's)."""

    @cached_property
    def critical(self):
        """:class:`~bikemass.analysis.engine.critical.CriticalSpeeds` of the design's model."""
        return critical_speeds(self.built.model, self.problem.max_speed)

    @cached_property
    def rider(self):
        """``(plant, gains)`` of the rider in the loop at the spec's speed (:func:`~bikemass.design.metrics.rider_in_loop`)."""
        spec = self.problem.spec
        return rider_in_loop(self.built.model, spec.speed, spec.tuning)

    @cached_property
    def handling(self):
        """``{"hqm-peak": .., "closed-loop-real": ..}`` at the spec's speed
        (:func:`~bikemass.design.metrics.handling_of`)."""
        return dict(zip(("hqm-peak", "closed-loop-real"), handling_of(*self.rider)))

    @cached_property
    def hqm_curve(self):
        """The HQM on :data:`~bikemass.design.metrics.CURVE_FREQUENCIES` at the spec's speed."""
        return hqm_curve_of(*self.rider)


class Problem:
    """The variables of a spec (:class:`~bikemass.design.spec.OptimiseSpec`) and the metrics' values
    and gradients at any design; every design built once (:meth:`design`)."""

    def __init__(self, spec):
        self.spec = spec
        self.scenario = spec.scenario()
        self.variables = spec.variables
        self.max_speed = spec.max_speed
        self._designs = {}
        self._jacobians = {}
        self.builds = 0
        self.undefined = set()
        self.defined = set()

    # -- designs ---------------------------------------------------------------------------
    def changes(self, x):
        """The scenario changes of design ``x`` (SI values, in the variables' order)."""
        return {v.key: v.change(float(value)) for v, value in zip(self.variables, x)}

    def design(self, x):
        """The :class:`Design` at ``x`` (cached by value)."""
        key = tuple(float(value) for value in x)
        found = self._designs.get(key)
        if found is None:
            found = self._designs[key] = Design(self, np.array(key))
            self.builds += 1
        return found

    def warn(self, x):
        """Warn again what building design ``x`` warned (the search keeps every design's warnings to
        itself: hundreds of designs would repeat them)."""
        for w in self.design(x).warnings:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)

    # -- values ----------------------------------------------------------------------------
    def value(self, metric, x):
        """The value of ``metric`` (:class:`~bikemass.design.metrics.Metric`) at design ``x`` in its SI
        unit; a speed that does not exist on the span gets its limit (:data:`~bikemass.design.metrics.UNDEFINED`)."""
        design = self.design(x)
        if metric.kind == PARAMETERS:
            return float(parameter_function(metric.name)(design.built.parameters))
        if metric.kind == GEOMETRY:
            return self._toe_overlap(design.changes)
        if metric.kind == HANDLING:
            return design.handling[metric.name]
        value, _ = speed_crossings(metric.name, design.critical)
        if value is None:
            self.undefined.add(metric.name)
            return UNDEFINED.get(metric.name, self.max_speed)
        self.defined.add(metric.name)
        return float(value)

    def exists(self, metric, x):
        """Whether ``metric`` has a value at design ``x`` (a critical speed or range on the span; every other
        metric always has one), not the stand-in :meth:`value` gives where it does not."""
        if metric.kind in (PARAMETERS, GEOMETRY, HANDLING):
            return True
        return speed_crossings(metric.name, self.design(x).critical)[0] is not None

    def gradient(self, metric, x):
        """``d metric / d x`` (SI per SI unit of each variable) at design ``x``."""
        design = self.design(x)
        if metric.kind == PARAMETERS:
            dp = parameter_gradient(metric.name, design.built.parameters)
            jac = self.parameter_jacobian(x)["parameters"]
            return sum(dp[n] * jac[n] for n in jac)
        if metric.kind == GEOMETRY:
            return self._difference(lambda xx: self._toe_overlap(self.changes(xx)), x)
        if metric.kind == HANDLING:
            return self._difference(lambda xx: self.design(xx).handling[metric.name], x)
        _, parts = speed_crossings(metric.name, design.critical)
        total = np.zeros(len(x))
        for sign, crossing in parts:
            total += sign * self._crossing_gradient(design, crossing)
        return total

    def _crossing_gradient(self, design, crossing):
        """``d speed / d x`` of one crossing of the design's model (the implicit function theorem on
        the crossing root, :func:`bikemass.analysis.sensitivity.speed_derivatives`)."""
        built, speed = design.built, crossing.speed
        jac = self.parameter_jacobian(design.x)
        if built.choice.members:
            varied = jac["values"]
            dA = member_state_derivatives(built, speed, tuple(varied))
        else:
            varied = {**jac["parameters"], **jac["stiffness"]}
            dA = state_matrix_derivatives(built.parameters, speed, built.stiffness, tuple(jac["parameters"]))
            if jac["stiffness"]:
                dA.update(stiffness_state_derivatives(built.parameters, speed, built.stiffness))
        dv = speed_derivatives(built.model, dA, speed, crossing.kind, crossing.frequency)
        return sum(dv[name] * column for name, column in varied.items())

    # -- derivatives of the parameters -------------------------------------------------------
    def parameter_jacobian(self, x):
        """``{"parameters": {name: column}, "values": {name: column}, "stiffness": {entry: column}}``:
        the derivatives (columns of length n) of the benchmark set, of the member model's parameters and
        of the frame stiffness S with respect to ``x``; only entries that change are listed.  Exact for a
        benchmark parameter varied by name (a unit column), a central difference of relative step
        :data:`~bikemass.analysis.sensitivity.GEOMETRY_STEP` for every other variable."""
        key = tuple(float(value) for value in x)
        if key in self._jacobians:
            return self._jacobians[key]
        design = self.design(x)
        n = len(x)
        params = {name: np.zeros(n) for name in NAMES}
        values = {name: np.zeros(n) for name in design.built.values()}
        stiffness = {entry: np.zeros(n) for entry in STIFFNESS_CELLS}
        members = bool(design.built.choice.members)
        for k, variable in enumerate(self.variables):
            if variable.key in NAMES and not members:
                params[variable.key][k] = 1.0
                continue
            h = _step_size(x[k])
            plus, minus, width = difference_sides(
                lambda value, k=k: self.design(np.where(np.arange(n) == k, value, x)).built, x[k], h)
            for name in NAMES:
                params[name][k] = (getattr(plus.parameters, name) - getattr(minus.parameters, name)) / width
            vp, vm = plus.values(), minus.values()
            for name in values:
                values[name][k] = (vp[name] - vm[name]) / width
            if plus.stiffness is not None:
                for entry, ((i, j),) in STIFFNESS_CELLS.items():
                    stiffness[entry][k] = (plus.stiffness[i, j] - minus.stiffness[i, j]) / width
        nonzero = lambda columns: {k: c for k, c in columns.items() if np.any(c != 0)}   # noqa: E731
        found = self._jacobians[key] = {"parameters": nonzero(params), "values": nonzero(values),
                                        "stiffness": nonzero(stiffness)}
        return found

    def hqm_curve(self, x):
        """The HQM curve of design ``x`` (:attr:`Design.hqm_curve`)."""
        return self.design(x).hqm_curve

    def hqm_curve_jacobian(self, x):
        """``d HQM(w_j) / d x_k`` (240, n): central differences (relative step :data:`GEOMETRY_STEP`)."""
        return self._difference(self.hqm_curve, x)

    def _difference(self, f, x):
        """Central differences of ``f`` (a number or an array of shape s) in each variable (relative step
        :data:`GEOMETRY_STEP`): shape (n,) or (*s, n)."""
        columns = []
        for k in range(len(x)):
            h = _step_size(x[k])
            step = np.where(np.arange(len(x)) == k, h, 0.0)
            columns.append((np.asarray(f(x + step)) - np.asarray(f(x - step))) / (2 * h))
        return np.stack(columns, axis=-1)

    # -- geometry ----------------------------------------------------------------------------
    @cached_property
    def _inseam(self):
        """The rider's inseam (m): a person's or a chain pose's body."""
        source, doc = self.scenario.inputs._read_rider()
        if not isinstance(doc, dict) or "body" not in doc:
            raise InputError(self.spec.source, "rider", "a person or chain pose (a body with an inseam) for "
                             "the metric toe-overlap")
        chain = load_body(Node(doc["body"], source, "body")).chain
        if chain is None:
            raise InputError(self.spec.source, "rider", "a body with joints (an inseam) for toe-overlap")
        return chain.inseam

    def _toe_overlap(self, changes):
        bike_changes = split_changes(changes)[0]
        return toe_overlap_of(self.scenario.inputs.bicycle(bike_changes), self._inseam)
