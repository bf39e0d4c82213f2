"""The rider's arms: the hands on the grips, a torsional spring and viscous damper about the steer axis
between the handlebars and the body that carries the rider's shoulders.

The handlebars are the front frame E.  The shoulders ride on the rider's upper body: the rear frame C
of the Whipple bicycle (the rider held rigid on the saddle), or the leaning upper body G where the
``rider-lean`` member splits the rider at the hips.  The arms turn the handlebars relative to that
body with the torque ``-(k_arms a + c_arms a')`` about the steer axis (on E; the opposite on the upper
body), ``a`` the handlebars' rotation relative to the upper body about the steer axis: the steer angle,
plus the frame's twist about the steer axis where the ``flexible`` member twists the head tube away
from the saddle, minus the upper body's lean about it (``sin(lam)`` per radian of lean).  The angle is
the relative angular velocity's component along the steer axis with each coordinate's rate replaced
by the coordinate (exact to first order, all the linear model needs); the member adds no coordinate.

The arms' own mass is in the bodies the benchmark parameters give (where the rider's pose puts the
segments, or the forearms on the front frame with ``forearms: handlebars``: :mod:`bikemass.rider.hands`);
the derivation adds only the joint's stiffness and damping.
"""

from ...derive.bicycle import Member

PARAMETERS = (("k_arms", "N m/rad", "arms' stiffness about the steer axis"),
              ("c_arms", "N m s/rad", "arms' damping about the steer axis"))
"""The member's parameters (name, SI unit, meaning)."""


class Arms(Member):
    """The hands on the grips (see the module docstring)."""

    name = "arms"

    def axle(self, bike, frame):
        k, c = (bike.parameter(name, unit, text) for name, unit, text in PARAMETERS)
        E, S = bike.frames["E"], bike.frames["S"]
        upper = bike.frames.get("G", bike.frames["C"])         # the leaning upper body, else the rear frame
        rate = (E.ang_vel_in(upper) & S.z).xreplace(bike.coordinate_rates)
        angle = rate.xreplace({u: q for q, u in bike.kinematics.items() if u in bike.speeds})
        torque = -(k * angle + c * rate) * S.z
        bike.loads += [(E, torque), (upper, -torque)]
        return frame


DERIVATION = Arms
"""The derivation hook of this member (:meth:`bikemass.models.members.spec.Member.derivation`)."""
