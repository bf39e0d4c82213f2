"""The Whipple bicycle as a sympy.physics.mechanics multibody system, and the hooks its members use.

Parameterised as Meijaard et al. (2007): the 26 benchmark parameters, every body's centre of mass
and inertia in the benchmark frame (x forward, y right, z down, origin at the rear contact) at the
upright, straight configuration.  Coordinates::

    x, y       rear contact on the ground (m)          psi    heading (yaw) of the rear frame
    phi        roll of the rear frame                  theta  pitch of the rear frame (dependent)
    delta      steer (front frame about the steer axis)
    betaR, betaF  wheel rotations (cyclic)

Frames: N ground; A = N turned by psi about z; B = A rolled by phi about x; C = B pitched by theta
about y: the rear frame, equal to the benchmark axes when upright.  The steer axis is
``s = sin(lam) C.x + cos(lam) C.z`` through the point where it meets the ground, ``(w + c, 0, 0)``;
the front frame E turns about it by delta and equals C when straight.  Speeds: ``u_lon, u_lat``
(the rear contact's velocity along and across the heading), then the rates of the other coordinates.

A member changes the system through the hooks of :class:`Member`, called in this order:
``rear`` (bodies on the rear frame: the leaning rider), ``head`` (the frame that carries the steer
axis: the rear frame, or the rear frame's twisted head tube of the flexible member), ``axle`` (the
frame that carries the front axle: the front frame, or the fork's bent tip), ``contact`` (how a
wheel meets the ground: rolling without slip, or a tyre), ``states`` (first-order states added
after the linearisation: the tyres' lateral forces).  A ``head`` or ``axle`` frame turned about a
line away from the default pivot (the rear axle; the steer axis's ground point) names the point it
turns about in ``bike.pivots`` (see :attr:`Bicycle.pivots`).
"""

from dataclasses import dataclass, field

import sympy as sm
import sympy.physics.mechanics as me

from .kane import System

BENCHMARK = (
    ("w", "m", "wheelbase"), ("c", "m", "trail"), ("lam", "rad", "steer-axis tilt"),
    ("g", "m/s^2", "gravity"), ("rR", "m", "rear wheel radius"), ("mR", "kg", "rear wheel mass"),
    ("IRxx", "kg m^2", "rear wheel Ixx"), ("IRyy", "kg m^2", "rear wheel Iyy"),
    ("xB", "m", "rear frame CoM x"), ("zB", "m", "rear frame CoM z"), ("mB", "kg", "rear frame mass"),
    ("IBxx", "kg m^2", "rear frame Ixx"), ("IByy", "kg m^2", "rear frame Iyy"),
    ("IBzz", "kg m^2", "rear frame Izz"), ("IBxz", "kg m^2", "rear frame Ixz"),
    ("xH", "m", "front frame CoM x"), ("zH", "m", "front frame CoM z"), ("mH", "kg", "front frame mass"),
    ("IHxx", "kg m^2", "front frame Ixx"), ("IHyy", "kg m^2", "front frame Iyy"),
    ("IHzz", "kg m^2", "front frame Izz"), ("IHxz", "kg m^2", "front frame Ixz"),
    ("rF", "m", "front wheel radius"), ("mF", "kg", "front wheel mass"),
    ("IFxx", "kg m^2", "front wheel Ixx"), ("IFyy", "kg m^2", "front wheel Iyy"),
)
"""The 26 Meijaard et al. (2007) parameters: (name, SI unit, meaning), in the paper's order."""


@dataclass(frozen=True)
class Coordinate:
    """A coordinate of the linear model: its symbol, its speed, and the states' names and units."""

    q: object
    u: object
    name: str
    rate: str
    unit: str
    family: str


@dataclass
class Wheel:
    """A wheel as the contact models see it.

    ``contact`` is the vector from the centre to the contact point, ``velocity`` the velocity of the
    wheel's material point there, ``longitudinal`` and ``lateral`` the unit vectors of the wheel's
    line on the ground and across it (right), ``camber`` the sine of the wheel plane's lean (right
    positive), ``spin`` the speed fixed by rolling and ``lateral_speed`` the speed fixed by a
    knife-edge contact's lateral constraint.
    """

    name: str
    centre: object
    contact: object
    velocity: object
    longitudinal: object
    lateral: object
    camber: object
    spin: object
    lateral_speed: object


