"""The sweep specification (YAML) and the configurations it describes.

```yaml
bike: benchmark            # as BIKE on the command line
rider: none                # optional, as --rider
stiffness: infinite        # optional, as --stiffness
combine: exact             # optional
model: whipple             # optional, as --model (rider-lean, tyre, flexible, members joined by +)
tyres: tyres.yaml          # optional, as --tyres (a model with the tyre member; each member's option)
max_speed: 30              # optional: critical speeds on (0, max_speed] m/s
vary:                      # key -> list of values, or {from, to, num}
  c: {from: 0.0, to: 0.2, num: 41}
  lam: [0.2, 0.3, 0.4]
sample: grid               # grid (default), or {method: lhs | sobol, n: 64, seed: 0}
global_sensitivity: false  # true: Saltelli sample (SALib) of n base points and Sobol indices
chunk: 500                 # optional: configurations per task (default: docs/analysis.md, Engines)
```

Keys are those of :mod:`bikemass.scenario.inputs` (the 26 parameters, ``stiffness``,
dotted paths into the bicycle or pose YAML).  Varied values follow the one units rule of every
YAML format: ``["0.5 mm", "1.0 mm"]``, ``{from: 15 deg, to: 45 deg, num: 4}``.  A parameter's
values are read in SI (its ``lam`` bare in radians, as its file format has it); a dotted path's
given with a unit keep it (``results.csv`` lists them in it) and reach the YAML with it, bare
ones take the unit the file writes there; the bicycle or pose loader checks them as it checks
the file (a bare angle where the file has no unit either is refused there).
"""

import hashlib
import itertools
import json
import math
import os
from dataclasses import dataclass

import numpy as np

from ..core.config import load_yaml
from ..core.limits import MAX_SPEED
from ..core.paths import near_spec, near_spec_file
from ..core.units import DIMENSIONS, UnitError, dimension_of, split_quantity
from ..models.parameters import NAMES, dimension
from ..models.registry import BASE, KEYWORDS, spec_members, spec_model
from ..scenario.scenario import Scenario, own_model, refuse_riderless

SAMPLE_METHODS = ("grid", "lhs", "sobol")
TOP_KEYS = ("bike", "rider", "stiffness", "combine", "model", *KEYWORDS, "max_speed", "vary", "sample",
            "global_sensitivity", "chunk", "name", "description")
MAX_CONFIGURATIONS = 10 ** 8
"""Most configurations in one grid, checked before any is made.  No process holds a row per
configuration (chunks are made from their index range and streamed to disk, docs/sweep.md), so
the bound is the disk's: about 100 bytes of ``results.csv`` and as much in chunk files a row
(10^8 rows: about 20 GB)."""
MAX_SAMPLES = 10 ** 6
"""Most configurations of a random or Saltelli sample: its points are drawn at once (n x keys
numbers in memory, 8 bytes each)."""


@dataclass(frozen=True)
class Variable:
    """One varied key: ``values`` (a list) or a range ``low..high`` with ``num`` points, numbers
    in ``unit`` (``None``: as given, bare; a benchmark parameter's are SI)."""

    key: str
    values: tuple = None
    low: float = None
    high: float = None
    num: int = None
    unit: str = None

    def size(self):
        """Number of grid values (without making them)."""
        return len(self.values) if self.values is not None else self.num

    def grid(self):
        return self.values if self.values is not None else tuple(np.linspace(self.low, self.high, self.num).tolist())

    def at(self, digits):
        """The grid values at the indices ``digits`` (an integer array), as plain Python values,
        without making the grid: a range's are ``np.linspace``'s own arithmetic (``low + i *
        step``, the last point exactly ``high``), so one key of 10^8 points costs a chunk its
        own rows only."""
        if self.values is not None:
            return _values(self.values, digits)
        step = (self.high - self.low) / (self.num - 1)
        x = np.asarray(digits, dtype=float) * step + self.low
        x[np.asarray(digits) == self.num - 1] = self.high
        return x.tolist()

    def from_unit(self, u):
        """Map ``u`` in [0, 1) to a value: uniform on the range, or an element of the list."""
        if self.values is not None:
            return self.values[min(int(u * len(self.values)), len(self.values) - 1)]
        return float(self.low + u * (self.high - self.low))


