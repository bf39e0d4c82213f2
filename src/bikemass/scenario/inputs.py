"""A bicycle, rider and stiffness read once, rebuilt with changed inputs.

Inputs are named by keys:

* one of the 26 benchmark names (``c``, ``lam``, ...): replaces that value in the final set;
* ``stiffness``: a stiffness choice (``infinite``, ``steel``, ... or a file), as ``--stiffness``;
* ``rider.<path>``: a dotted path into the pose YAML (``rider.chain.torso_lean``,
  ``rider.segments.torso.angle``);
* any other dotted path: into the bicycle YAML (``sections.seat_stay.wall``,
  ``geometry.trail``, ``chart.head_tube_angle``).  In a list, a step is an element's
  ``name`` or its index (``tubes.down_tube.section``, ``components.0.mass``).

The YAML files are parsed once; a bicycle (its meshes' mass properties, and its stiffness)
and a rider are built once per distinct set of their own changes and reused by every
configuration that shares them.
"""

import copy
import pickle
from collections import OrderedDict
from collections.abc import Mapping

from ..bicycle.benchmark import merge_rider, parameters_from_bodies, refuse_second_rider, rider_bodies
from ..bicycle.loader import _is_parameter_text, _with_base, bicycle_from_mapping, bicycle_from_parameters
from ..bicycle.chart import ANGLE_KEYS, CHECKED_KEYS, FRAME_KEYS, STAND_INS
from ..bicycle.model import BODIES, Bicycle
from ..bicycle.parameter_text import load_parameter_text
from ..bicycle.sizes import split_size
from ..core.config import Node, load_yaml
from ..core.errors import InputError
from ..core.gate import MAPPING, plain_input
from ..core.paths import frames_dir, resolve
from ..core.units import DIMENSIONS, dimension_of
from ..mass.inertia import combine
from ..mass.materials import load_materials
from ..models.parameters import NAMES, BenchmarkParameters
from ..models.plausibility import check_parameters
from ..rider import Rider, _read_document, poses_dir
from . import catalog
from .catalog import seated_rider

RIDER_PREFIX = "rider."
STIFFNESS_KEY = "stiffness"
CACHE_SIZE = 32
PART_CACHE_SIZE = 4096


def _lru(cache, key, build):
    if key in cache:
        cache.move_to_end(key)
        return cache[key]
    value = build()
    cache[key] = value
    if len(cache) > CACHE_SIZE:
        cache.popitem(last=False)
    return value


def _slot(node, step):
    """The key or index of ``step`` in a mapping or list ``node``, or ``None``."""
    if isinstance(node, dict):
        return step if step in node else None
    if isinstance(node, list):
        named = [k for k, e in enumerate(node) if isinstance(e, dict) and e.get("name") == step]
        if named:
            return named[0]
        return int(step) if step.isdigit() and int(step) < len(node) else None
    return None


def _walk(document, path, source, origin, parent=False):
    """The value at dotted ``path`` (or, with ``parent``, its container and slot)."""
    steps = path.split(".")
    node = document
    for i, step in enumerate(steps):
        slot = _slot(node, step)
        if slot is None:
            where = ".".join(steps[:i]) or "(top)"
            has = f" (has: {', '.join(map(str, node))})" if isinstance(node, dict) else ""
            raise InputError(origin, path, f"a key path into {source}: no {step!r} under {where}{has}")
        if parent and i == len(steps) - 1:
            return node, slot
        node = node[slot]
    return node


def set_path(document, path, value, source, origin="spec", size_index=None):
    """Set dotted ``path`` in the nested mapping ``document`` (in place) to ``value``; in a size
    run (a list with one value per size) only the element ``size_index``.

    A ``"<number> <unit>"`` string is written as it is.  A number is in SI (m, kg, rad, ...):
    where the file writes a unit there (``"0.040 in"``, or a chart's ``units:`` block) it is
    written with the SI unit of that quantity (``"0.0011 m"``); a bare number stays bare (the
    file's bare numbers are SI already)."""
    container, slot = _walk(document, path, source, origin, parent=True)
    if size_index is not None and isinstance(container[slot], list):
        container, slot = container[slot], size_index
    unit = _file_unit(document, path, container[slot])
    if unit and not isinstance(value, str):
        value = f"{float(value)!r} {DIMENSIONS[dimension_of(unit)][0]}"
    container[slot] = value


