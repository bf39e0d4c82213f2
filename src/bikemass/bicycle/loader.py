"""Reading a bicycle: ``frames/<name>.yaml``, any bicycle YAML file, a benchmark parameter file
(YAML/JSON with the 26 names, or BicycleParameters' ``name = value+/-std`` text), BicycleParameters'
raw measurements (``<Name>Measured.txt`` or its YAML form: :mod:`bikemass.bicycle.measured`), or a
measured bicycle: a YAML file naming such a file (``parameters:``) next to ``contacts:`` and
``stiffness:``, so that riders can be posed on it.

The file format is described in docs/bicycles.md.  Every problem is reported as
one :class:`~bikemass.core.errors.InputError` naming the file and the key.
"""

import os
from dataclasses import replace
from pathlib import Path

import numpy as np

from ..core.config import Node, load_yaml
from ..core.errors import InputError, short
from ..core.gate import plain_input, read_text
from ..core.paths import frames_dir, resolve, named_file, within_reach
from ..mass.inertia import MassProperties
from ..mass.materials import load_materials, read_materials
from ..mass.parts import Part
from ..mass.placement import Placement
from ..mass.sections import RoundSection, SquareSection
from ..mass.solids import Lumped, RoundTube, SquareTube
from ..mass.tubes import Structure, Tube
from ..models.plausibility import check_stiffness
from .measured import looks_measured, measured_of_node
from .parameter_sets import (kind_of, measured_parameter_set, read_parameter_set, read_parameter_set_text,
                             whipple_parameters)
from .parameter_text import looks_like_parameter_text
from .chart_build import expand_chart
from .components import materials_lookup, read_component, read_wheel
from .contacts import read_contacts
from .geometry import Geometry, check_keypoints, read_geometry
from .model import Bicycle
from .sizes import select_size, size_names, split_size

TOP_KEYS = ("name", "base", "source", "description", "geometry", "keypoints", "material", "sections", "tubes",
            "structure", "components", "loads", "wheels", "stiffness", "contacts", "materials", "rider_included")


MEASURED_KEYS = ("name", "parameters", "contacts", "stiffness", "source", "description", "rider_included")
"""Keys of a measured-bicycle file (a parameter file plus what a parameter set cannot hold)."""


def load_bicycle(name_or_path, size=None):
    """:class:`Bicycle` for a shipped name (``frames/``), a bicycle YAML file or a parameter file.

    A size run (``sizes:``) needs ``size``, or the name as ``BIKE@SIZE``.
    """
    name, at_size = split_size(name_or_path)
    path = resolve(name, frames_dir(), "bicycle")
    if _is_parameter_text(path):
        return _parameter_set_bicycle(read_parameter_set_text(path), path.stem, str(path))
    return _read_document(load_yaml(path), path.stem, str(path), size or at_size)


def read_measured_bicycle(node, default_name, source):
    """A :class:`Bicycle` of a YAML mapping of BicycleParameters measurements (:mod:`.measured`)."""
    measured = measured_of_node(node)
    name = node["name"].string() if node.has("name") else default_name
    return bicycle_from_parameters(measured.parameters, name, source, measured=measured)


def bicycle_from_mapping(mapping, source, size=None):
    """:class:`Bicycle` from a Python mapping holding what a bicycle or parameter file holds;
    errors name ``source``.  A ``base`` is looked up as a shipped name or relative to the
    working folder."""
    node = Node(plain_input(mapping, source), source, "")
    if not isinstance(node.value, dict):
        node.fail("a mapping of a bicycle or of the 26 benchmark parameters")
    return _read_document(node, source, source, size)


def _read_document(node, default_name, source, size):
    if isinstance(node.value, dict) and looks_measured(node.value):
        select_size(node, size)                        # measurements have no sizes: refuse one asked for
        return read_measured_bicycle(node, default_name, source)
    if kind_of(node) is not None:
        select_size(node, size)                        # a parameter set has no sizes: refuse one asked for
        return _parameter_set_bicycle(read_parameter_set(node), default_name, source)
    if node.has("parameters"):
        return _measured_bicycle(node, Path(source))
    return _read_any(_with_base(node), source, size)