@dataclass(frozen=True)
class SweepSpec:
    source: str
    bike: str
    rider: str
    stiffness: "str | None"                # None: the bicycle's own (a parameter file's block, else rigid)
    combine: str
    max_speed: float
    variables: tuple
    method: str
    n: int
    seed: int
    global_sensitivity: bool
    chunk: int = None
    model: str = BASE
    members: tuple = ()
    """``((keyword, path), ...)``: the members' files (``tyres``, as ``--tyres``)."""
    inputs: str = None
    """A digest of the input files' contents (:func:`bikemass.sweep.run.run_sweep` sets it): a
    process that computes chunks reuses its scenario, and the files read into it, only for the
    same contents."""

    def scenario(self):
        """The :class:`~bikemass.scenario.scenario.Scenario` every configuration changes."""
        return Scenario(self.bike, self.rider, self.stiffness, self.combine, model=self.model,
                        member_inputs=dict(self.members), origin=self.source)

    @property
    def keys(self):
        return tuple(v.key for v in self.variables)

    @property
    def units(self):
        """``{key: unit}`` of the varied values given with a unit (they reach the model with it)."""
        return {v.key: v.unit for v in self.variables if v.unit}

    @property
    def count(self):
        """The number of configurations (:func:`count_of`)."""
        return count_of(self)

    def columns(self, start, stop):
        """Configurations ``start .. stop - 1`` as columns ``{key: list of values}`` (the rows of
        results.csv in that range), made from the index range alone: a grid's index is unravelled
        (the last key varying fastest, as :meth:`configurations` orders them); a sample's points
        are drawn once and cut."""
        if self.method == "grid" and not self.global_sensitivity:
            sizes = [v.size() for v in self.variables]
            digits = np.unravel_index(np.arange(start, stop), sizes)
            return {v.key: v.at(d) for v, d in zip(self.variables, digits)}
        rows = self._sample()[start:stop]
        return {k: [row[k] for row in rows] for k in self.keys}

    def _sample(self):
        cached = _SAMPLES.get(self)
        if cached is None:
            _SAMPLES.clear()
            cached = _SAMPLES[self] = self._configurations()
        return cached

    def configurations(self):
        """List of ``{key: value}`` in a fixed order (the rows of results.csv)."""
        if self.method == "grid" and not self.global_sensitivity:
            return self._configurations()
        return list(self._sample())

    def _configurations(self):
        if self.global_sensitivity:
            # lazy: SALib is optional (the sweep extra) and slow to import; only Sobol samples need it
            from SALib.sample import sobol
            x = sobol.sample(self.problem(), self.n, calc_second_order=False, seed=self.seed)
            return [dict(zip(self.keys, map(float, row))) for row in x]
        if self.method == "grid":
            return [dict(zip(self.keys, combo)) for combo in itertools.product(*(v.grid() for v in self.variables))]
        # lazy: scipy.stats is slow to import (more than numpy); only random samples need it
        from scipy.stats import qmc
        d = len(self.variables)
        engine = qmc.LatinHypercube(d=d, seed=self.seed) if self.method == "lhs" else qmc.Sobol(d=d, seed=self.seed)
        u = engine.random(self.n)
        return [{v.key: v.from_unit(x) for v, x in zip(self.variables, row)} for row in u]

    def problem(self):
        """SALib problem definition (ranges only)."""
        return {"num_vars": len(self.variables), "names": list(self.keys),
                "bounds": [[v.low, v.high] for v in self.variables]}

    def fingerprint(self):
        """Hash of everything that decides the results (a resumed sweep must match it; the chunk
        size does not decide them)."""
        doc = {k: getattr(self, k) for k in ("bike", "rider", "stiffness", "combine", "max_speed", "method", "n",
                                            "seed", "global_sensitivity")}
        doc["variables"] = [v.__dict__ for v in self.variables]
        if self.model != BASE or self.members:         # the model joins the hash (older Whipple sweeps resume)
            doc.update(model=self.model, **dict(self.members))
        return hashlib.sha256(json.dumps(doc, sort_keys=True, default=str).encode()).hexdigest()[:16]


