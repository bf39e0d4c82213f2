"""A rider on a bicycle: the pose seated on the bicycle's ``contacts:`` and its contacts checked.

``seat_rider(pose, bicycle)`` gives a :class:`SeatedRider`:

* a chain pose without ``bike:`` is solved on ``bicycle`` (hips on the saddle, hands on
  the grip, feet on the pedals); with ``bike:`` it is solved on that bicycle and checked on
  this one;
* a placement pose is used as written where its contacts are within
  :data:`CONTACT_TOLERANCE` of the bicycle's; otherwise, if it carries a ``posture:`` (the
  shipped thesis poses do), the posture is re-solved on this bicycle;
* anything else off the bicycle by more than the tolerance is an :class:`InputError`
  naming the contact and the gap, unless ``allow_off_contact=True`` (the thesis's way: its
  riders sit where it printed them, off the bicycles' bars and pedals), which keeps the
  pose as written and reports each gap as a warning line;
* a rider of lumped bodies only (``relaxed-thesis``) has no contacts: used, with a warning;
* a seated rider's fit is checked as a fitter would (:mod:`bikemass.rider.fit`): too much seat
  post showing, a saddle that cannot go low enough, locked or cramped elbows, toe overlap,
  each a warning.

Contacts are measured on the placed segments (m, in the x-z plane): ``hips`` = the
sit point (thigh tops' midpoint lowered by the body's seat depth) against the saddle;
``right hand``/``left hand`` = the lower arms' far ends against the posture's grip (without
a posture: against the nearest grip when the lower arms move with the front frame, else
free); ``right foot``/``left foot`` = the lower legs' far ends against the crank axis or
the pedal circle, whichever is nearer.
"""

import os
from collections.abc import Mapping
from dataclasses import dataclass, replace

import numpy as np

from ..core.config import Node, load_yaml
from ..core.errors import InputError, shown, wrong_type
from ..core.gate import MAPPING, plain_input
from ..core.paths import resolve
from . import Rider, poses_dir
from .body import load_body
from .chain_file import bicycle_contacts, chain_settings, feet_body, read_chain_pose, solve_chain
from .pose import is_lumped, pose_parts, read_pose
from .fit import fit_warnings

CONTACT_TOLERANCE = 1e-3
"""A contact further than this (m) from its target is off the bicycle."""


@dataclass(frozen=True, eq=False)
class SeatedRider:
    """``rider`` (:class:`~bikemass.rider.Rider`) on ``bicycle``: ``how`` it was placed
    (``as written``, ``solved``, ``unchecked``), measured ``contacts`` ``{name: (residual m,
    bicycle key)}``, the chain ``solution`` if solved, and ``warnings`` (lines)."""

    rider: Rider
    bicycle: object
    how: str
    contacts: dict
    solution: object
    warnings: tuple

    def residuals(self):
        """``{contact: residual (m)}``."""
        return {k: v[0] for k, v in self.contacts.items()}


def _xz(v):
    return np.asarray(v, dtype=float)[[0, 2]]


def _ends(parts, segment, length):
    """{side: (top, far end)} of a placed chain segment (parts ``<segment>_<side>`` or ``<segment>``)."""
    out = {}
    for p in parts:
        side = p.name[len(segment) + 1:] if p.name.startswith(segment + "_") else "" if p.name == segment else None
        if side is None or side not in ("", "right", "left"):
            continue
        top = p.placement.translation
        out[side or "right"] = (top, top + length * (p.placement.rotation @ [0.0, 0.0, 1.0]))
    return out


