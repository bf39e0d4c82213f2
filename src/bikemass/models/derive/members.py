"""The members of the model family that the derivation knows, in their canonical order.

``flexible`` (the rear frame's twist and the fork's lateral bending with their inertia) joins here:
a :class:`~bikemass.models.derive.bicycle.Member` whose ``head`` hook turns the steer axis's frame
by the frame's twist and whose ``axle`` hook turns the front axle's frame by the fork's bending,
with the bodies' masses shared as its reduction says.
"""

from .rider_lean import RiderLean
from .tyre import Tyre

MEMBERS = {"rider-lean": RiderLean, "tyre": Tyre}
"""Member name -> its :class:`~bikemass.models.derive.bicycle.Member` class, in canonical order."""

COMBINATIONS = ((), ("rider-lean",), ("tyre",), ("rider-lean", "tyre"))
"""The member combinations the package ships (``()`` is the Whipple bicycle)."""


def members(names):
    """New member objects for ``names`` (canonical order)."""
    return [MEMBERS[n]() for n in MEMBERS if n in names]
