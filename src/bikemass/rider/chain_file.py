"""Chain-form pose files: a pose given by joint angles, solved on a bicycle when loaded.

::

    body: thesis_rider            # or {height: 1.80 m, mass: 75 kg, sex: male}, {yeadon: PATH}
    bike: jamis                   # optional: without it the pose is solved on the bicycle
    chain: {torso_lean: 30 deg, hands: hoods}   # it is used with (bikemass stability cargo --rider ...)

``chain`` keys: ``hands`` (a grip of the bicycle's ``contacts:``, a list of grips (the first
the bicycle has) or ``none``; default ``hoods`` if the bicycle has them, else its first
grip), ``crank`` (deg; default: legs symmetric, feet on the crank axis), ``feet`` (which point
of the lower leg goes there: ``ball``, default, or ``bicycleparameters`` for a yeadon body,
BicycleParameters' seating; docs/riders.md), ``front`` (the
segments that move with the front frame, e.g. ``[lower_arm]`` for hands holding the bars)
and any joint angle to fix (deg, see :data:`~bikemass.rider.chain.JOINTS`).  ``name`` is
optional.  The same keys form the ``posture:`` of a placement-form pose.  See docs/poses.md.
"""

import warnings
from pathlib import Path

from ..bicycle import Bicycle, load_bicycle
from ..core.errors import BikemassWarning, InputError, shown
from .body import chain_of, load_body
from .chain import CHAIN_SEGMENTS, FEET, JOINTS
from .fit import standover_clearance, standover_height
from .pose import angle_deg, pose_parts
from ..core.paths import within_reach

CHAIN_KEYS = ("hands", "crank", "front", "feet", *JOINTS)


def feet_body(chain, body):
    """``body`` (:class:`~bikemass.rider.chain.ChainBody`) with the ``feet:`` placement of the
    ``chain``/``posture`` node (default ``ball``; docs/riders.md); an error on the key for a
    placement the body has no point for."""
    if chain is None or not chain.has("feet"):
        return body
    placement = chain["feet"].string(FEET)
    try:
        return body.with_feet(placement)
    except KeyError:
        chain.fail(f"ball for this body ({placement} places a yeadon body: body: {{yeadon: FILE}}; other bodies' "
                   "lower legs end at the sole already)", "feet")


def default_hands(contacts):
    """``hoods`` if the bicycle has them, else its first grip, else ``none``."""
    if "hoods" in contacts.grips:
        return "hoods"
    return next(iter(contacts.grips), "none")


def bicycle_contacts(bike, node):
    """The bicycle ``bike`` (a Bicycle, or a name or file; a relative file is looked up next to
    the pose file first) with its ``contacts``; ``node`` is blamed if the bicycle has none."""
    if isinstance(bike, Bicycle):
        bicycle = bike
    else:
        here = Path(node.source).parent / bike
        try:
            bicycle = load_bicycle(str(here) if within_reach(here) and here.is_file() else bike)
        except InputError as exc:
            if exc.key not in ("(name)", "(file)") or exc.source not in (str(bike), str(here)):
                raise
            node.fail(f"{exc.expected} [{exc.source}]")
    if bicycle.contacts is None:
        node.fail(f"a bicycle with a contacts: section (saddle, bottom_bracket, crank_length, grips); "
                  f"{shown(bicycle.source)} has none")
    return bicycle


def _is_bicycle(value):
    return isinstance(value, Bicycle)


def _hands(node, contacts):
    """The grip named by ``node`` (a name, ``none`` or a list of names: the first the bicycle has)."""
    choices = (*contacts.grips, "none")
    if isinstance(node.value, list):
        names = [e.string() for e in node.elements()]
        found = [n for n in names if n in choices]
        if not found:
            node.fail(f"a grip of {shown(contacts.source)} ({', '.join(choices)}), got {', '.join(names)}")
        return found[0]
    if not isinstance(node.value, str) or node.value not in choices:
        node.fail(f"a grip of {shown(contacts.source)} ({', '.join(choices)}), got {node.value!r}")
    return node.value


