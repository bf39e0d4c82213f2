"""A compliance of the bicycle reduced to one coordinate: a small rotation ``theta`` about a line in the
plane of symmetry, its stiffness and the inertia of the tubes that deform with it (docs/models-flexible.md).

The value only (numpy, no scipy: the model family imports it); the beam models that make it are
:mod:`bikemass.fe.twist` (the rear frame) and :mod:`bikemass.fe.fork`.
"""

from dataclasses import dataclass, field, fields, replace

import numpy as np

from ..core.errors import InputError

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

    def __post_init__(self):
        for name in ("point", "direction", "modal_moment", "load_point"):
            value = getattr(self, name)
            if value is not None:
                object.__setattr__(self, name, tuple(float(x) for x in value))
        for name in ("stiffness", "modal_momentum", "modal_mass"):
            object.__setattr__(self, name, float(getattr(self, name)))
        values = (*self.point, *self.direction, self.stiffness, self.modal_momentum, *self.modal_moment,
                  self.modal_mass)
        if not np.all(np.isfinite(values)):
            raise InputError(f"compliance {self.name}", "(values)", f"finite numbers, got {values}")
        if not np.isclose(np.hypot(*self.direction), 1.0, atol=1e-9):
            raise InputError(f"compliance {self.name}", "direction", f"a unit vector (x, z), got {self.direction}")
        if not self.stiffness > 0:
            raise InputError(f"compliance {self.name}", "stiffness", f"a positive number (N m/rad), got {self.stiffness}")
        if self.modal_mass < 0:
            raise InputError(f"compliance {self.name}", "modal_mass", f"a number >= 0 (kg m^2/rad^2), got {self.modal_mass}")

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
    node.check_keys(required=[n for n in names if n != "load_point"], optional=("load_point", "note"))

    def number(child, name):
        return child.number(_DIMENSIONS.get(name, "dimensionless"))

    values = {}
    for name in names:
        child = node.get(name)
        if name == "name":
            values[name] = child.string()
        elif child.missing:
            values[name] = None
        elif isinstance(child.value, list):
            values[name] = tuple(number(e, name) for e in child.elements())
            if len(values[name]) != 2:
                child.fail("a pair (x, z)")
        else:
            values[name] = number(child, name)
    return Compliance(**values)
