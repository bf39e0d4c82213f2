"""The flexible member's run-time protocol (:mod:`bikemass.models.members.spec`): how the family takes
its typed parameters."""

from ...compliance import Compliance
from ....core.errors import InputError
from .parameters import Compliances, compliances_from_node


def coerce(given, source="compliances"):
    """``given`` when it is :class:`Compliances`; InputError otherwise (they come from the beam models)."""
    if isinstance(given, Compliances):
        return given
    raise InputError(source, "flexible", "the flexible model needs the frame's and the fork's compliances "
                     "(Compliances: bikemass.fe.flexible.compliances(bicycle, material), or a Scenario with a "
                     "material as its stiffness)")


def values(typed, base):
    """The generated code's compliance parameters (:meth:`Compliances.values` on the set so far)."""
    return typed.values(base)


def held(typed):
    """The infinitely stiff coordinates (:attr:`Compliances.held`)."""
    return typed.held


def read_block(node):
    """The ``flexible:`` block of a parameter file (:func:`compliances_from_node`)."""
    return compliances_from_node(node)


def write_block(typed):
    """The ``flexible:`` block of a parameter file (:meth:`Compliances.to_dict`)."""
    return typed.to_dict()


def units():
    """Units of the ``flexible:`` block's plain values."""
    return {k: u for k, u in Compliance.units().items() if u}


INPUTS = {"cs": "steer_damping", "kr": "frame.stiffness", "kf": "fork.stiffness"}
"""The steering bearing's damping (N m s/rad) and the frame's and the fork's torsional stiffnesses (N m/rad)
as inputs of a scenario (the axes, the modal inertias and the damping ratios follow the beam models)."""
