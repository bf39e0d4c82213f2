"""Components, loads and wheel hoops read from a bicycle YAML file as placed :class:`~bikemass.mass.parts.Part`.

A component is a solid with a mass (or a material), placed by the position of
its centroid ``at`` (m) and an orientation: ``axis`` (the direction of the
solid's local z), or ``angle`` (deg, Williams 2015 Table 3-7: clockwise about y
seen with x to the right, local z turned from straight down), or neither (local
axes = bicycle axes).  ``mirror_y: true`` adds the same part mirrored to -y.
A ``lumped`` component is a body known by its mass, CoM ``at`` and ``inertia``.

A component's parts are read once per distinct mapping (by value: its ``repr``, the file and
key it came from and the materials): a sweep rebuilds the same saddle, bar and wheels' hubs for
every configuration that leaves them as they were.
"""

from collections import OrderedDict

import numpy as np

from ..core.convention import thesis_segment_rotation
from ..mass.inertia import MassProperties
from ..mass.parts import Part
from ..mass.placement import Placement
from ..mass.solids import Box, Cylinder, Hoop, Lumped, PointMass, RoundTube, SquareTube, TrapezoidalPrism
from ..models.plausibility import check_inertia

BODIES = ("rear_frame", "front_frame", "rear_wheel", "front_wheel")
"""The four rigid bodies of the benchmark model."""

SHAPES = {
    "cylinder": (Cylinder, ("diameter", "length")),
    "round_tube": (RoundTube, ("outer_diameter", "wall", "length")),
    "square_tube": (SquareTube, ("side", "wall", "length")),
    "box": (Box, ("size_x", "size_y", "size_z")),
    "trapezoidal_prism": (TrapezoidalPrism, ("depth", "width_top", "width_bottom", "length")),
    "hoop": (Hoop, ("inner_diameter", "outer_diameter", "thickness")),
    "point": (PointMass, ()),
}
"""``shape:`` name -> (solid class, its size keys in constructor order, m)."""

OPTIONAL_KEYS = ("body", "mass", "material", "axis", "angle", "mirror_y", "note")
INERTIA_KEYS = ("xx", "yy", "zz", "xy", "xz", "yz")


def read_inertia(node):
    """3x3 inertia tensor (kg m^2) from ``{xx, yy, zz, xy, xz, yz}`` (tensor elements, missing = 0)."""
    node.check_keys(required=("xx", "yy", "zz"), optional=("xy", "xz", "yz"))
    v = {k: node[k].number("inertia") if node.has(k) else 0.0 for k in INERTIA_KEYS}
    tensor = np.array([[v["xx"], v["xy"], v["xz"]], [v["xy"], v["yy"], v["yz"]], [v["xz"], v["yz"], v["zz"]]])
    return check_inertia(tensor, node)


def _solid(node, shape):
    cls, sizes = SHAPES[shape]
    node.check_keys(required=("name", "shape", "at") + sizes, optional=OPTIONAL_KEYS)
    values = [node[k].number("length", nonnegative=(k == "inner_diameter"), positive=(k != "inner_diameter"))
              for k in sizes]
    try:
        return cls(*values)
    except ValueError as exc:
        node.fail(str(exc), "wall" if "wall" in sizes else sizes[0])


def _rotation(node):
    if node.has("axis") and node.has("angle"):
        node.fail("either axis or angle, not both", "angle")
    if node.has("axis"):
        axis = node["axis"].vector("dimensionless")
        if np.linalg.norm(axis) == 0:
            node.fail("a non-zero direction", "axis")
        return Placement.along(np.zeros(3), axis).rotation
    if node.has("angle"):
        return thesis_segment_rotation(node["angle"].number("angle", unit="deg"))
    return np.eye(3)


COMPONENT_CACHE_SIZE = 1024
_COMPONENTS = OrderedDict()


def read_component(node, materials, default_body=None):
    """Parts (one, or two with ``mirror_y``) of one component mapping (a tuple; see the module
    docstring for the cache)."""
    key = (repr(node.value), node.source, node.key, default_body, tuple(materials.items()))
    parts = _COMPONENTS.get(key)
    if parts is None:
        parts = _COMPONENTS[key] = tuple(_read_component(node, materials, default_body))
        if len(_COMPONENTS) > COMPONENT_CACHE_SIZE:
            _COMPONENTS.popitem(last=False)
    return list(parts)


