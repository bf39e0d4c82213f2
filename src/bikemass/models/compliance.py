"""A compliance of the bicycle reduced to one coordinate: a small rotation ``theta`` about a line in the
plane of symmetry, its stiffness and the inertia of the tubes that deform with it (docs/models-flexible.md).

The value only (numpy, no scipy: the model family imports it); the beam models that make it are
:mod:`bikemass.fe.twist` (the rear frame) and :mod:`bikemass.fe.fork`.
"""

import warnings
from dataclasses import dataclass, field, fields, replace

import numpy as np

from ..core.errors import BikemassWarning, InputError
from .plausibility import STIFFNESS_RANGE, warn

DAMPING_RATIO = 0.0
"""Default structural damping ratio of a frame or fork compliance: none, since no published measurement
of a bicycle frame's or fork's damping ratio was at hand (docs/models-flexible.md, "Damping"); give a
measured one as ``damping_ratio``."""

_DIMENSIONS = {"point": "length", "load_point": "length", "stiffness": "stiffness"}
"""The fields read with a unit (others are plain numbers in the SI unit of :meth:`Compliance.units`)."""

@dataclass(frozen=True)
class Compliance:
    """One compliance as a rotation ``theta`` about a line in the plane of symmetry (benchmark frame,
    reference configuration), with its stiffness and the modal inertia of the tubes that deform.

    Every field's unit and meaning are in its metadata (:meth:`units`); :meth:`scaled` and
    :meth:`massless` give stiffer or softer compliances and the limit of tubes without inertia.
    """

    name: str = field(metadata={"unit": "", "description": "which compliance"})
    point: tuple = field(metadata={"unit": "m", "description": "(x, z) of a point of the axis"})
    direction: tuple = field(metadata={"unit": "1", "description": "(x, z) of the axis' unit direction; "
                                                                   "theta turns right-handed about it"})
    stiffness: float = field(metadata={"unit": "N m/rad", "description": "torsional stiffness about the axis"})
    modal_momentum: float = field(metadata={"unit": "kg m/rad", "description": (
        "L: lateral (y) momentum of the deforming tubes per unit theta rate")})
    modal_moment: tuple = field(metadata={"unit": "kg m^2/rad", "description": (
        "(Jx, Jz): the moment of that momentum about the benchmark origin")})
    modal_mass: float = field(metadata={"unit": "kg m^2/rad^2", "description": (
        "m: the deforming tubes' kinetic energy is m theta'**2 / 2 (relative to the parent)")})
    load_point: tuple = field(default=None, metadata={"unit": "m", "description": (
        "(x, z) of the design load's (unit lateral force's) point on the steer axis")})
    damping_ratio: float = field(default=DAMPING_RATIO, metadata={"unit": "1", "description": (
        "structural damping as the damping ratio of the compliance's own vibration (docs/models-flexible.md)")})

    def __post_init__(self):
        for name in ("point", "direction", "modal_moment", "load_point"):
            value = getattr(self, name)
            if value is not None:
                object.__setattr__(self, name, tuple(float(x) for x in value))
        for name in ("stiffness", "modal_momentum", "modal_mass", "damping_ratio"):
            object.__setattr__(self, name, float(getattr(self, name)))
        values = (*self.point, *self.direction, self.stiffness, self.modal_momentum, *self.modal_moment,
                  self.modal_mass, self.damping_ratio)
        if not np.all(np.isfinite(values)):
            raise InputError(f"compliance {self.name}", "(values)", f"finite numbers, got {values}")
        if not np.isclose(np.hypot(*self.direction), 1.0, atol=1e-9):
            raise InputError(f"compliance {self.name}", "direction", f"a unit vector (x, z), got {self.direction}")
        if not self.stiffness > 0:
            raise InputError(f"compliance {self.name}", "stiffness", f"a positive number (N m/rad), got {self.stiffness}")
        if not 0 <= self.damping_ratio < 1:
            raise InputError(f"compliance {self.name}", "damping_ratio",
                             f"a number in [0, 1) (an underdamped structure), got {self.damping_ratio}")
        if self.modal_mass < 0:
            raise InputError(f"compliance {self.name}", "modal_mass", f"a number >= 0 (kg m^2/rad^2), got {self.modal_mass}")
        _warn_stiffness(self.stiffness, f"compliance {self.name}: stiffness =")
        L, (Jx, Jz), m = self.modal_momentum, self.modal_moment, self.modal_mass
        if (L == 0) != (m == 0) or (L == 0 and (Jx != 0 or Jz != 0)):
            key = "modal_mass" if L != 0 and m == 0 else "modal_momentum"     # the field that is missing
            raise InputError(f"compliance {self.name}", key, "a nonzero lateral momentum and modal "
                             "mass together, or none of L, J and m (a field is carried by one particle)")

    @classmethod
    def units(cls):
        """``{field: SI unit}`` of every field (``"1"`` dimensionless, ``""`` not a quantity)."""
        return {f.name: f.metadata["unit"] for f in fields(cls)}

    def scaled(self, stiffness=1.0, inertia=1.0):
        """The same axis with the stiffness and the modal inertia (L, J, m) multiplied by factors."""
        return replace(self, stiffness=self.stiffness * stiffness, modal_momentum=self.modal_momentum * inertia,
                       modal_moment=tuple(inertia * j for j in self.modal_moment),
                       modal_mass=self.modal_mass * inertia)

    def massless(self):
        """The limit of tubes without inertia (the parts that ride on the compliance keep theirs)."""
        return self.scaled(inertia=0.0)

    def to_dict(self):
        """Plain values (SI; the units: :meth:`units`)."""
        return {f.name: (list(v) if isinstance(v := getattr(self, f.name), tuple) else v) for f in fields(self)}


