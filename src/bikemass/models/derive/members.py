"""The members of the model family that the derivation knows, in their canonical order."""

from .flexible import Flexible
from .rider_lean import RiderLean
from .tyre import Tyre

MEMBERS = {"rider-lean": RiderLean, "tyre": Tyre, "flexible": Flexible}
"""Member name -> its :class:`~bikemass.models.derive.bicycle.Member` class, in canonical order."""

COMBINATIONS = ((), ("rider-lean",), ("tyre",), ("rider-lean", "tyre"), ("flexible",), ("rider-lean", "flexible"),
                ("tyre", "flexible"), ("rider-lean", "tyre", "flexible"))
"""The member combinations the package ships (``()`` is the Whipple bicycle)."""


def members(names):
    """New member objects for ``names`` (canonical order)."""
    return [MEMBERS[n]() for n in MEMBERS if n in names]