def bicycle_sizes(name_or_path):
    """The size names of a bicycle file's size run, ``()`` if it has none (``BIKE@SIZE``: that size)."""
    name, at_size = split_size(name_or_path)
    if at_size is not None:
        return ()
    path = resolve(name, frames_dir(), "bicycle")
    if _is_parameter_text(path):
        return ()
    return size_names(load_yaml(path))


def _read_any(node, source, size=None):
    """A keypoints or chart bicycle (one size of a size run) from its merged top-level mapping."""
    node = select_size(node, size)
    if not node.has("chart"):
        return read_bicycle(node, source)
    if node.has("geometry"):
        node.fail("either chart: (a geometry chart) or geometry: with keypoints:, not both", "geometry")
    mapping, chart = expand_chart(node)
    return replace(read_bicycle(mapping, source), chart=chart, size=size)


def _is_parameter_text(path):
    if path.suffix.lower() == ".txt":
        return True
    try:
        return looks_like_parameter_text(read_text(path))
    except InputError:
        return False                      # load_yaml names the problem


def _parameter_set_bicycle(parameter_set, default_name, source, **extra):
    """A :class:`Bicycle` of four lumped bodies holding a parameter set read from ``source``."""
    return bicycle_from_parameters(whipple_parameters(parameter_set), parameter_set.label or default_name,
                                   source, rider_included=parameter_set.rider_included,
                                   speed=parameter_set.speed, measured=parameter_set.measured, **extra)


def _measured_bicycle(node, path):
    """A parameter file (``parameters:``, relative to this file) with contacts and published stiffness."""
    node.check_keys(required=("parameters",), optional=MEASURED_KEYS)
    target = named_file(node["parameters"])
    if not target.is_file():
        node.fail(f"an existing parameter file, got {str(target)!r}", "parameters")
    if _is_parameter_text(target):
        inner = read_parameter_set_text(target)
    else:
        document = load_yaml(target)
        if looks_measured(document.value):
            inner = measured_parameter_set(measured_of_node(document))
        elif kind_of(document) is None:
            node.fail(f"a parameter file (the 26 benchmark names, a BicycleParameters text or parameter-set "
                      f"file), got {short(str(target))}, which is none", "parameters")
        else:
            inner = read_parameter_set(document)
    stiffness = _read_stiffness(node["stiffness"], load_materials()) if node.has("stiffness") else {}
    contacts = read_contacts(node["contacts"], {}) if node.has("contacts") else None
    name = node["name"].string() if node.has("name") else path.stem
    included = inner.rider_included or node.get("rider_included", False).boolean()
    return bicycle_from_parameters(whipple_parameters(inner), name, str(path), stiffness, contacts, included,
                                   speed=inner.speed, measured=inner.measured)


MAX_BASE_CHAIN = 16
"""Most ``base:`` files one bicycle may stand on."""


def _base_path(node):
    """A base bicycle: a file next to the referring file (``name`` or ``name.yaml``), else as any BIKE;
    a missing one is blamed on the ``base`` key of the referring file."""
    name = node.string()
    for candidate in (name, f"{name.replace('-', '_')}.yaml"):
        path = named_file(node, candidate) if within_reach(Path(node.source).parent / candidate) else None
        if path is not None and os.path.lexists(path):     # the input gate says if it is not a regular file
            return path
    try:
        return resolve(name, frames_dir(), "bicycle")
    except InputError as exc:
        node.fail(f"{exc.expected}, got {short(name)}")


def _with_base(node, seen=()):
    """``node`` on top of its ``base`` bicycle: the base's top-level keys, replaced by this file's.

    The base file is first read on its own, so its errors name the base file.
    """
    if not node.has("base"):
        return node
    path = _base_path(node["base"])
    if path.resolve() in seen or len(seen) >= MAX_BASE_CHAIN:
        node.fail("a base bicycle that does not lead back to this file" if path.resolve() in seen else
                  f"a chain of at most {MAX_BASE_CHAIN} base files", "base")
    base = _with_base(load_yaml(path), seen + (path.resolve(),))
    if not size_names(base):
        _read_any(base, str(path))
    merged = {**base.mapping(), **{k: v for k, v in node.mapping().items() if k != "base"}}
    return Node(merged, node.source, node.key)


