"""The rider's forearms with the hands on the grips: moved from the rear frame to the front frame.

The ``arms`` member's option ``forearms: handlebars`` (:class:`~bikemass.models.members.arms.parameters.Arms`) lumps each
forearm (``lower_arm_*``, hand included) with the handlebars, the body its hand holds, and leaves the
upper arms with the torso: the thesis's lumped arms (Williams 2015, Sec. 6.2), an approximation of the
linkage between shoulders and grips (Moore 2012 and Schwab et al. 2012 model that linkage's inertia in
full).  A forearm moves only if its hand is on a grip: its far end within
:data:`~bikemass.rider.seating.CONTACT_TOLERANCE` of one of the bicycle's grips (in x and z; the
seating's own test of a hand on a grip).
"""

import dataclasses

import numpy as np

from ..core.errors import InputError
from . import Rider
from .lean_split import kind
from .seating import CONTACT_TOLERANCE

FOREARM = "lower_arm"
"""The segment kind that the hands end."""


def hand_gaps(rider, grips):
    """``{part name: (gap m, grip name)}``: each forearm's far end (its solid's length along the part's
    z axis) to the nearest of ``grips`` (``{name: [x, y, z]}``, m), in x and z; ``(inf, None)`` where
    that end is not known."""
    out = {}
    for p in rider.parts:
        if kind(p.name) != FOREARM:
            continue
        length = getattr(p.solid, "length", None)          # a segment along its z axis (the chain's solids)
        if length is None:
            out[p.name] = (float("inf"), None)
            continue
        end = p.placement.translation + length * (p.placement.rotation @ [0.0, 0.0, 1.0])
        gaps = {g: float(np.hypot(end[0] - xyz[0], end[2] - xyz[2])) for g, xyz in grips.items()}
        name = min(gaps, key=gaps.get) if gaps else None
        out[p.name] = (gaps[name] if gaps else float("inf"), name)
    return out


def forearms_on_handlebars(rider, bicycle, tolerance=CONTACT_TOLERANCE):
    """``rider`` (:class:`~bikemass.rider.Rider`, seated on ``bicycle``) with its forearms on the front
    frame; :class:`~bikemass.core.errors.InputError` if a hand is not on a grip (a no-hands pose) or the
    rider has no forearms.

    Examples
    --------
    >>> import bikemass as bm
    >>> from bikemass.rider.hands import forearms_on_handlebars
    >>> bike = bm.load_bicycle("jamis")
    >>> held = forearms_on_handlebars(bm.seated_rider(bike, "relaxed"), bike)
    >>> sorted(p.name for p in held.parts if p.body == "front_frame")
    ['lower_arm_left', 'lower_arm_right']
    """
    gaps = hand_gaps(rider, dict(bicycle.contacts.grips))
    if not gaps:
        raise InputError(rider.pose, "segments", f"forearms (lower_arm) to put on the handlebars; rider "
                         f"{rider.name!r} has none")
    off = {n: g for n, g in gaps.items() if not g[0] <= tolerance}
    if off:
        name, (gap, grip) = next(iter(off.items()))
        where = (f"{gap * 1000:.1f} mm from the nearest grip ({grip})" if grip else
                 "not known to be on a grip (no grips on the bicycle, or a forearm solid without a length)")
        raise InputError(rider.pose, "arms.forearms", f"hands on the grips for forearms: handlebars: {name}'s hand "
                         f"is {where} (a no-hands rider has no arms on the bars: forearms: pose)")
    parts = tuple(dataclasses.replace(p, body="front_frame") if p.name in gaps else p for p in rider.parts)
    return Rider(rider.pose, rider.name, parts, rider.spec)
