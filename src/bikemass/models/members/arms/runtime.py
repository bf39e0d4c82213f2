"""The arms member's run-time protocol (:mod:`bikemass.models.members.spec`): how the family takes
its typed parameters."""

from .parameters import Arms, as_arms, arms_from_node


def coerce(given, source="arms"):
    """:func:`as_arms`: no stiffness or damping (warned) without ``given``."""
    return as_arms(given, source)


def values(typed, base):
    """The generated code's arm parameters (:meth:`Arms.values`)."""
    return typed.values()


def read_block(node):
    """The ``arms:`` block of a parameter file (:func:`arms_from_node`)."""
    return arms_from_node(node)


def write_block(typed):
    """The ``arms:`` block of a parameter file (:meth:`Arms.to_dict`)."""
    return typed.to_dict()


def units():
    """Units of the ``arms:`` block's plain values."""
    return Arms.units()


def forearms_held(typed):
    """Whether the rider's forearms move with the front frame (``forearms: handlebars``)."""
    return typed.forearms == "handlebars"
