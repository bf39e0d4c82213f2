"""The optimisation specification (YAML), beside the sweep's.

```yaml
bike: bmc-roadmachine@54        # as in a sweep spec: a name, a file, chart@size
rider: person.yaml              # optional; a person is re-seated on every design
stiffness: infinite             # optional, as --stiffness
model: whipple                  # optional, any --model
max_speed: 30                   # optional: speeds on (0, max_speed] m/s
speed: 5.0                      # m/s, for metrics taken at one speed (hqm-peak)
tuning: hmh2012                 # for hqm-peak: hmh2012 (the 10 dB rule, default) or bmd2016
variables:                      # any input a sweep can vary, with bounds (units allowed)
  chart.head_tube_angle: {min: 70 deg, max: 75 deg}
  chart.fork_offset: {min: 35 mm, max: 60 mm}
maximise: stable-range          # or  minimise: METRIC  or  target: {METRIC: VALUE}
constraints:                    # optional: METRIC: {min: ..., max: ...}
  trail: {min: 50 mm, max: 70 mm}
starts: 2                       # optional: local searches from the best points of a screening of the box
seed: 0                         # optional: the screening's (scrambled Sobol) seed
```

A bound or target with a unit is converted to SI; a bare number is SI for a benchmark parameter
(its ``lam`` in radians) and for a metric, and in the unit the file writes there for a dotted path
(the sweep's rule).  Paths (``bike``, ``rider``, ``stiffness``, a member's file such as ``tyres``) are relative
to the spec.
"""

from dataclasses import dataclass

from ..core.config import load_yaml
from ..core.errors import InputError
from ..core.limits import MAX_SPEED
from ..core.paths import near_spec, near_spec_file
from ..core.units import DIMENSIONS, Quantity, UnitError, dimension_of, split_quantity
from ..models.parameters import NAMES, dimension
from ..models.registry import BASE, KEYWORDS, spec_members, spec_model
from ..scenario.scenario import Scenario, own_model, refuse_riderless
from ..core.choices import Tuning
from .metrics import HANDLING, STABILITY_MARGIN, catalogue

TOP_KEYS = ("bike", "rider", "stiffness", "combine", "model", *KEYWORDS, "max_speed", "speed", "tuning", "variables",
            "maximise",
            "minimise", "target", "constraints", "starts", "seed", "name", "description")
SENSES = ("maximise", "minimise", "target")
MAX_VARIABLES = 20
"""Most design variables: each costs two builds a gradient."""
MAX_STARTS = 50


@dataclass(frozen=True)
class DesignVariable:
    """One design variable: ``key`` (as a sweep's), bounds ``low < high`` in SI, and the SI ``unit``
    its value carries when it reaches a document (a :class:`~bikemass.core.units.Quantity`; ``None``:
    a bare SI number)."""

    key: str
    low: float
    high: float
    unit: str = None

    def change(self, value):
        """The scenario change that sets this variable to ``value`` (SI)."""
        return value if self.unit is None else Quantity(value, self.unit)


@dataclass(frozen=True)
class Bounds:
    """``low <= metric <= high`` (SI; ``None``: open)."""

    metric: str
    low: float = None
    high: float = None


@dataclass(frozen=True)
class OptimiseSpec:
    """A read optimisation spec (see the module docstring); values in SI."""

    source: str
    bike: str
    variables: tuple
    sense: str
    objective: str
    target: float = None
    constraints: tuple = ()
    rider: str = "none"
    stiffness: "str | None" = None         # None: the bicycle's own (a parameter file's block, else rigid)
    combine: str = "exact"
    model: str = BASE
    members: tuple = ()
    """``((keyword, path), ...)``: the members' files (``tyres``, as ``--tyres``)."""
    max_speed: float = 30.0
    starts: int = 2
    seed: int = 0
    speed: float = None
    tuning: str = Tuning.HMH2012.value

    def scenario(self):
        """The :class:`~bikemass.scenario.scenario.Scenario` every design changes."""
        return Scenario(self.bike, self.rider, self.stiffness, self.combine, model=self.model,
                        member_inputs=dict(self.members), origin=self.source)

    @property
    def all_constraints(self):
        """The constraints, and where ``hqm-peak`` is optimised without a bound on ``closed-loop-real``,
        the closed loop held stable (:data:`~bikemass.design.metrics.STABILITY_MARGIN`)."""
        named = {c.metric for c in self.constraints}
        if "hqm-peak" in (self.objective, *named) and "closed-loop-real" not in named:
            return (*self.constraints, Bounds("closed-loop-real", None, -STABILITY_MARGIN))
        return self.constraints

    @property
    def metrics(self):
        """The objective's metric and every constraint's, each once, in that order."""
        return tuple(dict.fromkeys((self.objective, *(c.metric for c in self.all_constraints))))


def _variable(scenario, key, node):
    """:class:`DesignVariable` of ``key: {min, max}``."""
    node.check_keys(required=("min", "max"))
    if key in NAMES:
        bare, dim = ("rad" if key == "lam" else None), dimension(key)
    else:
        try:
            unit = scenario.file_unit(key)
        except InputError as exc:
            node.fail(f"an input of the bicycle or rider ({exc.expected})")
        dim = scenario.input_dimension(key)        # a file's unit there, or a member input's (its code's unit)
        bare = unit or (DIMENSIONS[dim][0] if dim else None)
    low, high = (_bound_value(node[b], dim, bare) for b in ("min", "max"))
    if not low < high:
        node.fail(f"min < max, got {low!r} and {high!r} (SI)")
    unit = None if key in NAMES or dim is None else DIMENSIONS[dim][0]
    return DesignVariable(key, low, high, unit)


