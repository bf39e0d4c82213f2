"""The flexible member: the rear frame twists and the fork bends, each by a small rotation about a line in
the plane of symmetry against a torsional spring, and the tubes that deform carry their inertia
(docs/models-flexible.md).

* **Frame twist** ``theta_r``: the head frame D (the head tube as the steer bearings see it, massless)
  turns relative to the rear frame about the line through ``(xr, 0, zr)`` with direction
  ``(nrx, 0, nrz)`` (benchmark frame, reference configuration); the front frame steers relative to D.
  Spring ``kr`` (N m/rad) between the rear frame and D.
* **Fork bending** ``theta_f``: the hub frame K (massless) turns relative to the front frame about the
  line through ``(xf, 0, zf)`` with direction ``(nfx, 0, nfz)``; the front wheel turns on K's axle.
  Spring ``kf``.
* **Damping**: a viscous damper in parallel with each spring (``cr``, ``cf``, N m s/rad: the structural
  damping, :meth:`bikemass.models.members.flexible.parameters.Compliances.values` converts a damping ratio), and one in the
  steering bearing, ``cs`` (N m s/rad) between the front frame and the head frame D about the steer axis.

The tubes' inertia is their Ritz field's (:mod:`bikemass.fe.twist`): the modal momentum ``L``, its
moment about the origin ``(Jx, Jz)`` and the modal mass ``m`` of the deformation relative to the parent
body (the rear frame for the twist, the front frame for the fork).  The linearised equations need no
more of a field than these four numbers: Kane's generalised inertia forces of a field ``phi`` riding on
a body are ``L . a + J . alpha + m theta''`` for the coordinate and ``(L theta'') . v_r + (J theta'') .
w_r`` for the others (``a``, ``alpha``, ``v_r``, ``w_r`` the body's; to first order), and gravity sees
``L`` alone.  So the field is represented exactly by a particle of mass ``mt = L**2 / m`` at ``(xt, 0, zt) =
(Jz/L, 0, -Jx/L)`` that moves sideways by ``dt theta = (m/L) theta`` in the parent's axes, beside the
same mass, negative, fixed in the parent: the tubes' rigid mass is already in the parent's benchmark
parameters.  The particle's four numbers are the member's parameters (so that tubes without inertia,
``mt = 0``, divide by nothing); :meth:`bikemass.models.members.flexible.parameters.Compliances.values` converts.
"""

import sympy as sm
import sympy.physics.mechanics as me

from ...derive.bicycle import Coordinate, Member, inertia

PARAMETERS = {
    "r": (("xr", "m", "frame twist axis, x of a point"), ("zr", "m", "frame twist axis, z of a point"),
          ("nrx", "1", "frame twist axis, direction x"), ("nrz", "1", "frame twist axis, direction z"),
          ("kr", "N m/rad", "frame twist stiffness"), ("mtr", "kg", "frame tubes' modal particle, mass"),
          ("xtr", "m", "frame tubes' modal particle, x"), ("ztr", "m", "frame tubes' modal particle, z"),
          ("dtr", "m/rad", "frame tubes' modal particle, sideways per radian"),
          ("cr", "N m s/rad", "frame twist damping")),
    "f": (("xf", "m", "fork bending axis, x of a point"), ("zf", "m", "fork bending axis, z of a point"),
          ("nfx", "1", "fork bending axis, direction x"), ("nfz", "1", "fork bending axis, direction z"),
          ("kf", "N m/rad", "fork bending stiffness"), ("mtf", "kg", "fork tubes' modal particle, mass"),
          ("xtf", "m", "fork tubes' modal particle, x"), ("ztf", "m", "fork tubes' modal particle, z"),
          ("dtf", "m/rad", "fork tubes' modal particle, sideways per radian"),
          ("cf", "N m s/rad", "fork bending damping")),
    "s": (("cs", "N m s/rad", "steering bearing damping"),),
}
"""The member's parameters (name, SI unit, meaning): the frame's (``r``), the fork's (``f``), the steering
bearing's (``s``)."""
FAMILY = "wobble"
"""The family of both compliances' modes (the engine names a mode by the family holding most of it)."""