def measure_contacts(parts, chain, contacts, hands=None):
    """``{contact: (residual m, bicycle key)}`` of placed ``parts`` of a body with joints
    ``chain`` on ``contacts``; ``hands``: the grip name, ``"none"`` or None (see module doc)."""
    key, L = contacts.key, chain.lengths
    found = {}
    thighs = _ends(parts, "thigh", L["thigh"])
    if thighs:
        hip = np.mean([_xz(top) for top, _ in thighs.values()], axis=0) + [0.0, chain.seat]
        found["hips"] = (float(np.linalg.norm(hip - _xz(contacts.sit_point(chain.inseam)))), f"{key}.saddle")
    bb = _xz(contacts.bottom_bracket)
    for side, (_, foot) in sorted(_ends(parts, "lower_leg", L["lower_leg"]).items(), reverse=True):
        d = float(np.linalg.norm(_xz(foot) - bb))
        found[f"{side} foot"] = (min(d, abs(d - contacts.crank_length)), f"{key}.bottom_bracket")
    arms = [p for p in parts if p.name.startswith("lower_arm")]
    if hands is None and arms and all(p.body == "front_frame" for p in arms) and contacts.grips:
        hands = "nearest"
    if hands not in (None, "none"):
        for side, (_, hand) in sorted(_ends(parts, "lower_arm", L["lower_arm"]).items(), reverse=True):
            grips = contacts.grips if hands == "nearest" else {hands: contacts.grips[hands]}
            name, d = min(((g, float(np.linalg.norm(_xz(hand) - _xz(p)))) for g, p in grips.items()),
                          key=lambda gd: gd[1])
            found[f"{side} hand"] = (d, f"{key}.grips.{name}")
    return found


def _off(contacts, tolerance):
    return {k: v for k, v in contacts.items() if v[0] > tolerance}


def _gap_lines(pose, bicycle, off):
    return [f"{pose}: {name} {gap * 1000:.1f} mm from {shown(bicycle.source)}: {key}"
            for name, (gap, key) in off.items()]


