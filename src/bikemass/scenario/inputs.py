"""A bicycle, rider and stiffness read once, rebuilt with changed inputs.

Inputs are named by keys:

* one of the 26 benchmark names (``c``, ``lam``, ...): replaces that value in the final set (for a
  model that splits the rider at the hips, the leaning rider's, the set without the upper body;
  :attr:`~bikemass.scenario.scenario.Built.parameters` is the rigid set, upper body included);
* ``stiffness``: a stiffness choice (``infinite``, ``steel``, ... or a file), as ``--stiffness``;
* ``rider.<path>``: a dotted path into the pose YAML (``rider.chain.torso_lean``,
  ``rider.posture.elbow``; ``rider.segments.torso.angle`` of a placement pose that meets the
  bicycle's contacts as written: one re-seated by its ``posture:`` refuses it);
* any other dotted path: into the bicycle YAML (``sections.seat_stay.wall``,
  ``geometry.trail``, ``chart.head_tube_angle``).  In a list, a step is an element's
  ``name`` or its index (``tubes.down_tube.section``, ``components.0.mass``).

The YAML files are parsed once; a bicycle (its meshes' mass properties, and its stiffness)
and a rider are built once per distinct set of their own changes and reused by every
configuration that shares them; each part's mass properties once per distinct part (a
changed stack re-computes only the parts it moves or resizes), a changed document copied only
along the changed paths, and a chain pose's own bicycle (another than the scenario's) read once.
"""

import copy
import os
from collections import OrderedDict
from collections.abc import Mapping

from ..bicycle.benchmark import bicycle_parameters, combined_bodies, parameters_from_bodies, refuse_second_rider
from ..bicycle.chart import ANGLE_KEYS, CHECKED_KEYS, FRAME_KEYS, STAND_INS
from ..bicycle.geometry import changed_geometry
from ..bicycle.loader import _is_parameter_text, _with_base, bicycle_from_mapping, bicycle_from_parameters
from ..bicycle.measured import measured_values
from ..bicycle.model import BODIES, Bicycle
from ..bicycle.parameter_sets import RIDER_LEAN, kind_of, read_parameter_set, read_parameter_set_text
from ..bicycle.sizes import select_size, split_size
from ..core.choices import RIGID
from ..core.config import Node, load_yaml
from ..core.errors import InputError, short
from ..core.gate import MAPPING, plain_input
from ..core.paths import frames_dir, resolve
from ..core.plain import file_form
from ..core.units import DIMENSIONS, Quantity, dimension_of, to_si
from ..mass.inertia import combine
from ..mass.materials import Material, load_materials
from ..models.members.flexible.parameters import Compliances
from ..models.members.rider_lean.parameters import RiderLeanParameters
from ..models.parameters import NAMES, BenchmarkParameters
from ..models.registry import SPECS
from ..models.plausibility import front_load_problem, warn
from ..rider import Rider, _read_document, poses_dir
from ..rider.chain_file import bicycle_contacts
from ..rider.hands import forearms_on_handlebars
from ..rider.lean_split import rider_lean_parameters
from ..rider.pose import is_lumped
from ..rider.seating import SeatedRider
from . import catalog
from .catalog import seated_rider, seating
from .loading import load_bicycle, load_rider