def turned(name, parent, nx, nz, angle, rate):
    """A frame turned from ``parent`` by ``angle`` about the unit axis ``(nx, 0, nz)`` (in ``parent``), and
    that axis.  The direction cosines are Rodrigues' formula written for a unit axis (no normalising
    square root: the parameters have ``nx**2 + nz**2 = 1``); the angular velocity is ``rate`` about the
    axis."""
    n = sm.Matrix([nx, 0, nz])
    skew = sm.Matrix([[0, -nz, 0], [nz, 0, -nx], [0, nx, 0]])
    frame = me.ReferenceFrame(name)
    frame.orient_explicit(parent, sm.cos(angle) * sm.eye(3) + sm.sin(angle) * skew + (1 - sm.cos(angle)) * n * n.T)
    axis = nx * parent.x + nz * parent.z
    frame.set_ang_vel(parent, rate * axis)
    return frame, axis


class Flexible(Member):
    """The twisting rear frame and the bending fork (see the module docstring)."""

    name = "flexible"

    def rear(self, bike):
        self.p = {name: bike.parameter(name, unit, text) for key in "rfs" for name, unit, text in PARAMETERS[key]}
        self.theta_r, self.u_r = bike.coordinate("theta_r")
        bike.dynamic.append(Coordinate(self.theta_r, self.u_r, "frame-twist", "frame-twist-rate", "rad", FAMILY))
        C = bike.frames["C"]
        self._modal(bike, "frame", C, bike.points["Rc"], (0, -bike.p("rR")), "r", self.theta_r)

    def head(self, bike, frame):
        p = self.p
        D, axis = turned("D", frame, p["nrx"], p["nrz"], self.theta_r, self.u_r)
        Z = bike.points["Rc"].locatenew("Zr", p["xr"] * frame.x + (p["zr"] + bike.p("rR")) * frame.z)
        bike.pivots["head"] = (Z, (p["xr"], p["zr"]))
        bike.frames["D"] = D
        spring = -(p["kr"] * self.theta_r + p["cr"] * self.u_r) * axis
        bike.loads += [(D, spring), (frame, -spring)]
        self.head_frame = D
        return D

    def axle(self, bike, frame):
        p = self.p
        theta_f, u_f = bike.coordinate("theta_f")
        bike.dynamic.append(Coordinate(theta_f, u_f, "fork-bending", "fork-bending-rate", "rad", FAMILY))
        S0, steer_point = bike.points["S0"], (bike.p("w") + bike.p("c"), 0)
        self._modal(bike, "fork", frame, S0, steer_point, "f", theta_f)
        K, axis = turned("K", frame, p["nfx"], p["nfz"], theta_f, u_f)
        Z = S0.locatenew("Zf", (p["xf"] - steer_point[0]) * frame.x + p["zf"] * frame.z)
        bike.pivots["axle"] = (Z, (p["xf"], p["zf"]))
        bike.frames["K"] = K
        spring = -(p["kf"] * theta_f + p["cf"] * u_f) * axis
        bike.loads += [(K, spring), (frame, -spring)]
        steer = next(c for c in bike.dynamic if c.name == "steer-angle")
        damper = -p["cs"] * steer.u * bike.frames["S"].z        # on the front frame, about the steer axis
        bike.loads += [(frame, damper), (self.head_frame, -damper)]
        return K

    def _modal(self, bike, name, parent, base, at, key, theta):
        """The particle pair of a Ritz field on ``parent`` (``base`` a point of it at benchmark ``at``)."""
        mass, x, z, sideways = (self.p[f"{s}t{key}"] for s in "mxzd")
        fixed = base.locatenew(f"{name} modal, fixed", (x - at[0]) * parent.x + (z - at[1]) * parent.z)
        moving = fixed.locatenew(f"{name} modal", sideways * theta * parent.y)
        none = inertia(parent, 0, 0, 0)
        bike.body(f"{name} tubes, modal", mass, moving, parent, none)
        bike.body(f"{name} tubes, rigid copy", -mass, fixed, parent, none)


DERIVATION = Flexible
"""The derivation hook of this member (:meth:`bikemass.models.members.spec.Member.derivation`)."""
