"""The members of the model family that the derivation knows, in their canonical order."""

from ..members.arms.derivation import Arms
from ..members.flexible.derivation import Flexible
from ..members.rider_lean.derivation import RiderLean
from ..members.tyre.derivation import Tyre

MEMBERS = {"rider-lean": RiderLean, "tyre": Tyre, "flexible": Flexible, "arms": Arms}
"""Member name -> its :class:`~bikemass.models.derive.bicycle.Member` class, in canonical order."""

_WITHOUT_ARMS = ((), ("rider-lean",), ("tyre",), ("rider-lean", "tyre"), ("flexible",), ("rider-lean", "flexible"),
                 ("tyre", "flexible"), ("rider-lean", "tyre", "flexible"))
COMBINATIONS = (*_WITHOUT_ARMS, *((*c, "arms") for c in _WITHOUT_ARMS))
"""The member combinations the package ships (``()`` is the Whipple bicycle)."""


def members(names):
    """New member objects for ``names`` (canonical order)."""
    return [MEMBERS[n]() for n in MEMBERS if n in names]