def compliance_from_node(node):
    """A :class:`Compliance` of a config :class:`~bikemass.core.config.Node` holding its fields
    (:meth:`Compliance.to_dict`'s form; ``stiffness`` may carry a unit: ``"1.2e4 N m/rad"``,
    ``"210 N m/deg"``)."""
    names = [f.name for f in fields(Compliance)]
    optional = ("load_point", "damping_ratio")
    node.check_keys(required=[n for n in names if n not in optional], optional=(*optional, "note"))

    def number(child, name):
        return child.number(_DIMENSIONS.get(name, "dimensionless"))

    values = {}
    for name in names:
        child = node.get(name)
        if name == "stiffness" and isinstance(child.value, dict):
            continue                                       # a measurement: needs the axis, read below
        if name == "name":
            values[name] = child.string()
        elif name == "damping_ratio" and child.missing:
            continue                                       # the default (Compliance.damping_ratio)
        elif child.missing:
            values[name] = None
        elif isinstance(child.value, list):
            values[name] = tuple(number(e, name) for e in child.elements())
            if len(values[name]) != 2:
                child.fail("a pair (x, z)")
        else:
            values[name] = number(child, name)
    stiffness = node["stiffness"]
    if isinstance(stiffness.value, dict):
        values["stiffness"] = measured_stiffness(stiffness, values["point"], values["direction"])
    try:
        with warnings.catch_warnings():                     # its range said below, naming the file and the key
            warnings.simplefilter("ignore", BikemassWarning)
            found = Compliance(**values)
    except InputError as exc:                              # the file and the key, not the axis's name alone
        node.fail(exc.expected, None if exc.key == "(values)" else exc.key)
    _warn_stiffness(found.stiffness, f"{node.source}: {node.key + '.' if node.key else ''}stiffness:")
    return found


def _warn_stiffness(stiffness, what):
    """Warn, as ``what`` says where, of a compliance ``stiffness`` (N m/rad) outside :data:`STIFFNESS_RANGE`."""
    if not STIFFNESS_RANGE[0] <= stiffness <= STIFFNESS_RANGE[1]:
        warn(f"{what} {stiffness:.6g} N m/rad is outside {STIFFNESS_RANGE[0]:g}..{STIFFNESS_RANGE[1]:g} N m/rad "
             "(measured frames and forks: 1e3..1e5); computed as given")


def _distance(at, point, direction):
    """Distance (m) of ``at`` (x, z) from the axis through ``point`` along the unit ``direction``."""
    dx, dz = at[0] - point[0], at[1] - point[1]
    return abs(dx * direction[1] - dz * direction[0])


def measured_stiffness(node, point, direction):
    """The torsional stiffness (N m/rad) about the axis (``point``, unit ``direction``, x-z plane) of a
    bench test's measurement (a config :class:`~bikemass.core.config.Node`):

    * ``{lateral: "120 N/mm", at: [x, z]}``: a lateral force at ``at`` over the lateral deflection
      there (a fork's lateral stiffness at the axle); the force's moment about the axis is ``F d``
      and the deflection ``theta d`` (``d`` the distance of ``at`` from the axis), so ``k = K d**2``;
    * ``{torsional: "95 N m/deg", load: [x, z], gauge: [x, z], lever: m, gauge_arm: m}``: a
      torque over a rotation as a test reports them (a steering-head stiffness): the torque the
      test states is ``F lever`` for a lateral force ``F`` at ``load``, the rotation it states the
      deflection at ``gauge`` over ``gauge_arm``; about this axis the force's moment is ``F d_load``
      and the deflection ``theta d_gauge``, so ``k = K d_load d_gauge / (lever gauge_arm)``.
      ``lever`` and ``gauge_arm`` default to ``d_load`` and ``d_gauge`` (the test's arms measured
      from this axis), and without ``load`` and ``gauge`` the torque and the rotation are taken
      about the axis itself: ``k = K``.
    """
    if node.has("lateral"):
        node.check_keys(required=("lateral", "at"), optional=("note", "source"))
        K = node["lateral"].number("linear stiffness", positive=True)
        d = _distance(node["at"].vector("length", 2), point, direction)
        if not d > 0:
            node.fail("a point off the compliance's axis (its lateral stiffness there is a torsional one)", "at")
        return K * d * d
    node.check_keys(required=("torsional",), optional=("load", "gauge", "lever", "gauge_arm", "note", "source"))
    K = node["torsional"].number("stiffness", positive=True)
    if node.has("load") != node.has("gauge"):
        node.fail("both load: and gauge: (the test's points), or neither (torque and rotation about the axis)")
    if not node.has("load"):
        return K
    arms = []
    for where, arm in (("load", "lever"), ("gauge", "gauge_arm")):
        d = _distance(node[where].vector("length", 2), point, direction)
        if not d > 0:
            node.fail("a point off the compliance's axis", where)
        arms.append((d, node[arm].number("length", positive=True) if node.has(arm) else d))
    (d_load, lever), (d_gauge, gauge_arm) = arms
    return K * d_load * d_gauge / (lever * gauge_arm)