_SAMPLES = {}
"""The drawn points of the last random or Saltelli sample (``columns`` of its chunks cut them)."""


def _values(grid, digits):
    """``grid[d]`` for each index of ``digits``, as plain Python values."""
    if all(isinstance(g, float) for g in grid):
        return np.asarray(grid, dtype=float)[digits].tolist()
    return [grid[d] for d in digits.tolist()]


def count_of(spec):
    """Number of configurations ``spec`` describes, counted without making them (exact integers:
    a grid of many keys can exceed any fixed-width integer): the grid's product of sizes, the
    sample's ``n``, or a Saltelli sample's ``n (D + 2)``."""
    if spec.global_sensitivity:
        return spec.n * (len(spec.variables) + 2)
    if spec.method == "grid":
        return math.prod(v.size() for v in spec.variables)
    return spec.n


STIFFNESS_CHOICES = "infinite, a material of frames/materials.yaml (steel, titanium, aluminum, carbon) or a file"


VARY_TAKES = ("one of the 26 benchmark parameter names (c, lam, ...), stiffness, or a dotted path into the "
              "bicycle or pose YAML (chart.stack, rider.chain.torso_lean, ...)")
"""What a key under ``vary:`` may be, for messages."""
SET_ONCE = ("bike", "rider", "combine", "model", *KEYWORDS, "max_speed")
"""Spec keys that hold one value for the whole sweep (one sweep per model, per bicycle, ...)."""


def _variable(key, node):
    if key in SET_ONCE:
        node.fail(f"a key that varies one input: {VARY_TAKES}; {key} is set once for the whole sweep, at the "
                  f"top of the spec ({key}: ...), so run one sweep per {key}")
    if isinstance(node.value, list):
        if not node.value:
            node.fail("a non-empty list of values, or {from, to, num}")
        if key == "stiffness":
            for v in node.elements():
                if not isinstance(v.value, str):
                    v.fail(f"a stiffness choice ({STIFFNESS_CHOICES}), got {v.value!r}")
            return Variable(key, values=tuple(v.string() for v in node.elements()))
        if key in NAMES:
            return Variable(key, values=tuple(_parameter(key, v) for v in node.elements()))
        numbers, unit = _in_one_unit(node.elements())
        return Variable(key, values=tuple(numbers), unit=unit)
    if key == "stiffness":
        node.fail(f"a list of stiffness choices ({STIFFNESS_CHOICES})")
    node.check_keys(required=("from", "to"), optional=("num",))
    if key in NAMES:
        (low, high), unit = (_parameter(key, node["from"]), _parameter(key, node["to"])), None
    else:
        (low, high), unit = _in_one_unit([node["from"], node["to"]])
    if not (np.isfinite(low) and np.isfinite(high) and low < high):
        node.fail("from < to, both finite")
    num = int(node["num"].number("dimensionless", positive=True)) if node.has("num") else None
    if num is not None and (num != node["num"].number("dimensionless") or num < 2):
        node.fail("a whole number of points, at least 2", "num")
    return Variable(key, low=low, high=high, num=num, unit=unit)


def _parameter(key, node):
    """A value of benchmark parameter ``key`` in SI (``lam`` bare in radians, as its file format)."""
    return node.number(dimension(key), bare_unit="rad" if key == "lam" else None)


def _in_one_unit(nodes):
    """``(numbers, unit)`` of values given as numbers or ``"<number> <unit>"``: all bare (unit
    ``None``), or all with units of one dimension, converted to the first one's unit."""
    read = []
    for node in nodes:
        try:
            read.append(split_quantity(node.value))
        except UnitError as exc:
            if isinstance(node.value, str) and not _starts_with_number(node.value):
                node.fail(f"a number, or '<number> <unit>' (every value of a varied key is a number; only "
                          f"stiffness takes names: {STIFFNESS_CHOICES}), got {node.value!r}")
            node.fail(str(exc))
    unit = read[0][1]
    if not unit:
        for node, (_, given) in zip(nodes, read):
            if given:
                node.fail(f"a bare number like the first value, or units on every value, got {node.value!r}")
        return [x for x, _ in read], None
    dimension = dimension_of(unit)
    table = DIMENSIONS[dimension][1]
    numbers = []
    for node, (x, given) in zip(nodes, read):
        if dimension_of(given) != dimension:
            node.fail(f"a value of the first value's dimension ({dimension}, e.g. '1 {unit}'), got {node.value!r}")
        numbers.append(x if given == unit else x * table[given] / table[unit])
    return numbers, unit


