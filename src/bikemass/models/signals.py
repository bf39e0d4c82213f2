"""Every state and input of the model family, named once (units and meaning)."""

from .linear import Signal
from .whipple import HEADING, LATERAL, ROLL_ANGLE, ROLL_RATE, ROLL_TORQUE, STEER_ANGLE, STEER_RATE, STEER_TORQUE

SIGNALS = {s.name: s for s in (
    ROLL_ANGLE, STEER_ANGLE, ROLL_RATE, STEER_RATE, HEADING, LATERAL, ROLL_TORQUE, STEER_TORQUE,
    Signal("lean-angle", "rad", "lean of the rider's upper body relative to the rear frame, positive to the right"),
    Signal("lean-rate", "rad/s", "lean angular rate of the upper body relative to the rear frame"),
    Signal("lean-torque", "N m", "torque between the rear frame and the upper body about the hip axis"),
    Signal("yaw-rate", "rad/s", "yaw angular rate of the rear frame (free when the tyres slip)"),
    Signal("lateral-velocity", "m/s", "velocity of the rear contact to the right of the heading (tyre slip)"),
    Signal("rear-lateral-force", "N", "lateral force of the ground on the rear tyre, to the right"),
    Signal("front-lateral-force", "N", "lateral force of the ground on the front tyre, to the right"),
    Signal("frame-twist", "rad", "rotation of the head tube (and the front assembly) relative to the rear frame "
                                 "about the frame's twist axis"),
    Signal("frame-twist-rate", "rad/s", "frame twist rate"),
    Signal("fork-bending", "rad", "rotation of the front wheel's hub relative to the front frame about the fork's "
                                  "bending axis"),
    Signal("fork-bending-rate", "rad/s", "fork bending rate"),
)}
"""State or input name -> :class:`~bikemass.models.linear.Signal`."""


def signal(name, unit):
    """The :class:`~bikemass.models.linear.Signal` ``name``, checked against the ``unit`` the code uses."""
    s = SIGNALS[name]
    if s.unit != unit:
        raise ValueError(f"{name}: the generated code has unit {unit!r}, the signal {s.unit!r}")
    return s
