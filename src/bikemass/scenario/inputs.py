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

from ..bicycle.benchmark import merge_rider, parameters_from_bodies, refuse_second_rider, rider_bodies
from ..bicycle.loader import _is_parameter_text, _with_base, bicycle_from_mapping, bicycle_from_parameters
from ..bicycle.model import BODIES
from ..bicycle.parameter_text import load_parameter_text
from ..bicycle.sizes import split_size
from ..core.config import Node, load_yaml
from ..core.errors import InputError
from ..core.paths import frames_dir, resolve
from ..mass.inertia import combine
from ..mass.materials import load_materials
from ..models.parameters import NAMES
from ..models.plausibility import check_parameters
from ..rider import _read_document, poses_dir
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
    run (a list with one value per size) only the element ``size_index``.  A bare number takes the
    unit the file writes there (``"0.040 in"``: inches); a ``"<number> <unit>"`` string keeps its own."""
    container, slot = _walk(document, path, source, origin, parent=True)
    if size_index is not None and isinstance(container[slot], list):
        container, slot = container[slot], size_index
    unit = _unit(container[slot])
    container[slot] = f"{value!r} {unit}" if unit and not isinstance(value, str) else value


def _unit(value):
    """The unit of a ``"<number> <unit>"`` YAML value, else None."""
    parts = value.split() if isinstance(value, str) else ()
    return parts[1] if len(parts) == 2 else None


def get_path(model, key):
    """Current value of input ``key`` of ``model``, in the unit the file writes it in (``"0.040 in"`` -> 0.04)."""
    if key in NAMES:
        return float(getattr(model.parameters(), key))
    if key.startswith(RIDER_PREFIX):
        if model._rider_doc is None:
            raise InputError(model.origin, key, "a rider to change (no rider given)")
        value = _walk(model._rider_doc, key[len(RIDER_PREFIX):], model._rider_source, model.origin)
    else:
        value = _walk(model._bike_doc, key, model._bike_source, model.origin)
        if model._size_index is not None and isinstance(value, list):
            value = value[model._size_index]
    try:
        return float(value.split()[0] if _unit(value) else value)
    except (TypeError, ValueError, AttributeError):
        raise InputError(model.origin, key, f"a number at that path, got {value!r}") from None


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
        name, self._size = split_size(bike)
        path = resolve(name, frames_dir(), "bicycle")
        self._bike_source = str(path)
        self.file_std = {}
        self._measured = None
        """``{name: std}`` of a BicycleParameters text file's ``+/-`` values (SI; those above 0)."""
        if _is_parameter_text(path):
            measured = load_parameter_text(path)
            self._measured = measured.parameters
            self._bike_doc = {"name": path.stem, **measured.parameters.to_dict()}
            self.file_std = {k: float(v) for k, v in measured.std.items() if v > 0}
        else:
            self._bike_doc = _with_base(load_yaml(path)).mapping()
        sizes = [str(x) for x in self._bike_doc.get("sizes", [])] if self._size is not None else []
        self._size_index = sizes.index(str(self._size)) if str(self._size) in sizes else None
        self._rider_doc = self._rider_source = None
        if rider not in (None, "none"):
            rpath = resolve(rider, poses_dir(), "pose")
            self._rider_source, self._rider_doc = str(rpath), load_yaml(rpath).value
        self._bicycles, self._bodies, self._riders, self._seated, self._stiffness, self._params, self._parts = (
            OrderedDict() for _ in range(7))
        self._materials = None

    # -- pieces, each cached by its own changes -------------------------------------------
    def _document(self, doc, changes, source, size_index=None):
        out = copy.deepcopy(doc)
        for path, value in changes:
            set_path(out, path, value, source, self.origin, size_index)
        return out

    def bicycle(self, changes=()):
        def build():
            if self._measured is not None:        # read as the file reader does (bikemass.bicycle.parameter_text)
                if changes:
                    raise InputError(self.origin, changes[0][0], "one of the 26 parameter names (the bicycle "
                                     "is a parameter file)")
                return bicycle_from_parameters(self._measured, self._bike_doc["name"], self._bike_source)
            doc = self._document(self._bike_doc, changes, self._bike_source, self._size_index)
            return bicycle_from_mapping(doc, self._bike_source, self._size)
        return _lru(self._bicycles, changes, build)

    def posed_rider(self, changes=()):
        """The rider (pose file with ``changes``) as written, or ``None``."""
        if self._rider_doc is None:
            if changes:
                raise InputError(self.origin, changes[0][0], "a rider to change (no rider given)")
            return None

        def build():
            doc = self._document(self._rider_doc, changes, self._rider_source)
            return _read_document(Node(doc, self._rider_source, ""), self.rider, False)
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
        :func:`bikemass.scenario.catalog.stiffness`; a changed bicycle's S is computed, never published)."""
        def build():
            if which in (None, "infinite", "rigid") or which not in self.materials():
                return catalog.stiffness(self.bike, which)
            return catalog.stiffness(self.bicycle(bike_changes), which, "computed" if bike_changes else "auto")
        return _lru(self._stiffness, (which, bike_changes), build)

    def build(self, changes=None):
        """:class:`Built` for ``{key: value}`` changes (see the module docstring)."""
        bike, rider, params, stiffness = split_changes(changes or {})
        p = self.parameters(bike, rider)
        if params:
            p = check_parameters(p.replace(**dict(params)), self.origin)
        return p, self.frame_stiffness(self.stiffness if stiffness is None else stiffness, bike)