def read_bicycle(node, source):
    """:class:`Bicycle` from the top-level mapping ``node`` of a bicycle YAML file."""
    node.check_keys(required=("name", "geometry", "wheels"), optional=TOP_KEYS)
    materials = {**load_materials(), **_file_materials(node)}
    geometry = read_geometry(node["geometry"])
    keypoints = {str(k): v.vector("length") for k, v in node.get("keypoints", {}).items()}
    tubes = _read_tubes(node, keypoints, materials)
    structure = _read_structure(node, tubes, keypoints) if node.has("structure") else None
    check_keypoints(geometry, node["geometry"], keypoints,
                    structure.head_tube if structure else None, structure.dropouts if structure else None)
    parts = [_tube_part(t) for t in tubes]
    for key, default_body in (("components", None), ("loads", "rear_frame")):
        for item in node.get(key, []).elements():
            parts += read_component(item, materials, default_body)
    wheels = node["wheels"]
    wheels.check_keys(required=("rear", "front"))
    parts += read_wheel(wheels["rear"], "rear_wheel", geometry.rear_axle, geometry.rear_wheel_radius,
                        "rear_wheel_radius")
    parts += read_wheel(wheels["front"], "front_wheel", geometry.front_axle, geometry.front_wheel_radius,
                        "front_wheel_radius")
    for body in ("rear_frame", "front_frame"):
        if not any(p.body == body for p in parts):
            node.fail(f"at least one tube or component with body {body}", "components")
    stiffness = _read_stiffness(node["stiffness"], materials) if node.has("stiffness") else {}
    contacts = read_contacts(node["contacts"], keypoints) if node.has("contacts") else None
    return Bicycle(node["name"].string(), source, geometry, keypoints, tuple(tubes), tuple(parts),
                   structure, stiffness, contacts=contacts,
                   rider_included=node.get("rider_included", False).boolean())


def _file_materials(node):
    """Materials of the bicycle file: ``materials:`` as a mapping in the format of
    ``frames/materials.yaml``, or the path of such a file (relative to the bicycle file)."""
    if not node.has("materials"):
        return {}
    m = node["materials"]
    if isinstance(m.value, str):
        path = named_file(m)
        if not path.is_file():
            m.fail(f"a materials YAML file (as frames/materials.yaml), {path} does not exist")
        return load_materials(path)
    return read_materials(m)


def _read_sections(node):
    sections = {}
    for name, s in node.get("sections", {}).items():
        if s.has("side"):
            s.check_keys(required=("side", "wall"), optional=("note",))
            size, wall = s["side"].number("length", positive=True), s["wall"].number("length", positive=True)
            if wall >= size / 2:
                s.fail(f"a wall thinner than half the side {size:.6g} m, got {wall:.6g} m", "wall")
            sections[name] = SquareSection(size, wall)
        else:
            s.check_keys(required=("outer_diameter", "wall"), optional=("note",))
            size, wall = s["outer_diameter"].number("length", positive=True), s["wall"].number("length", positive=True)
            if wall > size / 2:
                s.fail(f"a wall no thicker than the radius {size / 2:.6g} m, got {wall:.6g} m", "wall")
            sections[name] = RoundSection(size, wall)
    return sections


def _read_tubes(node, keypoints, materials):
    sections = _read_sections(node)
    default_material = node.get("material")
    tubes, names = [], set()
    for t in node.get("tubes", []).elements():
        t.check_keys(required=("name", "from", "to", "section"), optional=("material", "body", "note"))
        name = t["name"].string()
        if name in names:
            t.fail(f"a tube name not used before, got {name!r}", "name")
        names.add(name)
        ends = []
        for key in ("from", "to"):
            kp = t[key].string()
            if kp not in keypoints:
                t.fail(f"a keypoint defined under keypoints, got {kp!r}", key)
            ends.append(kp)
        start, end = keypoints[ends[0]], keypoints[ends[1]]
        if np.linalg.norm(end - start) < 1e-6:
            t.fail(f"a keypoint other than {ends[0]!r} (zero-length tube)", "to")
        section = t["section"].string()
        if section not in sections:
            t.fail(f"a section defined under sections ({', '.join(sections)}), got {section!r}", "section")
        material_node = t["material"] if t.has("material") else default_material
        if material_node.missing:
            t.fail("a required key that is missing (no top-level material either)", "material")
        material = materials_lookup(material_node, materials)
        body = t.get("body", "rear_frame").string(choices=("rear_frame", "front_frame"))
        tubes.append(Tube(name, ends[0], ends[1], start, end, sections[section], material, body))
    return tubes


