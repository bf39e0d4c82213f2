"""The rider: an anthropometry (``bodies/*.yaml``) placed in a pose (``bodies/poses/*.yaml``).

``load_rider("relaxed")`` builds the Williams (2015) rider of Table 3-3 (errata
applied; ``as_printed=True`` uses the printed Table 3-3); ``load_rider("relaxed-thesis")``
is the published Table 3-4 rider as one lumped body.  See :mod:`bikemass.rider.pose`
for the file format.
"""

from dataclasses import dataclass, field
from pathlib import Path

from ..core.config import FrozenNode, Node, load_yaml
from ..core.errors import InputError
from ..core.gate import plain_input
from ..core.paths import available, bodies_dir, resolve
from ..mass.parts import METHODS, OVERLAPS, body_properties
from .chain_file import check_chain_pose, read_chain_pose
from .pose import read_pose

THESIS_POSES = ("no-hands", "relaxed", "on-hoods", "aerobars", "aero-tuck")
"""The five poses of Williams (2015), Table 3-3, in the thesis's order."""

PUBLISHED_SUFFIX = "-thesis"
"""``<pose>-thesis`` is the published Table 3-4 rider of ``<pose>`` as a lumped body."""


def poses_dir() -> Path:
    return bodies_dir() / "poses"


def shipped_poses() -> list[str]:
    """Shipped pose names: the five thesis poses in thesis order, then any others (no ``-thesis``)."""
    others = [n for n in available(poses_dir())
              if n not in THESIS_POSES and not n.endswith(PUBLISHED_SUFFIX)]
    return [n for n in THESIS_POSES if (poses_dir() / f"{n.replace('-', '_')}.yaml").is_file()] + others


@dataclass(frozen=True, eq=False)
class Rider:
    """A posed rider: ``pose`` as asked for, display ``name``, and its ``parts`` (tuple of Part);
    ``spec`` = (pose node, as_printed) it was read from, which lets a bicycle re-seat it
    (:mod:`bikemass.rider.seating`), or None; the node is kept as a read-only
    :class:`~bikemass.core.config.FrozenNode` (its ``thaw()`` gives a working Node).

    A chain-form pose without ``bike:`` (a person with a posture rule: hands on a grip, a torso
    lean, the saddle) has no parts until a bicycle seats it: :attr:`needs_bicycle` is True and
    :meth:`properties` refuses; :func:`bikemass.seated_rider` (and every analysis given the
    rider with a bicycle) solves it on that bicycle's contacts.

    See Also
    --------
    bikemass.load_rider : Makes one from a pose name, a file or a mapping.
    bikemass.pose_rider : Poses one by joint angles.

    Examples
    --------
    >>> import bikemass as bm
    >>> rider = bm.load_rider("aero-tuck")
    >>> [name for name, body, _ in rider.breakdown()][:3]
    ['head', 'torso', 'upper_arm_right']
    >>> print(f"{rider.properties().mass:.2f} kg")
    82.15 kg
    """

    pose: str
    name: str
    parts: tuple
    spec: tuple | None = field(default=None, repr=False)

    def __post_init__(self):
        object.__setattr__(self, "parts", tuple(self.parts))
        if self.spec is not None:
            node, as_printed = self.spec
            object.__setattr__(self, "spec", (FrozenNode.of(node), as_printed))

    @property
    def needs_bicycle(self) -> bool:
        """True for a chain-form pose without ``bike:``: its parts exist once a bicycle seats it."""
        return not self.parts and self.spec is not None and "chain" in self.spec[0].value

    def __repr__(self):
        if self.needs_bicycle:
            return f"Rider(pose={self.pose!r}, name={self.name!r}, chain pose: seated when given a bicycle)"
        mass = sum(p.mass for p in self.parts)
        return f"Rider(pose={self.pose!r}, name={self.name!r}, parts={len(self.parts)}, mass={mass:.6g} kg)"

    def _seated_parts(self):
        if self.needs_bicycle:
            raise InputError(str(self.spec[0].source), "bike", "a bicycle to seat this chain pose on (bikemass "
                             "rider POSE --bike BIKE; bm.seated_rider(bicycle, rider)), or a bike: line in the pose")
        return self.parts

    def properties(self, method="mesh", overlap="sum"):
        """Total :class:`~bikemass.mass.inertia.MassProperties` (trimesh ``mesh`` or ``exact``;
        overlapping parts ``sum``-med as in the thesis or counted once with ``union``)."""
        _check(method, METHODS, "method")
        _check(overlap, OVERLAPS, "overlap")
        return body_properties(self._seated_parts(), method, overlap)

    def breakdown(self, method="mesh"):
        """[(part name, frame body, MassProperties)] of every part (in the benchmark frame)."""
        _check(method, METHODS, "method")
        return [(p.name, p.body, p.mass_properties(method)) for p in self._seated_parts()]

    def to_dict(self, method="mesh", overlap="sum"):
        """``{"pose": str, "mass": kg, "com": [x, y, z], "inertia": [[3x3]]}``."""
        return {"pose": self.pose, **self.properties(method, overlap).to_dict()}


def _check(value, choices, what):
    if value not in choices:
        raise InputError(what, value, f"{what} must be one of {', '.join(choices)}, got {value!r}")


def load_rider(pose: str, as_printed: bool = False) -> Rider:
    """The rider in ``pose``: a shipped pose name or a pose YAML file.

    ``as_printed=True`` replaces every corrected value by its ``printed:`` value.
    A chain-form pose file (``chain:``, docs/poses.md) is solved on its bicycle.
    Bad input raises :class:`~bikemass.core.errors.InputError`.
    """
    return _read_document(load_yaml(resolve(pose, poses_dir(), "pose")), str(pose), as_printed)


def rider_from_mapping(mapping, source, as_printed=False):
    """The rider of a Python mapping in any form a pose file takes (placement, chain or
    lumped segments); errors name ``source``.  A chain pose's ``bike`` may also be a
    :class:`~bikemass.bicycle.Bicycle`."""
    node = Node(plain_input(mapping, source), source, "")
    if not isinstance(node.value, dict):
        node.fail("a mapping of a pose (segments: or chain:)")
    return _read_document(node, source, as_printed)


def _read_document(node, pose, as_printed):
    if isinstance(node.value, dict) and "chain" in node.value:
        if not node.has("bike"):
            return Rider(pose, check_chain_pose(node), (), (node, as_printed))
        name, parts, _, _ = read_chain_pose(node)
        return Rider(pose, name, parts, (node, as_printed))
    name, parts = read_pose(node, as_printed)
    return Rider(pose, name, parts, (node, as_printed))
