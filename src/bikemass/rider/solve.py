"""Solving chain poses (scipy least squares): on a bicycle's contacts, or closest to a placement pose.

``solve_on_bicycle`` puts the sit point on the saddle (this fixes the hip joints), the
hands on a grip and the feet on the pedals; the joint angles the user fixes stay fixed,
the others are solved.
Defaults keep the problem exactly determined: neck 0; with hands on a grip and no
torso lean given, elbow flexion 20 deg and the torso lean solved; without a grip, the
torso upright (0) and the arms hanging straight down; without a crank angle the legs are
symmetric and both feet sit on the crank axis (the pedals' midpoint, where the thesis
puts them), with a crank angle each foot is on its own pedal.
"""

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares

from ..core.convention import thesis_segment_axis
from ..core.errors import InputError
from ..core.frozen import frozen_fields
from .chain import JOINTS, ChainPose

REACH_TOLERANCE = 1e-3
"""A contact further than this (m) from its target after solving is out of reach."""

BOUNDS = {"torso_lean": (-45.0, 110.0), "neck": (-90.0, 90.0), "shoulder": (-90.0, 220.0),
          "elbow": (0.0, 175.0), "hip": (-60.0, 180.0), "knee": (0.0, 175.0)}
"""Solver bounds (deg): wide, but no hyperextended elbows or knees (picks the natural branch)."""

START = {"torso_lean": 30.0, "neck": 0.0, "shoulder": 60.0, "elbow": 20.0, "hip": 90.0, "knee": 60.0}
"""Initial guess (deg)."""

DEFAULT_ELBOW = 20.0
"""Elbow flexion (deg) used when the hands are on a grip and the torso lean is not given."""


@dataclass(frozen=True, eq=False)
class Target:
    """A contact: ``point(pose)`` (m) must meet ``target`` (m, x and z); ``key`` names it in errors;
    the point is the pose's point ``point_name`` of the limbs of ``side``
    (:meth:`~bikemass.rider.chain.ChainPose.points`)."""

    name: str
    point: object
    target: np.ndarray
    source: str
    key: str
    why: str
    point_name: str = ""
    side: str = "right"

    def __post_init__(self):
        frozen_fields(self, "target")


@dataclass(frozen=True, eq=False)
class Solution:
    """A solved :class:`ChainPose`, the contacts' residual distances (m, x-z) and the free joints."""

    pose: ChainPose
    residuals: Mapping
    free: tuple
    targets: tuple

    def __post_init__(self):
        frozen_fields(self, "residuals", "free", "targets")

    def check_reachable(self, tolerance=REACH_TOLERANCE):
        """Raise :class:`InputError` naming the worst contact missed by more than ``tolerance`` (m)."""
        worst = max(self.targets, key=lambda t: self.residuals[t.name])
        miss = self.residuals[worst.name]
        if miss > tolerance:
            raise InputError(worst.source, worst.key,
                             f"a contact within reach: {worst.name} out of reach by {miss * 1000:.1f} mm "
                             f"({worst.why})")
        return self


def _variables(fixed, names):
    return [n for n in names if n not in fixed]


def _pose_from(x, free, fixed, body):
    values = dict(fixed)
    values.update(zip(free, x))
    root = np.array([values.pop("root_x"), values.pop("root_z")])
    angles = {k: float(np.degrees(v)) for k, v in values.items()}
    return ChainPose(body, root, angles)


def _least_squares(residual, free, fixed, body, start, jacobian=None):
    """The pose minimising ``residual(pose)``; ``jacobian(pose, free)`` its derivative (rows as the
    residual's, a column per free variable), else finite differences."""
    lo = [-np.inf if n.startswith("root") else np.radians(BOUNDS[n.replace("_left", "")][0]) for n in free]
    hi = [np.inf if n.startswith("root") else np.radians(BOUNDS[n.replace("_left", "")][1]) for n in free]
    x0 = np.clip([start[n] for n in free], np.array(lo) + 1e-9, np.array(hi) - 1e-9)
    jac = "2-point" if jacobian is None else (lambda x: jacobian(_pose_from(x, free, fixed, body), free))
    result = least_squares(lambda x: residual(_pose_from(x, free, fixed, body)), x0, jac=jac, bounds=(lo, hi),
                           xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=2000)
    return _pose_from(result.x, free, fixed, body)


def _xz(v):
    return np.asarray(v)[[0, 2]]