class Member:
    """A member of the model family: every hook leaves the bicycle as it is unless overridden."""

    name = ""

    def rear(self, bike):
        """Add bodies and coordinates to the rear frame."""

    def head(self, bike, frame):
        """The frame that carries the steer axis (default: ``frame``, the rear frame)."""
        return frame

    def axle(self, bike, frame):
        """The frame that carries the front axle (default: ``frame``, the front frame)."""
        return frame

    def contact(self, bike, wheel):
        """Model ``wheel``'s contact and return True, or return False to leave it rolling without slip."""
        return False

    def states(self, bike, linear):
        """First-order states added to the linearised equations (see :class:`ExtraState`)."""
        return []


@dataclass
class ExtraState:
    """A first-order state ``tau x' = sum_k v**k (row_q[k] dq + row_u[k] du) - v x`` added after
    the linearisation (rows as functions of ``v`` given as sympy row vectors over the independent
    coordinates and speeds); ``input`` is the dynamicsymbol by which it enters the loads."""

    name: str
    unit: str
    family: str
    input: object
    tau: object
    row_q: object
    row_u: object
    self_term: object


@dataclass
class Bicycle:
    """The multibody system under construction (see the module docstring).

    Besides what :class:`~bikemass.models.derive.kane.System` takes: the parameters' symbols,
    units and meanings (in declaration order), the dynamic coordinates of the linear model
    (:class:`Coordinate`), the wheels (:class:`Wheel`), the speeds a member frees (``(u, name,
    unit, family)``), the named frames and points, and the heading and lateral coordinates.
    """

    frame: object = None
    parameters: dict = field(default_factory=dict)
    units: dict = field(default_factory=dict)
    descriptions: dict = field(default_factory=dict)
    coordinates: list = field(default_factory=list)
    speeds: list = field(default_factory=list)
    kinematics: dict = field(default_factory=dict)
    bodies: list = field(default_factory=list)
    loads: list = field(default_factory=list)
    inputs: list = field(default_factory=list)
    input_names: list = field(default_factory=list)
    holonomic: list = field(default_factory=list)
    dependent_coordinates: list = field(default_factory=list)
    nonholonomic: list = field(default_factory=list)
    dependent_speeds: list = field(default_factory=list)
    point: dict = field(default_factory=dict)
    dynamic: list = field(default_factory=list)
    wheels: list = field(default_factory=list)
    extra_speeds: list = field(default_factory=list)
    frames: dict = field(default_factory=dict)
    points: dict = field(default_factory=dict)
    heading: object = None
    lateral: object = None
    pivots: dict = field(default_factory=dict)
    """``{"head" or "axle": (point, (x, z))}``: a point fixed in both the hook's frame and the frame it
    turns from, and its benchmark coordinates in the reference configuration; the steer axis (the front
    axle) is placed from it.  Default: the rear axle ``Rc`` (the steer axis's ground point ``S0``)."""
    speed = sm.Symbol("v")
    """The forward speed (m/s): the steady motion's, in every coefficient."""

    def parameter(self, name, unit, description):
        """The symbol of parameter ``name`` (declared on first use, in order)."""
        if name not in self.parameters:
            self.parameters[name] = sm.Symbol(name)
            self.units[name], self.descriptions[name] = unit, description
        return self.parameters[name]

    def p(self, name):
        """A declared parameter's symbol."""
        return self.parameters[name]

    def coordinate(self, name, speed_name=None, rate=0):
        """A new coordinate and its speed (``q' = u``): zero at the steady motion, its speed ``rate``."""
        q = me.dynamicsymbols(name)
        u = me.dynamicsymbols(speed_name or f"u_{name}")
        self.coordinates.append(q)
        self.speeds.append(u)
        self.kinematics[q] = u
        self.point[q], self.point[u] = 0, rate
        return q, u

    def input(self, name, unit):
        """A new input of the linear model (a force or torque, zero at the steady motion)."""
        r = me.dynamicsymbols(name.replace("-", "_"))
        self.inputs.append(r)
        self.input_names.append((name, unit))
        return r

    def body(self, name, mass, centre, frame, inertia):
        """Add a rigid body whose centre of mass ``centre`` has its velocity set from its position."""
        centre.set_vel(self.frame, self.velocity_of(centre))
        self.bodies.append(me.RigidBody(name, centre, frame, mass, (inertia, centre)))
        return self.bodies[-1]

    def velocity_of(self, point):
        """The velocity of ``point`` in the ground frame, in terms of the speeds."""
        return point.pos_from(self.points["O"]).dt(self.frame).xreplace(self.coordinate_rates)

    @property
    def coordinate_rates(self):
        """``{q_i'(t): N(q) u}`` for substitution."""
        return {q.diff(me.dynamicsymbols._t): rate for q, rate in self.kinematics.items()}

    def system(self):
        """The :class:`~bikemass.models.derive.kane.System` to linearise."""
        return System(self.frame, self.coordinates, self.speeds, self.kinematics, self.bodies, self.loads,
                      self.inputs, self.holonomic, self.dependent_coordinates, self.nonholonomic,
                      self.dependent_speeds, self.point)