RIDER_PREFIX = "rider."
MEASURED_PREFIX = "measured."
"""Inputs ``measured.<name>``: a raw measurement of a bicycle computed from measurements
(:mod:`bikemass.bicycle.measured`), in its file's units; the bicycle is recomputed from them."""
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

    A ``"<number> <unit>"`` string or a :class:`~bikemass.core.units.Quantity` is set as it is.  A
    number is in SI (m, kg, rad, ...): where the file writes a unit there (``"0.040 in"``, or a
    chart's ``units:`` block) it is set as a Quantity in the SI unit of that quantity (typed, no
    text); a bare number stays bare (the file's bare numbers are SI already)."""
    container, slot = _walk(document, path, source, origin, parent=True)
    if size_index is not None and isinstance(container[slot], list):
        container, slot = container[slot], size_index
    unit = _file_unit(document, path, container[slot])
    if unit and not isinstance(value, (str, Quantity)):
        try:
            value = Quantity(float(value), DIMENSIONS[dimension_of(unit)][0])
        except (TypeError, ValueError):
            raise InputError(origin, path, f"a number in SI or a value with its unit (the file writes {unit} "
                             f"there), got {short(value)}") from None
    container[slot] = _as_list(value)


def _as_list(value):
    """A change's tuple (a cache key) as the list the YAML document holds, recursively."""
    return [_as_list(v) for v in value] if isinstance(value, tuple) else value


def _unit(value):
    """The unit of a ``"<number> <unit>"`` YAML value or of a Quantity, else None."""
    if isinstance(value, Quantity):
        return value.unit
    parts = value.split() if isinstance(value, str) else ()
    return parts[1] if len(parts) == 2 and dimension_of(parts[1]) is not None else None


CHART_KEY = "chart"


def _file_unit(document, path, value):
    """The unit the file writes ``value`` (at dotted ``path``) in: its own (``"585 mm"``), for a
    bare chart value the chart's ``units:`` block (angles for the head and seat tube angles,
    else lengths), else None (a bare number in SI)."""
    own = _unit(value)
    if own is not None or isinstance(value, (str, Quantity)):
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
    if key in NAMES or key == STIFFNESS_KEY or key.startswith(MEASURED_PREFIX):
        return None
    document, path, value = _located(model, key)
    return _file_unit(document, path, value)


def _located(model, key):
    """``(document, path, value)`` of dotted input ``key`` of ``model`` (one size of a size run)."""
    if key.startswith(RIDER_PREFIX):
        source, doc = model._read_rider()
        if doc is None:
            raise InputError(model.origin, key, "a rider to change (no rider given)")
        path = key[len(RIDER_PREFIX):]
        return doc, path, _walk(doc, path, source, model.origin)
    model._read()
    if model.lean_set is not None:
        raise InputError(model.origin, key, "one of the 26 parameter names (the bicycle is a MooreRiderLean2012 "
                         "parameter set, which has no other inputs)")
    value = _walk(model._bike_doc, key, model._bike_source, model.origin)
    if model._size_index is not None and isinstance(value, list):
        value = value[model._size_index]
    return model._bike_doc, key, value


def get_path(model, key):
    """Current value of input ``key`` of ``model`` in SI (m, kg, rad, ...; ``"0.040 in"`` ->
    0.001016, a chart's ``590`` under ``units: {length: mm}`` -> 0.59); a bare number as written."""
    if key in NAMES:
        return float(getattr(model.parameters(), key))
    if key.startswith(MEASURED_PREFIX):
        nominal, name = model.measurements(key), key[len(MEASURED_PREFIX):]
        if name not in nominal:
            raise InputError(model.origin, key, f"a measurement of this file ({short(', '.join(nominal), 80)})")
        return float(nominal[name])
    document, path, value = _located(model, key)
    unit = _file_unit(document, path, value)
    try:
        number = value.value if isinstance(value, Quantity) else float(value.split()[0] if _unit(value) else value)
    except (TypeError, ValueError, AttributeError):
        raise InputError(model.origin, key, f"a number at that path, got {value!r}") from None
    return to_si(number, dimension_of(unit), bare_unit=unit) if unit else number


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


def _shallow(value):
    return dict(value) if isinstance(value, dict) else list(value) if isinstance(value, list) else value


def _copied_along(document, paths):
    """``document`` with every mapping and list on the way to each dotted path of ``paths`` (and
    the value there, if it is one) copied, the rest shared: what :func:`set_path` may then change
    without touching ``document`` (a whole deep copy costs more than the bicycle it describes)."""
    out = _shallow(document)
    for path in paths:
        node = out
        for step in path.split("."):
            slot = _slot(node, step)
            if slot is None:
                break                              # set_path names the missing step
            node[slot] = _shallow(node[slot])
            node = node[slot]
    return out


class Inputs:
    """The inputs of one :class:`~bikemass.scenario.scenario.Scenario`, read once and rebuilt with changes.

    Every piece (a bicycle, a posed and a seated rider, the bicycle's bodies, the benchmark set, the
    leaning rider's split, a stiffness, the flexible model's compliances, the tyres) is cached by the
    changes it depends on, so a sweep or a web page pays only for what changed.  Without changes
    every piece is what the loaders give for the scenario as written (``bm.load_bicycle``,
    ``bm.seated_rider``, ``bm.stiffness``).
    """

    def __init__(self, bike, rider=None, combine="exact", method="mesh", origin="spec", allow_off_contact=False):
        self.bike, self.rider, self.combine, self.method = bike, rider, combine, method
        self.origin, self.allow_off_contact = origin, allow_off_contact
        self._documents = None
        self._rider_documents = None
        self._caches = {}
        self._materials = None

    def _cache(self, name):
        return self._caches.setdefault(name, OrderedDict())

    # -- the documents, read on first use --------------------------------------------------
    def _read(self):
        """Read the bicycle's document once (for changes and their values): its source and
        document, or what a parameter file or a built value holds instead."""
        if self._documents is not None:
            return
        self._measured = self._fixed = None
        self._size = self._size_index = None
        bike = self.bike
        if self.lean_set is not None:
            self._bike_source, self._bike_doc = self._lean_source, {}
        elif isinstance(bike, Bicycle):               # built already: only its parameters can change
            self._fixed, self._bike_source, self._bike_doc = bike, bike.source, {}
        elif isinstance(bike, BenchmarkParameters):
            self._fixed = load_bicycle(bike)
            self._bike_source, self._bike_doc = "<parameters>", {}
        elif isinstance(bike, Mapping):
            self._bike_source, self._bike_doc = MAPPING, plain_input(bike, MAPPING)
        else:
            self._read_bicycle_file(os.fspath(bike))
        self._documents = True

    def _read_bicycle_file(self, bike):
        name, self._size = split_size(bike)
        path = resolve(name, frames_dir(), "bicycle")
        self._bike_source = str(path)
        if _is_parameter_text(path):
            measured = read_parameter_set_text(path)
            self._measured = measured.parameters
            self._bike_doc = {"name": path.stem, **measured.parameters.to_dict()}
            return
        self._bike_doc = _with_base(load_yaml(path)).mapping()
        sizes = [str(x) for x in self._bike_doc.get("sizes", [])] if self._size is not None else []
        self._size_index = sizes.index(str(self._size)) if str(self._size) in sizes else None

    @property
    def lean_set(self):
        """The :class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters` of a bicycle given as a
        ``MooreRiderLean2012`` parameter set (BicycleParameters' YAML) or as the value itself, else ``None``."""
        if "_lean_set" not in self.__dict__:
            self._lean_set, self._lean_source = None, None
            bike = self.bike
            node = None
            if isinstance(bike, RiderLeanParameters):
                self._lean_set, self._lean_source = bike, "<rider-lean parameters>"
            elif isinstance(bike, Mapping):
                node = Node(plain_input(bike, MAPPING), MAPPING, "")
            elif isinstance(bike, (str, os.PathLike)):
                path = resolve(split_size(os.fspath(bike))[0], frames_dir(), "bicycle")
                node = None if _is_parameter_text(path) else load_yaml(path)
            if node is not None and kind_of(node) == RIDER_LEAN:
                read = read_parameter_set(node)
                self._lean_set, self._lean_source = read.parameters, read.source
        return self._lean_set

    @property
    def parameter_node(self):
        """The :class:`~bikemass.core.config.Node` of a parameter file (or mapping) the bicycle is, read
        once; ``None`` for any other bicycle (a bicycle YAML, a chart, a name of one, a parameter text)."""
        if "_parameter_node" not in self.__dict__:
            node, bike = None, self.bike
            if isinstance(bike, Mapping):
                node = Node(plain_input(bike, MAPPING), MAPPING, "")
            elif isinstance(bike, (str, os.PathLike)):
                path = resolve(split_size(os.fspath(bike))[0], frames_dir(), "bicycle")
                node = None if _is_parameter_text(path) else load_yaml(path)
            self._parameter_node = node if node is not None and kind_of(node) is not None else None
        return self._parameter_node

    @property
    def file_members(self):
        """What a parameter file written by ``bikemass params --model M`` carries beside its set
        (:data:`~bikemass.bicycle.parameter_sets.MEMBER_KEYS`): ``{"model": str, <member name>: its typed
        parameters (its ``read_block``), "frame_stiffness": 2x2 S (N m/rad)}``, each key only when
        present; ``{}`` for any other bicycle."""
        if "_file_members" not in self.__dict__:
            node = self.parameter_node
            found = {}
            if node is not None:
                if node.has("model"):
                    found["model"] = node["model"].string()
                for spec in SPECS:                       # each member's block, under its name
                    read = spec.hook("read_block")
                    if read is not None and node.has(spec.name):
                        found[spec.name] = read(node[spec.name])
                if node.has("frame_stiffness"):
                    found["frame_stiffness"] = catalog.stiffness_matrix(node["frame_stiffness"].matrix(
                        "stiffness", (2, 2)))
            self._file_members = found
        return self._file_members

    def _read_rider(self):
        """The rider's source and document (``None`` without a rider or for a Rider built from parts)."""
        if self._rider_documents is not None:
            return self._rider_documents
        rider, source, doc = self.rider, None, None
        if isinstance(rider, SeatedRider):
            rider = rider.rider
        if isinstance(rider, Rider):
            if rider.spec is not None:
                node, _ = rider.spec
                source, doc = str(node.source), node.thaw().value
        elif isinstance(rider, Mapping):
            source, doc = MAPPING, plain_input(rider, MAPPING)
        elif isinstance(rider, (str, os.PathLike)) and rider != "none":
            rpath = resolve(os.fspath(rider), poses_dir(), "pose")
            source, doc = str(rpath), load_yaml(rpath).value
        elif rider not in (None, "none"):
            load_rider(rider)                      # names what a rider is
        self._rider_documents = (source, self._own_bicycle_pose(doc))
        return self._rider_documents

    @property
    def file_std(self):
        """``{name: std}`` (SI; those above 0) of a measured bicycle's parameters: a BicycleParameters
        text file's ``+/-`` values, a parameter file's ``uncertainty:`` block, or computed from
        measurements (:attr:`~bikemass.bicycle.model.Bicycle.measured`); ``{}`` for any other bicycle."""
        if self.lean_set is not None:
            return {}
        measured = self.bicycle(()).measured
        return {} if measured is None else {k: float(v) for k, v in measured.std.items() if v > 0}

    def _own_bicycle_pose(self, doc):
        """A chain pose whose ``bike:`` names this scenario's own bicycle is solved on the bicycle
        as changed (a person re-seated by the same posture rule), so its ``bike:`` is dropped."""
        if not (isinstance(doc, dict) and "chain" in doc and isinstance(doc.get("bike"), str)):
            return doc
        self._read()
        own, _ = split_size(doc["bike"])
        try:
            same = str(resolve(own, frames_dir(), "bicycle")) == self._bike_source
        except InputError:
            return doc                             # the pose's own error, reported where it is read
        if same and split_size(doc["bike"])[1] in (None, self._size):
            return {k: v for k, v in doc.items() if k != "bike"}
        return doc

    # -- pieces, each cached by its own changes -------------------------------------------
    def _document(self, doc, changes, source, size_index=None):
        out = _copied_along(doc, [path for path, _ in changes])
        for path, value in changes:
            set_path(out, path, value, source, self.origin, size_index)
        return out

    def bicycle(self, changes=()):
        """The bicycle with dotted-path ``changes`` (``((path, value), ...)``, sorted); without
        changes, ``bm.load_bicycle`` of the scenario's bicycle."""
        if self.lean_set is not None:
            raise InputError(self._lean_source, "parameterization", "a bicycle (benchmark parameters, a bicycle "
                             "YAML or a chart); a MooreRiderLean2012 set holds only the rider-lean model's "
                             "parameters")

        def build():
            if not changes:
                return load_bicycle(self.bike)
            remeasured = [c for c in changes if c[0].startswith(MEASURED_PREFIX)]
            if remeasured:
                return self._remeasured(changes)
            self._read()
            if self._measured is not None or self._fixed is not None:
                what = "is a parameter file" if self._measured is not None else "was given built, not as YAML"
                raise InputError(self.origin, changes[0][0], f"one of the 26 parameter names (the bicycle {what})")
            chart_changes = [path for path, _ in changes if path.split(".")[0] == CHART_KEY]
            for path in chart_changes:
                if path.split(".")[-1] in CHECKED_KEYS:
                    raise InputError(self.origin, path, f"a frame value of the chart ({', '.join(FRAME_KEYS)}); "
                                     f"{path.split('.')[-1]} is derived from the frame (the published value "
                                     "only checks the chart as published)")
            base = self._changeable_chart() if chart_changes else self._bike_doc
            doc = self._document(base, changes, self._bike_source, self._size_index)
            geometry = {path.split(".")[1] for path, _ in changes if path.startswith("geometry.") and "." in path}
            if geometry:
                self.bicycle(())            # the file as written passes every keypoint check
            with changed_geometry(geometry):
                return bicycle_from_mapping(doc, self._bike_source, self._size)
        return _lru(self._cache("bicycles"), changes, build)

    def bicycle_document(self, changes=()):
        """The bicycle's YAML document with dotted-path ``changes`` (``((path, value), ...)``), one size of
        a size run picked and its chart ready to change (:meth:`_changeable_chart`): the document
        :meth:`bicycle` builds the changed bicycle from, what a changed design is written as (its
        typed values as text: :func:`~bikemass.core.plain.file_form`, for a file)."""
        self._read()
        if self._measured is not None or self._fixed is not None or self.lean_set is not None:
            raise InputError(self.origin, "bike", "a bicycle YAML or chart to write a changed design as (this "
                             "bicycle is a parameter set)")
        chart = any(path.split(".")[0] == CHART_KEY for path, _ in changes)
        doc = self._document(self._changeable_chart() if chart else self._bike_doc, changes, self._bike_source,
                             self._size_index)
        return file_form(select_size(Node(doc, self._bike_source, ""), self._size).value)

    def measurements(self, key=MEASURED_PREFIX):
        """The :class:`~bikemass.bicycle.measured.MeasuredData` ``nominal`` values of a bicycle computed
        from measurements; InputError naming ``key`` for any other bicycle."""
        measured = self.bicycle(()).measured
        if measured is None or measured.data is None:
            raise InputError(self.origin, key, "a bicycle computed from measurements (BicycleParameters' "
                             "<Name>Measured.txt or its YAML form) for a measured.<name> input")
        return measured.data.nominal

    @property
    def measurement_std(self):
        """``{"measured.<name>": std}`` of a bicycle computed from measurements (the file's units; those
        above 0), else ``{}``."""
        if self.lean_set is not None:
            return {}
        measured = self.bicycle(()).measured
        if measured is None or measured.data is None:
            return {}
        return {MEASURED_PREFIX + k: float(v) for k, v in measured.data.std.items() if v > 0}

    def _remeasured(self, changes):
        """The bicycle computed from its measurements with ``measured.<name>`` ``changes``."""
        other = [key for key, _ in changes if not key.startswith(MEASURED_PREFIX)]
        if other:
            raise InputError(self.origin, other[0], "measured.<name> inputs only, or none, on a bicycle computed "
                             "from measurements (its measurements are its document)")
        self.measurements(changes[0][0])
        base = self.bicycle(())
        params = measured_values(base.measured.data, {k[len(MEASURED_PREFIX):]: v for k, v in changes})
        return bicycle_from_parameters(params, base.name, base.source, base.stiffness, base.contacts,
                                       base.rider_included, base.speed)

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
                for key in STAND_INS:
                    if chart.get(key) is None and built is not None:
                        chart[key] = Quantity(float(getattr(built, key)), "m")
                for key in CHECKED_KEYS:
                    chart.pop(key, None)
                chart.pop("tolerances", None)
            self._chart_base = doc
        return self._chart_base

    def posed_rider(self, changes=()):
        """The rider (pose file with ``changes``) as written, or ``None``; a chain pose without
        ``bike:`` is seated on each changed bicycle (:meth:`seated`)."""
        if isinstance(self.rider, (Rider, SeatedRider)) and not changes:
            return self.rider.rider if isinstance(self.rider, SeatedRider) else self.rider
        source, doc = self._read_rider()
        if doc is None:
            if changes:
                raise InputError(self.origin, changes[0][0], "a rider to change (no rider given)")
            return None

        def build():
            changed = self._document(doc, changes, source)
            if isinstance(changed, dict) and "chain" in changed and isinstance(changed.get("bike"), str):
                changed["bike"] = self._pose_bicycle(changed["bike"], source)   # another bicycle: read once
            return _read_document(Node(changed, source, ""), source, False)
        return _lru(self._cache("riders"), changes, build)

    def _pose_bicycle(self, name, source):
        """The bicycle a chain pose names as its own ``bike:`` (other than the scenario's), loaded once
        per name: the pose is solved there and re-checked on every configuration's bicycle."""
        bicycles = self._cache("pose bicycles")
        if name not in bicycles:
            bicycles[name] = bicycle_contacts(name, Node(name, source, "bike"))
        return bicycles[name]

    def seated(self, bike_changes=(), rider_changes=()):
        """The rider seated on the changed bicycle (:func:`bikemass.scenario.catalog.seated_rider`),
        or ``None``; without changes, the scenario's rider as given, seated."""
        if self.rider in (None, "none") and not rider_changes:
            return None
        if self.lean_set is not None:
            raise InputError(self._lean_source, "rider", "no rider added: a MooreRiderLean2012 set holds its "
                             "rider (use --rider none)")

        def build():
            bicycle = self.bicycle(bike_changes)
            if not bike_changes and not rider_changes:
                if isinstance(self.rider, SeatedRider):       # seated already (its contacts measured)
                    refuse_second_rider(bicycle, self.rider.rider)
                    return self.rider.rider
                return seated_rider(bicycle, self.rider, self.allow_off_contact)
            rider = self.posed_rider(rider_changes)
            if rider is None:
                return None
            seated = seating(bicycle, rider, self.allow_off_contact)
            self._refuse_lost_segments(seated, rider_changes)
            return seated.rider
        return _lru(self._cache("seated"), (bike_changes, rider_changes), build)

    def _refuse_lost_segments(self, seated, rider_changes):
        """A change of a placement pose that the seated rider would drop without a word (a sweep of it
        flat, its derivative 0) is refused, naming the keys that do act:

        * re-seated by its ``posture:`` (its contacts, as changed, off the bicycle's), every segment of
          the body is placed afresh: a change of ``segments.<segment>`` is lost (a lumped body's is
          kept, and a segment's ``frame:`` where the posture names no ``front:``);
        * used as written (its contacts on the bicycle's, or allowed off them), its ``posture:`` is not
          used: a change of ``posture.*`` is lost."""
        _, doc = self._read_rider()
        if not (isinstance(doc, dict) and "segments" in doc and "chain" not in doc):
            return
        segments = doc["segments"] if isinstance(doc["segments"], dict) else {}
        posture = doc.get("posture") if isinstance(doc.get("posture"), dict) else {}
        lumped = {k for k, v in segments.items() if is_lumped(v)}
        parts = [path.split(".") for path, _ in rider_changes]
        if seated.how == "solved":
            lost = [p for p in parts if p[0] == "segments" and len(p) > 1 and p[1] not in lumped
                    and not (p[-1] == "frame" and "front" not in posture)]
            keys = ", ".join(f"rider.posture.{k}" for k in posture) or "rider.posture.*"
            why = (f"this placement pose, as changed, is off the bicycle's contacts, so it is re-seated by its "
                   f"posture:, which places every segment afresh; change {keys}, or give a pose that meets "
                   f"the bicycle's contacts")
        else:
            lost = [p for p in parts if p[0] == "posture"]
            why = ("this placement pose is used as written (its contacts on the bicycle's, or allowed off "
                   "them), so its posture: is not used; change rider.segments.*")
        if lost:
            raise InputError(self.origin, "rider." + ".".join(lost[0]), f"a change the seated rider keeps ({why})")

    def held(self, bike_changes=(), rider_changes=()):
        """The seated rider (:meth:`seated`) with the forearms on the handlebars (the arms member's
        ``forearms: handlebars``: :func:`bikemass.rider.hands.forearms_on_handlebars`), or ``None``."""
        def build():
            rider = self.seated(bike_changes, rider_changes)
            return None if rider is None else forearms_on_handlebars(rider, self.bicycle(bike_changes))
        return _lru(self._cache("held"), (bike_changes, rider_changes), build)

    def parameters(self, bike_changes=(), rider_changes=(), forearms_held=False):
        """Benchmark parameters of the bicycle and rider with their changes (before parameter
        changes): what ``bm.parameters`` gives for the changed files; ``forearms_held``: the rider's
        forearms on the front frame (:meth:`held`)."""
        if self.lean_set is not None:
            if bike_changes or rider_changes:
                key = (bike_changes or rider_changes)[0][0]
                raise InputError(self.origin, key, "one of the 26 parameter names (the bicycle is a "
                                 "MooreRiderLean2012 parameter set)")
            return _lru(self._cache("params"), ((), ()), self._lean_set.rigid)

        def build():
            bicycle = self.bicycle(bike_changes)
            if bike_changes or rider_changes:
                refuse_second_rider(bicycle, self.posed_rider(rider_changes))
            rider = (self.held if forearms_held else self.seated)(bike_changes, rider_changes)
            if rider is None and bicycle.published is not None:
                return bicycle_parameters(bicycle, None, self.combine, self.method)
            bodies = _lru(self._cache("bodies"), bike_changes, lambda: self._bicycle_bodies(bicycle))
            params = parameters_from_bodies(bicycle, combined_bodies(bicycle, rider, self.combine, self.method, bodies))
            if rider is not None:
                problem = front_load_problem(params, f"{bicycle.name} with rider {rider.name}")
                if problem:
                    warn(problem)
            return params
        return _lru(self._cache("params"), (bike_changes, rider_changes, forearms_held), build)

    def lean(self, bike_changes=(), rider_changes=(), forearms_held=False):
        """The leaning rider's :class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters` of the changed
        bicycle and rider: the seated rider split at the hips (:mod:`bikemass.rider.lean_split`),
        or the bicycle's own ``MooreRiderLean2012`` set; ``forearms_held``: the forearms on the front
        frame (:meth:`held`), not leaning with the upper body."""
        if self.lean_set is not None:
            if self.rider not in (None, "none"):                   # its rider is the set's own: none is added
                raise InputError(self._lean_source, "rider", "no rider added: a MooreRiderLean2012 set holds its "
                                 "rider (use --rider none)")
            self.parameters(bike_changes, rider_changes)           # refuses changes of the set's own
            return self.lean_set
        if self.combine != "exact":
            raise InputError(self.origin if self.origin != "spec" else "combine", "combine", "exact with the "
                             "rider-lean model (its split rider is combined with the parallel-axis theorem)")

        def build():
            rider = (self.held if forearms_held else self.seated)(bike_changes, rider_changes)
            if rider is None:
                raise InputError("rider", "(none)", "a rider for the rider-lean model to split at the hips "
                                 "(--rider POSE), or a MooreRiderLean2012 parameter set as the bicycle")
            return rider_lean_parameters(self.bicycle(bike_changes), rider, self.method)
        return _lru(self._cache("lean"), (bike_changes, rider_changes, forearms_held), build)

    def _bicycle_bodies(self, bicycle):
        """``bicycle.bodies(method)`` with each part's mass properties (its mesh) computed once per
        distinct part: a changed tube wall re-meshes only the tubes of that section."""
        parts = self._cache("parts")

        def props(part):
            placement = part.placement
            key = (part.name, part.solid, part.mass, placement.rotation.tobytes(), placement.translation.tobytes(),
                   part.body)
            cached = parts.get(key)
            if cached is None:
                cached = parts[key] = part.mass_properties(self.method)
                if len(parts) > PART_CACHE_SIZE:
                    parts.popitem(last=False)
            return cached
        return {b: combine(props(p) for p in bicycle.body_parts(b)) for b in BODIES}

    def materials(self):
        if self._materials is None:
            self._materials = load_materials()
        return self._materials

    def _is_material(self, which):
        return isinstance(which, Material) or (isinstance(which, str) and which not in (RIGID, "rigid")
                                               and which in self.materials())

    def frame_stiffness(self, which, bike_changes=()):
        """2x2 S (N m/rad) or None, for stiffness choice ``which`` on the changed bicycle (as
        :func:`bikemass.scenario.catalog.stiffness`; a changed bicycle's S is computed, never
        published).  ``which`` may be a name, a file, a Material or a 2x2 matrix (N m/rad)."""
        which, key = _stiffness_key(which)

        def build():
            if which is None and "frame_stiffness" in self.file_members and not bike_changes:
                return self.file_members["frame_stiffness"]          # the S a parameter file carries (no choice
                                                                     # given: the bicycle's own)
            if not self._is_material(which):
                return catalog.stiffness(self.bike, which)
            return catalog.stiffness(self.bicycle(bike_changes), which, "computed" if bike_changes else "auto")
        return _lru(self._cache("stiffness"), (key, bike_changes), build)

    def compliances(self, which, bike_changes=()):
        """The flexible model's :class:`~bikemass.models.members.flexible.parameters.Compliances` for stiffness choice
        ``which``: a material (every frame and fork tube in it, :func:`bikemass.fe.flexible.compliances`)
        or ``infinite`` (both held rigid)."""
        which, key = _stiffness_key(which)

        def build():
            for spec in SPECS:                       # a parameter file's compliances (params --model)
                if which is None and spec.takes_stiffness and spec.name in self.file_members:
                    return self.file_members[spec.name]
            if which is None or (isinstance(which, str) and which in (RIGID, "rigid")):
                return Compliances()
            if not (self._is_material(which) or _material_file(which)):
                raise InputError(self.origin if self.origin != "spec" else "stiffness", "stiffness",
                                 f"{RIGID} or a material ({', '.join(sorted(self.materials()))}) with the flexible "
                                 "model: its beam models make the compliances (a 2x2 S is the quasi-static spring "
                                 "of --model whipple)")
            # lazy: the beam models load scipy.linalg (0.4 s); only the flexible model needs them
            from ..fe.flexible import compliances
            return compliances(self.bicycle(bike_changes), which)
        return _lru(self._cache("compliances"), (key, bike_changes), build)


def _rigid(which):
    """Whether stiffness choice ``which`` is the default, rigid one."""
    return which is None or (isinstance(which, str) and which in (RIGID, "rigid"))


def _stiffness_key(which):
    """``(which, key)``: a stiffness choice and a hashable key of it (a matrix by its values)."""
    try:
        hash(which)
        return which, which
    except TypeError:                          # a matrix (a list or an array): cached by its values
        which = catalog.stiffness_matrix(which)
        return which, tuple(map(tuple, which.tolist()))


def _material_file(which):
    """Whether ``which`` names a one-material YAML file (not a stiffness file, which holds ``S:``)."""
    if not isinstance(which, (str, os.PathLike)) or not os.fspath(which).endswith((".yaml", ".yml")):
        return False
    node = load_yaml(os.fspath(which))
    return not (isinstance(node.value, dict) and "S" in node.value)