def _read_component(node, materials, default_body):
    shape = node["shape"].string(choices=tuple(SHAPES) + ("lumped",))
    name = node["name"].string()
    if not node.has("body") and default_body is None:
        node.fail("a required key that is missing", "body")
    body = node.get("body", default_body).string(choices=BODIES)
    rotation = _rotation(node)
    at = node["at"].vector("length")
    if shape == "lumped":
        node.check_keys(required=("name", "shape", "mass", "at", "inertia"),
                        optional=("body", "mirror_y", "note"))
        mass = node["mass"].number("mass", positive=True)
        solid = Lumped(MassProperties(mass, np.zeros(3), read_inertia(node["inertia"])))
        centroid = np.zeros(3)
    else:
        solid = _solid(node, shape)
        mass = _mass(node, solid, materials)
        centroid = solid.exact(1.0).com if solid.volume else np.zeros(3)
    mirrored = node.get("mirror_y", False).boolean()
    parts = []
    for side, suffix in ((1.0, ""), (-1.0, "_mirrored")) if mirrored else ((1.0, ""),):
        position = at * [1.0, side, 1.0]
        placement = Placement(rotation, position - rotation @ centroid)
        parts.append(Part(name + suffix, solid, mass, placement, body))
    return parts


def _mass(node, solid, materials):
    if node.has("mass") == node.has("material"):
        node.fail("exactly one of mass (kg) or material (a key of materials.yaml)", "mass")
    if node.has("mass"):
        return node["mass"].number("mass", positive=True)
    if solid.volume == 0:
        node.fail("a mass for a point mass (it has no volume)", "material")
    return materials_lookup(node["material"], materials).density * solid.volume


def materials_lookup(node, materials):
    """The :class:`~bikemass.mass.materials.Material` named by ``node`` (key or alias)."""
    key = node.string()
    if key not in materials:
        node.fail(f"a material of frames/materials.yaml ({', '.join(sorted(materials))}), got {key!r}")
    return materials[key]


def read_wheel(node, body, axle, radius, radius_key):
    """Parts of one wheel: ``hoops`` (name -> hoop sizes and mass, centred on the axle, axis y)
    or ``lumped`` ({mass, inertia: {xx, yy}}, Izz = Ixx).  The outermost hoop's outer radius
    must equal the wheel radius within 1 mm."""
    node.check_keys(optional=("hoops", "lumped", "note"))
    if node.has("hoops") == node.has("lumped"):
        node.fail("exactly one of hoops or lumped")
    if node.has("lumped"):
        lumped = node["lumped"]
        lumped.check_keys(required=("mass", "inertia"))
        inertia = lumped["inertia"]
        inertia.check_keys(required=("xx", "yy"))
        ixx, iyy = inertia["xx"].number("inertia", positive=True), inertia["yy"].number("inertia", positive=True)
        check_inertia(np.diag([ixx, iyy, ixx]), inertia, "yy")
        props = MassProperties(lumped["mass"].number("mass", positive=True), np.zeros(3), np.diag([ixx, iyy, ixx]))
        return [Part(body, Lumped(props), props.mass, Placement.at(axle), body)]
    placement = Placement.along(axle, [0.0, 1.0, 0.0])
    parts, outer = [], 0.0
    for name, hoop in node["hoops"].items():
        hoop.check_keys(required=("inner_diameter", "outer_diameter", "thickness", "mass"), optional=("note",))
        solid = _solid_hoop(hoop)
        outer = max(outer, solid.outer_radius)
        parts.append(Part(f"{body}_{name}", solid, hoop["mass"].number("mass", positive=True), placement, body))
    if abs(outer - radius) > 0.001:
        node.fail(f"hoops whose outer radius equals geometry.{radius_key} = {radius} m "
                  f"(the outermost is {outer:.4f} m)", "hoops")
    return parts


def _solid_hoop(node):
    inner = node["inner_diameter"].number("length", nonnegative=True)
    outer = node["outer_diameter"].number("length", positive=True)
    if inner >= outer:
        node.fail(f"an inner diameter below the outer diameter {outer} m", "inner_diameter")
    return Hoop(inner, outer, node["thickness"].number("length", positive=True))