def seat_rider(pose, bicycle, as_printed=False, allow_off_contact=False, tolerance=CONTACT_TOLERANCE):
    """:class:`SeatedRider`: ``pose`` (shipped name, pose file, a mapping in any pose form, the
    :class:`~bikemass.core.config.Node` of a pose document (errors name its source), or a
    :class:`~bikemass.rider.Rider`) on ``bicycle``; see the module doc.

    Bad input, an unreachable contact or a contact off by more than ``tolerance`` (m) without
    ``allow_off_contact`` raise :class:`InputError`."""
    if isinstance(pose, Rider) and pose.spec is None:
        return SeatedRider(pose, bicycle, "unchecked", {}, None,
                           (f"{pose.name}: contacts with {bicycle.name} not checked (a Rider built "
                            "from parts carries no body to seat; pass its pose instead)",))
    if isinstance(pose, Rider):
        (frozen, as_printed), source, pose = pose.spec, pose.spec[0].source, pose.pose
        node = frozen.thaw()
    elif isinstance(pose, Node):
        node, source = pose, pose.source
        pose = node.value.get("name", str(source)) if isinstance(node.value, dict) else str(source)
    elif isinstance(pose, Mapping):
        source, node = MAPPING, Node(plain_input(pose, MAPPING), MAPPING, "")
        pose = node.value.get("name", MAPPING) if isinstance(node.value, dict) else MAPPING
    else:
        if not isinstance(pose, (str, os.PathLike)):
            raise wrong_type("rider", pose, "a rider is a pose name, a file path, a mapping, a Rider or None")
        source = resolve(os.fspath(pose), poses_dir(), "pose")
        node = load_yaml(source)
    contacts = bicycle.contacts
    if not isinstance(node.value, dict):
        node.fail("a pose (a mapping with segments: or chain:)")
    lumped_only = "chain" not in node.value and "body" not in node.value
    if contacts is None and "chain" in node.value and not node.has("bike"):
        bicycle_contacts(bicycle, node["chain"])      # the error: a bicycle with a contacts: section
    if contacts is None or lumped_only:
        rider = _load(pose, node, as_printed)
        why = (f"{shown(bicycle.source)} has no contacts: section" if contacts is None
               else "a rider of lumped bodies has no contact points")
        return SeatedRider(rider, bicycle, "unchecked", {}, None,
                           (f"{pose}: contacts with {bicycle.name} not checked ({why})",))
    if "chain" in node.value:
        own = node.has("bike")
        name, parts, solution, solved_on = read_chain_pose(node, None if own else bicycle)
        chain = feet_body(node["chain"], load_body(node["body"]).chain)
        hands = chain_settings(node["chain"], solved_on.contacts)[0]
        rider = Rider(str(pose), name, parts)
        return _checked(pose, rider, bicycle, chain, hands, "solved", solution, allow_off_contact, tolerance,
                        node["bike"] if own else node["chain"])
    body = load_body(node["body"])
    rider = _load(pose, node, as_printed)
    if body.chain is None:
        return SeatedRider(rider, bicycle, "unchecked", {}, None,
                           (f"{pose}: contacts with {bicycle.name} not checked (its body has no joints:)",))
    posture = node["posture"] if node.has("posture") else None
    hands = None
    if posture is not None:
        try:
            hands = chain_settings(posture, contacts)[0]
        except InputError:
            if not allow_off_contact:
                raise
            hands = "nearest"          # the posture's grip is missing here: the nearest one counts
    chain = feet_body(posture, body.chain)
    measured = measure_contacts(rider.parts, chain, contacts, hands)
    if _off(measured, tolerance) and posture is not None and not allow_off_contact:
        solution, front = solve_chain(posture, body.chain, bicycle)
        front = front or tuple(s for s, seg in node["segments"].items()
                               if isinstance(seg.value, dict) and seg.value.get("frame") == "front")
        name = node.get("name", str(source)).string()
        # a lumped body (mass, com, inertia: a load given in the bicycle's frame) is no segment of the chain:
        # kept where the file puts it, and said so (re-seating moves the body's segments alone)
        lumped_keys = {key for key, seg in node["segments"].items() if is_lumped(seg.value)}
        lumped = [p for p in rider.parts if p.name in lumped_keys]
        rider = Rider(str(pose), name, pose_parts(solution.pose, body.anthropometry, front, source) + tuple(lumped))
        seated = _checked(pose, rider, bicycle, chain, hands, "solved", solution, False, tolerance, posture)
        if lumped:
            kept = ", ".join(f"{p.name} ({p.mass:g} kg)" for p in lumped)
            seated = replace(seated, warnings=seated.warnings + (
                f"{pose}: re-seated on {bicycle.name} by its posture: the lumped {kept} kept where the file "
                f"puts {'it' if len(lumped) == 1 else 'them'} (only the body's segments move)",))
        return seated
    return _checked(pose, rider, bicycle, chain, hands, "as written", None, allow_off_contact, tolerance,
                    node)


def _load(pose, node, as_printed):
    """The rider of a pose node as written (a chain pose solved on its own ``bike:``)."""
    if "chain" in node.value:
        name, parts, _, _ = read_chain_pose(node)
    else:
        name, parts = read_pose(node, as_printed)
    return Rider(str(pose), name, parts)


def _checked(pose, rider, bicycle, chain, hands, how, solution, allow, tolerance, blame):
    measured = measure_contacts(rider.parts, chain, bicycle.contacts, hands)
    off = _off(measured, tolerance)
    if off and not allow:
        name, (gap, key) = max(off.items(), key=lambda kv: kv[1][0])
        raise InputError(blame.source, blame.key or "(top)",
                         f"a rider within {tolerance * 1000:g} mm of {bicycle.name}'s contacts: {name} is "
                         f"{gap * 1000:.1f} mm from {key} (--allow-off-contact uses the pose as written)")
    lines = tuple(line + " (allowed: off contact)" for line in _gap_lines(pose, bicycle, off))
    lines += tuple(fit_warnings(bicycle, chain, solution, rider.name, hands))
    return SeatedRider(rider, bicycle, how, measured, solution, lines)