def contact_targets(body, contacts, hands, crank):
    """The :class:`Target` list for ``hands`` (a grip name or ``"none"``) and ``crank`` (deg or None)."""
    src = contacts.source
    targets = [Target("hips", lambda p: p.points()["seat"], _xz(contacts.sit_point(body.inseam)), src,
                      f"{contacts.key}.saddle", "the sit point is fixed to the saddle", "seat")]
    if hands != "none":
        if hands not in contacts.grips:
            raise InputError(src, f"{contacts.key}.grips.{hands}",
                             f"a grip named {hands} (this bicycle has: {', '.join(contacts.grips) or 'none'})")
        targets.append(Target("hands", lambda p: p.points()["hand"], _xz(contacts.grips[hands]), src,
                              f"{contacts.key}.grips.{hands}", "arms too short for the bars", "hand"))
    if crank is None:
        targets.append(Target("feet", lambda p: p.points()["foot"], _xz(contacts.bottom_bracket), src,
                              f"{contacts.key}.bottom_bracket", "saddle too high for the pedals", "foot"))
    else:
        for side in ("right", "left"):
            targets.append(Target(f"{side} foot", lambda p, s=side: p.points(s)["foot"],
                                  _xz(contacts.pedal(crank, side)), src, f"{contacts.key}.crank_length",
                                  f"saddle too high for the {side} pedal at crank {crank:g} deg", "foot", side))
    return targets


def targets_jacobian(targets, pose, free):
    """Derivative of the stacked x-z residuals of ``targets`` at ``pose``: a row per residual,
    a column per variable of ``free`` (m per rad, m per m)."""
    rows = []
    for t in targets:
        d = pose.point_jacobian(t.point_name, t.side)
        rows.append(np.array([d.get(v, (0.0, 0.0)) for v in free]).T)
    return np.vstack(rows)


def solve_on_bicycle(body, contacts, hands="hoods", crank=None, fixed=None):
    """:class:`Solution`: ``body`` (:class:`ChainBody`) on ``contacts`` with joint angles
    ``fixed`` (deg, any of :data:`~bikemass.rider.chain.JOINTS`; see the module docstring)."""
    fixed = dict(fixed or {})
    unknown = set(fixed) - set(JOINTS)
    if unknown:
        raise ValueError(f"unknown joints {sorted(unknown)}; known: {', '.join(JOINTS)}")
    fixed.setdefault("neck", 0.0)
    if hands == "none":
        fixed.setdefault("torso_lean", 0.0)
        fixed.setdefault("shoulder", fixed["torso_lean"])
        fixed.setdefault("elbow", 0.0)
    elif "torso_lean" not in fixed:
        fixed.setdefault("elbow", DEFAULT_ELBOW)
    names = ["root_x", "root_z", *JOINTS] + (["hip_left", "knee_left"] if crank is not None else [])
    hip = contacts.sit_point(body.inseam) - [0.0, 0.0, body.seat]
    fixed_rad = {"root_x": hip[0], "root_z": hip[2], **{k: np.radians(v) for k, v in fixed.items()}}
    free = _variables(fixed_rad, names)
    targets = contact_targets(body, contacts, hands, crank)
    start = {**{k: np.radians(v) for k, v in START.items()},
             "hip_left": np.radians(START["hip"]), "knee_left": np.radians(START["knee"])}
    pose = _least_squares(lambda p: np.concatenate([_xz(t.point(p)) - t.target for t in targets]),
                          free, fixed_rad, body, start, lambda p, names: targets_jacobian(targets, p, names))
    residuals = {t.name: float(np.linalg.norm(_xz(t.point(pose)) - t.target)) for t in targets}
    return Solution(pose, residuals, tuple(free), tuple(targets))


def _ends(placements, lengths):
    """(top, far end) x-z points of each segment of a placement dict."""
    return {s: (_xz(loc), _xz(np.asarray(loc) + lengths[s] * thesis_segment_axis(a)))
            for s, (loc, a) in placements.items()}


def fit_to_placements(body, placements):
    """(ChainPose, rms, max) closest to a placement-form pose: every joint angle and the
    root free, least squares on the x-z distances (m) of every segment's top and far end.

    ``placements`` = ``{segment: (location, angle)}`` (right copies of pairs)."""
    target = _ends(placements, body.lengths)

    def residual(pose):
        right, _ = pose.placements()
        ends = _ends(right, body.lengths)
        return np.concatenate([np.concatenate(ends[s]) - np.concatenate(target[s]) for s in target])

    hip = placements["thigh"][0]
    start = {"root_x": hip[0], "root_z": hip[2], **{k: np.radians(v) for k, v in START.items()}}
    pose = _least_squares(residual, ["root_x", "root_z", *JOINTS], {}, body, start)
    d = np.linalg.norm(residual(pose).reshape(-1, 2), axis=1)
    return pose, float(np.sqrt(np.mean(d**2))), float(d.max())
