"""The leaning rider: the upper body on a longitudinal hip axis of the rear frame, with a spring and damper.

The rider is split at the hips: the rear frame B keeps the bicycle's rear frame, the legs and the
pelvis; the upper body U (torso, head, arms that do not hold the bars) turns about the line through
``(0, 0, zhip)`` parallel to x (horizontal when upright) by the lean angle ``rho`` relative to the rear
frame (right positive), against ``-(klean rho + clean rho')``; a lean torque between rear frame and
upper body is an input.  This is the rider of Moore (2012, PhD thesis, UC Davis, the rider-lean
model of BicycleParameters' ``MooreRiderLean2012Model``), parameterised like the benchmark: U's mass,
centre of mass and inertia (about its centre of mass, benchmark axes) when upright.
"""

from ...derive.bicycle import Coordinate, Member, inertia

PARAMETERS = (
    ("mU", "kg", "upper body mass"), ("xU", "m", "upper body CoM x"), ("zU", "m", "upper body CoM z"),
    ("IUxx", "kg m^2", "upper body Ixx"), ("IUyy", "kg m^2", "upper body Iyy"),
    ("IUzz", "kg m^2", "upper body Izz"), ("IUxz", "kg m^2", "upper body Ixz"),
    ("zhip", "m", "hip (lean) axis z"), ("klean", "N m/rad", "lean stiffness"),
    ("clean", "N m s/rad", "lean damping"),
)
"""The member's parameters (name, SI unit, meaning), after the benchmark's."""


class RiderLean(Member):
    """The upper body leaning on the rear frame (see the module docstring)."""

    name = "rider-lean"

    def rear(self, bike):
        p = {name: bike.parameter(name, unit, text) for name, unit, text in PARAMETERS}
        rho, u_rho = bike.coordinate("rho")
        bike.dynamic.append(Coordinate(rho, u_rho, "lean-angle", "lean-rate", "rad", "lean"))
        C = bike.frames["C"]
        G = C.orientnew("G", "Axis", (rho, C.x))
        bike.frames["G"] = G                                   # the upper body (the arms member holds to it)
        hip = bike.points["Rc"].locatenew("J", (p["zhip"] + bike.p("rR")) * C.z)
        Uo = hip.locatenew("Uo", p["xU"] * G.x + (p["zU"] - p["zhip"]) * G.z)
        bike.body("upper body", p["mU"], Uo, G, inertia(G, p["IUxx"], p["IUyy"], p["IUzz"], p["IUxz"]))
        torque = bike.input("lean-torque", "N m") - p["klean"] * rho - p["clean"] * u_rho
        bike.loads += [(G, torque * C.x), (C, -torque * C.x)]


DERIVATION = RiderLean
"""The derivation hook of this member (:meth:`bikemass.models.members.spec.Member.derivation`)."""