def inertia(frame, xx, yy, zz, xz=0):
    """The inertia dyadic with tensor elements ``xx, yy, zz, xz`` in ``frame`` (the benchmark's form)."""
    return me.inertia(frame, xx, yy, zz, 0, 0, xz)


def rear(bike):
    """Ground, rear frame and rear wheel; the parameters of Meijaard et al. (2007)."""
    for name, unit, description in BENCHMARK:
        bike.parameter(name, unit, description)
    p, v = bike.p, bike.speed
    N = bike.frame = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    bike.points["O"] = O
    x, u_lon = bike.coordinate("x", "u_lon", rate=v)
    y, u_lat = bike.coordinate("y", "u_lat")
    psi, u_psi = bike.coordinate("psi")
    phi, u_phi = bike.coordinate("phi")
    theta, u_theta = bike.coordinate("theta")
    bike.kinematics[x] = u_lon * sm.cos(psi) - u_lat * sm.sin(psi)
    bike.kinematics[y] = u_lon * sm.sin(psi) + u_lat * sm.cos(psi)
    A = N.orientnew("A", "Axis", (psi, N.z))
    B = A.orientnew("B", "Axis", (phi, A.x))
    C = B.orientnew("C", "Axis", (theta, B.y))
    betaR, u_betaR = bike.coordinate("betaR", rate=-v / p("rR"))
    R = C.orientnew("R", "Axis", (betaR, C.y))
    bike.frames.update(N=N, A=A, B=B, C=C, R=R)
    bike.dynamic += [Coordinate(phi, u_phi, "roll-angle", "roll-rate", "rad", "bicycle")]
    bike.dependent_coordinates.append(theta)
    bike.dependent_speeds.append(u_theta)
    bike.heading, bike.lateral = psi, y
    Rc = O.locatenew("Rc", x * N.x + y * N.y - p("rR") * B.z)
    Bo = Rc.locatenew("Bo", p("xB") * C.x + (p("zB") + p("rR")) * C.z)
    bike.points.update(Rc=Rc, Bo=Bo)
    bike.body("rear wheel", p("mR"), Rc, R, inertia(C, p("IRxx"), p("IRyy"), p("IRxx")))
    bike.body("rear frame", p("mB"), Bo, C, inertia(C, p("IBxx"), p("IByy"), p("IBzz"), p("IBxz")))
    contact = p("rR") * B.z
    velocity = Rc.vel(N) + R.ang_vel_in(N).xreplace(bike.coordinate_rates).cross(contact)
    bike.wheels.append(Wheel("rear", Rc, contact, velocity, A.x, A.y, C.y & N.z, u_betaR, u_lat))
    bike.loads.append((C, bike.input("roll-torque", "N m") * A.x))


