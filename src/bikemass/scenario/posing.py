"""A rider posed by joint angles on a bicycle's contacts (``bm.pose_rider``): hips on the
saddle, hands on a grip, feet on the pedals, the free joint angles solved (scipy least
squares, :mod:`bikemass.rider.solve`).  Joint angles outside typical human ranges are
reported with :mod:`warnings` (:class:`~bikemass.core.errors.BikemassWarning`), not refused."""

import math
import numbers
import warnings
from collections.abc import Mapping
from dataclasses import dataclass

from ..core.choices import Grip, check
from ..core.config import Node
from ..core.errors import BikemassWarning, InputError, short, wrong_type
from ..core.frozen import FrozenMap, freeze, short_repr, thaw
from ..core.results import Result, quantity, renamed_field
from ..core.units import Quantity
from ..rider import Rider
from ..rider.body import chain_of, load_body
from ..rider.chain import BALL, FEET, JOINTS, joint_gaps
from ..rider.chain_file import bicycle_contacts, default_hands
from ..rider.pose import POSE_UNITS, pose_parts
from .loading import BicycleLike, load_bicycle

DEFAULT_BODY = "thesis_rider"
"""The anthropometry (``bodies/``) posed when none is named."""


@dataclass(frozen=True, eq=False, repr=False)
class PosedRider(Result):
    """A chain-posed rider and how it was solved (what :func:`bikemass.pose_rider` returns).

    Attributes
    ----------
    rider : Rider
        The posed rider (use it anywhere a rider goes).
    bicycle : Bicycle
        The bicycle whose ``contacts`` it sits on.
    solution : Solution
        Joint angles (``solution.pose.angles``, deg), hip joints (``solution.pose.root``,
        x and z in m), the contacts' residuals (m) and which joints were solved.
    hands : Grip
        The grip used (or ``"none"``); a string enum.
    crank : float or None
        The crank angle (deg), ``None`` for symmetric legs.
    placement : Mapping
        The pose in the placement form (read-only; its angles and crank typed,
        :class:`~bikemass.core.units.Quantity` in deg, which ``bikemass pose -o`` writes as
        ``"<number> deg"``).  ``document``, its name before 0.3, still reads it with a
        DeprecationWarning; ``document()`` is the result's document, as on every result.
    gaps : Mapping
        ``{joint: gap (m)}`` between the joined segment ends (zero to rounding).

    See Also
    --------
    pose_rider : Makes one.
    plot_pose : Draws one.

    Examples
    --------
    >>> import bikemass as bm
    >>> posed = bm.pose_rider("jamis", hands="drops", fixed={"torso_lean": 40})
    >>> print(posed.hands, f"elbow {posed.solution.pose.angles['elbow']:.1f} deg")
    drops elbow 52.5 deg
    >>> params = bm.parameters("jamis", posed.rider)        # a rider like any other
    """

    rider: Rider
    bicycle: object
    solution: object
    hands: "Grip | str"
    crank: float | None = quantity("deg", "the crank angle; None: symmetric legs", default=None)
    placement: Mapping = quantity("as POSE_UNITS (location m, angle deg)", "the placement form",
                                  default_factory=FrozenMap)
    gaps: Mapping = quantity("m", "{joint: gap} between the joined segment ends", default_factory=FrozenMap)

    document = renamed_field("document", "placement", "_document")

    def __post_init__(self):
        super().__post_init__()
        object.__setattr__(self, "hands", Grip(self.hands))

    def to_dict(self):
        """Plain data: the rider's name, the grip, the crank angle (deg), the joint angles (deg), the
        hip joints (x, z in m), the contacts' residuals and the joints' gaps (m), and the placement
        form (``placement``)."""
        pose = self.solution.pose
        return {"name": self.rider.name, "hands": str(self.hands), "crank": self.crank,
                "angles": {k: float(v) for k, v in pose.angles.items()},
                "hip_joints": [float(x) for x in pose.root],
                "residuals": {k: float(v) for k, v in self.solution.residuals.items()},
                "gaps": {k: float(v) for k, v in self.gaps.items()}, "placement": thaw(self.placement)}

    def units(self):
        """The units block of :meth:`to_dict`: the crank's and the gaps' as declared, the joint
        angles in deg, hip joints and residuals in m, the placement form's as its file states them
        (:data:`~bikemass.rider.pose.POSE_UNITS`)."""
        declared = self.field_units()
        return {"crank": declared["crank"], "angles": "deg", "hip_joints": "m", "residuals": "m",
                "gaps": declared["gaps"], **POSE_UNITS}

    def _document(self):
        """:meth:`Result.document` (``document()``; the name ``document`` was the placement form's)."""
        return Result.document(self)

    def __repr__(self):
        angles = ", ".join(f"{k} {v:.1f}" for k, v in self.solution.pose.angles.items())
        return short_repr(self, ("rider", repr(self.rider.name)), ("hands", self.hands),
                          ("angles_deg", f"({angles})"))


MAX_ANGLE = 360.0
"""Largest joint or crank angle magnitude (deg) accepted, as ``bikemass pose --fix/--crank``."""


