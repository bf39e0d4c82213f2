"""The rider as a kinematic chain: segments joined end to end, posed by joint angles.

The chain is planar and left/right symmetric, like the thesis's placement form
(every segment turns about y only): a root point, the hip-joint midpoint ``root``
(x, z in m), and joint angles in degrees (see :data:`JOINTS`).  The thesis segment
angle ``a`` of each segment (axis ``(-sin a, 0, cos a)``, docs/riders.md) follows as

* torso ``a = torso_lean`` (0 upright, positive leaning forward);
* head ``a = torso_lean + neck`` (neck flexion, positive chin toward the chest);
* upper arm ``a = torso_lean - shoulder`` (shoulder flexion: 0 along the torso,
  positive raised forward); lower arm ``a = upper arm - elbow`` (elbow flexion, 0 straight);
* thigh ``a = torso_lean - hip`` (hip flexion: 0 in line with the torso, 90 seated
  upright); lower leg ``a = thigh + knee`` (knee flexion, 0 straight).

Where the segments join comes from the anthropometry's ``joints:`` block (points in
the torso's local frame: ``neck``, ``shoulder``, ``hip``; ``seat`` = the sit point's
depth below the hip joints).  Each child starts exactly where its parent ends:
head far end at the neck, upper arm at the shoulder, lower arm at the elbow (upper
arm far end), thigh at the hip joint, lower leg at the knee (thigh far end).
"""

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..core.config import load_yaml
from ..core.frozen import FrozenMap, LazyMap, freeze, frozen_fields
from ..core.convention import thesis_segment_axis, thesis_segment_rotation
from ..core.units import Quantity
from .anthropometry import load_anthropometry

CHAIN_SEGMENTS = ("head", "torso", "upper_arm", "lower_arm", "thigh", "lower_leg")
"""Segments an anthropometry needs for a chain pose."""

BALL, BICYCLEPARAMETERS = "ball", "bicycleparameters"
FEET = (BALL, BICYCLEPARAMETERS)
"""Which point of the lower leg goes on the crank axis (or the pedal): ``ball`` (its far end:
the ball of a yeadon foot, the sole of a cylinder to the floor), or ``bicycleparameters``
(BicycleParameters' ``rider_on_bike``: the shank's line at the heel's level, yeadon bodies)."""

JOINTS = ("torso_lean", "neck", "shoulder", "elbow", "hip", "knee")
"""Joint angles of the symmetric chain (deg).  ``hip_left``/``knee_left`` may differ
from ``hip``/``knee`` (the right leg) when the feet are on pedals at a crank angle."""

SIDED = ("hip", "knee")

HUMAN_RANGES = {"torso_lean": (-20.0, 90.0), "neck": (-45.0, 45.0), "shoulder": (-60.0, 180.0),
                "elbow": (0.0, 150.0), "hip": (-30.0, 120.0), "knee": (0.0, 135.0)}
"""Typical adult ranges of motion (deg; AAOS-style averages, rounded): a pose outside
them is warned about, not refused.  ``torso_lean`` is the trunk from vertical."""


@dataclass(frozen=True, eq=False)
class ChainBody:
    """An anthropometry with its joints: segment ``lengths`` (m) and attachment points
    (torso local frame, m: ``neck``, ``shoulder``, ``hip``; right-side y), ``seat`` depth (m)."""

    name: str
    source: Path
    lengths: dict
    neck: np.ndarray
    shoulder: np.ndarray
    hip: np.ndarray
    seat: float
    feet: tuple = ()
    """``((placement, lower-leg chain length m), ...)``: other points of the lower leg that may go
    on the crank axis or pedal than its far end (:data:`FEET`; a yeadon body's
    ``bicycleparameters``)."""
    leg_length: float | None = None

    def __post_init__(self):
        frozen_fields(self, "lengths", "neck", "shoulder", "hip", "feet")
    """Floor-to-crotch length (m) kept when the lower leg's chain length is another placement's."""

    @property
    def inseam(self):
        """Floor-to-crotch length (m) of the straight leg: hip joint to foot less the seat depth."""
        if self.leg_length is not None:
            return self.leg_length
        return self.lengths["thigh"] + self.lengths["lower_leg"] - self.seat

    def with_feet(self, placement):
        """This body with ``placement`` (one of :data:`FEET`) the point of the lower leg that goes
        on the crank axis or the pedal: ``ball`` (the lower leg's far end, the default) or
        ``bicycleparameters`` (BicycleParameters' seating of a yeadon rider: the shank's line at
        the heel's level, the foot beyond it; docs/riders.md).  The inseam stays the anatomical
        one.  KeyError if the body has no such point."""
        if placement == BALL:
            return self
        length = dict(self.feet)[placement]
        return ChainBody(self.name, self.source, {**self.lengths, "lower_leg": length}, self.neck, self.shoulder,
                         self.hip, self.seat, self.feet, self.inseam)