def _unit(value):
    """The unit of a ``"<number> <unit>"`` YAML value, else None."""
    parts = value.split() if isinstance(value, str) else ()
    return parts[1] if len(parts) == 2 and dimension_of(parts[1]) is not None else None


CHART_KEY = "chart"


def _file_unit(document, path, value):
    """The unit the file writes ``value`` (at dotted ``path``) in: its own (``"585 mm"``), for a
    bare chart value the chart's ``units:`` block (angles for the head and seat tube angles,
    else lengths), else None (a bare number in SI)."""
    own = _unit(value)
    if own is not None or isinstance(value, str):
        return own
    steps = path.split(".")
    chart = document.get(CHART_KEY) if isinstance(document, dict) else None
    if len(steps) == 2 and steps[0] == CHART_KEY and isinstance(chart, dict) and isinstance(chart.get("units"), dict):
        dimension = "angle" if steps[1] in ANGLE_KEYS else "length"
        unit = chart["units"].get(dimension)
        return unit if isinstance(unit, str) and dimension_of(unit) == dimension else None
    return None


def file_unit(model, key):
    """The unit bikemass reads input ``key`` of ``model`` in when it is given as a bare number in a
    sweep (the unit the file writes there), or None for SI.  Parameters and stiffness are SI."""
    if key in NAMES or key == STIFFNESS_KEY:
        return None
    document, path, value = _located(model, key)
    return _file_unit(document, path, value)


def _located(model, key):
    """``(document, path, value)`` of dotted input ``key`` of ``model`` (one size of a size run)."""
    if key.startswith(RIDER_PREFIX):
        if model._rider_doc is None:
            raise InputError(model.origin, key, "a rider to change (no rider given)")
        path = key[len(RIDER_PREFIX):]
        return model._rider_doc, path, _walk(model._rider_doc, path, model._rider_source, model.origin)
    value = _walk(model._bike_doc, key, model._bike_source, model.origin)
    if model._size_index is not None and isinstance(value, list):
        value = value[model._size_index]
    return model._bike_doc, key, value


def get_path(model, key):
    """Current value of input ``key`` of ``model`` in SI (m, kg, rad, ...; ``"0.040 in"`` ->
    0.001016, a chart's ``590`` under ``units: {length: mm}`` -> 0.59); a bare number as written."""
    if key in NAMES:
        return float(getattr(model.parameters(), key))
    document, path, value = _located(model, key)
    unit = _file_unit(document, path, value)
    try:
        number = float(value.split()[0] if _unit(value) else value)
    except (TypeError, ValueError, AttributeError):
        raise InputError(model.origin, key, f"a number at that path, got {value!r}") from None
    return number * DIMENSIONS[dimension_of(unit)][1][unit] if unit else number


def split_changes(changes):
    """``changes`` -> (bicycle paths, rider paths, parameter values, stiffness or None), each sorted."""
    bike, rider, params, stiffness = [], [], [], None
    for key, value in changes.items():
        if key in NAMES:
            params.append((key, value))
        elif key == STIFFNESS_KEY:
            stiffness = value
        elif key.startswith(RIDER_PREFIX):
            rider.append((key[len(RIDER_PREFIX):], value))
        else:
            bike.append((key, value))
    return tuple(sorted(bike)), tuple(sorted(rider)), tuple(sorted(params)), stiffness