def _starts_with_number(text):
    """Whether ``text`` begins with a number (``"0.5 mm"``), as a value with a unit does."""
    try:
        float(text.split()[0])
    except (ValueError, IndexError):
        return False
    return True


def read_spec(path: "str | os.PathLike") -> "SweepSpec":
    """:class:`SweepSpec` of a YAML file; InputError naming the key on bad input."""
    node = load_yaml(path)
    node.check_keys(required=("bike", "vary"), optional=TOP_KEYS)
    vary = node["vary"]
    if not vary.mapping():
        vary.fail("at least one key to vary")
    variables = tuple(_variable(str(k), item) for k, item in vary.items())
    variables = tuple(Variable(v.key, values=tuple(near_spec_file(path, x) for x in v.values))
                      if v.key == "stiffness" else v for v in variables)
    method, n, seed = "grid", None, 0
    if node.has("sample") and node["sample"].value != "grid":
        s = node["sample"]
        s.check_keys(required=("method", "n"), optional=("seed",))
        method = s["method"].string(SAMPLE_METHODS[1:])
        n = s["n"].number("dimensionless", positive=True)
        if n != int(n) or n > MAX_SAMPLES:
            s.fail(f"a whole number of samples up to {MAX_SAMPLES}", "n")
        n = int(n)
        seed = s["seed"].number("dimensionless", nonnegative=True) if s.has("seed") else 0
        if seed != int(seed):
            s.fail("a whole number >= 0", "seed")
        seed = int(seed)
    gsa = node["global_sensitivity"].boolean() if node.has("global_sensitivity") else False
    for v in variables:
        if v.values is None and v.num is None and method == "grid" and not gsa:
            vary.fail("num (the number of grid points) for a grid", f"{v.key}.num")
        if gsa and v.values is not None:
            vary.fail("{from, to} ranges for a global sensitivity analysis", v.key)
    if gsa and n is None:
        node.fail("sample: {method: sobol, n: N} (N base points of the Saltelli sample)", "global_sensitivity")
    max_speed = node["max_speed"].number("speed", positive=True) if node.has("max_speed") else 30.0
    if max_speed > MAX_SPEED:
        node.fail(f"a speed of at most {MAX_SPEED:g} m/s, got {max_speed:g}", "max_speed")
    chunk = None
    if node.has("chunk"):
        chunk = node["chunk"].number("dimensionless", positive=True)
        if chunk != int(chunk):
            node.fail("a whole number of configurations per task", "chunk")
    bike = near_spec(path, node["bike"].string())
    model = spec_model(node) if node.has("model") else own_model(bike).name    # none: the bicycle's own
    refuse_riderless(node, model, bike)
    spec = SweepSpec(
        source=str(path), bike=bike,
        rider=near_spec(path, node["rider"].string()) if node.has("rider") else "none",
        stiffness=near_spec_file(path, node["stiffness"].string()) if node.has("stiffness") else None,
        combine=node["combine"].string(("exact", "thesis")) if node.has("combine") else "exact",
        max_speed=float(max_speed), variables=variables, method=method, n=n, seed=seed,
        global_sensitivity=gsa, chunk=None if chunk is None else int(chunk),
        model=model, members=spec_members(node, lambda text: near_spec(path, text), model))
    grid = method == "grid" and not gsa
    limit = MAX_CONFIGURATIONS if grid else MAX_SAMPLES
    if count_of(spec) > limit:
        vary.fail(f"at most {limit} configurations (this {'grid' if grid else 'sample'} has {count_of(spec)})")
    return spec