def chain_settings(chain, contacts):
    """(hands, crank, fixed joint angles, front segments) of a ``chain:``/``posture:`` node."""
    chain.check_keys(optional=CHAIN_KEYS)
    hands = _hands(chain["hands"], contacts) if chain.has("hands") else default_hands(contacts)
    crank = angle_deg(chain["crank"]) if chain.has("crank") else None
    fixed = {k: angle_deg(chain[k]) for k in JOINTS if chain.has(k)}
    front = tuple(e.string(CHAIN_SEGMENTS) for e in chain["front"].elements()) if chain.has("front") else ()
    return hands, crank, fixed, front


def solve_chain(chain, body, bicycle):
    """:class:`~bikemass.rider.solve.Solution` of the ``chain``/``posture`` node for ``body``
    (:class:`~bikemass.rider.chain.ChainBody`) on ``bicycle``; an unreachable contact is an
    error naming the chain key and the bicycle key."""
    # lazy: rider.solve loads scipy.optimize (slower to import than numpy); only chain poses need it
    from .solve import solve_on_bicycle
    hands, crank, fixed, front = chain_settings(chain, bicycle.contacts)
    solution = solve_on_bicycle(feet_body(chain, body), bicycle.contacts, hands, crank, fixed)
    try:
        solution.check_reachable()
    except InputError as exc:
        key = "hands" if ".grips." in exc.key else "crank" if exc.key.endswith("crank_length") else None
        chain.fail(f"{exc.expected} [{exc.source}: {exc.key}]{_standover_note(bicycle, body)}", key)
    return solution, front


def _standover_note(bicycle, body):
    """``"; ... standover ..."`` where the top tube is also above the crotch of the rider standing
    astride the frame (a rider too small for the frame), else ``""``."""
    clearance = standover_clearance(bicycle, body.inseam)
    if clearance is None or clearance >= 0:
        return ""
    return (f"; the frame is too big for this rider: its top tube ({standover_height(bicycle) * 1000:.0f} mm) is "
            f"{-clearance * 1000:.0f} mm above the crotch of the rider standing astride it (standover)")


CHAIN_POSE_KEYS = ("body", "chain")
"""Keys a chain-form pose must have; ``name``, ``source`` and ``bike`` it may have."""


def check_chain_pose(node):
    """The display name of chain-form pose ``node`` once its keys and its body are checked (the
    chain itself is checked where it is solved, on a bicycle's contacts)."""
    node.check_keys(required=CHAIN_POSE_KEYS, optional=("name", "source", "bike"))
    chain_of(load_body(node["body"]), node["body"])
    return node.get("name", str(node.source)).string()


def read_chain_pose(node, bicycle=None):
    """(name, parts, Solution, bicycle) of a chain-form pose file, solved on ``bicycle``
    (default: the file's ``bike:``; one of the two is needed)."""
    node.check_keys(required=CHAIN_POSE_KEYS, optional=("name", "source", "bike"))
    body = load_body(node["body"])
    chain_body = chain_of(body, node["body"])
    if bicycle is None:
        if not node.has("bike"):
            node.fail("a bike: to solve the chain pose on, or a bicycle to use it with "
                      "(bikemass rider POSE --bike BIKE)", "bike")
        bike = node["bike"]
        bicycle = bicycle_contacts(bike.value if _is_bicycle(bike.value) else bike.string(), bike)
    solution, front = solve_chain(node["chain"], chain_body, bicycle)
    for line in solution.pose.warnings():
        warnings.warn(f"{node.source}: {line}", BikemassWarning, stacklevel=2)
    name = node.get("name", str(node.source)).string()
    return name, pose_parts(solution.pose, body.anthropometry, front, node.source), solution, bicycle