def _tube_part(tube):
    s = tube.section
    if isinstance(s, SquareSection):
        solid = SquareTube(s.side, s.wall, tube.length)
    else:
        solid = RoundTube(s.outer_diameter, s.wall, tube.length)
    return Part.from_density(tube.name, solid, tube.material.density,
                             Placement.along(tube.start, tube.end - tube.start), tube.body)


def _read_structure(node, tubes, keypoints):
    s = node["structure"]
    s.check_keys(required=("tubes", "dropouts", "head_tube"), optional=("note",))
    rear = {t.name: t for t in tubes if t.body == "rear_frame"}
    if s["tubes"].value == "all":
        chosen = list(rear.values())
    else:
        chosen = []
        for e in s["tubes"].elements():
            if e.string() not in rear:
                e.fail(f"a rear_frame tube name, got {e.value!r}")
            chosen.append(rear[e.value])
    supports = {}
    for key in ("dropouts", "head_tube"):
        pair = s[key].elements()
        if len(pair) != 2 or pair[0].value == pair[1].value:
            s.fail(f"a list of two different keypoint names, got {short(s[key].value)}", key)
        for e in pair:
            if e.string() not in keypoints:
                e.fail(f"a keypoint defined under keypoints, got {e.value!r}")
        supports[key] = tuple(e.value for e in pair)
        if np.linalg.norm(keypoints[pair[0].value] - keypoints[pair[1].value]) < 1e-6:
            s.fail(f"two keypoints at different places, got {supports[key]} both at "
                   f"{np.round(keypoints[pair[0].value], 4).tolist()}", key)
    used = {k for t in chosen for k in (t.start_key, t.end_key)} | set(supports["dropouts"]) | set(supports["head_tube"])
    return Structure(tuple(chosen), supports["dropouts"], supports["head_tube"],
                     {k: v for k, v in keypoints.items() if k in used})


def _read_stiffness(node, materials):
    table = {}
    for name, m in node.items():
        material = materials_lookup(Node(name, m.source, m.key), materials)
        table[material.key] = check_stiffness(m)
    return table


def bicycle_from_parameters(params, name, source, stiffness=None, contacts=None, rider_included=False,
                            speed=None, measured=None):
    """A :class:`Bicycle` of four lumped bodies holding a benchmark parameter set
    (optionally published ``stiffness`` by material and rider ``contacts``;
    ``rider_included``: its rear body B already holds a rider; ``speed``: the speed its file
    gives, m/s; ``measured``: the set's :class:`~bikemass.bicycle.parameter_text.MeasuredParameters`,
    its standard deviations)."""
    geometry = Geometry(params.w, params.c, np.pi / 2 - params.lam, params.rR, params.rF, params.g)
    bodies = (
        ("rear_wheel", params.mR, geometry.rear_axle, params.inertia("R")),
        ("rear_frame", params.mB, [params.xB, 0.0, params.zB], params.inertia("B")),
        ("front_frame", params.mH, [params.xH, 0.0, params.zH], params.inertia("H")),
        ("front_wheel", params.mF, geometry.front_axle, params.inertia("F")),
    )
    parts = tuple(Part(body, Lumped(MassProperties(mass, np.zeros(3), inertia)), mass, Placement.at(at), body)
                  for body, mass, at, inertia in bodies)
    return Bicycle(name, source, geometry, {}, (), parts, None, stiffness or {}, params, contacts,
                   rider_included=rider_included, speed=speed, measured=measured)
