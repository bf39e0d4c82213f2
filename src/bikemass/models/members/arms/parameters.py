"""The ``arms`` member's parameters: the rider's hands on the grips, a torsional spring and a viscous damper
about the steer axis between the handlebars and the rider's upper body (:mod:`bikemass.models.derive.arms`).

An arms file (YAML, read through the input gate; each value SI or with its unit)::

    stiffness: 0 N m/rad          # k_arms, about the steer axis
    damping: 0 N m s/rad          # c_arms, about the steer axis
    forearms: pose                # or handlebars: the forearms' mass moves with the bars

**No published default.** When this member was written no measured value of a bicycle rider's arm
stiffness or damping about the steer axis could be read (the rider-identification and wobble papers
that report them, Doria & Tognazzo 2014, Cossalter et al. 2011, Plöchl et al. 2012, Klinger et al.
2014, were reachable only as abstracts), so the defaults are zero: the hands rest on the grips
without holding them, the model of the rider without arms.  :func:`as_arms` warns when it gives
them; give measured values (docs/models.md, "The rider's arms").
"""

import math
import os
from collections.abc import Mapping
from dataclasses import dataclass, field, fields

from ....core.config import Node, load_yaml
from ....core.errors import InputError
from ....core.gate import plain_input
from ...plausibility import warn

KEYS = ("stiffness", "damping")
"""An arms file's numbers (both optional, 0 when not given)."""
FOREARMS = ("pose", "handlebars")
"""Where the forearms' mass goes: where the rider's pose puts it, or on the handlebars (front frame)."""


@dataclass(frozen=True)
class Arms:
    """The rider's arms about the steer axis: the torque ``-(stiffness a + damping a')`` on the handlebars
    (the opposite on the upper body), ``a`` the handlebars' rotation relative to the upper body about
    the steer axis (rad).  Both 0: the rider without arms.  ``forearms``: ``"pose"`` (default) leaves
    the arms' mass where the rider's pose puts it; ``"handlebars"`` moves each forearm whose hand is on
    a grip to the front frame (:mod:`bikemass.rider.hands`; a scenario's seated rider only).

    Examples
    --------
    >>> from bikemass.models.members.arms.parameters import Arms
    >>> Arms(stiffness=10.0, damping=1.5).values()
    {'k_arms': 10.0, 'c_arms': 1.5}
    """

    stiffness: float = field(default=0.0, metadata={"unit": "N m/rad", "description": "arms' stiffness about the steer axis"})
    damping: float = field(default=0.0, metadata={"unit": "N m s/rad", "description": "arms' damping about the steer axis"})
    forearms: str = field(default="pose", metadata={"description": "where the forearms' mass goes: pose or handlebars"})

    def __post_init__(self):
        if self.forearms not in FOREARMS:
            raise InputError("arms", "forearms", f"one of {', '.join(FOREARMS)}, got {self.forearms!r}")
        for f in fields(self):
            if f.name not in KEYS:
                continue
            x = getattr(self, f.name)
            if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x) or x < 0:
                raise InputError("arms", f.name, f"a finite number >= 0 ({f.metadata['unit']}), got {x!r}")
            object.__setattr__(self, f.name, float(x))
        if self.stiffness > MAX_STIFFNESS:
            warn(f"arms: stiffness = {self.stiffness:.6g} N m/rad is above {MAX_STIFFNESS:g} N m/rad (a degree of steer "
                 f"against it takes {MAX_STIFFNESS * math.pi / 180:.0f} N m, more than a rider's arms give; the "
                 "steer nearly locked to the rider puts roots far apart, and the critical speeds may be lost); "
                 "computed as given")
        if self.damping > MAX_DAMPING:
            warn(f"arms: damping = {self.damping:.6g} N m s/rad is above {MAX_DAMPING:g} N m s/rad (a steer rate of "
                 f"1 rad/s against it takes {MAX_DAMPING:.0f} N m, more than a rider's arms give); computed as given")

    def values(self):
        """``{name: float}`` of the generated code's parameters (``k_arms``, ``c_arms``)."""
        return {"k_arms": self.stiffness, "c_arms": self.damping}

    def to_dict(self):
        """``{"stiffness": N m/rad, "damping": N m s/rad, "forearms": str}``: the ``arms:`` block of a
        parameter file."""
        return {"stiffness": self.stiffness, "damping": self.damping, "forearms": self.forearms}

    @staticmethod
    def units():
        """``{field: SI unit}``."""
        return {f.name: f.metadata["unit"] for f in fields(Arms) if "unit" in f.metadata}


MAX_STIFFNESS = 1e4
"""Arm stiffnesses (N m/rad) above this are warned about: 175 N m for one degree of steer, past a rider's
strength (no published value could be read: docs/models.md, The rider's arms)."""
MAX_DAMPING = 1e3
"""Arm damping (N m s/rad) above this is warned about: 1000 N m at a steer rate of 1 rad/s."""

NO_ARMS = Arms()
"""Zero stiffness and damping: the default, for want of a published measurement (module docstring)."""


def arms_from_node(node):
    """:class:`Arms` of a config :class:`~bikemass.core.config.Node` (``stiffness:``, ``damping:``,
    ``forearms:``)."""
    node.check_keys(optional=(*KEYS, "forearms", "source", "note"))
    forearms = {"forearms": node["forearms"].string(FOREARMS)} if node.has("forearms") else {}
    return Arms(**{k: node[k].number(k, nonnegative=True) for k in KEYS if node.has(k)}, **forearms)


def as_arms(given=None, source="arms"):
    """:class:`Arms` of ``given``: an :class:`Arms` as it is, an arms file (a path), a mapping in its form,
    or ``None`` for the default :data:`NO_ARMS` (warned: no published default);
    :class:`~bikemass.core.errors.InputError` otherwise."""
    if given is None:
        warn("arms: no stiffness or damping given, and no published default: the arms hold nothing (0 N m/rad, "
             "0 N m s/rad), the rider without arms; give measured values (--arms FILE, an arms: block)")
        return NO_ARMS
    if isinstance(given, Arms):
        return given
    if isinstance(given, Mapping):
        node = Node(plain_input(given, source), source, "")
        node.mapping()
        return arms_from_node(node)
    if isinstance(given, (str, os.PathLike)):
        return arms_from_node(load_yaml(os.fspath(given)))
    raise InputError(source, "(argument)", f"Arms, an arms YAML file or a mapping in its form, not {type(given).__name__}")
