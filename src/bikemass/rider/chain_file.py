"""Chain-form pose files: a pose given by joint angles and a bicycle, solved on load.

::

    body: thesis_rider
    bike: jamis
    chain: {torso_lean: 30, hands: hoods}

``chain`` keys: ``hands`` (a grip of the bicycle's ``contacts:`` or ``none``; default
``hoods`` if the bicycle has them, else its first grip), ``crank`` (deg; default: legs
symmetric, feet on the crank axis) and any joint angle to fix (deg, see
:data:`~bikemass.rider.chain.JOINTS`).  ``name`` is optional.  See docs/poses.md.
"""

import warnings
from pathlib import Path

from ..config import Node
from ..errors import BikemassWarning, InputError
from .anthropometry import find_anthropometry
from .chain import JOINTS, load_chain_body
from .pose import angle_deg, read_pose

CHAIN_KEYS = ("hands", "crank", *JOINTS)


def default_hands(contacts):
    """``hoods`` if the bicycle has them, else its first grip, else ``none``."""
    if "hoods" in contacts.grips:
        return "hoods"
    return next(iter(contacts.grips), "none")


def bicycle_contacts(bike, node):
    """The ``contacts`` of bicycle ``bike`` (name or file; a relative file is looked up next
    to the pose file first); ``node`` is blamed if the bicycle has none."""
    from ..bicycle import Bicycle, load_bicycle
    if isinstance(bike, Bicycle):
        bicycle = bike
    else:
        here = Path(node.source).parent / bike
        bicycle = load_bicycle(str(here) if here.is_file() else bike)
    if bicycle.contacts is None:
        node.fail(f"a bicycle with a contacts: section (saddle, bottom_bracket, crank_length, grips); "
                  f"{bicycle.source} has none")
    return bicycle


def _is_bicycle(value):
    from ..bicycle import Bicycle
    return isinstance(value, Bicycle)


def read_chain_pose(node):
    """(name, parts, Solution) of a chain-form pose file (see the module docstring)."""
    from .solve import solve_on_bicycle
    node.check_keys(required=("body", "bike", "chain"), optional=("name", "source"))
    chain = node["chain"]
    chain.check_keys(optional=CHAIN_KEYS)
    body = load_chain_body(find_anthropometry(node["body"]), node["body"].string())
    bike = node["bike"]
    bicycle = bicycle_contacts(bike.value if _is_bicycle(bike.value) else bike.string(), bike)
    contacts = bicycle.contacts
    choices = (*contacts.grips, "none")
    hands = chain["hands"].string(choices) if chain.has("hands") else default_hands(contacts)
    crank = angle_deg(chain["crank"]) if chain.has("crank") else None
    fixed = {k: angle_deg(chain[k]) for k in JOINTS if chain.has(k)}
    solution = solve_on_bicycle(body, contacts, hands, crank, fixed)
    try:
        solution.check_reachable()
    except InputError as exc:
        key = "hands" if ".grips." in exc.key else "crank" if exc.key.endswith("crank_length") else None
        chain.fail(f"{exc.expected} [{exc.source}: {exc.key}]", key)
    for line in solution.pose.warnings():
        warnings.warn(f"{node.source}: {line}", BikemassWarning, stacklevel=2)
    name = node.get("name", str(node.source)).string()
    document = solution.pose.placement_form(name, node["body"].string())
    _, parts = read_pose(Node(document, node.source, None))
    return name, parts, solution
