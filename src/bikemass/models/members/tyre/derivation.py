"""Tyres: lateral force from slip and camber with a relaxation length, per wheel.

A wheel keeps rolling without longitudinal slip but may slide sideways.  The lateral force ``F``
(N, along the ground across the wheel's heading, right positive) acts at the contact point and
follows the steady-state force of the slip angle ``alpha = -s / v`` (``s`` the lateral velocity of the
wheel's material point at the contact, m/s) and the camber ``gamma`` (the wheel plane's lean, right
positive) with a first-order lag over the relaxation length ``sigma`` (Pacejka 2012, Tyre and Vehicle
Dynamics, Sec. 7.2)::

    (sigma / v) F' + F = N (C_alpha alpha + C_gamma gamma)

with cornering and camber coefficients ``C_alpha, C_gamma`` (1/rad) per unit normal load ``N`` (the
static load on the wheel).  Multiplied by ``v`` it is polynomial in speed::

    sigma F' = N (C_gamma v gamma - C_alpha s) - v F

The tyre also turns the wheel about the ground normal (z, down) with a moment at the contact::

    M_z = -t_p F + N C_mgamma gamma

the self-aligning moment of the lateral force acting a pneumatic trail ``t_p`` (m) behind the contact
point (so it lags with the force), and the twisting torque of the camber with coefficient
``C_mgamma`` (m/rad, per unit normal load; positive turns the wheel towards its lean).  Both zero give
back the force-only tyre exactly.

The knife-edge wheel of the Whipple bicycle is the limit ``C_alpha -> infinity``, ``sigma -> 0`` with
``C_gamma / C_alpha -> 0``: no lateral slip.  Without the lateral constraints the rear frame's yaw
rate and lateral velocity are free speeds of the model.
"""

from ...derive.bicycle import ExtraState, Member, rolling_forward

PARAMETERS = {
    "rear": (("CaR", "1/rad", "rear cornering coefficient"), ("CgR", "1/rad", "rear camber coefficient"),
             ("sigmaR", "m", "rear relaxation length"), ("tpR", "m", "rear pneumatic trail"),
             ("CmgR", "m/rad", "rear twisting torque coefficient")),
    "front": (("CaF", "1/rad", "front cornering coefficient"), ("CgF", "1/rad", "front camber coefficient"),
              ("sigmaF", "m", "front relaxation length"), ("tpF", "m", "front pneumatic trail"),
              ("CmgF", "m/rad", "front twisting torque coefficient")),
}
"""Each wheel's tyre parameters (name, SI unit, meaning)."""

SPEEDS = {"rear": ("lateral-velocity", "m/s"), "front": ("yaw-rate", "rad/s")}
"""The speed each wheel's lateral constraint fixed, now a state: the rear contact's lateral velocity
(along the heading's y axis) and the rear frame's yaw rate."""


WHEEL_FRAMES = {"rear": "R", "front": "F"}
"""Each wheel's body frame (the moment acts on the wheel)."""


def static_loads(bike, x_of):
    """``{wheel: N}``: the static normal loads (N) of the bodies at rest on level ground, ``x_of(point)`` the
    benchmark x of a point in the reference configuration."""
    g, origin = bike.p("g"), bike.points["O"]
    mass = sum(b.mass for b in bike.bodies)
    moment = sum(b.mass * x_of(b.masscenter.pos_from(origin) & bike.frame.x) for b in bike.bodies)
    return {"front": g * moment / bike.p("w"), "rear": g * (mass - moment / bike.p("w"))}


class Tyre(Member):
    """Both wheels on tyres (see the module docstring)."""

    name = "tyre"

    def __init__(self):
        self._forces = []

    def contact(self, bike, wheel):
        rolling_forward(bike, wheel)
        force = bike.input(f"{wheel.name}-lateral-force", "N")
        point = wheel.centre.locatenew(f"{wheel.name} contact", wheel.contact)
        point.set_vel(bike.frame, wheel.velocity)
        bike.loads.append((point, force * wheel.lateral))
        *_, trail, twisting = (bike.parameter(*spec) for spec in PARAMETERS[wheel.name])
        reference = {q: 0 for q in bike.coordinates}
        load = static_loads(bike, lambda x: x.xreplace(reference))[wheel.name]
        moment = -trail * force + twisting * load * wheel.camber
        bike.loads.append((bike.frames[WHEEL_FRAMES[wheel.name]], moment * bike.frame.z))
        name, unit = SPEEDS[wheel.name]
        bike.extra_speeds.append((wheel.lateral_speed, name, unit, "tyre"))
        self._forces.append((wheel, force))
        return True

    def states(self, bike, linear):
        v = bike.speed
        load = static_loads(bike, linear.value)
        out = []
        for wheel, force in self._forces:
            Ca, Cg, sigma = (bike.parameter(*spec) for spec in PARAMETERS[wheel.name][:3])
            sq, su = linear.linear(wheel.velocity & wheel.lateral)
            gq, gu = linear.linear(wheel.camber)
            n = load[wheel.name]
            out.append(ExtraState(f"{wheel.name}-lateral-force", "N", "tyre", force, sigma,
                                  n * (Cg * v * gq - Ca * sq), n * (Cg * v * gu - Ca * su), -v))
        return out


DERIVATION = Tyre
"""The derivation hook of this member (:meth:`bikemass.models.members.spec.Member.derivation`)."""