def load_chain_body(path, name=None) -> ChainBody:
    """:class:`ChainBody` of the anthropometry file ``path`` (needs a ``joints:`` block)."""
    anthropometry = load_anthropometry(path)
    node = load_yaml(path)
    missing = [s for s in CHAIN_SEGMENTS if s not in anthropometry.segments]
    if missing:
        node["segments"].fail(f"the chain segments {', '.join(CHAIN_SEGMENTS)} (missing: {', '.join(missing)})")
    if not node.has("joints"):
        node.fail("a joints: block (neck, shoulder, hip, seat) for chain poses, see docs/poses.md", "joints")
    joints = node["joints"].check_keys(required=("neck", "shoulder", "hip", "seat"), optional=("note",))
    points = {k: joints[k].vector("length", 3) for k in ("neck", "shoulder", "hip")}
    for k in ("shoulder", "hip"):
        if not points[k][1] > 0:
            joints.fail(f"a positive y (the right-side joint; mirrored to -y), got {points[k][1]!r}", k)
    lengths = {s: anthropometry.segments[s].solid.length for s in CHAIN_SEGMENTS}
    return ChainBody(name or Path(path).stem, Path(path), lengths, points["neck"], points["shoulder"],
                     points["hip"], joints["seat"].number("length", nonnegative=True))


def _numbers(v):
    return [float(x) + 0.0 for x in v]


def _degrees(angle):
    """An angle in degrees as a pose document holds it: typed, with its unit (a file writer writes
    it as ``"<x> deg"`` with every digit, :func:`~bikemass.core.plain.file_form`)."""
    return Quantity(float(angle) + 0.0, "deg")


def _midplane(p):
    return np.array([p[0], 0.0, p[2]])


@dataclass(frozen=True, eq=False)
class ChainPose:
    """``body`` posed with hip-joint midpoint ``root`` = (x, z) (m) and joint ``angles`` (deg)."""

    body: ChainBody
    root: np.ndarray
    angles: Mapping = field(default_factory=FrozenMap)
    _points: Mapping = field(default_factory=FrozenMap, init=False, repr=False)
    """:meth:`points` of each side, computed when first read (a solver's residual asks for several
    points of one pose)."""

    def __post_init__(self):
        frozen_fields(self, "root", "angles")
        object.__setattr__(self, "_points", FrozenMap(
            {side: LazyMap(lambda side=side: freeze(self._compute_points(side))) for side in ("right", "left")}))

    def angle(self, joint, side="right"):
        """Joint angle (deg); ``side='left'`` gives ``hip_left``/``knee_left`` when set."""
        if side == "left" and joint in SIDED:
            return self.angles.get(f"{joint}_left", self.angles[joint])
        return self.angles[joint]

    @property
    def symmetric(self):
        return all(self.angle(j, "left") == self.angle(j) for j in SIDED)

    def segment_angles(self, side="right"):
        """Thesis segment angle (deg) of every chain segment (legs of ``side``)."""
        t = self.angles["torso_lean"]
        upper_arm = t - self.angles["shoulder"]
        thigh = t - self.angle("hip", side)
        return {"head": t + self.angles["neck"], "torso": t, "upper_arm": upper_arm,
                "lower_arm": upper_arm - self.angles["elbow"], "thigh": thigh,
                "lower_leg": thigh + self.angle("knee", side)}

    def points(self, side="right"):
        """Named points (m, benchmark frame) of the right limbs, or the left legs' with ``side``
        (a read-only mapping of read-only arrays, computed once per side)."""
        points = self._points.get(side)
        return freeze(self._compute_points(side)) if points is None else points

    def _compute_points(self, side):
        a, L, b = self.segment_angles(side), self.body.lengths, self.body
        sign = -1.0 if side == "left" else 1.0
        R = thesis_segment_rotation(a["torso"])
        hip_mid = np.array([self.root[0], 0.0, self.root[1]])
        top = hip_mid - R @ _midplane(b.hip)
        p = {"hip_centre": hip_mid, "seat": hip_mid + [0.0, 0.0, b.seat], "torso_top": top,
             "neck": top + R @ b.neck}
        p["head_top"] = p["neck"] - L["head"] * thesis_segment_axis(a["head"])
        p["shoulder"] = top + R @ b.shoulder
        p["elbow"] = p["shoulder"] + L["upper_arm"] * thesis_segment_axis(a["upper_arm"])
        p["hand"] = p["elbow"] + L["lower_arm"] * thesis_segment_axis(a["lower_arm"])
        p["hip"] = hip_mid + [0.0, sign * b.hip[1], 0.0]
        p["knee"] = p["hip"] + L["thigh"] * thesis_segment_axis(a["thigh"])
        p["foot"] = p["knee"] + L["lower_leg"] * thesis_segment_axis(a["lower_leg"])
        return p

    def point_jacobian(self, name, side="right"):
        """``{variable: (dx, dz)}``: the derivative of point ``name`` of :meth:`points` (``seat``,
        ``hand`` or ``foot``; the left foot with ``side``) in the x-z plane, m per radian of each
        joint angle it depends on (``hip_left``/``knee_left`` for the left foot) and m per m of
        ``root_x``/``root_z``.  What a solver needs instead of finite differences."""
        a = {k: np.radians(v) for k, v in self.segment_angles(side).items()}
        L = self.body.lengths

        def turn(segment):          # d/da of L * axis(a) in (x, z): axis = (-sin a, cos a)
            return L[segment] * np.array([-np.cos(a[segment]), -np.sin(a[segment])])
        out = {"root_x": np.array([1.0, 0.0]), "root_z": np.array([0.0, 1.0])}
        if name == "hand":
            c, s = np.cos(a["torso"]), np.sin(a["torso"])
            v = np.asarray(self.body.shoulder, dtype=float) - _midplane(self.body.hip)
            torso = np.array([-s * v[0] - c * v[2], c * v[0] - s * v[2]])      # d(R(t) v)/dt, x and z
            arm, forearm = turn("upper_arm"), turn("lower_arm")
            out.update({"torso_lean": torso + arm + forearm, "shoulder": -(arm + forearm), "elbow": -forearm})
        elif name == "foot":
            hip, knee = (f"{j}_left" if side == "left" and f"{j}_left" in self.angles else j for j in SIDED)
            thigh, shank = turn("thigh"), turn("lower_leg")
            out.update({"torso_lean": thigh + shank, hip: -(thigh + shank), knee: shank})
        elif name != "seat":
            raise ValueError(f"no derivative of point {name!r} (seat, hand or foot)")
        return out

    def placements(self):
        """``{segment: (location, angle)}`` in the placement form (right copy of pairs), and
        ``{segment: (location, angle)}`` of the left legs where they differ from the mirror image."""
        a, p = self.segment_angles(), self.points()
        right = {"head": (p["head_top"], a["head"]), "torso": (p["torso_top"], a["torso"]),
                 "upper_arm": (p["shoulder"], a["upper_arm"]), "lower_arm": (p["elbow"], a["lower_arm"]),
                 "thigh": (p["hip"], a["thigh"]), "lower_leg": (p["knee"], a["lower_leg"])}
        left = {}
        if not self.symmetric:
            al, pl = self.segment_angles("left"), self.points("left")
            left = {"thigh": (pl["hip"], al["thigh"]), "lower_leg": (pl["knee"], al["lower_leg"])}
        return right, left

    def placement_form(self, name, body, front=()):
        """The pose as a placement-form pose document (docs/riders.md); ``body`` names the anthropometry
        (a name or a body mapping); the segments in ``front`` move with the front frame.

        Angles are :class:`~bikemass.core.units.Quantity` values in deg (a file writer writes them as
        text with every digit, so the file's joints stay joined).  A solved pose's parts come from
        the pose itself (:func:`~bikemass.rider.pose.pose_parts`), not from this document."""
        right, left = self.placements()
        segments = {}
        for seg, (location, angle) in right.items():
            entry = {"location": _numbers(location), "angle": _degrees(angle)}
            if seg in front:
                entry["frame"] = "front"
            if seg not in ("head", "torso"):
                entry["mirror"] = True
            if seg in left:
                loc, ang = left[seg]
                entry["left"] = {"location": _numbers(loc), "angle": _degrees(ang)}
            segments[seg] = entry
        return {"name": name, "body": body, "segments": segments}

    def warnings(self):
        """One line per joint angle outside :data:`HUMAN_RANGES`."""
        out = []
        for joint, value in sorted(self.angles.items(), key=lambda kv: JOINTS.index(kv[0].replace("_left", ""))):
            lo, hi = HUMAN_RANGES[joint.replace("_left", "")]
            if not lo - 1e-9 <= value <= hi + 1e-9:
                out.append(f"{joint.replace('_', ' ')} {value:.1f} deg is outside the typical human range "
                           f"{lo:g}..{hi:g} deg")
        return out


