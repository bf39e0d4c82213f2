"""The arms member's run-time protocol (:mod:`bikemass.models.members.spec`): how the family takes
its typed parameters."""

import warnings

from ....core.errors import BikemassWarning
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


HANDS_ON = 0.05
"""A hand this far (m) from a grip is on it, for the arms' stiffness and damping (the seating puts the
hands of a pose that holds the bars on the grips, 0 mm; a no-hands pose leaves them 0.66 m (the Jamis)
to 0.76 m (the Cargo) away)."""


def check_hands(typed, gap, rider_in_set=False):
    """Warn where the arms act through no hands on the bars: ``forearms: handlebars`` with no rider
    seated (``gap`` ``None``: nothing to move), a stiffness or damping with no rider at all (``gap``
    ``None`` and no rider in the parameter set either: no arms to hold the bars), or a stiffness or
    damping while the seated rider's hand furthest from a grip is ``gap`` m away (a no-hands pose)."""
    if gap is None:
        if typed.forearms == "handlebars":
            warnings.warn("arms: forearms: handlebars with no rider seated: there are no forearms to move (the "
                          "bicycle's parameter set is taken as it is; give a rider, --rider POSE)", BikemassWarning,
                          stacklevel=4)
        if not rider_in_set and (typed.stiffness or typed.damping):
            warnings.warn("arms: a stiffness or damping between the bars and the rider, but no rider rides (neither "
                          "seated nor in the parameter set): it acts between the bars and the rear frame; applied as "
                          "given (give a rider, --rider POSE)", BikemassWarning, stacklevel=4)
        return
    if (typed.stiffness or typed.damping) and gap > HANDS_ON:
        where = ("not known to be on a grip (the bicycle has no grips to reach)" if gap == float("inf")
                 else f"{gap * 1000:.0f} mm from the nearest grip (a no-hands pose)")
        warnings.warn(f"arms: a stiffness or damping between the rider and the bars, but a hand is {where}: applied "
                      "as given", BikemassWarning, stacklevel=4)


def forearms_held(typed):
    """Whether the rider's forearms move with the front frame (``forearms: handlebars``)."""
    return typed.forearms == "handlebars"


INPUTS = {"k_arms": "stiffness", "c_arms": "damping"}
"""The arms' stiffness (N m/rad) and damping (N m s/rad) as inputs of a scenario."""
