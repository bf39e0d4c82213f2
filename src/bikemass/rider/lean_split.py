"""A bicycle and a seated rider -> the leaning rider's parameters: the rider split at the hips.

The rider's segments are sorted by kind (a pair's ``_right``/``_left`` copies alike): the upper body
(``head``, ``torso``, ``upper_arm``, ``lower_arm``) that moves with the rear frame leans; the legs
(``thigh``, ``lower_leg``) and any lumped body stay with the rear frame B; segments that move with
the front frame (hands on the bars: ``frame: front``) stay with the front frame H.  The pelvis is
part of the torso segment in every body bikemass builds (the thesis's and the height-and-mass
torso end at the hip joints, yeadon's holds the pelvis solids), so it leans with the torso.  The hip
axis is the line parallel to x through the hip joints: the top planes of the thighs (where every
pose puts them), at their mean height.
"""

import numpy as np

from ..bicycle.benchmark import merge_rider, parameters_from_bodies, refuse_second_rider, rider_bodies
from ..core.errors import InputError
from ..mass.parts import body_properties
from ..models.plausibility import warn_rider
from . import Rider
from ..models.members.rider_lean.parameters import LeanJoint, RiderLeanParameters, UpperBody

UPPER_BODY = ("head", "torso", "upper_arm", "lower_arm")
"""Segment kinds that lean with the upper body (when they move with the rear frame)."""
THIGH = "thigh"


def kind(name):
    """A part's segment kind: ``upper_arm_right`` -> ``upper_arm``."""
    for side in ("_right", "_left"):
        if name.endswith(side):
            return name[: -len(side)]
    return name


def split(rider):
    """``(upper, rest)``: the rider's parts that lean, and the others (as they are)."""
    upper = tuple(p for p in rider.parts if p.body == "rear_frame" and kind(p.name) in UPPER_BODY)
    return upper, tuple(p for p in rider.parts if p not in upper)


def hip_axis_z(rider):
    """z (m, benchmark frame) of the hip axis: the mean height of the thighs' top planes."""
    thighs = [p for p in rider.parts if kind(p.name) == THIGH]
    if not thighs:
        raise InputError(rider.pose, "segments", f"thighs, whose top planes are the hip joints that the lean "
                         f"axis passes through; rider {rider.name!r} has none (a lumped rider cannot lean)")
    return float(np.mean([p.placement.translation[2] for p in thighs]))


def rider_lean_parameters(bicycle, rider, method="mesh", joint=LeanJoint()):
    """:class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters` of ``bicycle`` (a
    :class:`~bikemass.bicycle.Bicycle`) with the seated ``rider`` (a :class:`~bikemass.rider.Rider`)
    split at the hips (see the module docstring); ``method`` of the mass properties (``mesh`` or
    ``exact``); ``joint`` the hip joint's stiffness and damping."""
    refuse_second_rider(bicycle, rider)
    upper, rest = split(rider)
    if not upper:
        raise InputError(rider.pose, "segments", f"an upper body to lean (head, torso or arms on the rear "
                         f"frame); rider {rider.name!r} has none")
    hip_z = hip_axis_z(rider)
    warn_rider(body_properties(rider.parts, "exact").com, bicycle.geometry, bicycle.source, rider.name)
    bodies = merge_rider(bicycle.bodies(method), rider_bodies(Rider(rider.pose, rider.name, rest), method))
    props = body_properties(upper, method)
    I = props.inertia
    body = UpperBody(mass=props.mass, x=float(props.com[0]), z=float(props.com[2]), Ixx=float(I[0, 0]),
                     Iyy=float(I[1, 1]), Izz=float(I[2, 2]), Ixz=float(I[0, 2]), hip_z=hip_z)
    return RiderLeanParameters(parameters_from_bodies(bicycle, bodies), body, joint)