def _bound_value(node, dim, bare_unit):
    """A bound in SI: its unit's dimension where it has one (``dim`` when known), else bare in ``bare_unit``."""
    try:
        number, unit = split_quantity(node.value)
    except UnitError as exc:
        node.fail(str(exc))
    if dim is None:
        if unit:
            dim = dimension_of(unit)
        else:
            return node.number("dimensionless")
    return node.number(dim, bare_unit=bare_unit)


def _metric_value(node, name):
    """A metric's bound or target in SI (bare: SI; a unit must be of the metric's dimension)."""
    unit = catalogue()[name].unit
    si_dimension = next((d for d, (si, _) in DIMENSIONS.items() if si == unit), None)
    if unit in ("1", "") or si_dimension is None:
        return node.number("dimensionless")
    return node.number(si_dimension, bare_unit="rad" if si_dimension == "angle" else None)


def _metric_name(node, name, key=None):
    """``name`` if it is a metric; else InputError at ``node`` (its ``key``) listing the metrics."""
    if name not in catalogue():
        node.fail(f"a metric ({', '.join(catalogue())}), got {name!r}", key)
    return name


def read_spec(path):
    """:class:`OptimiseSpec` of a YAML file; InputError naming the file, the key and what was expected."""
    node = load_yaml(path)
    node.check_keys(required=("bike", "variables"), optional=TOP_KEYS)
    given = [s for s in SENSES if node.has(s)]
    if len(given) != 1:
        node.fail("one objective: maximise: METRIC, minimise: METRIC or target: {METRIC: VALUE}",
                  given[1] if len(given) > 1 else "maximise")
    sense = given[0]
    target = None
    if sense == "target":
        t = node["target"]
        pairs = t.items() if isinstance(t.value, dict) else []
        if len(pairs) != 1:
            t.fail("one metric and its value, e.g. {weave-speed: 5.0}")
        objective = _metric_name(t, str(pairs[0][0]), str(pairs[0][0]))
        target = _metric_value(pairs[0][1], objective)
    else:
        objective = _metric_name(node, node[sense].string(), sense)
    # no model: the bicycle's own (rider-lean for a MooreRiderLean2012 set)
    bike = near_spec(path, node["bike"].string())
    model = spec_model(node) if node.has("model") else own_model(bike).name
    refuse_riderless(node, model, bike)
    max_speed = node["max_speed"].number("speed", positive=True) if node.has("max_speed") else 30.0
    if max_speed > MAX_SPEED:
        node.fail(f"a speed of at most {MAX_SPEED:g} m/s, got {max_speed:g}", "max_speed")
    speed = node["speed"].number("speed", nonnegative=True) if node.has("speed") else None
    if speed is not None and speed > MAX_SPEED:
        node.fail(f"a speed of at most {MAX_SPEED:g} m/s", "speed")
    tuning = node["tuning"].string(Tuning.values()) if node.has("tuning") else Tuning.HMH2012.value
    spec = OptimiseSpec(
        source=str(path), speed=speed, tuning=tuning, bike=bike,
        rider=near_spec(path, node["rider"].string()) if node.has("rider") else "none",
        stiffness=near_spec_file(path, node["stiffness"].string()) if node.has("stiffness") else None,
        combine=node["combine"].string(("exact", "thesis")) if node.has("combine") else "exact",
        model=model, members=spec_members(node, lambda text: near_spec(path, text), model),
        max_speed=float(max_speed), variables=(), sense=sense, objective=objective, target=target)
    scenario = spec.scenario()
    variables = node["variables"]
    if not variables.mapping():
        variables.fail("at least one input with {min, max}")
    if len(variables.mapping()) > MAX_VARIABLES:
        variables.fail(f"at most {MAX_VARIABLES} variables")
    design = tuple(_variable(scenario, str(k), item) for k, item in variables.items())
    constraints = ()
    if node.has("constraints"):
        c = node["constraints"]
        items = []
        for name, item in c.items():
            name = _metric_name(c, str(name), str(name))
            item.check_keys(optional=("min", "max"))
            low = _metric_value(item["min"], name) if item.has("min") else None
            high = _metric_value(item["max"], name) if item.has("max") else None
            if low is None and high is None:
                item.fail("min, max or both")
            if low is not None and high is not None and not low <= high:
                item.fail("min <= max")
            items.append(Bounds(name, low, high))
        constraints = tuple(items)
    if speed is None and any(catalogue()[m].kind == HANDLING for m in (objective, *(c.metric for c in constraints))):
        node.fail("the speed (m/s) at which hqm-peak and closed-loop-real are taken", "speed")
    starts = _whole(node, "starts", 2, 1, MAX_STARTS)
    seed = _whole(node, "seed", 0, 0, 2 ** 32 - 1)
    return OptimiseSpec(**{**spec.__dict__, "variables": design, "constraints": constraints, "starts": starts,
                           "seed": seed})


def _whole(node, key, default, low, high):
    if not node.has(key):
        return default
    x = node[key].number("dimensionless")
    if x != int(x) or not low <= x <= high:
        node.fail(f"a whole number from {low} to {high}", key)
    return int(x)