def front(bike, head):
    """The front frame on the steer axis carried by ``head`` (the rear frame unless a member bends it)."""
    p = bike.p
    delta, u_delta = bike.coordinate("delta")
    bike.dynamic.append(Coordinate(delta, u_delta, "steer-angle", "steer-rate", "rad", "bicycle"))
    S = head.orientnew("S", "Axis", (p("lam"), head.y))          # S.z along the steer axis
    Es = S.orientnew("Es", "Axis", (delta, S.z))
    E = Es.orientnew("E", "Axis", (-p("lam"), Es.y))             # the benchmark axes when straight
    bike.frames.update(S=S, E=E)
    pivot, (x, z) = bike.pivots.get("head", (bike.points["Rc"], (0, -p("rR"))))
    S0 = pivot.locatenew("S0", (p("w") + p("c") - x) * head.x - z * head.z)
    Ho = S0.locatenew("Ho", (p("xH") - p("w") - p("c")) * E.x + p("zH") * E.z)
    bike.points.update(S0=S0, Ho=Ho)
    bike.body("front frame", p("mH"), Ho, E, inertia(E, p("IHxx"), p("IHyy"), p("IHzz"), p("IHxz")))
    torque = bike.input("steer-torque", "N m")
    bike.loads += [(E, torque * S.z), (head, -torque * S.z)]


def front_wheel(bike, axle):
    """The front wheel on the axle carried by ``axle`` (the front frame unless a member bends it)."""
    p, v = bike.p, bike.speed
    N, O = bike.frame, bike.points["O"]
    betaF, u_betaF = bike.coordinate("betaF", rate=-v / p("rF"))
    Fw = axle.orientnew("F", "Axis", (betaF, axle.y))
    bike.frames["F"] = Fw
    pivot, (x, z) = bike.pivots.get("axle", (bike.points["S0"], (p("w") + p("c"), 0)))
    Fc = pivot.locatenew("Fc", (p("w") - x) * axle.x - (p("rF") + z) * axle.z)
    bike.points["Fc"] = Fc
    bike.body("front wheel", p("mF"), Fc, Fw, inertia(axle, p("IFxx"), p("IFyy"), p("IFxx")))
    tilt = N.z & axle.y
    contact = p("rF") * (N.z - tilt * axle.y) / sm.sqrt(1 - tilt ** 2)
    bike.holonomic.append((Fc.pos_from(O) + contact) & N.z)
    velocity = Fc.vel(N) + Fw.ang_vel_in(N).xreplace(bike.coordinate_rates).cross(contact)
    ahead = axle.y.cross(N.z) / sm.sqrt(1 - tilt ** 2)
    u_psi = bike.speeds[bike.coordinates.index(bike.heading)]
    bike.wheels.append(Wheel("front", Fc, contact, velocity, ahead, N.z.cross(ahead), tilt, u_betaF, u_psi))


def rolling(bike, wheel):
    """A knife-edge wheel rolling without slip: its contact point has no velocity along the ground."""
    bike.nonholonomic += [wheel.velocity & wheel.longitudinal, wheel.velocity & wheel.lateral]
    bike.dependent_speeds += [wheel.spin, wheel.lateral_speed]


def rolling_forward(bike, wheel):
    """A wheel that rolls without longitudinal slip (its lateral slip left to a tyre model)."""
    bike.nonholonomic.append(wheel.velocity & wheel.longitudinal)
    bike.dependent_speeds.append(wheel.spin)


def gravity(bike):
    """Gravity on every body (down is +z)."""
    for body in bike.bodies:
        bike.loads.append((body.masscenter, body.mass * bike.p("g") * bike.frame.z))


def assemble(members):
    """The :class:`Bicycle` with ``members`` (sequence of :class:`Member`) on."""
    bike = Bicycle()
    rear(bike)
    for m in members:
        m.rear(bike)
    head = bike.frames["C"]
    for m in members:
        head = m.head(bike, head)
    front(bike, head)
    axle = bike.frames["E"]
    for m in members:
        axle = m.axle(bike, axle)
    front_wheel(bike, axle)
    for wheel in bike.wheels:
        if not any(m.contact(bike, wheel) for m in members):
            rolling(bike, wheel)
    gravity(bike)
    return bike