def _degrees(value, what):
    """``value`` as a float angle in [-:data:`MAX_ANGLE`, :data:`MAX_ANGLE`] deg, else InputError."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value) \
            or abs(value) > MAX_ANGLE:
        raise InputError(what, short(value), f"an angle in degrees within +-{MAX_ANGLE:g}")
    return float(value)


def pose_rider(bicycle: BicycleLike, body: "str | Mapping" = DEFAULT_BODY, hands: Grip | str | None = None,
               crank: float | None = None, fixed: "Mapping[str, float] | None" = None,
               name: str | None = None, feet: str = "ball") -> PosedRider:
    """Pose a rider by joint angles on a bicycle's contact points.

    Hips on the saddle, hands on a grip, feet on the pedals; the joint angles not ``fixed`` are
    solved (scipy least squares, :mod:`bikemass.rider.solve`).

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        Anything :func:`bikemass.load_bicycle` takes, with a ``contacts:`` section.
    body : str or Mapping
        Anthropometry with ``joints:`` (a name in ``bodies/`` or a YAML file), or a body
        mapping: ``{height, mass, sex}`` or ``{yeadon: FILE}`` (docs/riders.md).
    hands : {"tops", "hoods", "drops", "aero", "none"}, optional
        Grip; default ``hoods`` if the bicycle has them, else its first grip.
    crank : float, optional
        Crank angle (deg, 0 = right crank forward); default: symmetric legs with the feet
        on the crank axis (as the thesis).
    fixed : Mapping[str, float], optional
        Joint angles to hold (deg): any of torso_lean, neck, shoulder, elbow, hip, knee.
    name : str, optional
        The pose's name (default ``"<hands> on <bicycle name as given, or its name:>"``).
    feet : {"ball", "bicycleparameters"}
        The point of the lower leg on the crank axis (or pedal): the ball of the foot (default),
        or BicycleParameters' seating of a yeadon body, the shank's line at the heel's level
        (docs/riders.md, "Feet").

    Returns
    -------
    PosedRider
        ``.rider`` to use anywhere a rider goes, ``.solution`` the joint angles and residuals.

    Raises
    ------
    InputError
        A bicycle without contacts, an unknown grip or joint, an angle beyond +-360 deg, or a
        contact out of reach.

    Warns
    -----
    BikemassWarning
        A joint angle outside the typical human range (the pose is still returned).

    See Also
    --------
    plot_pose : Draw the posed rider with its joints and contact targets.
    load_rider : A rider from a pose file or name.

    Examples
    --------
    >>> import bikemass as bm
    >>> for lean in (25, 40):
    ...     posed = bm.pose_rider("jamis", hands="hoods", fixed={"torso_lean": lean})
    ...     print(f"torso lean {lean} deg: elbow {posed.solution.pose.angles['elbow']:.1f} deg")
    torso lean 25 deg: elbow 22.7 deg
    torso lean 40 deg: elbow 74.6 deg
    """
    # lazy: rider.solve loads scipy.optimize (slower to import than numpy); only this call needs it
    from ..rider.solve import solve_on_bicycle

    model = load_bicycle(bicycle)
    model = bicycle_contacts(model, Node(model.source, model.source, "contacts"))
    body_node = Node(dict(body) if isinstance(body, Mapping) else str(body), "body", "body")
    loaded = load_body(body_node)
    chain_body = chain_of(loaded, body_node)
    hands = default_hands(model.contacts) if hands is None else check(Grip, hands, "hands").value
    if fixed is not None and not isinstance(fixed, Mapping):
        raise wrong_type("fixed", fixed, "a mapping of joint -> angle (deg)")
    fixed = dict(fixed or {})
    for joint, value in fixed.items():
        if joint not in JOINTS:
            raise InputError("fixed", joint, f"a joint angle: one of {', '.join(JOINTS)}")
        fixed[joint] = _degrees(value, f"fixed.{joint}")
    crank = None if crank is None else _degrees(crank, "crank")
    if feet not in FEET:
        raise InputError("feet", short(feet), f"one of {', '.join(FEET)}")
    try:
        chain_body = chain_body.with_feet(feet)
    except KeyError:
        raise InputError("feet", feet, "ball for this body (bicycleparameters places a yeadon body: "
                         "{yeadon: FILE})") from None
    solution = solve_on_bicycle(chain_body, model.contacts, hands, crank, fixed).check_reachable()
    for line in solution.pose.warnings():
        warnings.warn(line, BikemassWarning, stacklevel=2)
    name = name or f"{hands} on {bicycle if isinstance(bicycle, str) else model.name}"
    document = solution.pose.placement_form(name, loaded.label)
    if feet != BALL:         # read again, the contacts are checked with the same point on the crank axis
        document["posture"] = {"hands": hands, "feet": feet, **({"crank": Quantity(crank, "deg")}
                                                                if crank is not None else {})}
    node = Node(document, name, None)
    parts = pose_parts(solution.pose, loaded.anthropometry, (), name)
    # a body named or given inline can be read again from the document: bicycles re-check it
    spec = (node, False) if isinstance(body, Mapping) or not str(body).endswith((".yaml", ".yml")) else None
    right, _ = solution.pose.placements()
    return PosedRider(Rider(name, name, parts, spec), model, solution, hands, crank, freeze(document),
                      freeze(joint_gaps(right, chain_body)))