class Model:
    """``Model(bike, rider, stiffness, combine).build(changes)`` -> :class:`Built`."""

    def __init__(self, bike, rider=None, stiffness="infinite", combine="exact", method="mesh", origin="spec"):
        self.bike, self.rider, self.stiffness, self.combine, self.method = bike, rider, stiffness, combine, method
        self.origin = origin
        self.file_std = {}
        """``{name: std}`` of a BicycleParameters text file's ``+/-`` values (SI; those above 0)."""
        self._measured = self._fixed = None
        self._size = self._size_index = None
        if isinstance(bike, Bicycle):                 # built already: only its parameters can change
            self._fixed, self._bike_source, self._bike_doc = bike, bike.source, {}
        elif isinstance(bike, BenchmarkParameters):
            self._fixed = bicycle_from_parameters(bike, "parameters", "<parameters>")
            self._bike_source, self._bike_doc = "<parameters>", {}
        elif isinstance(bike, Mapping):
            self._bike_source, self._bike_doc = MAPPING, plain_input(bike, MAPPING)
        else:
            self._read_bicycle_file(bike)
        self._rider_doc = self._rider_source = self._fixed_rider = None
        if isinstance(rider, Rider):
            if rider.spec is None:
                self._fixed_rider = rider
            else:
                node, _ = rider.spec
                self._rider_source, self._rider_doc = str(node.source), copy.deepcopy(node.value)
        elif isinstance(rider, Mapping):
            self._rider_source, self._rider_doc = MAPPING, plain_input(rider, MAPPING)
        elif rider not in (None, "none"):
            rpath = resolve(rider, poses_dir(), "pose")
            self._rider_source, self._rider_doc = str(rpath), load_yaml(rpath).value
        self._own_bicycle_pose()
        self._bicycles, self._bodies, self._riders, self._seated, self._stiffness, self._params, self._parts = (
            OrderedDict() for _ in range(7))
        self._materials = None

    def _read_bicycle_file(self, bike):
        name, self._size = split_size(bike)
        path = resolve(name, frames_dir(), "bicycle")
        self._bike_source = str(path)
        if _is_parameter_text(path):
            measured = load_parameter_text(path)
            self._measured = measured.parameters
            self._bike_doc = {"name": path.stem, **measured.parameters.to_dict()}
            self.file_std = {k: float(v) for k, v in measured.std.items() if v > 0}
            return
        self._bike_doc = _with_base(load_yaml(path)).mapping()
        sizes = [str(x) for x in self._bike_doc.get("sizes", [])] if self._size is not None else []
        self._size_index = sizes.index(str(self._size)) if str(self._size) in sizes else None

    def _own_bicycle_pose(self):
        """A chain pose whose ``bike:`` names this scenario's own bicycle is solved on the bicycle
        as changed (a person re-seated by the same posture rule), so its ``bike:`` is dropped."""
        doc = self._rider_doc
        if not (isinstance(doc, dict) and "chain" in doc and isinstance(doc.get("bike"), str)):
            return
        own, _ = split_size(doc["bike"])
        try:
            same = str(resolve(own, frames_dir(), "bicycle")) == self._bike_source
        except InputError:
            return                                 # the pose's own error, reported where it is read
        if same and split_size(doc["bike"])[1] in (None, self._size):
            self._rider_doc = {k: v for k, v in doc.items() if k != "bike"}

    # -- pieces, each cached by its own changes -------------------------------------------
    def _document(self, doc, changes, source, size_index=None):
        out = copy.deepcopy(doc)
        for path, value in changes:
            set_path(out, path, value, source, self.origin, size_index)
        return out

    def bicycle(self, changes=()):
        """The bicycle with dotted-path ``changes`` (``((path, value), ...)``, sorted)."""
        def build():
            if self._measured is not None or self._fixed is not None:
                if changes:
                    what = "is a parameter file" if self._measured is not None else "was given built, not as YAML"
                    raise InputError(self.origin, changes[0][0], f"one of the 26 parameter names (the bicycle {what})")
                if self._fixed is not None:
                    return self._fixed
                return bicycle_from_parameters(self._measured, self._bike_doc["name"], self._bike_source)
            chart_changes = [path for path, _ in changes if path.split(".")[0] == CHART_KEY]
            for path in chart_changes:
                if path.split(".")[-1] in CHECKED_KEYS:
                    raise InputError(self.origin, path, f"a frame value of the chart ({', '.join(FRAME_KEYS)}); "
                                     f"{path.split('.')[-1]} is derived from the frame (the published value "
                                     "only checks the chart as published)")
            base = self._changeable_chart() if chart_changes else self._bike_doc
            doc = self._document(base, changes, self._bike_source, self._size_index)
            return bicycle_from_mapping(doc, self._bike_source, self._size)
        return _lru(self._bicycles, changes, build)

    def _changeable_chart(self):
        """The bicycle document with its chart ready to change: the published redundant values
        (wheelbase, front centre, trail, ...: :data:`~bikemass.bicycle.chart.CHECKED_KEYS`) check
        the chart as published, so they are dropped, and a frame value the chart gives through a
        stand-in (``trail`` for ``fork_offset``, ``bb_height`` for ``bb_drop``) is written as the
        value the published chart builds, so that the changed frame keeps its fork and bottom
        bracket rather than its trail."""
        if "_chart_base" not in self.__dict__:
            doc = copy.deepcopy(self._bike_doc)
            chart = doc.get(CHART_KEY)
            if isinstance(chart, dict):
                built = self.bicycle(()).chart
                for key, stand_in in STAND_INS.items():
                    if chart.get(key) is None and built is not None:
                        chart[key] = f"{float(getattr(built, key))!r} m"
                for key in CHECKED_KEYS:
                    chart.pop(key, None)
                chart.pop("tolerances", None)
            self._chart_base = doc
        return self._chart_base

    def posed_rider(self, changes=()):
        """The rider (pose file with ``changes``) as written, or ``None``; a chain pose without
        ``bike:`` is seated on each changed bicycle (:meth:`rider_bodies`)."""
        if self._fixed_rider is not None and not changes:
            return self._fixed_rider
        if self._rider_doc is None:
            if changes:
                raise InputError(self.origin, changes[0][0], "a rider to change (no rider given)")
            return None

        def build():
            doc = self._document(self._rider_doc, changes, self._rider_source)
            return _read_document(Node(doc, self._rider_source, ""), self._rider_source, False)
        return _lru(self._riders, changes, build)

    def rider_bodies(self, bike_changes=(), rider_changes=()):
        """``{body: MassProperties}`` of the rider seated on the changed bicycle (as
        :func:`bikemass.scenario.catalog.seated_rider` does), or ``None``."""
        rider = self.posed_rider(rider_changes)
        if rider is None:
            return None

        def build():
            return rider_bodies(seated_rider(self.bicycle(bike_changes), rider), self.method)
        return _lru(self._seated, (bike_changes, rider_changes), build)

    def parameters(self, bike_changes=(), rider_changes=()):
        """Benchmark parameters of the bicycle and rider with their changes (before parameter changes)."""
        def build():
            bicycle = self.bicycle(bike_changes)
            refuse_second_rider(bicycle, self.posed_rider(rider_changes))
            riders = self.rider_bodies(bike_changes, rider_changes)
            if riders is None and bicycle.published is not None:
                return bicycle.published
            bodies = _lru(self._bodies, bike_changes, lambda: self._bicycle_bodies(bicycle))
            return parameters_from_bodies(bicycle, merge_rider(bodies, riders or {}, self.combine))
        return _lru(self._params, (bike_changes, rider_changes), build)

    def _bicycle_bodies(self, bicycle):
        """``bicycle.bodies(method)`` with each part's mass properties (its mesh) computed once per
        distinct part: a changed tube wall re-meshes only the tubes of that section."""
        def props(part):
            key = pickle.dumps((part.name, part.solid, part.mass, part.placement, part.body))
            cached = self._parts.get(key)
            if cached is None:
                cached = self._parts[key] = part.mass_properties(self.method)
                if len(self._parts) > PART_CACHE_SIZE:
                    self._parts.popitem(last=False)
            return cached
        return {b: combine(props(p) for p in bicycle.body_parts(b)) for b in BODIES}

    def materials(self):
        if self._materials is None:
            self._materials = load_materials()
        return self._materials

    def frame_stiffness(self, which, bike_changes=()):
        """2x2 S (N m/rad) or None, for stiffness choice ``which`` on the changed bicycle (as
        :func:`bikemass.scenario.catalog.stiffness`; a changed bicycle's S is computed, never
        published).  ``which`` may be a name, a file, a Material or a 2x2 matrix (N m/rad)."""
        try:
            hash(which)
            key = which
        except TypeError:                          # a matrix (a list or an array): cached by its values
            which = catalog.stiffness_matrix(which)
            key = tuple(map(tuple, which.tolist()))

        def build():
            if not isinstance(which, str) or which in ("infinite", "rigid") or which not in self.materials():
                return catalog.stiffness(self.bike, which)
            return catalog.stiffness(self.bicycle(bike_changes), which, "computed" if bike_changes else "auto")
        return _lru(self._stiffness, (key, bike_changes), build)

    def build(self, changes=None):
        """:class:`Built` for ``{key: value}`` changes (see the module docstring)."""
        bike, rider, params, stiffness = split_changes(changes or {})
        p = self.parameters(bike, rider)
        if params:
            p = check_parameters(p.replace(**dict(params)), self.origin)
        return p, self.frame_stiffness(self.stiffness if stiffness is None else stiffness, bike)