JOINT_PAIRS = (("neck", "torso", "neck", "head"), ("shoulder", "torso", "shoulder", "upper_arm"),
               ("elbow", "upper_arm", None, "lower_arm"), ("hip", "torso", "hip", "thigh"),
               ("knee", "thigh", None, "lower_leg"))
"""(joint, parent, attachment point of the parent or None = its far end, child)."""


def joint_gaps(placements, body, plane=False):
    """``{joint: gap}`` (m): distance between where a placement-form pose puts each child
    segment's joint end and the point of its parent it should be joined to.

    ``placements`` = ``{segment: (location, angle)}`` (right copies of pairs, any pose).
    The head joins at its far end, every other child at its top plane.  ``plane=True``:
    the distance in the x-z plane only (y differences left out).
    """
    gaps = {}
    for joint, parent, attach, child in JOINT_PAIRS:
        loc, ang = (np.asarray(v, dtype=float) if i == 0 else v for i, v in enumerate(placements[parent]))
        if attach is None:
            anchor = loc + body.lengths[parent] * thesis_segment_axis(ang)
        else:
            anchor = loc + thesis_segment_rotation(ang) @ getattr(body, attach)
        c_loc, c_ang = placements[child]
        end = np.asarray(c_loc, dtype=float)
        if child == "head":
            end = end + body.lengths["head"] * thesis_segment_axis(c_ang)
        gap = end - anchor
        gaps[joint] = float(np.linalg.norm(gap[[0, 2]] if plane else gap))
    return gaps
